// Small helpers of the shared plain-data types.
#include "types.h"

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

}  // namespace cadmedial
