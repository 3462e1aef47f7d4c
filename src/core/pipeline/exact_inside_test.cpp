#include "exact_inside_test.h"

#include <memory>

#include <BRepClass3d_SolidClassifier.hxx>
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

  void classify(int core, const std::vector<Point3>& pts, std::size_t begin, std::size_t end,
                std::vector<std::uint8_t>& out) {
    if (begin == end) return;
    if (!on_core[core]) on_core[core] = std::make_unique<BRepClass3d_SolidClassifier>(solid);
    BRepClass3d_SolidClassifier& c = *on_core[core];
    for (std::size_t k = begin; k < end; ++k) {
      c.Perform(gp_Pnt(pts[k][0], pts[k][1], pts[k][2]), tol);
      const TopAbs_State s = c.State();
      out[k] = (s == TopAbs_IN || s == TopAbs_ON) ? 1 : 0;
    }
  }
};

}  // namespace

InsideTest exact_inside_test(const TopoDS_Solid& solid, double tol) {
  auto classifiers = std::make_shared<Classifiers>();
  classifiers->solid = solid;
  classifiers->tol = tol;
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

}  // namespace cadmedial
