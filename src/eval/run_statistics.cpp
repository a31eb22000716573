#include "dslam/eval/run_statistics.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "dslam/eval/status_table.h"

namespace dslam {

std::string StatusCsvHeader() {
  return "frame,stamp,state,keyframe,features,features_with_depth,tracked,static,dynamic,"
         "candidates,"
         "pose_inliers,graph_points,graph_edges,culled_edges,map_points,new_points,"
         "pose_observations,pose_chi2_per_dof,"
         "features_ms,matching_ms,initial_pose_ms,static_points_ms,refine_ms,mapping_ms,total_ms,"
         "tracking_ms,backlog,backend_delivered," +
         BackEndCsvHeader();
}

std::string StatusCsvRow(const FrameResult& r) {
  const FrameCounts& c = r.counts;
  const StageTimes& t = r.times;
  char buffer[640];
  std::snprintf(buffer, sizeof(buffer),
                "%d,%.6f,%s,%d,%d,%d,%d,%d,%d,%d,%d,%d,%d,%d,%d,%d,%d,%.4f,"
                "%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%d,%d,",
                r.frame_index, r.stamp_s, ToString(r.state), r.keyframe ? 1 : 0, c.features,
                c.features_with_depth, c.tracked, c.static_points, c.dynamic_points,
                c.candidate_points, c.pose_inliers, c.graph_points, c.graph_edges, c.culled_edges,
                c.map_points, c.new_points, c.pose_observations, c.pose_chi2_per_dof, t.features_ms,
                t.matching_ms, t.initial_pose_ms, t.static_points_ms, t.refine_ms, t.mapping_ms,
                t.total_ms, t.tracking_ms, r.backend_thread.backlog,
                r.backend_thread.delivered ? 1 : 0);
  return buffer + BackEndCsvValues(r.backend);
}

void RunSummary::Add(const FrameResult& result) {
  ++frames_;
  if (result.has_pose) ++with_pose_;
  if (result.state == TrackingState::kLost) ++lost_;
  if (result.state == TrackingState::kLocalising) ++localising_;
  labelled_static_ += result.counts.static_points;
  labelled_dynamic_ += result.counts.dynamic_points;
  if (result.state == TrackingState::kTracking || result.state == TrackingState::kRecovered) {
    times_.push_back(result.times);
    graph_points_.push_back(result.counts.graph_points);
    // A run reported late (threaded) did not cost this frame.
    const bool own_run = !result.backend_thread.delivered;
    frame_ms_.push_back(result.times.total_ms +
                        (own_run ? result.backend.ba.time_ms + result.backend.spd.total_ms : 0.0));
    tracking_ms_.push_back(result.times.tracking_ms);
  }
  max_backlog_ = std::max(max_backlog_, result.backend_thread.backlog);
  AddBackEnd(result.backend);
}

void RunSummary::AddBackEnd(const BackEndStatus& status) {
  if (status.ba.ran || status.spd.ran) backend_.push_back(status);
}

double RunSummary::BackEndQuantile(const std::string& field, double fraction) const {
  return Quantile(BackEndStageValues(backend_, field), fraction);
}

double RunSummary::MedianMs(const std::string& stage) const {
  double StageTimes::*member = nullptr;
  if (stage == "features") member = &StageTimes::features_ms;
  if (stage == "matching") member = &StageTimes::matching_ms;
  if (stage == "initial_pose") member = &StageTimes::initial_pose_ms;
  if (stage == "static_points") member = &StageTimes::static_points_ms;
  if (stage == "refine") member = &StageTimes::refine_ms;
  if (stage == "mapping") member = &StageTimes::mapping_ms;
  if (stage == "total") member = &StageTimes::total_ms;
  if (member == nullptr) throw std::invalid_argument("unknown stage " + stage);
  std::vector<double> values;
  for (const StageTimes& t : times_) values.push_back(t.*member);
  return Median(values);
}

double RunSummary::MedianGraphPoints() const { return Median(graph_points_); }

double RunSummary::LabelledDynamicShare() const {
  const long all = labelled_static_ + labelled_dynamic_;
  return all == 0 ? 0.0 : static_cast<double>(labelled_dynamic_) / all;
}

void RunSummary::PrintStages(std::ostream& out) const {
  char line[160];
  out << "stage              median [ms]\n";
  for (const char* stage :
       {"features", "matching", "initial_pose", "static_points", "refine", "mapping", "total"}) {
    std::snprintf(line, sizeof(line), "%-18s %8.2f\n", stage, MedianMs(stage));
    out << line;
  }
  std::snprintf(line, sizeof(line), "median graph points %7.0f\n", MedianGraphPoints());
  out << line;
}

}  // namespace dslam
