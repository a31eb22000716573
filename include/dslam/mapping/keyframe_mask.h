#pragma once
// Which pixels of a keyframe belong to moving objects, so that the static map leaves them out:
// the one call the static mapper makes, the per-pixel dynamic mask of dynamic_mask.h grown from
// the keyframe's unmarked points.

#include <opencv2/core.hpp>

#include "dslam/backend/keyframe_observer.h"
#include "dslam/core/objects_config.h"

namespace dslam {

/// CV_8UC1 mask of `keyframe`'s images (their size): 255 on pixels of moving objects, 0 elsewhere
/// (ComputeDynamicMask of the keyframe's frame, pose and point labels, each cell's label on its
/// pixels; pixels beyond the last whole cell are 0).
cv::Mat DynamicPixelMask(const KeyFrameRecord& keyframe, const DynamicMaskConfig& config);

}  // namespace dslam
