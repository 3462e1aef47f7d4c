#include "sample_votes.h"

#include <cmath>

#include "geometry_3.h"

namespace cadmedial::internal {

// 4.2.5 with the exact solid at hand. A Voronoi vertex x is the centre of a ball through its
// cell's samples p that holds no sample. Each sample votes with the side of its face's tangent
// plane that x lies on (at a sharp edge, the two faces' half-spaces: inside both for convex,
// either for concave). A vote counts only when x clears the plane by more than the surface can
// bend within |x - p| (kappa |x - p|^2 / 2); the empty ball keeps other sheets of the surface
// from passing between p and x unless the sampling missed them. Vertices with a dissenting vote
// or none go to the exact B-rep classifier; vertices beyond the samples' box or with a ball
// larger than it are outside.
int vote(const Samples& samples, int s, const Point3& x) {
  const Point3 d = sub(x, samples.points[s]);
  const double r2 = dot(d, d);
  const double margin = 0.5 * samples.curvature[s] * r2 + 1e-12 * std::sqrt(r2);
  const SampleTag tag = samples.tag[s];
  const bool on_edge = tag == SampleTag::Edge || tag == SampleTag::Ball;
  if (tag == SampleTag::Face || tag == SampleTag::Triplet || (on_edge && samples.edge_convex[s] == 0)) {
    const double a = dot(d, samples.normal[s]);
    if (dot(samples.normal[s], samples.normal[s]) == 0) return 0;
    return a < -margin ? 1 : a > margin ? -1 : 0;
  }
  if (on_edge) {
    const double a1 = dot(d, samples.normal[s]), a2 = dot(d, samples.normal2[s]);
    const bool in1 = a1 < -margin, in2 = a2 < -margin, out1 = a1 > margin, out2 = a2 > margin;
    if (samples.edge_convex[s] == 1) return (in1 && in2) ? 1 : (out1 || out2) ? -1 : 0;
    return (in1 || in2) ? 1 : (out1 && out2) ? -1 : 0;
  }
  return 0;
}

bool straddles(const MedialComplex& mc, const Samples& samples, int cell) {
  bool in = false, out = false;
  for (int s : mc.cell_samples[cell]) {
    const int v = vote(samples, s, mc.centers[cell]);
    in = in || v > 0, out = out || v < 0;
  }
  return in && out;
}

void mark_far_outside(const Samples& samples, const Point3& lo, const Point3& hi, MedialComplex& mc,
                      std::size_t begin, std::size_t end) {
  // The margin keeps a vertex that merges with a near one (coincident_cells: within 1e-9 of the
  // diagonal) beyond too.
  const double diag = norm(sub(hi, lo)), margin = 1e-6 * diag;
  for (std::size_t id = begin; id < end; ++id) {
    const bool far = beyond_box(mc.centers[id], mc.radii[id], lo, hi, diag, margin);
    mc.surely_outside[id] = far && !mc.flat[id] && !straddles(mc, samples, static_cast<int>(id));
    mc.voted[id] = MedialComplex::kNotVoted;
  }
}

void mark_voted_outside(const Samples& samples, double eps, MedialComplex& mc, std::size_t begin, std::size_t end) {
  for (std::size_t id = begin; id < end; ++id) {
    if (mc.surely_outside[id] || mc.flat[id]) continue;
    const Point3& x = mc.centers[id];
    // A cell that merges with a neighbour (coincident_cells: centres within eps) is labelled
    // through its group's representative, at the group's centre: left to label_inside.
    bool merges = false;
    for (int nb : mc.cell_neighbors[id])
      if (nb >= 0) merges = merges || mc.centers[nb] == x || norm(sub(mc.centers[nb], x)) <= eps;
    if (merges) continue;
    int in = 0, out = 0;
    for (int s : mc.cell_samples[id]) {
      const int v = vote(samples, s, x);
      in += v > 0, out += v < 0;
    }
    const int settled = votes_settle(in, out);
    mc.voted[id] = static_cast<std::int8_t>(settled);
    mc.surely_outside[id] = settled == 0;
  }
}

}  // namespace cadmedial::internal
