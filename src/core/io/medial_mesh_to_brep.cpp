// The medial mesh as a compound of planar faces and straight edges (the mesh's 1-D edges),
// serialised as BREP text.
//
// Speed: vertices are made once per mesh vertex and edges once per mesh edge, and shared by
// every face that uses them; sharing also makes the compound connected, as FreeCAD expects of a
// surface. Faces are built directly on the polygon's own plane (Newell normal through the
// centroid) with BRep_Builder: BRepBuilderAPI_MakeFace(wire, OnlyPlane) found the same plane by
// least squares at about 160 us per polygon, five times the cost of everything else together
// (measured: 1e5 triangles, 16 s against 3.5 s for BRepTools::Write). Now BRepTools::Write is
// most of the time: about 6 s of 8 for the 58,000 Voronoi polygons of a box at spacing 0.25.
#include "medial_mesh_to_brep.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <unordered_map>

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <Geom_Plane.hxx>
#include <Precision.hxx>
#include <Standard_Failure.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Dir.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

#include "../errors.h"

namespace cadmedial {
namespace {

class Builder {
 public:
  explicit Builder(const MedialMesh& mesh) : mesh_(mesh), vertices_(mesh.num_vertices()) {
    builder_.MakeCompound(compound_);
  }

  const TopoDS_Vertex& vertex(int v) {
    TopoDS_Vertex& shape = vertices_[v];
    if (shape.IsNull()) shape = BRepBuilderAPI_MakeVertex(point(v));
    return shape;
  }

  // The edge from a to b, shared with every other polygon that has the edge {a, b}.
  TopoDS_Edge edge(int a, int b) {
    const bool flip = a > b;
    const std::uint64_t key = (static_cast<std::uint64_t>(flip ? b : a) << 32) | static_cast<std::uint32_t>(flip ? a : b);
    auto it = edges_.find(key);
    if (it == edges_.end()) {
      const int lo = flip ? b : a, hi = flip ? a : b;
      it = edges_.emplace(key, BRepBuilderAPI_MakeEdge(vertex(lo), vertex(hi)).Edge()).first;
    }
    return flip ? TopoDS::Edge(it->second.Reversed()) : it->second;
  }

  // Adds the planar face bounded by the closed loop `loop`, whose vector area (Newell) is
  // `normal`; false when a vertex lies off the plane by more than the vertices' tolerance.
  bool add_face(const std::vector<int>& loop, const gp_Vec& normal) {
    gp_XYZ centroid(0, 0, 0);
    for (int v : loop) centroid += point(v).XYZ();
    centroid /= static_cast<double>(loop.size());
    const gp_Dir n(normal);
    for (int v : loop)
      if (std::abs((point(v).XYZ() - centroid).Dot(n.XYZ())) > Precision::Confusion()) return false;

    TopoDS_Wire wire;
    builder_.MakeWire(wire);
    for (std::size_t i = 0; i < loop.size(); ++i) builder_.Add(wire, edge(loop[i], loop[(i + 1) % loop.size()]));
    wire.Closed(true);
    // The loop turns counter-clockwise around its Newell normal, so with the plane's normal along
    // it the loop is the face's outer boundary as it stands (material on the left).
    TopoDS_Face face;
    builder_.MakeFace(face, new Geom_Plane(gp_Pnt(centroid), n), Precision::Confusion());
    builder_.Add(face, wire);
    builder_.Add(compound_, face);
    return true;
  }

  // Adds the segment {a, b} as a free edge of the compound, unless a face added before already
  // has it as a side (it is in the compound through that face) or it is shorter than the
  // tolerance (no edge).
  void add_free_edge(int a, int b) {
    if (same_point(a, b)) return;
    const std::uint64_t key = (static_cast<std::uint64_t>(std::min(a, b)) << 32) | static_cast<std::uint32_t>(std::max(a, b));
    if (edges_.count(key)) return;
    builder_.Add(compound_, edge(a, b));
  }

  // Whether OpenCASCADE takes the two vertices for one point (no edge can join them).
  bool same_point(int a, int b) const { return point(a).Distance(point(b)) <= Precision::Confusion(); }

