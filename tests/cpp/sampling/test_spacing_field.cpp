// The spacing field of the adaptive sampling: a thin-wall point's spacing holds within one
// (uniform) spacing of it, then grows with the gradation's slope up to the uniform spacing; points
// the others already cover are dropped without changing the field by more than 10 %.
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "core/sampling/spacing_field.h"

namespace cadmedial {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(SpacingField, UniformIsTheSpacingEverywhere) {
  const SpacingField f(2.0);
  EXPECT_TRUE(f.is_uniform());
  EXPECT_EQ(f.at({0, 0, 0}), 2.0);
  EXPECT_EQ(f.at({1e6, -3, 7}), 2.0);
  EXPECT_EQ(f.smallest(), 2.0);
}

TEST(SpacingField, APointsSpacingHoldsWithinASpacingThenGrowsWithTheGradation) {
  const SpacingField f(1.0, {{0, 0, 0}}, {0.25}, 0.5);
  EXPECT_FALSE(f.is_uniform());
  EXPECT_DOUBLE_EQ(f.smallest(), 0.25);
  EXPECT_DOUBLE_EQ(f.at({0, 0, 0}), 0.25);
  EXPECT_DOUBLE_EQ(f.at({0.9, 0, 0}), 0.25);
  EXPECT_DOUBLE_EQ(f.at({0, 1.5, 0}), 0.25 + 0.5 * 0.5);
  EXPECT_DOUBLE_EQ(f.at({0, 0, 2.2}), 0.25 + 0.5 * 1.2);
  EXPECT_DOUBLE_EQ(f.at({0, 0, 2.5}), 1.0);  // back to the uniform spacing
  EXPECT_DOUBLE_EQ(f.at({30, 0, 0}), 1.0);
}

TEST(SpacingField, TheSmallestNearbyValueWinsAndCoveredPointsChangeItByAtMostTenPercent) {
  // The second point is covered by the first (0.25 there, against its 0.26); the third is not.
  const SpacingField f(1.0, {{0, 0, 0}, {0.1, 0, 0}, {4, 0, 0}}, {0.25, 0.26, 0.4}, 0.5);
  EXPECT_DOUBLE_EQ(f.at({0.1, 0, 0}), 0.25);
  EXPECT_DOUBLE_EQ(f.at({4, 0, 0}), 0.4);
  // Between them: whichever is smaller.
  EXPECT_DOUBLE_EQ(f.at({2, 0, 0}), std::min(0.25 + 0.5 * 1.0, 0.4 + 0.5 * 1.0));
  for (double x = -3; x <= 7; x += 0.37) {
    const double exact = std::min({1.0, 0.25 + 0.5 * std::max(0.0, std::abs(x) - 1.0),
                                   0.26 + 0.5 * std::max(0.0, std::abs(x - 0.1) - 1.0),
                                   0.4 + 0.5 * std::max(0.0, std::abs(x - 4) - 1.0)});
    EXPECT_LE(f.at({x, 0, 0}), 1.1 * exact + 1e-12) << x;
    EXPECT_GE(f.at({x, 0, 0}), exact - 1e-12) << x;
  }
}

TEST(SpacingField, DenseCellsGiveTheHashGridsValues) {
  // Thin-wall points over a compact box: at() looks them up in a dense box of cells. One more
  // point far off makes that box too large, and at() asks the hash grid instead; it is beyond
  // every query's reach, so the two fields must agree bit for bit (and be no finer than a brute
  // force over all the points: dropped points can only make it coarser).
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> coord(-6, 6), local(0.25, 0.9);
  std::vector<Point3> points;
  std::vector<double> locals;
  for (int k = 0; k < 4000; ++k) points.push_back({coord(rng), coord(rng), 0.1 * coord(rng)}), locals.push_back(local(rng));
  const SpacingField dense(1.0, points, locals, 0.5);
  points.push_back({1e5, -1e5, 1e5});
  locals.push_back(0.3);
  const SpacingField hashed(1.0, points, locals, 0.5);
  ASSERT_TRUE(dense.dense());
  ASSERT_FALSE(hashed.dense());
  std::uniform_real_distribution<double> query(-9, 9);
  int finer = 0;
  for (int q = 0; q < 20000; ++q) {
    const Point3 x{query(rng), query(rng), 0.3 * query(rng)};
    const double h = dense.at(x);
    ASSERT_EQ(h, hashed.at(x)) << x[0] << " " << x[1] << " " << x[2];
    double exact = 1.0;
    for (size_t k = 0; k + 1 < points.size(); ++k) {
      const double d = std::sqrt((points[k][0] - x[0]) * (points[k][0] - x[0]) + (points[k][1] - x[1]) * (points[k][1] - x[1]) +
                                 (points[k][2] - x[2]) * (points[k][2] - x[2]));
      exact = std::min(exact, locals[k] + 0.5 * std::max(0.0, d - 1.0));
    }
    ASSERT_GE(h, exact - 1e-12);
    finer += h < 1.0;
  }
  EXPECT_GT(finer, 10000);
}

TEST(SpacingField, PointsFarOffOrNotFiniteGetTheUniformSpacing) {
  const SpacingField f(1.0, {{0, 0, 0}, {3, 0, 0}}, {0.25, 0.5}, 0.5);
  ASSERT_TRUE(f.dense());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const Point3& x : std::vector<Point3>{{nan, 0, 0}, {0, kInf, 0}, {0, 0, -kInf}, {1e300, 0, 0}, {-1e300, 1e300, 0},
                                             {0, 0, 1e18}, {40, 0, 0}})
    EXPECT_EQ(f.at(x), 1.0) << x[0] << " " << x[1] << " " << x[2];
  EXPECT_EQ(f.at({0, 0, 0}), 0.25);
}

