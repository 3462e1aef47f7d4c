#include "convex_edge_reach.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "../sampling/point_grid.h"

namespace cadmedial {

EdgeReach convex_edge_reach(const Samples& samples, const SpacingField& field, const std::vector<Point3>& vertices) {
  EdgeReach out;
  const double turn_cos = std::cos(EdgeReach::kTurnDegrees * 3.14159265358979323846 / 180.0);
  struct Count {
    std::size_t total = 0, reached = 0;
    int missed = -1;  // a sample not reached
  };
  std::unordered_map<int, Count> per_edge;
  std::vector<int> sharp;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    if (samples.edge_convex[i] != 1 || samples.edge[i] < 0) continue;
    if (samples.normals_dot(i) > turn_cos) continue;
    sharp.push_back(static_cast<int>(i));
  }
  if (sharp.empty()) return out;
  PointGrid grid(field.uniform());
  for (std::size_t v = 0; v < vertices.size(); ++v) grid.insert(vertices[v], static_cast<int>(v));
  std::size_t reached = 0;
  for (int i : sharp) {
    const Point3& p = samples.points[i];
    // Within the solid's uniform spacing, as docs/RESULTS.md counts it: a thin rib's sheet may
    // end a rib's thickness short of its end edges, finer than the user's spacing resolves.
    const double tol = field.uniform();
    const bool hit = grid.any_near(p, tol, [&](int v) {
      const Point3& q = vertices[v];
      const double dx = p[0] - q[0], dy = p[1] - q[1], dz = p[2] - q[2];
      return dx * dx + dy * dy + dz * dz <= tol * tol;
    });
    Count& c = per_edge[samples.edge[i]];
    ++c.total;
    if (hit)
      ++c.reached, ++reached;
    else if (c.missed < 0)
      c.missed = i;
  }
  out.reached = static_cast<double>(reached) / static_cast<double>(sharp.size());
  for (const auto& [edge, c] : per_edge) {
    const double share = static_cast<double>(c.reached) / static_cast<double>(c.total);
    if (share < EdgeReach::kReachedShare) out.short_edges.push_back({edge, share, samples.points[c.missed]});
  }
  // Least reached first; the order of an unordered_map is not the user's.
  std::sort(out.short_edges.begin(), out.short_edges.end(), [](const ShortEdge& x, const ShortEdge& y) {
    return x.reached != y.reached ? x.reached < y.reached : x.edge < y.edge;
  });
  return out;
}

}  // namespace cadmedial
