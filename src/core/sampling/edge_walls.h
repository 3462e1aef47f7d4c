// Where a convex edge bounds a wall thinner than the spacing (the rim of a can, a sheet's edge, a
// terminal cap's lip): mirrored sampling (mirror_thin_walls.h) carries the wall's sheet at any
// spacing, but the sheet must still fork to the edge and its neighbour across the rim, a wall's
// thickness away, and the samples there must resolve that. The thickness is measured exactly
// at the edge's triplets: the radius of the medial ball tangent there, from the B-rep.
#pragma once

#include <vector>

#include "../exact/boundary_distance.h"
#include "samples.h"

namespace cadmedial {

/// Per sample: at the samples of a convex edge, the smallest radius of the medial balls tangent
/// at its triplets' face points that reach a facing face (normals more than 120 degrees apart)
/// other than the edge's own two, when below `r_max`; infinity elsewhere. Two threads
/// (`boundaries`: one instance per thread on the sampled solid).
std::vector<double> edge_wall_radii(const Samples& samples, BoundaryDistance* boundaries[2], double r_max,
                                    double tol);

/// `radii` (per sample) kept only at samples within `reach` of a sample of an edge or a corner:
/// a thin wall's rims and junctions, where the sheet forks or joins the rest of the axis.
/// Infinity elsewhere: the wall's interior is sampled in mirrored pairs, which carry its sheet.
void keep_near_edges(const Samples& samples, double reach, std::vector<double>& radii);

}  // namespace cadmedial
