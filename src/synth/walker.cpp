// Person-like walkers: 10 boxes whose limbs swing with the gait phase (actors.h).
#include <algorithm>
#include <cmath>

#include "dslam/synth/actors.h"
#include "dslam/synth/texture.h"

namespace dslam {
namespace synth {
namespace {

constexpr double kTwoPi = 2.0 * M_PI;
constexpr double kDegToRad = M_PI / 180.0;

/// Joint angles of one pose [rad]; positive = limb swung forward.
struct Pose {
  double hip[2], knee[2], arm[2], elbow[2];
  double yaw_offset = 0.0;
};

Pose GaitPose(const WalkerParams& w, const WalkerState& state) {
  const double phi = state.gait_phase_rad;
  const double hip = w.hip_swing_deg * kDegToRad, knee = w.knee_bend_deg * kDegToRad;
  const double arm = w.arm_swing_deg * kDegToRad;
  Pose p;
  for (int side = 0; side < 2; ++side) {
    const double sign = side == 0 ? 1.0 : -1.0;
    p.hip[side] = sign * hip * std::sin(phi);
    p.knee[side] = knee * std::max(0.0, sign * std::cos(phi));
    p.arm[side] = -sign * arm * std::sin(phi);
    p.elbow[side] = 20.0 * kDegToRad;
  }
  if (state.idle_time_s >= 0.0) {
    const double sway = w.idle_sway_deg * kDegToRad;
    const double tau = state.idle_time_s;
    p.yaw_offset = sway * std::sin(kTwoPi * 0.5 * tau);
    p.arm[0] += 2.5 * sway * std::sin(kTwoPi * 0.8 * tau);
    p.arm[1] -= 2.0 * sway * std::sin(kTwoPi * 0.65 * tau);
    p.elbow[0] += 2.0 * sway * (1.0 - std::cos(kTwoPi * 0.8 * tau));
  }
  return p;
}

Material PartMaterial(uint32_t seed, int part, TextureStyle style, const Eigen::Vector3f& bgr) {
  Material m;
  m.style = style;
  m.seed = seed * 16u + static_cast<uint32_t>(part);
  m.base_bgr = bgr;
  return m;
}

/// A limb hanging from `joint` (walker frame) swung forward by `angle`; returns its far end.
Eigen::Vector3d AddLimb(const Eigen::Isometry3d& T_world_walker, const Eigen::Vector3d& joint,
                        double angle, double length, double half_width, const Material& material,
                        uint16_t id, SceneGeometry* scene) {
  const Eigen::Vector3d dir(std::sin(angle), 0.0, -std::cos(angle));
  Box box;
  Eigen::Isometry3d T_walker_box = Eigen::Isometry3d::Identity();
  T_walker_box.translation() = joint + 0.5 * length * dir;
  T_walker_box.linear() = Eigen::AngleAxisd(-angle, Eigen::Vector3d::UnitY()).toRotationMatrix();
  box.T_world_box = T_world_walker * T_walker_box;
  box.half_extent = Eigen::Vector3d(half_width, half_width, 0.5 * length);
  box.object_id = id;
  box.material = material;
  scene->boxes.push_back(box);
  return joint + length * dir;
}

void AddBlock(const Eigen::Isometry3d& T_world_walker, const Eigen::Vector3d& centre,
              const Eigen::Vector3d& half, const Material& material, uint16_t id,
              SceneGeometry* scene) {
  Box box;
  box.T_world_box = T_world_walker * Eigen::Translation3d(centre);
  box.half_extent = half;
  box.object_id = id;
  box.material = material;
  scene->boxes.push_back(box);
}

}  // namespace

WalkerState WalkerStateAt(const WalkerParams& w, double t_s) {
  const size_t n = w.path_m.size();
  std::vector<double> length(n), dwell(n, 0.0);
  double cycle = 0.0, loop_length = 0.0;
  for (size_t i = 0; i < n; ++i) {
    length[i] = (w.path_m[(i + 1) % n] - w.path_m[i]).norm();
    if (i < w.dwell_s.size()) dwell[i] = w.dwell_s[i];
    loop_length += length[i];
  }
  for (size_t i = 0; i < n; ++i) cycle += length[i] / w.speed_mps + dwell[(i + 1) % n];
  const double t_total = t_s + w.start_offset_m / w.speed_mps;
  const double laps = std::floor(t_total / cycle);
  double tau = t_total - laps * cycle;
  double walked = laps * loop_length;
  WalkerState state;
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d a = w.path_m[i], b = w.path_m[(i + 1) % n];
    state.heading_rad = std::atan2(b.y() - a.y(), b.x() - a.x());
    const double walk_time = length[i] / w.speed_mps;
    if (tau < walk_time) {
      state.position_m = a + (b - a) * (tau / walk_time);
      walked += tau * w.speed_mps;
      break;
    }
    tau -= walk_time;
    walked += length[i];
    state.position_m = b;
    if (tau < dwell[(i + 1) % n]) {
      state.idle_time_s = tau;
      break;
    }
    tau -= dwell[(i + 1) % n];
  }
  state.gait_phase_rad = kTwoPi * walked / w.stride_m;
  return state;
}

Eigen::Vector3d WalkerVelocityAt(const WalkerParams& w, double t_s) {
  const WalkerState state = WalkerStateAt(w, t_s);
  if (state.idle_time_s >= 0.0) return Eigen::Vector3d::Zero();
  return w.speed_mps *
         Eigen::Vector3d(std::cos(state.heading_rad), std::sin(state.heading_rad), 0.0);
}

void AppendWalker(const WalkerParams& w, double t_s, uint16_t id, SceneGeometry* scene) {
  const WalkerState state = WalkerStateAt(w, t_s);
  const Pose pose = GaitPose(w, state);
  const double k = w.height_m / 1.75;
  Eigen::Isometry3d T_world_walker = Eigen::Isometry3d::Identity();
  T_world_walker.translation() << state.position_m, 0.0;
  T_world_walker.linear() =
      Eigen::AngleAxisd(state.heading_rad + pose.yaw_offset, Eigen::Vector3d::UnitZ())
          .toRotationMatrix();
  const Eigen::Vector3f shirt = HashColour(Hash3(w.look_seed, 1, 99));
  const Eigen::Vector3f trousers = 0.5f * HashColour(Hash3(w.look_seed, 2, 99));
  const Eigen::Vector3f skin(110.f, 150.f, 200.f);
  const uint32_t s = w.look_seed;
  const Eigen::Isometry3d& T = T_world_walker;  // body positions below are scaled by k
  AddBlock(T, k * Eigen::Vector3d(0, 0, 1.2), k * Eigen::Vector3d(0.13, 0.22, 0.3),
           PartMaterial(s, 0, TextureStyle::kCloth, shirt), id, scene);
  AddBlock(T, k * Eigen::Vector3d(0.01, 0, 1.625), k * Eigen::Vector3d(0.1, 0.09, 0.125),
           PartMaterial(s, 1, TextureStyle::kSkin, skin), id, scene);
  for (int side = 0; side < 2; ++side) {
    const double y = side == 0 ? 1.0 : -1.0;
    const Eigen::Vector3d elbow =
        AddLimb(T, k * Eigen::Vector3d(0, 0.29 * y, 1.47), pose.arm[side], 0.3 * k, 0.05 * k,
                PartMaterial(s, 2 + side, TextureStyle::kCloth, shirt), id, scene);
    AddLimb(T, elbow, pose.arm[side] + pose.elbow[side], 0.3 * k, 0.045 * k,
            PartMaterial(s, 4 + side, TextureStyle::kSkin, skin), id, scene);
    const Eigen::Vector3d knee =
        AddLimb(T, k * Eigen::Vector3d(0, 0.11 * y, 0.9), pose.hip[side], 0.45 * k, 0.075 * k,
                PartMaterial(s, 6 + side, TextureStyle::kCloth, trousers), id, scene);
    AddLimb(T, knee, pose.hip[side] - pose.knee[side], 0.45 * k, 0.06 * k,
            PartMaterial(s, 8 + side, TextureStyle::kCloth, trousers), id, scene);
  }
}

}  // namespace synth
}  // namespace dslam
