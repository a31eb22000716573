#include "dslam/backend/refined_trajectory.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <stdexcept>
#include <type_traits>

#include "dslam/core/keyframe_motion.h"

namespace dslam {

/// Full blocks of frames, block k at byte k * kBlock * sizeof(Frame) of an unnamed temporary file.
/// Each block is written once; reads (pread) of written blocks and writes (pwrite) of later ones
/// may run at once, from different threads.
class RefinedTrajectory::BlockFile {
 public:
  /// A new temporary file (std::tmpfile); null when none can be made.
  static std::shared_ptr<BlockFile> Open() {
    std::FILE* file = std::tmpfile();
    return file != nullptr ? std::make_shared<BlockFile>(file) : nullptr;
  }

  explicit BlockFile(std::FILE* file) : file_(file, &std::fclose) {}

  /// Writes `block` (kBlock frames) as block `index`; false when it could not be written whole.
  bool Write(size_t index, const std::vector<Frame>& block) {
    const char* bytes = reinterpret_cast<const char*>(block.data());
    size_t done = 0;
    while (done < kBytes) {
      const ssize_t n = pwrite(fileno(file_.get()), bytes + done, kBytes - done,
                               static_cast<off_t>(index * kBytes + done));
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) return false;
      done += static_cast<size_t>(n);
    }
    return true;
  }

  /// Block `index` as Write wrote it. Throws std::runtime_error when it cannot be read.
  std::vector<Frame> Read(size_t index) const {
    std::vector<Frame> block(kBlock);
    char* bytes = reinterpret_cast<char*>(block.data());
    size_t done = 0;
    while (done < kBytes) {
      const ssize_t n = pread(fileno(file_.get()), bytes + done, kBytes - done,
                              static_cast<off_t>(index * kBytes + done));
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) {
        throw std::runtime_error("cannot read block " + std::to_string(index) +
                                 " of the refined trajectory's temporary file");
      }
      done += static_cast<size_t>(n);
    }
    return block;
  }

 private:
  static_assert(std::is_trivially_copyable<Frame>::value, "frames are written as bytes");
  static constexpr size_t kBytes = kBlock * sizeof(Frame);
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file_;
};

namespace {

/// Appends `entry` to `open`, moving `open` into `blocks` as a full block at `block` entries.
template <typename T, typename Blocks>
void Append(T entry, size_t block, std::vector<T>* open, Blocks* blocks) {
  open->push_back(std::move(entry));
  if (open->size() < block) return;
  blocks->push_back(std::make_shared<const std::vector<T>>(std::move(*open)));
  open->clear();
  open->reserve(block);
}

/// Writes `T` as quaternion (x, y, z, w) and translation in the precision of T_scalar.
template <typename T_scalar>
void Pack(const Eigen::Isometry3d& T, T_scalar q_out[4], T_scalar t_out[3]) {
  const Eigen::Quaterniond q(T.rotation());
  const Eigen::Vector4d q_xyzw(q.x(), q.y(), q.z(), q.w());
  for (int i = 0; i < 4; ++i) q_out[i] = static_cast<T_scalar>(q_xyzw[i]);
  for (int i = 0; i < 3; ++i) t_out[i] = static_cast<T_scalar>(T.translation()[i]);
}

/// The pose Pack wrote (the quaternion normalised).
template <typename T_scalar>
Eigen::Isometry3d Unpack(const T_scalar q[4], const T_scalar t[3]) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::Quaterniond(q[3], q[0], q[1], q[2]).normalized().toRotationMatrix();
  T.translation() = Eigen::Vector3d(t[0], t[1], t[2]);
  return T;
}

RefinedTrajectory::Frame Compact(double stamp_s, int keyframe_id,
                                 const Eigen::Isometry3d& T_keyframe_camera) {
  RefinedTrajectory::Frame frame{stamp_s, keyframe_id, {}, {}};
  Pack(T_keyframe_camera, frame.q_keyframe_camera, frame.t_keyframe_camera);
  return frame;
}

RefinedTrajectory::ErasedKeyFrame CompactErased(int id, const Eigen::Isometry3d& T_world_keyframe) {
  RefinedTrajectory::ErasedKeyFrame keyframe{id, {}, {}};
  Pack(T_world_keyframe, keyframe.q_world_keyframe, keyframe.t_world_keyframe);
  return keyframe;
}

}  // namespace

RefinedTrajectory::RefinedTrajectory() : file_(BlockFile::Open()) {}

