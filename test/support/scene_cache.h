#pragma once
// A file of rendered synthetic images shared by the test binaries of one test run, so that each
// scene is rendered once per run instead of once per binary (rendering is most of the time of the
// whole-trajectory tests). Holds the colour, depth and mask images of frames 0..N-1 of one
// scenario and seed, bit for bit; stamps, poses and the camera come from the SyntheticSequence.
// Written to a temporary file and renamed into place, so that binaries running at the same time
// read either the old file or the new one.

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace dslam {
namespace test {

/// One frame's images as rendered (SyntheticFrame::frame.colour, .depth_m and ::mask).
struct CachedImages {
  cv::Mat colour, depth_m, mask;
};

inline void WriteMat(std::ofstream& out, const cv::Mat& m) {
  const cv::Mat c = m.isContinuous() ? m : m.clone();
  const int32_t header[3] = {c.type(), c.rows, c.cols};
  out.write(reinterpret_cast<const char*>(header), sizeof(header));
  out.write(reinterpret_cast<const char*>(c.data),
            static_cast<std::streamsize>(c.total() * c.elemSize()));
}

inline bool ReadMat(std::ifstream& in, cv::Mat* m) {
  int32_t header[3] = {0, 0, 0};
  if (!in.read(reinterpret_cast<char*>(header), sizeof(header))) return false;
  if (header[1] < 0 || header[2] < 0 || header[1] > 10000 || header[2] > 10000) return false;
  m->create(header[1], header[2], header[0]);
  return static_cast<bool>(in.read(reinterpret_cast<char*>(m->data),
                                   static_cast<std::streamsize>(m->total() * m->elemSize())));
}

/// The number of frames in the file at `path` (0 when it is missing).
inline int CachedFrameCount(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  int32_t count = 0;
  return in.read(reinterpret_cast<char*>(&count), sizeof(count)) && count > 0 ? count : 0;
}

/// The images of the first `frames` frames in the file at `path` (all with a negative `frames`);
/// empty when it is missing, unreadable or holds fewer.
inline std::vector<CachedImages> ReadSceneCache(const std::string& path, int frames = -1) {
  std::ifstream in(path, std::ios::binary);
  int32_t count = 0;
  if (!in.read(reinterpret_cast<char*>(&count), sizeof(count)) || count < 0) return {};
  if (frames > count) return {};
  std::vector<CachedImages> frames_read(frames < 0 ? count : frames);
  for (CachedImages& f : frames_read) {
    if (!ReadMat(in, &f.colour) || !ReadMat(in, &f.depth_m) || !ReadMat(in, &f.mask)) return {};
  }
  return frames_read;
}

/// Writes `frames` to `path` (into a file of its own beside it, then renamed to `path`). Leaves
/// nothing when writing fails (a full disk): the next binary renders again.
inline void WriteSceneCache(const std::string& path, const std::vector<CachedImages>& frames) {
  const std::string partial = path + ".partial" + std::to_string(cv::getTickCount());
  std::ofstream out(partial, std::ios::binary);
  const int32_t count = static_cast<int32_t>(frames.size());
  out.write(reinterpret_cast<const char*>(&count), sizeof(count));
  for (const CachedImages& f : frames) {
    WriteMat(out, f.colour);
    WriteMat(out, f.depth_m);
    WriteMat(out, f.mask);
  }
  out.close();
  if (!out || std::rename(partial.c_str(), path.c_str()) != 0) std::remove(partial.c_str());
}

}  // namespace test
}  // namespace dslam
