// CSLib_Class2d's point-in-polygon answer (what BRepTopAdaptor_FClass2d::Perform asks of each of
// a face's wires), found among the few polygon edges near the point instead of all of them.
#pragma once

#include <vector>

namespace cadmedial {

/// A polygon as CSLib_Class2d stores it (OpenCASCADE 7.6, CSLib_Class2d::Init): n + 1 points,
/// the last equal to the first, in coordinates scaled to the bounds where their extent exceeds
/// 1e-10; the tolerances scaled likewise.
struct StoredPolygon {
  std::vector<double> x, y;  ///< n + 1 stored coordinates
  double tolu = 0, tolv = 0;
  double umin = 0, umax = 0, vmin = 0, vmax = 0;
  int n() const { return static_cast<int>(x.size()) - 1; }
};

/// The same answers as CSLib_Class2d::SiDans (1 inside, -1 outside, 0 on the boundary within
/// tolerance), bit for bit: each edge's own test is CSLib_Class2d's expression for expression,
/// and SiDans's crossing parity and "on" tests depend on each edge alone, so only the edges
/// whose y range can meet the horizontal line through the point (within the tolerance) are
/// looked at. Those are kept in bands of y. tests/cpp/sampling/test_polygon_classifier.cpp
/// compares the two.
class PolygonClassifier {
 public:
  explicit PolygonClassifier(StoredPolygon polygon);

  int si_dans(double u, double v) const;

  /// CSLib_Class2d::InternalSiDans and InternalSiDansOuOn (stored coordinates): the crossing
  /// parity, and -1 for "on" in the second.
  int internal_si_dans(double px, double py) const;
  int internal_si_dans_ou_on(double px, double py) const;

 private:
  int band_of(double y) const;
  bool crosses(int i, double px, double py) const;

  StoredPolygon p_;
  double y0_ = 0, band_height_ = 1;
  int bands_ = 1;
  std::vector<int> start_, edges_;  ///< CSR: band b holds edges edges_[start_[b]..start_[b+1])
};

}  // namespace cadmedial
