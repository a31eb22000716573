#pragma once
// Building blocks of the procedural textures (texture.h): irregular cell partitions, random
// shapes and multi-octave noise, all hashed functions of surface coordinates [m], so that every
// patch of a surface looks different from every other (unambiguous ORB descriptors) while staying
// identical from frame to frame.

#include <cstdint>

#include <Eigen/Core>

namespace dslam {
namespace synth {

/// Identifies the cell of an irregular partition that contains a point.
struct CellId {
  int32_t row = 0;
  int32_t column = 0;
  uint32_t hash = 0;  ///< hash of (seed, row, column): drives the cell's colour and brightness
};

/// Irregular "brick" partition of the plane: rows of jittered height (cell_m * [0.8, 1.2] on
/// average), each row split into cells whose width varies per row (cell_m * [0.6, 1.4]) and whose
/// boundaries are jittered per cell, so no two junctions look alike. `cell_m` [m].
CellId JitteredCell(uint32_t seed, const Eigen::Vector2d& uv, double cell_m);

/// Random shapes scattered on a grid of cells of size `cell_m` [m]: each cell holds, with
/// probability `density`, one shape (rotated rectangle, ellipse, triangle or stroke) of random
/// size (up to 1.4 cell_m across), position and orientation. Overlaps are resolved by a hashed
/// priority. Returns true and the shape's hash when `uv` [m] lies inside a shape.
bool RandomShape(uint32_t seed, const Eigen::Vector2d& uv, double cell_m, float density,
                 uint32_t* shape_hash);

/// Sum of `octaves` value-noise octaves in [0, 1], the first with period `coarse_m` [m], each next
/// one 2.3 times finer with 0.55 times the weight.
float FractalNoise(uint32_t seed, const Eigen::Vector2d& uv, double coarse_m, int octaves);

/// `hue` [0, 255] BGR scaled to grey level `luminance` [0, 255] (0.114 B + 0.587 G + 0.299 R),
/// clipped at 255 per channel.
Eigen::Vector3f WithLuminance(const Eigen::Vector3f& hue, float luminance);

/// A colour [0, 255] BGR for a shape or cell with hash `h`: a random hue that is either clearly
/// darker or clearly brighter than mid-grey, so shapes keep FAST-level contrast on any background.
Eigen::Vector3f ContrastColour(uint32_t h);

}  // namespace synth
}  // namespace dslam
