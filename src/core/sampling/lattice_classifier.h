// Point-in-face answers for a face's lattice of sampling candidates, identical to
// BRepTopAdaptor_FClass2d::Perform's but without calling it away from the face's boundary.
#pragma once

#include <cstdint>
#include <vector>

#include <BRepAdaptor_Surface.hxx>
#include <BRepTopAdaptor_FClass2d.hxx>
#include <CSLib_Class2d.hxx>
#include <TopAbs_State.hxx>
#include <gp_Pnt2d.hxx>

#include "polygon_classifier.h"

namespace cadmedial {

/// The polygon as `polygon` stores it (read from its private fields, as LatticeClassifier does).
StoredPolygon stored_polygon(const CSLib_Class2d& polygon);

/// Cells of a face's candidate lattice: cell (i, j) is [u0 + i du, u0 + (i+1) du] x
/// [v0 + j dv, v0 + (j+1) dv], for 0 <= i < nu, 0 <= j < nv.
struct UvLattice {
  double u0 = 0, v0 = 0, du = 1, dv = 1;
  long nu = 1, nv = 1;
};

/// Perform tests a point against one polygon per wire (CSLib_Class2d). A point whose tolerance
/// box meets no polygon gets each polygon's inside/outside parity, and so the same answer as
/// every point of a connected set that no tolerance box around the polygons reaches. So the
/// lattice cells those boxes may reach are marked, the other cells fall into connected regions,
/// and Perform's polygon tests run once per region (on the first point asked there), once for all
/// points away from every polygon's bounding box; a point in a marked cell is left to Perform
/// (Ask), or to exact(), the same tests through PolygonClassifier (the polygon edges near the
/// point; Perform scans every edge five times, and builds a surface adaptor, on each call). On a
/// periodic surface Perform retries a point outside at shifted copies; so does this, in the same
/// order.
///
/// Reads the classifier's polygons, which OpenCASCADE keeps private. Written from OCC 7.7.0's
/// BRepTopAdaptor_FClass2d.cxx and CSLib_Class2d.cxx and checked against 7.6.3 (Debian 12) with
/// CADMEDIAL_VERIFY_LATTICE_CLASSIFIER (see the .cpp). The classifier must outlive this object.
class LatticeClassifier {
 public:
  enum class Answer : std::uint8_t {
    In,   ///< Perform(uv) returns TopAbs_IN
    Out,  ///< Perform(uv) returns something else
    Ask,  ///< near the boundary, or the classifier has no usable polygons: call Perform
  };

  /// `surface`: the classifier's face (its periodicity is what Perform uses).
  LatticeClassifier(const BRepTopAdaptor_FClass2d& classifier, const BRepAdaptor_Surface& surface,
                    const UvLattice& lattice);

  /// Perform's answer for `uv`, which lies in lattice cell (i, j).
  Answer classify(long i, long j, const gp_Pnt2d& uv);

  /// The same for any point.
  Answer classify(const gp_Pnt2d& uv);

  /// Perform's answer for any point, Ask only within a polygon's tolerance (where Perform asks
  /// BRepClass_FaceClassifier): for the points classify leaves to Perform, which the sampler asks
  /// only of the candidates it would keep.
  Answer exact(const gp_Pnt2d& uv);

 private:
  // Perform(uv, Standard_False): the polygons' answer without the periodic retries.
  enum class State : std::uint8_t { Unknown, In, Out, Ask };
  State polygon_state(long i, long j, const gp_Pnt2d& uv);
  State polygon_state(const gp_Pnt2d& uv);
  State remember(State& slot, const gp_Pnt2d& uv);
  State wires_state(const gp_Pnt2d& uv) const;
  Answer with_retries(const gp_Pnt2d& uv, State first, bool exact = false);
  Answer checked(Answer a, const gp_Pnt2d& uv) const;
  void mark_polygons();
  void label_regions();

  struct Box {
    double u0, u1, v0, v1;
  };

  const BRepTopAdaptor_FClass2d& classifier_;
  bool usable_ = false;
  bool u_periodic_ = false, v_periodic_ = false;
  double u_period_ = 0, v_period_ = 0;
  double umin_ = 0, umax_ = 0, vmin_ = 0, vmax_ = 0;  ///< the classifier's own bounds
  UvLattice lat_;
  std::vector<Box> wire_boxes_;       ///< each polygon's points' box, grown by its tolerance
  std::vector<PolygonClassifier> polygons_;  ///< per wire, in the classifier's order
  std::vector<int> orientation_;             ///< per wire: the classifier's TabOrien
  std::vector<std::int32_t> region_;  ///< per cell (i * nv + j): its region, or -1 if marked
  std::vector<State> region_state_;   ///< per region
  State far_state_ = State::Unknown;  ///< outside every wire box
};

}  // namespace cadmedial
