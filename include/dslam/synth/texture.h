#pragma once
// Procedural textures of the synthetic renderer: a colour as a function of a material and a point
// on its surface. Textures are functions of surface coordinates only, so they move rigidly with
// their object and keep their brightness from frame to frame. Every family layers irregular cells
// of random colour and brightness, multi-octave value noise and random shapes at two scales
// (pattern.h), so that ORB finds distinctive corners everywhere at 0.5-5 m viewing distance
// (1 px ~ 1-10 mm at f = 525 px) and no patch looks like another.

#include <cstdint>

#include <Eigen/Core>

#include "dslam/synth/geometry.h"

namespace dslam {
namespace synth {

/// Deterministic 32-bit hash of a seed and two lattice coordinates.
uint32_t Hash3(uint32_t seed, int32_t x, int32_t y);

/// Uniform value in [0, 1) from a hash.
inline float HashToUnit(uint32_t h) { return static_cast<float>(h >> 8) * (1.0f / 16777216.0f); }

/// Smooth value noise in [0, 1] at spatial period `scale_m` [m] of the point `uv` [m].
float ValueNoise(uint32_t seed, const Eigen::Vector2d& uv, double scale_m);

/// Colour [0, 255] BGR (before lighting) of `material` at surface coordinates `uv` [m] on
/// surface `face` (box face 0..5; triangles use 0).
Eigen::Vector3f TextureColour(const Material& material, int face, const Eigen::Vector2d& uv);

/// A random saturated-ish colour [30, 225]^3 BGR from a hash.
Eigen::Vector3f HashColour(uint32_t h);

}  // namespace synth
}  // namespace dslam
