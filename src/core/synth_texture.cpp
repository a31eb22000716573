#include "dslam/core/synth_texture.h"

#include <algorithm>
#include <cmath>

namespace dslam {
namespace synth {
namespace {

float Smooth(float x) { return x * x * (3.0f - 2.0f * x); }

/// Sharp-edged rectangles, one per cell of size `cell_m` with probability `probability`; returns
/// true and the patch colour when `uv` lies inside a patch.
bool Patch(uint32_t seed, const Eigen::Vector2d& uv, double cell_m, float probability,
           Eigen::Vector3f* colour) {
  const double gx = uv.x() / cell_m, gy = uv.y() / cell_m;
  const int32_t ix = static_cast<int32_t>(std::floor(gx)),
                iy = static_cast<int32_t>(std::floor(gy));
  const uint32_t h = Hash3(seed, ix, iy);
  if (HashToUnit(h) >= probability) return false;
  const float fx = static_cast<float>(gx - ix), fy = static_cast<float>(gy - iy);
  const uint32_t h2 = Hash3(seed ^ 0x9e3779b9u, ix, iy);
  const float x0 = 0.05f + 0.35f * HashToUnit(h2), y0 = 0.05f + 0.35f * HashToUnit(h2 * 747796405u);
  const float x1 = x0 + 0.25f + 0.3f * HashToUnit(h2 * 2891336453u);
  const float y1 = y0 + 0.25f + 0.3f * HashToUnit(h2 * 1181783497u);
  if (fx < x0 || fx > x1 || fy < y0 || fy > y1) return false;
  *colour = HashColour(h2 * 277803737u);
  return true;
}

/// Multi-scale value noise in [0, 1] with periods `coarse`, coarse/4 and coarse/12 [m].
float Fractal(uint32_t seed, const Eigen::Vector2d& uv, double coarse) {
  return 0.5f * ValueNoise(seed, uv, coarse) + 0.3f * ValueNoise(seed + 1, uv, coarse / 4.0) +
         0.2f * ValueNoise(seed + 2, uv, coarse / 12.0);
}

Eigen::Vector3f Shade(const Eigen::Vector3f& colour, float factor) {
  return (colour * factor).cwiseMax(0.0f).cwiseMin(255.0f);
}

}  // namespace

uint32_t Hash3(uint32_t seed, int32_t x, int32_t y) {
  uint32_t h = seed * 0x27d4eb2du ^ static_cast<uint32_t>(x) * 0x85ebca6bu ^
               static_cast<uint32_t>(y) * 0xc2b2ae35u;
  h ^= h >> 15;
  h *= 0x2c1b3c6du;
  h ^= h >> 12;
  h *= 0x297a2d39u;
  h ^= h >> 15;
  return h;
}

float ValueNoise(uint32_t seed, const Eigen::Vector2d& uv, double scale_m) {
  const double gx = uv.x() / scale_m, gy = uv.y() / scale_m;
  const double fx0 = std::floor(gx), fy0 = std::floor(gy);
  const int32_t ix = static_cast<int32_t>(fx0), iy = static_cast<int32_t>(fy0);
  const float tx = Smooth(static_cast<float>(gx - fx0)), ty = Smooth(static_cast<float>(gy - fy0));
  const float v00 = HashToUnit(Hash3(seed, ix, iy)), v10 = HashToUnit(Hash3(seed, ix + 1, iy));
  const float v01 = HashToUnit(Hash3(seed, ix, iy + 1));
  const float v11 = HashToUnit(Hash3(seed, ix + 1, iy + 1));
  return (v00 * (1 - tx) + v10 * tx) * (1 - ty) + (v01 * (1 - tx) + v11 * tx) * ty;
}

Eigen::Vector3f HashColour(uint32_t h) {
  return Eigen::Vector3f(30.f + 195.f * HashToUnit(h), 30.f + 195.f * HashToUnit(h * 2654435761u),
                         30.f + 195.f * HashToUnit(h * 2246822519u));
}

Eigen::Vector3f TextureColour(const Material& material, int face, const Eigen::Vector2d& uv) {
  if (material.style == TextureStyle::kRoom) {
    static const TextureStyle kFaceStyle[6] = {TextureStyle::kPatches,  TextureStyle::kStripes,
                                               TextureStyle::kStripes,  TextureStyle::kPatches,
                                               TextureStyle::kCheckers, TextureStyle::kNoise};
    Material face_material = material;
    face_material.style = kFaceStyle[face];
    face_material.base_bgr = HashColour(Hash3(material.seed, face, 5));
    return TextureColour(face_material, face, uv);
  }
  const uint32_t seed = material.seed * 0x9e3779b1u + static_cast<uint32_t>(face) * 0x632be5abu;
  const float params = HashToUnit(Hash3(seed, 7, 11));
  Eigen::Vector3f patch;
  switch (material.style) {
    case TextureStyle::kPatches: {
      if (Patch(seed, uv, 0.12 + 0.15 * params, 0.7f, &patch)) {
        return Shade(patch, 0.8f + 0.4f * ValueNoise(seed + 5, uv, 0.05));
      }
      return Shade(material.base_bgr, 0.5f + 0.9f * Fractal(seed, uv, 0.6));
    }
    case TextureStyle::kCheckers: {
      if (Patch(seed, uv, 0.35, 0.3f, &patch)) return patch;
      const double cell = 0.06 + 0.12 * params;
      const int parity =
          static_cast<int>(std::floor(uv.x() / cell) + std::floor(uv.y() / cell)) & 1;
      const float noise = Fractal(seed, uv, 0.5);
      return Shade(material.base_bgr, parity ? 0.45f + 0.4f * noise : 1.1f + 0.4f * noise);
    }
    case TextureStyle::kStripes: {
      if (Patch(seed, uv, 0.25, 0.45f, &patch)) return patch;
      const double width = 0.04 + 0.08 * params;
      const double coord = (params > 0.5f) ? uv.x() : uv.x() + uv.y();
      const int parity = static_cast<int>(std::floor(coord / width)) & 1;
      return Shade(parity ? material.base_bgr : HashColour(seed),
                   0.6f + 0.7f * Fractal(seed, uv, 0.4));
    }
    case TextureStyle::kNoise: {
      if (Patch(seed, uv, 0.2, 0.35f, &patch)) return patch;
      const float n = Fractal(seed, uv, 0.25);
      return Shade(material.base_bgr, 0.2f + 1.6f * n);
    }
    case TextureStyle::kCloth: {
      if (Patch(seed, uv, 0.09, 0.35f, &patch)) return Shade(patch, 0.9f);
      const double cell = 0.03 + 0.03 * params;
      const int parity =
          static_cast<int>(std::floor(uv.x() / cell) + std::floor(uv.y() / cell)) & 1;
      return Shade(material.base_bgr,
                   (parity ? 0.7f : 1.15f) * (0.7f + 0.6f * Fractal(seed, uv, 0.2)));
    }
    case TextureStyle::kRoom:
      break;
    case TextureStyle::kSkin: {
      if (Patch(seed, uv, 0.05, 0.25f, &patch)) return Shade(material.base_bgr, 0.45f);
      return Shade(material.base_bgr, 0.75f + 0.5f * Fractal(seed, uv, 0.1));
    }
  }
  return material.base_bgr;
}

}  // namespace synth
}  // namespace dslam
