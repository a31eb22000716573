// The truth files of a written sequence (objects.txt, depth_true/) read back by the measurements
// of part eval: the truth scored against itself is perfect, and the reference clouds of the map
// measurement separate the static world from the walkers.
#include <gtest/gtest.h>

#include <filesystem>

#include <opencv2/imgcodecs.hpp>

#include "dslam/eval/map_metrics.h"
#include "dslam/eval/object_metrics.h"
#include "dslam/io/dataset_io.h"
#include "dslam/io/trajectory_io.h"
#include "dslam/synth/object_truth.h"
#include "dslam/synth/writer.h"

namespace dslam {
namespace synth {
namespace {

class TruthFiles : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    root_ = (std::filesystem::temp_directory_path() / "dslam_truth_files_test").string();
    std::filesystem::remove_all(root_);
    sequence_ = std::make_unique<SyntheticSequence>(MakeScenario("walking", 1));
    WriteSequence(*sequence_, root_, kFrames);
  }
  static void TearDownTestSuite() {
    std::filesystem::remove_all(root_);
    sequence_.reset();
  }

  static constexpr int kFrames = 4;
  static std::string root_;
  static std::unique_ptr<SyntheticSequence> sequence_;
};

std::string TruthFiles::root_;
std::unique_ptr<SyntheticSequence> TruthFiles::sequence_;

TEST_F(TruthFiles, ObjectsAndNoiseFreeDepthRoundTrip) {
  const std::vector<TruthObject> read = ReadTruthObjects(root_ + "/objects.txt");
  const std::vector<StampedFile> depths = ReadFileList(root_ + "/depth_true.txt");
  ASSERT_EQ(depths.size(), static_cast<size_t>(kFrames));
  size_t line = 0;
  for (int i = 0; i < kFrames; ++i) {
    const SyntheticFrame f = sequence_->RenderFrame(i);
    EXPECT_EQ(depths[i].stamp_s, f.frame.stamp_s);
    const cv::Mat units = cv::imread(root_ + "/" + depths[i].path, cv::IMREAD_ANYDEPTH);
    ASSERT_EQ(units.type(), CV_16UC1);
    cv::Mat metres;
    units.convertTo(metres, CV_32FC1, 1.0 / 5000.0);
    EXPECT_LE(cv::norm(metres, f.depth_true_m, cv::NORM_INF), 0.5 / 5000.0 + 1e-6);
    for (const ObjectTruth& o : VisibleObjects(*sequence_, f)) {
      ASSERT_LT(line, read.size());
      const TruthObject& r = read[line++];
      EXPECT_EQ(r.stamp_s, f.frame.stamp_s);
      EXPECT_EQ(r.id, o.id);
      EXPECT_LT((r.position_m - o.centroid_world_m).norm(), 1e-5);
      EXPECT_LT((r.velocity_mps - o.velocity_world_mps).norm(), 1e-5);
      EXPECT_NEAR(r.pixel_share, o.pixel_share, 1e-6);
    }
  }
  EXPECT_EQ(line, read.size());
  EXPECT_GE(read.size(), static_cast<size_t>(kFrames));  // walking shows a walker in every frame
}

TEST_F(TruthFiles, TruthAsEstimateScoresPerfectly) {
  // The truth moved into the first frame's optical frame, as dslam_run_dataset writes estimates.
  const Trajectory groundtruth = ReadTumTrajectory(root_ + "/groundtruth.txt");
  const Eigen::Isometry3d T_world_first = groundtruth.front().T_world_camera;
  const std::vector<TruthObject> truth = ReadTruthObjects(root_ + "/objects.txt");
  std::vector<EstimatedObject> estimated;
  for (const TruthObject& t : truth) {
    EstimatedObject e;
    e.stamp_s = t.stamp_s;
    e.id = 100 + t.id;
    e.position_m = T_world_first.inverse() * t.position_m;
    e.velocity_mps = T_world_first.linear().transpose() * t.velocity_mps;
    estimated.push_back(e);
  }
  const ObjectMetrics m =
      EvaluateObjects(truth, estimated, groundtruth, T_world_first, ObjectMetricsOptions());
  ASSERT_GT(m.truth_object_frames, 0);
  EXPECT_EQ(m.found_share, 1.0);
  EXPECT_EQ(m.false_objects, 0);
  EXPECT_EQ(m.ignored_estimates + m.found, static_cast<long>(truth.size()));
  EXPECT_LT(m.centroid_error_median_m, 1e-9);
  EXPECT_LT(m.velocity_error_median_mps, 1e-9);
  EXPECT_EQ(m.id_switches, 0);
}

TEST_F(TruthFiles, MapReferenceSeparatesStaticWorldAndWalkers) {
  const MapMetricsOptions options;
  const MapReference reference = LoadMapReference(root_, options);
  EXPECT_EQ(reference.frames, kFrames);
  ASSERT_GT(reference.static_points.size(), 10000u);
  ASSERT_GT(reference.dynamic_points.size(), 1000u);
  // The static surface as a map: full coverage, no ghosts. The walkers as a map: ghosts but for
  // their points within 5 cm of static surface (soles on the floor; measured: 0.99994 ghosts,
  // 0.00013 coverage).
  const MapMetrics clean = EvaluateMap(reference.static_points, reference, options.radius_m);
  EXPECT_EQ(clean.static_coverage, 1.0);
  EXPECT_EQ(clean.ghost_points, 0u);
  EXPECT_EQ(clean.static_share, 1.0);
  const MapMetrics ghosts = EvaluateMap(reference.dynamic_points, reference, options.radius_m);
  EXPECT_GT(ghosts.ghost_share, 0.99);
  EXPECT_LT(ghosts.static_coverage, 0.01);
  // Static points lie inside the room (x in [-3, 3], y in [-2.8, 3.0], z in [0, 2.8] m).
  for (const Eigen::Vector3d& p : reference.static_points) {
    ASSERT_TRUE(p.x() >= -3.001 && p.x() <= 3.001 && p.y() >= -2.801 && p.y() <= 3.001 &&
                p.z() >= -0.001 && p.z() <= 2.801)
        << p.transpose();
  }
}

}  // namespace
}  // namespace synth
}  // namespace dslam
