// One face's interior samples as the sampler makes them, before they get their sample ids.
#pragma once

#include <array>
#include <limits>
#include <vector>

#include "../types.h"

namespace cadmedial::sampling_detail {

/// A face's interior samples (positions, outer normals, largest principal curvatures,
/// parameters), and the box of the candidates that asked whether a sample lay near (empty: none
/// asked).
struct FaceInterior {
  std::vector<Point3> point, normal;
  std::vector<float> curvature;
  std::vector<std::array<double, 2>> uv;
  Point3 probed_lo{kInf, kInf, kInf}, probed_hi{-kInf, -kInf, -kInf};
  static constexpr double kInf = std::numeric_limits<double>::infinity();
};

}  // namespace cadmedial::sampling_detail
