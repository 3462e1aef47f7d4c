#include "support/shape_measures.h"

#include <algorithm>
#include <cmath>

#include <BRepAdaptor_Curve.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepClass3d_SolidClassifier.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <GCPnts_AbscissaPoint.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>

namespace cadmedial::test {

struct SolidClassifier::Impl {
  BRepClass3d_SolidClassifier classifier;
  Bnd_Box box;
};

SolidClassifier::SolidClassifier(const TopoDS_Shape& solid) : impl_(std::make_unique<Impl>()) {
  impl_->classifier.Load(solid);
  BRepBndLib::AddOptimal(solid, impl_->box, /*useTriangulation=*/false, /*useShapeTolerance=*/false);
}

SolidClassifier::~SolidClassifier() = default;

bool SolidClassifier::inside_or_on(const Vec3& p, double tol) const {
  // The classifier answers IN for some points 1e15 away (rounding in its ray casting): a point
  // outside the bounding box enlarged by tol is outside, whatever it says.
  Bnd_Box grown = impl_->box;
  grown.Enlarge(tol);
  if (grown.IsOut(gp_Pnt(p[0], p[1], p[2]))) return false;
  impl_->classifier.Perform(gp_Pnt(p[0], p[1], p[2]), tol);
  const TopAbs_State state = impl_->classifier.State();
  return state == TopAbs_IN || state == TopAbs_ON;
}

struct BoundaryDistance::Impl {
  TopoDS_Compound faces;
};

BoundaryDistance::BoundaryDistance(const TopoDS_Shape& shape) : impl_(std::make_unique<Impl>()) {
  BRep_Builder builder;
  builder.MakeCompound(impl_->faces);
  for (TopExp_Explorer e(shape, TopAbs_FACE); e.More(); e.Next()) builder.Add(impl_->faces, e.Current());
}

BoundaryDistance::~BoundaryDistance() = default;

double BoundaryDistance::distance(const Vec3& p) const {
  const TopoDS_Vertex vertex = BRepBuilderAPI_MakeVertex(gp_Pnt(p[0], p[1], p[2]));
  BRepExtrema_DistShapeShape dist(vertex, impl_->faces);
  return dist.IsDone() ? dist.Value() : -1.0;
}

double shape_bbox_diagonal(const TopoDS_Shape& shape) {
  Bnd_Box box;
  BRepBndLib::AddOptimal(shape, box, /*useTriangulation=*/false, /*useShapeTolerance=*/false);
  return std::sqrt(box.SquareExtent());
}

std::vector<Vec3> convex_edge_points(const Features& features, double step) {
  std::vector<Vec3> points;
  for (int e = 0; e < static_cast<int>(features.edge_kind.size()); ++e) {
    if (features.edge_kind[e] != EdgeKind::Convex) continue;
    const TopoDS_Edge& edge = TopoDS::Edge(features.edges.FindKey(e + 1));
    if (BRep_Tool::Degenerated(edge)) continue;
    BRepAdaptor_Curve curve(edge);
    const double t0 = curve.FirstParameter(), t1 = curve.LastParameter();
    const double length = GCPnts_AbscissaPoint::Length(curve);
    const int n = std::max(1, static_cast<int>(std::ceil(length / step)));
    // Uniform in arc length, so that consecutive points are at most `step` apart.
    for (int k = 0; k <= n; ++k) {
      double t = k == 0 ? t0 : (k == n ? t1 : GCPnts_AbscissaPoint(curve, length * k / n, t0).Parameter());
      const gp_Pnt p = curve.Value(t);
      points.push_back({p.X(), p.Y(), p.Z()});
    }
  }
  return points;
}

std::vector<Vec3> nonconcave_corner_points(const Features& features) {
  std::vector<Vec3> points;
  for (int v = 0; v < static_cast<int>(features.nonconcave_corner.size()); ++v) {
    if (!features.nonconcave_corner[v]) continue;
    const gp_Pnt p = BRep_Tool::Pnt(TopoDS::Vertex(features.vertices.FindKey(v + 1)));
    points.push_back({p.X(), p.Y(), p.Z()});
  }
  return points;
}

}  // namespace cadmedial::test


