#include "thin_walls.h"

#include <algorithm>
#include <limits>

#include "point_grid.h"

namespace cadmedial {

namespace {

double dot3(const Point3& a, const Point3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

bool on_face(const Samples& s, std::size_t i) { return s.tag[i] == SampleTag::Face || s.tag[i] == SampleTag::Triplet; }

}  // namespace

ThinWall thinnest_wall(const Samples& s, double spacing, const Progress& progress) {
  // The ball tangent at p (outward normal n) through q has radius |q - p|^2 / (2 (p - q).n): the
  // shrinking-ball estimate of the medial radius at p. Only a facing wall counts: across a convex
  // or concave edge the ball shrinks too, but there the axis meets the edge by construction. A
  // ball smaller than the spacing through q lies within two spacings of p.
  // Near a convex edge of less than 60 degrees the two faces face each other too, and the wedge
  // thins to nothing at the edge, where the completion (4.2.2) joins the axis to the edge: face
  // samples within a spacing of a convex-edge sample are not asked.
  ThinWall w;
  const double reach = 2.0 * spacing;
  PointGrid grid(reach), convex(spacing);
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (on_face(s, i)) grid.insert(s.points[i], static_cast<int>(i));
    if (s.edge_convex[i] == 1) convex.insert(s.points[i], static_cast<int>(i));
  }
  const double spacing2 = spacing * spacing, reach2 = reach * reach;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (i % 4096 == 0) report(progress, "thin walls", static_cast<double>(i) / s.size());
    if (!on_face(s, i)) continue;
    const Point3 &p = s.points[i], &n = s.normal[i];
    if (convex.any_near(p, spacing, [&](int j) { return distance2(s.points[j], p) < spacing2; })) continue;
    double radius = std::numeric_limits<double>::infinity();
    grid.any_near(p, reach, [&](int j) {
      if (dot3(n, s.normal[j]) > -0.5) return false;
      const Point3 d{s.points[j][0] - p[0], s.points[j][1] - p[1], s.points[j][2] - p[2]};
      const double d2 = dot3(d, d);
      const double depth = -dot3(d, n);  // how far q lies inside p's tangent plane
      if (depth > 0 && d2 < reach2) radius = std::min(radius, d2 / (2.0 * depth));
      return false;
    });
    if (!(radius < spacing)) continue;
    ++w.samples;
    if (radius < w.radius) w.radius = radius, w.at = p;
  }
  return w;
}

}  // namespace cadmedial
