// The static room of the synthetic scenarios: walls, floor, ceiling and furniture
// (scenario.h).
#include <random>

#include "dslam/synth/scenario.h"
#include "dslam/synth/texture.h"

namespace dslam {
namespace synth {
namespace {

/// Adds a static box of full size `size` [m] centred at `centre` [m] with a random texture.
void AddFurniture(const Eigen::Vector3d& centre, const Eigen::Vector3d& size, std::mt19937* rng,
                  SceneGeometry* scene) {
  static const TextureStyle kStyles[4] = {TextureStyle::kPatches, TextureStyle::kCheckers,
                                          TextureStyle::kStripes, TextureStyle::kNoise};
  Box box;
  box.T_world_box = Eigen::Translation3d(centre);
  box.half_extent = 0.5 * size;
  box.material.style = kStyles[(*rng)() % 4];
  box.material.seed = (*rng)();
  box.material.base_bgr = HashColour((*rng)());
  scene->boxes.push_back(box);
}

}  // namespace

SceneGeometry BuildStaticScene(const RoomParams& room, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> jitter(-room.furniture_jitter_m, room.furniture_jitter_m);
  SceneGeometry scene;
  Box shell;
  shell.T_world_box = Eigen::Translation3d(0.5 * (room.min_corner_m + room.max_corner_m));
  shell.half_extent = 0.5 * (room.max_corner_m - room.min_corner_m);
  shell.inward = true;
  shell.material.style = TextureStyle::kRoom;
  shell.material.seed = rng();
  scene.boxes.push_back(shell);
  const Eigen::Vector3d lo = room.min_corner_m, hi = room.max_corner_m;
  auto shift = [&](double x, double y) { return Eigen::Vector3d(x + jitter(rng), y, 0.0); };
  // Table with legs and objects on it, in the back half of the room.
  const Eigen::Vector3d table = shift(0.4, hi.y() - 1.4);
  AddFurniture(table + Eigen::Vector3d(0, 0, 0.74), {1.4, 0.8, 0.05}, &rng, &scene);
  for (int i = 0; i < 4; ++i) {
    AddFurniture(table + Eigen::Vector3d(i & 1 ? 0.62 : -0.62, i & 2 ? 0.32 : -0.32, 0.36),
                 {0.05, 0.05, 0.72}, &rng, &scene);
  }
  std::uniform_real_distribution<double> item(0.12, 0.35);
  for (int i = 0; i < 3; ++i) {
    Eigen::Vector3d size;
    for (int k = 0; k < 3; ++k) size[k] = item(rng);  // sequenced: evaluation order is fixed
    AddFurniture(table + Eigen::Vector3d(-0.45 + 0.45 * i, 0.1 * (i - 1), 0.765 + 0.5 * size.z()),
                 size, &rng, &scene);
  }
  // Against the far wall: a tall shelf and a low cabinet with a box on it.
  AddFurniture(shift(-1.6, hi.y() - 0.2) + Eigen::Vector3d(0, 0, 0.9), {1.2, 0.4, 1.8}, &rng,
               &scene);
  const Eigen::Vector3d cabinet = shift(1.9, hi.y() - 0.25);
  AddFurniture(cabinet + Eigen::Vector3d(0, 0, 0.5), {1.0, 0.5, 1.0}, &rng, &scene);
  AddFurniture(cabinet + Eigen::Vector3d(0.2, 0, 1.2), {0.4, 0.3, 0.4}, &rng, &scene);
  // Pictures on the walls.
  AddFurniture(shift(0.2, hi.y() - 0.02) + Eigen::Vector3d(0, 0, 1.75), {1.0, 0.04, 0.7}, &rng,
               &scene);
  const double left_picture_y = 0.8 + jitter(rng);
  AddFurniture(Eigen::Vector3d(lo.x() + 0.02, left_picture_y, 1.6), {0.04, 0.9, 0.6}, &rng, &scene);
  const double right_picture_y = 1.6 + jitter(rng);
  AddFurniture(Eigen::Vector3d(hi.x() - 0.02, right_picture_y, 1.5), {0.04, 0.8, 0.8}, &rng,
               &scene);
  // Sofa (seat and back) along the left wall, tall cabinet along the right wall.
  const double sofa_y = 0.6 + jitter(rng);
  AddFurniture(Eigen::Vector3d(lo.x() + 0.45, sofa_y, 0.25), {0.8, 1.8, 0.5}, &rng, &scene);
  AddFurniture(Eigen::Vector3d(lo.x() + 0.1, sofa_y, 0.6), {0.2, 1.8, 1.0}, &rng, &scene);
  const double cupboard_y = 0.2 + jitter(rng);
  AddFurniture(Eigen::Vector3d(hi.x() - 0.25, cupboard_y, 0.9), {0.5, 0.8, 1.8}, &rng, &scene);
  return scene;
}

}  // namespace synth
}  // namespace dslam
