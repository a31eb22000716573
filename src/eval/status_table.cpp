#include "dslam/eval/status_table.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <type_traits>
#include <utility>

namespace dslam {
namespace {

// The summary keys of a field's quantiles are these prefixes + its name.
constexpr const char* kMedianPrefix = "median_";
constexpr const char* kP95Prefix = "p95_";

// Every entry of the table, in table order.
std::vector<StatusFieldInfo> TableFields() {
  std::vector<StatusFieldInfo> fields;
  const BackEndStatus status;
  BackEndStatus::Fields(status,
                        [&](const StatusFieldInfo& info, const auto&) { fields.push_back(info); });
  return fields;
}

// The entries that are status CSV columns, in CSV order.
std::vector<StatusFieldInfo> CsvFields() {
  std::vector<StatusFieldInfo> fields = TableFields();
  fields.erase(std::remove_if(fields.begin(), fields.end(),
                              [](const StatusFieldInfo& f) { return !(f.outputs & kStatusCsv); }),
               fields.end());
  return fields;
}

// The entries with summary quantiles, in summary order.
std::vector<StatusFieldInfo> SummaryFields() {
  std::vector<StatusFieldInfo> fields = TableFields();
  fields.erase(std::remove_if(fields.begin(), fields.end(),
                              [](const StatusFieldInfo& f) { return f.summary_rank < 0; }),
               fields.end());
  std::sort(fields.begin(), fields.end(), [](const StatusFieldInfo& a, const StatusFieldInfo& b) {
    return a.summary_rank < b.summary_rank;
  });
  return fields;
}

// A CSV cell: flags 0 / 1, counts "%d", numbers "%.3f".
std::string Cell(bool value) { return value ? "1" : "0"; }
std::string Cell(int value) { return std::to_string(value); }
std::string Cell(double value) {
  const int size = std::snprintf(nullptr, 0, "%.3f", value);
  std::string text(size + 1, '\0');
  std::snprintf(&text[0], text.size(), "%.3f", value);
  text.resize(size);
  return text;
}

// Reads the numeric field `name` of a stage, if there is one (see BackEndStageValues).
class StageValueReader {
 public:
  explicit StageValueReader(std::string name) : name_(std::move(name)) {}

  template <typename T>
  void operator()(const StatusFieldInfo& info, const T& value) {
    if (name_ != info.name || std::is_same<T, bool>::value) return;
    if (info.stage == StatusStage::kWindow) return;
    found_ = true;
    stage_ = info.stage;
    value_ = static_cast<double>(value);
  }

  bool found() const { return found_; }
  /// Whether the field's stage ran in `status`.
  bool StageRan(const BackEndStatus& status) const {
    return stage_ == StatusStage::kWindowSpd ? status.spd.ran : status.ba.ran;
  }
  double value() const { return value_; }

 private:
  std::string name_;
  bool found_ = false;
  StatusStage stage_ = StatusStage::kWindow;
  double value_ = 0.0;
};

// What a stage's fields describe, as the docs name it.
const char* StageLabel(StatusStage stage) {
  switch (stage) {
    case StatusStage::kWindow:
      return "back end";
    case StatusStage::kLocalBa:
      return "local BA";
    case StatusStage::kWindowSpd:
      return "window static point determination";
  }
  return "";
}

// "stage: meaning [unit]" (no unit for "-").
std::string Meaning(const StatusFieldInfo& info) {
  std::string meaning = std::string(StageLabel(info.stage)) + ": " + info.doc;
  if (std::string(info.unit) != "-") meaning += std::string(" [") + info.unit + "]";
  return meaning;
}

}  // namespace

std::string BackEndCsvHeader() {
  std::string header;
  for (const StatusFieldInfo& field : CsvFields()) {
    header += (header.empty() ? "" : ",") + std::string(field.name);
  }
  return header;
}

std::string BackEndCsvValues(const BackEndStatus& status) {
  std::string values;
  bool first = true;
  BackEndStatus::Fields(status, [&](const StatusFieldInfo& info, const auto& value) {
    if (!(info.outputs & kStatusCsv)) return;
    values += (first ? "" : ",") + Cell(value);
    first = false;
  });
  return values;
}

std::vector<std::string> BackEndSummaryFields() {
  std::vector<std::string> names;
  for (const StatusFieldInfo& field : SummaryFields()) names.push_back(field.name);
  return names;
}

std::vector<double> BackEndStageValues(const std::vector<BackEndStatus>& runs,
                                       const std::string& name) {
  const BackEndStatus none;
  StageValueReader probe(name);
  BackEndStatus::Fields(none, probe);
  if (!probe.found()) throw std::invalid_argument("unknown back-end field " + name);
  std::vector<double> values;
  for (const BackEndStatus& run : runs) {
    StageValueReader reader(name);
    BackEndStatus::Fields(run, reader);
    if (reader.StageRan(run)) values.push_back(reader.value());
  }
  return values;
}

void AddBackEndQuantiles(const RunSummary& summary, int significant_digits, JsonObject* json) {
  for (const std::string& name : BackEndSummaryFields()) {
    json->AddNumber(kMedianPrefix + name, summary.BackEndQuantile(name, 0.5), significant_digits)
        .AddNumber(kP95Prefix + name, summary.BackEndQuantile(name, 0.95), significant_digits);
  }
}

std::string BackEndCsvMarkdown() {
  std::string table = "| column | meaning |\n|---|---|\n";
  for (const StatusFieldInfo& field : CsvFields()) {
    table += "| `" + std::string(field.name) + "` | " + Meaning(field) + " |\n";
  }
  return table;
}

std::string BackEndSummaryMarkdown() {
  std::string table = "| keys | meaning |\n|---|---|\n";
  for (const StatusFieldInfo& field : SummaryFields()) {
    table += "| `" + std::string(kMedianPrefix) + field.name + "`, `" + kP95Prefix + field.name +
             "` | " + Meaning(field) + " |\n";
  }
  return table;
}

}  // namespace dslam
