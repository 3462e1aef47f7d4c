// Arc length along edge curves: the tabulated length and the parameter at a given length agree
// with OpenCASCADE's adaptive integration (GCPnts_AbscissaPoint with a tolerance); lines and
// circles give exactly what OpenCASCADE's closed form gives.
#include <cmath>

#include <GCPnts_AbscissaPoint.hxx>
#include <GeomAdaptor_Curve.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_Circle.hxx>
#include <Geom_Ellipse.hxx>
#include <Geom_Line.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <gp_Ax2.hxx>
#include <gtest/gtest.h>

#include "core/sampling/arc_length.h"

namespace cadmedial {
namespace {

constexpr double kTol = 1e-12;  // GCPnts_AbscissaPoint's adaptive integration

// The reference: OpenCASCADE's length from a to b with a tolerance.
double reference_length(const GeomAdaptor_Curve& c, double a, double b) {
  return GCPnts_AbscissaPoint::Length(c, a, b, kTol);
}

// Every parameter at k/n of the length lies where the reference length from t0 is k/n of it,
// and every length between two of them is the reference's.
void expect_agrees_with_reference(const GeomAdaptor_Curve& c, int n) {
  const double t0 = c.FirstParameter(), t1 = c.LastParameter();
  const ArcLength arc(c, t0, t1);
  const double len = reference_length(c, t0, t1);
  ASSERT_GT(len, 0);
  EXPECT_NEAR(arc.length(t0, t1), len, 1e-9 * len);
  double previous = t0;
  for (int k = 1; k < n; ++k) {
    const double t = arc.parameter(len * k / n, t0);
    ASSERT_GT(t, previous) << k;
    EXPECT_NEAR(reference_length(c, t0, t), len * k / n, 1e-8 * len) << k;
    EXPECT_NEAR(arc.length(previous, t), reference_length(c, previous, t), 1e-8 * len) << k;
    // Backwards from the end, as the ball rule steps in from an edge's last corner.
    const double back = arc.parameter(-len * k / n, t1);
    EXPECT_NEAR(reference_length(c, back, t1), len * k / n, 1e-8 * len) << k;
    previous = t;
  }
}

TEST(ArcLength, EllipseWhoseSpeedVariesFiveFoldAgreesWithAdaptiveIntegration) {
  const GeomAdaptor_Curve c(new Geom_Ellipse(gp_Ax2(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), 5.0, 1.0));
  expect_agrees_with_reference(c, 37);
}

TEST(ArcLength, PeriodicZigzagBSplineWithUnevenSpansAgreesWithAdaptiveIntegration) {
  // A closed outline of 37 poles alternating 30 and 70 from the centre, spans of 13 and 1, and a
  // double knot at the seam (the speed jumps there): the kind of sketch outline a CSG part
  // extrudes.
  const int n = 37;
  TColgp_Array1OfPnt poles(1, n);
  for (int i = 0; i < n; ++i) {
    const double a = 2 * M_PI * i / n, r = i % 2 ? 70.0 : 30.0;
    poles(i + 1) = gp_Pnt(1.5 * r * std::cos(a), r * std::sin(a), 0);
  }
  TColStd_Array1OfReal knots(1, n);
  TColStd_Array1OfInteger mult(1, n);
  double t = 0;
  for (int i = 0; i < n; ++i) {
    knots(i + 1) = t;
    mult(i + 1) = i == 0 || i == n - 1 ? 2 : 1;
    t += i % 5 == 3 ? 1.0 : 13.0;
  }
  const GeomAdaptor_Curve c(new Geom_BSplineCurve(poles, knots, mult, 3, true));
  expect_agrees_with_reference(c, 101);
}

TEST(ArcLength, LinesAndCirclesGiveOpenCascadesClosedFormExactly) {
  const GeomAdaptor_Curve line(new Geom_Line(gp_Pnt(1, 2, 3), gp_Dir(1, 1, 0)), -2.5, 7.25);
  const GeomAdaptor_Curve circle(new Geom_Circle(gp_Ax2(gp_Pnt(0, 0, 0), gp_Dir(0, 1, 1)), 3.0), 0.5, 5.0);
  for (const GeomAdaptor_Curve* c : {&line, &circle}) {
    const double t0 = c->FirstParameter(), t1 = c->LastParameter();
    const ArcLength arc(*c, t0, t1);
    EXPECT_EQ(arc.length(t0, t1), GCPnts_AbscissaPoint::Length(*c, t0, t1));
    for (double ds : {0.1, 1.0, 3.3})
      EXPECT_EQ(arc.parameter(ds, t0 + 0.2), GCPnts_AbscissaPoint(*c, ds, t0 + 0.2).Parameter());
    EXPECT_EQ(arc.parameter(-1.0, t1), GCPnts_AbscissaPoint(*c, -1.0, t1).Parameter());
  }
}

TEST(ArcLength, LengthsBeyondTheRangeStopAtItsEnds) {
  const GeomAdaptor_Curve c(new Geom_Ellipse(gp_Ax2(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), 2.0, 1.0), 0.0, 3.0);
  const ArcLength arc(c, 0.0, 3.0);
  EXPECT_EQ(arc.parameter(1e9, 0.0), 3.0);
  EXPECT_EQ(arc.parameter(-1e9, 3.0), 0.0);
  EXPECT_EQ(arc.parameter(0.0, 0.0), 0.0);
}

}  // namespace
}  // namespace cadmedial
