#pragma once
// Joining the dynamic-mask regions that are parts of one moving thing. A region grows only
// within DynamicMaskConfig::margin_m of its seed points' box (dynamic_mask.h), so a person whose
// unmarked points lie on the head and torso and on the feet, with none between, becomes two
// regions one above the other when the seed boxes are too far apart for the two growths to meet.
// As separate observations the lower part is a second, false object and the person's centroid is
// off by a quarter of their height.
//
// Two regions are joined (JoinStackedRegions) when
// - their cell column ranges in the image overlap by more than ObjectsConfig::split_max_overlap
//   of the narrower range (one above the other: the side-by-side test that region_split.h
//   requires before splitting, reversed; the split measures the overlap on its parts' 10th-90th
//   percentile ranges of optical x, the join on the full column ranges, so two split parts can be
//   joined again when their full ranges overlap by more than their percentile ranges do), and
// - their world boxes come within DynamicMaskConfig::margin_m of each other along every axis
//   (two people one behind the other overlap in the image but are a body's depth apart).

#include "dslam/core/objects_config.h"
#include "dslam/mapping/dynamic_mask.h"

namespace dslam {

/// Joins the stacked regions of `mask` (see above): the later region's cells, points and
/// statistics go to the earlier one; the remaining regions are relabelled 1..n in order.
/// Returns the number of joins.
int JoinStackedRegions(const DynamicMaskConfig& mask_config, const ObjectsConfig& objects_config,
                       DynamicMask* mask);

}  // namespace dslam
