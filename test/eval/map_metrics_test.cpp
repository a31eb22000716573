// Tests of the voxel hashing (against brute force) and of the map measurement with hand-made
// reference clouds, frames and maps whose scores are known.
#include <random>

#include <gtest/gtest.h>

#include "dslam/eval/map_metrics.h"

namespace dslam {
namespace {

TEST(VoxelIndex, RadiusQueriesAgreeWithBruteForce) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> coord(-0.5, 0.5);
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < 400; ++i) points.emplace_back(coord(rng), coord(rng), coord(rng));
  points.emplace_back(std::nan(""), 0.0, 0.0);  // left out
  const double radius = 0.05;
  const RadiusIndex index(points, radius);
  EXPECT_EQ(index.size(), 400u);
  int hits = 0;
  for (int q = 0; q < 3000; ++q) {
    const Eigen::Vector3d query(coord(rng), coord(rng), coord(rng));
    bool brute = false;
    for (int i = 0; i < 400; ++i) brute = brute || (points[i] - query).norm() <= radius;
    ASSERT_EQ(index.AnyWithin(query), brute) << query.transpose();
    hits += brute;
  }
  EXPECT_GT(hits, 300);  // both answers occur often
  EXPECT_LT(hits, 2700);
  // A neighbour at 0.9 radius across a cell border in every axis.
  const RadiusIndex one({Eigen::Vector3d(0.001, 0.001, 0.001)}, radius);
  EXPECT_TRUE(one.AnyWithin(Eigen::Vector3d(-0.025, -0.025, -0.025)));
  EXPECT_FALSE(one.AnyWithin(Eigen::Vector3d(-0.03, -0.03, -0.03)));
}

TEST(VoxelIndex, DownsamplerKeepsOneCentroidPerVoxel) {
  VoxelDownsampler voxels(0.1);
  voxels.Add(Eigen::Vector3d(0.01, 0.02, 0.03));
  voxels.Add(Eigen::Vector3d(0.03, 0.04, 0.05));      // same voxel
  voxels.Add(Eigen::Vector3d(-0.01, 0.02, 0.03));     // x < 0: the voxel below
  voxels.Add(Eigen::Vector3d(0.0, std::nan(""), 0));  // ignored
  ASSERT_EQ(voxels.size(), 2u);
  const std::vector<Eigen::Vector3d> c = voxels.Centroids();
  EXPECT_TRUE(c[0].isApprox(Eigen::Vector3d(-0.01, 0.02, 0.03)));  // smaller key first
  EXPECT_TRUE(c[1].isApprox(Eigen::Vector3d(0.02, 0.03, 0.04)));
  EXPECT_THROW(VoxelDownsampler(0.0), std::invalid_argument);
  EXPECT_EQ(CellOf(Eigen::Vector3d(1e12, -1e12, 0.0), 0.01), Eigen::Vector3i(1048575, -1048576, 0));
}

/// Points of a square grid in the plane z = 0: x = x0 + i * step (i < nx), y = j * step (j < ny).
std::vector<Eigen::Vector3d> Grid(double x0, int nx, int ny, double step) {
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < nx; ++i) {
    for (int j = 0; j < ny; ++j) points.emplace_back(x0 + i * step, j * step, 0.0);
  }
  return points;
}

TEST(MapMetrics, GhostsCoverageAndStaticShareOfAHandMadeMap) {
  MapReference reference;
  reference.static_points = Grid(0.0, 101, 11, 0.01);  // 1 m x 0.1 m of floor
  reference.dynamic_points = {Eigen::Vector3d(2.0, 0.0, 1.0), Eigen::Vector3d(0.5, 0.05, 0.02)};
  // The map: the floor for x in [0.003, 0.503] (covers floor columns 0..55), a point at the
  // person far from the floor (a ghost), one at the person touching the floor (not a ghost: the
  // floor is within 5 cm) and one in empty space.
  std::vector<Eigen::Vector3d> map = Grid(0.003, 51, 11, 0.01);
  map.emplace_back(2.0, 0.01, 1.02);
  map.emplace_back(0.5, 0.05, 0.03);
  map.emplace_back(-1.0, -1.0, 2.0);
  map.emplace_back(std::nan(""), 0.0, 0.0);  // left out
  const MapMetrics m = EvaluateMap(map, reference, 0.05);
  EXPECT_EQ(m.map_points, 51u * 11u + 3u);
  EXPECT_EQ(m.ghost_points, 1u);
  EXPECT_DOUBLE_EQ(m.ghost_share, 1.0 / (51 * 11 + 3));
  EXPECT_EQ(m.near_static_points, 51u * 11u + 1u);
  EXPECT_EQ(m.static_reference_points, 101u * 11u);
  EXPECT_EQ(m.covered_static_points, 56u * 11u);
  EXPECT_DOUBLE_EQ(m.static_coverage, 56.0 / 101.0);
  const MapMetrics empty = EvaluateMap({}, reference, 0.05);
  EXPECT_EQ(empty.ghost_share, 0.0);
  EXPECT_EQ(empty.static_coverage, 0.0);
}

TEST(MapMetrics, ReferenceFromAFrameIsTheBackProjectedPlane) {
  // A 40 x 30 camera 2 m in front of a wall; the left half of the image sees a person at 1.5 m.
  const PinholeCamera camera(40, 30, 20.0, 20.0, 19.5, 14.5);
  cv::Mat depth(30, 40, CV_32FC1, cv::Scalar(2.0f)), mask(30, 40, CV_16UC1, cv::Scalar(0));
  depth(cv::Rect(0, 0, 20, 30)).setTo(1.5f);
  mask(cv::Rect(0, 0, 20, 30)).setTo(4);
  depth.at<float>(0, 38) = 0.0f;  // nothing hit
  depth.at<float>(2, 38) = 9.0f;  // beyond max_depth_m
  Eigen::Isometry3d T_world_camera = Eigen::Isometry3d::Identity();
  T_world_camera.translation() = Eigen::Vector3d(1.0, 2.0, 3.0);
  MapMetricsOptions options;
  options.voxel_m = 0.001;  // finer than the pixel footprint: one point per sampled pixel
  MapReferenceBuilder builder(options);
  builder.AddFrame(depth, mask, camera, T_world_camera);
  const MapReference reference = builder.Build();
  EXPECT_EQ(reference.frames, 1);
  // Pixel stride 2: 20 x 15 samples; 10 x 15 on the person, the rest on the wall minus two.
  EXPECT_EQ(reference.dynamic_points.size(), 150u);
  EXPECT_EQ(reference.static_points.size(), 148u);
  for (const Eigen::Vector3d& p : reference.static_points) EXPECT_NEAR(p.z(), 5.0, 1e-9);
  for (const Eigen::Vector3d& p : reference.dynamic_points) {
    EXPECT_NEAR(p.z(), 4.5, 1e-9);
    EXPECT_LT(p.x(), 1.0);  // left of the optical axis
  }
  EXPECT_THROW(builder.AddFrame(depth, cv::Mat(30, 40, CV_8UC1), camera, T_world_camera),
               std::invalid_argument);
}

}  // namespace
}  // namespace dslam
