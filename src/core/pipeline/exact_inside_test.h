// The exact inside test on the B-rep, for the Voronoi vertices the medial stage cannot settle.
#pragma once

#include <TopoDS_Solid.hxx>

#include "../medial/medial_axis.h"

namespace cadmedial {

/// OpenCASCADE's solid classifier with tolerance `tol`; on the boundary counts as inside. The
/// returned function keeps a reference to `solid`.
InsideTest exact_inside_test(const TopoDS_Solid& solid, double tol);

}  // namespace cadmedial
