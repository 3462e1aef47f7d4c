// Plain data of the boundary sample (4.2.1): points with their tags, normals, triplets and each
// face's samples in its parameter plane. No OpenCASCADE types, so CGAL code can include it.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "../types.h"

namespace cadmedial {

enum class SampleTag : std::uint8_t {
  Corner = 0,   ///< a vertex of the solid
  Ball = 1,     ///< where the ball around a sharp corner meets an incident edge
  Edge = 2,     ///< on an edge
  Triplet = 3,  ///< s_l or s_r of a triplet (on a face, beside a convex edge)
  Face = 4,     ///< in a face's interior
};

/// A triplet s, s_l, s_r across a convex edge (4.2.1), with s's neighbours s', s'' on the edge.
struct Triplet {
  int s = -1, sl = -1, sr = -1;
  int prev = -1, next = -1;  ///< adjacent samples of s on the edge (-1 at none)
};

/// A face's samples in its parameter plane, for the face-by-face reconstruction (4.2.4).
/// A sample on a seam or a degenerate edge appears more than once.
struct FaceDomain {
  std::vector<int> sample;                       ///< global sample index per local point
  std::vector<std::array<double, 2>> uv;         ///< parameters per local point
  std::vector<std::array<int, 2>> boundary;      ///< consecutive boundary points (local indices)
  double u_scale = 1.0, v_scale = 1.0;           ///< lengths per unit parameter, to make uv isotropic
};

/// A convex edge whose two faces' outward normals meet with a dot product below this is a sharp
/// wedge (under 18 degrees): the sampling, the thin-wall check and the inner axis treat it apart.
constexpr double kSharpWedgeDot = -0.95;

struct Samples {
  std::vector<Point3> points;
  std::vector<SampleTag> tag;
  std::vector<Point3> normal;      ///< outward unit normal on Face/Triplet samples and of the first
                                   ///< face on Edge/Ball samples; zero on corners
  std::vector<Point3> normal2;     ///< on Edge/Ball samples: the second face's normal
  std::vector<std::uint8_t> edge_convex;  ///< on Edge/Ball samples: 1 convex, 2 concave, 0 smooth here
  std::vector<float> curvature;    ///< largest principal curvature of the face(s) at the sample
  std::vector<int> face;           ///< face of Face/Triplet samples, -1 elsewhere
  std::vector<int> edge;           ///< edge of Edge/Ball samples, -1 elsewhere
  std::vector<int> vertex;         ///< vertex of Corner samples, -1 elsewhere
  std::vector<std::uint8_t> nonconcave;  ///< 1 on non-concave corner samples
  std::vector<Triplet> triplets;
  std::vector<FaceDomain> faces;   ///< per face of the solid
  double spacing = 0.0;

  std::size_t size() const { return points.size(); }
  /// On an Edge/Ball sample: the dot product of its two faces' outward normals (1 where they do
  /// not turn; below kSharpWedgeDot at a sharp wedge).
  double normals_dot(std::size_t i) const {
    const Point3 &a = normal[i], &b = normal2[i];
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  }
};

}  // namespace cadmedial
