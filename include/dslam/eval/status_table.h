#pragma once
// The back end's part of the offline runner's outputs, written from the one field table
// BackEndStatus::Fields() (tracking/backend_status.h): the status CSV's back-end columns, the
// summary JSON's back-end quantiles, and the Markdown tables of docs/tools-and-data.md that
// describe both (printed by `dslam_config_doc --status-columns` / `--summary-keys`, written by
// scripts/update_readme.sh, checked by test/eval/status_table_test.cpp).

#include <string>
#include <vector>

#include "dslam/eval/json_writer.h"
#include "dslam/eval/run_statistics.h"
#include "dslam/tracking/backend_status.h"

namespace dslam {

/// The back-end column names of the status CSV, comma-separated in table order (no newline, no
/// leading comma).
std::string BackEndCsvHeader();

/// The back-end values of one status CSV row, comma-separated like BackEndCsvHeader(): counts in
/// decimal, times [ms] with 3 decimals ("%.3f"), flags as 0 / 1.
std::string BackEndCsvValues(const BackEndStatus& status);

/// Names of the fields whose quantiles the summary reports, in the summary's order.
std::vector<std::string> BackEndSummaryFields();

/// The values of the field `name` over the `runs` in which its stage ran (local BA for the
/// kLocalBa fields, window static point determination for kWindowSpd), in the order of `runs`.
/// Throws std::invalid_argument("unknown back-end field NAME") when `name` is no numeric field
/// of those stages (flags and window_keyframes have no quantiles).
std::vector<double> BackEndStageValues(const std::vector<BackEndStatus>& runs,
                                       const std::string& name);

/// Adds "median_<name>" and "p95_<name>" (RunSummary::BackEndQuantile at 0.5 and 0.95) for each
/// of BackEndSummaryFields(), in that order, with `significant_digits` [-].
void AddBackEndQuantiles(const RunSummary& summary, int significant_digits, JsonObject* json);

/// The Markdown table of the status CSV's back-end columns, one row per column in CSV order:
/// name, "stage: meaning [unit]". Lines end in '\n'.
std::string BackEndCsvMarkdown();

/// The Markdown table of the summary's back-end keys, one row per field in summary order: its
/// median_ and p95_ keys, "stage: meaning [unit]". Lines end in '\n'.
std::string BackEndSummaryMarkdown();

}  // namespace dslam
