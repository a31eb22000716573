#pragma once
// Loop detection (ORB-SLAM2's LoopClosing::DetectLoop and ComputeSim3, adapted to RGB-D and to
// dynamic scenes): each keyframe's bag of words over its verified static points goes into a
// place database; the keyframe queries it for older keyframes that look alike but share no map
// point with it; candidates agreeing over consecutive query keyframes are verified geometrically
// on static points (loop_verification.h). Points on people (unmarked) never enter the database,
// never vote and never take part in the verification, so a crowd walking the same path twice
// cannot make a loop.
//
// One Process call per new keyframe, in keyframe order:
//  1. Words: Vocabulary::Transform of the descriptors of the keyframe's StaticMeasuredPoints,
//     computed once, when the keyframe is processed: marks that change later do not change its
//     entry (a later Process of the same keyframe replaces it).
//  2. Candidates: PlaceDatabase::Query (at most kMaxLoopCandidates), leaving out keyframes made
//     less than config.min_frames_apart frames before the query (frame_index), keyframes sharing
//     a map point with it (its covisible keyframes: the neighbourhood it tracks against) and
//     keyframes no longer in the map; min_score = config.min_score_ratio x the query's highest
//     score against its covisible keyframes in the database (none there: against the previously
//     processed keyframe; none at all: 0).
//  3. Consistency (loop_consistency.h): each candidate's group is the candidate plus the
//     database keyframes within kLoopGroupFrames frames of it and the keyframes sharing points
//     with it; a candidate is consistent once its chain spans config.consistent_keyframes
//     consecutive processed keyframes.
//  4. Verification of the consistent candidates, best score first, against the candidate and its
//     kLoopVerificationNeighbours most covisible keyframes; the first accepted one is the loop,
//     and every chain ends then (the next loop needs a new chain). RANSAC is seeded from the two
//     keyframe ids; no threads: the same inputs give the same answers.

#include <cstddef>
#include <map>
#include <memory>
#include <optional>
#include <vector>

#include <Eigen/Geometry>

#include "dslam/core/camera.h"
#include "dslam/core/features_config.h"
#include "dslam/core/loop_closing_config.h"
#include "dslam/loop_closing/loop_consistency.h"
#include "dslam/place_recognition/place_database.h"
#include "dslam/place_recognition/vocabulary.h"
#include "dslam/tracking/map.h"

namespace dslam {

/// Candidates a query keeps at most (the best scores).
constexpr int kMaxLoopCandidates = 10;
/// [frames] A candidate's group holds the database keyframes within this many frames of it.
constexpr int kLoopGroupFrames = 30;
/// Covisible keyframes of the candidate whose points join the verification (most shared first).
constexpr int kLoopVerificationNeighbours = 5;

/// A loop found and verified: the query keyframe seen again in the match keyframe.
struct LoopDetection {
  int query_keyframe_id = -1;  ///< the keyframe given to Process
  int match_keyframe_id = -1;  ///< the older keyframe of the same place
  int query_frame_index = 0;   ///< KeyFrame::frame_index of the query
  int match_frame_index = 0;   ///< KeyFrame::frame_index of the match
  double query_stamp_s = 0.0;  ///< [s] KeyFrame::stamp_s of the query
  double match_stamp_s = 0.0;  ///< [s] KeyFrame::stamp_s of the match
  /// [m] query camera (optical frame) in the match keyframe's camera frame, as verified:
  /// T_world_match^-1 T_world_query_verified with the match's T_world_camera in the map.
  Eigen::Isometry3d T_match_query = Eigen::Isometry3d::Identity();
  /// [m] where the match side of the map puts the query camera (optical frame -> world).
  Eigen::Isometry3d T_world_query_verified = Eigen::Isometry3d::Identity();
  int inliers = 0;     ///< inliers of the verified pose
  int matches = 0;     ///< descriptor matches verified
  int quadrants = 0;   ///< image quadrants of the query the inliers reach (0..4)
  double score = 0.0;  ///< [0, 1] bag-of-words score of the match against the query
};

/// Counters since construction or Clear, for status output.
struct LoopDetectorStats {
  int processed = 0;      ///< keyframes processed
  int candidates = 0;     ///< candidates the database queries returned, summed
  int consistent = 0;     ///< consistent candidates (chain long enough), summed
  int verifications = 0;  ///< geometric verifications tried
  int accepted = 0;       ///< verifications accepted: loops reported
};

/// The place database of the processed keyframes and the consistency chains; see the top of
/// this file. Not thread-safe; reads the map only during Process.
class LoopDetector {
 public:
  /// Throws std::invalid_argument when `vocabulary` is null or empty. `camera` gives the image
  /// quadrants; `pose_config` the RANSAC's and motion-only BA's thresholds.
  LoopDetector(std::shared_ptr<const Vocabulary> vocabulary, const LoopClosingConfig& config,
               const PinholeCamera& camera, const PoseConfig& pose_config = PoseConfig());

  /// Adds keyframe `keyframe_id` of `map` to the database and looks for a loop for it (steps 1-4
  /// above). nullopt: none (yet). Throws std::invalid_argument when the map has no such keyframe.
  std::optional<LoopDetection> Process(const Map& map, int keyframe_id);

  /// Step 1 alone: adds keyframe `keyframe_id` of `map` to the database without looking for a
  /// loop (a keyframe of a loaded map) and without touching the chains. Throws
  /// std::invalid_argument when the map has no such keyframe.
  void Add(const Map& map, int keyframe_id);

  /// Removes a keyframe (erased from the map) from the database; no-op when it is not there.
  void Erase(int keyframe_id);
  /// Removes every keyframe, ends the chains and zeroes the counters (a reset of the map).
  void Clear();

  bool Contains(int keyframe_id) const { return entries_.count(keyframe_id) > 0; }
  std::size_t size() const { return entries_.size(); }  ///< keyframes in the database
  /// The candidates of the last Process call (step 2), best score first.
  const std::vector<PlaceCandidate>& last_candidates() const { return last_candidates_; }
  const LoopDetectorStats& stats() const { return stats_; }

 private:
  struct Entry {
    int frame_index = 0;  // KeyFrame::frame_index
    BowVector words;      // as computed by Process
  };

  BowVector Words(const Map& map, const KeyFrame& keyframe) const;
  double MinScore(const KeyFrame& query, const BowVector& words, const std::vector<int>& covisible,
                  const std::vector<PlaceCandidate>& scored) const;
  std::vector<PlaceCandidate> Candidates(const Map& map, const KeyFrame& query,
                                         const BowVector& words,
                                         const std::vector<int>& covisible) const;
  CandidateGroup Group(const Map& map, int candidate) const;
  std::optional<LoopDetection> Verify(const Map& map, const KeyFrame& query,
                                      const PlaceCandidate& candidate);

  std::shared_ptr<const Vocabulary> vocabulary_;
  LoopClosingConfig config_;
  PinholeCamera camera_;
  PoseConfig pose_config_;
  PlaceDatabase database_;
  std::map<int, Entry> entries_;  // keyframe id -> what Process stored
  ConsistentGroups chains_;
  std::vector<PlaceCandidate> last_candidates_;
  LoopDetectorStats stats_;
};

}  // namespace dslam
