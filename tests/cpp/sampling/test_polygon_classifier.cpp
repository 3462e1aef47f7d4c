// PolygonClassifier against OpenCASCADE's CSLib_Class2d, answer for answer, on polygons built in
// the test (with points on vertices, on edges, on the tolerance box's sides, on the heights of
// vertices, where the crossing count and the "on" tests are decided by rounding), and
// LatticeClassifier against BRepTopAdaptor_FClass2d::Perform near the boundaries of real faces.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <CSLib_Class2d.hxx>
#include <Geom2d_Curve.hxx>
#include <TColgp_Array1OfPnt2d.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>

#include "core/sampling/lattice_classifier.h"
#include "core/sampling/polygon_classifier.h"
#include "support/engine_run.h"

namespace cadmedial {
namespace {

struct Polygon2 {
  std::vector<gp_Pnt2d> points;
  double tolu, tolv, umin, vmin, umax, vmax;
};

// A star-shaped polygon around (cu, cv) with n vertices, some repeated, some on a common height
// (horizontal edges), some collinear.
std::vector<gp_Pnt2d> star(std::mt19937& rng, int n, double cu, double cv, double size) {
  std::uniform_real_distribution<double> radius(0.3 * size, size);
  std::vector<gp_Pnt2d> out;
  for (int k = 0; k < n; ++k) {
    const double a = 2 * M_PI * k / n;
    double r = radius(rng);
    gp_Pnt2d p(cu + r * std::cos(a), cv + r * std::sin(a));
    if (k % 7 == 3 && !out.empty()) p.SetY(out.back().Y());             // a horizontal edge
    if (k % 11 == 5 && !out.empty()) p = out.back();                    // a repeated point
    if (k % 13 == 6 && out.size() >= 2) p = gp_Pnt2d(2 * out.back().X() - out[out.size() - 2].X(),
                                                     2 * out.back().Y() - out[out.size() - 2].Y());  // collinear
    out.push_back(p);
  }
  return out;
}

std::vector<gp_Pnt2d> queries(std::mt19937& rng, const Polygon2& poly) {
  std::vector<gp_Pnt2d> q;
  const double du = poly.umax - poly.umin, dv = poly.vmax - poly.vmin;
  std::uniform_real_distribution<double> u(poly.umin - 0.1 * du, poly.umax + 0.1 * du);
  std::uniform_real_distribution<double> v(poly.vmin - 0.1 * dv, poly.vmax + 0.1 * dv);
  std::uniform_real_distribution<double> unit(0, 1);
  for (int k = 0; k < 3000; ++k) q.emplace_back(u(rng), v(rng));
  const size_t n = poly.points.size();
  for (size_t i = 0; i < n; ++i) {
    const gp_Pnt2d& a = poly.points[i];
    const gp_Pnt2d& b = poly.points[(i + 1) % n];
    q.push_back(a);
    const double t = unit(rng);
    q.emplace_back(a.X() + t * (b.X() - a.X()), a.Y() + t * (b.Y() - a.Y()));
    // On the sides of the tolerance box, and just inside and outside it.
    for (double f : {1.0, 1.0 - 1e-12, 1.0 + 1e-12, 0.5, 2.0}) {
      q.emplace_back(a.X() + f * poly.tolu, a.Y());
      q.emplace_back(a.X(), a.Y() - f * poly.tolv);
      q.emplace_back(a.X() - f * poly.tolu, a.Y() + f * poly.tolv);
    }
    // On the height of a vertex, left and right of it: the crossing count's ties.
    q.emplace_back(u(rng), a.Y());
    q.emplace_back(std::nextafter(a.X(), 1e300), a.Y());
  }
  q.emplace_back(std::numeric_limits<double>::quiet_NaN(), poly.vmin);
  q.emplace_back(poly.umin, std::numeric_limits<double>::infinity());
  return q;
}

TEST(PolygonClassifier, SameAnswersAsCSLibClass2d) {
  std::mt19937 rng(11);
  std::vector<Polygon2> polygons;
  for (int n : {3, 8, 40, 300}) {
    for (double tol : {0.0, 1e-9, 1e-3, 0.05}) {
      Polygon2 p{star(rng, n, 2.0, -1.0, 1.5), tol, 0.5 * tol, 0, 0, 0, 0};
      double u0 = 1e300, u1 = -1e300, v0 = 1e300, v1 = -1e300;
      for (const gp_Pnt2d& x : p.points)
        u0 = std::min(u0, x.X()), u1 = std::max(u1, x.X()), v0 = std::min(v0, x.Y()), v1 = std::max(v1, x.Y());
      p.umin = u0, p.umax = u1, p.vmin = v0, p.vmax = v1;
      polygons.push_back(p);
    }
  }
  // An inner wire: the bounds are the face's, larger than the polygon's box.
  {
    Polygon2 hole{star(rng, 60, 0.0, 0.0, 1.0), 1e-6, 1e-6, -5.0, -3.0, 4.0, 6.0};
    polygons.push_back(hole);
  }
  // A comb: many teeth, each a pair of edges spanning the polygon's height (band lists would grow
  // as teeth times bands).
  {
    Polygon2 comb{{}, 1e-7, 1e-7, 0, 0, 0, 0};
    const int teeth = 200;
    comb.points.push_back(gp_Pnt2d(0, -1));
    for (int k = 0; k < teeth; ++k) {
      comb.points.push_back(gp_Pnt2d(k, 10));
      comb.points.push_back(gp_Pnt2d(k + 0.5, 10));
      comb.points.push_back(gp_Pnt2d(k + 0.5, 0));
      comb.points.push_back(gp_Pnt2d(k + 1, 0));
    }
    comb.points.push_back(gp_Pnt2d(teeth, -1));
    comb.umin = 0, comb.umax = teeth, comb.vmin = -1, comb.vmax = 10;
    polygons.push_back(comb);
  }
  // A polygon far from the origin with a tiny extent in v (stored unscaled in v).
  Polygon2 flat{{gp_Pnt2d(1e5, 0), gp_Pnt2d(1e5 + 1, 0), gp_Pnt2d(1e5 + 1, 5e-11), gp_Pnt2d(1e5, 5e-11)}, 1e-12, 1e-12,
                1e5, 0, 1e5 + 1, 5e-11};
  polygons.push_back(flat);
  int inside = 0, on = 0, outside = 0;
  for (const Polygon2& p : polygons) {
    TColgp_Array1OfPnt2d pts(1, static_cast<int>(p.points.size()));
    for (size_t k = 0; k < p.points.size(); ++k) pts(static_cast<int>(k) + 1) = p.points[k];
    const CSLib_Class2d ref(pts, p.tolu, p.tolv, p.umin, p.vmin, p.umax, p.vmax);
    const PolygonClassifier fast(stored_polygon(ref));
    for (const gp_Pnt2d& q : queries(rng, p)) {
      const int want = ref.SiDans(q);
      ASSERT_EQ(fast.si_dans(q.X(), q.Y()), want) << "n " << p.points.size() << " tol " << p.tolu << " at (" << q.X()
                                                  << ", " << q.Y() << ")";
      inside += want == 1, on += want == 0, outside += want == -1;
      // The stored coordinates' tests too, at points that are not transformed.
      const double x = (q.X() - p.umin) / (p.umax - p.umin), y = (q.Y() - p.vmin) / (p.vmax - p.vmin);
      ASSERT_EQ(fast.internal_si_dans(x, y), ref.InternalSiDans(x, y));
      ASSERT_EQ(fast.internal_si_dans_ou_on(x, y), ref.InternalSiDansOuOn(x, y));
    }
  }
  // Each answer is exercised.
  EXPECT_GT(inside, 1000);
  EXPECT_GT(outside, 1000);
  EXPECT_GT(on, 100);
}

TEST(PolygonClassifier, SameAnswersWithAVertexThatIsNotANumber) {
  // CSLib_Class2d compares NaN as it compares anything (false): the answers must follow it.
  std::mt19937 rng(2);
  std::vector<gp_Pnt2d> pts = star(rng, 40, 0, 0, 1);
  pts[5].SetY(std::numeric_limits<double>::quiet_NaN());
  pts[17].SetX(std::numeric_limits<double>::quiet_NaN());
  TColgp_Array1OfPnt2d arr(1, static_cast<int>(pts.size()));
  for (size_t k = 0; k < pts.size(); ++k) arr(static_cast<int>(k) + 1) = pts[k];
  const CSLib_Class2d ref(arr, 1e-6, 1e-6, -1, -1, 1, 1);
  const PolygonClassifier fast(stored_polygon(ref));
  std::uniform_real_distribution<double> c(-1.2, 1.2);
  for (int q = 0; q < 3000; ++q) {
    const gp_Pnt2d p(c(rng), c(rng));
    ASSERT_EQ(fast.si_dans(p.X(), p.Y()), ref.SiDans(p)) << p.X() << " " << p.Y();
  }
}

TEST(PolygonClassifier, EmptyPolygonIsOnEverywhere) {
  TColgp_Array1OfPnt2d pts(1, 2);
  pts(1) = gp_Pnt2d(0, 0);
  pts(2) = gp_Pnt2d(1, 1);
  const CSLib_Class2d ref(pts, 1e-9, 1e-9, 0, 0, 1, 1);  // fewer than 3 points: no polygon
  const PolygonClassifier fast(stored_polygon(ref));
  EXPECT_EQ(ref.SiDans(gp_Pnt2d(0.5, 0.5)), 0);
  EXPECT_EQ(fast.si_dans(0.5, 0.5), 0);
}

// Points near each face's boundary (on its pcurves and beside them): wherever the lattice
// classifier answers (classify, or exact where classify leaves it to Perform), Perform says the
// same.
void expect_lattice_agrees_with_perform(const std::string& path) {
  TopoDS_Shape shape;
  BRep_Builder builder;
  ASSERT_TRUE(BRepTools::Read(shape, path.c_str(), builder)) << path;
  std::mt19937 rng(5);
  std::normal_distribution<double> offset(0.0, 1.0);
  int answered = 0, asked = 0;
  for (TopExp_Explorer fx(shape, TopAbs_FACE); fx.More(); fx.Next()) {
    const TopoDS_Face& face = TopoDS::Face(fx.Current());
    const BRepTopAdaptor_FClass2d classifier(face, 1e-9);
    const BRepAdaptor_Surface surface(face, Standard_False);
    double u0, u1, v0, v1;
    BRepTools::UVBounds(face, u0, u1, v0, v1);
    const long n = 40;
    const UvLattice lattice{u0, v0, (u1 - u0) / n, (v1 - v0) / n, n, n};
    LatticeClassifier lc(classifier, surface, lattice);
    for (TopExp_Explorer ex(face, TopAbs_EDGE); ex.More(); ex.Next()) {
      double a, b;
      const Handle(Geom2d_Curve) pc = BRep_Tool::CurveOnSurface(TopoDS::Edge(ex.Current()), face, a, b);
      if (pc.IsNull()) continue;
      for (int k = 0; k <= 40; ++k) {
        const gp_Pnt2d on = pc->Value(a + (b - a) * k / 40);
        for (double scale : {0.0, 1e-9, 1e-6, 1e-3, 3e-2}) {
          const gp_Pnt2d uv(on.X() + scale * (u1 - u0) * offset(rng), on.Y() + scale * (v1 - v0) * offset(rng));
          LatticeClassifier::Answer got = lc.classify(uv);
          if (got == LatticeClassifier::Answer::Ask) got = lc.exact(uv);
          if (got == LatticeClassifier::Answer::Ask) {
            asked += scale == 3e-2;
            continue;
          }
          answered += scale == 3e-2;
          ASSERT_EQ(got == LatticeClassifier::Answer::In, classifier.Perform(uv) == TopAbs_IN)
              << path << " at (" << uv.X() << ", " << uv.Y() << ")";
        }
      }
    }
  }
  // Points a little away from a boundary are answered without Perform; those within its
  // tolerance (most of the nearer ones) are not.
  EXPECT_GT(answered, 10 * asked) << path;
}

TEST(LatticeClassifier, AnswersAsPerformNearFaceBoundaries) {
  for (const char* part : {"freecad/Y_Rod_Mount.brep", "freecad/holesInFace2.brep", "freecad/filletBox.brep"}) {
    const std::string path = test::model_path(part);
    if (path.empty()) GTEST_SKIP() << "../shared/data/models is not beside the repository";
    expect_lattice_agrees_with_perform(path);
  }
}

}  // namespace
}  // namespace cadmedial
