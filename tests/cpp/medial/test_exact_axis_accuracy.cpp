// The engine against exact inner medial axes: convex polytopes (box, thin plate, wedge, random) and
// solids of revolution (cylinder, disc, sphere, torus). Tolerances: support/exact_cases.h.
#include <algorithm>
#include <sstream>

#include <gtest/gtest.h>

#include "support/engine_run.h"
#include "support/exact_cases.h"
#include "support/mesh_measures.h"
#include "support/summary.h"
#include "known_weaknesses.h"

namespace cadmedial::test {
namespace {

class ExactMedialAxis : public ::testing::TestWithParam<int> {
 protected:
  const ExactCase& c() const { return exact_cases()[GetParam()]; }
  // The engine's output for this solid; fails the test (returns nullptr) when it is empty. A
  // sphere's axis is its centre: vertices without faces are an answer, not an empty output.
  const MedialMesh* mesh() {
    const ComputeResult& result = medial_axis_of(c().name, c().make_shape, c().spacing);
    EXPECT_GT(result.mesh.num_vertices(), 0u) << c().name << ": empty output";
    EXPECT_EQ(result.mesh.radius.size(), result.mesh.vertices.size());
    return result.mesh.num_vertices() > 0 ? &result.mesh : nullptr;
  }
};

TEST_P(ExactMedialAxis, EveryVertexIsNearTheExactAxis) {
  const MedialMesh* m = mesh();
  if (!m) return;
  std::vector<double> d;
  std::vector<Vec3> at;
  for (const auto& v : m->vertices) d.push_back(c().axis_distance(v)), at.push_back(v);
  const Summary s = summarize(d, at, c().axis_tolerance);
  if (known_weakness("NearAxis", c().name) && s.max > c().axis_tolerance)
    GTEST_SKIP() << "known weakness: " << c().name << " vertex to exact axis " << s.str();
  EXPECT_LE(s.max, c().axis_tolerance) << c().name << " (h = " << c().spacing << ", tolerance "
                                       << c().axis_tolerance << "): vertex to exact axis " << s.str();
}

TEST_P(ExactMedialAxis, TheExactAxisIsCoveredByTheOutput) {
  const MedialMesh* m = mesh();
  if (!m) return;
  const MeshDistance surface(*m, c().bbox_diagonal);
  const std::vector<Vec3> points = c().axis_sample(2000, 17);
  std::vector<double> d;
  for (const auto& p : points) d.push_back(surface.distance(p));
  const Summary s = summarize(d, points, c().axis_tolerance);
  EXPECT_LE(s.max, c().axis_tolerance) << c().name << " (h = " << c().spacing << ", tolerance "
                                       << c().axis_tolerance << "): exact axis point to output " << s.str();
}

TEST_P(ExactMedialAxis, EveryConvexEdgeIsReached) {
  if (c().convex_edge_points.empty()) GTEST_SKIP() << c().name << " has no convex edge";
  const MedialMesh* m = mesh();
  if (!m) return;
  const MeshDistance surface(*m, c().bbox_diagonal);
  std::vector<double> d;
  for (const auto& p : c().convex_edge_points) d.push_back(surface.distance(p));
  const Summary s = summarize(d, c().convex_edge_points, c().spacing);
  EXPECT_LE(s.max, c().spacing) << c().name << " (tolerance h = " << c().spacing << "): edge point to output "
                                << s.str();
}

TEST_P(ExactMedialAxis, EveryNonconcaveCornerIsReached) {
  if (c().corners.empty()) GTEST_SKIP() << c().name << " has no corner";
  const MedialMesh* m = mesh();
  if (!m) return;
  const MeshDistance surface(*m, c().bbox_diagonal);
  std::vector<double> d;
  for (const auto& p : c().corners) d.push_back(surface.distance(p));
  const Summary s = summarize(d, c().corners, c().spacing);
  EXPECT_LE(s.max, c().spacing) << c().name << " (tolerance h = " << c().spacing << "): corner to output "
                                << s.str();
}

TEST_P(ExactMedialAxis, EveryVertexIsInsideTheSolid) {
  const MedialMesh* m = mesh();
  if (!m) return;
  // Completion vertices lie on edges (D = 0 up to rounding): tolerance 1e-6 of the bounding box.
  const double tol = 1e-6 * c().bbox_diagonal;
  std::vector<double> outside;
  std::vector<Vec3> at;
  for (const auto& v : m->vertices) outside.push_back(-c().boundary_distance(v)), at.push_back(v);
  const Summary s = summarize(outside, at, tol);
  EXPECT_LE(s.max, tol) << c().name << ": depth outside the solid " << s.str();
}

TEST_P(ExactMedialAxis, EveryRadiusIsTheDistanceToTheBoundary) {
  const MedialMesh* m = mesh();
  if (!m) return;
  // D <= r <= D + delta, delta <= h (support/exact_cases.h); 1e-6 bbox for rounding.
  const double eps = 1e-6 * c().bbox_diagonal;
  std::vector<double> below, above;
  std::vector<Vec3> at;
  for (std::size_t v = 0; v < m->vertices.size(); ++v) {
    const double D = c().boundary_distance(m->vertices[v]);
    below.push_back(D - m->radius[v]);
    above.push_back(m->radius[v] - D);
    at.push_back(m->vertices[v]);
  }
  const Summary lo = summarize(below, at, eps), hi = summarize(above, at, c().spacing + eps);
  EXPECT_LE(lo.max, eps) << c().name << ": radius smaller than the distance to the boundary by " << lo.str();
  EXPECT_LE(hi.max, c().spacing + eps) << c().name << " (h = " << c().spacing
                                       << "): radius larger than the distance to the boundary by " << hi.str();
}

TEST_P(ExactMedialAxis, TheOutputIsOnePiece) {
  const MedialMesh* m = mesh();
  if (!m) return;
  EXPECT_EQ(connected_pieces(*m, c().bbox_diagonal), 1) << c().name;
}

TEST_P(ExactMedialAxis, EveryFaceBelongsToSolidZero) {
  const MedialMesh* m = mesh();
  if (!m) return;
  const auto wrong = std::count_if(m->solid.begin(), m->solid.end(), [](int s) { return s != 0; });
  EXPECT_EQ(m->solid.size(), m->num_faces());
  EXPECT_EQ(wrong, 0) << c().name << ": faces with a solid index other than 0";
}

TEST_P(ExactMedialAxis, EveryEdgeBelongsToSolidZero) {
  const MedialMesh* m = mesh();
  if (!m) return;
  const auto wrong = std::count_if(m->edge_solid.begin(), m->edge_solid.end(), [](int s) { return s != 0; });
  EXPECT_EQ(m->edge_solid.size(), m->num_edges());
  EXPECT_EQ(wrong, 0) << c().name << ": 1-D edges with a solid index other than 0";
}

TEST_P(ExactMedialAxis, TheEulerCharacteristicIsTheSolids) {
  const MedialMesh* m = mesh();
  if (!m) return;
  int degenerate = 0;
  const long chi = euler_characteristic(*m, c().bbox_diagonal, -1, &degenerate);
  if (known_weakness("Euler", c().name) && chi != c().euler)
    GTEST_SKIP() << "known weakness: " << c().name << " V - E + F = " << chi << ", the solid's is " << c().euler;
  EXPECT_EQ(chi, c().euler) << c().name << ": V - E + F of the output (" << degenerate
                            << " degenerate polygons after welding)";
}

std::vector<int> case_indices() {
  std::vector<int> v(exact_cases().size());
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = static_cast<int>(i);
  return v;
}

INSTANTIATE_TEST_SUITE_P(Solids, ExactMedialAxis, ::testing::ValuesIn(case_indices()),
                         [](const ::testing::TestParamInfo<int>& info) { return exact_cases()[info.param].name; });

}  // namespace
}  // namespace cadmedial::test
