// The exact inside test on the B-rep, for the Voronoi vertices the medial stage cannot settle.
#pragma once

#include <functional>

#include <TopoDS_Solid.hxx>

#include "../medial/medial_axis.h"

namespace cadmedial {

/// Rays from the point (internal::RayClassifier), and where they do not settle it OpenCASCADE's
/// solid classifier, with tolerance `tol`; on the boundary counts as inside. The returned function
/// keeps a reference to `solid`.
InsideTest exact_inside_test(const TopoDS_Solid& solid, double tol);

/// The same, and in `prepare` a call that builds the ray classifiers (one per core), which the
/// first points asked would pay for otherwise: compute_medial_axis makes it on the core that idles
/// while CGAL triangulates.
InsideTest exact_inside_test(const TopoDS_Solid& solid, double tol, std::function<void()>& prepare);

}  // namespace cadmedial
