#include "exact_inside_test.h"

#include <memory>

#include <BRepBndLib.hxx>
#include <BRepClass3d_SolidClassifier.hxx>
#include <Bnd_Box.hxx>
#include <Standard_Failure.hxx>
#include <gp_Pnt.hxx>

#include "../two_cores.h"

namespace cadmedial {

namespace {

// One classifier per core: a classifier keeps state between calls, and each point costs about a
// millisecond (a ray against every face), so a batch splits in two. The classifiers are made on
// first use, each on its own thread; they only read the solid.
struct Classifiers {
  TopoDS_Solid solid;
  double tol = 0;
  std::unique_ptr<BRepClass3d_SolidClassifier> on_core[2];

  BRepClass3d_SolidClassifier& on(int core) {
    if (!on_core[core]) on_core[core] = std::make_unique<BRepClass3d_SolidClassifier>(solid);
    return *on_core[core];
  }

  void classify(int core, const std::vector<Point3>& pts, std::size_t begin, std::size_t end,
                std::vector<std::uint8_t>& out) {
    if (begin == end) return;
    BRepClass3d_SolidClassifier& c = on(core);
    for (std::size_t k = begin; k < end; ++k) {
      c.Perform(gp_Pnt(pts[k][0], pts[k][1], pts[k][2]), tol);
      const TopAbs_State s = c.State();
      out[k] = (s == TopAbs_IN || s == TopAbs_ON) ? 1 : 0;
    }
  }
};

InsideTest test_with(const std::shared_ptr<Classifiers>& classifiers) {
  return [classifiers](const std::vector<Point3>& pts) {
    std::vector<std::uint8_t> out(pts.size());
    // A few points are not worth a thread (or a second classifier).
    if (pts.size() < 8) {
      classifiers->classify(0, pts, 0, pts.size(), out);
      return out;
    }
    const std::size_t mid = pts.size() / 2;
    internal::on_two_cores([&] { classifiers->classify(0, pts, 0, mid, out); },
                           [&](const std::atomic<bool>&) { classifiers->classify(1, pts, mid, pts.size(), out); });
    return out;
  };
}

std::shared_ptr<Classifiers> classifiers_of(const TopoDS_Solid& solid, double tol) {
  auto classifiers = std::make_shared<Classifiers>();
  classifiers->solid = solid;
  classifiers->tol = tol;
  return classifiers;
}

}  // namespace

InsideTest exact_inside_test(const TopoDS_Solid& solid, double tol) {
  return test_with(classifiers_of(solid, tol));
}

InsideTest exact_inside_test(const TopoDS_Solid& solid, double tol, std::function<void()>& prepare) {
  const std::shared_ptr<Classifiers> classifiers = classifiers_of(solid, tol);
  prepare = [classifiers] {
    // The centre of the solid's box: any point makes the classifier set up what its first
    // Perform would (the answer is not used).
    try {
      Bnd_Box box;
      BRepBndLib::Add(classifiers->solid, box);
      if (box.IsVoid()) return;
      double x0, y0, z0, x1, y1, z1;
      box.Get(x0, y0, z0, x1, y1, z1);
      for (int core = 0; core < 2; ++core)
        classifiers->on(core).Perform(gp_Pnt(0.5 * (x0 + x1), 0.5 * (y0 + y1), 0.5 * (z0 + z1)), classifiers->tol);
    } catch (const Standard_Failure&) {
      // Only a head start: a classifier that fails here fails again on the points asked, where
      // the pipeline reports it.
    }
  };
  return test_with(classifiers);
}

}  // namespace cadmedial
