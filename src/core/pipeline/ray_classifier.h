// A point inside or outside a solid from the first boundary crossing along a ray, for the points
// the medial stage cannot settle from its samples.
#pragma once

#include <array>
#include <memory>
#include <utility>
#include <vector>

#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Solid.hxx>

class BRepTopAdaptor_FClass2d;
class IntCurvesFace_Intersector;

namespace cadmedial {
class LatticeClassifier;
}

namespace cadmedial::internal {

/// Casts rays from the point and reads the first face crossing on each: a ray that leaves the
/// solid there started inside. OpenCASCADE's BRepClass3d_SolidClassifier decides the same way, but
/// each of its calls maps every edge of the solid to its faces and looks for a ray through a point
/// inside some face: 2 to 6 ms a point on parts of a few hundred faces. Here the faces' boxes and
/// intersectors are kept between points. A ray is refused (another direction is tried) when its
/// first crossing is not clean: near a face's boundary, tangent, or beside a crossing that says the
/// opposite. The intersectors find crossings without the faces' boundary tolerances (with them,
/// OpenCASCADE builds a new face classifier for every crossing just beyond a face); the deciding
/// crossing is then checked against the face's boundary with a margin.
/// One instance per thread: it keeps state between calls.
class RayClassifier {
 public:
  /// `tol`: a point this close to a face is on the boundary (inside).
  RayClassifier(const TopoDS_Solid& solid, double tol);
  ~RayClassifier();
  RayClassifier(const RayClassifier&) = delete;
  RayClassifier& operator=(const RayClassifier&) = delete;

  enum class Answer { Outside, Inside, Unknown };
  /// On an edge or a vertex (within its tolerance) is inside. Otherwise two clean rays that agree
  /// decide; Unknown when two disagree, fewer than two of the directions tried are clean, or
  /// OpenCASCADE fails on a face or an edge.
  Answer classify(const std::array<double, 3>& p);

 private:
  Answer cast(const std::array<double, 3>& p, const std::array<double, 3>& d);
  /// Within its tolerance (or tol) of an edge or a vertex, which OpenCASCADE's classifier also
  /// asks first.
  bool on_edge(const std::array<double, 3>& p) const;
  IntCurvesFace_Intersector& intersector(int face);
  /// Whether (u, v) on the face is within the margin of its boundary.
  bool near_boundary(int face, double u, double v);

  std::vector<TopoDS_Face> faces_;
  std::vector<std::array<double, 6>> boxes_;  ///< per face: min x y z, max x y z (enlarged)
  std::vector<TopoDS_Edge> edges_;
  std::vector<std::array<double, 6>> edge_boxes_;  ///< with the edge's tolerance
  std::vector<std::unique_ptr<IntCurvesFace_Intersector>> intersectors_;  ///< made on first use
  std::vector<std::unique_ptr<BRepTopAdaptor_FClass2d>> boundaries_;      ///< made on first use
  /// Their answers without Perform's scans of every polygon edge (with them)
  std::vector<std::unique_ptr<LatticeClassifier>> boundary_answers_;
  double tol_;
  double margin_;  ///< crossings closer than this along a ray are one
  double reach_;   ///< longer than any ray needs
  std::vector<std::pair<double, int>> order_;  ///< reused: boxes hit by a ray, nearest first
};

}  // namespace cadmedial::internal
