// PointCarrier on hand-made frames: a textured box (seeded random texture, blurred) at 2 m
// moves 12 px to the right in front of a textured wall at 3 m. The first frame's region holds
// points on the box; the second frame's region covers the moved box but the front end matched
// none of them: the carrier must find them 12 px to the right, at the box's depth.
#include "dslam/mapping/point_carrier.h"

#include <memory>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

namespace dslam {
namespace {

constexpr int kWidth = 640, kHeight = 480, kDecimation = 4, kShiftPx = 12;
const cv::Rect kBox(200, 152, 100, 100);  ///< the box in the first frame [px]

cv::Mat Texture(uint64_t seed, cv::Size size) {
  cv::Mat texture(size, CV_8UC1);
  cv::RNG rng(seed);
  rng.fill(texture, cv::RNG::UNIFORM, 0, 256);
  // Smooth enough that the flow's coarse pyramid levels see it (pixel noise would alias there).
  cv::GaussianBlur(texture, texture, cv::Size(0, 0), 4.0);
  cv::normalize(texture, texture, 0, 255, cv::NORM_MINMAX);
  return texture;
}

/// The frame with the box shifted `shift_px` to the right (box texture and depth move along).
RgbdFrame MakeFrame(int shift_px, double stamp_s) {
  static const cv::Mat wall = Texture(1, cv::Size(kWidth, kHeight));
  static const cv::Mat box = Texture(2, kBox.size());
  RgbdFrame frame;
  frame.stamp_s = stamp_s;
  frame.camera = std::make_shared<PinholeCamera>(kWidth, kHeight, 525, 525, 319.5, 239.5);
  frame.colour = wall.clone();
  frame.depth_m = cv::Mat(kHeight, kWidth, CV_32FC1, cv::Scalar(3.0f));
  const cv::Rect moved = kBox + cv::Point(shift_px, 0);
  box.copyTo(frame.colour(moved));
  frame.depth_m(moved).setTo(2.0f);
  return frame;
}

/// The camera's pose in both frames (it stands still; the box moves).
Eigen::Isometry3d CameraPose() {
  Eigen::Isometry3d T_world_camera = Eigen::Isometry3d::Identity();
  T_world_camera.translation() = Eigen::Vector3d(1.0, 0.0, 0.0);
  return T_world_camera;
}

/// A mask with one region over pixel rectangle `rect`, holding `points` (with their cells and
/// their positions at 2 m, world frame).
DynamicMask MaskOver(const cv::Rect& rect, const RgbdFrame& frame,
                     const std::vector<ObservedPoint>& points) {
  DynamicMask mask;
  mask.decimation = kDecimation;
  mask.labels = cv::Mat(kHeight / kDecimation, kWidth / kDecimation, CV_16UC1, cv::Scalar(0));
  const cv::Rect cells(rect.x / kDecimation, rect.y / kDecimation, rect.width / kDecimation,
                       rect.height / kDecimation);
  mask.labels(cells).setTo(1);
  DynamicRegion region;
  region.label = 1;
  region.cells = cells.area();
  for (const ObservedPoint& point : points) {
    region.points.push_back(point.id);
    region.points_world.push_back(CameraPose() * frame.camera->BackProject(point.uv_raw, 2.0));
    region.point_cells.push_back(static_cast<int>(point.uv_raw.y()) / kDecimation *
                                     mask.labels.cols +
                                 static_cast<int>(point.uv_raw.x()) / kDecimation);
  }
  mask.regions.push_back(region);
  return mask;
}

/// Unmarked points on a 4 x 4 grid inside the first frame's box, ids 1..16.
std::vector<ObservedPoint> BoxPoints() {
  std::vector<ObservedPoint> points;
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 4; ++i) {
      ObservedPoint point;
      point.id = static_cast<PointId>(points.size() + 1);
      point.uv_raw = Eigen::Vector2d(222 + 18 * i, 174 + 18 * j);
      point.is_static = false;
      points.push_back(point);
    }
  }
  return points;
}

class PointCarrierTest : public ::testing::Test {
 protected:
  PointCarrierTest() : carrier_(ObjectsConfig(), DynamicMaskConfig()) {
    first_ = MakeFrame(0, 0.0);
    second_ = MakeFrame(kShiftPx, 1.0 / 30.0);
    DynamicMask first_mask = MaskOver(kBox, first_, BoxPoints());
    EXPECT_EQ(carrier_.Carry(first_, CameraPose(), BoxPoints(), &first_mask), 0);
  }

  PointCarrier carrier_;
  RgbdFrame first_, second_;
};

