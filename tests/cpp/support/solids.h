// Test solids built with OpenCASCADE. Every builder returns one valid closed solid (checked with
// BRepCheck_Analyzer; std::runtime_error otherwise). Dimensions are in model units.
#pragma once

#include <array>
#include <vector>

#include <TopoDS_Shape.hxx>
#include <TopoDS_Solid.hxx>

#include "support/convex_polytope.h"

namespace cadmedial::test {

/// [0,a] x [0,b] x [0,c] (BRepPrimAPI_MakeBox); its planes are box_polytope(a, b, c).
TopoDS_Solid make_box(double a, double b, double c);
/// The prism over a convex counter-clockwise xy polygon, z in [0, height] (BRepPrimAPI_MakePrism of
/// a planar face); its planes are prism_polytope(polygon, height).
TopoDS_Solid make_prism(const std::vector<std::array<double, 2>>& polygon, double height);
/// Any convex polytope, from its facet polygons sewn into a shell.
TopoDS_Solid make_polytope_solid(const ConvexPolytope& polytope);

/// rho <= R, 0 <= z <= H (BRepPrimAPI_MakeCylinder).
TopoDS_Solid make_cylinder(double R, double H);
/// Centre at the origin.
TopoDS_Solid make_sphere(double R);
/// Centre at the origin, axis z, major radius R, minor radius r.
TopoDS_Solid make_torus(double R, double r);
/// A cone with base radius R at z = 0 and apex at (0, 0, H).
TopoDS_Solid make_cone(double R, double H);

/// [0,a] x [0,b] x [0,c] minus the cylinder of radius r about the vertical line through the centre
/// of the top face: one through-hole, genus 1.
TopoDS_Solid make_block_with_hole(double a, double b, double c, double r);
/// The L-shaped prism over (0,0) (a,0) (a,t) (t,t) (t,a) (0,a), height c: exactly one concave edge
/// (the vertical edge at (t,t)).
TopoDS_Solid make_l_block(double a, double t, double c);
/// The box [0,a]^2 x [0,c] with a pocket [p0,p1]^2 x [c-depth, c] cut into its top face: the pocket's
/// four floor corners are concave (three concave edges each), its four rim corners are saddles
/// (two convex rim edges and one concave vertical edge).
TopoDS_Solid make_pocket_block(double a, double c, double p0, double p1, double depth);
/// The box [0,a] x [0,b] x [0,c] with its edge x = a, z = c (along y) rounded with radius r: the
/// round meets the top and the x = a faces tangentially (two smooth edges).
TopoDS_Solid make_filleted_box(double a, double b, double c, double r);

/// A compound of the given solids, in that order.
TopoDS_Shape make_compound(const std::vector<TopoDS_Solid>& solids);

}  // namespace cadmedial::test