RefinedTrajectory::~RefinedTrajectory() = default;

void RefinedTrajectory::AddFrame(double stamp_s, const Eigen::Isometry3d& T_world_camera,
                                 const Map& map) {
  if (map.window().empty()) return;
  const KeyFrame& reference = map.window().back();
  live_[reference.id] = reference.T_world_camera;
  if (live_.size() > live_limit_) RetireErased(map);
  open_frames_.push_back(
      Compact(stamp_s, reference.id, reference.T_world_camera.inverse() * T_world_camera));
  if (open_frames_.size() == kBlock) CloseFrameBlock();
}

void RefinedTrajectory::CloseFrameBlock() {
  if (FramesFiled() && file_->Write(filed_blocks_, open_frames_)) {
    ++filed_blocks_;
  } else {  // no file, or a write failed: this block and the later ones stay in memory, in order
    frame_blocks_.push_back(std::make_shared<const std::vector<Frame>>(std::move(open_frames_)));
  }
  open_frames_.clear();
  open_frames_.reserve(kBlock);
}

void RefinedTrajectory::UpdateKeyFrames(const Map& map) {
  for (const KeyFrame& keyframe : map.window()) live_[keyframe.id] = keyframe.T_world_camera;
  for (const auto& [id, keyframe] : map.archived_keyframes()) {
    live_[id] = keyframe.T_world_camera;
  }
  RetireErased(map);
}

void RefinedTrajectory::FollowCorrection(const Map& map) {
  RetireErased(map);  // erased since the last update: at their poses before the correction
  KeyFrameMotion motion;
  for (const auto& [id, T_world_keyframe_old] : live_) {
    if (const KeyFrame* keyframe = map.FindKeyFrame(id)) {
      motion.Add(id, keyframe->T_world_camera, T_world_keyframe_old);
    }
  }
  if (!motion.empty()) {
    const auto moved = [&motion](std::vector<ErasedKeyFrame> keyframes) {
      for (ErasedKeyFrame& keyframe : keyframes) {
        keyframe = CompactErased(keyframe.id, motion.For(keyframe.id) *
                                                  Unpack(keyframe.q_world_keyframe,
                                                         keyframe.t_world_keyframe));
      }
      return keyframes;
    };
    for (auto& block : erased_) {
      block = std::make_shared<const std::vector<ErasedKeyFrame>>(moved(*block));
    }
    open_erased_ = moved(std::move(open_erased_));
  }
  UpdateKeyFrames(map);
}

void RefinedTrajectory::RetireErased(const Map& map) {
  for (auto it = live_.begin(); it != live_.end();) {
    if (map.FindKeyFrame(it->first) != nullptr) {
      ++it;
      continue;
    }
    Append(CompactErased(it->first, it->second), kBlock, &open_erased_, &erased_);
    it = live_.erase(it);
  }
  live_limit_ = 2 * live_.size() + 64;
}

RefinedTrajectory::Snapshot RefinedTrajectory::Take() const {
  Snapshot snapshot;
  snapshot.file = file_;
  snapshot.filed_blocks = filed_blocks_;
  snapshot.frames = frame_blocks_;
  snapshot.frames.push_back(std::make_shared<const std::vector<Frame>>(open_frames_));
  snapshot.erased = erased_;
  snapshot.erased.push_back(std::make_shared<const std::vector<ErasedKeyFrame>>(open_erased_));
  snapshot.live = live_;
  return snapshot;
}

Trajectory RefinedTrajectory::Snapshot::Poses() const {
  std::unordered_map<int, Eigen::Isometry3d> T_world_keyframe = live;
  for (const auto& block : erased) {
    for (const ErasedKeyFrame& keyframe : *block) {  // live ones win
      if (T_world_keyframe.count(keyframe.id) == 0) {
        T_world_keyframe.emplace(keyframe.id,
                                 Unpack(keyframe.q_world_keyframe, keyframe.t_world_keyframe));
      }
    }
  }
  Trajectory poses;
  const auto add = [&](const std::vector<Frame>& block) {
    for (const Frame& frame : block) {
      poses.push_back(
          {frame.stamp_s, T_world_keyframe.at(frame.keyframe_id) *
                              Unpack(frame.q_keyframe_camera, frame.t_keyframe_camera)});
    }
  };
  for (size_t k = 0; k < filed_blocks; ++k) add(file->Read(k));
  for (const auto& block : frames) add(*block);
  return poses;
}

}  // namespace dslam
