// PointGrid::any_near against a brute-force search: every point within the radius is visited
// (radii under, at and over a cell; points far from the origin, where p -/+ radius rounds), and
// the visit stops at the first true; any_in_box visits cells in x, y, z order and a cell's ids in
// insertion order (the thin-wall search's ties depend on that order), and skips the cells asked
// by the index insert() gave them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <set>
#include <tuple>
#include <vector>

#include "core/sampling/point_grid.h"

namespace cadmedial {
namespace {

// n random points in coord's cube, inserted into grid with their index as id.
std::vector<Point3> insert_random_points(PointGrid& grid, std::mt19937& rng,
                                         std::uniform_real_distribution<double>& coord, int n) {
  std::vector<Point3> points;
  for (int i = 0; i < n; ++i) {
    points.push_back({coord(rng), coord(rng), coord(rng)});
    grid.insert(points.back(), i);
  }
  return points;
}

TEST(PointGrid, AnyNearVisitsEveryPointWithinTheRadius) {
  std::mt19937 rng(7);
  for (const double origin : {0.0, 1.0e6}) {
    std::uniform_real_distribution<double> coord(origin - 10.0, origin + 10.0);
    const double cell = 1.0;
    PointGrid grid(cell);
    std::vector<Point3> points = insert_random_points(grid, rng, coord, 20000);
    // Points on cell walls too.
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

TEST(PointGrid, AnyNearVisitsPointsAtExactlyTheRadius) {
  // p -/+ radius along each axis (as the doubles round it, and one step inward), with p and the
  // radius such that those points fall on or next to cell walls, near the origin and far off.
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (const double origin : {0.0, 3.0e5, -7.0e6}) {
    for (int q = 0; q < 400; ++q) {
      const double cell = 0.5 + unit(rng);
      const double radius = q % 2 ? cell * (0.25 + 0.75 * unit(rng)) : cell * std::round(4 * unit(rng) + 1) / 4;
      const double wall = cell * std::round(origin / cell + 20 * unit(rng));  // p - radius on a cell wall
      const Point3 p{wall + radius, origin + 10 * unit(rng), origin - 3 * unit(rng)};
      PointGrid grid(cell);
      std::vector<Point3> points;
      for (int a = 0; a < 3; ++a)
        for (const double sign : {-1.0, 1.0}) {
          Point3 x = p;
          x[a] = p[a] + sign * radius;
          points.push_back(x);
          x[a] = std::nextafter(x[a], p[a]);
          points.push_back(x);
        }
      for (std::size_t i = 0; i < points.size(); ++i) grid.insert(points[i], static_cast<int>(i));
      std::set<int> seen;
      grid.any_near(p, radius, [&](int id) {
        seen.insert(id);
        return false;
      });
      for (std::size_t i = 0; i < points.size(); ++i)
        if (distance2(points[i], p) <= radius * radius) ASSERT_TRUE(seen.count(static_cast<int>(i))) << "point " << i;
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

TEST(PointGrid, AnyInBoxVisitsCellsInOrderAndEachCellsIdsAsInserted) {
  // Around the origin (cells of negative coordinates, blocks split by the axes) and far off.
  std::mt19937 rng(5);
  for (const double origin : {0.0, -4.0e5}) {
    std::uniform_real_distribution<double> coord(origin - 9.0, origin + 9.0);
    const double cell = 0.7;
    PointGrid grid(cell);
    const std::vector<Point3> points = insert_random_points(grid, rng, coord, 5000);
    const auto cell_of = [&](double v) { return static_cast<long long>(std::floor(v / cell)); };
    for (int q = 0; q < 50; ++q) {
      Point3 lo{coord(rng), coord(rng), coord(rng)}, hi = lo;
      for (int a = 0; a < 3; ++a) hi[a] += 0.1 + 4.0 * (rng() % 1000) / 1000.0;
      std::vector<int> seen;
      grid.any_in_box(lo, hi, [&](int id) {
        seen.push_back(id);
        return false;
      });
      // Every point in the box's cells, by (cell x, y, z), then by id (the insertion order).
      std::vector<std::tuple<long long, long long, long long, int>> expected;
      for (int id = 0; id < static_cast<int>(points.size()); ++id) {
        const Point3& p = points[id];
        bool in = true;
        for (int a = 0; a < 3; ++a) in = in && cell_of(p[a]) >= cell_of(lo[a]) && cell_of(p[a]) <= cell_of(hi[a]);
        if (in) expected.emplace_back(cell_of(p[0]), cell_of(p[1]), cell_of(p[2]), id);
      }
      std::sort(expected.begin(), expected.end());
      ASSERT_EQ(seen.size(), expected.size());
      for (std::size_t k = 0; k < seen.size(); ++k) ASSERT_EQ(seen[k], std::get<3>(expected[k])) << "visit " << k;
    }
  }
}

TEST(PointGrid, InsertNamesItsCellAndTheBoxQuerySkipsTheCellsAsked) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> coord(-9.0, 9.0);
  const double cell = 0.7;
  PointGrid grid(cell);
  const auto cell_of = [&](double v) { return static_cast<long long>(std::floor(v / cell)); };
  std::vector<Point3> points;
  std::vector<std::size_t> index;  // per point, the cell index insert() returned
  for (int id = 0; id < 5000; ++id) {
    points.push_back({coord(rng), coord(rng), coord(rng)});
    index.push_back(grid.insert(points.back(), id));
  }
  // One index per cell, and the same for every point of it (later points do not move it).
  std::map<std::tuple<long long, long long, long long>, std::size_t> of_cell;
  std::set<std::size_t> used;
  for (std::size_t id = 0; id < points.size(); ++id) {
    ASSERT_LT(index[id], grid.cells());
    const auto key = std::make_tuple(cell_of(points[id][0]), cell_of(points[id][1]), cell_of(points[id][2]));
    const auto [it, fresh] = of_cell.emplace(key, index[id]);
    if (fresh) {
      EXPECT_TRUE(used.insert(index[id]).second) << "two cells share index " << index[id];
    } else {
      EXPECT_EQ(it->second, index[id]) << "point " << id;
    }
  }
  // Skipping a random third of the cells drops exactly their ids, the others in the same order.
  std::set<std::size_t> skipped;
  for (std::size_t c : used)
    if (rng() % 3 == 0) skipped.insert(c);
  for (int q = 0; q < 50; ++q) {
    Point3 lo{coord(rng), coord(rng), coord(rng)}, hi = lo;
    for (int a = 0; a < 3; ++a) hi[a] += 0.1 + 4.0 * (rng() % 1000) / 1000.0;
    std::vector<int> all, kept;
    grid.any_in_box(lo, hi, [&](int id) {
      all.push_back(id);
      return false;
    });
    grid.any_in_box(
        lo, hi,
        [&](int id) {
          kept.push_back(id);
          return false;
        },
        [&](std::size_t c) { return skipped.count(c) > 0; });
    std::vector<int> expected;
    for (int id : all)
      if (!skipped.count(index[static_cast<std::size_t>(id)])) expected.push_back(id);
    EXPECT_EQ(kept, expected) << "query " << q;
  }
}

}  // namespace
}  // namespace cadmedial
