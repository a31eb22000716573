#include "dslam/eval/segmentation_score.h"

#include <cmath>

namespace dslam {
namespace {

// 1 = on a moving object, 0 = static, -1 = within `margin` of a mask edge or off the image.
int MaskClass(const cv::Mat& mask, const Eigen::Vector2d& uv, int margin) {
  const int u = static_cast<int>(std::lround(uv.x()));
  const int v = static_cast<int>(std::lround(uv.y()));
  if (u < margin || v < margin || u >= mask.cols - margin || v >= mask.rows - margin) return -1;
  const uint16_t centre = mask.at<uint16_t>(v, u);
  for (int dv = -margin; dv <= margin; ++dv) {
    for (int du = -margin; du <= margin; ++du) {
      if (mask.at<uint16_t>(v + dv, u + du) != centre) return -1;
    }
  }
  return centre != 0 ? 1 : 0;
}

double Ratio(long num, long den) { return den == 0 ? 1.0 : static_cast<double>(num) / den; }

}  // namespace

void SegmentationScore::Add(const std::vector<ObservedPoint>& points, const cv::Mat& mask) {
  for (const ObservedPoint& point : points) {
    const int truth = MaskClass(mask, point.uv_raw, margin_);
    if (truth < 0) {
      ++skipped_;
    } else if (point.is_candidate) {
      (truth == 1 ? cand_dyn_ : cand_static_)++;
    } else if (truth == 1) {
      (point.is_static ? fn_ : tp_)++;
    } else {
      (point.is_static ? tn_ : fp_)++;
    }
  }
}

void SegmentationScore::Merge(const SegmentationScore& other) {
  tp_ += other.tp_;
  fp_ += other.fp_;
  fn_ += other.fn_;
  tn_ += other.tn_;
  skipped_ += other.skipped_;
  cand_dyn_ += other.cand_dyn_;
  cand_static_ += other.cand_static_;
}

double SegmentationScore::Precision() const { return Ratio(tp_, tp_ + fp_); }
double SegmentationScore::Recall() const { return Ratio(tp_, tp_ + fn_); }
double SegmentationScore::FalseDynamicRate() const {
  return fp_ + tn_ == 0 ? 0.0 : Ratio(fp_, fp_ + tn_);
}

}  // namespace dslam
