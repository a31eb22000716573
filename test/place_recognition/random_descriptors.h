#pragma once
// Seeded random binary descriptors for the place_recognition tests: planted clusters (a centre
// and copies of it with a few bits flipped) and images drawn from them.

#include <random>
#include <vector>

#include <opencv2/core.hpp>

namespace dslam {
namespace test {

/// `rows` uniformly random 32-byte descriptors (CV_8UC1).
inline cv::Mat RandomDescriptors(int rows, std::mt19937* rng) {
  std::uniform_int_distribution<int> byte(0, 255);
  cv::Mat d(rows, 32, CV_8UC1);
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < 32; ++c) d.at<uchar>(r, c) = static_cast<uchar>(byte(*rng));
  }
  return d;
}

/// A copy of `descriptors` with `bits` random bits of every row flipped (a bit may be drawn twice).
inline cv::Mat FlipBits(const cv::Mat& descriptors, int bits, std::mt19937* rng) {
  std::uniform_int_distribution<int> bit(0, 255);
  cv::Mat out = descriptors.clone();
  for (int r = 0; r < out.rows; ++r) {
    for (int b = 0; b < bits; ++b) {
      const int k = bit(*rng);
      out.at<uchar>(r, k / 8) ^= static_cast<uchar>(1 << (k % 8));
    }
  }
  return out;
}

/// One image of `rows` descriptors, each a random row of `centres` with `bits` bits flipped.
inline cv::Mat ImageFromCentres(const cv::Mat& centres, int rows, int bits, std::mt19937* rng) {
  std::uniform_int_distribution<int> pick(0, centres.rows - 1);
  cv::Mat image(rows, 32, CV_8UC1);
  for (int r = 0; r < rows; ++r) centres.row(pick(*rng)).copyTo(image.row(r));
  return FlipBits(image, bits, rng);
}

}  // namespace test
}  // namespace dslam
