#include "dslam/features/matching.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>

#include <opencv2/core/utility.hpp>
#include <opencv2/features2d.hpp>

namespace dslam {
namespace {

constexpr int kDescriptorBytes = 32;

// Keeps, for every train index claimed by several queries, only the closest; others get -1.
void ResolveConflicts(const std::vector<int>& distances, int num_train, std::vector<int>* match) {
  std::vector<int> owner(num_train, -1);
  for (size_t q = 0; q < match->size(); ++q) {
    const int t = (*match)[q];
    if (t < 0) continue;
    if (owner[t] < 0 || distances[q] < distances[owner[t]]) owner[t] = static_cast<int>(q);
  }
  for (size_t q = 0; q < match->size(); ++q) {
    const int t = (*match)[q];
    if (t >= 0 && owner[t] != static_cast<int>(q)) (*match)[q] = -1;
  }
}

// What the radius search reads of a feature, stored by cell so that a search reads memory in
// order and touches FrameFeatures only for the candidates it compares.
struct GridEntry {
  double u = 0.0, v = 0.0;  // [px] uv_ideal
  int octave = 0;
  int index = 0;  // into frame.features
};

// Features bucketed by their ideal pixel position, so a radius search visits few of them. The
// cells are one flat array (each cell's entries in feature order) with offsets per cell.
class FeatureGrid {
 public:
  explicit FeatureGrid(const FrameFeatures& frame) {
    double max_u = 1.0, max_v = 1.0;
    for (const Feature& f : frame.features) {
      max_u = std::max(max_u, f.uv_ideal.x());
      max_v = std::max(max_v, f.uv_ideal.y());
    }
    cols_ = static_cast<int>(max_u / kCellPx) + 1;
    rows_ = static_cast<int>(max_v / kCellPx) + 1;
    std::vector<size_t> cell_of(frame.features.size());
    offsets_.assign(static_cast<size_t>(cols_) * rows_ + 1, 0);
    for (size_t i = 0; i < frame.features.size(); ++i) {
      const Eigen::Vector2d& uv = frame.features[i].uv_ideal;
      cell_of[i] = Cell(Clamp(uv.x() / kCellPx, cols_), Clamp(uv.y() / kCellPx, rows_));
      ++offsets_[cell_of[i] + 1];
    }
    for (size_t c = 1; c < offsets_.size(); ++c) offsets_[c] += offsets_[c - 1];
    entries_.resize(frame.features.size());
    std::vector<size_t> next(offsets_.begin(), offsets_.end() - 1);
    for (size_t i = 0; i < frame.features.size(); ++i) {
      const Feature& f = frame.features[i];
      entries_[next[cell_of[i]]++] = {f.uv_ideal.x(), f.uv_ideal.y(), f.octave,
                                      static_cast<int>(i)};
    }
  }

  // Calls f(entry) for every feature in the cells overlapping the square around uv.
  template <typename F>
  void ForEachNear(const Eigen::Vector2d& uv, double radius, F&& f) const {
    const int c0 = Clamp((uv.x() - radius) / kCellPx, cols_);
    const int c1 = Clamp((uv.x() + radius) / kCellPx, cols_);
    const int r0 = Clamp((uv.y() - radius) / kCellPx, rows_);
    const int r1 = Clamp((uv.y() + radius) / kCellPx, rows_);
    for (int r = r0; r <= r1; ++r) {
      // The cells c0..c1 of a row are adjacent in entries_.
      const size_t end = offsets_[Cell(c1, r) + 1];
      for (size_t e = offsets_[Cell(c0, r)]; e < end; ++e) f(entries_[e]);
    }
  }

