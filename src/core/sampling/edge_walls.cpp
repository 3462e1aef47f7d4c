#include "edge_walls.h"

#include <cmath>
#include <limits>

#include "../two_cores.h"
#include "mirror_thin_walls.h"
#include "point_grid.h"

namespace cadmedial {

std::vector<double> edge_wall_radii(const Samples& samples, BoundaryDistance* boundaries[2], double r_max,
                                    double tol) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  std::vector<double> radii(samples.size(), kInf);
  const std::vector<Triplet>& t = samples.triplets;
  std::vector<double> at(t.size(), kInf);
  internal::on_two_halves(t.size(), [&](int part, std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) {
      const int legs[2] = {t[k].sl, t[k].sr};
      for (int side = 0; side < 2; ++side) {
        const int leg = legs[side], other_leg = legs[1 - side];
        if (leg < 0) continue;
        const Point3& n = samples.normal[leg];
        const MedialContact c = shrink_ball(*boundaries[part], samples.points[leg], n, r_max, tol);
        if (!c.found || c.other.face < 0) continue;
        const double facing = c.other.normal[0] * n[0] + c.other.normal[1] * n[1] + c.other.normal[2] * n[2];
        // The edge's other face is the wedge itself, thinning to nothing at the edge: the
        // completion (4.2.2) joins the axis there, not the density.
        if (facing > -0.5 || c.other.face == samples.face[leg] ||
            (other_leg >= 0 && c.other.face == samples.face[other_leg]))
          continue;
        at[k] = std::min(at[k], c.radius);
      }
    }
  }, 64);
  for (std::size_t k = 0; k < t.size(); ++k)
    if (t[k].s >= 0) radii[t[k].s] = std::min(radii[t[k].s], at[k]);
  return radii;
}

void keep_near_edges(const Samples& samples, double reach, std::vector<double>& radii) {
  PointGrid edges(reach);
  for (std::size_t i = 0; i < samples.size(); ++i)
    if (samples.tag[i] != SampleTag::Face && samples.tag[i] != SampleTag::Triplet)
      edges.insert(samples.points[i], static_cast<int>(i));
  const double reach2 = reach * reach;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    if (!std::isfinite(radii[i]) || (samples.tag[i] != SampleTag::Face && samples.tag[i] != SampleTag::Triplet))
      continue;
    const Point3& p = samples.points[i];
    const bool near = edges.any_near(p, reach, [&](int j) {
      const Point3& q = samples.points[j];
      const double dx = p[0] - q[0], dy = p[1] - q[1], dz = p[2] - q[2];
      return dx * dx + dy * dy + dz * dz < reach2;
    });
    if (!near) radii[i] = std::numeric_limits<double>::infinity();
  }
}

}  // namespace cadmedial
