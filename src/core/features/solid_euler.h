// The Euler characteristic of a solid from its B-rep: what a medial axis with the solid's
// topology has (the axis is homotopy equivalent to the solid).
#pragma once

class TopoDS_Shape;

namespace cadmedial {

/// Euler characteristic of the solid (as a 3-manifold with boundary), from its B-rep alone:
/// chi(solid) = chi(boundary) / 2, and chi(boundary) = V - E + sum over faces of (2 - #wires)
/// (a face with k wires is a disc with k - 1 holes; a seam edge is an ordinary edge of the cell
/// decomposition; degenerate edges, e.g. a sphere's poles, collapse to their vertex and are not
/// counted). Box 1, ball 1, solid torus 0, a block with g through-holes 1 - g.
long solid_euler_characteristic(const TopoDS_Shape& solid);

}  // namespace cadmedial
