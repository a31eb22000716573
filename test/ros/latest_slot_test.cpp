#include "dslam/ros/latest_slot.h"

#include <thread>

#include <gtest/gtest.h>

namespace dslam {
namespace ros_layer {
namespace {

TEST(LatestSlot, KeepsTheNewestAndCountsDrops) {
  LatestSlot<int> slot(1);
  EXPECT_FALSE(slot.Put(1));
  EXPECT_TRUE(slot.Put(2));
  EXPECT_TRUE(slot.Put(3));
  EXPECT_EQ(slot.dropped(), 2u);
  EXPECT_EQ(*slot.Take(), 3);
  EXPECT_FALSE(slot.Put(4));
  EXPECT_EQ(*slot.Take(), 4);
}

TEST(LatestSlot, AbsorbsABurstUpToItsCapacityInOrder) {
  LatestSlot<int> slot(2);
  EXPECT_FALSE(slot.Put(1));
  EXPECT_FALSE(slot.Put(2));  // a burst of two: nothing dropped
  EXPECT_TRUE(slot.Put(3));   // the third drops the oldest
  EXPECT_EQ(slot.dropped(), 1u);
  EXPECT_EQ(*slot.Take(), 2);
  EXPECT_EQ(*slot.Take(), 3);
}

TEST(LatestSlot, CloseWakesABlockedTake) {
  LatestSlot<int> slot;
  bool got_nothing = false;
  std::thread worker([&] { got_nothing = !slot.Take().has_value(); });
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  slot.Close();
  worker.join();
  EXPECT_TRUE(got_nothing);
}

}  // namespace
}  // namespace ros_layer
}  // namespace dslam
