// simplify_axis: the compact mesh keeps the topology and the structure of the full one, and every
// ball of the full mesh stays within the tolerance of the compact mesh (checked here by brute
// force over the compact triangles, not by the simplifier's own bookkeeping).
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include <gtest/gtest.h>

#include "core/compact/ball_distance.h"
#include "core/compact/simplify_axis.h"
#include "support/engine_run.h"
#include "support/mesh_measures.h"
#include "support/polytope_medial_axis.h"
#include "support/random.h"
#include "support/solids.h"

namespace cadmedial::test {
namespace {

// A grid of n x n vertices over [0, 1]^2 (with holes where `hole` says), z and radius from f.
template <class Z, class Hole>
MedialMesh grid_sheet(int n, Z z_and_r, Hole hole) {
  MedialMesh m;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double x = i / double(n - 1), y = j / double(n - 1);
      const auto [z, r] = z_and_r(x, y);
      m.vertices.push_back({x, y, z});
      m.radius.push_back(r);
    }
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      if (hole((i + 0.5) / (n - 1), (j + 0.5) / (n - 1))) continue;
      const int a = j * n + i;
      m.add_face({a, a + 1, a + n + 1, a + n}, FaceKind::Voronoi, 0);
    }
  return m;
}

// The largest |dc| + |dr| from a ball of `full` to the compact mesh, over all its triangles.
double worst_ball_error(const MedialMesh& full, const MedialMesh& compact) {
  double worst = 0;
  std::vector<char> used(full.num_vertices(), 0);
  for (int v : full.face_vertices) used[static_cast<std::size_t>(v)] = 1;
  for (const auto& e : full.edges) used[static_cast<std::size_t>(e[0])] = used[static_cast<std::size_t>(e[1])] = 1;
  for (std::size_t v = 0; v < full.num_vertices(); ++v) {
    if (!used[v]) continue;
    const compact::Ball p{full.vertices[v], full.radius[v]};
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t f = 0; f < compact.num_faces(); ++f) {
      const int* c = compact.face(f);
      const auto b = [&](int k) { return compact::Ball{compact.vertices[c[k]], compact.radius[c[k]]}; };
      best = std::min(best, compact::ball_to_triangle(p, b(0), b(1), b(2)));
    }
    for (const auto& e : compact.edges)
      best = std::min(best, compact::ball_to_segment(p, {compact.vertices[e[0]], compact.radius[e[0]]},
                                                     {compact.vertices[e[1]], compact.radius[e[1]]}));
    worst = std::max(worst, best);
  }
  return worst;
}

// Sides of the polygons held by other than two polygons (borders and seams), by their count.
std::map<int, int> feature_sides(const MedialMesh& m) {
  std::map<std::pair<int, int>, int> count;
  for (std::size_t f = 0; f < m.num_faces(); ++f) {
    const int* c = m.face(f);
    const int n = m.face_size(f);
    for (int k = 0; k < n; ++k) ++count[{std::min(c[k], c[(k + 1) % n]), std::max(c[k], c[(k + 1) % n])}];
  }
  std::map<int, int> by_count;
  for (const auto& [side, k] : count)
    if (k != 2) ++by_count[k];
  return by_count;
}

TEST(SimplifyAxis, FlatSheetBecomesItsCornersAndKeepsEveryBall) {
  Random rng(3);
  std::vector<double> noise;
  for (int k = 0; k < 41 * 41; ++k) noise.push_back(rng.uniform(-1e-4, 1e-4));
  int k = 0;
  const MedialMesh full = grid_sheet(41, [&](double x, double) { return std::pair{noise[k++], 0.2 + 0.1 * x}; },
                                     [](double, double) { return false; });
  SimplifyStats st;
  const MedialMesh compact = simplify_axis(full, 1e-3, &st);
  // The square's 4 corners are junctions of its border (the sides beside them turn 90 degrees,
  // farther than the tolerance): 2 triangles. A linear radius interpolates exactly.
  EXPECT_EQ(compact.num_faces(), 2u);
  EXPECT_EQ(compact.num_vertices(), 4u);
  EXPECT_LE(worst_ball_error(full, compact), 1e-3);
  EXPECT_LE(st.max_error, 1e-3);
  EXPECT_EQ(st.euler_after, 1);
  EXPECT_EQ(st.euler_before, 1);
}

