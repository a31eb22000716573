#include "dslam/io/trajectory_recorder.h"

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <system_error>
#include <vector>

#include "dslam/io/trajectory_io.h"

namespace dslam {
namespace fs = std::filesystem;
namespace {

/// Copies the first `bytes` bytes of `from` (already open) to the file `to`.
void CopyBytes(std::ifstream& from, std::uintmax_t bytes, const std::string& from_path,
               const std::string& to) {
  std::ofstream out(to, std::ios::binary | std::ios::trunc);
  if (!out) throw std::runtime_error("cannot write trajectory " + to);
  from.clear();
  from.seekg(0);
  std::vector<char> buffer(1 << 16);
  while (bytes > 0) {
    const std::streamsize chunk =
        static_cast<std::streamsize>(std::min<std::uintmax_t>(bytes, buffer.size()));
    if (!from.read(buffer.data(), chunk)) {
      throw std::runtime_error("cannot read the streamed trajectory " + from_path);
    }
    out.write(buffer.data(), chunk);
    bytes -= static_cast<std::uintmax_t>(chunk);
  }
  if (!out) throw std::runtime_error("error while writing trajectory " + to);
}

bool SameFile(const std::string& a, const std::string& b) {
  std::error_code error;
  return fs::equivalent(a, b, error) && !error;
}

}  // namespace

std::string SegmentPath(const std::string& path, int n) {
  const fs::path p(path);
  const std::string suffix = ".seg" + std::to_string(n);
  if (!p.has_extension() || p.stem().empty()) return path + suffix;
  fs::path out = p.parent_path() / p.stem();
  out += suffix;
  out += p.extension();
  return out.string();
}

std::uintmax_t WriteTrajectorySnapshot(const TrajectorySnapshot& snapshot,
                                       const std::string& path) {
  const bool streamed = !snapshot.streamed.empty();
  const int segments =
      static_cast<int>(streamed ? snapshot.streamed.size() : snapshot.segments.size());
  if (streamed && SameFile(snapshot.streamed.back().path, path)) return snapshot.poses;
  for (int i = 0; i < segments; ++i) {
    const std::string target = i + 1 == segments ? path : SegmentPath(path, i + 1);
    if (streamed) {
      const TrajectorySnapshot::StreamedSegment& s = snapshot.streamed[i];
      CopyBytes(*s.file, s.bytes, s.path, target);
    } else {
      WriteTumTrajectory(target, snapshot.segments[i]);
    }
  }
  // A save with fewer earlier segments than the files beside `path` (a restarted node).
  std::error_code ignored;
  for (int k = segments; fs::exists(SegmentPath(path, k)); ++k) {
    fs::remove(SegmentPath(path, k), ignored);
  }
  return snapshot.poses;
}

TrajectoryRecorder::TrajectoryRecorder(std::string stream_path)
    : stream_path_(std::move(stream_path)) {
  segment_poses_.push_back(0);
  segment_bytes_.push_back(0);
  segments_.emplace_back();
  if (!stream_path_.empty()) OpenStream();
}

void TrajectoryRecorder::OpenStream() {
  stream_.close();
  stream_.clear();
  stream_.open(stream_path_, std::ios::binary | std::ios::trunc);
  if (!stream_) throw std::runtime_error("cannot write the trajectory stream " + stream_path_);
  stream_ << kTumTrajectoryHeader << std::flush;
  segment_bytes_.back() = std::strlen(kTumTrajectoryHeader);
}

void TrajectoryRecorder::Add(const StampedPose& pose) {
  ++poses_;
  ++segment_poses_.back();
  if (stream_path_.empty()) {
    segments_.back().push_back(pose);
    return;
  }
  const std::string line = FormatTumLine(pose) + "\n";
  stream_ << line << std::flush;
  if (!stream_) throw std::runtime_error("error while writing the trajectory " + stream_path_);
  segment_bytes_.back() += line.size();
}

void TrajectoryRecorder::StartSegment() {
  if (segment_poses_.back() == 0) return;
  const int earlier = num_segments();  // the current becomes earlier segment number `earlier`
  segment_poses_.push_back(0);
  segment_bytes_.push_back(0);
  if (stream_path_.empty()) {
    segments_.emplace_back();
    return;
  }
  stream_.close();
  std::error_code error;
  fs::rename(stream_path_, SegmentPath(stream_path_, earlier), error);
  if (error) {
    throw std::runtime_error("cannot rename " + stream_path_ + ": " + error.message());
  }
  OpenStream();
}

TrajectorySnapshot TrajectoryRecorder::Snapshot() const {
  TrajectorySnapshot out;
  out.poses = poses_;
  // The current segment is written even when empty, so that `path` always exists after a save;
  // an empty earlier segment never exists (StartSegment).
  if (stream_path_.empty()) {
    out.segments = segments_;
    return out;
  }
  const int segments = num_segments();
  for (int i = 0; i < segments; ++i) {
    TrajectorySnapshot::StreamedSegment s;
    s.path = i + 1 == segments ? stream_path_ : SegmentPath(stream_path_, i + 1);
    s.file = std::make_shared<std::ifstream>(s.path, std::ios::binary);
    if (!*s.file) throw std::runtime_error("cannot read the streamed trajectory " + s.path);
    s.bytes = segment_bytes_[i];
    out.streamed.push_back(std::move(s));
  }
  return out;
}

}  // namespace dslam
