// Checks of one solid or shell, each giving the words a refusal uses: closedness, BRepCheck's
// first complaint, volume, size.
#pragma once

#include <string>

#include <BRepCheck_Analyzer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS_Shape.hxx>
#include <TopoDS_Solid.hxx>

namespace cadmedial::internal {

/// "" or why `shell` is not closed and manifold ("edge 6 is bounded by 1 face (the shell is
/// open) near (...)"), its edge numbered by `edge_index`.
std::string open_or_nonmanifold_edge(const TopoDS_Shape& shell, const TopTools_IndexedMapOfShape& edge_index);
/// The first defect `analyzer` (run on `solid`) found, as "wire 3 is invalid (BRepCheck_...)".
std::string first_check_failure(const TopoDS_Shape& solid, const BRepCheck_Analyzer& analyzer);
/// The solid's volume, negative when its faces point inward.
double signed_volume(const TopoDS_Solid& solid);
/// The diagonal of the shape's bounding box, 0 when it has none.
double diagonal(const TopoDS_Shape& shape);

}  // namespace cadmedial::internal
