// MedialMesh::sort_canonically against the order it promises, computed here the plain way on one
// thread (sort the vertices by (position, radius), with repeated vertices in std::sort's order of
// their indices; renumber; rotate each polygon to its smallest vertex towards the smaller
// neighbour; sort the faces by (solid, corners, kind) and the edges): array for array, on random
// meshes that take its bucket path (one solid, spread-out x; a small mesh on one thread), its
// fallbacks (two solids; most vertices at one x), and with exactly repeated vertices.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <tuple>
#include <vector>

#include "core/types.h"
#include "support/same_mesh.h"

namespace cadmedial {
namespace {

struct Shape {
  int solids = 1;
  double plane_share = 0.0;  ///< vertices with x = 0
  double repeat_share = 0.0;  ///< vertices that copy an earlier one exactly
  int vertices = 30000, faces = 25000;
};

MedialMesh random_mesh(const Shape& shape, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> coord(-5.0, 5.0);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  MedialMesh m;
  const int nv = shape.vertices;
  for (int v = 0; v < nv; ++v) {
    if (v > 0 && unit(rng) < shape.repeat_share) {
      const int w = static_cast<int>(rng() % v);
      m.vertices.push_back(m.vertices[w]);
      m.radius.push_back(m.radius[w]);
      continue;
    }
    const double x = unit(rng) < shape.plane_share ? 0.0 : coord(rng);
    m.vertices.push_back({x, coord(rng), coord(rng)});
    m.radius.push_back(unit(rng));
  }
  for (int f = 0; f < shape.faces; ++f) {
    const int n = 3 + static_cast<int>(rng() % 4);
    std::vector<int> poly;
    while (static_cast<int>(poly.size()) < n) {
      const int v = static_cast<int>(rng() % nv);
      if (std::find(poly.begin(), poly.end(), v) == poly.end()) poly.push_back(v);
    }
    m.add_face(poly, static_cast<FaceKind>(rng() % 3), static_cast<int>(rng() % shape.solids));
  }
  for (int e = 0; e < shape.faces / 50; ++e) {
    m.edges.push_back({static_cast<int>(rng() % nv), static_cast<int>(rng() % nv)});
    m.edge_solid.push_back(static_cast<int>(rng() % shape.solids));
  }
  return m;
}

// Each face as its corners' (position, radius), kind and solid: what the file says, whatever
// the numbering.
using FaceText = std::tuple<int, std::vector<std::pair<Point3, double>>, FaceKind>;

std::vector<FaceText> face_texts(const MedialMesh& m) {
  std::vector<FaceText> out;
  for (std::size_t f = 0; f < m.num_faces(); ++f) {
    std::vector<std::pair<Point3, double>> corners;
    for (int k = 0; k < m.face_size(f); ++k) corners.push_back({m.vertices[m.face(f)[k]], m.radius[m.face(f)[k]]});
    out.emplace_back(m.solid[f], corners, m.kind[f]);
  }
  return out;
}

// The canonical order, plainly.
MedialMesh plain_canonical(const MedialMesh& given) {
  MedialMesh m = given;
  const std::size_t nv = m.num_vertices();
  auto less = [&](int a, int b) {
    const Point3 &x = given.vertices[a], &y = given.vertices[b];
    return x < y || (x == y && given.radius[a] < given.radius[b]);
  };
  std::vector<int> order(nv);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), less);
  std::vector<int> new_index(nv);
  for (std::size_t i = 0; i < nv; ++i) {
    new_index[order[i]] = static_cast<int>(i);
    m.vertices[i] = given.vertices[order[i]];
    m.radius[i] = given.radius[order[i]];
  }
  std::vector<std::tuple<int, std::vector<int>, FaceKind>> faces;
  for (std::size_t f = 0; f < given.num_faces(); ++f) {
    std::vector<int> p;
    for (int k = 0; k < given.face_size(f); ++k) p.push_back(new_index[given.face(f)[k]]);
    std::rotate(p.begin(), std::min_element(p.begin(), p.end()), p.end());
    if (p.size() > 2 && p.back() < p[1]) std::reverse(p.begin() + 1, p.end());
    faces.emplace_back(given.solid[f], p, given.kind[f]);
  }
  std::sort(faces.begin(), faces.end());
  m.face_vertices.clear();
  m.face_start.assign(1, 0);
  m.kind.clear();
  m.solid.clear();
  for (const auto& [solid, p, kind] : faces) m.add_face(p, kind, solid);
  std::vector<std::array<int, 3>> segs;
  for (std::size_t e = 0; e < given.edges.size(); ++e) {
    const int a = new_index[given.edges[e][0]], b = new_index[given.edges[e][1]];
    segs.push_back({given.edge_solid[e], std::min(a, b), std::max(a, b)});
  }
  std::sort(segs.begin(), segs.end());
  for (std::size_t e = 0; e < segs.size(); ++e) m.edges[e] = {segs[e][1], segs[e][2]}, m.edge_solid[e] = segs[e][0];
  return m;
}

