// DetermineStaticPointsFrontEnd on a scene with a known answer: a static room of verified points
// and a cluster of new points (candidates) that moved 0.3 m between a reference frame and the
// current one, with and without the graph's point cap (static_points.max_graph_points).
#include "dslam/tracking/front_end_static_points.h"

#include <random>

#include <gtest/gtest.h>

namespace dslam {
namespace {

struct MovingClusterScene {
  static constexpr int kStatic = 300;
  static constexpr int kMoving = 60;
  Map map;
  std::vector<PointMatch> matches;
  FrameFeatures features;
  FrameMeasurements reference;  // an earlier frame, same camera pose, the cluster elsewhere

  MovingClusterScene() {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> x(-2.0, 2.0), y(-1.5, 1.5), z(2.0, 5.0);
    std::uniform_real_distribution<double> blob(-0.2, 0.2);
    const Eigen::Vector3d moved(0.3, 0.0, 0.0);
    for (int i = 0; i < kStatic + kMoving; ++i) {
      const bool moving = i >= kStatic;
      const Eigen::Vector3d p = moving
                                    ? Eigen::Vector3d(0.5 + blob(rng), blob(rng), 2.5 + blob(rng))
                                    : Eigen::Vector3d(x(rng), y(rng), z(rng));
      MapPoint point;
      point.p_world = p;  // the current camera is the world frame
      point.candidate = moving;
      const PointId id = map.AddPoint(point);
      PointMeasurement m;
      m.y_camera = p;
      m.covariance = Eigen::Matrix3d::Identity() * 1e-4;
      Feature f;
      f.uv_ideal = Eigen::Vector2d(320.0 + 525.0 * p.x() / p.z(), 240.0 + 525.0 * p.y() / p.z());
      f.uv_raw = f.uv_ideal;
      f.measurement = m;
      matches.push_back({id, static_cast<int>(features.features.size())});
      features.features.push_back(f);
      m.y_camera = moving ? Eigen::Vector3d(p - moved) : p;
      reference.by_point.emplace(id, m);
    }
  }

  // Share of the static points labelled static and of the moving ones labelled dynamic.
  std::pair<double, double> Scores(const FrontEndStaticPoints& out) const {
    int static_ok = 0, dynamic_ok = 0;
    for (size_t g = 0; g < out.graph_match.size(); ++g) {
      const bool moving = out.graph_match[g] >= kStatic;
      static_ok += !moving && out.result.labels[g] == PointLabel::kStatic;
      dynamic_ok += moving && out.result.labels[g] == PointLabel::kDynamic;
    }
    return {static_cast<double>(static_ok) / kStatic, static_cast<double>(dynamic_ok) / kMoving};
  }
};

TEST(FrontEndStaticPoints, CapBuildsTheGraphOverASubsetAndLabelsEveryPoint) {
  const MovingClusterScene scene;
  for (const int cap : {1000, 120}) {
    StaticPointsConfig config;
    config.max_graph_points = cap;
    const FrontEndStaticPoints out =
        DetermineStaticPointsFrontEnd(scene.map, scene.matches, scene.features,
                                      Eigen::Isometry3d::Identity(), {&scene.reference}, config);
    ASSERT_TRUE(out.ran);
    // Every match once, labels parallel to graph_match, edges only among the first `cap`.
    std::vector<int> sorted = out.graph_match;
    std::sort(sorted.begin(), sorted.end());
    ASSERT_EQ(sorted.size(), scene.matches.size()) << cap;
    for (size_t m = 0; m < sorted.size(); ++m) ASSERT_EQ(sorted[m], static_cast<int>(m));
    ASSERT_EQ(out.result.labels.size(), out.graph_match.size());
    const int graph_points = std::min(cap, static_cast<int>(scene.matches.size()));
    EXPECT_EQ(out.result.stats.points, graph_points);
    for (const GraphEdge& e : out.result.edges) ASSERT_LT(e.j, graph_points);
    const auto [static_share, dynamic_share] = scene.Scores(out);
    EXPECT_GE(static_share, 0.95) << cap;
    EXPECT_GE(dynamic_share, 0.9) << cap;
  }
}

}  // namespace
}  // namespace dslam
