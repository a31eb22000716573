#include "dslam/synth/pattern.h"

#include <algorithm>
#include <cmath>

#include "dslam/synth/texture.h"

namespace dslam {
namespace synth {
namespace {

constexpr double kTwoPi = 6.283185307179586;

/// Independent uniform draw number `k` in [0, 1) from hash `h`.
float Draw(uint32_t h, int32_t k) { return HashToUnit(Hash3(h, k, 0x5bd1e995)); }

/// Boundary `k` [m] of a 1-D partition of period `cell_m` jittered by +-0.2 cell_m per boundary.
double Boundary(uint32_t seed, int32_t k, int32_t line, double cell_m) {
  return (k + 0.4 * (HashToUnit(Hash3(seed, k, line)) - 0.5)) * cell_m;
}

/// Index of the interval of the jittered partition of line `line` that contains `x` [m].
int32_t Interval(uint32_t seed, double x, double cell_m, int32_t line) {
  const int32_t k = static_cast<int32_t>(std::floor(x / cell_m));
  if (x < Boundary(seed, k, line, cell_m)) return k - 1;
  if (x >= Boundary(seed, k + 1, line, cell_m)) return k + 1;
  return k;
}

/// Eight bits of `h` starting at bit `shift`, scaled to [0, 1).
double Bits(uint32_t h, int shift) { return static_cast<double>((h >> shift) & 0xffu) / 256.0; }

/// cos and sin of 256 angles evenly spread over the full turn (shape orientations).
struct DirectionTable {
  double cos[256];
  double sin[256];
};

const DirectionTable& Directions() {
  static const DirectionTable kTable = [] {
    DirectionTable table;
    for (int i = 0; i < 256; ++i) {
      table.cos[i] = std::cos(kTwoPi * i / 256.0);
      table.sin[i] = std::sin(kTwoPi * i / 256.0);
    }
    return table;
  }();
  return kTable;
}

/// Whether the point (x, y), in cell units relative to the shape centre, lies in shape `h`
/// (type: bits 0-1, orientation: bits 2-9, sizes: bits 10-17 and 18-25, apex: bits 24-31).
/// Every shape fits in a disc of radius 0.7 cells.
bool InShape(uint32_t h, double x_cell, double y_cell) {
  const DirectionTable& table = Directions();
  const double c = table.cos[(h >> 2) & 0xffu], s = table.sin[(h >> 2) & 0xffu];
  const double x = c * x_cell + s * y_cell, y = -s * x_cell + c * y_cell;
  const double a = 0.15 + 0.35 * Bits(h, 10), b = 0.06 + 0.39 * Bits(h, 18);
  switch (h & 3u) {
    case 0:  // rotated rectangle
      return std::abs(x) <= a && std::abs(y) <= b;
    case 1:  // ellipse
      return (x * x) / (a * a) + (y * y) / (b * b) <= 1.0;
    case 2: {  // triangle (-a, -b), (a, -b), (t, b)
      const double t = a * (2.0 * Bits(h, 24) - 1.0);
      if (y < -b) return false;
      const double left = (t + a) * (y + b) - 2.0 * b * (x + a);   // edge (-a,-b) -> (t,b)
      const double right = (t - a) * (y + b) - 2.0 * b * (x - a);  // edge (a,-b) -> (t,b)
      return left <= 0.0 && right >= 0.0;
    }
    default: {  // stroke: long thin bar
      const double half_length = 0.55 + 0.1 * Bits(h, 10), half_width = 0.04 + 0.05 * Bits(h, 18);
      return std::abs(x) <= half_length && std::abs(y) <= half_width;
    }
  }
}

}  // namespace

CellId JitteredCell(uint32_t seed, const Eigen::Vector2d& uv, double cell_m) {
  CellId id;
  id.row = Interval(seed ^ 0x68e31da4u, uv.y(), cell_m, 0x7fffffff);
  const uint32_t row_hash = Hash3(seed, id.row, 0x3c6ef372);
  const double width = cell_m * (0.6 + 0.8 * Draw(row_hash, 1));
  const double offset = width * Draw(row_hash, 2);  // bricks: rows do not share boundaries
  id.column = Interval(seed ^ 0xb5297a4du, uv.x() + offset, width, id.row);
  id.hash = Hash3(seed ^ 0x1b56c4e9u, id.row, id.column);
  return id;
}

bool RandomShape(uint32_t seed, const Eigen::Vector2d& uv, double cell_m, float density,
                 uint32_t* shape_hash) {
  const double gx = uv.x() / cell_m, gy = uv.y() / cell_m;
  // Shape centres lie in [0.2, 0.8] of their cell and shapes reach 0.7 cells from it, so only
  // the 2 x 2 cells nearest to the point can cover it.
  const int32_t x0 = static_cast<int32_t>(std::floor(gx - 0.5)),
                y0 = static_cast<int32_t>(std::floor(gy - 0.5));
  bool found = false;
  uint32_t best = 0;
  for (int32_t iy = y0; iy <= y0 + 1; ++iy) {
    for (int32_t ix = x0; ix <= x0 + 1; ++ix) {
      const uint32_t h = Hash3(seed, ix, iy);
      if (HashToUnit(h) >= density) continue;
      // The cell hash's low bits place the centre (its top bits decided the density test).
      const double dx = gx - (ix + 0.2 + 0.6 * Bits(h, 0)), dy = gy - (iy + 0.2 + 0.6 * Bits(h, 8));
      if (dx * dx + dy * dy > 0.49) continue;
      const uint32_t shape = Hash3(h, ix, 0x2545f491);
      if (!InShape(shape, dx, dy)) continue;
      if (!found || shape > best) best = shape;  // hashed priority decides overlaps
      found = true;
    }
  }
  if (found) *shape_hash = best;
  return found;
}

float FractalNoise(uint32_t seed, const Eigen::Vector2d& uv, double coarse_m, int octaves) {
  float sum = 0.0f, weight_sum = 0.0f, weight = 1.0f;
  double scale = coarse_m;
  for (int k = 0; k < octaves; ++k) {
    sum += weight * ValueNoise(seed + static_cast<uint32_t>(k) * 0x9e3779b9u, uv, scale);
    weight_sum += weight;
    weight *= 0.55f;
    scale /= 2.3;
  }
  return sum / weight_sum;
}

Eigen::Vector3f WithLuminance(const Eigen::Vector3f& hue, float luminance) {
  const float current = 0.114f * hue[0] + 0.587f * hue[1] + 0.299f * hue[2];
  return (hue * (luminance / std::max(current, 1.0f))).cwiseMin(255.0f);
}

Eigen::Vector3f ContrastColour(uint32_t h) {
  const float target =
      Draw(h, 9) < 0.5f ? 25.0f + 55.0f * Draw(h, 10) : 165.0f + 70.0f * Draw(h, 10);
  return WithLuminance(HashColour(h), target);
}

}  // namespace synth
}  // namespace dslam