void expect_canonical(const MedialMesh& sorted, const MedialMesh& given) {
  test::expect_same_mesh(sorted, plain_canonical(given));
  // Vertices by (position, radius).
  for (std::size_t v = 1; v < sorted.num_vertices(); ++v) {
    const auto a = std::tie(sorted.vertices[v - 1], sorted.radius[v - 1]);
    const auto b = std::tie(sorted.vertices[v], sorted.radius[v]);
    ASSERT_FALSE(b < a) << "vertex " << v;
  }
  // Each polygon from its smallest vertex, towards the smaller neighbour; faces sorted.
  for (std::size_t f = 0; f < sorted.num_faces(); ++f) {
    const int* p = sorted.face(f);
    const int n = sorted.face_size(f);
    for (int k = 1; k < n; ++k) ASSERT_LT(p[0], p[k]) << "face " << f;
    ASSERT_LT(p[1], p[n - 1]) << "face " << f;
    if (f == 0) continue;
    const int* q = sorted.face(f - 1);
    const auto key = [&](std::size_t g, const int* c) {
      return std::make_tuple(sorted.solid[g], std::vector<int>(c, c + sorted.face_size(g)), sorted.kind[g]);
    };
    ASSERT_FALSE(key(f, p) < key(f - 1, q)) << "faces not sorted at " << f;
  }
  // The same faces as before, corner for corner (up to where each polygon starts and its turn).
  auto canon = [](std::vector<FaceText> faces) {
    for (auto& [solid, corners, kind] : faces) {
      std::rotate(corners.begin(), std::min_element(corners.begin(), corners.end()), corners.end());
      if (corners.size() > 2 && corners.back() < corners[1]) std::reverse(corners.begin() + 1, corners.end());
    }
    std::sort(faces.begin(), faces.end());
    return faces;
  };
  EXPECT_EQ(canon(face_texts(sorted)), canon(face_texts(given)));
  std::vector<std::pair<Point3, double>> a, b;
  for (std::size_t v = 0; v < sorted.num_vertices(); ++v) a.push_back({sorted.vertices[v], sorted.radius[v]});
  for (std::size_t v = 0; v < given.num_vertices(); ++v) b.push_back({given.vertices[v], given.radius[v]});
  std::sort(b.begin(), b.end());
  EXPECT_EQ(a, b);
}

TEST(CanonicalOrder, OneSolidSpreadOut) {
  const MedialMesh given = random_mesh({}, 1);
  MedialMesh m = given;
  m.sort_canonically();
  expect_canonical(m, given);
}

TEST(CanonicalOrder, SmallMeshOnOneThread) {
  const MedialMesh given = random_mesh({1, 0.0, 0.0, 900, 700}, 5);
  MedialMesh m = given;
  m.sort_canonically();
  expect_canonical(m, given);
}

TEST(CanonicalOrder, TwoSolids) {
  const MedialMesh given = random_mesh({2, 0.0, 0.0}, 2);
  MedialMesh m = given;
  m.sort_canonically();
  expect_canonical(m, given);
}

TEST(CanonicalOrder, MostVerticesInOnePlane) {
  const MedialMesh given = random_mesh({1, 0.6, 0.0}, 3);
  MedialMesh m = given;
  m.sort_canonically();
  expect_canonical(m, given);
}

TEST(CanonicalOrder, RepeatedVerticesAndTheSameAnswerTwice) {
  const MedialMesh given = random_mesh({1, 0.0, 0.05}, 4);
  MedialMesh m = given, again = given;
  m.sort_canonically();
  expect_canonical(m, given);
  again.sort_canonically();
  test::expect_same_mesh(m, again);
}

}  // namespace
}  // namespace cadmedial
