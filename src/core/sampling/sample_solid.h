// Sampling of the exact B-rep as in 4.2.1: corners, the ball rule around sharp corners, edges at a
// regular spacing, triplets across convex edges, and face interiors evenly in space.
#pragma once

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <vector>

#include <TopoDS_Solid.hxx>

#include "../features/classify_features.h"
#include "../progress.h"
#include "../types.h"
#include "samples.h"
#include "spacing_field.h"

namespace cadmedial {

/// Sample parameters derived from the density: spacing h of face samples; sharp edges get h/2
/// and triplet legs h/2; curved regions shrink the spacing to keep chords within a few degrees.
struct SampleSpacing {
  double face = 0.0;
  double edge = 0.0;
  double triplet = 0.0;
  double min_face = 0.0;     ///< floor of the curvature refinement
  double max_turn_rad = 0.0; ///< largest angle a chord between neighbours may turn on a curve

  /// The face spacing where the surface's largest principal curvature is `curvature`: finer
  /// where it curves, down to min_face.
  double face_at(double curvature) const {
    return curvature > 0 ? std::clamp(max_turn_rad / curvature, min_face, face) : face;
  }
  /// The same where the local spacing is h (finer than `face` at thin walls): finer where it
  /// curves, down to min_face or h if that is finer.
  double face_at(double curvature, double h) const {
    return curvature > 0 ? std::clamp(max_turn_rad / curvature, std::min(min_face, h), h) : h;
  }
};
SampleSpacing sample_spacing(double spacing);

/// Samples one solid. Deterministic for a given input.
Samples sample_solid(const TopoDS_Solid& solid, const Features& features, double spacing,
                     const Progress& progress = {});
/// The same with a spacing that varies (thin walls): an edge takes its smallest, face lattice
/// cells are cut finer where the field is smaller than the face's spacing.
Samples sample_solid(const TopoDS_Solid& solid, const Features& features, const SpacingField& field,
                     const Progress& progress = {});

class FaceDomainBuilder;

/// A solid's per-face set-up that no spacing changes (each face's surface adaptor and boundary
/// classifier), made ahead: the pipeline makes it on its second core while the features are
/// classified (on the Y-rod mount, 6 ms of its first pass's 23 at 10k samples). The faces in
/// TopExp::MapShapes order, as Features::faces.
class FaceSetup {
 public:
  FaceSetup();
  ~FaceSetup();
  FaceSetup(FaceSetup&&) noexcept;
  FaceSetup& operator=(FaceSetup&&) noexcept;

  /// Returns early when `stop` is set; the sampler makes the faces not made by then. A face
  /// OpenCASCADE fails on is left to the sampler too, which reports the failure when it gets there.
  static FaceSetup make(const TopoDS_Solid& solid, const std::atomic<bool>* stop = nullptr);

  struct Data;

 private:
  friend class SolidSampler;
  std::unique_ptr<Data> data_;
};

/// Samples one solid pass after pass (calibrating the spacing, refining thin walls) without redoing
/// what a pass leaves unchanged: each face's surface, classifier and candidate lattice and, when a
/// pass repeats the last uniform pass's spacing, the interior samples of every face that is not
/// refined and near which no earlier sample changed. The samples are those sample_solid places.
class SolidSampler {
 public:
  /// Keeps copies of the solid's handle and of `features`, and takes over `faces` (made for this
  /// solid) where it has them.
  SolidSampler(const TopoDS_Solid& solid, const Features& features, FaceSetup faces = {});
  ~SolidSampler();
  SolidSampler(const SolidSampler&) = delete;
  SolidSampler& operator=(const SolidSampler&) = delete;

  Samples sample(const SpacingField& field, const Progress& progress = {});
  /// The same with the face domains (Samples::faces: as many as faces, empty) left to `domains`,
  /// which can build them on another thread. Only the reconstruction reads them: the pipeline
  /// builds them beside the triangulation (on the Y-rod mount at 10k samples, 2 + 3 ms of its
  /// two passes, one of which is given up).
  Samples sample(const SpacingField& field, FaceDomainBuilder& domains, const Progress& progress = {});
  /// How many faces the last sample() took over from the pass before.
  int kept_faces() const;
  /// Whether walls thinner than a few spacings are sampled in mirrored pairs
  /// (mirror_thin_walls.h); on by default.
  void mirror_thin_walls(bool on);
  bool mirrors_thin_walls() const;
  /// How many face samples the last sample() placed as mirrors of a thin wall's other side.
  std::size_t mirrored() const;
  /// edge_wall_radii (edge_walls.h) of a sampling this sampler made, for walls up to 2 r_max thick.
  std::vector<double> edge_wall_radii(const Samples& samples, double r_max);

  struct State;

 private:
  std::unique_ptr<State> state_;
};

/// What a sampling's face domains are made of: each face's boundary chains (their samples and
/// curve parameters) and its other samples in its parameter plane. Needs the SolidSampler that
/// filled it (its features) to live while it builds.
class FaceDomainBuilder {
 public:
  FaceDomainBuilder();
  ~FaceDomainBuilder();
  FaceDomainBuilder(FaceDomainBuilder&&) noexcept;
  FaceDomainBuilder& operator=(FaceDomainBuilder&&) noexcept;

  /// Whether build() has something to do.
  bool pending() const { return data_ != nullptr; }
  /// Fills s.faces, the domains of the sampling that filled this builder, and empties it.
  /// Throws GeometryError when OpenCASCADE fails on a face's curves.
  void build(Samples& s);

  struct Data;

 private:
  friend class SolidSampler;
  std::unique_ptr<Data> data_;
};

/// Surface area of the solid's faces and the total length of its edges (for planning).
struct SolidMeasure {
  double area = 0.0;
  double sharp_edge_length = 0.0;
  double convex_edge_length = 0.0;
  struct Piece {
    double size;       ///< area of a face, length of a sharp edge
    double curvature;  ///< typical largest principal curvature (faces) or curvature (edges)
    bool convex;       ///< a convex edge (it takes triplets)
    /// Faces: the length of their convex and of their concave edges (a strip along each gets
    /// no interior samples).
    double convex_edges = 0.0, concave_edges = 0.0;
    int edge = -1;  ///< sharp edges: the edge's index in Features::edges (0-based)
  };
  std::vector<Piece> faces, sharp_edges;
};

/// Approximate number of samples sample_solid places at `spacing` (the same density rules).
double estimate_samples(const SolidMeasure& m, double spacing);
SolidMeasure measure_solid(const TopoDS_Solid& solid, const Features& features);

/// Approximate number of samples sample_solid places with a spacing that varies, from `first`, its
/// uniform sampling at field.uniform() (0.74 to 1.06 of the count on the parts of
/// ../shared/data/models but NIST CTC 03, 0.62 there, far over any budget). A face's interior
/// samples in `first` stand for (own / local)^2 each (own: their spacing, finer where the surface
/// curves; local at most 13 times finer, as fine as the sampler goes); a face with fewer than 8
/// counts by its area, less the strips along its edges, at the mean spacing around it; a sharp
/// edge and its triplets by its length at its smallest spacing (the sampler spaces the whole edge
/// by it), any other edge by its samples in `first`; corners and ball samples as in `first`.
double estimate_samples(const SolidMeasure& m, const Features& features, const SpacingField& field,
                        const Samples& first);

}  // namespace cadmedial
