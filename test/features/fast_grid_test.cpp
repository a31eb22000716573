#include "dslam/features/fast_grid.h"

#include <random>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/features2d.hpp>
#include <opencv2/imgproc.hpp>

namespace dslam {
namespace {

// Seeded test images: blurred noise (corners everywhere, many ties in flat-ish areas), random
// blocks (strong corners at block corners) and a low-contrast copy of the blocks.
std::vector<cv::Mat> TestImages(int rows, int cols) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> grey(0, 255);
  cv::Mat noise(rows, cols, CV_8UC1), blocks_small(rows / 6 + 1, cols / 6 + 1, CV_8UC1);
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) noise.at<uchar>(r, c) = static_cast<uchar>(grey(rng));
  }
  for (int r = 0; r < blocks_small.rows; ++r) {
    for (int c = 0; c < blocks_small.cols; ++c) {
      blocks_small.at<uchar>(r, c) = static_cast<uchar>(grey(rng));
    }
  }
  cv::Mat blurred, blocks, low_contrast;
  cv::GaussianBlur(noise, blurred, cv::Size(5, 5), 1.0);
  cv::resize(blocks_small, blocks, cv::Size(blocks_small.cols * 6, blocks_small.rows * 6), 0, 0,
             cv::INTER_NEAREST);
  blocks = blocks(cv::Rect(0, 0, cols, rows)).clone();
  blocks.convertTo(low_contrast, -1, 0.1, 100.0);
  return {noise, blurred, blocks, low_contrast};
}

// What FastPerCell must equal: one cv::FAST call per cell on the cell and its 3-pixel margin.
std::vector<cv::KeyPoint> CvFastOnCell(const cv::Mat& image, const cv::Rect& cell, int threshold) {
  const cv::Rect roi(cell.x - 3, cell.y - 3, cell.width + 6, cell.height + 6);
  std::vector<cv::KeyPoint> found;
  cv::FAST(image(roi), found, threshold, true);
  for (cv::KeyPoint& kp : found) kp.pt += cv::Point2f(roi.x, roi.y);
  return found;
}

TEST(FastGrid, CellsCoverTheAreaCutAtItsEnd) {
  FastGrid grid;
  grid.x0 = 19, grid.y0 = 19, grid.x1 = 621, grid.y1 = 461, grid.size = 30;
  EXPECT_EQ(grid.Cols(), 21);
  EXPECT_EQ(grid.Rows(), 15);
  EXPECT_EQ(grid.Cell(0), cv::Rect(19, 19, 30, 30));
  EXPECT_EQ(grid.Cell(20), cv::Rect(619, 19, 2, 30));  // 602 = 20 * 30 + 2
  EXPECT_EQ(grid.Cell(21 * 14), cv::Rect(19, 439, 30, 22));
}

TEST(FastGrid, EveryCellEqualsOneCvFastCallOnIt) {
  for (const cv::Mat& image : TestImages(157, 203)) {
    int found = 0;  // keypoints over all grids and thresholds: the comparison is not empty
    for (int size : {30, 13, 7, 1}) {
      for (int threshold : {0, 1, 7, 20, 60}) {
        FastGrid grid;
        grid.x0 = 4, grid.y0 = 5, grid.x1 = image.cols - 3, grid.y1 = image.rows - 9;
        grid.size = size;
        const std::vector<std::vector<cv::KeyPoint>> cells = FastPerCell(image, grid, threshold);
        ASSERT_EQ(static_cast<int>(cells.size()), grid.Cols() * grid.Rows());
        for (int index = 0; index < static_cast<int>(cells.size()); ++index) {
          const std::vector<cv::KeyPoint> expected =
              CvFastOnCell(image, grid.Cell(index), threshold);
          ASSERT_EQ(cells[index].size(), expected.size())
              << "size " << size << " threshold " << threshold << " cell " << index;
          for (size_t k = 0; k < expected.size(); ++k) {
            EXPECT_EQ(cells[index][k].pt, expected[k].pt);
            EXPECT_EQ(cells[index][k].response, expected[k].response);
            EXPECT_EQ(cells[index][k].size, expected[k].size);
            EXPECT_EQ(cells[index][k].angle, expected[k].angle);
            EXPECT_EQ(cells[index][k].octave, expected[k].octave);
          }
          found += static_cast<int>(expected.size());
        }
      }
    }
    EXPECT_GT(found, 500);
  }
}

TEST(FastGrid, OnlyTheWantedCellsAreSearched) {
  const cv::Mat image = TestImages(157, 203)[1];
  FastGrid grid;
  grid.x0 = 19, grid.y0 = 19, grid.x1 = image.cols - 19, grid.y1 = image.rows - 19;
  grid.size = 13;
  std::mt19937 rng(3);
  std::vector<uint8_t> wanted(grid.Cols() * grid.Rows());
  for (uint8_t& w : wanted) w = static_cast<uint8_t>(rng() % 2);  // runs of every length
  const std::vector<std::vector<cv::KeyPoint>> cells = FastPerCell(image, grid, 7, &wanted);
  ASSERT_EQ(cells.size(), wanted.size());
  for (size_t index = 0; index < cells.size(); ++index) {
    const std::vector<cv::KeyPoint> expected =
        wanted[index] ? CvFastOnCell(image, grid.Cell(index), 7) : std::vector<cv::KeyPoint>();
    ASSERT_EQ(cells[index].size(), expected.size()) << index;
    for (size_t k = 0; k < expected.size(); ++k) {
      EXPECT_EQ(cells[index][k].pt, expected[k].pt);
      EXPECT_EQ(cells[index][k].response, expected[k].response);
    }
  }
  wanted.pop_back();
  EXPECT_THROW(FastPerCell(image, grid, 7, &wanted), std::invalid_argument);
}

TEST(FastGrid, ScoreIsTheLargestThresholdAtWhichCvFastFindsTheCorner) {
  const cv::Mat image = TestImages(60, 60)[1];
  int corners = 0;
  for (int y = 3; y < image.rows - 3; y += 2) {
    for (int x = 3; x < image.cols - 3; x += 3) {
      const int score = FastScore(image, x, y);
      const cv::Mat pixel = image(cv::Rect(x - 3, y - 3, 7, 7));  // FAST tests its centre only
      std::vector<cv::KeyPoint> found;
      if (score >= 0) {
        cv::FAST(pixel, found, score, false);
        EXPECT_EQ(found.size(), 1u) << x << " " << y;
        ++corners;
      }
      if (score < 255) {
        cv::FAST(pixel, found, std::max(score + 1, 0), false);
        EXPECT_TRUE(found.empty()) << x << " " << y;
      }
    }
  }
  EXPECT_GT(corners, 50);
}

TEST(FastGrid, RejectsBadInput) {
  const cv::Mat image = TestImages(60, 60)[0];
  FastGrid grid;
  grid.x0 = 3, grid.y0 = 3, grid.x1 = 57, grid.y1 = 57;
  EXPECT_NO_THROW(FastPerCell(image, grid, 20));
  cv::Mat colour;
  cv::cvtColor(image, colour, cv::COLOR_GRAY2BGR);
  EXPECT_THROW(FastPerCell(colour, grid, 20), std::invalid_argument);
  EXPECT_THROW(FastPerCell(image, grid, 256), std::invalid_argument);
  grid.x0 = 2;
  EXPECT_THROW(FastPerCell(image, grid, 20), std::invalid_argument);
  EXPECT_THROW(FastScore(image, 2, 30), std::invalid_argument);
}

}  // namespace
}  // namespace dslam
