#include "dslam/mapping/view_votes.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "dslam/core/depth_uncertainty.h"

namespace dslam {
namespace {

constexpr float kNone = std::numeric_limits<float>::infinity();

// Directions from a camera binned on the six faces of a cube: a face of n x n bins, each about
// 2 / n rad wide at the face's centre. Each bin keeps the nearest range [m] added in it.
class CubeMap {
 public:
  explicit CubeMap(double bin_rad)
      : n_(std::max(1, static_cast<int>(std::ceil(2.0 / bin_rad)))),
        range_(6 * static_cast<size_t>(n_) * n_, kNone) {}

  // Empties the bins that hold a range.
  void Clear() {
    for (const size_t i : filled_) range_[i] = kNone;
    filled_.clear();
  }

  // Adds a measurement at `d` [m] (camera to point, world frame).
  void Add(const Eigen::Vector3f& d) {
    const size_t i = Index(BinOf(d), 0, 0);
    const float r = d.norm();
    if (range_[i] == kNone) filled_.push_back(i);
    range_[i] = std::min(range_[i], r);
  }

  // The range in the bin of direction `d` and the nearest in its 3x3 neighbourhood (the face's
  // bins only); kNone where nothing was added.
  void Ranges(const Eigen::Vector3f& d, float* own, float* nearest) const {
    const Bin bin = BinOf(d);
    *own = range_[Index(bin, 0, 0)];
    *nearest = kNone;
    for (int dv = -1; dv <= 1; ++dv) {
      for (int du = -1; du <= 1; ++du) {
        const int u = bin.u + du, v = bin.v + dv;
        if (u < 0 || v < 0 || u >= n_ || v >= n_) continue;
        *nearest = std::min(*nearest, range_[Index(bin, du, dv)]);
      }
    }
  }

 private:
  struct Bin {
    int face, u, v;
  };

  Bin BinOf(const Eigen::Vector3f& d) const {
    int axis;
    d.cwiseAbs().maxCoeff(&axis);
    const float m = std::abs(d[axis]);
    const int face = 2 * axis + (d[axis] < 0.0f ? 1 : 0);
    const float a = d[(axis + 1) % 3] / m, b = d[(axis + 2) % 3] / m;  // in [-1, 1]
    const auto cell = [&](float t) {
      return std::min(n_ - 1, std::max(0, static_cast<int>((t + 1.0f) * 0.5f * n_)));
    };
    return {face, cell(a), cell(b)};
  }

  size_t Index(const Bin& bin, int du, int dv) const {
    return (static_cast<size_t>(bin.face) * n_ + (bin.v + dv)) * n_ + (bin.u + du);
  }

  int n_;
  std::vector<float> range_;
  std::vector<size_t> filled_;
};

}  // namespace

ViewVoteTolerance ViewVoteTolerance::From(const Config& config) {
  ViewVoteTolerance tolerance;
  tolerance.see_through = FreeSpaceTolerance::From(config.map, config.depth_noise.min_depth_m,
                                                   config.depth_noise.max_depth_m);
  tolerance.depth_noise = config.depth_noise;
  tolerance.voxel_size_m = config.map.voxel_size_m;
  return tolerance;
}

double ViewVoteTolerance::HitMargin(double range_m) const {
  return 0.5 * voxel_size_m + 2.0 * DepthSigma(range_m, depth_noise);
}

std::vector<RayVotes> VoteByViews(const std::vector<Eigen::Vector3f>& points_world,
                                  const std::vector<GridView>& views,
                                  const ViewVoteTolerance& tolerance, double bin_rad) {
  std::vector<RayVotes> votes(points_world.size());
  CubeMap bins(bin_rad);
  for (const GridView& view : views) {
    const Eigen::Vector3f camera = view.camera_world.cast<float>();
    bins.Clear();
    for (const Eigen::Vector3f& p : view.points_world) bins.Add(p - camera);
    for (size_t k = 0; k < points_world.size(); ++k) {
      const Eigen::Vector3f d = points_world[k] - camera;
      const float r = d.norm();
      if (!tolerance.see_through.InRange(r)) continue;
      float own, nearest;
      bins.Ranges(d, &own, &nearest);
      if (nearest == kNone) continue;
      const float margin = static_cast<float>(tolerance.see_through.Margin(r));
      if (nearest > r + margin) {
        ++votes[k].misses;
      } else if (std::abs(own - r) <= margin) {
        ++votes[k].hits;
        if (std::abs(own - r) <= tolerance.HitMargin(r)) ++votes[k].measured;
      }
    }
  }
  return votes;
}

}  // namespace dslam
