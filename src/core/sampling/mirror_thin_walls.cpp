#include "mirror_thin_walls.h"

#include <algorithm>
#include <cmath>

#include "../two_cores.h"

namespace cadmedial {

namespace {

double dot(const Point3& a, const Point3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Point3 sub(const Point3& a, const Point3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dist2(const Point3& a, const Point3& b) { return dot(sub(a, b), sub(a, b)); }

// The other side's contact of a face sample, when the wall there is thin.
struct Opposite {
  int face = -1;
  Point3 point{0, 0, 0}, normal{0, 0, 0};
  std::array<double, 2> uv{0, 0};
};

}  // namespace

MedialContact shrink_ball(BoundaryDistance& boundary, const Point3& p, const Point3& n, double r_max, double tol) {
  MedialContact out;
  double r = r_max;
  for (int it = 0; it < 50; ++it) {
    const Point3 c{p[0] - r * n[0], p[1] - r * n[1], p[2] - r * n[2]};
    const BoundaryDistance::Nearest q = boundary.nearest(c, r);
    if (q.distance >= r - tol || (q.face < 0 && q.edge < 0)) return out;  // nothing else inside the ball
    // The ball tangent at p through q: |c' - q| = r' with c' = p - r' n.
    const Point3 v = sub(p, q.point);
    const double along = dot(v, n);
    const double r_next = dot(v, v) / (2 * along);
    if (!(along > tol) || dot(v, v) < tol * tol) return out;  // q is p itself, or above its plane
    out.found = true;
    out.other = q;
    out.radius = r_next;
    if (r - r_next <= tol) return out;
    r = r_next;
  }
  return out;
}

MirrorStats mirror_thin_walls(std::vector<sampling_detail::FaceInterior>& interiors, const SpacingField& field,
                              const std::vector<PlacedSample>& placed, BoundaryDistance* boundaries[2],
                              double per_spacing, double tol) {
  MirrorStats st;
  const int nf = static_cast<int>(interiors.size());
  std::vector<std::pair<int, int>> all;  // (face, sample)
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < static_cast<int>(interiors[f].point.size()); ++k) all.push_back({f, k});
  if (all.empty()) return st;
  std::vector<Opposite> opposite(all.size());
  internal::on_two_halves(all.size(), [&](int part, std::size_t begin, std::size_t end) {
    BoundaryDistance& boundary = *boundaries[part];
    for (std::size_t i = begin; i < end; ++i) {
      const auto [f, k] = all[i];
      const Point3& p = interiors[f].point[k];
      const Point3& n = interiors[f].normal[k];
      const MedialContact c = shrink_ball(boundary, p, n, per_spacing * field.uniform(), tol);
      // Another face, facing this one (normals more than 120 degrees apart), in its interior.
      if (!c.found || c.other.face < 0 || c.other.face == f || dot(c.other.normal, n) > -0.5) continue;
      opposite[i] = {c.other.face, c.other.point, c.other.normal, c.other.uv};
    }
  }, 256);

  // Mirrors kept clear of the samples placed before on their side, as a face's own samples are.
  const double h_max = field.uniform();
  double reach = 0.5 * h_max;
  PointGrid placed_grid(h_max);
  for (std::size_t i = 0; i < placed.size(); ++i) {
    placed_grid.insert(placed[i].point, static_cast<int>(i));
    reach = std::max(reach, placed[i].exclusion);
  }
  std::vector<sampling_detail::FaceInterior> mirrors(nf);
  std::vector<std::vector<char>> slave(nf);
  for (int f = 0; f < nf; ++f) slave[f].assign(interiors[f].point.size(), 0);
  for (std::size_t i = 0; i < all.size(); ++i) {
    const Opposite& o = opposite[i];
    if (o.face < 0) continue;
    const auto [f, k] = all[i];
    if (o.face < f) {
      slave[f][k] = 1;
      continue;
    }
    const double h = field.at(o.point);
    const bool crowded = placed_grid.any_near(o.point, reach, [&](int j) {
      const PlacedSample& s = placed[j];
      const double keep = std::max(s.exclusion, 0.5 * h);
      return dot(s.normal, o.normal) > -0.5 && dist2(s.point, o.point) < keep * keep;
    });
    if (crowded) continue;
    sampling_detail::FaceInterior& m = mirrors[o.face];
    m.point.push_back(o.point);
    m.normal.push_back(o.normal);
    m.curvature.push_back(interiors[f].curvature[k]);
    m.uv.push_back(o.uv);
  }
  for (int f = 0; f < nf; ++f) {
    sampling_detail::FaceInterior& m = mirrors[f];
    if (m.point.empty()) continue;
    PointGrid grid(h_max);
    for (std::size_t j = 0; j < m.point.size(); ++j) grid.insert(m.point[j], static_cast<int>(j));
    sampling_detail::FaceInterior& own = interiors[f];
    sampling_detail::FaceInterior kept;
    kept.probed_lo = own.probed_lo;
    kept.probed_hi = own.probed_hi;
    for (std::size_t k = 0; k < own.point.size(); ++k) {
      const double h = field.at(own.point[k]);
      // A sample whose wall has mirrors gives way to one within 1.5 spacings (the mirrors'
      // gaps are their side's, up to a spacing there, and the field may be finer on this side:
      // within one spacing, a plate's own sample 0.5 from the mirrors stayed, and bent its
      // sheet 35 % of the thickness off the mid-plane); any other, to one that would crowd it.
      const double r = slave[f][k] ? 1.5 * h : 0.5 * h;
      const bool near = grid.any_near(own.point[k], r, [&](int j) { return dist2(m.point[j], own.point[k]) < r * r; });
      if (near) {
        ++st.replaced;
        continue;
      }
      kept.point.push_back(own.point[k]);
      kept.normal.push_back(own.normal[k]);
      kept.curvature.push_back(own.curvature[k]);
      kept.uv.push_back(own.uv[k]);
    }
    st.mirrored += m.point.size();
    kept.point.insert(kept.point.end(), m.point.begin(), m.point.end());
    kept.normal.insert(kept.normal.end(), m.normal.begin(), m.normal.end());
    kept.curvature.insert(kept.curvature.end(), m.curvature.begin(), m.curvature.end());
    kept.uv.insert(kept.uv.end(), m.uv.begin(), m.uv.end());
    own = std::move(kept);
  }
  return st;
}

}  // namespace cadmedial
