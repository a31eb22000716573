#pragma once
// Which pixels of a keyframe belong to moving objects, so that the static map leaves them out.
// DynamicPixelMask is the one call the static mapper makes; today it draws a disc around each
// point the odometry unmarked (seen moving).

#include <vector>

#include <opencv2/core.hpp>

#include "dslam/backend/keyframe_observer.h"
#include "dslam/core/map_config.h"
#include "dslam/tracking/frame_result.h"

namespace dslam {

/// CV_8UC1 mask of `keyframe`'s images (their size): 255 on pixels of moving objects, 0 elsewhere
/// (DiscMask with config.mask_radius_px).
cv::Mat DynamicPixelMask(const KeyFrameRecord& keyframe, const MapConfig& config);

/// CV_8UC1 mask of `size`: 255 within `radius_px` [px] of the raw pixel (ObservedPoint::uv_raw) of
/// each point not marked static, 0 elsewhere.
cv::Mat DiscMask(const std::vector<ObservedPoint>& points, cv::Size size, int radius_px);

}  // namespace dslam
