// dslam_place_recognition_eval: how well the vocabulary recognises places on a TUM-layout folder
// with ground truth. The database holds the --database frames, each --queries frame asks it
// (PlaceDatabase::Query); a candidate is true when its ground-truth pose is within --max-distance
// [m] and --max-angle [deg] of the query's. Prints per query the top 3, the best true and the best
// false score, then the top-1 and top-3 hits over the queries that have a true frame in the
// database. docs/tools-and-data.md ("Place recognition") has the measurements.
// Usage: kUsage below.

#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "dataset_descriptors.h"
#include "dslam/core/geometry.h"
#include "dslam/eval/groundtruth_correction.h"
#include "dslam/eval/quantile.h"
#include "dslam/io/stamp_association.h"
#include "dslam/io/trajectory_io.h"
#include "dslam/place_recognition/place_database.h"
#include "dslam/place_recognition/vocabulary.h"
#include "eval_tool.h"

namespace {

using Pose = std::optional<Eigen::Isometry3d>;

constexpr char kUsage[] =
    "usage: dslam_place_recognition_eval --dataset FOLDER [--vocabulary FILE]\n"
    "                                    [--database 0:400:10] [--queries 560:727:10]\n"
    "                                    [--max-distance 0.3] [--max-angle 20]\n"
    "  --dataset       TUM-layout folder with groundtruth.txt\n"
    "  --vocabulary    vocabulary file (default: the committed one, DefaultVocabularyPath())\n"
    "  --database      frames FIRST:LAST:STEP put into the database (LAST -1: the last frame)\n"
    "  --queries       frames FIRST:LAST:STEP that ask it\n"
    "  --max-distance  [m] a candidate within this of the query is true (default 0.3)\n"
    "  --max-angle     [deg] and within this rotation (default 20)\n";

struct Args {
  std::string dataset;
  std::string vocabulary = dslam::DefaultVocabularyPath();
  dslam::tools::FrameRange database{0, 400, 10};
  dslam::tools::FrameRange queries{560, 727, 10};
  double max_distance_m = 0.3;
  double max_angle_deg = 20.0;
};

Args ReadArgs(const dslam::tools::Options& options) {
  using dslam::tools::NumberKind;
  using dslam::tools::NumberOption;
  Args args;
  args.dataset = options.at("dataset");
  if (options.count("vocabulary")) args.vocabulary = options.at("vocabulary");
  if (options.count("database"))
    args.database = dslam::tools::ParseFrameRange(options.at("database"));
  if (options.count("queries")) args.queries = dslam::tools::ParseFrameRange(options.at("queries"));
  args.max_distance_m = NumberOption(options, "max-distance", 0.3, NumberKind::kNonNegative);
  args.max_angle_deg = NumberOption(options, "max-angle", 20.0, NumberKind::kNonNegative);
  return args;
}

// The ground-truth camera pose of every associated frame (nearest stamp within the association
// limit), or none.
std::vector<Pose> GroundTruthPoses(const dslam::TumDataset& dataset, double max_dt_s) {
  const dslam::Trajectory truth =
      dslam::ApplyGroundTruthCorrection(dslam::ReadTumTrajectory(dataset.groundtruth_path()),
                                        dataset.camera_yaml().groundtruth_correction);
  std::vector<double> frame_stamps;
  for (const auto& pair : dataset.pairs()) frame_stamps.push_back(pair.colour.stamp_s);
  std::vector<double> truth_stamps;
  for (const auto& pose : truth) truth_stamps.push_back(pose.stamp_s);
  std::vector<Pose> poses(dataset.size());
  for (const auto& [frame, t] : dslam::AssociateStamps(frame_stamps, truth_stamps, max_dt_s)) {
    poses[frame] = truth[t].T_world_camera;
  }
  return poses;
}

struct QueryResult {
  std::vector<dslam::PlaceCandidate> top;  // best 3
  std::vector<bool> top_true;
  bool answerable = false;  // a true frame is in the database
  double best_true = 0.0;
  double best_false = 0.0;
};

class Evaluation {
 public:
  Evaluation(const Args& args, const dslam::TumDataset& dataset, const dslam::Config& config)
      : args_(args),
        dataset_(dataset),
        config_(config),
        vocabulary_(dslam::Vocabulary::Load(args.vocabulary)),
        poses_(GroundTruthPoses(dataset, config.dataset.association_max_dt_s)) {}

