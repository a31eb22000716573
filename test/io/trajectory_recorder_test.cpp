#include "dslam/io/trajectory_recorder.h"

#include <filesystem>

#include <gtest/gtest.h>

#include "dslam/io/private_folder.h"
#include "dslam/io/trajectory_io.h"

namespace dslam {
namespace {
namespace fs = std::filesystem;

StampedPose Pose(double stamp_s, double x) {
  StampedPose pose;
  pose.stamp_s = stamp_s;
  pose.T_world_camera.translation() = Eigen::Vector3d(x, 0.0, 0.0);
  return pose;
}

class TrajectoryRecorderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("dslam_recorder_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string Path(const std::string& name) const { return (dir_ / name).string(); }

  /// Two segments of 3 and 2 poses: time went back from 1002 to 500.
  static void Record(TrajectoryRecorder* recorder) {
    for (int i = 0; i < 3; ++i) recorder->Add(Pose(1000.0 + i, 0.1 * i));
    recorder->StartSegment();
    recorder->StartSegment();  // an empty segment is never started
    for (int i = 0; i < 2; ++i) recorder->Add(Pose(500.0 + i, 0.2 * i));
  }

  fs::path dir_;
};

TEST(SegmentPath, StemSegmentExtension) {
  EXPECT_EQ(SegmentPath("out/traj.txt", 1), "out/traj.seg1.txt");
  EXPECT_EQ(SegmentPath("traj.txt", 12), "traj.seg12.txt");
  EXPECT_EQ(SegmentPath("/a/b/trajectory", 2), "/a/b/trajectory.seg2");
  EXPECT_EQ(SegmentPath("/a/b.d/.hidden", 1), "/a/b.d/.hidden.seg1");
}

TEST_F(TrajectoryRecorderTest, InMemorySegmentsAreSavedBesideThePath) {
  TrajectoryRecorder recorder;
  Record(&recorder);
  EXPECT_EQ(recorder.num_segments(), 2);
  EXPECT_EQ(recorder.num_poses(), 5u);
  EXPECT_EQ(WriteTrajectorySnapshot(recorder.Snapshot(), Path("t.txt")), 5u);
  const Trajectory current = ReadTumTrajectory(Path("t.txt"));
  const Trajectory oldest = ReadTumTrajectory(Path("t.seg1.txt"));
  ASSERT_EQ(current.size(), 2u);
  ASSERT_EQ(oldest.size(), 3u);
  EXPECT_DOUBLE_EQ(current[1].stamp_s, 501.0);
  EXPECT_DOUBLE_EQ(oldest[2].T_world_camera.translation().x(), 0.2);
  EXPECT_FALSE(fs::exists(Path("t.seg2.txt")));
}

TEST_F(TrajectoryRecorderTest, StreamingKeepsNothingInMemoryAndSavesTheSameFiles) {
  TrajectoryRecorder memory, stream(Path("stream.txt"));
  Record(&memory);
  Record(&stream);
  // The stream is on disk as it goes: the earlier segment renamed, the current one growing.
  EXPECT_EQ(ReadTumTrajectory(Path("stream.seg1.txt")).size(), 3u);
  EXPECT_EQ(ReadTumTrajectory(Path("stream.txt")).size(), 2u);
  EXPECT_TRUE(stream.Snapshot().segments.empty());
  WriteTrajectorySnapshot(memory.Snapshot(), Path("m.txt"));
  EXPECT_EQ(WriteTrajectorySnapshot(stream.Snapshot(), Path("s.txt")), 5u);
  for (const char* name : {".txt", ".seg1.txt"}) {
    std::ifstream a(Path(std::string("m") + name)), b(Path(std::string("s") + name));
    const std::string text_a((std::istreambuf_iterator<char>(a)), {});
    const std::string text_b((std::istreambuf_iterator<char>(b)), {});
    EXPECT_EQ(text_a, text_b) << name;
    EXPECT_FALSE(text_a.empty());
  }
  // Saving onto the stream itself leaves it as it is.
  EXPECT_EQ(WriteTrajectorySnapshot(stream.Snapshot(), Path("stream.txt")), 5u);
  EXPECT_EQ(ReadTumTrajectory(Path("stream.txt")).size(), 2u);
}

TEST_F(TrajectoryRecorderTest, SnapshotIsUnaffectedByLaterPosesAndSegments) {
  TrajectoryRecorder stream(Path("stream.txt"));
  Record(&stream);
  const TrajectorySnapshot snapshot = stream.Snapshot();
  stream.Add(Pose(502.0, 0.4));  // after the snapshot, before writing
  stream.StartSegment();         // renames the file the snapshot holds open
  stream.Add(Pose(10.0, 0.0));
  EXPECT_EQ(WriteTrajectorySnapshot(snapshot, Path("s.txt")), 5u);
  EXPECT_EQ(ReadTumTrajectory(Path("s.txt")).size(), 2u);
  EXPECT_EQ(ReadTumTrajectory(Path("s.seg1.txt")).size(), 3u);
  EXPECT_EQ(stream.num_segments(), 3);
}

TEST_F(TrajectoryRecorderTest, StaleSegmentFilesOfAnEarlierSaveAreRemoved) {
  TrajectoryRecorder three;
  Record(&three);
  three.StartSegment();
  three.Add(Pose(5.0, 0.0));
  WriteTrajectorySnapshot(three.Snapshot(), Path("t.txt"));
  EXPECT_TRUE(fs::exists(Path("t.seg2.txt")));
  TrajectoryRecorder one;  // a restarted node saving to the same path
  one.Add(Pose(1.0, 0.0));
  WriteTrajectorySnapshot(one.Snapshot(), Path("t.txt"));
  EXPECT_FALSE(fs::exists(Path("t.seg1.txt")));
  EXPECT_FALSE(fs::exists(Path("t.seg2.txt")));
  EXPECT_EQ(ReadTumTrajectory(Path("t.txt")).size(), 1u);
}

TEST_F(TrajectoryRecorderTest, UnwritablePathsAreNamedErrors) {
  EXPECT_THROW(TrajectoryRecorder(Path("missing/dir/stream.txt")), std::runtime_error);
  TrajectoryRecorder recorder;
  recorder.Add(Pose(1.0, 0.0));
  try {
    WriteTrajectorySnapshot(recorder.Snapshot(), Path("missing/t.txt"));
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("missing/t.txt"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace dslam

namespace dslam {
namespace {

TEST(PrivateFolder, IsMadeUnderTheTemporaryFolderAndRemovedWithItsFiles) {
  std::string path;
  {
    const PrivateFolder a("dslam-test-");
    const PrivateFolder b("dslam-test-");
    path = a.path();
    EXPECT_NE(a.path(), b.path());
    EXPECT_TRUE(std::filesystem::is_directory(path));
    EXPECT_EQ(std::filesystem::path(path).filename().string().rfind("dslam-test-", 0), 0u);
    EXPECT_EQ(std::filesystem::status(path).permissions() & std::filesystem::perms::all,
              std::filesystem::perms::owner_all);
    // A streaming recorder inside it, as the node's default.
    TrajectoryRecorder recorder(path + "/trajectory.txt");
    recorder.Add({1.0, Eigen::Isometry3d::Identity()});
    recorder.StartSegment();
    recorder.Add({0.5, Eigen::Isometry3d::Identity()});
    EXPECT_TRUE(std::filesystem::exists(path + "/trajectory.seg1.txt"));
  }
  EXPECT_FALSE(std::filesystem::exists(path));
}

}  // namespace
}  // namespace dslam
