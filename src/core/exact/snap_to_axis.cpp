#include "snap_to_axis.h"

#include <cmath>
#include <cstdint>
#include <vector>

#include "../two_cores.h"
#include "boundary_distance.h"

namespace cadmedial {

namespace {

Point3 along(const Point3& p, const Point3& n, double t) { return {p[0] + t * n[0], p[1] + t * n[1], p[2] + t * n[2]}; }

// The largest t <= t_max with the ball B(p + t n, t) inside the solid, from t0 (whose ball is
// inside), or a negative number when the search does not settle.
double largest_tangent_ball(BoundaryDistance& dist, const Point3& p, const Point3& n, double t0, double t_max,
                            double eps) {
  // Grow until the ball is not inside (another boundary point comes nearer than t), or t_max.
  double t = t0;
  BoundaryDistance::Nearest q;
  for (;;) {
    const double next = std::min(t_max, t0 + 2 * (t - t0) + eps * 1e3 + 0.25 * t0);
    q = dist.nearest(along(p, n, next), next + eps);
    if (q.distance < next - eps) {
      t = next;
      break;
    }
    if (next >= t_max) return -1;  // the ball grows past the reach: no axis point near
    t = next;
  }
  // Shrink: the ball tangent at p through the nearer point q, until no point is nearer.
  for (int it = 0; it < 40; ++it) {
    const Point3 d{q.point[0] - p[0], q.point[1] - p[1], q.point[2] - p[2]};
    const double dn = d[0] * n[0] + d[1] * n[1] + d[2] * n[2];
    if (!(dn > 0)) return -1;
    const double shrunk = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) / (2 * dn);
    if (!(shrunk < t)) return t;
    t = shrunk;
    if (t < t0 - eps) return -1;  // below the ball known to be inside: the foot was not p
    q = dist.nearest(along(p, n, t), t + eps);
    if (q.distance >= t - eps) return t;
  }
  return -1;
}

}  // namespace

SnapStats snap_to_axis(const TopoDS_Solid& solid, int solid_index, double diag, double reach, MedialMesh& mesh) {
  SnapStats st;
  const std::vector<int> todo = mesh.vertices_of_solid(solid_index);
  st.vertices = todo.size();
  if (todo.empty()) return st;
  const double eps = 1e-9 * diag;
  std::vector<double> moved(todo.size(), -1.0);
  BoundaryDistance dist[2] = {BoundaryDistance(solid), BoundaryDistance(solid)};
  internal::on_two_halves(todo.size(), [&](int part, std::size_t, std::size_t) {
    for (std::size_t k = static_cast<std::size_t>(part); k < todo.size(); k += 2) {
      const int v = todo[static_cast<std::size_t>(k)];
      const Point3 x = mesh.vertices[static_cast<std::size_t>(v)];
      const double r = mesh.radius[static_cast<std::size_t>(v)];
      if (!(r > 10 * eps)) continue;
      const BoundaryDistance::Nearest foot = dist[part].nearest(x, r + 10 * eps);
      if (foot.face < 0 || foot.side > 0) continue;
      const Point3 n{-foot.normal[0], -foot.normal[1], -foot.normal[2]};
      const double t = largest_tangent_ball(dist[part], foot.point, n, foot.distance, foot.distance + reach, eps);
      if (!(t > 0)) continue;
      mesh.vertices[static_cast<std::size_t>(v)] = along(foot.point, n, t);
      mesh.radius[static_cast<std::size_t>(v)] = t;
      moved[k] = t - foot.distance;
    }
  }, 64);
  double sum = 0;
  for (double m : moved) {
    if (m < 0) continue;
    ++st.snapped;
    sum += m;
    st.max_move = std::max(st.max_move, m);
  }
  st.mean_move = st.snapped ? sum / static_cast<double>(st.snapped) : 0.0;
  return st;
}

}  // namespace cadmedial
