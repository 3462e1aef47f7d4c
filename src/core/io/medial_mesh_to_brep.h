// The medial surface as an OpenCASCADE compound of planar faces, one per polygon, as BREP text.
#pragma once

#include <string>

#include "../types.h"

namespace cadmedial {

/// BREP text of a compound with one planar face per polygon of the mesh (degenerate polygons are
/// skipped). Built in C++ because faces made one by one in FreeCAD's Python are far too slow.
std::string medial_mesh_to_brep(const MedialMesh& mesh);

}  // namespace cadmedial
