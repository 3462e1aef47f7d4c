// PointGrid::any_near against a brute-force search: every point within the radius is visited
// (radii under, at and over a cell; points far from the origin, where p -/+ radius rounds), and
// the visit stops at the first true.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>
#include <vector>

#include "core/sampling/point_grid.h"

namespace cadmedial {
namespace {

TEST(PointGrid, AnyNearVisitsEveryPointWithinTheRadius) {
  std::mt19937 rng(7);
  for (const double origin : {0.0, 1.0e6}) {
    std::uniform_real_distribution<double> coord(origin - 10.0, origin + 10.0);
    const double cell = 1.0;
    PointGrid grid(cell);
    std::vector<Point3> points;
    for (int i = 0; i < 20000; ++i) {
      points.push_back({coord(rng), coord(rng), coord(rng)});
      grid.insert(points.back(), i);
    }
    // Points on cell walls and at exactly the radius from a query too.
    for (int i = 0; i < 200; ++i) {
      const Point3 p{std::round(coord(rng)), std::round(coord(rng)), coord(rng)};
      points.push_back(p);
      grid.insert(p, static_cast<int>(points.size()) - 1);
    }
    for (const double radius : {0.3, 0.999, 1.0, 1.7, 2.5}) {
      for (int q = 0; q < 300; ++q) {
        const Point3 p = q % 3 == 0 ? points[rng() % points.size()] : Point3{coord(rng), coord(rng), coord(rng)};
        std::set<int> seen;
        grid.any_near(p, radius, [&](int id) {
          seen.insert(id);
          return false;
        });
        for (int id = 0; id < static_cast<int>(points.size()); ++id)
          if (distance2(points[id], p) <= radius * radius)
            ASSERT_TRUE(seen.count(id)) << "point " << id << " within " << radius << " of a query near " << origin;
      }
    }
  }
}

TEST(PointGrid, AnyNearStopsAtTheFirstTrue) {
  PointGrid grid(1.0);
  for (int i = 0; i < 10; ++i) grid.insert({0.1 * i, 0.0, 0.0}, i);
  int visits = 0;
  EXPECT_TRUE(grid.any_near({0.0, 0.0, 0.0}, 1.0, [&](int id) {
    ++visits;
    return id == 3;
  }));
  EXPECT_EQ(visits, 4);  // ids 0..3, in insertion order, all in the query's own cell
  EXPECT_FALSE(grid.any_near({50.0, 0.0, 0.0}, 1.0, [](int) { return true; }));
}

}  // namespace
}  // namespace cadmedial
