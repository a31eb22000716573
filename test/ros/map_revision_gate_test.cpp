// MapRevisionGate: a map is published again only after its revision or its transform changed,
// never before the worker set a transform.
#include <gtest/gtest.h>

#include "dslam/ros/map_revision_gate.h"

namespace dslam {
namespace ros_layer {
namespace {

TEST(MapRevisionGate, PublishesOnlyWhatChanged) {
  MapRevisionGate gate;
  EXPECT_FALSE(gate.TakeChange(1));  // no transform yet
  EXPECT_FALSE(gate.WorldFrame());
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation().x() = 0.5;
  gate.SetWorldFrame(T);
  ASSERT_TRUE(gate.TakeChange(1));
  EXPECT_TRUE(gate.TakeChange(1) == std::nullopt);  // nothing changed
  const std::optional<Eigen::Isometry3d> next = gate.TakeChange(2);  // the map changed
  ASSERT_TRUE(next);
  EXPECT_EQ(next->translation().x(), 0.5);
  EXPECT_FALSE(gate.TakeChange(2));
  T.translation().x() = 0.7;  // a correction moved the published frame (odom_frame)
  gate.SetWorldFrame(T);
  ASSERT_TRUE(gate.TakeChange(2));
  EXPECT_EQ(gate.WorldFrame()->translation().x(), 0.7);
  EXPECT_FALSE(gate.TakeChange(2));
}

}  // namespace
}  // namespace ros_layer
}  // namespace dslam
