#pragma once
// Counter-based noise of the synthetic sensor (sensor.cpp, structured_light.cpp): every value is a
// function of a 64-bit key, so a pixel's noise does not depend on the order (or the thread) in
// which pixels are processed.

#include <cmath>
#include <cstdint>

namespace dslam {
namespace synth {

/// splitmix64's finaliser: a well-mixed 64-bit value of `x`.
inline uint64_t Mix64(uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

/// A uniform value in (0, 1) from the top 53 bits.
inline double Unit(uint64_t bits) {
  return (static_cast<double>(bits >> 11) + 0.5) * (1.0 / 9007199254740992.0);
}

/// Standard normal sample (Box-Muller) for `key`.
inline double Gaussian(uint64_t key) {
  const uint64_t a = Mix64(key), b = Mix64(a);
  return std::sqrt(-2.0 * std::log(Unit(a))) * std::cos(2.0 * M_PI * Unit(b));
}

}  // namespace synth
}  // namespace dslam
