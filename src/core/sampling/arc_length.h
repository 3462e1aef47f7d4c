// Arc length along an edge's curve, and the parameter at a given arc length.
#pragma once

#include <vector>

class Adaptor3d_Curve;

namespace cadmedial {

/// Lines and circles use OpenCASCADE's closed form (GCPnts_AbscissaPoint). Any other curve is
/// tabulated once over [t0, t1]: pieces, each split in two until 8-point Gauss-Legendre agrees
/// with itself on the halves (relative 1e-10), with the length from t0 to each piece's end.
/// GCPnts_AbscissaPoint integrates again from its start for every point, its length without a
/// tolerance comes out 5 % short on a wiggly periodic B-spline (EngineBlock.FCStd's cylinder-head
/// outline: 444.2 against 468.2), and its Newton search fails there ("no result").
/// The curve must outlive this object.
class ArcLength {
 public:
  ArcLength(const Adaptor3d_Curve& curve, double t0, double t1);
  ArcLength(const Adaptor3d_Curve&& curve, double t0, double t1) = delete;  // it keeps a reference

  /// The arc length from parameter a to b, t0 <= a <= b <= t1.
  double length(double a, double b) const;
  /// The parameter at arc length ds from parameter `from` (backwards when ds < 0), clamped to
  /// [t0, t1].
  double parameter(double ds, double from) const;

 private:
  double speed(double t) const;
  double gauss(double a, double b) const;
  void add_pieces(double a, double b, double whole, int depth);
  double length_to(double t) const;  // from t0
  double parameter_at(double s) const;  // s from t0

  const Adaptor3d_Curve& curve_;
  bool closed_form_;
  double tolerance_ = 0;  ///< on a piece's length (kRelative of the whole)
  std::vector<double> end_;     ///< piece ends: t0, then each piece's end
  std::vector<double> before_;  ///< arc length from t0 to end_[i]
};

}  // namespace cadmedial
