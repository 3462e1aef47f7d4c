// The ray classifier that decides most of the exact inside tests: against the solids' analytic
// insides, on curved faces, seams, apexes and many faces; points on the boundary count as inside.
#include <cmath>
#include <functional>
#include <vector>

#include <BRepClass3d_SolidClassifier.hxx>
#include <gp_Pnt.hxx>
#include <gtest/gtest.h>

#include "core/pipeline/ray_classifier.h"
#include "core/types.h"
#include "support/hard_solids.h"
#include "support/random.h"
#include "support/solids.h"

namespace cadmedial::internal {
namespace {

using cadmedial::Point3;
using test::Random;
using Answer = RayClassifier::Answer;

struct Case {
  const char* name;
  TopoDS_Solid solid;
  Point3 lo, hi;                               ///< a box around the solid
  std::function<double(const Point3&)> depth;  ///< > 0 inside, < 0 outside: distance-like
};

std::vector<Case> cases() {
  std::vector<Case> out;
  // A block [0,10] x [0,8] x [0,4] with a hole of radius 2 about x = 5, y = 4.
  out.push_back(
      {"block with a hole", test::make_block_with_hole(10, 8, 4, 2), {-1, -1, -1}, {11, 9, 5}, [](const Point3& p) {
         const double box = std::min({p[0], 10 - p[0], p[1], 8 - p[1], p[2], 4 - p[2]});
         return std::min(box, std::hypot(p[0] - 5, p[1] - 4) - 2);
       }});
  out.push_back({"torus", test::make_torus(5, 1.5), {-7, -7, -2}, {7, 7, 2}, [](const Point3& p) {
                   return 1.5 - std::hypot(std::hypot(p[0], p[1]) - 5, p[2]);
                 }});
  // A sphere: a seam and two degenerate edges at the poles.
  out.push_back({"sphere", test::make_sphere(3), {-4, -4, -4}, {4, 4, 4}, [](const Point3& p) {
                   return 3 - std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
                 }});
  // A cone of radius 3 and height 6 on z = 0, apex up (a degenerate edge at the apex).
  out.push_back({"cone", test::make_cone(3, 6), {-4, -4, -1}, {4, 4, 7}, [](const Point3& p) {
                   const double side = (3 * (6 - p[2]) / 6 - std::hypot(p[0], p[1])) * 6 / std::hypot(3.0, 6.0);
                   return std::min({side, p[2], 6 - p[2]});
                 }});
  // A plate 20 x 20 x 2 with 4 x 4 round holes of radius 2 at pitch 5.
  out.push_back({"plate with holes",
                 test::make_plate_with_holes(20, 20, 2, 4, 4, 2, false),
                 {-1, -1, -1},
                 {21, 21, 3},
                 [](const Point3& p) {
                   double d = std::min({p[0], 20 - p[0], p[1], 20 - p[1], p[2], 2 - p[2]});
                   for (int i = 0; i < 4; ++i)
                     for (int j = 0; j < 4; ++j)
                       d = std::min(d, std::hypot(p[0] - (2.5 + 5 * i), p[1] - (2.5 + 5 * j)) - 2);
                   return d;
                 }});
  return out;
}

TEST(RayClassifier, AgreesWithTheAnalyticInsideAndDecidesAlmostEveryPoint) {
  for (const Case& c : cases()) {
    RayClassifier rays(c.solid, 1e-7);
    Random rng(11);
    int points = 0, unknown = 0;
    while (points < 2000) {
      Point3 p;
      for (int k = 0; k < 3; ++k) p[k] = rng.uniform(c.lo[k], c.hi[k]);
      const double d = c.depth(p);
      // Half of them within 1e-2 of the boundary, where the pipeline asks.
      if (std::abs(d) < 1e-4 || (points % 2 == 1 && std::abs(d) > 1e-2)) continue;
      ++points;
      const Answer a = rays.classify(p);
      if (a == Answer::Unknown) {
        ++unknown;
        continue;
      }
      EXPECT_EQ(a == Answer::Inside, d > 0) << c.name << " at " << p[0] << " " << p[1] << " " << p[2];
    }
    EXPECT_LE(unknown, points / 50) << c.name;
  }
}

// A B-spline face (crossed through the intersector's polyhedron, not in closed form): the same
// answers as OpenCASCADE's classifier.
TEST(RayClassifier, AgreesWithOpenCascadeOnABSplineFace) {
  const TopoDS_Solid solid = test::make_box_with_bspline_top(10, 8, 3, 1.5);
  RayClassifier rays(solid, 1e-7);
  BRepClass3d_SolidClassifier occt(solid);
  Random rng(3);
  int decided = 0;
  for (int k = 0; k < 1000; ++k) {
    const Point3 p{rng.uniform(-1, 11), rng.uniform(-1, 9), rng.uniform(2, 5)};
    occt.Perform(gp_Pnt(p[0], p[1], p[2]), 1e-7);
    if (occt.State() == TopAbs_ON) continue;
    const Answer a = rays.classify(p);
    if (a == Answer::Unknown) continue;
    ++decided;
    EXPECT_EQ(a == Answer::Inside, occt.State() == TopAbs_IN) << p[0] << " " << p[1] << " " << p[2];
  }
  EXPECT_GE(decided, 980);
}

TEST(RayClassifier, PointsOnTheBoundaryAreInside) {
  // On the faces, the edges and the corners of a block, and on its hole's wall.
  const TopoDS_Solid solid = test::make_block_with_hole(10, 8, 4, 2);
  RayClassifier rays(solid, 1e-7);
  Random rng(5);
  std::vector<Point3> on;
  for (int k = 0; k < 50; ++k) {
    const double x = rng.uniform(0, 10), y = rng.uniform(0, 8), z = rng.uniform(0, 4), t = rng.uniform(0, 6.28);
    on.push_back({x, 0, z});
    on.push_back({10, y, z});
    on.push_back({x, 8, 4});
    on.push_back({0, 0, z});
    on.push_back({5 + 2 * std::cos(t), 4 + 2 * std::sin(t), z});
  }
  for (const Point3& c : std::vector<Point3>{{0, 0, 0}, {10, 8, 4}, {10, 0, 4}}) on.push_back(c);
  for (const Point3& p : on) EXPECT_EQ(rays.classify(p), Answer::Inside) << p[0] << " " << p[1] << " " << p[2];
}

}  // namespace
}  // namespace cadmedial::internal
