// Hard but valid test solids built with OpenCASCADE (issue 5): tiny features beside large ones,
// very sharp and nearly flat edges, tangent-continuous fillets, B-spline faces, many through-holes.
// Every builder returns one valid closed solid (checked with BRepCheck_Analyzer;
// std::runtime_error otherwise). Dimensions are in model units.
#pragma once

#include <TopoDS_Solid.hxx>

namespace cadmedial::test {

/// The block [0,a] x [0,b] x [0,c] with a rib [a/2 - w/2, a/2 + w/2] x [0,b] x [c, c + rib_height]
/// on its top (coplanar faces merged): a thin wall across the whole block.
TopoDS_Solid make_block_with_rib(double a, double b, double c, double w, double rib_height);

/// The block [0,a] x [0,b] x [0,c] with n ribs w wide and rib_height tall across its top, the
/// k-th over x in [x0 + k pitch, x0 + k pitch + w] (coplanar faces merged): thin walls standing
/// free of each other.
TopoDS_Solid make_block_with_ribs(double a, double b, double c, int n, double x0, double pitch, double w,
                                  double rib_height);

/// The block [0,a] x [0,b] x [0,c] with a cylindrical boss of radius r and height boss_height
/// standing on the centre of its top face.
TopoDS_Solid make_block_with_boss(double a, double b, double c, double r, double boss_height);

/// The block [0,a] x [0,b] x [0,c] fused with the cylinder of radius r about the vertical line
/// (a/2, -offset), z in [c/6, 5c/6], whose axis lies outside the block's face y = 0 (0 < offset < r):
/// the cylinder meets that face along two concave edges with an exterior angle of
/// acos(offset / r), under 90 degrees.
TopoDS_Solid make_block_with_outside_boss(double a, double b, double c, double r, double offset);

/// The prism over the triangle (0,0) (length,0) (length, length tan(angle)), z in [0, height]:
/// its edge on the z axis has the dihedral angle `angle_deg`.
TopoDS_Solid make_sharp_wedge(double angle_deg, double length, double height);

/// The prism over the pentagon (0,0) (a,0) (a,b) (a/2, b + k a/2 tan(bend)) (0,b), z in [0, c],
/// with k = +1 (convex) or -1 (concave): its vertical edge at x = a/2 has the dihedral angle
/// 180 - 2 bend (convex) or 180 + 2 bend (concave): nearly flat for a small bend.
TopoDS_Solid make_bent_prism(double a, double b, double c, double bend_deg, bool convex);

/// make_l_block(a, t, c) of solids.h with its concave vertical edge rounded with radius r_in and
/// its outer vertical edges rounded with radius r_out (BRepFilletAPI_MakeFillet): every vertical
/// edge becomes a tangent-continuous round.
TopoDS_Solid make_filleted_l_block(double a, double t, double c, double r_in, double r_out);

/// make_block_with_hole(a, b, c, r) of solids.h with both rims of the hole rounded with radius
/// r_fillet (tori meeting the hole and the faces tangentially).
TopoDS_Solid make_block_with_filleted_hole(double a, double b, double c, double r, double r_fillet);

/// A loft (BRepOffsetAPI_ThruSections, smooth, closed with planar caps) through three
/// interpolated closed B-spline sections at z = 0, height/2, height: one B-spline side face.
TopoDS_Solid make_bspline_loft(double height);

/// The block [0,a] x [0,b] x [0, top(x, y)] whose top is one B-spline surface
/// (GeomAPI_PointsToBSplineSurface) through c + bump sin(pi x / a) sin(pi y / b).
TopoDS_Solid make_box_with_bspline_top(double a, double b, double c, double bump);

/// The plate [0,a] x [0,b] x [0,c] with nx * ny through-holes along z on a regular grid (pitch
/// a/nx by b/ny, centred in their cells): round of radius `size` or square of side 2 `size`.
TopoDS_Solid make_plate_with_holes(double a, double b, double c, int nx, int ny, double size, bool square);

/// A ball of radius R about the origin fused with a neck, the cylinder of radius r < R along +y
/// from the origin to y = length, their circle of intersection rounded with radius r_fillet. The
/// fillet's edge on the ball is an approximation: OpenCASCADE gives it a tolerance of about 2e-5,
/// so its samples lie that far off the ball's sphere.
TopoDS_Solid make_ball_on_neck(double R, double r, double length, double r_fillet);

}  // namespace cadmedial::test
