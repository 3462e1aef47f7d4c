// A compound of two disjoint boxes: each solid gets its own axis, labelled with its index in
// TopExp_Explorer order (the order the compound holds them).
#include <gtest/gtest.h>

#include <BRepPrimAPI_MakeBox.hxx>

#include "support/convex_polytope.h"
#include "support/engine_run.h"
#include "support/polytope_medial_axis.h"
#include "support/solids.h"
#include "support/summary.h"

namespace cadmedial::test {
namespace {

// Box A = [0,10] x [0,8] x [0,6]; box B = [20,26] x [0,6] x [0,4] (disjoint, 10 apart).
constexpr double kSpacing = 0.3;

const ComputeResult& two_boxes() {
  return medial_axis_of("TwoBoxes", [] {
    const TopoDS_Solid b = BRepPrimAPI_MakeBox(gp_Pnt(20, 0, 0), 6, 6, 4).Solid();
    return make_compound({make_box(10, 8, 6), b});
  }, kSpacing);
}

ConvexPolytope box_b() {
  return polytope_from_halfspaces({{{1, 0, 0}, 26}, {{-1, 0, 0}, -20}, {{0, 1, 0}, 6},
                                   {{0, -1, 0}, 0}, {{0, 0, 1}, 4}, {{0, 0, -1}, 0}});
}

TEST(MultiSolid, TwoBoxesGiveFacesOfSolidZeroAndOne) {
  const MedialMesh& m = two_boxes().mesh;
  std::size_t count[2] = {0, 0}, other = 0;
  for (int s : m.solid) (s == 0 || s == 1) ? ++count[s] : ++other;
  EXPECT_GT(count[0], 0u);
  EXPECT_GT(count[1], 0u);
  EXPECT_EQ(other, 0u) << "faces with a solid index other than 0 or 1";
  EXPECT_EQ(two_boxes().stats.solids.size(), 2u);
}

TEST(MultiSolid, EachSolidsFacesLieNearItsOwnBoxAxis) {
  // Tolerance h for a box (support/exact_cases.h: h / (1 - max n_i.n_j), boxes have n_i.n_j <= 0).
  const MedialMesh& m = two_boxes().mesh;
  const ConvexPolytope a = box_polytope(10, 8, 6), b = box_b();
  const PolytopeMedialAxis axis[2] = {PolytopeMedialAxis(a), PolytopeMedialAxis(b)};
  std::vector<double> d[2];
  std::vector<Vec3> at[2];
  for (std::size_t f = 0; f < m.num_faces(); ++f) {
    const int s = m.solid[f];
    if (s != 0 && s != 1) continue;
    for (int k = 0; k < m.face_size(f); ++k) {
      const Vec3& v = m.vertices[m.face(f)[k]];
      d[s].push_back(axis[s].distance(v));
      at[s].push_back(v);
    }
  }
  for (int s = 0; s < 2; ++s) {
    const Summary sum = summarize(d[s], at[s], kSpacing);
    EXPECT_LE(sum.max, kSpacing) << "solid " << s << ": vertex to its own box's axis " << sum.str();
  }
}

}  // namespace
}  // namespace cadmedial::test