  gp_Pnt point(int v) const {
    const Point3& p = mesh_.vertices[v];
    return gp_Pnt(p[0], p[1], p[2]);
  }

  const TopoDS_Compound& compound() const { return compound_; }

 private:
  const MedialMesh& mesh_;
  BRep_Builder builder_;
  TopoDS_Compound compound_;
  std::vector<TopoDS_Vertex> vertices_;
  std::unordered_map<std::uint64_t, TopoDS_Edge> edges_;
};

// Twice the vector area of a polygon (Newell's formula); its norm is twice the area.
gp_Vec area_vector(const Builder& b, const std::vector<int>& loop) {
  gp_Vec n(0, 0, 0);
  const gp_Pnt o = b.point(loop[0]);
  for (std::size_t i = 1; i + 1 < loop.size(); ++i)
    n += gp_Vec(o, b.point(loop[i])).Crossed(gp_Vec(o, b.point(loop[i + 1])));
  return n;
}

}  // namespace

std::string medial_mesh_to_brep(const MedialMesh& mesh) {
  for (int v : mesh.face_vertices)
    if (v < 0 || static_cast<std::size_t>(v) >= mesh.num_vertices())
      throw InvalidInput("medial mesh: vertex index " + std::to_string(v) + " out of range");
  if (mesh.face_start.size() != mesh.num_faces() + 1)
    throw InvalidInput("medial mesh: face_start and kind disagree on the number of faces");
  for (const auto& e : mesh.edges)
    for (int v : e)
      if (v < 0 || static_cast<std::size_t>(v) >= mesh.num_vertices())
        throw InvalidInput("medial mesh: edge vertex index " + std::to_string(v) + " out of range");

  std::size_t f = 0;
  try {
    Builder b(mesh);
    std::vector<int> loop;
    for (; f < mesh.num_faces(); ++f) {
      // Drop repeated points (consecutive, and last == first): OpenCASCADE makes no edge between
      // points closer than its tolerance (BRepBuilderAPI_MakeEdge fails; axom's boxed_sphere had
      // three vertices of one polygon within 6e-14).
      loop.clear();
      const int* p = mesh.face(f);
      for (int i = 0; i < mesh.face_size(f); ++i)
        if (loop.empty() || !b.same_point(loop.back(), p[i])) loop.push_back(p[i]);
      while (loop.size() > 1 && b.same_point(loop.back(), loop.front())) loop.pop_back();
      if (loop.size() < 3) continue;

      // Zero area against the polygon's size: collinear points bound no face.
      double perimeter = 0.0;
      for (std::size_t i = 0; i < loop.size(); ++i) perimeter += b.point(loop[i]).Distance(b.point(loop[(i + 1) % loop.size()]));
      const gp_Vec normal = area_vector(b, loop);
      if (normal.Magnitude() <= 1e-12 * perimeter * perimeter) continue;

      if (b.add_face(loop, normal)) continue;
      // Not planar within tolerance (a Voronoi facet from a near-degenerate Delaunay cell): its fan
      // triangles are planar by construction and cover the same surface.
      for (std::size_t i = 1; i + 1 < loop.size(); ++i) {
        const std::vector<int> tri{loop[0], loop[i], loop[i + 1]};
        const gp_Vec tri_normal = area_vector(b, tri);
        if (tri_normal.Magnitude() > 1e-12 * perimeter * perimeter) b.add_face(tri, tri_normal);
      }
    }
    // After the faces, so that an edge that is also a face's side is not added twice.
    for (const auto& e : mesh.edges) b.add_free_edge(e[0], e[1]);
    std::ostringstream out;
    BRepTools::Write(b.compound(), out);
    return out.str();
  } catch (const Standard_Failure& e) {
    const char* m = e.GetMessageString();
    const std::string where = f < mesh.num_faces() ? "face " + std::to_string(f) : "an edge";
    throw GeometryError("medial mesh to BREP: " + where + ": " + e.DynamicType()->Name() +
                        (m && *m ? std::string(": ") + m : std::string()));
  }
}

}  // namespace cadmedial
