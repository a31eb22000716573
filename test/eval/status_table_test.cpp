// The one table of the back end's reported fields (BackEndStatus::Fields()) against what reads
// its outputs: the status CSV's columns and the summary's keys keep their names and order
// (scripts and older builds read them), msg/FrameStatus.msg carries the table's message fields,
// and docs/tools-and-data.md's tables are generated from it.
#include <algorithm>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "dslam/eval/run_statistics.h"
#include "dslam/eval/status_table.h"
#include "support/generated_block.h"
#include "support/message_fields.h"

namespace dslam {
namespace {

std::vector<std::string> Split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::stringstream in(text);
  for (std::string part; std::getline(in, part, separator);) parts.push_back(part);
  return parts;
}

TEST(StatusTable, CsvColumnsKeepTheirNamesAndOrder) {
  EXPECT_EQ(
      StatusCsvHeader(),
      "frame,stamp,state,keyframe,features,features_with_depth,tracked,static,dynamic,"
      "candidates,pose_inliers,graph_points,graph_edges,culled_edges,map_points,new_points,"
      "pose_observations,pose_chi2_per_dof,"
      "features_ms,matching_ms,initial_pose_ms,static_points_ms,refine_ms,mapping_ms,"
      "total_ms,tracking_ms,backlog,backend_delivered,window_keyframes,ba_points,"
      "ba_measurements,ba_outliers,ba_iterations,ba_chi2_per_dof,ba_inlier_chi2_per_dof,ba_ms,"
      "spd_points,spd_culled_edges,spd_unmarked,spd_ms");
}

TEST(StatusTable, SummaryKeysKeepTheirNamesAndOrder) {
  EXPECT_EQ(BackEndSummaryFields(),
            (std::vector<std::string>{
                "ba_ms", "ba_keyframes", "ba_points", "ba_outliers", "ba_iterations", "spd_ms",
                "spd_graph_ms", "spd_culling_ms", "spd_components_ms", "spd_points", "spd_edges",
                "spd_culled_edges", "spd_unmarked", "ba_chi2_per_dof", "ba_inlier_chi2_per_dof"}));
  JsonObject json;
  AddBackEndQuantiles(RunSummary(), 6, &json);
  const std::string text = json.ToString();
  EXPECT_LT(text.find("\"median_ba_ms\": 0,\n  \"p95_ba_ms\": 0,\n  \"median_ba_keyframes\""),
            text.size());
}

TEST(StatusTable, NamesAreUniqueAndSummaryRanksCountFromZero) {
  std::set<std::string> names;
  std::vector<int> ranks;
  const BackEndStatus status;
  BackEndStatus::Fields(status, [&](const StatusFieldInfo& info, const auto&) {
    EXPECT_TRUE(names.insert(info.name).second) << info.name;
    if (info.summary_rank >= 0) ranks.push_back(info.summary_rank);
  });
  std::sort(ranks.begin(), ranks.end());
  for (size_t i = 0; i < ranks.size(); ++i) EXPECT_EQ(ranks[i], static_cast<int>(i));
}

// Each field set to a distinct value; its CSV text by name.
std::map<std::string, std::string> DistinctValues(BackEndStatus* status) {
  std::map<std::string, std::string> text;
  int k = 0;
  BackEndStatus::Fields(*status, [&](const StatusFieldInfo& info, auto& value) {
    using T = std::decay_t<decltype(value)>;
    ++k;
    value = static_cast<T>(k + 0.25);  // a flag: true
    if constexpr (std::is_same<T, double>::value) {
      text[info.name] = std::to_string(k) + ".250";
    } else {
      text[info.name] = std::to_string(static_cast<int>(value));
    }
  });
  return text;
}

TEST(StatusTable, CsvValuesFollowTheHeader) {
  BackEndStatus status;
  const std::map<std::string, std::string> expected = DistinctValues(&status);
  const std::vector<std::string> columns = Split(BackEndCsvHeader(), ',');
  const std::vector<std::string> values = Split(BackEndCsvValues(status), ',');
  ASSERT_EQ(columns.size(), values.size());
  for (size_t i = 0; i < columns.size(); ++i) EXPECT_EQ(values[i], expected.at(columns[i]));
  EXPECT_EQ(BackEndCsvValues(BackEndStatus()), "0,0,0,0,0,0.000,0.000,0.000,0,0,0,0.000");
}

TEST(StatusTable, SummaryCountsLostAndLocalisingFramesApart) {
  RunSummary summary;
  FrameResult result;
  result.state = TrackingState::kLocalising;
  summary.Add(result);
  summary.Add(result);
  result.state = TrackingState::kLost;
  summary.Add(result);
  result.state = TrackingState::kTracking;
  result.has_pose = true;
  summary.Add(result);
  EXPECT_EQ(summary.frames(), 4);
  EXPECT_EQ(summary.localising_frames(), 2);
  EXPECT_EQ(summary.lost_frames(), 1);
  EXPECT_EQ(summary.frames_with_pose(), 1);
}

TEST(StatusTable, QuantilesAreOverTheRunsOfTheirStage) {
  BackEndStatus ba, spd;
  ba.ba.ran = true;
  ba.ba.time_ms = 4.0;
  ba.spd.total_ms = 100.0;  // did not run: left out
  spd.spd.ran = true;
  spd.spd.total_ms = 2.0;
  spd.spd.graph.points = 30;
  RunSummary summary;
  summary.AddBackEnd(ba);
  summary.AddBackEnd(spd);
  summary.AddBackEnd(BackEndStatus());  // neither ran: not a run
  EXPECT_EQ(summary.backend_runs(), 2);
  EXPECT_EQ(summary.BackEndQuantile("ba_ms", 0.5), 4.0);
  EXPECT_EQ(summary.BackEndQuantile("spd_ms", 0.5), 2.0);
  EXPECT_EQ(summary.BackEndQuantile("spd_points", 0.5), 30.0);
  EXPECT_EQ(summary.BackEndQuantile("ba_measurements", 0.5), 0.0);
  for (const char* name : {"window_keyframes", "backend_ran", "spd_ran", "ba_rejected", "x"}) {
    EXPECT_THROW(summary.BackEndQuantile(name, 0.5), std::invalid_argument) << name;
    EXPECT_THROW(RunSummary().BackEndQuantile(name, 0.5), std::invalid_argument) << name;
  }
}

const char* MessageType(bool) { return "bool"; }
const char* MessageType(int) { return "int32"; }
const char* MessageType(double) { return "float64"; }

// The back-end fields of FrameStatus.msg lie between the stage times (tracking_ms) and the
// threaded mode's fields (backend_delivered): the table's message fields, in its order, with
// the types of its values.
TEST(StatusTable, FrameStatusMessageCarriesTheTablesFields) {
  const auto fields = test::MessageFields("msg/FrameStatus.msg");
  auto first = fields.begin(), last = fields.end();
  for (auto it = fields.begin(); it != fields.end(); ++it) {
    if (it->second == "tracking_ms") first = it + 1;
    if (it->second == "backend_delivered") last = it;
  }
  ASSERT_TRUE(first != fields.begin() && last != fields.end() && first <= last);
  using Fields = std::vector<std::pair<std::string, std::string>>;
  Fields expected;
  const BackEndStatus status;
  BackEndStatus::Fields(status, [&](const StatusFieldInfo& info, const auto& value) {
    if (info.outputs & kStatusMessage) expected.emplace_back(MessageType(value), info.name);
  });
  EXPECT_EQ(Fields(first, last), expected);
}

TEST(StatusTable, DocsTablesMatchCode) {
  EXPECT_EQ(test::GeneratedBlock("docs/tools-and-data.md",
                                 "<!-- BEGIN STATUS COLUMNS (generated by dslam_config_doc "
                                 "--status-columns) -->",
                                 "<!-- END STATUS COLUMNS -->"),
            BackEndCsvMarkdown())
      << "run scripts/update_readme.sh";
  EXPECT_EQ(test::GeneratedBlock("docs/tools-and-data.md",
                                 "<!-- BEGIN SUMMARY KEYS (generated by dslam_config_doc "
                                 "--summary-keys) -->",
                                 "<!-- END SUMMARY KEYS -->"),
            BackEndSummaryMarkdown())
      << "run scripts/update_readme.sh";
}

}  // namespace
}  // namespace dslam
