#include <gtest/gtest.h>

#include "dslam/eval/segmentation_score.h"

namespace dslam {
namespace {

ObservedPoint At(double u, double v, bool is_static) {
  ObservedPoint p;
  p.uv_raw = Eigen::Vector2d(u, v);
  p.is_static = is_static;
  return p;
}

TEST(SegmentationScore, CountsConfusionAndSkipsMaskEdges) {
  cv::Mat mask(40, 40, CV_16UC1, cv::Scalar(0));
  mask(cv::Rect(20, 0, 20, 40)).setTo(3);  // object 3 on the right half
  SegmentationScore score(2);
  score.Add({At(5, 5, true), At(6, 30, false),      // static world: TN, FP
             At(30, 10, false), At(30, 20, false),  // object: TP, TP
             At(33, 33, true),                      // object: FN
             At(19, 10, false), At(21, 10, true),   // within 2 px of the edge: skipped
             At(0, 0, true)},                       // image border: skipped
            mask);
  ObservedPoint candidate = At(30, 30, true);
  candidate.is_candidate = true;
  score.Add({candidate}, mask);
  EXPECT_EQ(score.candidates_on_dynamic(), 1);
  EXPECT_EQ(score.candidates_on_static(), 0);
  EXPECT_EQ(score.true_static(), 1);
  EXPECT_EQ(score.false_dynamic(), 1);
  EXPECT_EQ(score.true_dynamic(), 2);
  EXPECT_EQ(score.missed_dynamic(), 1);
  EXPECT_EQ(score.skipped(), 3);
  EXPECT_DOUBLE_EQ(score.Precision(), 2.0 / 3.0);
  EXPECT_DOUBLE_EQ(score.Recall(), 2.0 / 3.0);
  EXPECT_DOUBLE_EQ(score.FalseDynamicRate(), 0.5);
}

TEST(SegmentationScore, MergeAddsEveryCount) {
  cv::Mat mask(40, 40, CV_16UC1, cv::Scalar(0));
  mask(cv::Rect(20, 0, 20, 40)).setTo(1);
  SegmentationScore first, second, both;
  first.Add({At(5, 5, true), At(30, 10, false)}, mask);
  second.Add({At(6, 30, false), At(33, 33, true), At(0, 0, true)}, mask);
  both.Merge(first);
  both.Merge(second);
  EXPECT_EQ(both.true_static(), 1);
  EXPECT_EQ(both.true_dynamic(), 1);
  EXPECT_EQ(both.false_dynamic(), 1);
  EXPECT_EQ(both.missed_dynamic(), 1);
  EXPECT_EQ(both.skipped(), 1);
}

}  // namespace
}  // namespace dslam