 private:
  static constexpr double kCellPx = 16.0;
  static int Clamp(double x, int n) { return std::clamp(static_cast<int>(x), 0, n - 1); }
  size_t Cell(int c, int r) const { return static_cast<size_t>(r) * cols_ + c; }
  int cols_ = 1, rows_ = 1;
  std::vector<size_t> offsets_;  // cell k holds entries_[offsets_[k], offsets_[k + 1])
  std::vector<GridEntry> entries_;
};

// Best feature index for one projected point, or -1; writes its distance.
int BestCandidate(const ProjectedPoint& p, const FrameFeatures& frame, const FeatureGrid& grid,
                  const ProjectionSearchOptions& options, int* best_distance) {
  const bool octave_known =
      p.predicted_octave >= 0 && p.predicted_octave < static_cast<int>(frame.octave_scale.size());
  const double radius_px = p.radius_px > 0.0 ? p.radius_px : options.radius_px;
  const double radius = radius_px * (octave_known ? frame.octave_scale[p.predicted_octave] : 1.0);
  const double radius2 = radius * radius;
  const uchar* descriptor = p.descriptor.ptr<uchar>(0);
  int best = std::numeric_limits<int>::max(), second = best, best_index = -1;
  grid.ForEachNear(p.uv_ideal, radius, [&](const GridEntry& e) {
    if (octave_known && std::abs(e.octave - p.predicted_octave) > options.octave_tolerance) {
      return;
    }
    const double du = e.u - p.uv_ideal.x(), dv = e.v - p.uv_ideal.y();
    if (du * du + dv * dv > radius2) return;
    const int d = Hamming(descriptor, frame.descriptors.ptr<uchar>(e.index));
    if (d < best) {
      second = best;
      best = d;
      best_index = e.index;
    } else if (d < second) {
      second = d;
    }
  });
  *best_distance = best;
  if (best_index < 0 || best >= options.max_distance) return -1;
  if (second != std::numeric_limits<int>::max() && best >= options.ratio * second) return -1;
  return best_index;
}

}  // namespace

int Hamming(const uchar* a, const uchar* b) {
  int bits = 0;
  for (int i = 0; i < kDescriptorBytes; i += 8) {
    std::uint64_t x, y;
    std::memcpy(&x, a + i, 8);
    std::memcpy(&y, b + i, 8);
    bits += __builtin_popcountll(x ^ y);
  }
  return bits;
}

int HammingDistance(const cv::Mat& a, const cv::Mat& b) {
  if (a.type() != CV_8UC1 || b.type() != CV_8UC1 || a.total() != kDescriptorBytes ||
      b.total() != kDescriptorBytes || !a.isContinuous() || !b.isContinuous()) {
    throw std::invalid_argument("HammingDistance: expects two 32-byte CV_8UC1 descriptors");
  }
  return Hamming(a.ptr<uchar>(0), b.ptr<uchar>(0));
}

std::vector<int> SearchByProjection(const std::vector<ProjectedPoint>& points,
                                    const FrameFeatures& frame,
                                    const ProjectionSearchOptions& options) {
  std::vector<int> match(points.size(), -1);
  std::vector<int> distances(points.size(), 0);
  for (const ProjectedPoint& point : points) {
    if (point.descriptor.total() != kDescriptorBytes) {
      throw std::invalid_argument("SearchByProjection: descriptor must have 32 bytes");
    }
  }
  const FeatureGrid grid(frame);
  // Points are searched independently (in parallel); conflicts are resolved afterwards.
  cv::parallel_for_(cv::Range(0, static_cast<int>(points.size())), [&](const cv::Range& range) {
    for (int k = range.start; k < range.end; ++k) {
      match[k] = BestCandidate(points[k], frame, grid, options, &distances[k]);
    }
  });
  ResolveConflicts(distances, static_cast<int>(frame.features.size()), &match);
  return match;
}

std::vector<DescriptorMatch> MatchBruteForce(const cv::Mat& query, const cv::Mat& train,
                                             int max_distance, double ratio) {
  std::vector<DescriptorMatch> out;
  if (query.empty() || train.empty()) return out;
  cv::BFMatcher matcher(cv::NORM_HAMMING);
  std::vector<std::vector<cv::DMatch>> knn;
  matcher.knnMatch(query, train, knn, 2);
  std::vector<int> match(query.rows, -1), distances(query.rows, 0);
  for (const auto& pair : knn) {
    if (pair.empty()) continue;
    const cv::DMatch& best = pair[0];
    if (best.distance >= max_distance) continue;
    if (pair.size() > 1 && best.distance >= ratio * pair[1].distance) continue;
    match[best.queryIdx] = best.trainIdx;
    distances[best.queryIdx] = static_cast<int>(best.distance);
  }
  ResolveConflicts(distances, train.rows, &match);
  for (int q = 0; q < query.rows; ++q) {
    if (match[q] >= 0) out.push_back({q, match[q], distances[q]});
  }
  return out;
}

}  // namespace dslam
