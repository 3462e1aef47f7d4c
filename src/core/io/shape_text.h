// Words for OpenCASCADE things in messages: a failure, a point, where an edge is.
#pragma once

#include <string>

#include <Standard_Failure.hxx>
#include <TopoDS_Edge.hxx>
#include <gp_Pnt.hxx>

namespace cadmedial::internal {

/// "Type: message" of an OpenCASCADE failure (the type alone when it has no message).
std::string failure_text(const Standard_Failure& e);
/// "(x, y, z)" with six significant digits.
std::string point_text(const gp_Pnt& p);
/// " near (x, y, z)", the midpoint of the edge's 3D curve, or "" when it has none.
std::string edge_location(const TopoDS_Edge& edge);

}  // namespace cadmedial::internal
