#pragma once
// Scoring static/dynamic labels of tracked map points against ground-truth masks (synthetic
// scenes): every map point observed in a frame, with its label at the end of that frame, against
// the mask at its pixel; points within `edge_margin_px` of a mask edge are left out. Labels are
// static (marked and verified), dynamic (unmarked) or candidate (new, not yet verified: not used
// for the pose, not yet judged); precision and recall are over the judged points, and the share
// of candidates is reported per ground-truth class.

#include <vector>

#include <opencv2/core.hpp>

#include "dslam/tracking/frame_result.h"

namespace dslam {

/// Confusion counts of "dynamic" summed over frames.
class SegmentationScore {
 public:
  explicit SegmentationScore(int edge_margin_px = 2) : margin_(edge_margin_px) {}

  /// Adds the points of one frame. `mask` is CV_16UC1 (moving object id per pixel, 0 = static),
  /// indexed by the raw pixel of each point.
  void Add(const std::vector<ObservedPoint>& points, const cv::Mat& mask);

  /// Adds another score's counts (e.g. one frame's score to the run's).
  void Merge(const SegmentationScore& other);

  long true_dynamic() const { return tp_; }    ///< labelled dynamic, on a moving object
  long false_dynamic() const { return fp_; }   ///< labelled dynamic, on the static world
  long missed_dynamic() const { return fn_; }  ///< labelled static, on a moving object
  long true_static() const { return tn_; }     ///< labelled static, on the static world
  long skipped() const { return skipped_; }    ///< near a mask edge or outside the image
  long candidates_on_dynamic() const { return cand_dyn_; }    ///< not yet judged, on an object
  long candidates_on_static() const { return cand_static_; }  ///< not yet judged, static world

  /// [-] TP / (TP + FP); 1 when nothing was labelled dynamic.
  double Precision() const;
  /// [-] TP / (TP + FN); 1 when nothing was on a moving object.
  double Recall() const;
  /// [-] FP / (FP + TN): share of static-world points wrongly labelled dynamic.
  double FalseDynamicRate() const;

 private:
  int margin_;
  long tp_ = 0, fp_ = 0, fn_ = 0, tn_ = 0, skipped_ = 0, cand_dyn_ = 0, cand_static_ = 0;
};

}  // namespace dslam
