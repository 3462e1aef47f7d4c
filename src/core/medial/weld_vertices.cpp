#include "weld_vertices.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <set>
#include <utility>
#include <vector>

namespace cadmedial {

namespace {

int find_root(std::vector<int>& parent, int x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}

}  // namespace

WeldStats weld_vertices(MedialMesh& mesh, double eps) {
  WeldStats st;
  const int nv = static_cast<int>(mesh.num_vertices());
  if (nv == 0 || !(eps > 0)) return st;
  // Along the mesh's own sides and edges only: two ends of a side shorter than eps are one point
  // (a degenerate Voronoi vertex split over several cells). Two vertices that no short chain of
  // sides joins are different points of the axis, however close: merging them would pinch it.
  std::vector<int> parent(static_cast<std::size_t>(nv));
  std::iota(parent.begin(), parent.end(), 0);
  const double eps2 = eps * eps;
  auto join_if_short = [&](int a, int b) {
    const Point3 &p = mesh.vertices[a], &q = mesh.vertices[b];
    const double d2 = (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]);
    if (d2 > eps2) return;
    const int ra = find_root(parent, a), rb = find_root(parent, b);
    if (ra != rb) parent[std::max(ra, rb)] = std::min(ra, rb);
  };
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
    const int* c = mesh.face(f);
    const int n = mesh.face_size(f);
    for (int k = 0; k < n; ++k) join_if_short(c[k], c[(k + 1) % n]);
  }
  for (const auto& e : mesh.edges) join_if_short(e[0], e[1]);
  std::vector<int> root(static_cast<std::size_t>(nv));
  bool any = false;
  for (int v = 0; v < nv; ++v) {
    root[v] = find_root(parent, v);
    if (root[v] != v) {
      any = true;
      ++st.merged_vertices;
      mesh.radius[root[v]] = std::min(mesh.radius[root[v]], mesh.radius[v]);
    }
  }
  if (!any) return st;

  MedialMesh out;
  out.vertices = mesh.vertices;
  out.radius = mesh.radius;
  // Faces: consecutive repeats removed (a polygon that loops back through a vertex stays).
  std::set<std::vector<int>> seen_faces;
  std::set<std::pair<int, int>> sides;
  std::vector<std::array<int, 2>> collapsed_sides;
  std::vector<int> collapsed_side_solid;
  std::vector<int> collapsed_points;
  std::vector<int> poly;
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
    poly.clear();
    for (int k = 0; k < mesh.face_size(f); ++k) {
      const int v = root[mesh.face(f)[k]];
      if (poly.empty() || poly.back() != v) poly.push_back(v);
    }
    while (poly.size() > 1 && poly.front() == poly.back()) poly.pop_back();
    std::vector<int> key = poly;
    std::sort(key.begin(), key.end());
    const bool distinct = std::adjacent_find(key.begin(), key.end()) == key.end();
    if (poly.size() < 3 || !distinct || !seen_faces.insert(key).second) {
      ++st.dropped_faces;
      // What is left of a face that collapsed stays, as an edge or a point: contracting a short
      // side keeps the axis's topology, dropping the face would not (a sphere's axis, its centre,
      // is a cluster of Voronoi vertices that welds into one).
      if (poly.size() == 2) {
        collapsed_sides.push_back({poly[0], poly[1]});
        collapsed_side_solid.push_back(mesh.solid[f]);
      }
      if (poly.size() == 1) collapsed_points.push_back(poly[0]);
      continue;
    }
    out.add_face(poly, mesh.kind[f], mesh.solid[f]);
    for (std::size_t k = 0; k < poly.size(); ++k) {
      const int a = poly[k], b = poly[(k + 1) % poly.size()];
      sides.insert({std::min(a, b), std::max(a, b)});
    }
  }
  std::set<std::pair<int, int>> seen_edges;
  for (std::size_t e = 0; e < mesh.num_edges(); ++e) {
    const int a = root[mesh.edges[e][0]], b = root[mesh.edges[e][1]];
    const std::pair<int, int> key{std::min(a, b), std::max(a, b)};
    if (a == b || sides.count(key) || !seen_edges.insert(key).second) {
      ++st.dropped_edges;
      continue;
    }
    out.edges.push_back({a, b});
    out.edge_solid.push_back(mesh.edge_solid[e]);
  }
  for (std::size_t k = 0; k < collapsed_sides.size(); ++k) {
    const int a = collapsed_sides[k][0], b = collapsed_sides[k][1];
    const std::pair<int, int> key{std::min(a, b), std::max(a, b)};
    if (sides.count(key) || !seen_edges.insert(key).second) continue;
    out.edges.push_back({a, b});
    out.edge_solid.push_back(collapsed_side_solid[k]);
  }
  // Vertices no face or edge uses go (the merged ones, and any a dropped face alone held).
  std::vector<int> used(static_cast<std::size_t>(nv), -1);
  std::vector<char> held(static_cast<std::size_t>(nv), 0);  // by a face or an edge, before
  for (int v : mesh.face_vertices) held[v] = 1;
  for (const auto& e : mesh.edges) held[e[0]] = held[e[1]] = 1;
  for (int v : out.face_vertices) used[v] = 0;
  for (const auto& e : out.edges) used[e[0]] = used[e[1]] = 0;
  for (int v : collapsed_points) used[v] = 0;
  MedialMesh packed;
  for (int v = 0; v < nv; ++v) {
    // A vertex on its own before (no face, no edge) stays, as the mesh had it.
    if (used[v] < 0 && (held[v] || root[v] != v)) continue;
    used[v] = static_cast<int>(packed.vertices.size());
    packed.vertices.push_back(out.vertices[v]);
    packed.radius.push_back(out.radius[v]);
  }
  packed.face_start = std::move(out.face_start);
  packed.face_vertices = std::move(out.face_vertices);
  for (int& v : packed.face_vertices) v = used[v];
  packed.kind = std::move(out.kind);
  packed.solid = std::move(out.solid);
  packed.edges = std::move(out.edges);
  for (auto& e : packed.edges) e = {used[e[0]], used[e[1]]};
  packed.edge_solid = std::move(out.edge_solid);
  mesh = std::move(packed);
  return st;
}

}  // namespace cadmedial
