// The medial axis as an OpenCASCADE compound of planar faces, one per polygon, and straight
// edges, one per 1-D edge, as BREP text.
#pragma once

#include <string>

#include "../types.h"

namespace cadmedial {

/// BREP text of a compound with one planar face per polygon of the mesh (degenerate polygons are
/// skipped) and one straight edge per 1-D edge (zero-length ones, and those that are a side of a
/// face in the compound, are not added again). Vertices are shared, so an edge hanging off the
/// surface is connected to it. Built in C++ because faces made one by one in FreeCAD's Python
/// are far too slow.
std::string medial_mesh_to_brep(const MedialMesh& mesh);

}  // namespace cadmedial
