// MedialMesh::sort_canonically against the order it promises, computed here the plain way (sort
// the vertices by (position, radius), renumber, rotate each polygon to its smallest vertex towards
// the smaller neighbour, sort the faces by (solid, corners, kind)): on random meshes that take its
// bucket path (one solid, spread-out x), its fallbacks (two solids; most vertices at one x), and
// with exactly repeated vertices.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <tuple>
#include <vector>

#include "core/types.h"

namespace cadmedial {
namespace {

struct Shape {
  int solids = 1;
  double plane_share = 0.0;  ///< vertices with x = 0
  double repeat_share = 0.0;  ///< vertices that copy an earlier one exactly
};

MedialMesh random_mesh(const Shape& shape, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> coord(-5.0, 5.0);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  MedialMesh m;
  const int nv = 30000;
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
  for (int f = 0; f < 25000; ++f) {
    const int n = 3 + static_cast<int>(rng() % 4);
    std::vector<int> poly;
    while (static_cast<int>(poly.size()) < n) {
      const int v = static_cast<int>(rng() % nv);
      if (std::find(poly.begin(), poly.end(), v) == poly.end()) poly.push_back(v);
    }
    m.add_face(poly, static_cast<FaceKind>(rng() % 3), static_cast<int>(rng() % shape.solids));
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

void expect_canonical(const MedialMesh& sorted, const MedialMesh& given) {
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
  EXPECT_EQ(m.vertices, again.vertices);
  EXPECT_EQ(m.face_vertices, again.face_vertices);
  EXPECT_EQ(m.face_start, again.face_start);
}

}  // namespace
}  // namespace cadmedial
