// Plain data shared by every stage of the pipeline: points, the medial mesh, parameters.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace cadmedial {

using Point3 = std::array<double, 3>;

/// What produced a face of the medial mesh.
enum class FaceKind : std::uint8_t {
  Voronoi = 0,  ///< a Voronoi facet dual to a selected Delaunay edge (3, 4.2.6)
  Edge = 1,     ///< a completion triangle at a convex edge (4.2.2)
  Corner = 2,   ///< a completion triangle at a non-concave corner (4.2.3)
};

const char* face_kind_name(FaceKind kind);

/// An indexed polygon mesh: faces share vertices. Polygons are stored flat (CSR):
/// face f has the vertices face_vertices[face_start[f] .. face_start[f+1]).
struct MedialMesh {
  std::vector<Point3> vertices;    ///< #V positions
  std::vector<double> radius;      ///< #V medial radius: distance to the solid's boundary (the B-rep)
  std::vector<int> face_start{0};  ///< #F+1 offsets into face_vertices
  std::vector<int> face_vertices;  ///< vertex indices of all polygons, counter-clockwise is not implied
  std::vector<FaceKind> kind;      ///< #F
  std::vector<int> solid;          ///< #F index of the input solid the face belongs to
  /// #E segments of the axis that no face carries: where the medial axis is a curve (a torus's
  /// core circle) the Voronoi facets around it can degenerate, and a Voronoi edge is all that
  /// joins two parts. Vertex index pairs.
  std::vector<std::array<int, 2>> edges;
  std::vector<int> edge_solid;     ///< #E index of the input solid the edge belongs to

  std::size_t num_vertices() const { return vertices.size(); }
  std::size_t num_faces() const { return kind.size(); }
  std::size_t num_edges() const { return edges.size(); }
  int face_size(std::size_t f) const { return face_start[f + 1] - face_start[f]; }
  const int* face(std::size_t f) const { return face_vertices.data() + face_start[f]; }

  /// Appends a polygon; returns its index.
  std::size_t add_face(const std::vector<int>& polygon, FaceKind face_kind, int solid_index);
  /// The vertices that faces or 1-D edges of solid `solid_index` use, in index order.
  std::vector<int> vertices_of_solid(int solid_index) const;
  /// Appends another mesh (its vertices are renumbered).
  void append(const MedialMesh& other);
  /// Orders vertices by position and faces and edges by their vertices (each polygon starting at
  /// its smallest vertex, towards its smaller neighbour): the same axis gives the same file,
  /// whatever order the triangulation visited it in.
  void sort_canonically();
};

/// Density of the boundary sample (4.2.1). Exactly one of spacing / target_samples may be set;
/// with neither, the spacing is chosen for about default_target_samples samples.
struct SamplingParams {
  double spacing = 0.0;              ///< model units; 0 = derive
  std::size_t target_samples = 0;    ///< approximate total over all solids; 0 = derive
  /// Where walls are too thin for the spacing to carry the axis's topology, sample them again
  /// more densely (down to a quarter of the spacing; to what the thinnest wall needs, at most a
  /// 32nd, where that takes at most 3 times the samples); the target count is the uniform
  /// sampling's.
  bool adapt_to_walls = true;
  /// Where a solid's medial axis comes out with an Euler characteristic other than the solid's
  /// (holes or extra loops where the samples are too sparse for its walls), sample that solid
  /// again with 2.5 times the samples and compute it anew, at most twice. The command line and
  /// Python turn this on when the user gives no density.
  bool refine_topology = false;
  /// Walls thinner than this (model units; 0 = none) are not sampled finer than it needs: the
  /// user's "ignore features below 0.01 mm". What it leaves unresolved is named in a warning.
  double min_feature = 0.0;
  static constexpr std::size_t default_target_samples = 20000;
};

/// Selection thresholds of CAD_MEDIAL (section 3 and 4.2.2).
struct MedialParams {
  double theta_deg = 5.0;  ///< Angle condition threshold, degrees, in (0, 90)
  double rho = 8.0;        ///< Ratio condition threshold, > 0
  /// Plain MEDIAL (section 3) instead of CAD_MEDIAL, for the ablation: umbrellas from the poles
  /// (the Delaunay triangles dual to Voronoi edges that the tangent plane at p, normal to the
  /// pole vector, crosses), no convex-edge or corner completion. The paper uses theta = 22.5.
  bool plain_medial = false;
};

/// The compact mesh (compact/simplify_axis.h): the axis simplified within a tolerance.
struct CompactParams {
  double tolerance = 0.0;  ///< 0 keeps the full Voronoi axis; model units, or a share of the diagonal
  bool relative = false;   ///< tolerance is a share of the solids' bounding-box diagonal (0.001 = 0.1 %)
};

struct ComputeParams {
  SamplingParams sampling;
  MedialParams medial;
  CompactParams compact;
};

/// Seconds per named stage, in the order they ran.
using Timings = std::vector<std::pair<std::string, double>>;

}  // namespace cadmedial
