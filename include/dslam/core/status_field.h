#pragma once
// Field descriptions of the per-frame status (tracking/backend_status.h): one entry per reported
// field names it in every output (status CSV column, summary JSON key, FrameStatus.msg field),
// gives its unit, the stage it describes and its meaning. Visitors over a struct's Fields()
// write the status CSV, the summary quantiles and their documentation (eval/status_table.h), as
// the Config's Fields() drive its loaders and parameter tables (config_field.h).

namespace dslam {

/// The stage a status field describes; a summary quantile of the field is taken over the runs in
/// which that stage ran.
enum class StatusStage {
  kWindow,     ///< the keyframe window itself (no run of its own: no quantiles)
  kLocalBa,    ///< local bundle adjustment
  kWindowSpd,  ///< the back end's static point determination over the window
};

/// Outputs a status field appears in (bit flags of StatusFieldInfo::outputs; 0: none).
enum StatusOutput : unsigned {
  kStatusCsv = 1u,      ///< a status CSV column; the columns follow the order of the table
  kStatusMessage = 2u,  ///< a field of FrameStatus.msg; the fields follow the order of the table
};

/// Static description of one status field, passed to visitors beside a reference to its value
/// (bool, int or double).
struct StatusFieldInfo {
  const char* name;   ///< CSV column, FrameStatus.msg field and summary key stem, e.g. "ba_ms"
  const char* unit;   ///< unit of the value ("ms"; "-" for counts and flags)
  StatusStage stage;  ///< the stage it describes
  unsigned outputs;   ///< StatusOutput flags
  /// 0-based position of its quantiles (median_<name>, p95_<name>) among the summary's back-end
  /// keys; -1: not in the summary.
  int summary_rank;
  const char* doc;  ///< one-line meaning
};

/// Description of a status field (see StatusFieldInfo for the arguments).
inline StatusFieldInfo StatusField(const char* name, const char* unit, StatusStage stage,
                                   unsigned outputs, int summary_rank, const char* doc) {
  return StatusFieldInfo{name, unit, stage, outputs, summary_rank, doc};
}

}  // namespace dslam
