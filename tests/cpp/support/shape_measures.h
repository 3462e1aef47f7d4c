// Measures on OpenCASCADE solids: inside test, distance to the boundary, points on features.
#pragma once

#include <memory>
#include <vector>

#include <TopoDS_Shape.hxx>

#include "core/features/classify_features.h"
#include "core/features/solid_euler.h"
#include "support/vec3.h"

namespace cadmedial::test {

/// Inside test by BRepClass3d_SolidClassifier, loaded once for many points.
class SolidClassifier {
 public:
  explicit SolidClassifier(const TopoDS_Shape& solid);
  ~SolidClassifier();
  /// True when p is IN the solid or ON its boundary within tolerance tol.
  bool inside_or_on(const Vec3& p, double tol) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Distance from a point to the boundary of a shape (its faces, as a compound: a solid would
/// count interior points at distance 0), by BRepExtrema_DistShapeShape. About a millisecond per
/// point on a part with dozens of faces: callers sample.
class BoundaryDistance {
 public:
  explicit BoundaryDistance(const TopoDS_Shape& shape);
  ~BoundaryDistance();
  double distance(const Vec3& p) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Diagonal of the shape's bounding box (BRepBndLib, without the tolerance enlargement).
double shape_bbox_diagonal(const TopoDS_Shape& shape);

/// Points along every edge classified Convex, at most `step` apart along the curve (ends included).
std::vector<Vec3> convex_edge_points(const Features& features, double step);

/// The positions of the vertices flagged nonconcave_corner.
std::vector<Vec3> nonconcave_corner_points(const Features& features);

}  // namespace cadmedial::test

namespace cadmedial::test {

/// The engine's count from the B-rep (features/solid_euler.h): box 1, ball 1, solid torus 0, a
/// block with g through-holes 1 - g.
using cadmedial::solid_euler_characteristic;

}  // namespace cadmedial::test
