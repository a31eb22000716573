#pragma once
// A keyframe map file with every field set (none at its default), for the map_file tests and
// the fuzz seeds, and a field-by-field comparison of two files.

#include <cstdint>
#include <limits>

#include <gtest/gtest.h>

#include "dslam/map_file/keyframe_map_file.h"

namespace dslam {
namespace test {

/// A 16x12 camera with distortion.
inline PinholeCamera SampleCamera() {
  return PinholeCamera(16, 12, 20.5, 21.25, 7.75, 5.5,
                       Distortion{0.1, -0.02, 0.001, -0.002, 0.003});
}

/// Point `i` with every field set from `i`; without descriptor when i % 3 == 2.
inline MapPoint SamplePoint(int i) {
  MapPoint p;
  p.id = 3 * i + 1;
  p.p_world = Eigen::Vector3d(0.1 * i, -0.2 * i, 1.0 + i);
  for (int r = 0; r < 3; ++r) {  // symmetric, diagonally dominant: positive definite
    for (int c = 0; c < 3; ++c)
      p.cov_world(r, c) = r == c ? 1e-3 * (r + 1) + 1e-4 * i : 1e-5 * (r + c + 1);
  }
  if (i % 3 != 2) {
    p.descriptor = cv::Mat(1, 32, CV_8U);
    for (int k = 0; k < 32; ++k) p.descriptor.at<uchar>(0, k) = static_cast<uchar>(7 * k + i);
  }
  p.octave = i % 4;
  p.created_feature = 10 + i;
  p.reference_distance_m = 1.5 + i;
  p.marked = i % 2 == 0;
  p.candidate = i % 3 == 0;
  p.created_frame = 100 + i;
  p.last_seen_frame = 200 + i;
  p.times_visible = 30 + i;
  p.times_found = 20 + i;
  p.isolated_frames = i % 5;
  p.static_streak = 1 + i % 2;
  p.dynamic_frames = 2 + i % 3;
  p.observing_keyframes = 9;  // not stored: recounted on load
  return p;
}

/// Keyframe `k` observing and measuring points of SamplePoint ids (and one id that no point has).
inline KeyFrame SampleKeyFrame(int k, int points) {
  KeyFrame kf;
  kf.id = 2 * k + 5;
  kf.frame_index = 10 * k + 3;
  kf.stamp_s = 1000.25 + k;
  kf.T_world_camera = Eigen::Translation3d(0.5 * k, 0.1, -0.2) *
                      Eigen::AngleAxisd(0.1 + 0.2 * k, Eigen::Vector3d(1, 2, 3).normalized());
  for (int i = k % 2; i < points; i += 2) kf.points.push_back(3 * i + 1);
  kf.points.push_back(999);  // absent from the map: Map::FromContents drops it
  kf.measurements.T_camera_world = kf.T_world_camera.inverse();
  for (int i = 0; i < points; i += 1 + k % 2) {
    PointMeasurement m;
    m.y_camera = Eigen::Vector3d(0.01 * i, 0.02 * k, 1.0 + 0.1 * i);
    m.covariance = Eigen::Matrix3d::Identity() * (1e-3 * (i + 1)) + Eigen::Matrix3d::Constant(1e-5);
    m.depth_mean_m = 1.0 + 0.1 * i;
    m.depth_sigma_m = 0.01 + 0.001 * i;
    kf.measurements.by_point.emplace(3 * i + 1, m);
  }
  for (int r = 0; r < 6; ++r) {
    for (int c = 0; c < 6; ++c) kf.information(r, c) = r == c ? 1e4 + k : 0.5 * (r + c) - k;
  }
  kf.weak_since_previous = k % 2 == 1;
  return kf;
}

/// Images of the sample camera's size: a colour gradient and depth from 0.3 m to 9 m with
/// holes (0) and a NaN, a negative and a far (70 m) pixel, all stored as 0.
inline KeyFrameImages SampleImages(int k, bool grey = false) {
  KeyFrameImages images;
  images.colour = cv::Mat(12, 16, grey ? CV_8UC1 : CV_8UC3);
  images.depth_m = cv::Mat(12, 16, CV_32FC1);
  for (int r = 0; r < 12; ++r) {
    for (int c = 0; c < 16; ++c) {
      const auto v = static_cast<uchar>(16 * c + r + k);
      if (grey) {
        images.colour.at<uchar>(r, c) = v;
      } else {
        images.colour.at<cv::Vec3b>(r, c) = cv::Vec3b(v, static_cast<uchar>(255 - v), 17 * r);
      }
      images.depth_m.at<float>(r, c) =
          (r * 16 + c) % 7 == 0 ? 0.0f : 0.3f + 0.0456789f * (r * 16 + c);
    }
  }
  images.depth_m.at<float>(0, 1) = std::numeric_limits<float>::quiet_NaN();
  images.depth_m.at<float>(0, 2) = -1.0f;
  images.depth_m.at<float>(0, 3) = 70.0f;
  return images;
}

/// Settings with every field off its default.
inline KeyFrameMapSettings SampleSettings() {
  return KeyFrameMapSettings{6, 1.25, DepthNoiseConfig{1.5, 2e-3, 1.5e-3, 0.25, 7.5}};
}

/// A file of `points` points and `keyframes` keyframes, images of every other keyframe, with
/// SampleSettings (format version 2).
inline KeyFrameMapFile SampleMapFile(int points, int keyframes, bool images) {
  KeyFrameMapFile file{SampleCamera(), 0x723a8e39b1688a18ull, {}, {}, SampleSettings()};
  for (int i = 0; i < points; ++i) file.contents.points.push_back(SamplePoint(i));
  for (int k = 0; k < keyframes; ++k) {
    file.contents.keyframes.push_back(SampleKeyFrame(k, points));
    if (images && k % 2 == 0)
      file.images[file.contents.keyframes.back().id] = SampleImages(k, k == 2);
  }
  return file;
}

/// Expects every field but observing_keyframes equal (doubles bit-for-bit).
inline void ExpectSamePoint(const MapPoint& p, const MapPoint& q) {
  EXPECT_EQ(p.id, q.id);
  EXPECT_EQ(p.p_world, q.p_world);
  EXPECT_EQ(p.cov_world, q.cov_world);
  ASSERT_EQ(p.descriptor.empty(), q.descriptor.empty()) << p.id;
  if (!p.descriptor.empty()) {
    EXPECT_EQ(q.descriptor.type(), CV_8U);
    EXPECT_EQ(q.descriptor.size(), cv::Size(32, 1));
    EXPECT_EQ(cv::norm(p.descriptor, q.descriptor, cv::NORM_HAMMING), 0.0);
  }
  EXPECT_EQ(p.octave, q.octave);
  EXPECT_EQ(p.created_feature, q.created_feature);
  EXPECT_EQ(p.reference_distance_m, q.reference_distance_m);
  EXPECT_EQ(p.marked, q.marked);
  EXPECT_EQ(p.candidate, q.candidate);
  EXPECT_EQ(p.created_frame, q.created_frame);
  EXPECT_EQ(p.last_seen_frame, q.last_seen_frame);
  EXPECT_EQ(p.times_visible, q.times_visible);
  EXPECT_EQ(p.times_found, q.times_found);
  EXPECT_EQ(p.isolated_frames, q.isolated_frames);
  EXPECT_EQ(p.static_streak, q.static_streak);
  EXPECT_EQ(p.dynamic_frames, q.dynamic_frames);
}

/// Expects every field equal (doubles bit-for-bit).
inline void ExpectSameKeyFrame(const KeyFrame& k, const KeyFrame& l) {
  EXPECT_EQ(k.id, l.id);
  EXPECT_EQ(k.frame_index, l.frame_index);
  EXPECT_EQ(k.stamp_s, l.stamp_s);
  EXPECT_EQ(k.T_world_camera.matrix(), l.T_world_camera.matrix());
  EXPECT_EQ(k.points, l.points);
  EXPECT_EQ(k.measurements.T_camera_world.matrix(), l.measurements.T_camera_world.matrix());
  ASSERT_EQ(k.measurements.by_point.size(), l.measurements.by_point.size());
  for (const auto& [id, m] : k.measurements.by_point) {
    ASSERT_EQ(l.measurements.by_point.count(id), 1u) << id;
    const PointMeasurement& n = l.measurements.by_point.at(id);
    EXPECT_EQ(m.y_camera, n.y_camera);
    EXPECT_EQ(m.covariance, n.covariance);
    EXPECT_EQ(m.depth_mean_m, n.depth_mean_m);
    EXPECT_EQ(m.depth_sigma_m, n.depth_sigma_m);
  }
  EXPECT_EQ(k.information, l.information);
  EXPECT_EQ(k.weak_since_previous, l.weak_since_previous);
}

/// Expects equal settings (bit for bit; or none in both).
inline void ExpectSameSettings(const KeyFrameMapFile& a, const KeyFrameMapFile& b) {
  ASSERT_EQ(a.settings.has_value(), b.settings.has_value());
  if (!a.settings) return;
  EXPECT_EQ(a.settings->orb_levels, b.settings->orb_levels);
  EXPECT_EQ(a.settings->orb_scale_factor, b.settings->orb_scale_factor);
  const DepthNoiseConfig& m = a.settings->depth_noise;
  const DepthNoiseConfig& n = b.settings->depth_noise;
  EXPECT_EQ(m.pixel_sigma_px, n.pixel_sigma_px);
  EXPECT_EQ(m.sigma_d_quadratic, n.sigma_d_quadratic);
  EXPECT_EQ(m.sigma_d_constant_m, n.sigma_d_constant_m);
  EXPECT_EQ(m.min_depth_m, n.min_depth_m);
  EXPECT_EQ(m.max_depth_m, n.max_depth_m);
}

/// Expects equal camera, identity, settings, points and keyframes; images are compared by the
/// caller.
inline void ExpectSameMap(const KeyFrameMapFile& a, const KeyFrameMapFile& b) {
  EXPECT_EQ(CheckCompatible(a, b.camera, b.vocabulary_identity,
                            b.settings.value_or(KeyFrameMapSettings{})),
            "");
  ExpectSameSettings(a, b);
  ASSERT_EQ(a.contents.points.size(), b.contents.points.size());
  ASSERT_EQ(a.contents.keyframes.size(), b.contents.keyframes.size());
  for (size_t i = 0; i < a.contents.points.size(); ++i) {
    ExpectSamePoint(a.contents.points[i], b.contents.points[i]);
  }
  for (size_t i = 0; i < a.contents.keyframes.size(); ++i) {
    ExpectSameKeyFrame(a.contents.keyframes[i], b.contents.keyframes[i]);
  }
}

}  // namespace test
}  // namespace dslam
