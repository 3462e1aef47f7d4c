// The cheap checks of a shape's geometry that run before any OpenCASCADE algorithm touches it.
#pragma once

#include <TopoDS_Shape.hxx>

namespace cadmedial::internal {

/// Throws InvalidInput naming the first face, edge or vertex (numbered over `shape`) whose geometry
/// is degenerate or not finite, or whose curves do not meet at their ends.
void check_geometry(const TopoDS_Shape& shape);

}  // namespace cadmedial::internal