TEST(SpacingField, AFieldWhosePointsAreAllCoveredIsUniform) {
  // 0.95 is within 10 % of the uniform spacing: the point is dropped, and the field keeps none.
  const SpacingField f(1.0, {{0, 0, 0}}, {0.95}, 0.5);
  EXPECT_TRUE(f.is_uniform());
  EXPECT_EQ(f.at({0, 0, 0}), 1.0);
}

TEST(SpacingField, ThinWallSpacingIsHalfTheRadiusAtLeastTheFloor) {
  Samples s;
  s.points = {{0, 0, 0}, {10, 0, 0}, {20, 0, 0}};
  const std::vector<double> radii{0.8, 0.01, kInf};
  // per radius 0.5, at most 4 times finer than 1: 0.4 at the first, the floor 0.25 at the second.
  const SpacingField f = thin_wall_spacing(s, radii, 1.0, 0.5, 4.0, 0.5);
  EXPECT_DOUBLE_EQ(f.at({0, 0, 0}), 0.4);
  EXPECT_DOUBLE_EQ(f.at({10, 0, 0}), 0.25);
  EXPECT_DOUBLE_EQ(f.at({20, 0, 0}), 1.0);
  EXPECT_TRUE(thin_wall_spacing(s, {kInf, kInf, kInf}, 1.0, 0.5, 4.0, 0.5).is_uniform());
  // A radius of 3 asks for 1.5, coarser than the spacing: nothing to refine.
  EXPECT_TRUE(thin_wall_spacing(s, {3.0, kInf, kInf}, 1.0, 0.5, 4.0, 0.5).is_uniform());
}

TEST(SpacingField, FacesAndEdgesTakeTheSmallestSpacingAtTheirSamples) {
  Samples s;
  s.points = {{0, 0, 0}, {0.5, 0, 0}, {50, 0, 0}};
  s.face = {0, -1, 2};
  s.edge = {-1, 0, -1};
  s.faces.resize(3);
  SpacingField f(1.0, {{0, 0, 0}}, {0.3}, 0.5);
  // Edge 0 joins faces 0 and 1: face 1 has no sample near the thin point, but its edge does.
  f.measure_on(s, {{0, 1}});
  EXPECT_DOUBLE_EQ(f.on_face(0), 0.3);
  EXPECT_DOUBLE_EQ(f.on_face(1), 0.3);
  EXPECT_DOUBLE_EQ(f.on_face(2), 1.0);
  EXPECT_DOUBLE_EQ(f.on_edge(0), 0.3);
  EXPECT_DOUBLE_EQ(f.on_edge(5), 1.0);  // unknown: the uniform spacing
}

}  // namespace
}  // namespace cadmedial
