// Feature classification from the exact B-rep (4.1.1, 4.2.1): convex / concave / smooth edges and
// non-concave corners, decided from the faces' true normals, never from a tessellation.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include <BRepAdaptor_Surface.hxx>
#include <Geom2d_Curve.hxx>
#include <Geom_Curve.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Solid.hxx>
#include <gp_Pnt.hxx>
#include <gp_Pnt2d.hxx>
#include <gp_Vec.hxx>

namespace cadmedial {

/// Character of an edge along its length.
enum class EdgeKind : std::uint8_t {
  Smooth = 0,      ///< tangent-continuous everywhere (e.g. a fillet's boundary)
  Convex = 1,      ///< sharp and convex everywhere: the inner medial axis reaches it
  Concave = 2,     ///< sharp and concave everywhere
  Mixed = 3,       ///< changes character along its length; sampling decides per point
  Seam = 4,        ///< seam of a periodic face (same face on both sides): not a feature
  Degenerate = 5,  ///< zero-length edge (cone apex, sphere pole): not a feature
};

const char* edge_kind_name(EdgeKind kind);

/// Local character at one point of an edge.
enum class PointKind : std::uint8_t { Smooth = 0, Convex = 1, Concave = 2 };

/// The exact geometry of an edge and its two faces at one edge parameter.
struct EdgePoint {
  gp_Pnt point;
  gp_Vec tangent;            ///< unit, along the edge's own parameter
  gp_Vec normal[2];          ///< unit outward normals of the two faces
  gp_Vec inward[2];          ///< unit, in face i's tangent plane, perpendicular to the edge, into face i
  gp_Pnt2d uv[2];            ///< the point in each face's parameter domain
  PointKind kind = PointKind::Smooth;
  double dihedral_deg = 180.0;  ///< interior angle between the faces (180 = smooth)
};

class EdgeGeometry;

/// The indexed topology of a solid and the character of its edges and vertices.
/// Index i of a vector is index i+1 of the matching OpenCASCADE map.
struct Features {
  TopTools_IndexedMapOfShape faces, edges, vertices;
  std::vector<EdgeKind> edge_kind;                  ///< #edges
  std::vector<std::array<int, 2>> edge_faces;       ///< #edges: 0-based face indices (same for seams)
  std::vector<bool> nonconcave_corner;              ///< #vertices: the inner medial axis reaches it
  std::vector<bool> sharp_vertex;                   ///< #vertices: on a sharp edge or a singular point
  double smooth_angle_deg = 1.0;                    ///< normals closer than this count as smooth
  /// #faces: BRepTools::UVBounds as (u0, u1, v0, v1), NaN where it failed. Found once: on a plane
  /// without curves on it, every call projects every edge of the face again.
  std::vector<std::array<double, 4>> face_uv_bounds;
  /// #edges: each edge's geometry, made once for the classification and the sampling (null on
  /// degenerate edges and where it could not be made). Not for use on two threads at once.
  std::vector<std::shared_ptr<const EdgeGeometry>> edge_geometry;
};

/// Face fi's (0-based) parameter bounds (u0, u1, v0, v1): the classification's, or
/// BRepTools::UVBounds now where it has none (it throws where it failed then too).
std::array<double, 4> uv_bounds_of(const Features& features, int fi);

/// Classifies every edge from normals at several points along it (ends and interior), and every
/// vertex: a vertex is a non-concave corner when the inner medial axis reaches it, that is when
/// the solid's exterior near it does not fit in a half-space: it has an incident edge that is
/// convex at the vertex, or it is a singular point (cone apex) where the solid is locally convex.
Features classify_features(const TopoDS_Solid& solid, double smooth_angle_deg = 1.0);

/// The two faces of every convex or mixed edge.
std::vector<std::array<int, 2>> convex_face_pairs(const Features& features);

/// Geometry of edge `edge_index` (0-based) and its two faces at edge parameter t.
EdgePoint edge_point(const Features& features, int edge_index, double t);

/// edge_point at many parameters of one edge: its curve, pcurves, orientations in its faces and
/// the faces' surfaces are looked up once (the sampler asks at every edge sample).
class EdgeGeometry {
 public:
  EdgeGeometry(const Features& features, int edge_index);
  /// edge_point(features, edge_index, t); `inset` > 0 takes the normals that far inside the faces
  /// (a fraction of their parameter range), where a collapsed boundary has one.
  EdgePoint at(double t, double inset = 0.0) const;

 private:
  struct Side {
    TopAbs_Orientation in_face = TopAbs_FORWARD;  ///< the edge's orientation in the face's wires
    bool face_reversed = false;
    Handle(Geom2d_Curve) pcurve;
    std::shared_ptr<BRepAdaptor_Surface> surface;  ///< of the face taken FORWARD
    double uv_extent = 0.0;                        ///< larger side of its parameter box
  };
  double smooth_angle_deg_;
  Handle(Geom_Curve) curve_;
  Side side_[2];
};

}  // namespace cadmedial
