// The thinnest wall a sampling shows: where two walls face each other closer than the spacing can
// carry the medial sheet between them (section 3's density condition fails there), the axis may
// get holes or extra loops. A cheap check on the samples that lets the user know.
#pragma once

#include <cstddef>
#include <limits>

#include "../progress.h"
#include "../types.h"
#include "samples.h"

namespace cadmedial {

struct ThinWall {
  /// Radius of the smallest inner ball tangent at a face sample through a sample of a facing
  /// wall: half the wall's thickness there (an upper bound: the samples need not sit opposite).
  /// Only balls smaller than the spacing are looked for: infinity when there is none.
  double radius = std::numeric_limits<double>::infinity();
  Point3 at{0, 0, 0};         ///< the face sample where it was found
  std::size_t samples = 0;    ///< face samples with such a ball
};

/// Looks for facing walls (outward normals more than 120 degrees apart) within two spacings of
/// each face sample farther than a spacing from every convex-edge sample.
/// Progress is reported (and so can cancel) every few thousand samples.
ThinWall thinnest_wall(const Samples& samples, double spacing, const Progress& progress = {});

}  // namespace cadmedial
