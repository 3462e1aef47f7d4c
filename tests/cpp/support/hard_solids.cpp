#include "support/hard_solids.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <BRepAdaptor_Curve.hxx>
#include <BRepAlgoAPI_Common.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepFilletAPI_MakeFillet.hxx>
#include <BRepOffsetAPI_ThruSections.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRep_Tool.hxx>
#include <GeomAPI_Interpolate.hxx>
#include <GeomAPI_PointsToBSplineSurface.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <ShapeUpgrade_UnifySameDomain.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TColgp_HArray1OfPnt.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <gp_Ax2.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

#include "support/solids.h"

namespace cadmedial::test {

namespace {

constexpr double kPi = 3.14159265358979323846;

// The one solid of a shape, checked valid (the same contract as solids.h's builders).
TopoDS_Solid single_valid_solid(const TopoDS_Shape& shape, const std::string& what) {
  TopoDS_Solid solid;
  int count = 0;
  for (TopExp_Explorer e(shape, TopAbs_SOLID); e.More(); e.Next(), ++count) solid = TopoDS::Solid(e.Current());
  if (count != 1) throw std::runtime_error(what + ": " + std::to_string(count) + " solids");
  if (!BRepCheck_Analyzer(solid).IsValid()) throw std::runtime_error(what + ": invalid solid");
  return solid;
}

// Coplanar faces left by a boolean merged into one, as a modeller would show the part.
TopoDS_Shape unified(const TopoDS_Shape& shape) {
  ShapeUpgrade_UnifySameDomain unify(shape, /*UnifyEdges=*/true, /*UnifyFaces=*/true, /*ConcatBSplines=*/false);
  unify.Build();
  return unify.Shape();
}

TopoDS_Shape fuse(const TopoDS_Shape& a, const TopoDS_Shape& b) { return BRepAlgoAPI_Fuse(a, b).Shape(); }

// a minus every tool, in one boolean (faster and more robust than a chain of cuts).
TopoDS_Shape cut_all(const TopoDS_Shape& a, const std::vector<TopoDS_Shape>& tools) {
  TopTools_ListOfShape args, tool_list;
  args.Append(a);
  for (const auto& t : tools) tool_list.Append(t);
  BRepAlgoAPI_Cut cut;
  cut.SetArguments(args);
  cut.SetTools(tool_list);
  cut.Build();
  if (!cut.IsDone()) throw std::runtime_error("cut_all: the boolean failed");
  return cut.Shape();
}

// A vertical edge (a line parallel to z) whose xy is within 1e-7 of (x, y).
bool is_vertical_edge_at(const TopoDS_Edge& edge, double x, double y) {
  BRepAdaptor_Curve c(edge);
  if (c.GetType() != GeomAbs_Line) return false;
  const gp_Pnt p0 = c.Value(c.FirstParameter()), p1 = c.Value(c.LastParameter());
  return std::abs(p0.X() - x) < 1e-7 && std::abs(p0.Y() - y) < 1e-7 && std::abs(p1.X() - x) < 1e-7 &&
         std::abs(p1.Y() - y) < 1e-7;
}

// A closed periodic B-spline through n points of the curve r(phi) (rx cos, ry sin) + wobble.
TopoDS_Wire bspline_section(double rx, double ry, double wobble, double z) {
  const int n = 12;
  Handle(TColgp_HArray1OfPnt) points = new TColgp_HArray1OfPnt(1, n);
  for (int i = 0; i < n; ++i) {
    const double phi = 2 * kPi * i / n;
    const double w = 1.0 + wobble * std::cos(3 * phi);
    points->SetValue(i + 1, gp_Pnt(rx * w * std::cos(phi), ry * w * std::sin(phi), z));
  }
  GeomAPI_Interpolate interpolate(points, /*PeriodicFlag=*/Standard_True, 1e-7);
  interpolate.Perform();
  if (!interpolate.IsDone()) throw std::runtime_error("bspline_section: interpolation failed");
  return BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(interpolate.Curve()).Edge()).Wire();
}

}  // namespace

TopoDS_Solid make_block_with_rib(double a, double b, double c, double w, double rib_height) {
  const TopoDS_Shape block = BRepPrimAPI_MakeBox(a, b, c).Shape();
  // The rib starts inside the block so that the fuse has no coplanar faces at z = c to resolve.
  const TopoDS_Shape rib =
      BRepPrimAPI_MakeBox(gp_Pnt(a / 2 - w / 2, 0, c / 2), gp_Pnt(a / 2 + w / 2, b, c + rib_height)).Shape();
  return single_valid_solid(unified(fuse(block, rib)), "make_block_with_rib");
}

