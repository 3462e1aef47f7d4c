// SamplingParams::refine_topology: a solid whose medial axis comes out with another topology than
// the solid's (its Euler characteristic, or in pieces) is sampled again, finer, and computed
// anew; a solid whose axis is right is left as it was. Without it the result says what is wrong.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/errors.h"
#include "core/pipeline/compute_medial_axis.h"
#include "support/hard_solids.h"
#include "support/same_mesh.h"
#include "support/solids.h"

namespace cadmedial::test {
namespace {

// One spacing everywhere (no thin-wall refinement), so that the solid's walls stay undersampled
// for the spacing given, with or without refinement of the topology.
ComputeResult uniform_run(const TopoDS_Shape& shape, double spacing, bool refine) {
  ComputeParams params;
  params.sampling.spacing = spacing;
  params.sampling.adapt_to_walls = false;
  params.sampling.refine_topology = refine;
  return compute_medial_axis(shape, params);
}

bool has_warning(const ComputeResult& r, const std::string& fragment) {
  for (const std::string& w : r.stats.warnings)
    if (w.find(fragment) != std::string::npos) return true;
  return false;
}

// What a refined result must show: the solid's topology, sampled finer by whole steps of the
// spacing's factor, and no warning of its topology.
void expect_refined_right(const ComputeResult& once, const ComputeResult& refined) {
  const SolidStats& s = refined.stats.solids.at(0);
  EXPECT_EQ(s.euler_characteristic, s.solid_euler_characteristic);
  EXPECT_EQ(s.components, 1u);
  ASSERT_GE(s.refinements, 1);
  ASSERT_LE(s.refinements, 2);
  EXPECT_NEAR(s.spacing, refined.stats.spacing / std::pow(std::sqrt(2.5), s.refinements), 1e-12 * s.spacing);
  EXPECT_GT(refined.stats.samples, once.stats.samples);
  EXPECT_EQ(refined.stats.samples, s.samples);
  EXPECT_FALSE(has_warning(refined, "medial axis")) << refined.stats.warnings.at(0);
}

// Fifteen holes through a plate 3 thick: at spacings 5.45 and 4.48 the sheet between the plate's
// faces has holes of its own (Euler -9 where the solid's is -14); sampled finer it has not.
TEST(TopologyRefinement, APlateWhoseSheetHasHolesIsSampledFinerUntilItHasTheSolidsEulerCharacteristic) {
  const TopoDS_Solid plate = make_plate_with_holes(60, 40, 3, 5, 3, 2.5, false);
  for (const double spacing : {5.449, 4.475}) {
    const ComputeResult once = uniform_run(plate, spacing, false);
    const SolidStats& s = once.stats.solids.at(0);
    ASSERT_EQ(s.solid_euler_characteristic, -14);
    // The premise: this sampling is too coarse for the plate's topology.
    ASSERT_NE(s.euler_characteristic, s.solid_euler_characteristic) << "spacing " << spacing;
    EXPECT_EQ(s.refinements, 0);
    EXPECT_EQ(s.spacing, spacing);
    EXPECT_TRUE(has_warning(once, "the medial axis's Euler characteristic is " + std::to_string(s.euler_characteristic) +
                                      " where the solid's is -14"));
    expect_refined_right(once, uniform_run(plate, spacing, true));
  }
}

// Six ribs 0.6 thick and 15 tall on a block: at spacing 1.2 the sheets inside the ribs break off
// the rest (211 pieces; the stray ones are dropped, and the Euler characteristic cannot tell, each
// rib being contractible). Refined, the axis is one piece and runs up the middle of every rib:
// the point halfway up a rib's mid-plane is a medial point of radius 0.3 (half the rib's width).
TEST(TopologyRefinement, RibsWhoseSheetsBrokeOffAreSampledFinerUntilTheAxisIsOnePiece) {
  const double x0 = 4, pitch = 8, w = 0.6, height = 15, c = 5;
  const TopoDS_Solid ribs = make_block_with_ribs(50, 50, c, 6, x0, pitch, w, height);
  const ComputeResult once = uniform_run(ribs, 1.2, false);
  ASSERT_GT(once.stats.solids.at(0).components, 1u);
  EXPECT_TRUE(has_warning(once, "parts of the medial axis are missing"));
  const ComputeResult refined = uniform_run(ribs, 1.2, true);
  expect_refined_right(once, refined);
  const double h = refined.stats.solids.at(0).spacing;
  for (int k = 0; k < 6; ++k) {
    const Point3 mid{x0 + k * pitch + w / 2, 25, c + height / 2};
    double best = 1e300, radius = 0;
    for (std::size_t v = 0; v < refined.mesh.num_vertices(); ++v) {
      const Point3& p = refined.mesh.vertices[v];
      const double d = std::hypot(p[0] - mid[0], p[1] - mid[1], p[2] - mid[2]);
      if (d < best) best = d, radius = refined.mesh.radius[v];
    }
    EXPECT_LT(best, h) << "rib " << k;
    EXPECT_NEAR(radius, w / 2, h) << "rib " << k;
  }
}

// A refinement that fails (made to throw, as OpenCASCADE might on a face, at its sampling, at the
// selection beside its worker thread, or at the inner stage) loses nothing: the coarser axis is
// the result, with a warning that says why. A cancel there cancels.
TEST(TopologyRefinement, AFailedRefinementKeepsTheCoarserAxisAndSaysSo) {
  const TopoDS_Solid plate = make_plate_with_holes(60, 40, 3, 5, 3, 2.5, false);
  ComputeParams params;
  params.sampling.spacing = 4.475;
  params.sampling.adapt_to_walls = false;
  const ComputeResult once = compute_medial_axis(plate, params);
  ASSERT_NE(once.stats.solids.at(0).euler_characteristic, -14);  // the premise: it wants refining
  params.sampling.refine_topology = true;
  auto failing_after_refining = [](const std::string& at, bool cancel) {
    return [at, cancel, refining = false](const std::string& stage, double) mutable {
      refining = refining || stage == "refining";
      if (refining && stage == at) {
        if (cancel) return false;
        throw GeometryError("injected failure");
      }
      return true;
    };
  };
  for (const std::string at : {"sampling", "selection", "inner"}) {
    SCOPED_TRACE(at);
    const ComputeResult kept = compute_medial_axis(plate, params, failing_after_refining(at, false));
    expect_same_mesh(kept.mesh, once.mesh);
    EXPECT_EQ(kept.stats.solids.at(0).refinements, 0);
    EXPECT_EQ(kept.stats.solids.at(0).spacing, 4.475);
    EXPECT_EQ(kept.stats.samples, once.stats.samples);
    EXPECT_TRUE(has_warning(kept, "sampling finer for the axis's topology failed (injected failure); the axis is "
                                  "that of the coarser sampling"));
    EXPECT_TRUE(has_warning(kept, "the medial axis's Euler characteristic is"));
    EXPECT_THROW(compute_medial_axis(plate, params, failing_after_refining(at, true)), Cancelled);
  }
}

// A solid whose axis is right at once is computed once: the same mesh as without refinement.
// Plain MEDIAL (the ablation) is never refined.
TEST(TopologyRefinement, ARightAxisAndPlainMedialAreLeftAsTheyAre) {
  const TopoDS_Solid block = make_block_with_hole(10, 8, 6, 2);
  const ComputeResult once = uniform_run(block, 0.5, false), refined = uniform_run(block, 0.5, true);
  ASSERT_EQ(once.stats.solids.at(0).euler_characteristic, 0);
  EXPECT_EQ(refined.stats.solids.at(0).refinements, 0);
  EXPECT_EQ(refined.stats.solids.at(0).spacing, 0.5);
  expect_same_mesh(once.mesh, refined.mesh);

  ComputeParams plain;
  plain.sampling.spacing = 4.475;
  plain.sampling.adapt_to_walls = false;
  plain.sampling.refine_topology = true;
  plain.medial.plain_medial = true;
  plain.medial.theta_deg = 22.5;
  const ComputeResult medial = compute_medial_axis(make_plate_with_holes(60, 40, 3, 5, 3, 2.5, false), plain);
  EXPECT_EQ(medial.stats.solids.at(0).refinements, 0);
}

}  // namespace
}  // namespace cadmedial::test
