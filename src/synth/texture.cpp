#include "dslam/synth/texture.h"

#include <algorithm>
#include <cmath>

#include "dslam/synth/pattern.h"

namespace dslam {
namespace synth {
namespace {

float Smooth(float x) { return x * x * (3.0f - 2.0f * x); }

/// Parameters of the layered texture of one family (sizes [m]).
struct Layers {
  double region_m;       ///< irregular cells with their own colour and brightness
  float region_hue;      ///< how far a cell's colour departs from the base colour, [0, 1]
  double noise_m;        ///< coarsest noise period
  float noise_contrast;  ///< brightness range of the noise, factor 1 -+ contrast / 2
  double big_shape_m;    ///< cell size of the large shapes
  float big_density;     ///< probability of a large shape per cell
  double small_shape_m;  ///< cell size of the small shapes (drawn on top)
  float small_density;
};

/// Layer parameters per family; `params` in [0, 1) varies them per material.
Layers LayersOf(TextureStyle style, float params) {
  const double k = 0.8 + 0.4 * params;
  switch (style) {
    case TextureStyle::kCheckers:  // tiles of random size and shade
      return {0.2 * k, 0.3f, 0.4, 0.5f, 0.3 * k, 0.3f, 0.1 * k, 0.25f};
    case TextureStyle::kStripes:  // stripes of random width and colour
      return {0.1 * k, 0.6f, 0.5, 0.5f, 0.28 * k, 0.45f, 0.09 * k, 0.3f};
    case TextureStyle::kNoise:
      return {0.6 * k, 0.4f, 0.3, 1.1f, 0.3 * k, 0.4f, 0.1 * k, 0.3f};
    case TextureStyle::kCloth:
      return {0.06 * k, 0.25f, 0.2, 0.5f, 0.12 * k, 0.45f, 0.04 * k, 0.35f};
    case TextureStyle::kSkin:
      return {0.08 * k, 0.05f, 0.1, 0.5f, 0.1 * k, 0.2f, 0.035 * k, 0.35f};
    default:  // kPatches
      return {0.45 * k, 0.35f, 0.5, 0.6f, 0.25 * k, 0.4f, 0.08 * k, 0.25f};
  }
}

/// Colour of the shapes layers at `uv`, if a shape covers it (small shapes over large ones).
bool ShapeColour(TextureStyle style, uint32_t seed, const Layers& l, const Eigen::Vector2d& uv,
                 const Eigen::Vector3f& base, Eigen::Vector3f* colour) {
  uint32_t h = 0;
  if (!RandomShape(seed + 11u, uv, l.small_shape_m, l.small_density, &h) &&
      !RandomShape(seed + 13u, uv, l.big_shape_m, l.big_density, &h)) {
    return false;
  }
  const float pick = HashToUnit(Hash3(h, 3, 5));
  if (style == TextureStyle::kSkin || (style == TextureStyle::kCloth && pick < 0.5f)) {
    // prints in the material's own hue, far from its grey level: people stay recognisable
    const float grey = 0.114f * base[0] + 0.587f * base[1] + 0.299f * base[2];
    *colour = WithLuminance(base, grey < 110.0f ? 170.0f + 60.0f * pick : 20.0f + 50.0f * pick);
  } else {
    *colour = ContrastColour(h);
  }
  return true;
}

/// The layered texture: irregular cells (stripes for kStripes) of random colour and brightness,
/// modulated by multi-octave noise, under random shapes at two scales.
Eigen::Vector3f Layered(TextureStyle style, uint32_t seed, const Eigen::Vector3f& base,
                        const Eigen::Vector2d& uv) {
  const float params = HashToUnit(Hash3(seed, 7, 11));
  const Layers l = LayersOf(style, params);
  Eigen::Vector3f colour;
  if (ShapeColour(style, seed, l, uv, base, &colour)) {
    const float detail = ValueNoise(seed + 3u, uv, l.noise_m / 4.0);
    return (colour * (0.85f + 0.3f * detail)).cwiseMax(0.0f).cwiseMin(255.0f);
  }
  const Eigen::Vector2d stripe_uv(params > 0.5f ? uv.x() : uv.x() + uv.y(), 0.0);
  const CellId cell =
      JitteredCell(seed, style == TextureStyle::kStripes ? stripe_uv : uv, l.region_m);
  const float brightness = 0.45f + 0.9f * HashToUnit(Hash3(cell.hash, 1, 2));
  colour = ((1.0f - l.region_hue) * base + l.region_hue * HashColour(cell.hash)) * brightness;
  const float noise = FractalNoise(seed, uv, l.noise_m, 3);
  colour *= 1.0f - 0.5f * l.noise_contrast + l.noise_contrast * noise;
  return colour.cwiseMax(0.0f).cwiseMin(255.0f);
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
  return Layered(material.style, seed, material.base_bgr, uv);
}

}  // namespace synth
}  // namespace dslam
