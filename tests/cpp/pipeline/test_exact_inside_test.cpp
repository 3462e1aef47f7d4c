// The exact inside test that settles the Voronoi vertices the samples leave in doubt, against the
// solids' analytic insides: prepared on another thread ahead of time (as the pipeline does while
// CGAL triangulates) or not.
#include <cmath>
#include <functional>
#include <future>
#include <vector>

#include <gtest/gtest.h>

#include "core/pipeline/exact_inside_test.h"
#include "support/random.h"
#include "support/solids.h"

namespace cadmedial {
namespace {

using test::Random;

struct Case {
  TopoDS_Solid solid;
  Point3 lo, hi;                                    ///< a box around the solid
  std::function<double(const Point3&)> depth;  ///< > 0 inside, < 0 outside: distance-like
};

// Points of the box at least `margin` off the boundary, and the analytic answers.
void random_points(const Case& c, double margin, std::vector<Point3>& pts, std::vector<std::uint8_t>& expected) {
  Random rng(7);
  while (pts.size() < 400) {
    Point3 p;
    for (int k = 0; k < 3; ++k) p[k] = rng.uniform(c.lo[k], c.hi[k]);
    const double d = c.depth(p);
    if (std::abs(d) < margin) continue;
    pts.push_back(p);
    expected.push_back(d > 0 ? 1 : 0);
  }
}

std::vector<Case> cases() {
  std::vector<Case> out;
  // A block [0,10] x [0,8] x [0,4] with a hole of radius 2 about x = 5, y = 4.
  out.push_back({test::make_block_with_hole(10, 8, 4, 2), {-1, -1, -1}, {11, 9, 5}, [](const Point3& p) {
                   const double box = std::min({p[0], 10 - p[0], p[1], 8 - p[1], p[2], 4 - p[2]});
                   const double hole = std::hypot(p[0] - 5, p[1] - 4) - 2;
                   return std::min(box, hole);
                 }});
  // A torus R = 5, r = 1.5 about the z axis.
  out.push_back({test::make_torus(5, 1.5), {-7, -7, -2}, {7, 7, 2}, [](const Point3& p) {
                   return 1.5 - std::hypot(std::hypot(p[0], p[1]) - 5, p[2]);
                 }});
  return out;
}

TEST(ExactInsideTest, AgreesWithTheAnalyticInsidePreparedOrNot) {
  for (const Case& c : cases()) {
    std::vector<Point3> pts;
    std::vector<std::uint8_t> expected;
    random_points(c, 1e-3, pts, expected);
    EXPECT_EQ(exact_inside_test(c.solid, 1e-7)(pts), expected);
    std::function<void()> prepare;
    const InsideTest prepared = exact_inside_test(c.solid, 1e-7, prepare);
    std::async(std::launch::async, prepare).get();
    EXPECT_EQ(prepared(pts), expected);
    // A few at a time too (fewer than 8 run on one classifier).
    for (std::size_t k = 0; k < 20; ++k)
      EXPECT_EQ(prepared({pts[k]})[0], expected[k]) << k;
  }
}

}  // namespace
}  // namespace cadmedial