  void AddDatabase() {
    for (const int index : dslam::tools::FrameIndices(args_.database, dataset_.size())) {
      if (!poses_[index]) continue;
      database_.Add(index, Words(index));
      database_frames_.push_back(index);
    }
  }

  std::optional<QueryResult> Ask(int query) const {
    if (!poses_[query]) return std::nullopt;
    QueryResult result;
    for (const int frame : database_frames_) result.answerable |= Close(query, frame);
    const auto candidates = database_.Query(Words(query), {0, 0.0, 1, {}});
    for (const dslam::PlaceCandidate& c : candidates) {
      const bool close = Close(query, c.id);
      double& best = close ? result.best_true : result.best_false;
      best = std::max(best, c.score);
      if (result.top.size() < 3) {
        result.top.push_back(c);
        result.top_true.push_back(close);
      }
    }
    return result;
  }

  const dslam::Vocabulary& vocabulary() const { return vocabulary_; }
  size_t database_size() const { return database_frames_.size(); }

 private:
  dslam::BowVector Words(int index) const {
    return vocabulary_.Transform(dslam::tools::FrameDescriptors(dataset_, index, config_));
  }

  bool Close(int a, int b) const {
    const Eigen::Isometry3d delta = poses_[a]->inverse() * *poses_[b];
    return delta.translation().norm() <= args_.max_distance_m &&
           dslam::RotationAngleDeg(delta.rotation()) <= args_.max_angle_deg;
  }

  const Args& args_;
  const dslam::TumDataset& dataset_;
  const dslam::Config& config_;
  const dslam::Vocabulary vocabulary_;
  const std::vector<Pose> poses_;
  dslam::PlaceDatabase database_;
  std::vector<int> database_frames_;
};

void PrintQuery(int query, const QueryResult& r) {
  std::printf("query %4d%s:", query, r.answerable ? "" : " (no true frame in the database)");
  for (size_t i = 0; i < r.top.size(); ++i) {
    std::printf(" %d %.3f %s", r.top[i].id, r.top[i].score, r.top_true[i] ? "true" : "false");
    std::printf(i + 1 < r.top.size() ? "," : "");
  }
  std::printf("; best true %.3f, best false %.3f\n", r.best_true, r.best_false);
}

int Run(const Args& args) {
  const dslam::Config config;
  const dslam::TumDataset dataset(args.dataset, "", config.dataset.association_max_dt_s);
  Evaluation evaluation(args, dataset, config);
  evaluation.AddDatabase();
  int answerable = 0, top1 = 0, top3 = 0, asked = 0, separated = 0;
  std::vector<double> best_true, best_false;
  for (const int query : dslam::tools::FrameIndices(args.queries, dataset.size())) {
    const std::optional<QueryResult> r = evaluation.Ask(query);
    if (!r) continue;
    PrintQuery(query, *r);
    ++asked;
    if (!r->answerable) continue;
    ++answerable;
    top1 += !r->top_true.empty() && r->top_true[0];
    top3 += std::find(r->top_true.begin(), r->top_true.end(), true) != r->top_true.end();
    separated += r->best_true > r->best_false;
    best_true.push_back(r->best_true);
    best_false.push_back(r->best_false);
  }
  std::printf(
      "summary: %d queries, database %zu frames, %d queries with a true frame in it: top-1 %d, "
      "top-3 %d, best true above best false %d; median best true score %.3f, median best false "
      "score %.3f (vocabulary %s)\n",
      asked, evaluation.database_size(), answerable, top1, top3, separated,
      best_true.empty() ? 0.0 : dslam::Median(best_true),
      best_false.empty() ? 0.0 : dslam::Median(best_false),
      dslam::FormatIdentity(evaluation.vocabulary().identity()).c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return dslam::tools::RunTool(
      "dslam_place_recognition_eval", kUsage, argc, argv,
      {"dataset", "vocabulary", "database", "queries", "max-distance", "max-angle"}, {"dataset"},
      [](const dslam::tools::Options& options) { return Run(ReadArgs(options)); });
}
