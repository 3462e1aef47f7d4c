// The sample spacing as a field: uniform, or smaller where a first sampling found walls too thin
// for it (thin_walls.h), growing back gradually away from them.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "../types.h"
#include "point_grid.h"
#include "samples.h"

namespace cadmedial {

class SpacingField {
 public:
  /// The same spacing everywhere.
  explicit SpacingField(double spacing) : spacing_(spacing), grid_(spacing) {}

  /// min(spacing, min over k of local[k] + gradation max(0, |x - points[k]| - spacing)): each
  /// point's spacing holds within a (uniform) spacing of it, where the first pass had no other
  /// sample to say, and then grows with a bounded slope, so the density changes gradually.
  /// Points whose spacing the others already give (within 10 %) are dropped.
  SpacingField(double spacing, const std::vector<Point3>& points, const std::vector<double>& local, double gradation);

  double uniform() const { return spacing_; }
  bool is_uniform() const { return points_.empty(); }
  double smallest() const { return smallest_; }
  double at(const Point3& x) const;
  /// Whether at() looks points up in a dense box of cells (else in the hash grid).
  bool dense() const { return !cell_start_.empty(); }

  /// The smallest spacing at the samples of each face and each edge of a sampling of the solid
  /// (Samples::face, Samples::edge; a face also takes its edges' samples' through `edge_faces`):
  /// the sampler refines only those faces, and spaces an edge by its smallest.
  void measure_on(const Samples& samples, const std::vector<std::array<int, 2>>& edge_faces);
  double on_face(int f) const { return f >= 0 && f < static_cast<int>(face_.size()) ? face_[f] : spacing_; }
  double on_edge(int e) const { return e >= 0 && e < static_cast<int>(edge_.size()) ? edge_[e] : spacing_; }

 private:
  double reach() const { return spacing_ + (spacing_ - smallest_) / gradation_; }
  int64_t cell_of(double v) const { return static_cast<int64_t>(std::floor(v / reach_)); }
  void index_cells();

  double spacing_, gradation_ = 1.0, smallest_ = spacing_, reach_ = spacing_;
  std::vector<Point3> points_;
  std::vector<double> local_, face_, edge_;
  PointGrid grid_;  // cells as large as the farthest a point's spacing spreads
  // The same cells in a dense box once the field is made (at() runs for every lattice cell of a
  // refined face: a dense box spares it 27 hash lookups). Per cell, its points in grid_'s order,
  // the order they were added: smallest local first.
  struct Item {
    Point3 point;
    double local;
  };
  std::vector<int> cell_start_;
  std::vector<Item> items_;
  std::array<int64_t, 3> lo_{0, 0, 0}, size_{0, 0, 0};
};

/// Where the first sampling shows walls thinner than its spacing allows (radii from
/// wall_radii): a local spacing of `per_radius` times the wall's half thickness, at least
/// spacing / max_refine, spread with slope `gradation`. Uniform when no wall is thin.
SpacingField thin_wall_spacing(const Samples& first, const std::vector<double>& radii, double spacing,
                               double per_radius, double max_refine, double gradation);

}  // namespace cadmedial
