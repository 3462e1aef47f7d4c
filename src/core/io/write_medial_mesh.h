// Writers (and readers, for round trips and tools) of the medial mesh: binary PLY, OBJ, and .ma.
#pragma once

#include <iosfwd>
#include <string>

#include "../types.h"

namespace cadmedial {

/// Writes by extension (.ply, .obj, .ma). The file appears complete or not at all: it is written
/// to a temporary file beside the target and renamed. Throws InvalidInput on an unknown extension
/// or an unwritable path.
void write_medial_mesh(const MedialMesh& mesh, const std::string& path);

/// Binary little-endian PLY: vertex `x y z radius` (double), face `vertex_indices` (uchar/int list),
/// `kind` (uchar: 0 voronoi, 1 edge, 2 corner) and `solid` (int), then edge `vertex1 vertex2`
/// `solid` (int) for the 1-D edges (the element is present, maybe with 0 edges, in every file).
void write_ply(const MedialMesh& mesh, std::ostream& out);
/// Wavefront OBJ: `v x y z`, polygons as `f`, 1-D edges as `l i j`; the radius goes in a `vr`
/// line per vertex that other tools ignore.
void write_obj(const MedialMesh& mesh, std::ostream& out);
/// The .ma format of Q-MAT / MATFP: `nv ne nf`, `v x y z r`, `e i j`, `f i j k` (polygons fanned
/// into triangles; edges are the unique sides of those triangles, then the 1-D edges that are not
/// such a side).
void write_ma(const MedialMesh& mesh, std::ostream& out);

/// Reads a file written by write_medial_mesh (by extension). Throws InvalidInput on a bad file.
MedialMesh read_medial_mesh(const std::string& path);

}  // namespace cadmedial
