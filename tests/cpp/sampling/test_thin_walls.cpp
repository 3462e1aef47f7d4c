// The thin-wall check: on a plate thinner than two spacings it finds the plate's half thickness
// (the medial radius there) and the pipeline warns; on a block whose walls are far apart, and on
// a wedge whose faces only meet at its convex edge, it finds nothing. Its radii are those of its
// rule over every pair of wall samples (a brute-force search).
#include <cmath>
#include <limits>
#include <set>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "core/features/classify_features.h"
#include "core/pipeline/compute_medial_axis.h"
#include "core/sampling/point_grid.h"
#include "core/sampling/sample_solid.h"
#include "core/sampling/thin_walls.h"
#include "support/hard_solids.h"
#include "support/solids.h"

namespace cadmedial {
namespace {

// One spacing everywhere, and the default (finer at thin walls), both at `spacing`.
std::pair<ComputeParams, ComputeParams> uniform_and_adaptive(double spacing) {
  ComputeParams uniform;
  uniform.sampling.spacing = spacing;
  uniform.sampling.adapt_to_walls = false;
  ComputeParams adaptive = uniform;
  adaptive.sampling.adapt_to_walls = true;
  return {uniform, adaptive};
}

ThinWall thin_wall_of(const TopoDS_Solid& solid, double spacing) {
  const Features f = classify_features(solid);
  return thinnest_wall(sample_solid(solid, f, spacing), spacing, convex_face_pairs(f));
}

TEST(ThinWalls, APlateThinnerThanTwoSpacingsShowsItsHalfThickness) {
  // 1 thick, spacing 1: the medial radius is 0.5; samples of the two faces need not sit exactly
  // opposite, which only makes the estimate larger, and some pairs are nearly opposite.
  const ThinWall w = thin_wall_of(test::make_box(30, 30, 1), 1.0);
  EXPECT_GE(w.radius, 0.5 - 1e-9);
  EXPECT_LE(w.radius, 0.6);
  EXPECT_TRUE(std::abs(w.at[2]) < 1e-9 || std::abs(w.at[2] - 1.0) < 1e-9) << "found off the plate's faces";
  EXPECT_GT(w.samples, 100u);  // the whole plate is thin, not one spot
}

TEST(ThinWalls, WallsFartherApartThanTwoSpacingsAreNotSeen) {
  const ThinWall w = thin_wall_of(test::make_box(20, 20, 20), 1.5);
  EXPECT_TRUE(std::isinf(w.radius)) << w.radius;
  EXPECT_EQ(w.samples, 0u);
}

TEST(ThinWalls, AWedgeIsNotAWallNearItsConvexEdge) {
  // 20 degrees, 40 long, 8 tall (hard_solids): the faces face each other, but within a spacing of
  // the sharp edge the completion carries the axis. Farther in the wedge is thin too: at distance
  // d from the edge its inscribed radius is d tan(10 deg), 0.085 where the check starts (d > 0.48
  // at h = 0.5, edge samples 0.25 apart), against 0.044 at the triplets (d = 0.25).
  const ThinWall w = thin_wall_of(test::make_sharp_wedge(20, 40, 8), 0.5);
  EXPECT_GT(w.radius, 0.08);
  EXPECT_LT(w.radius, 0.5);
}

// The pipeline's search from the uniform pass's thinnest wall finds thinnest_wall's wall whatever
// the guess: too small (it widens), about right, or larger than the spacing. A block with a thin
// rib, an L block with thin arms and a plate with holes, sampled at half the spacing (as a refined
// sampling is finer than the spacing).
TEST(ThinWalls, TheSearchFromAGuessFindsTheSameWall) {
  struct Case {
    TopoDS_Solid solid;
    double spacing;
  };
  const Case cases[] = {{test::make_block_with_rib(20, 16, 4, 0.6, 5), 1.0},
                        {test::make_l_block(12, 1.2, 6), 1.5},
                        {test::make_plate_with_holes(20, 20, 1.5, 3, 3, 1.5, false), 2.0}};
  for (const Case& c : cases) {
    const Features f = classify_features(c.solid);
    const Samples samples = sample_solid(c.solid, f, c.spacing * 0.5);
    const ThinWall full = thinnest_wall(samples, c.spacing, convex_face_pairs(f));
    ASSERT_LT(full.radius, c.spacing);
    for (double guess : {0.0, 1e-3, 0.3 * full.radius, full.radius, 3 * full.radius, 10 * c.spacing}) {
      const ThinWall near = thinnest_wall_near(samples, c.spacing, convex_face_pairs(f), guess);
      EXPECT_EQ(near.radius, full.radius) << guess;
      EXPECT_EQ(near.at, full.at) << guess;
    }
  }
}

// wall_radii's rule (thin_walls.h, the search in WallMeter::radius) by brute force over every pair of
// wall samples: the same radii, to the bit, whichever cells the grid search visits or skips.
double radius_by_brute_force(const Samples& s, std::size_t i, double spacing,
                             const std::set<std::pair<int, int>>& wedges, double wedge_dot) {
  auto dot = [](const Point3& a, const Point3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
  auto on_edge = [&](std::size_t j) { return s.tag[j] == SampleTag::Edge || s.tag[j] == SampleTag::Ball; };
  auto on_wall = [&](std::size_t j) {
    return s.tag[j] == SampleTag::Face || s.tag[j] == SampleTag::Triplet || (on_edge(j) && s.edge_convex[j] != 1);
  };
  const double inf = std::numeric_limits<double>::infinity();
  if (!on_wall(i)) return inf;
  const Point3& p = s.points[i];
  const double reach = 2.0 * spacing;
  bool by_edge = false;
  for (std::size_t j = 0; j < s.size(); ++j)
    by_edge = by_edge || (s.edge_convex[j] == 1 && distance2(s.points[j], p) < spacing * spacing);
  double radius = inf;
  for (const Point3* n : {&s.normal[i], on_edge(i) ? &s.normal2[i] : nullptr}) {
    if (!n) continue;
    for (std::size_t j = 0; j < s.size(); ++j) {
      if (!on_wall(j)) continue;
      if (!(dot(*n, s.normal[j]) <= -0.5 || (on_edge(j) && dot(*n, s.normal2[j]) <= -0.5))) continue;
      if (by_edge && s.face[i] >= 0 && s.face[j] >= 0 && s.face[j] != s.face[i] && dot(*n, s.normal[j]) < wedge_dot &&
          wedges.count({s.face[i], s.face[j]}))
        continue;
      const Point3 d{s.points[j][0] - p[0], s.points[j][1] - p[1], s.points[j][2] - p[2]};
      const double d2 = dot(d, d), depth = -dot(d, *n);
      if (!(depth > 0 && d2 < reach * reach) || depth > reach) continue;
      radius = std::min(radius, d2 / (2.0 * depth));
      if (dot(*n, s.normal[j]) < -0.95 && depth * depth >= 0.04 * (d2 - depth * depth)) radius = std::min(radius, 0.5 * depth);
    }
  }
  return radius < spacing ? radius : inf;
}

// Thin walls between planes, between a plane and a hole's cylinder, across fillets (smooth edges
// are walls) and in a wedge (its faces are not walls for each other near the sharp edge).
TEST(ThinWalls, TheRadiiAreTheShrinkingBallsOverEveryWallSample) {
  struct Case {
    const char* name;
    TopoDS_Solid solid;
    double spacing;
  };
  const Case cases[] = {{"plate", test::make_box(12, 10, 0.8), 1.0},
                        {"block with a hole near its sides", test::make_block_with_hole(10, 10, 3, 4.6), 0.6},
                        {"filleted L block", test::make_filleted_l_block(8, 1.0, 3, 0.4, 0.3), 0.5},
                        {"wedge", test::make_sharp_wedge(20, 12, 4), 0.5}};
  for (const Case& c : cases) {
    const Features f = classify_features(c.solid);
    const Samples samples = sample_solid(c.solid, f, c.spacing);
    std::set<std::pair<int, int>> wedges;
    for (const auto& [a, b] : convex_face_pairs(f)) wedges.insert({a, b}), wedges.insert({b, a});
    for (const double wedge_dot : {1.0, -0.95}) {
      std::vector<double> expected(samples.size());
      std::size_t finite = 0;
      for (std::size_t i = 0; i < samples.size(); ++i) {
        expected[i] = radius_by_brute_force(samples, i, c.spacing, wedges, wedge_dot);
        finite += std::isfinite(expected[i]);
      }
      EXPECT_GT(finite, 20u) << c.name << ": too few thin samples to tell";
      for (const int threads : {1, 2}) {
        const std::vector<double> radii = wall_radii(samples, c.spacing, convex_face_pairs(f), wedge_dot, {}, threads);
        ASSERT_EQ(radii.size(), samples.size());
        std::size_t differ = 0;
        for (std::size_t i = 0; i < samples.size(); ++i) differ += !(radii[i] == expected[i]);
        EXPECT_EQ(differ, 0u) << c.name << ", wedge_dot " << wedge_dot << ", " << threads << " thread(s)";
      }
    }
  }
}

TEST(ThinWalls, WithOneSpacingThePipelineWarnsAndReportsTheThickness) {
  ComputeParams params;
  params.sampling.spacing = 1.0;
  params.sampling.adapt_to_walls = false;
  const ComputeResult thin = compute_medial_axis(test::make_box(30, 30, 1), params);
  ASSERT_EQ(thin.stats.warnings.size(), 1u);
  EXPECT_NE(thin.stats.warnings[0].find("thinner than two sample spacings"), std::string::npos) << thin.stats.warnings[0];
  ASSERT_EQ(thin.stats.solids.size(), 1u);
  EXPECT_GE(thin.stats.solids[0].thinnest_wall, 1.0 - 1e-9);
  EXPECT_LE(thin.stats.solids[0].thinnest_wall, 1.2);
  // Where: on the plate's top or bottom face (z = 1 or 0), inside its 30 x 30 extent.
  const Point3 at = thin.stats.solids[0].thinnest_wall_at;
  EXPECT_TRUE(std::abs(at[2]) < 1e-9 || std::abs(at[2] - 1.0) < 1e-9) << at[2];
  EXPECT_TRUE(at[0] >= 0 && at[0] <= 30 && at[1] >= 0 && at[1] <= 30) << at[0] << ", " << at[1];
  const ComputeResult thick = compute_medial_axis(test::make_box(20, 20, 20), params);
  EXPECT_TRUE(thick.stats.warnings.empty());
  EXPECT_TRUE(std::isinf(thick.stats.solids[0].thinnest_wall));
}

// Adaptive sampling (the default): a plate thinner than the spacing is sampled in mirrored pairs
// (mirror_thin_walls.h), whose sheet lies on the mid-plane at any spacing, and finer only at its
// rims and junctions (edge_walls.h). The 1-thick plate at spacing 1 and one 0.4 thick: the plate's
// topology, the sheet at the mid-plane with radius half the thickness away from the rims, and
// fewer samples than refining the whole faces took (16 times their samples, by the old rule). A
// thick block is sampled once, unchanged.
TEST(ThinWalls, AdaptiveSamplingResolvesThinPlatesInMirroredPairs) {
  const auto [uniform, adaptive] = uniform_and_adaptive(1.0);
  for (const double t : {1.0, 0.4}) {
    const TopoDS_Solid plate = test::make_box(30, 30, t);
    const ComputeResult once = compute_medial_axis(plate, uniform);
    const ComputeResult adapted = compute_medial_axis(plate, adaptive);
    EXPECT_EQ(adapted.stats.solids[0].euler_characteristic, 1) << t;
    EXPECT_EQ(adapted.stats.solids[0].components, 1u) << t;
    EXPECT_GT(adapted.stats.solids[0].mirrored_samples, 0u) << t;
    EXPECT_GT(adapted.stats.samples, once.stats.samples) << t << ": the rims are sampled finer";
    EXPECT_LT(adapted.stats.samples, 8 * once.stats.samples) << t;
    std::size_t on_sheet = 0;
    for (std::size_t v = 0; v < adapted.mesh.num_vertices(); ++v) {
      const Point3& p = adapted.mesh.vertices[v];
      if (p[0] < 2 * t || p[0] > 30 - 2 * t || p[1] < 2 * t || p[1] > 30 - 2 * t) continue;
      ++on_sheet;
      EXPECT_NEAR(p[2], t / 2, 1e-6 * t) << t << ": vertex " << v;
      EXPECT_NEAR(adapted.mesh.radius[v], t / 2, 1e-6 * t) << t << ": vertex " << v;
    }
    EXPECT_GT(on_sheet, 100u) << t;
  }

  const TopoDS_Solid block = test::make_box(20, 20, 20);
  const ComputeResult block_once = compute_medial_axis(block, uniform);
  const ComputeResult block_adapted = compute_medial_axis(block, adaptive);
  EXPECT_EQ(block_adapted.stats.samples, block_once.stats.samples);
  EXPECT_EQ(block_adapted.mesh.vertices, block_once.mesh.vertices);
}

// A pin 1 thick on a block, small against the block: resolving it needs a twelfth of the spacing
// (0.5 per unit of its medial radius 0.5, at spacing 3), finer than a quarter, and costs few
// samples. The sampling goes down to it: no warning, and the block's topology. (Before, it
// stopped at a quarter and warned; NIST FTC 06's raised letters left 12 extra loops so.)
TEST(ThinWalls, AFewSmallThinWallsAreSampledFinerThanAQuarterOfTheSpacing) {
  const auto [uniform, adaptive] = uniform_and_adaptive(3.0);
  const TopoDS_Solid pinned = test::make_block_with_boss(100, 100, 20, 0.5, 1.0);
  const ComputeResult once = compute_medial_axis(pinned, uniform);
  const ComputeResult adapted = compute_medial_axis(pinned, adaptive);
  EXPECT_TRUE(adapted.stats.warnings.empty()) << adapted.stats.warnings[0];
  EXPECT_EQ(adapted.stats.solids[0].euler_characteristic, 1);
  EXPECT_EQ(adapted.stats.solids[0].components, 1u);
  // Within the budget: at most 3 times the uniform sampling's count.
  EXPECT_GT(adapted.stats.samples, once.stats.samples);
  EXPECT_LE(adapted.stats.samples, 3 * once.stats.samples);
}

// The user's minimum feature size (SamplingParams::min_feature): the 1-thick pin counts as 2
// thick, so it is sampled finer than the block but half as finely as it needs, and the warning
// says so with its place and thickness. A minimum under the pin's thickness changes nothing.
TEST(ThinWalls, WallsBelowTheMinimumFeatureSizeAreSampledOnlyAsItNeedsAndNamed) {
  const auto [uniform, adaptive] = uniform_and_adaptive(3.0);
  const TopoDS_Solid pinned = test::make_block_with_boss(100, 100, 20, 0.5, 1.0);
  const ComputeResult once = compute_medial_axis(pinned, uniform);
  const ComputeResult full = compute_medial_axis(pinned, adaptive);
  ComputeParams coarse = adaptive;
  coarse.sampling.min_feature = 2.0;
  const ComputeResult limited = compute_medial_axis(pinned, coarse);
  EXPECT_GT(limited.stats.samples, once.stats.samples);
  EXPECT_LT(limited.stats.samples, full.stats.samples);
  ASSERT_EQ(limited.stats.warnings.size(), 1u);
  const std::string& warning = limited.stats.warnings[0];
  EXPECT_NE(warning.find("thinner than the minimum feature size given (2)"), std::string::npos) << warning;
  EXPECT_NEAR(limited.stats.solids[0].thinnest_wall, 1.0, 0.05);
  // Named where the pin is (on the block's top face, within its footprint).
  const Point3 at = limited.stats.solids[0].thinnest_wall_at;
  EXPECT_GE(at[2], 20.0 - 1e-6) << warning;
  EXPECT_NEAR(at[0], 50.0, 1.0) << warning;
  EXPECT_NEAR(at[1], 50.0, 1.0) << warning;

  ComputeParams fine = adaptive;
  fine.sampling.min_feature = 0.5;
  const ComputeResult unchanged = compute_medial_axis(pinned, fine);
  EXPECT_EQ(unchanged.stats.samples, full.stats.samples);
  EXPECT_TRUE(unchanged.stats.warnings.empty()) << unchanged.stats.warnings[0];

  ComputeParams bad = adaptive;
  bad.sampling.min_feature = -1.0;
  EXPECT_THROW(compute_medial_axis(pinned, bad), InvalidInput);
}

// compute_medial_axis checks the uniform sampling for thin walls beside its triangulation, and
// gives that triangulation up when it must sample finer; sample_shape (the preview's path) checks
// first. Both must take the same samples: a plate that is refined, a block that is not, and both
// in one compound (the plate second, after the block's triangulation is kept).
TEST(ThinWalls, TheCheckBesideTheTriangulationTakesThePreviewsSamples) {
  ComputeParams params;
  params.sampling.spacing = 1.0;
  const TopoDS_Solid plate = test::make_box(30, 30, 1), block = test::make_box(20, 20, 20);
  const TopoDS_Shape both = test::make_compound({block, plate});
  for (const TopoDS_Shape& shape : {TopoDS_Shape(plate), TopoDS_Shape(block), both}) {
    const std::vector<Samples> preview = sample_shape(shape, params.sampling);
    const ComputeResult result = compute_medial_axis(shape, params);
    ASSERT_EQ(result.stats.solids.size(), preview.size());
    for (std::size_t k = 0; k < preview.size(); ++k) {
      EXPECT_EQ(result.stats.solids[k].samples, preview[k].size()) << "solid " << k;
      EXPECT_EQ(result.stats.solids[k].euler_characteristic, 1) << "solid " << k;
    }
  }
  // The plate was refined (at its rims), the block not.
  ComputeParams uniform = params;
  uniform.sampling.adapt_to_walls = false;
  EXPECT_GT(compute_medial_axis(plate, params).stats.samples, compute_medial_axis(plate, uniform).stats.samples);
  EXPECT_EQ(compute_medial_axis(block, params).stats.samples, compute_medial_axis(block, uniform).stats.samples);
}

}  // namespace
}  // namespace cadmedial