TEST_F(PointCarrierTest, LostPointsAreFoundWhereTheBoxMovedAtItsDepth) {
  DynamicMask mask = MaskOver(kBox + cv::Point(kShiftPx, 0), second_, {});
  ASSERT_EQ(carrier_.Carry(second_, CameraPose(), {}, &mask), 16);
  const DynamicRegion& region = mask.regions[0];
  const std::vector<ObservedPoint> before = BoxPoints();
  for (size_t i = 0; i < region.points.size(); ++i) {
    const ObservedPoint& point = before[region.points[i] - 1];
    const Eigen::Vector3d expected =
        CameraPose() *
        second_.camera->BackProject(point.uv_raw + Eigen::Vector2d(kShiftPx, 0.0), 2.0);
    // 0.1 px at 2 m is 0.4 mm.
    EXPECT_LT((region.points_world[i] - expected).norm(), 4e-4) << "point " << region.points[i];
    EXPECT_GE(region.point_cells[i], 0);
  }
}

TEST_F(PointCarrierTest, PointsTheFrontEndMatchedAreNotCarried) {
  DynamicMask mask = MaskOver(kBox + cv::Point(kShiftPx, 0), second_, {});
  ObservedPoint matched = BoxPoints()[0];
  matched.uv_raw.x() += kShiftPx;
  matched.is_static = true;  // matched and marked: no longer a region point, not carried either
  EXPECT_EQ(carrier_.Carry(second_, CameraPose(), {matched}, &mask), 15);
  for (PointId id : mask.regions[0].points) EXPECT_NE(id, matched.id);
}

TEST_F(PointCarrierTest, PointsLandingOutsideTheMaskAreDropped) {
  // The region covers only the left part of the moved box (x < 260): the last two points of
  // each row (moved to x = 270 and 288) land on unmasked cells.
  const cv::Rect left_half(kBox.x + kShiftPx, kBox.y, 48, kBox.height);
  DynamicMask mask = MaskOver(left_half, second_, {});
  EXPECT_EQ(carrier_.Carry(second_, CameraPose(), {}, &mask), 8);
}

TEST_F(PointCarrierTest, PointsLandingWithoutDepthOrOnAnOccupiedCellAreDropped) {
  DynamicMask mask = MaskOver(kBox + cv::Point(kShiftPx, 0), second_, {});
  // No depth where point 1 lands; point 2's cell already holds a point of this frame.
  second_.depth_m.at<float>(174, 222 + kShiftPx) = 0.0f;
  mask.regions[0].points.push_back(100);
  mask.regions[0].points_world.push_back(Eigen::Vector3d::Zero());
  mask.regions[0].point_cells.push_back(174 / kDecimation * mask.labels.cols +
                                        (240 + kShiftPx) / kDecimation);
  EXPECT_EQ(carrier_.Carry(second_, CameraPose(), {}, &mask), 14);
}

TEST_F(PointCarrierTest, PointsWhoseDepthJumpedToAnotherSurfaceAreDropped) {
  DynamicMask mask = MaskOver(kBox + cv::Point(kShiftPx, 0), second_, {});
  // Point 1 lands where the depth is now 1 m farther (e.g. the wall behind at an occlusion
  // border): 30 m/s in 1/30 s, beyond max_point_speed_mps.
  second_.depth_m.at<float>(174, 222 + kShiftPx) = 3.0f;
  EXPECT_EQ(carrier_.Carry(second_, CameraPose(), {}, &mask), 15);
}

TEST_F(PointCarrierTest, ResetForgetsThePreviousFrame) {
  carrier_.Reset();
  DynamicMask mask = MaskOver(kBox + cv::Point(kShiftPx, 0), second_, {});
  EXPECT_EQ(carrier_.Carry(second_, CameraPose(), {}, &mask), 0);
  EXPECT_TRUE(mask.regions[0].points.empty());
}

TEST_F(PointCarrierTest, AFrameOfAnotherSizeCarriesNothing) {
  RgbdFrame small;
  small.stamp_s = second_.stamp_s;
  small.camera = std::make_shared<PinholeCamera>(320, 240, 262.5, 262.5, 159.5, 119.5);
  cv::resize(second_.colour, small.colour, cv::Size(320, 240));
  cv::resize(second_.depth_m, small.depth_m, cv::Size(320, 240), 0, 0, cv::INTER_NEAREST);
  DynamicMask mask;
  mask.decimation = kDecimation;
  mask.labels = cv::Mat(240 / kDecimation, 320 / kDecimation, CV_16UC1, cv::Scalar(1));
  mask.regions.resize(1);
  mask.regions[0].label = 1;
  EXPECT_EQ(carrier_.Carry(small, CameraPose(), {}, &mask), 0);
}

TEST_F(PointCarrierTest, CarriedPointsAreCarriedAgainInTheNextFrame) {
  DynamicMask mask = MaskOver(kBox + cv::Point(kShiftPx, 0), second_, {});
  ASSERT_EQ(carrier_.Carry(second_, CameraPose(), {}, &mask), 16);
  const RgbdFrame third = MakeFrame(2 * kShiftPx, 2.0 / 30.0);
  DynamicMask third_mask = MaskOver(kBox + cv::Point(2 * kShiftPx, 0), third, {});
  EXPECT_EQ(carrier_.Carry(third, CameraPose(), {}, &third_mask), 16);
}

}  // namespace
}  // namespace dslam
