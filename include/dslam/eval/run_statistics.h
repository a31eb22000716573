#pragma once
// Per-frame status rows (CSV) and run summaries of the offline runner and benchmarks.

#include <ostream>
#include <string>
#include <vector>

#include "dslam/eval/quantile.h"
#include "dslam/tracking/frame_result.h"

namespace dslam {

/// Header line of the status CSV (no newline).
std::string StatusCsvHeader();

/// One CSV row of a frame's state, counts and per-stage times [ms] (no newline).
std::string StatusCsvRow(const FrameResult& result);

/// Collects per-frame results for a summary.
class RunSummary {
 public:
  /// Adds one frame.
  void Add(const FrameResult& result);

  /// Adds a back-end run that no FrameResult reported (threaded mode: Slam::TakeUnreportedRuns
  /// at the end of a run).
  void AddBackEnd(const BackEndStatus& status);

  int frames() const { return frames_; }               ///< frames processed
  int frames_with_pose() const { return with_pose_; }  ///< frames with a reported pose
  int lost_frames() const { return lost_; }            ///< frames in state kLost
  /// Frames in state kLocalising (before a run that started in a loaded keyframe map found
  /// its place in it).
  int localising_frames() const { return localising_; }

  /// Writes a table of per-stage medians [ms] and counts (median points in the graph, ...).
  void PrintStages(std::ostream& out) const;

  /// Median [ms] of the stage named "features", "matching", "initial_pose", "static_points",
  /// "refine", "mapping" or "total" over the tracked frames.
  double MedianMs(const std::string& stage) const;

  /// Median number of points in the front-end graph over tracked frames.
  double MedianGraphPoints() const;

  /// Median [ms] of the whole frame over tracked frames: the front end plus, after keyframes,
  /// the back end (what a synchronous run spends per frame); with the back end on its own
  /// thread (BackEndThreadStatus::threaded), the front end only.
  double MedianFrameMs() const { return Median(frame_ms_); }

  /// The `fraction`-quantile [ms] of StageTimes::tracking_ms (the tracking thread's own time:
  /// lock wait, front end, bookkeeping) over tracked frames.
  double TrackingQuantile(double fraction) const { return Quantile(tracking_ms_, fraction); }

  /// [keyframes] The largest back-end backlog any frame reported (BackEndThreadStatus::backlog;
  /// 0 in synchronous mode).
  int max_backlog() const { return max_backlog_; }

  /// Keyframes after which the back end ran (local BA or back-end static point determination).
  int backend_runs() const { return static_cast<int>(backend_.size()); }

  /// The `fraction`-quantile of a numeric BackEndStatus field of local BA or of the window's
  /// static point determination, named as in BackEndStatus::Fields() ("ba_ms", "spd_points",
  /// ...), over the keyframes after which that stage ran (BackEndStageValues,
  /// eval/status_table.h; throws std::invalid_argument for other names).
  double BackEndQuantile(const std::string& field, double fraction) const;

  /// [-] Share of matched-point observations labelled dynamic (unmarked), over all frames: on a
  /// static scene, the share wrongly marked dynamic.
  double LabelledDynamicShare() const;

 private:
  int frames_ = 0, with_pose_ = 0, lost_ = 0, localising_ = 0;
  std::vector<StageTimes> times_;
  std::vector<double> frame_ms_, tracking_ms_;
  int max_backlog_ = 0;
  std::vector<BackEndStatus> backend_;
  std::vector<double> graph_points_;
  long labelled_static_ = 0, labelled_dynamic_ = 0;
};

}  // namespace dslam
