#include "dslam/synth/geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dslam {
namespace synth {

BoxInCamera PrepareBox(const Box& box, const Eigen::Isometry3d& T_world_camera) {
  const Eigen::Isometry3d T_box_camera = box.T_world_box.inverse() * T_world_camera;
  BoxInCamera prepared;
  prepared.origin = T_box_camera.translation();
  prepared.R_box_camera = T_box_camera.linear();
  return prepared;
}

double IntersectBox(const Box& box, const BoxInCamera& prepared, const Eigen::Vector3d& dir_box,
                    double t_min, int* face) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  double t_enter = -kInf, t_exit = kInf;
  int face_enter = 0, face_exit = 0;
  for (int axis = 0; axis < 3; ++axis) {
    const double o = prepared.origin[axis];
    const double d = dir_box[axis];
    const double h = box.half_extent[axis];
    if (std::abs(d) < 1e-12) {
      if (o < -h || o > h) return -1.0;
      continue;
    }
    const double inv = 1.0 / d;
    double t_lo = (-h - o) * inv, t_hi = (h - o) * inv;
    int f_lo = axis * 2, f_hi = axis * 2 + 1;
    if (t_lo > t_hi) {
      std::swap(t_lo, t_hi);
      std::swap(f_lo, f_hi);
    }
    if (t_lo > t_enter) {
      t_enter = t_lo;
      face_enter = f_lo;
    }
    if (t_hi < t_exit) {
      t_exit = t_hi;
      face_exit = f_hi;
    }
  }
  if (t_exit < t_enter) return -1.0;
  if (box.inward) {
    if (t_exit <= t_min) return -1.0;
    *face = face_exit;
    return t_exit;
  }
  if (t_enter <= t_min) return -1.0;  // camera inside or box behind: not visible from outside
  *face = face_enter;
  return t_enter;
}

double IntersectTriangle(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                         const Eigen::Vector3d& c, const Eigen::Vector3d& dir, double t_min,
                         Eigen::Vector2d* bary) {
  // Moeller-Trumbore with the ray origin at the camera centre.
  const Eigen::Vector3d e1 = b - a, e2 = c - a;
  const Eigen::Vector3d p = dir.cross(e2);
  const double det = e1.dot(p);
  if (std::abs(det) < 1e-14) return -1.0;
  const double inv_det = 1.0 / det;
  const Eigen::Vector3d s = -a;
  const double u = s.dot(p) * inv_det;
  if (u < 0.0 || u > 1.0) return -1.0;
  const Eigen::Vector3d q = s.cross(e1);
  const double v = dir.dot(q) * inv_det;
  if (v < 0.0 || u + v > 1.0) return -1.0;
  const double t = e2.dot(q) * inv_det;
  if (t <= t_min) return -1.0;
  *bary = Eigen::Vector2d(u, v);
  return t;
}

Eigen::Vector2d BoxFaceUv(const Box& box, int face, const Eigen::Vector3d& p_box) {
  const int axis = face / 2;
  const int a0 = (axis + 1) % 3, a1 = (axis + 2) % 3;
  // Faces on opposite sides get distinct offsets so their textures differ.
  const double offset = (face % 2) ? 0.0 : 17.0;
  return Eigen::Vector2d(p_box[a0] + box.half_extent[a0] + offset,
                         p_box[a1] + box.half_extent[a1] + offset);
}

Eigen::Vector3d BoxFaceNormalWorld(const Box& box, int face) {
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  n[face / 2] = (face % 2) ? 1.0 : -1.0;
  if (box.inward) n = -n;
  return box.T_world_box.linear() * n;
}

}  // namespace synth
}  // namespace dslam