TEST(SimplifyAxis, RadiusBumpsBeyondTheToleranceStay) {
  // A radius bump of 0.05 in the middle: the compact mesh must keep vertices there.
  const auto bump = [](double x, double y) {
    const double d2 = (x - 0.5) * (x - 0.5) + (y - 0.5) * (y - 0.5);
    return std::pair{0.0, 0.3 + 0.05 * std::exp(-d2 / 0.01)};
  };
  const MedialMesh full = grid_sheet(41, bump, [](double, double) { return false; });
  for (double tol : {1e-2, 3e-3, 1e-3}) {
    SimplifyStats st;
    const MedialMesh compact = simplify_axis(full, tol, &st);
    EXPECT_GT(compact.num_faces(), 2u) << tol;
    EXPECT_LE(worst_ball_error(full, compact), tol * (1 + 1e-9)) << tol;
    EXPECT_LT(compact.num_faces(), full.num_faces()) << tol;
  }
}

TEST(SimplifyAxis, HolesKeepTheEulerCharacteristic) {
  // Three square holes: Euler 1 - 3 = -2, and each hole's border stays a loop.
  const auto holes = [](double x, double y) {
    for (double cx : {0.2, 0.5, 0.8})
      if (std::abs(x - cx) < 0.06 && std::abs(y - 0.5) < 0.06) return true;
    return false;
  };
  const MedialMesh full = grid_sheet(51, [](double x, double y) { return std::pair{0.0, 0.1}; }, holes);
  const double scale = mesh_bbox_diagonal(full);
  ASSERT_EQ(euler_characteristic(full, scale, 0), -2);
  const MedialMesh compact = simplify_axis(full, 1e-3);
  EXPECT_EQ(euler_characteristic(compact, scale, 0), -2);
  EXPECT_EQ(connected_pieces(compact, scale), 1);
  EXPECT_LT(compact.num_faces(), full.num_faces() / 10);
  EXPECT_LE(worst_ball_error(full, compact), 1e-3);
}

TEST(SimplifyAxis, ThreeSheetsKeepTheirSeam) {
  // Three half-planes meeting along the y axis (a Y in x-z), each a grid: the seam's sides are
  // held by three triangles, before and after; its two ends are junctions and stay.
  MedialMesh full;
  const int n = 21;
  std::vector<int> seam(n);
  for (int j = 0; j < n; ++j) {
    seam[j] = static_cast<int>(full.vertices.size());
    full.vertices.push_back({0, j / double(n - 1), 0});
    full.radius.push_back(0.5);
  }
  for (double angle : {0.0, 2.0, 4.0}) {
    std::vector<int> prev = seam;
    for (int i = 1; i < n; ++i) {
      std::vector<int> row(n);
      for (int j = 0; j < n; ++j) {
        row[j] = static_cast<int>(full.vertices.size());
        const double s = i / double(n - 1);
        full.vertices.push_back({s * std::cos(angle), j / double(n - 1), s * std::sin(angle)});
        full.radius.push_back(0.5 - 0.3 * s);
      }
      for (int j = 0; j + 1 < n; ++j) full.add_face({prev[j], prev[j + 1], row[j + 1], row[j]}, FaceKind::Voronoi, 0);
      prev = row;
    }
  }
  ASSERT_EQ(feature_sides(full)[3], n - 1);
  const MedialMesh compact = simplify_axis(full, 1e-3);
  const auto sides = feature_sides(compact);
  ASSERT_TRUE(sides.count(3));
  EXPECT_GE(sides.at(3), 1);
  EXPECT_EQ(compact.num_faces(), 6u);  // each planar sheet: a rectangle, 2 triangles
  EXPECT_LE(worst_ball_error(full, compact), 1e-3);
  const double scale = mesh_bbox_diagonal(full);
  EXPECT_EQ(euler_characteristic(compact, scale), euler_characteristic(full, scale));
}