TopoDS_Solid make_block_with_ribs(double a, double b, double c, int n, double x0, double pitch, double w,
                                  double rib_height) {
  TopoDS_Shape shape = BRepPrimAPI_MakeBox(a, b, c).Shape();
  // Each rib starts inside the block, as make_block_with_rib's does.
  for (int k = 0; k < n; ++k) {
    const double x = x0 + k * pitch;
    shape = fuse(shape, BRepPrimAPI_MakeBox(gp_Pnt(x, 0, c / 2), gp_Pnt(x + w, b, c + rib_height)).Shape());
  }
  return single_valid_solid(unified(shape), "make_block_with_ribs");
}

TopoDS_Solid make_block_with_boss(double a, double b, double c, double r, double boss_height) {
  const TopoDS_Shape block = BRepPrimAPI_MakeBox(a, b, c).Shape();
  const TopoDS_Shape boss =
      BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(a / 2, b / 2, c / 2), gp_Dir(0, 0, 1)), r, c / 2 + boss_height).Shape();
  return single_valid_solid(unified(fuse(block, boss)), "make_block_with_boss");
}

TopoDS_Solid make_block_with_outside_boss(double a, double b, double c, double r, double offset) {
  const TopoDS_Shape block = BRepPrimAPI_MakeBox(a, b, c).Shape();
  const TopoDS_Shape boss =
      BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(a / 2, -offset, c / 6), gp_Dir(0, 0, 1)), r, 2 * c / 3).Shape();
  return single_valid_solid(unified(fuse(block, boss)), "make_block_with_outside_boss");
}

TopoDS_Solid make_sharp_wedge(double angle_deg, double length, double height) {
  return make_prism({{0, 0}, {length, 0}, {length, length * std::tan(angle_deg * kPi / 180)}}, height);
}

TopoDS_Solid make_bent_prism(double a, double b, double c, double bend_deg, bool convex) {
  const double rise = (convex ? 1.0 : -1.0) * a / 2 * std::tan(bend_deg * kPi / 180);
  // Not convex when bent inward, so make_prism (convex polygons only by its contract) is not used.
  BRepBuilderAPI_MakePolygon wire;
  for (const auto& [x, y] : std::vector<std::pair<double, double>>{{0, 0}, {a, 0}, {a, b}, {a / 2, b + rise}, {0, b}})
    wire.Add(gp_Pnt(x, y, 0));
  wire.Close();
  const TopoDS_Face face = BRepBuilderAPI_MakeFace(wire.Wire(), /*OnlyPlane=*/true).Face();
  return single_valid_solid(BRepPrimAPI_MakePrism(face, gp_Vec(0, 0, c)).Shape(), "make_bent_prism");
}

TopoDS_Solid make_filleted_l_block(double a, double t, double c, double r_in, double r_out) {
  const TopoDS_Solid l = make_l_block(a, t, c);
  BRepFilletAPI_MakeFillet fillet(l);
  const std::vector<std::pair<double, double>> outer{{0, 0}, {a, 0}, {a, t}, {t, a}, {0, a}};
  for (TopExp_Explorer e(l, TopAbs_EDGE); e.More(); e.Next()) {
    const TopoDS_Edge& edge = TopoDS::Edge(e.Current());
    if (is_vertical_edge_at(edge, t, t)) fillet.Add(r_in, edge);
    for (const auto& [x, y] : outer)
      if (is_vertical_edge_at(edge, x, y)) fillet.Add(r_out, edge);
  }
  fillet.Build();
  if (!fillet.IsDone()) throw std::runtime_error("make_filleted_l_block: the fillet failed");
  return single_valid_solid(fillet.Shape(), "make_filleted_l_block");
}

TopoDS_Solid make_block_with_filleted_hole(double a, double b, double c, double r, double r_fillet) {
  const TopoDS_Solid block = make_block_with_hole(a, b, c, r);
  BRepFilletAPI_MakeFillet fillet(block);
  // The hole's two rims are the block's only circles.
  for (TopExp_Explorer e(block, TopAbs_EDGE); e.More(); e.Next())
    if (BRepAdaptor_Curve(TopoDS::Edge(e.Current())).GetType() == GeomAbs_Circle)
      fillet.Add(r_fillet, TopoDS::Edge(e.Current()));
  fillet.Build();
  if (!fillet.IsDone()) throw std::runtime_error("make_block_with_filleted_hole: the fillet failed");
  return single_valid_solid(fillet.Shape(), "make_block_with_filleted_hole");
}

