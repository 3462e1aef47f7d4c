// The thinnest wall a sampling shows: where two walls face each other closer than the spacing can
// carry the medial sheet between them (section 3's density condition fails there), the axis may
// get holes or extra loops. Found on a first sampling, it tells the sampler where to sample more
// densely (spacing_field.h), and the user where that was not enough.
#pragma once

#include <array>
#include <cstddef>
#include <limits>
#include <vector>

#include "../progress.h"
#include "../types.h"
#include "samples.h"

namespace cadmedial {

/// Per sample: the radius of the smallest inner ball tangent at it through a sample of a facing
/// wall (outward normals more than 120 degrees apart), half the wall's thickness there (an upper
/// bound: the samples need not sit opposite). Only balls smaller than `spacing` are looked for;
/// infinity elsewhere: on edge and corner samples, and where no wall faces within two spacings.
/// Within a spacing of a convex-edge sample, the two faces of a convex edge (`wedges`, face index
/// pairs) do not count as walls for each other where their normals' dot product is below
/// `wedge_dot` (1: anywhere): a sharp wedge thins to nothing at its edge, where the completion
/// (4.2.2) joins the axis to the edge. (The faces of a thin plate's rim edges are not such a
/// pair: top and bottom face each other up to the rim.) Progress is reported (and so can cancel)
/// every few thousand samples. On two threads unless `threads` is 1 (the same radii).
std::vector<double> wall_radii(const Samples& samples, double spacing, const std::vector<std::array<int, 2>>& wedges,
                               double wedge_dot = 1.0, const Progress& progress = {}, int threads = 2);

/// Whether wall_radii would find any wall thinner than the spacing: it stops at the first.
bool any_thin_wall(const Samples& samples, double spacing, const std::vector<std::array<int, 2>>& wedges,
                   double wedge_dot = 1.0, const Progress& progress = {});

struct ThinWall {
  double radius = std::numeric_limits<double>::infinity();  ///< the smallest of wall_radii
  Point3 at{0, 0, 0};         ///< the face sample where it was found
  std::size_t samples = 0;    ///< face samples with a finite radius (thinnest_wall)
};

ThinWall thinnest_wall(const Samples& samples, const std::vector<double>& radii);
/// thinnest_wall's wall (on one thread), found faster on a sampling refined at thin walls, where
/// the spacing's reach takes in thousands of samples around each one (NIST FTC 10 at 66k: 5.2 s).
/// It looks first only for walls up to 1.5 `guess` (the uniform pass's thinnest, whose walls the
/// refined sampling shows about as thin), then as far as what it finds needs, and past each sample
/// only for walls thinner than the thinnest so far: `samples` is not counted (0).
ThinWall thinnest_wall_near(const Samples& samples, double spacing, const std::vector<std::array<int, 2>>& wedges,
                            double guess, const Progress& progress = {});
inline ThinWall thinnest_wall(const Samples& samples, double spacing, const std::vector<std::array<int, 2>>& wedges,
                              const Progress& progress = {}, int threads = 2) {
  return thinnest_wall(samples, wall_radii(samples, spacing, wedges, 1.0, progress, threads));
}

}  // namespace cadmedial
