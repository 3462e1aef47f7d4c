// Internal to medial/: the Angle and Ratio conditions (section 3) and the Voronoi facets they
// select (4.2.6 lines 5-8); MEDIAL's pole umbrellas for the ablation.
#pragma once

#include <vector>

#include "../progress.h"
#include "../sampling/samples.h"
#include "../types.h"
#include "delaunay_3.h"
#include "medial_axis.h"
#include "reconstruct_faces.h"

namespace cadmedial::internal {

/// Does Delaunay edge pq pass the Angle or the Ratio condition at p's umbrella?
class Selection {
 public:
  Selection(const Samples& s, const Umbrellas& u, const MedialParams& params);
  bool passes(int p, int q) const;
  /// 4.2.6 line 6: either endpoint may pass.
  bool selected(int p, int q) const { return passes(p, q) || passes(q, p); }
  const Samples& samples() const { return s_; }

 private:
  const Samples& s_;
  const Umbrellas& u_;
  double sin_theta_, rho_;
  std::vector<Point3> normals_;     ///< each sample's umbrella normals side by side (CSR of u_)
  std::vector<double> max_radius_;  ///< each sample's largest umbrella circumradius
  double cos_cone_side_;
  bool concave_fans_;  ///< the concave-edge wedge test (CAD_MEDIAL with exact normals; not plain MEDIAL)
  bool in_concave_cone(int p, const Point3& d, double len) const;
};

/// MEDIAL's umbrellas from the poles (section 3), for the ablation.
Umbrellas umbrellas_from_poles(const Delaunay& dt, std::size_t n);

/// The bounded Voronoi facets dual to selected Delaunay edges, added to mc; with `fillers`, those
/// of the other edges too, marked as fillers. Facets with a corner surely outside (mc.surely_outside)
/// are not built; their other corners are marked in mc.unbuilt_use.
/// Needs mc's cells numbered (number_cells) and surely_outside set. Runs on two threads unless
/// `threads` is 1 (the same faces in the same order); only the calling one reports progress.
void select_facets(const Selection& sel, MedialComplex& mc, MedialAxisStats& st, const Progress& progress,
                   bool fillers, int threads = 2);

}  // namespace cadmedial::internal
