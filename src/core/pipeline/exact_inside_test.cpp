#include "exact_inside_test.h"

#include <memory>
#include <mutex>

#include <BRepClass3d_SolidClassifier.hxx>
#include <Standard_Failure.hxx>
#include <gp_Pnt.hxx>

#include "../two_cores.h"
#include "ray_classifier.h"

namespace cadmedial {

namespace {

// Two classifiers per core: they keep state between calls, and a batch splits in two. They are
// made on first use, each on its own thread; they only read the solid. The rays decide almost
// every point; OpenCASCADE's classifier, 2 to 6 ms a point on parts of a few hundred faces, the
// few whose rays disagree or do not cross the boundary cleanly.
struct Classifiers {
  TopoDS_Solid solid;
  double tol = 0;
  std::unique_ptr<internal::RayClassifier> rays[2];
  std::unique_ptr<BRepClass3d_SolidClassifier> on_core[2];

  // The pipeline's worker may still be making them (prepare) when the first points are asked.
  std::mutex making[2];

  internal::RayClassifier& rays_on(int core) {
    const std::lock_guard<std::mutex> lock(making[core]);
    if (!rays[core]) rays[core] = std::make_unique<internal::RayClassifier>(solid, tol);
    return *rays[core];
  }
  BRepClass3d_SolidClassifier& on(int core) {
    if (!on_core[core]) on_core[core] = std::make_unique<BRepClass3d_SolidClassifier>(solid);
    return *on_core[core];
  }

  void classify(int core, const std::vector<Point3>& pts, std::size_t begin, std::size_t end,
                std::vector<std::uint8_t>& out) {
    if (begin == end) return;
    internal::RayClassifier& r = rays_on(core);
    for (std::size_t k = begin; k < end; ++k) {
      const internal::RayClassifier::Answer a = r.classify(pts[k]);
      if (a != internal::RayClassifier::Answer::Unknown) {
        out[k] = a == internal::RayClassifier::Answer::Inside;
        continue;
      }
      BRepClass3d_SolidClassifier& c = on(core);
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
    // The faces' and edges' boxes, one set per core.
    try {
      for (int core = 0; core < 2; ++core) classifiers->rays_on(core);
    } catch (const Standard_Failure&) {
      // Only a head start: a classifier that fails here fails again on the points asked, where
      // the pipeline reports it.
    }
  };
  return test_with(classifiers);
}

}  // namespace cadmedial
