// Exact inner medial axes of the solids of revolution about the z axis that the tests build:
// cylinder and disc (BRepPrimAPI_MakeCylinder(R, H): rho <= R, 0 <= z <= H), sphere (centre at the
// origin) and torus (major R, minor r, centre at the origin, axis z).
//
// Each axis is a surface of revolution of a polyline in the half plane (rho >= 0, z). The distance
// from x = (rho, phi, z) to a point (rho', phi', z') is sqrt(rho^2 + rho'^2 - 2 rho rho' cos(phi -
// phi') + (z - z')^2), smallest at phi' = phi, so the distance to a set of revolution is the 2D
// distance from (rho, z) to its profile.
//
// Cylinder, D(x) = min(R - rho, z, H - z): the axis is where two of the three tie.
//   H >= 2R: R - rho = z      -> segment (R, 0) - (0, R)      (cone to the bottom rim)
//            R - rho = H - z  -> segment (R, H) - (0, H - R)  (cone to the top rim)
//            rho = 0, R <= z <= H - R: the axis segment (the wall's nearest points form a circle)
//            z = H - z would need rho <= R - H/2 <= 0: nothing else.
//   H <  2R (disc): z = H/2 with rho <= R - H/2 (the mid plane disc), and the two cones
//            (R, 0) - (R - H/2, H/2), (R, H) - (R - H/2, H/2).
// Sphere, D = R - |x|: the centre only. Torus, D = r - |(rho - R, z)|: the circle rho = R, z = 0.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "support/vec3.h"

namespace cadmedial::test {

using Vec2 = std::array<double, 2>;  // (rho, z)

class RevolvedMedialAxis {
 public:
  static RevolvedMedialAxis cylinder(double R, double H);
  static RevolvedMedialAxis sphere(double R);
  static RevolvedMedialAxis torus(double R, double r);

  /// Segments of the profile in the (rho, z) half plane; a segment may be a point.
  const std::vector<std::array<Vec2, 2>>& profile() const { return segments_; }
  /// Exact distance from x to the axis (the 2D distance of (rho, z) to the profile).
  double distance(const Vec3& x) const;
  /// Exact distance from x to the solid's boundary when x is inside (positive), negative outside.
  double boundary_distance(const Vec3& x) const;
  /// `count` points on the axis: a segment chosen with probability proportional to the area of the
  /// surface it sweeps (or uniformly among point profiles), then a uniform parameter and angle.
  std::vector<Vec3> sample(int count, std::uint32_t seed) const;

 private:
  enum class Kind { Cylinder, Sphere, Torus };
  Kind kind_;
  double R_ = 0, H_ = 0, r_ = 0;
  std::vector<std::array<Vec2, 2>> segments_;
};

}  // namespace cadmedial::test
