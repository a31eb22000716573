#include "dslam/loop_closing/loop_detector.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <iterator>
#include <stdexcept>
#include <string>
#include <utility>

#include "dslam/loop_closing/loop_verification.h"
#include "dslam/tracking/keyframe_window.h"

namespace dslam {

LoopDetector::LoopDetector(std::shared_ptr<const Vocabulary> vocabulary,
                           const LoopClosingConfig& config, const PinholeCamera& camera,
                           const PoseConfig& pose_config)
    : vocabulary_(std::move(vocabulary)),
      config_(config),
      camera_(camera),
      pose_config_(pose_config) {
  if (vocabulary_ == nullptr || vocabulary_->empty()) {
    throw std::invalid_argument("LoopDetector: the vocabulary is null or empty");
  }
}

namespace {

const KeyFrame& FindOrThrow(const Map& map, int keyframe_id, const char* caller) {
  const KeyFrame* keyframe = map.FindKeyFrame(keyframe_id);
  if (keyframe == nullptr) {
    throw std::invalid_argument(std::string(caller) + ": no keyframe " +
                                std::to_string(keyframe_id) + " in the map");
  }
  return *keyframe;
}

// Ids of the keyframes sharing at least one point with `keyframe` (itself excluded), ascending.
std::vector<int> CovisibleIds(const Map& map, const KeyFrame& keyframe) {
  std::vector<int> ids;
  for (const auto& [id, shared] : SharedPointCounts(map, keyframe, 1)) ids.push_back(id);
  return ids;
}

// (keyframe id, shared points) of the keyframes sharing points with `keyframe`, most shared
// first (ties: lower id first).
std::vector<std::pair<int, int>> MostCovisibleFirst(const Map& map, const KeyFrame& keyframe) {
  std::vector<std::pair<int, int>> counts = SharedPointCounts(map, keyframe, 1);
  std::stable_sort(counts.begin(), counts.end(),
                   [](const auto& a, const auto& b) { return a.second > b.second; });
  return counts;
}

}  // namespace

void LoopDetector::Add(const Map& map, int keyframe_id) {
  const KeyFrame& keyframe = FindOrThrow(map, keyframe_id, "LoopDetector::Add");
  const BowVector words = Words(map, keyframe);
  database_.Add(keyframe_id, words);
  entries_[keyframe_id] = {keyframe.frame_index, words};
}

std::optional<LoopDetection> LoopDetector::Process(const Map& map, int keyframe_id) {
  const KeyFrame* query = &FindOrThrow(map, keyframe_id, "LoopDetector::Process");
  ++stats_.processed;
  const BowVector words = Words(map, *query);
  const std::vector<int> covisible = CovisibleIds(map, *query);
  last_candidates_ = Candidates(map, *query, words, covisible);
  stats_.candidates += static_cast<int>(last_candidates_.size());
  database_.Add(keyframe_id, words);
  entries_[keyframe_id] = {query->frame_index, words};

  std::vector<CandidateGroup> groups;
  for (const PlaceCandidate& candidate : last_candidates_) {
    groups.push_back(Group(map, candidate.id));
  }
  const std::vector<int> consistent = chains_.Update(groups, config_.consistent_keyframes);
  stats_.consistent += static_cast<int>(consistent.size());
  for (const PlaceCandidate& candidate : last_candidates_) {  // best score first
    if (std::find(consistent.begin(), consistent.end(), candidate.id) == consistent.end()) {
      continue;
    }
    std::optional<LoopDetection> loop = Verify(map, *query, candidate);
    if (loop) {
      chains_.Clear();
      return loop;
    }
  }
  return std::nullopt;
}

void LoopDetector::Erase(int keyframe_id) {
  database_.Erase(keyframe_id);
  entries_.erase(keyframe_id);
}

void LoopDetector::Clear() {
  database_.Clear();
  entries_.clear();
  chains_.Clear();
  last_candidates_.clear();
  stats_ = LoopDetectorStats();
}

BowVector LoopDetector::Words(const Map& map, const KeyFrame& keyframe) const {
  const cv::Mat descriptors = PointDescriptors(map, StaticMeasuredPoints(map, keyframe));
  if (descriptors.empty()) return BowVector();
  return vocabulary_->Transform(descriptors);
}

// `scored`: the database's scores of the query against the keyframes in it (one pass over the
// inverted index; the ones sharing no word are not listed and score 0).
double LoopDetector::MinScore(const KeyFrame& query, const BowVector& words,
                              const std::vector<int>& covisible,
                              const std::vector<PlaceCandidate>& scored) const {
  const bool covisible_in_database = std::any_of(covisible.begin(), covisible.end(),
                                                 [&](int id) { return entries_.count(id) != 0; });
  if (!covisible_in_database) {  // the previously processed keyframe instead
    const auto previous = entries_.lower_bound(query.id);
    if (previous == entries_.begin()) return 0.0;
    return config_.min_score_ratio * ScoreL1(words, std::prev(previous)->second.words);
  }
  double best = 0.0;  // a covisible keyframe sharing no word with the query scores 0
  for (const PlaceCandidate& c : scored) {
    if (std::binary_search(covisible.begin(), covisible.end(), c.id)) {
      best = std::max(best, c.score);
    }
  }
  return config_.min_score_ratio * best;
}

std::vector<PlaceCandidate> LoopDetector::Candidates(const Map& map, const KeyFrame& query,
                                                     const BowVector& words,
                                                     const std::vector<int>& covisible) const {
  if (words.empty()) return {};
  PlaceQueryOptions every;  // every keyframe in the database and the map, best score first
  every.max_results = 0;
  every.exclude = [&](int id) {
    return id == query.id || entries_.count(id) == 0 || map.FindKeyFrame(id) == nullptr;
  };
  const std::vector<PlaceCandidate> scored = database_.Query(words, every);
  const double min_score = MinScore(query, words, covisible, scored);
  const int newest_frame = query.frame_index - config_.min_frames_apart;
  std::vector<PlaceCandidate> candidates;
  for (const PlaceCandidate& c : scored) {
    if (static_cast<int>(candidates.size()) >= kMaxLoopCandidates) break;
    if (c.score < min_score || entries_.at(c.id).frame_index > newest_frame ||
        std::binary_search(covisible.begin(), covisible.end(), c.id)) {
      continue;
    }
    candidates.push_back(c);
  }
  return candidates;
}

CandidateGroup LoopDetector::Group(const Map& map, int candidate) const {
  CandidateGroup group;
  group.candidate = candidate;
  group.keyframes = CovisibleIds(map, *map.FindKeyFrame(candidate));
  const int frame = entries_.at(candidate).frame_index;
  for (const auto& [id, entry] : entries_) {
    if (std::abs(entry.frame_index - frame) <= kLoopGroupFrames) group.keyframes.push_back(id);
  }
  std::sort(group.keyframes.begin(), group.keyframes.end());
  group.keyframes.erase(std::unique(group.keyframes.begin(), group.keyframes.end()),
                        group.keyframes.end());
  return group;
}

std::optional<LoopDetection> LoopDetector::Verify(const Map& map, const KeyFrame& query,
                                                  const PlaceCandidate& candidate) {
  const KeyFrame& match = *map.FindKeyFrame(candidate.id);
  std::vector<int> match_side = {match.id};
  for (const auto& [id, shared] : MostCovisibleFirst(map, match)) {
    if (static_cast<int>(match_side.size()) > kLoopVerificationNeighbours) break;
    match_side.push_back(id);
  }
  const std::uint32_t seed =
      static_cast<std::uint32_t>(query.id) * 65599u + static_cast<std::uint32_t>(match.id);
  ++stats_.verifications;
  const LoopVerification verification =
      VerifyLoop(map, query, match_side, camera_, config_, pose_config_, seed);
  if (!verification.accepted) return std::nullopt;
  ++stats_.accepted;
  LoopDetection loop;
  loop.query_keyframe_id = query.id;
  loop.match_keyframe_id = match.id;
  loop.query_frame_index = query.frame_index;
  loop.match_frame_index = match.frame_index;
  loop.query_stamp_s = query.stamp_s;
  loop.match_stamp_s = match.stamp_s;
  loop.T_world_query_verified = verification.T_world_query;
  loop.T_match_query = match.T_world_camera.inverse() * verification.T_world_query;
  loop.inliers = verification.inliers;
  loop.matches = verification.matches;
  loop.quadrants = verification.quadrants;
  loop.score = candidate.score;
  return loop;
}

}  // namespace dslam
