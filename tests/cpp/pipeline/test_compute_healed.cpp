// compute_medial_axis on broken input: what OpenCASCADE heals is computed with a warning saying
// what was fixed, a bad solid of an assembly is skipped with a warning naming it, and what cannot
// be a solid is still refused. The axes are checked against the healed solids' own.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include "core/errors.h"
#include "core/pipeline/compute_medial_axis.h"
#include "support/broken_solids.h"
#include "support/mesh_measures.h"
#include "support/solids.h"

namespace cadmedial::test {
namespace {

constexpr double kSpacing = 0.4;

ComputeResult run(const TopoDS_Shape& shape) {
  ComputeParams params;
  params.sampling.spacing = kSpacing;
  return compute_medial_axis(shape, params);
}

bool has_warning(const ComputeResult& r, const std::string& fragment) {
  return std::any_of(r.stats.warnings.begin(), r.stats.warnings.end(),
                     [&](const std::string& w) { return w.find(fragment) != std::string::npos; });
}

// Solid `solid`'s axis is that of the box [x0, x0 + a] x [0, b] x [0, c]: the box's Euler
// characteristic (1, as the engine counts it), every vertex inside the box (to 1e-6: a healed
// vertex may have moved by its tolerance), and the largest radius half the box's smallest side
// (within a spacing: the radius is the distance to the samples).
void expect_box_axis(const ComputeResult& r, int solid, double x0, double a, double b, double c) {
  const SolidStats& s = r.stats.solids.at(solid);
  EXPECT_EQ(s.solid_euler_characteristic, 1) << "solid " << solid;
  EXPECT_EQ(s.euler_characteristic, 1) << "solid " << solid;
  double largest = 0;
  std::size_t used = 0;
  const MedialMesh& m = r.mesh;
  for (std::size_t f = 0; f < m.num_faces(); ++f) {
    if (m.solid[f] != solid) continue;
    for (int k = 0; k < m.face_size(f); ++k) {
      const int v = m.face(f)[k];
      const Point3& p = m.vertices[v];
      ++used;
      largest = std::max(largest, m.radius[v]);
      EXPECT_GE(p[0], x0 - 1e-6);
      EXPECT_LE(p[0], x0 + a + 1e-6);
      EXPECT_GE(p[1], -1e-6);
      EXPECT_LE(p[1], b + 1e-6);
      EXPECT_GE(p[2], -1e-6);
      EXPECT_LE(p[2], c + 1e-6);
    }
  }
  EXPECT_GT(used, 0u) << "solid " << solid << " has no faces";
  EXPECT_NEAR(largest, 0.5 * std::min({a, b, c}), kSpacing) << "solid " << solid;
}

TEST(ComputeHealed, AssemblyWithAnEmptySolidComputesTheOthers) {
  // Three 10 mm cubes in a row, touching, and an empty solid as the third of four (as
  // tests/data/bad/assembly_with_empty_solid.brep).
  const TopoDS_Shape shape = make_compound({make_box(10, 10, 10), BRepPrimAPI_MakeBox(gp_Pnt(10, 0, 0), 10, 10, 10).Solid(),
                                            empty_solid(), BRepPrimAPI_MakeBox(gp_Pnt(20, 0, 0), 10, 10, 10).Solid()});
  const ComputeResult r = run(shape);
  ASSERT_EQ(r.stats.solids.size(), 3u);
  EXPECT_TRUE(has_warning(r, "solid 3: has no shell (an empty solid); skipped")) << r.stats.warnings.size();
  for (int s : r.mesh.solid) EXPECT_TRUE(s >= 0 && s < 3) << s;
  for (int s = 0; s < 3; ++s) expect_box_axis(r, s, 10.0 * s, 10, 10, 10);
  // The same axis as the assembly without the empty solid, vertex for vertex.
  const ComputeResult without = run(make_compound({make_box(10, 10, 10), BRepPrimAPI_MakeBox(gp_Pnt(10, 0, 0), 10, 10, 10).Solid(),
                                                   BRepPrimAPI_MakeBox(gp_Pnt(20, 0, 0), 10, 10, 10).Solid()}));
  EXPECT_EQ(r.mesh.vertices, without.mesh.vertices);
  EXPECT_EQ(r.mesh.solid, without.mesh.solid);
}

// The axis of a single healed box, welded as the other end-to-end suites weld it, is one piece
// with the box's Euler characteristic too.
void expect_welded_box_topology(const ComputeResult& r, double a, double b, double c) {
  const double diagonal = std::sqrt(a * a + b * b + c * c);
  EXPECT_EQ(euler_characteristic(r.mesh, diagonal, 0), 1);
  EXPECT_EQ(connected_pieces(r.mesh, diagonal, 0), 1);
}

TEST(ComputeHealed, FaceReversedInItsShellIsHealedAndGivesTheBoxsAxis) {
  const ComputeResult r = run(box_with_reversed_face(10, 8, 6, 5));
  ASSERT_EQ(r.stats.solids.size(), 1u);
  ASSERT_FALSE(r.stats.warnings.empty());
  EXPECT_EQ(r.stats.warnings[0].rfind("solid 1: shell 1 is invalid (BRepCheck_BadOrientationOfSubshape); healed by ShapeFix", 0), 0u)
      << r.stats.warnings[0];
  expect_box_axis(r, 0, 0, 10, 8, 6);
  expect_welded_box_topology(r, 10, 8, 6);
  // The try that BRepCheck stopped is timed, and counted in the total.
  double healing = -1, total = -1;
  for (const auto& [stage, s] : r.stats.timings) {
    if (stage == "healing") healing = s;
    if (stage == "total") total = s;
  }
  EXPECT_GT(healing, 0.0);
  EXPECT_GT(total, healing);
}

TEST(ComputeHealed, SolidOpenByASmallGapIsSewnAndGivesTheBoxsAxis) {
  const ComputeResult r = run(box_with_gap(10, 8, 6, 1, 0.001));
  ASSERT_EQ(r.stats.solids.size(), 1u);
  EXPECT_TRUE(has_warning(r, "closed by sewing its faces"));
  // The moved face is at x = 10.001: the box is that much longer.
  expect_box_axis(r, 0, 0, 10.001, 8, 6);
  expect_welded_box_topology(r, 10.001, 8, 6);
}

TEST(ComputeHealed, VertexOffItsEdgesIsHealedAndGivesTheBoxsAxis) {
  const ComputeResult r = run(box_with_vertex_off_its_edges(10, 8, 6));
  ASSERT_EQ(r.stats.solids.size(), 1u);
  EXPECT_TRUE(has_warning(r, "solid 1: vertex 1 is invalid (BRepCheck_InvalidPointOnCurve)"));
  expect_box_axis(r, 0, 0, 10, 8, 6);
  expect_welded_box_topology(r, 10, 8, 6);
}

TopoDS_Solid bow_tie_prism() {
  TopoDS_Shape shape;
  BRep_Builder builder;
  const std::string path = std::string(CADMEDIAL_SOURCE_DIR) + "/tests/data/bad/self_intersecting.brep";
  if (!BRepTools::Read(shape, path.c_str(), builder)) throw std::runtime_error("cannot read " + path);
  return TopoDS::Solid(TopExp_Explorer(shape, TopAbs_SOLID).Current());
}

TEST(ComputeHealed, WhatCannotBeASolidIsStillRefused) {
  try {
    run(bow_tie_prism());
    ADD_FAILURE() << "expected InvalidInput";
  } catch (const InvalidInput& e) {
    const std::string why = e.what();
    EXPECT_EQ(why.rfind("solid 1: wire 5 is invalid (BRepCheck_SelfIntersectingWire); ShapeFix cannot heal it", 0), 0u)
        << why;
  }
}

TEST(ComputeHealed, UnhealableSolidBesideABoxIsSkippedAndTheBoxComputed) {
  // The bow-tie prism lies within [0, 10] x [0, 30] x [0, 5] (make_bad_inputs.py); the box beyond it.
  const TopoDS_Shape shape = make_compound({bow_tie_prism(), BRepPrimAPI_MakeBox(gp_Pnt(40, 0, 0), 10, 8, 6).Solid()});
  const ComputeResult r = run(shape);
  ASSERT_EQ(r.stats.solids.size(), 1u);
  EXPECT_TRUE(has_warning(r, "solid 1: wire 5 is invalid (BRepCheck_SelfIntersectingWire); ShapeFix cannot heal it"));
  EXPECT_TRUE(has_warning(r, "; skipped"));
  expect_box_axis(r, 0, 40, 10, 8, 6);
}

}  // namespace
}  // namespace cadmedial::test
