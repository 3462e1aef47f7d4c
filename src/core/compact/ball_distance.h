// How far a medial ball (centre, radius) is from a triangle or a segment of a medial mesh whose
// vertices carry radii: |c - q| + |r - r(q)| at the point q of the triangle nearest c, r(q) the
// radius interpolated there. That sum bounds the Hausdorff distance between the ball and the
// mesh's ball at q, so it bounds how much a union of balls changes (the reconstruction error).
#pragma once

#include <algorithm>
#include <cmath>

#include "../types.h"

namespace cadmedial::compact {

struct Ball {
  Point3 c;
  double r;
};

inline Point3 sub(const Point3& a, const Point3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline double dot(const Point3& a, const Point3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Point3 cross(const Point3& a, const Point3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

/// |p.c - q| + |p.r - r(q)|, q the point of segment ab nearest p.c.
inline double ball_to_segment(const Ball& p, const Ball& a, const Ball& b) {
  const Point3 ab = sub(b.c, a.c);
  const double len2 = dot(ab, ab);
  const double t = len2 > 0 ? std::clamp(dot(sub(p.c, a.c), ab) / len2, 0.0, 1.0) : 0.0;
  const Point3 q{a.c[0] + t * ab[0], a.c[1] + t * ab[1], a.c[2] + t * ab[2]};
  const Point3 d = sub(p.c, q);
  return std::sqrt(dot(d, d)) + std::abs(p.r - (a.r + t * (b.r - a.r)));
}

/// |p.c - q| + |p.r - r(q)|, q the point of triangle abc nearest p.c (Ericson, Real-Time
/// Collision Detection, 5.1.5), r(q) interpolated barycentrically.
inline double ball_to_triangle(const Ball& p, const Ball& a, const Ball& b, const Ball& c) {
  const Point3 ab = sub(b.c, a.c), ac = sub(c.c, a.c), ap = sub(p.c, a.c);
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  double u = 1, v = 0, w = 0;  // barycentric weights of a, b, c
  const auto done = [&] {
    const Point3 q{u * a.c[0] + v * b.c[0] + w * c.c[0], u * a.c[1] + v * b.c[1] + w * c.c[1],
                   u * a.c[2] + v * b.c[2] + w * c.c[2]};
    const Point3 d = sub(p.c, q);
    return std::sqrt(dot(d, d)) + std::abs(p.r - (u * a.r + v * b.r + w * c.r));
  };
  if (d1 <= 0 && d2 <= 0) return done();
  const Point3 bp = sub(p.c, b.c);
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return u = 0, v = 1, done();
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double t = d1 / (d1 - d3);
    return u = 1 - t, v = t, done();
  }
  const Point3 cp = sub(p.c, c.c);
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return u = 0, w = 1, done();
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double t = d2 / (d2 - d6);
    return u = 1 - t, w = t, done();
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    const double t = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return u = 0, v = 1 - t, w = t, done();
  }
  const double sum = va + vb + vc;
  if (!(sum > 0))  // a degenerate triangle: its sides
    return std::min({ball_to_segment(p, a, b), ball_to_segment(p, b, c), ball_to_segment(p, a, c)});
  v = vb / sum, w = vc / sum, u = 1 - v - w;
  return done();
}

}  // namespace cadmedial::compact
