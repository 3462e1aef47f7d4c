// Small helpers of the shared plain-data types.
#include "types.h"

#include <algorithm>
#include <numeric>
#include <tuple>

namespace cadmedial {

const char* face_kind_name(FaceKind kind) {
  switch (kind) {
    case FaceKind::Voronoi: return "voronoi";
    case FaceKind::Edge: return "edge";
    case FaceKind::Corner: return "corner";
  }
  return "unknown";
}

std::size_t MedialMesh::add_face(const std::vector<int>& polygon, FaceKind face_kind, int solid_index) {
  face_vertices.insert(face_vertices.end(), polygon.begin(), polygon.end());
  face_start.push_back(static_cast<int>(face_vertices.size()));
  kind.push_back(face_kind);
  solid.push_back(solid_index);
  return kind.size() - 1;
}

void MedialMesh::append(const MedialMesh& other) {
  const int offset = static_cast<int>(vertices.size());
  vertices.insert(vertices.end(), other.vertices.begin(), other.vertices.end());
  radius.insert(radius.end(), other.radius.begin(), other.radius.end());
  // Offsets of the other mesh's polygons shift by what we already hold; a default-constructed
  // mesh has face_start == {0}, so both sides always start at 0.
  const int base = face_start.empty() ? 0 : face_start.back();
  if (face_start.empty()) face_start.push_back(0);
  for (std::size_t f = 1; f < other.face_start.size(); ++f) face_start.push_back(base + other.face_start[f]);
  face_vertices.reserve(face_vertices.size() + other.face_vertices.size());
  for (int v : other.face_vertices) face_vertices.push_back(v + offset);
  kind.insert(kind.end(), other.kind.begin(), other.kind.end());
  solid.insert(solid.end(), other.solid.begin(), other.solid.end());
  for (const auto& e : other.edges) edges.push_back({e[0] + offset, e[1] + offset});
  edge_solid.insert(edge_solid.end(), other.edge_solid.begin(), other.edge_solid.end());
}

void MedialMesh::sort_canonically() {
  const std::size_t nv = vertices.size();
  std::vector<int> order(nv);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    return vertices[a] < vertices[b] || (vertices[a] == vertices[b] && radius[a] < radius[b]);
  });
  std::vector<int> new_index(nv);
  for (std::size_t i = 0; i < nv; ++i) new_index[order[i]] = static_cast<int>(i);
  std::vector<Point3> v2(nv);
  std::vector<double> r2(nv);
  for (std::size_t i = 0; i < nv; ++i) v2[i] = vertices[order[i]], r2[i] = radius[order[i]];
  vertices.swap(v2);
  radius.swap(r2);

  struct Poly {
    std::vector<int> corners;
    FaceKind kind;
    int solid;
  };
  std::vector<Poly> polys(num_faces());
  for (std::size_t f = 0; f < num_faces(); ++f) {
    auto& p = polys[f];
    for (int k = face_start[f]; k < face_start[f + 1]; ++k) p.corners.push_back(new_index[face_vertices[k]]);
    std::rotate(p.corners.begin(), std::min_element(p.corners.begin(), p.corners.end()), p.corners.end());
    // Polygons are not oriented (the triangulation's circulators run either way): walk towards
    // the smaller neighbour.
    if (p.corners.size() > 2 && p.corners.back() < p.corners[1]) std::reverse(p.corners.begin() + 1, p.corners.end());
    p.kind = kind[f];
    p.solid = solid[f];
  }
  std::sort(polys.begin(), polys.end(), [](const Poly& a, const Poly& b) {
    return std::tie(a.solid, a.corners, a.kind) < std::tie(b.solid, b.corners, b.kind);
  });
  face_start.assign(1, 0);
  face_vertices.clear();
  kind.clear();
  solid.clear();
  for (const auto& p : polys) add_face(p.corners, p.kind, p.solid);

  std::vector<std::array<int, 3>> segs(edges.size());
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const int a = new_index[edges[e][0]], b = new_index[edges[e][1]];
    segs[e] = {edge_solid[e], std::min(a, b), std::max(a, b)};
  }
  std::sort(segs.begin(), segs.end());
  for (std::size_t e = 0; e < segs.size(); ++e) edges[e] = {segs[e][1], segs[e][2]}, edge_solid[e] = segs[e][0];
}

}  // namespace cadmedial