TopoDS_Solid make_ball_on_neck(double R, double r, double length, double r_fillet) {
  const TopoDS_Shape ball = BRepPrimAPI_MakeSphere(R).Shape();
  const TopoDS_Shape neck = BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(0, 0, 0), gp_Dir(0, 1, 0)), r, length).Shape();
  const TopoDS_Solid body = single_valid_solid(unified(fuse(ball, neck)), "make_ball_on_neck");
  BRepFilletAPI_MakeFillet fillet(body);
  // The ball meets the neck along the one circle at y = sqrt(R^2 - r^2).
  const double y = std::sqrt(R * R - r * r);
  for (TopExp_Explorer e(body, TopAbs_EDGE); e.More(); e.Next()) {
    BRepAdaptor_Curve curve(TopoDS::Edge(e.Current()));
    if (curve.GetType() == GeomAbs_Circle && std::abs(curve.Circle().Location().Y() - y) < 1e-6)
      fillet.Add(r_fillet, TopoDS::Edge(e.Current()));
  }
  fillet.Build();
  if (!fillet.IsDone()) throw std::runtime_error("make_ball_on_neck: the fillet failed");
  return single_valid_solid(fillet.Shape(), "make_ball_on_neck");
}

TopoDS_Solid make_bspline_loft(double height) {
  BRepOffsetAPI_ThruSections loft(/*isSolid=*/Standard_True, /*ruled=*/Standard_False);
  loft.AddWire(bspline_section(6, 4, 0.10, 0));
  loft.AddWire(bspline_section(4, 5, 0.05, height / 2));
  loft.AddWire(bspline_section(5, 3, 0.10, height));
  loft.Build();
  if (!loft.IsDone()) throw std::runtime_error("make_bspline_loft: the loft failed");
  return single_valid_solid(loft.Shape(), "make_bspline_loft");
}

TopoDS_Solid make_box_with_bspline_top(double a, double b, double c, double bump) {
  // The surface overhangs the box by 10 % on every side so that the box's side faces cut it inside
  // its domain.
  const int n = 13;
  TColgp_Array2OfPnt grid(1, n, 1, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double x = a * (-0.1 + 1.2 * i / (n - 1)), y = b * (-0.1 + 1.2 * j / (n - 1));
      grid.SetValue(i + 1, j + 1, gp_Pnt(x, y, c + bump * std::sin(kPi * x / a) * std::sin(kPi * y / b)));
    }
  const Handle(Geom_BSplineSurface) surface = GeomAPI_PointsToBSplineSurface(grid).Surface();
  const TopoDS_Face top = BRepBuilderAPI_MakeFace(surface, 1e-7).Face();
  // The slab under the surface, cut to the box's footprint and floor.
  const double depth = c + 3 * std::abs(bump) + 1;
  const TopoDS_Shape slab = BRepPrimAPI_MakePrism(top, gp_Vec(0, 0, -depth)).Shape();
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), gp_Pnt(a, b, c + 3 * std::abs(bump) + 1)).Shape();
  return single_valid_solid(BRepAlgoAPI_Common(box, slab).Shape(), "make_box_with_bspline_top");
}

TopoDS_Solid make_plate_with_holes(double a, double b, double c, int nx, int ny, double size, bool square) {
  std::vector<TopoDS_Shape> tools;
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j) {
      const double x = a * (i + 0.5) / nx, y = b * (j + 0.5) / ny;
      // Taller than the plate: no tool face coincides with a plate face.
      if (square)
        tools.push_back(BRepPrimAPI_MakeBox(gp_Pnt(x - size, y - size, -1), gp_Pnt(x + size, y + size, c + 1)).Shape());
      else
        tools.push_back(BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(x, y, -1), gp_Dir(0, 0, 1)), size, c + 2).Shape());
    }
  return single_valid_solid(cut_all(BRepPrimAPI_MakeBox(a, b, c).Shape(), tools), "make_plate_with_holes");
}

}  // namespace cadmedial::test
