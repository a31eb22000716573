#include "dslam/synth/camera_motion.h"

#include <cmath>
#include <stdexcept>

#include "dslam/synth/texture.h"

namespace dslam {
namespace synth {
namespace {

constexpr double kTwoPi = 2.0 * M_PI;
constexpr double kDegToRad = M_PI / 180.0;

double Wave(double amplitude, double period_s, double t_s, double phase = 0.0) {
  return amplitude * std::sin(kTwoPi * t_s / period_s + phase);
}

Eigen::Isometry3d StaticJitter(const CameraMotionParams& p, double t, uint32_t seed,
                               const Eigen::Isometry3d& base) {
  const double periods[3] = {1.0, 1.37, 1.71};
  Eigen::Vector3d offset, angles;
  for (int i = 0; i < 3; ++i) {
    const double phase_t = kTwoPi * HashToUnit(Hash3(seed, i, 1));
    const double phase_r = kTwoPi * HashToUnit(Hash3(seed, i, 2));
    offset[i] = Wave(p.jitter_translation_m, p.jitter_period_s * periods[i], t, phase_t) -
                Wave(p.jitter_translation_m, p.jitter_period_s * periods[i], 0.0, phase_t);
    angles[i] =
        Wave(p.jitter_rotation_deg * kDegToRad, p.jitter_period_s * periods[2 - i], t, phase_r) -
        Wave(p.jitter_rotation_deg * kDegToRad, p.jitter_period_s * periods[2 - i], 0.0, phase_r);
  }
  Eigen::Isometry3d pose = base;
  pose.translation() += base.linear() * offset;
  pose.linear() = base.linear() * (Eigen::AngleAxisd(angles[0], Eigen::Vector3d::UnitX()) *
                                   Eigen::AngleAxisd(angles[1], Eigen::Vector3d::UnitY()) *
                                   Eigen::AngleAxisd(angles[2], Eigen::Vector3d::UnitZ()))
                                      .toRotationMatrix();
  return pose;
}

Eigen::Isometry3d Halfsphere(const CameraMotionParams& p, double t) {
  Eigen::Vector3d forward = p.look_at_m - p.position_m;
  forward.z() = 0.0;
  forward.normalize();
  const Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d right = forward.cross(up);
  const double r = p.halfsphere_radius_m;
  const Eigen::Vector3d centre = p.position_m + r * forward;
  const double az = Wave(p.halfsphere_azimuth_deg * kDegToRad, p.halfsphere_azimuth_period_s, t);
  const double el = p.halfsphere_elevation_deg * kDegToRad * 0.5 *
                    (1.0 - std::cos(kTwoPi * t / p.halfsphere_elevation_period_s));
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = centre + r * (-std::cos(el) * std::cos(az) * forward +
                                     std::cos(el) * std::sin(az) * right + std::sin(el) * up);
  pose.linear() = LookAtRotation(pose.translation(), p.look_at_m);
  return pose;
}

}  // namespace

CameraMotionKind ParseCameraMotion(const std::string& name) {
  if (name == "static") return CameraMotionKind::kStatic;
  if (name == "xyz") return CameraMotionKind::kXyz;
  if (name == "rpy") return CameraMotionKind::kRpy;
  if (name == "halfsphere") return CameraMotionKind::kHalfsphere;
  if (name == "tour") return CameraMotionKind::kTour;
  throw std::invalid_argument("unknown camera motion '" + name +
                              "' (static, xyz, rpy, halfsphere, tour)");
}

std::string CameraMotionName(CameraMotionKind kind) {
  switch (kind) {
    case CameraMotionKind::kStatic:
      return "static";
    case CameraMotionKind::kXyz:
      return "xyz";
    case CameraMotionKind::kRpy:
      return "rpy";
    case CameraMotionKind::kHalfsphere:
      return "halfsphere";
    case CameraMotionKind::kTour:
      return "tour";
  }
  return "unknown";
}

Eigen::Matrix3d LookAtRotation(const Eigen::Vector3d& position, const Eigen::Vector3d& target) {
  const Eigen::Vector3d z = (target - position).normalized();
  const Eigen::Vector3d x = z.cross(Eigen::Vector3d::UnitZ()).normalized();
  const Eigen::Vector3d y = z.cross(x);
  Eigen::Matrix3d R;
  R << x, y, z;
  return R;
}

Eigen::Isometry3d CameraPoseAt(const CameraMotionParams& p, double t, uint32_t seed) {
  Eigen::Isometry3d base = Eigen::Isometry3d::Identity();
  base.translation() = p.position_m;
  base.linear() = LookAtRotation(p.position_m, p.look_at_m);
  switch (p.kind) {
    case CameraMotionKind::kStatic:
      return StaticJitter(p, t, seed, base);
    case CameraMotionKind::kXyz: {
      Eigen::Vector3d offset;
      for (int i = 0; i < 3; ++i) offset[i] = Wave(p.xyz_amplitude_m[i], p.xyz_period_s[i], t);
      base.translation() += base.linear() * offset;
      return base;
    }
    case CameraMotionKind::kRpy: {
      Eigen::Vector3d a;
      for (int i = 0; i < 3; ++i)
        a[i] = Wave(p.rpy_amplitude_deg[i] * kDegToRad, p.rpy_period_s[i], t);
      if (p.rpy_translation_m != Eigen::Vector3d::Zero()) {  // hand shake (default: none)
        Eigen::Vector3d offset;
        for (int i = 0; i < 3; ++i)
          offset[i] = Wave(p.rpy_translation_m[i], p.rpy_translation_period_s[i], t);
        base.translation() += base.linear() * offset;
      }
      base.linear() = base.linear() * (Eigen::AngleAxisd(a[0], Eigen::Vector3d::UnitZ()) *
                                       Eigen::AngleAxisd(a[1], Eigen::Vector3d::UnitX()) *
                                       Eigen::AngleAxisd(a[2], Eigen::Vector3d::UnitY()))
                                          .toRotationMatrix();
      return base;
    }
    case CameraMotionKind::kHalfsphere:
      return Halfsphere(p, t);
    case CameraMotionKind::kTour:
      return TourPoseAt(p.tour, t, seed);
  }
  return base;
}

}  // namespace synth
}  // namespace dslam
