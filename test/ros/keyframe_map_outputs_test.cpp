// The keyframe map's outputs of the node (keyframe_map_outputs.h) from hand-made maps: the
// keyframes copied out of the map, the corrected keyframe path, the loop-edge markers, the loop
// status and the current segment of the refined trajectory.
#include "dslam/ros/keyframe_map_outputs.h"

#include <cmath>
#include <map>
#include <vector>

#include <gtest/gtest.h>

namespace dslam {
namespace ros_layer {
namespace {

Eigen::Isometry3d Pose(double x, double y, double z, double yaw_rad) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitY()).toRotationMatrix();
  T.translation() = Eigen::Vector3d(x, y, z);
  return T;
}

// A map of keyframes with ids 0, 3 and 7 (stamps 10 + id [s]), the newest two in the window, the
// oldest archived; keyframe id at (id, 0, 0) [m], turned by 0.1 id [rad].
Map ThreeKeyFrames() {
  MapContents contents;
  for (int id : {0, 3, 7}) {
    KeyFrame keyframe;
    keyframe.id = id;
    keyframe.stamp_s = 10.0 + id;
    keyframe.T_world_camera = Pose(id, 0.0, 0.0, 0.1 * id);
    contents.keyframes.push_back(keyframe);
  }
  Map map = Map::FromContents(contents);
  map.SetWindowTo({3, 7});
  return map;
}

void ExpectNear(const geometry_msgs::Point& p, const Eigen::Vector3d& expected) {
  EXPECT_NEAR(p.x, expected.x(), 1e-12);
  EXPECT_NEAR(p.y, expected.y(), 1e-12);
  EXPECT_NEAR(p.z, expected.z(), 1e-12);
}

std_msgs::Header MapHeader() {
  std_msgs::Header header;
  header.frame_id = "map";
  header.stamp.fromSec(20.0);
  return header;
}

TEST(KeyFrameMapOutputs, ViewsListWindowAndArchiveOldestFirstAtCurrentPoses) {
  Map map = ThreeKeyFrames();
  ASSERT_EQ(map.archived_keyframes().size(), 1u);
  map.CorrectKeyFrames({{3, Pose(3.0, 0.5, 0.0, 0.0)}, {7, Pose(7.0, 0.5, 0.0, 0.0)}});
  const std::vector<KeyFrameView> views = KeyFrameViews(map);
  ASSERT_EQ(views.size(), 3u);
  EXPECT_EQ(views[0].id, 0);
  EXPECT_EQ(views[1].id, 3);
  EXPECT_EQ(views[2].id, 7);
  EXPECT_DOUBLE_EQ(views[2].stamp_s, 17.0);
  EXPECT_TRUE(views[0].T_world_camera.isApprox(Pose(0.0, 0.0, 0.0, 0.0)));
  EXPECT_TRUE(views[1].T_world_camera.isApprox(Pose(3.0, 0.5, 0.0, 0.0)));  // corrected
}

TEST(KeyFrameMapOutputs, PathGivesTheBasePoseOfEachKeyFrameInTheHeaderFrame) {
  const std::vector<KeyFrameView> views = KeyFrameViews(ThreeKeyFrames());
  const Eigen::Isometry3d T_frame_world = Pose(0.0, 0.0, 1.0, 0.3);
  const Eigen::Isometry3d T_base_camera = Pose(0.1, 0.0, 0.2, -0.5);
  const nav_msgs::Path path = MakeKeyFramePath(views, T_frame_world, T_base_camera, MapHeader());
  EXPECT_EQ(path.header.frame_id, "map");
  EXPECT_DOUBLE_EQ(path.header.stamp.toSec(), 20.0);
  ASSERT_EQ(path.poses.size(), 3u);
  for (size_t i = 0; i < views.size(); ++i) {
    const geometry_msgs::PoseStamped& pose = path.poses[i];
    EXPECT_EQ(pose.header.frame_id, "map");
    EXPECT_NEAR(pose.header.stamp.toSec(), views[i].stamp_s, 1e-9);
    const Eigen::Isometry3d expected =
        T_frame_world * views[i].T_world_camera * T_base_camera.inverse();
    ExpectNear(pose.pose.position, expected.translation());
    const Eigen::Quaterniond q(pose.pose.orientation.w, pose.pose.orientation.x,
                               pose.pose.orientation.y, pose.pose.orientation.z);
    EXPECT_LT(q.angularDistance(Eigen::Quaterniond(expected.rotation())), 1e-9);
  }
  EXPECT_TRUE(MakeKeyFramePath({}, T_frame_world, T_base_camera, MapHeader()).poses.empty());
}

TEST(KeyFrameMapOutputs, LoopEdgesJoinCameraCentresAndSkipErasedKeyFrames) {
  const std::vector<KeyFrameView> views = KeyFrameViews(ThreeKeyFrames());
  const Eigen::Isometry3d T_frame_world = Pose(0.0, 0.0, 1.0, 0.3);
  // Loop 7 -> 0 is drawn; loop 5 -> 3 is not: keyframe 5 is not in the map.
  const visualization_msgs::MarkerArray markers =
      MakeLoopEdgeMarkers({{7, 0}, {5, 3}}, views, T_frame_world, MapHeader());
  ASSERT_EQ(markers.markers.size(), 1u);
  const visualization_msgs::Marker& lines = markers.markers[0];
  EXPECT_EQ(lines.header.frame_id, "map");
  EXPECT_EQ(lines.ns, "loops");
  EXPECT_EQ(lines.type, visualization_msgs::Marker::LINE_LIST);
  EXPECT_EQ(lines.action, visualization_msgs::Marker::ADD);
  EXPECT_GT(lines.scale.x, 0.0);
  EXPECT_GT(lines.color.a, 0.0f);
  ASSERT_EQ(lines.points.size(), 2u);
  ExpectNear(lines.points[0], T_frame_world * Eigen::Vector3d(7.0, 0.0, 0.0));
  ExpectNear(lines.points[1], T_frame_world * Eigen::Vector3d(0.0, 0.0, 0.0));
}

TEST(KeyFrameMapOutputs, NoLoopLeftIsADeleteOfTheLines) {
  const std::vector<KeyFrameView> views = KeyFrameViews(ThreeKeyFrames());
  for (const std::vector<LoopKeyFrames>& loops :
       {std::vector<LoopKeyFrames>{}, std::vector<LoopKeyFrames>{{9, 0}}}) {
    const visualization_msgs::MarkerArray markers =
        MakeLoopEdgeMarkers(loops, views, Eigen::Isometry3d::Identity(), MapHeader());
    ASSERT_EQ(markers.markers.size(), 1u);
    EXPECT_EQ(markers.markers[0].action, visualization_msgs::Marker::DELETE);
    EXPECT_EQ(markers.markers[0].ns, "loops");
    EXPECT_TRUE(markers.markers[0].points.empty());
  }
}

TEST(KeyFrameMapOutputs, LoopKeyFramesAndStatusOfClosedLoops) {
  std::vector<ClosedLoop> loops(2);
  loops[0].detection.query_keyframe_id = 40;
  loops[0].detection.match_keyframe_id = 2;
  loops[1].detection.query_keyframe_id = 90;
  loops[1].detection.match_keyframe_id = 11;
  const std::vector<LoopKeyFrames> ids = LoopKeyFramesOf(loops);
  ASSERT_EQ(ids.size(), 2u);
  EXPECT_EQ(ids[1].query_id, 90);
  EXPECT_EQ(ids[1].match_id, 11);
  const LoopStatus status = SummariseLoops(LoopWork{2, 3, 4.25});
  EXPECT_EQ(status.loop_closures, 2);
  EXPECT_EQ(status.loop_keyframes, 3);
  EXPECT_DOUBLE_EQ(status.loop_ms, 4.25);  // the newest keyframe's
  const LoopStatus none = SummariseLoops(LoopWork());
  EXPECT_EQ(none.loop_closures, 0);
  EXPECT_EQ(none.loop_keyframes, 0);
  EXPECT_EQ(none.loop_ms, 0.0);
}

Trajectory Stamped(const std::vector<double>& stamps) {
  Trajectory poses;
  for (double stamp : stamps) poses.push_back({stamp, Pose(stamp, 0.0, 0.0, 0.0)});
  return poses;
}

std::vector<double> Stamps(const Trajectory& poses) {
  std::vector<double> stamps;
  for (const StampedPose& pose : poses) stamps.push_back(pose.stamp_s);
  return stamps;
}

TEST(KeyFrameMapOutputs, CurrentSegmentIsTheLastRunFromItsFirstStamp) {
  using List = std::vector<double>;
  // One segment: all of it.
  EXPECT_EQ(Stamps(CurrentSegment(Stamped({1, 2, 3}), 1)), List({1, 2, 3}));
  // Time went backwards at 1.5 (a bag played again): the newer segment alone.
  EXPECT_EQ(Stamps(CurrentSegment(Stamped({1, 2, 3, 1.5, 2.5}), 1.5)), List({1.5, 2.5}));
  // The same stamps twice: the second run.
  EXPECT_EQ(Stamps(CurrentSegment(Stamped({1, 2, 3, 1, 2, 3, 4}), 1)), List({1, 2, 3, 4}));
  // A new world whose stamps did not go below the old segment's last tracked one (the old run
  // was lost at its end): the first stamp separates them.
  EXPECT_EQ(Stamps(CurrentSegment(Stamped({1, 2, 3, 5, 6}), 5)), List({5, 6}));
  EXPECT_TRUE(CurrentSegment({}, 1).empty());
  EXPECT_TRUE(CurrentSegment(Stamped({1, 2}), 3).empty());
}

}  // namespace
}  // namespace ros_layer
}  // namespace dslam
