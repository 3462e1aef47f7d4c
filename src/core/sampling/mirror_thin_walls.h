// Thin walls sampled in mirrored pairs. Where two faces face each other closer than a few
// spacings, samples of the two sides that are not opposite each other have bisectors tilted far
// from the wall's mid-plane: the sheet between them comes out crooked (on a plate 1.6 spacings
// thick, up to 5 % of its thickness off the mid-plane) or with holes. A sample on one side and
// the other contact point of its medial ball are mirror images across the medial sheet, so their
// Voronoi facet lies on it, at any spacing. So on each such pair of faces one side (the face of
// lower index) keeps its samples and the other gets their mirrors in place of its own.
#pragma once

#include <cstddef>
#include <vector>

#include "../exact/boundary_distance.h"
#include "face_interior.h"
#include "point_grid.h"
#include "spacing_field.h"

namespace cadmedial {

/// The medial ball tangent at p (outer unit normal n) if its radius is below r_max: shrunk from
/// r_max through the nearest boundary point of its centre until that point is on its sphere.
struct MedialContact {
  bool found = false;
  double radius = 0;
  BoundaryDistance::Nearest other;  ///< its other contact
};
MedialContact shrink_ball(BoundaryDistance& boundary, const Point3& p, const Point3& n, double r_max, double tol);

struct MirrorStats {
  std::size_t mirrored = 0;  ///< samples put on a face as mirrors of the other side's
  std::size_t replaced = 0;  ///< the face's own samples they took the place of
};

/// A sample placed before the face interiors (corner, edge, triplet), which a mirror keeps clear of
/// as a face's own samples do.
struct PlacedSample {
  Point3 point, normal;
  double exclusion;
};

/// Rewrites `interiors` (per face of the solid, in TopExp::MapShapes order) so that walls thinner
/// than 2 * per_spacing * the uniform spacing (field.uniform(), also where the field is finer) are
/// sampled in mirrored pairs. `boundaries`: two
/// instances (one per thread) on the solid. `placed`: the samples already placed. `tol`: lengths
/// below this are zero (1e-9 of the diagonal).
MirrorStats mirror_thin_walls(std::vector<sampling_detail::FaceInterior>& interiors, const SpacingField& field,
                              const std::vector<PlacedSample>& placed, BoundaryDistance* boundaries[2],
                              double per_spacing, double tol);

}  // namespace cadmedial