TEST(SimplifyAxis, BareChainsThinToTheirBends) {
  MedialMesh full;
  // An L of 1-D edges: 11 points along x then 11 along y; radius constant.
  for (int k = 0; k <= 20; ++k) {
    full.vertices.push_back(k <= 10 ? Point3{k * 0.1, 0, 0} : Point3{1, (k - 10) * 0.1, 0});
    full.radius.push_back(0.05);
    if (k > 0) full.edges.push_back({k - 1, k}), full.edge_solid.push_back(0);
  }
  SimplifyStats st;
  const MedialMesh compact = simplify_axis(full, 1e-3, &st);
  EXPECT_EQ(compact.num_edges(), 2u);
  EXPECT_EQ(compact.num_vertices(), 3u);
  EXPECT_LE(worst_ball_error(full, compact), 1e-3);
}

TEST(SimplifyAxis, BoxAxisKeepsTopologyAndExactness) {
  // The engine's axis of a 40 x 25 x 15 box, compacted at 0.1 % and 1 % of its diagonal.
  const ComputeResult& r = medial_axis_of("box40", [] { return make_box(40, 25, 15); }, 1.0);
  const MedialMesh& full = r.mesh;
  const double diag = std::sqrt(40.0 * 40 + 25 * 25 + 15 * 15);
  const PolytopeMedialAxis exact(box_polytope(40, 25, 15));
  double full_off = 0;
  for (const Point3& p : full.vertices) full_off = std::max(full_off, exact.distance(p));
  const MeshDistance to_full(full, diag);
  for (double share : {1e-3, 1e-2}) {
    const double tol = share * diag;
    SimplifyStats st;
    const MedialMesh compact = simplify_axis(full, tol, &st);
    EXPECT_EQ(euler_characteristic(compact, diag), euler_characteristic(full, diag)) << share;
    EXPECT_EQ(connected_pieces(compact, diag), connected_pieces(full, diag)) << share;
    EXPECT_EQ(st.euler_after, st.euler_before);
    EXPECT_LE(st.max_error, tol);
    EXPECT_LT(compact.num_faces(), full.num_faces()) << share;
    // Every vertex of the full mesh within the tolerance of the compact one (centres, exact
    // distance), and the compact one within it of the full one: the simplifier checks the
    // latter on a lattice of half a median side, so between its points it may exceed it (by 13 %
    // here at 0.1 %).
    const MeshDistance to_compact(compact, diag);
    double worst_full = 0, worst_compact = 0, compact_off = 0;
    for (const Point3& p : full.vertices) worst_full = std::max(worst_full, to_compact.distance(p));
    for (std::size_t f = 0; f < compact.num_faces(); ++f) {
      const int* c = compact.face(f);
      for (double a = 0; a <= 1; a += 0.0625)
        for (double b = 0; a + b <= 1; b += 0.0625) {
          const double w = 1 - a - b;
          Point3 q;
          for (int k = 0; k < 3; ++k)
            q[k] = a * compact.vertices[c[0]][k] + b * compact.vertices[c[1]][k] + w * compact.vertices[c[2]][k];
          worst_compact = std::max(worst_compact, to_full.distance(q));
          compact_off = std::max(compact_off, exact.distance(q));
        }
    }
    EXPECT_LE(worst_full, tol) << share;
    EXPECT_LE(worst_compact, 1.5 * tol) << share;
    // Against the exact axis: no farther from it than the full mesh plus the tolerance.
    EXPECT_LE(compact_off, full_off + 1.5 * tol) << share;
    // At 1 %: the box's 13 planar sheets in a few dozen triangles.
    if (share == 1e-2) EXPECT_LE(compact.num_faces(), 60u);
  }
}

}  // namespace
}  // namespace cadmedial::test
