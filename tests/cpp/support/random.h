// A deterministic random source for the tests: std::mt19937 is specified bit for bit by the
// standard, the std distributions are not, so the conversions to doubles are done here.
#pragma once

#include <cmath>
#include <cstdint>
#include <random>

#include "support/vec3.h"

namespace cadmedial::test {

class Random {
 public:
  explicit Random(std::uint32_t seed) : engine_(seed) {}
  /// Uniform in [0, 1).
  double uniform() { return static_cast<double>(engine_() >> 5) * (1.0 / 134217728.0); }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  /// Uniform on the unit sphere (Archimedes: z uniform, angle uniform).
  Vec3 unit_vector() {
    const double z = uniform(-1.0, 1.0), phi = uniform(0.0, 2.0 * M_PI), s = std::sqrt(1.0 - z * z);
    return {s * std::cos(phi), s * std::sin(phi), z};
  }

 private:
  std::mt19937 engine_;
};

}  // namespace cadmedial::test
