#include "dslam/loop_closing/loop_closing.h"

#include <cmath>
#include <exception>
#include <optional>
#include <string>
#include <utility>

#include "dslam/core/geometry.h"
#include "dslam/core/stopwatch.h"
#include "dslam/loop_closing/map_places.h"

namespace dslam {

LoopClosing::LoopClosing(const Config& config, std::shared_ptr<const Vocabulary> vocabulary,
                         WorkerMode mode)
    : config_(config.loop_closing),
      pose_config_(config.pose),
      vocabulary_(std::move(vocabulary)),
      errors_(std::make_shared<ErrorLog>()),
      worker_(std::make_unique<OrderedWorker>(mode, kMaxQueuedKeyFrames, errors_, "loop closing")) {
}

void LoopClosing::Attach(Slam* slam) {
  slam_ = slam;
  if (slam_ != nullptr) slam_->SetPlaceLookup(std::make_shared<MapPlaces>(vocabulary_));
}

void LoopClosing::OnKeyFrames(const std::vector<KeyFrameRecord>& added,
                              const std::vector<KeyFramePose>& /*window*/) {
  for (const KeyFrameRecord& record : added) {
    worker_->Post(
        [this, id = record.id, loaded = record.loaded, temporary = record.temporary,
         camera = record.frame.camera] { HandleKeyFrame(id, loaded, temporary, camera); });
  }
}

void LoopClosing::HandleKeyFrame(int id, bool loaded, bool temporary,
                                 const std::shared_ptr<const PinholeCamera>& camera) {
  if (stopping_) return;
  const Stopwatch stopwatch;
  if (!detector_ && camera) {
    detector_ = std::make_unique<LoopDetector>(vocabulary_, config_, *camera, pose_config_);
  }
  if (loaded) {
    AddLoadedKeyFrame(id);
    return;
  }
  if (temporary) return;  // localisation only: the loaded map stays as it is
  ProcessKeyFrame(id);
  const std::lock_guard<std::mutex> lock(mutex_);
  times_ms_.push_back(stopwatch.ElapsedMs());
  if (times_ms_.size() > kKeptTimes) times_ms_.pop_front();
  ++keyframes_timed_;
}

void LoopClosing::Wait() { worker_->Wait(); }

void LoopClosing::OnStop() {
  stopping_ = true;
  worker_->Wait();  // never throws: errors went to errors_
  slam_ = nullptr;
}

bool LoopClosing::ProcessKeyFrame(int id) {
  if (slam_ == nullptr || !detector_) return false;
  std::optional<LoopDetection> loop;
  LoopEdge edge;  // the loop's edge, when one is found
  PoseGraph graph;
  Eigen::Isometry3d T_world_query_before = Eigen::Isometry3d::Identity();
  const bool searching = keyframes_since_loop_ >= kKeyFramesAfterLoop;
  ++keyframes_since_loop_;
  slam_->ReadMap([&](const Map& map) {
    if (map.FindKeyFrame(id) == nullptr) return;  // erased already (threaded: made and culled)
    loop = detector_->Process(map, id);           // every keyframe enters the database
    in_database_.push_back(id);
    if (in_database_.size() % kPruneKeyFrames == 0) PruneErased(map);
    if (!loop || !searching) return;
    edge = {loop->match_keyframe_id, loop->query_keyframe_id, loop->T_match_query};
    std::vector<LoopEdge> edges = loop_edges_;
    edges.push_back(edge);
    graph = BuildLoopPoseGraph(map, edges);
    T_world_query_before = graph.nodes.at(loop->query_keyframe_id).T_world_camera;
  });
  if (!loop || !searching) return false;
  const std::map<int, Eigen::Isometry3d> corrected = CorrectedKeyFramePoses(graph);
  std::map<int, Eigen::Isometry3d> before;  // the poses the correction was computed from
  for (const auto& [node_id, node] : graph.nodes) before[node_id] = node.T_world_camera;
  const char* dropped = corrected.empty() ? "the pose graph solve failed"
                        : !slam_->CorrectKeyFrames(corrected, before) ? "the map refused it (reset)"
                                                                      : nullptr;
  if (dropped != nullptr) {
    errors_->Report("loop closing", "verified loop " + std::to_string(loop->query_keyframe_id) +
                                        " -> " + std::to_string(loop->match_keyframe_id) +
                                        " dropped: " + dropped);
    const std::lock_guard<std::mutex> lock(mutex_);
    ++dropped_loops_;
    return false;
  }
  keyframes_since_loop_ = 0;
  loop_edges_.push_back(edge);
  const Eigen::Isometry3d moved =
      corrected.at(loop->query_keyframe_id) * T_world_query_before.inverse();
  ClosedLoop closed;
  closed.detection = *loop;
  closed.query_moved_m = moved.translation().norm();
  closed.query_turned_deg = RotationAngleDeg(moved.rotation());
  const std::lock_guard<std::mutex> lock(mutex_);
  loops_.push_back(closed);
  return true;
}

void LoopClosing::AddLoadedKeyFrame(int id) {
  if (slam_ == nullptr || !detector_) return;
  slam_->ReadMap([&](const Map& map) {
    if (map.FindKeyFrame(id) == nullptr) return;
    detector_->Add(map, id);
    in_database_.push_back(id);
  });
}

void LoopClosing::PruneErased(const Map& map) {
  std::vector<int> kept;
  for (int id : in_database_) {
    if (map.FindKeyFrame(id) != nullptr) {
      kept.push_back(id);
    } else {
      detector_->Erase(id);
    }
  }
  in_database_ = std::move(kept);
  // Edges of erased keyframes never enter a pose graph again (BuildLoopPoseGraph skips them).
  std::vector<LoopEdge> edges;
  for (const LoopEdge& edge : loop_edges_) {
    if (map.FindKeyFrame(edge.match_keyframe_id) != nullptr &&
        map.FindKeyFrame(edge.query_keyframe_id) != nullptr) {
      edges.push_back(edge);
    }
  }
  loop_edges_ = std::move(edges);
}

void LoopClosing::OnReset(ResetMode /*mode*/) {
  worker_->Post([this] {  // after the keyframes of the run it ends
    in_database_.clear();
    loop_edges_.clear();
    if (detector_) detector_->Clear();
    keyframes_since_loop_ = kKeyFramesAfterLoop;
  });
}

std::vector<ClosedLoop> LoopClosing::loops() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return loops_;
}

std::vector<double> LoopClosing::times_ms() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return std::vector<double>(times_ms_.begin(), times_ms_.end());
}

LoopWork LoopClosing::work() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  LoopWork work;
  work.loops = static_cast<int>(loops_.size());
  work.dropped = dropped_loops_;
  work.keyframes = keyframes_timed_;
  if (!times_ms_.empty()) work.last_ms = times_ms_.back();
  return work;
}

}  // namespace dslam
