#pragma once
// Geometry of the synthetic renderer (dslam_synth): oriented boxes and triangles with materials,
// and their ray intersections. Rays start at the camera centre with direction (x_n, y_n, 1) in the
// optical frame, so a hit's ray parameter t is its depth along the optical axis [m].

#include <cstdint>
#include <vector>

#include <Eigen/Geometry>

namespace dslam {
namespace synth {

/// Procedural texture families (see texture.h).
/// kRoom picks per face of the room box: tiles (checkers) on the floor, noise on the ceiling,
/// patches or stripes on the walls.
enum class TextureStyle : uint8_t { kPatches, kCheckers, kStripes, kNoise, kCloth, kSkin, kRoom };

/// Appearance of a surface: a texture family, a seed for its random parameters and a base colour.
struct Material {
  TextureStyle style = TextureStyle::kPatches;
  uint32_t seed = 0;                                 ///< seeds the hashed value noise and patches
  Eigen::Vector3f base_bgr = {128.f, 128.f, 128.f};  ///< [0, 255] BGR
};

/// A box with half extents `half_extent` [m] centred at the origin of its frame, T_world_box.
/// `inward` boxes are seen from inside (the room); their hit is where the ray leaves the box.
struct Box {
  Eigen::Isometry3d T_world_box = Eigen::Isometry3d::Identity();
  Eigen::Vector3d half_extent = Eigen::Vector3d::Constant(0.5);  ///< [m]
  bool inward = false;
  uint16_t object_id = 0;  ///< mask id: 0 static, > 0 the moving object it belongs to
  Material material;
};

/// A triangle in the world frame [m] with texture coordinates [m] per vertex (non-rigid sheets).
struct Triangle {
  Eigen::Vector3d vertex[3];
  Eigen::Vector2d uv[3];  ///< surface coordinates [m] that move with the material
  uint16_t object_id = 0;
  Material material;
};

/// Everything visible at one instant, in the world frame.
struct SceneGeometry {
  std::vector<Box> boxes;
  std::vector<Triangle> triangles;
};

/// A box prepared for casting rays of one camera: the ray origin and direction basis in the box's
/// frame. Direction of pixel ray (x_n, y_n, 1) in the box frame = col0 * x_n + col1 * y_n + col2.
struct BoxInCamera {
  Eigen::Vector3d origin;  ///< camera centre in the box frame [m]
  Eigen::Matrix3d R_box_camera;
};

/// Prepares `box` for rays of a camera at T_world_camera.
BoxInCamera PrepareBox(const Box& box, const Eigen::Isometry3d& T_world_camera);

/// Intersects the ray with direction `dir_box` (box frame) from `prepared.origin` with `box`.
/// Returns the ray parameter t (> t_min) of the visible hit, or a negative value when missed;
/// `face` receives the hit face: axis (0..2) * 2 + (1 when on the + side).
double IntersectBox(const Box& box, const BoxInCamera& prepared, const Eigen::Vector3d& dir_box,
                    double t_min, int* face);

/// Intersects a ray from the origin with direction `dir` (camera frame) with the triangle whose
/// vertices are `a`, `b`, `c` (camera frame). Returns t (> t_min) or a negative value; `bary`
/// receives the barycentric weights of b and c.
double IntersectTriangle(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                         const Eigen::Vector3d& c, const Eigen::Vector3d& dir, double t_min,
                         Eigen::Vector2d* bary);

/// Texture coordinates [m] on `face` of a box for the hit point `p_box` (box frame): the two
/// coordinates orthogonal to the face normal, offset so they are positive.
Eigen::Vector2d BoxFaceUv(const Box& box, int face, const Eigen::Vector3d& p_box);

/// Outward (or, for inward boxes, inward) unit normal of `face` in the world frame.
Eigen::Vector3d BoxFaceNormalWorld(const Box& box, int face);

}  // namespace synth
}  // namespace dslam
