// A pseudorandom stream that is the same on every platform and compiler (unlike the standard library's
// distributions): splitmix64 (Steele, Lea & Flood, "Fast splittable pseudorandom number generators", 2014).
#pragma once

#include <cmath>
#include <cstdint>

namespace skinfem {

struct SplitMix64 {
  std::uint64_t state;
  std::uint64_t next() {
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  // Uniform in [lo, hi), 53 bits.
  double uniform(double lo, double hi) { return lo + (hi - lo) * double(next() >> 11) * 0x1.0p-53; }
  // Standard normal (Box–Muller on (0, 1]).
  double normal() {
    const double u = 1.0 - uniform(0, 1), v = uniform(0, 1);
    return std::sqrt(-2 * std::log(u)) * std::cos(2 * M_PI * v);
  }
};

}  // namespace skinfem
