// How much of each sharp convex edge of a solid its inner axis reaches (issue 32, item 4): the
// completion joins the axis to every convex edge, and where walls beside an edge are about a
// spacing thick it may not; nothing else in the output says so.
#pragma once

#include <vector>

#include "../sampling/samples.h"
#include "../sampling/spacing_field.h"
#include "../types.h"

namespace cadmedial {

/// A convex edge that the axis reaches along less than the threshold share of its length.
struct ShortEdge {
  int edge = -1;          ///< index in the solid's edges (TopExp::MapShapes order, 0-based)
  double reached = 0.0;   ///< share of its samples within the spacing of an axis vertex
  Point3 at{0, 0, 0};     ///< one of its samples that is not reached
};

struct EdgeReach {
  /// Share of the samples on sharp convex edges (their faces turn by more than kTurnDegrees)
  /// within the solid's uniform spacing of an output vertex; 1 with no such edge.
  double reached = 1.0;
  std::vector<ShortEdge> short_edges;  ///< the edges reached along less than kReachedShare
  static constexpr double kTurnDegrees = 10.0;
  static constexpr double kReachedShare = 0.98;
};

/// Edge samples are about evenly spaced along their edge, so the share of an edge's samples is
/// the share of its length. `vertices` are the solid's output vertices.
EdgeReach convex_edge_reach(const Samples& samples, const SpacingField& field, const std::vector<Point3>& vertices);

}  // namespace cadmedial
