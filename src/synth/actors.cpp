// Rigid moving boxes and the deforming sheet (actors.h); walkers are in walker.cpp.
#include "dslam/synth/actors.h"

#include <cmath>

#include "dslam/synth/texture.h"

namespace dslam {
namespace synth {
namespace {
constexpr double kTwoPi = 2.0 * M_PI;
}  // namespace

Eigen::Vector3d MovingBoxCentreAt(const MovingBoxParams& p, double t_s) {
  const Eigen::Vector3d span = p.end_m - p.start_m;
  const double distance = span.norm();
  Eigen::Vector3d centre = p.start_m;
  if (distance > 0.0) {
    const double s = std::fmod(p.speed_mps * t_s, 2.0 * distance);
    centre += span * ((s < distance ? s : 2.0 * distance - s) / distance);
  }
  return centre;
}

Eigen::Vector3d MovingBoxVelocityAt(const MovingBoxParams& p, double t_s) {
  const Eigen::Vector3d span = p.end_m - p.start_m;
  const double distance = span.norm();
  if (distance <= 0.0) return Eigen::Vector3d::Zero();
  const double s = std::fmod(p.speed_mps * t_s, 2.0 * distance);
  return (s < distance ? p.speed_mps : -p.speed_mps) / distance * span;
}

void AppendMovingBox(const MovingBoxParams& p, double t_s, uint16_t id, SceneGeometry* scene) {
  const Eigen::Vector3d centre = MovingBoxCentreAt(p, t_s);
  Box box;
  box.T_world_box =
      Eigen::Translation3d(centre) *
      Eigen::AngleAxisd(p.yaw_rate_dps * M_PI / 180.0 * t_s, Eigen::Vector3d::UnitZ());
  box.half_extent = 0.5 * p.size_m;
  box.object_id = id;
  box.material.style = TextureStyle::kPatches;
  box.material.seed = p.look_seed * 31u + 7u;
  box.material.base_bgr = HashColour(Hash3(p.look_seed, 3, 99));
  scene->boxes.push_back(box);
}

double SheetDisplacement(const SheetParams& p, double s_m, double h_m, double t_s) {
  const double hang = h_m / p.height_m;  // 0 at the fixed top edge, 1 at the bottom
  return p.amplitude_m * hang * std::sin(kTwoPi * (s_m / p.wavelength_m - p.frequency_hz * t_s)) +
         0.4 * p.amplitude_m * hang * hang *
             std::sin(kTwoPi * (h_m / (0.7 * p.wavelength_m) + 0.8 * p.frequency_hz * t_s));
}

void AppendSheet(const SheetParams& p, double t_s, uint16_t id, SceneGeometry* scene) {
  const double yaw = p.yaw_deg * M_PI / 180.0;
  const Eigen::Vector3d across(std::cos(yaw), std::sin(yaw), 0.0);
  const Eigen::Vector3d normal(-std::sin(yaw), std::cos(yaw), 0.0);
  const int nx = p.columns + 1;
  std::vector<Eigen::Vector3d> vertex;
  std::vector<Eigen::Vector2d> uv;
  for (int j = 0; j <= p.rows; ++j) {
    for (int i = 0; i <= p.columns; ++i) {
      const double s = p.width_m * i / p.columns, h = p.height_m * j / p.rows;
      vertex.push_back(p.top_left_m + s * across - h * Eigen::Vector3d::UnitZ() +
                       SheetDisplacement(p, s, h, t_s) * normal);
      uv.emplace_back(s, h);
    }
  }
  Triangle tri;
  tri.object_id = id;
  tri.material.style = TextureStyle::kNoise;
  tri.material.seed = p.look_seed * 37u + 3u;
  tri.material.base_bgr = HashColour(Hash3(p.look_seed, 4, 99));
  const int corners[2][3] = {{0, 1, nx + 1}, {0, nx + 1, nx}};
  for (int j = 0; j < p.rows; ++j) {
    for (int i = 0; i < p.columns; ++i) {
      const int base = j * nx + i;
      for (const auto& c : corners) {
        for (int k = 0; k < 3; ++k) {
          tri.vertex[k] = vertex[base + c[k]];
          tri.uv[k] = uv[base + c[k]];
        }
        scene->triangles.push_back(tri);
      }
    }
  }
}

}  // namespace synth
}  // namespace dslam
