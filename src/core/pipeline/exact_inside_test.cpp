#include "exact_inside_test.h"

#include <memory>

#include <BRepClass3d_SolidClassifier.hxx>
#include <gp_Pnt.hxx>

namespace cadmedial {

InsideTest exact_inside_test(const TopoDS_Solid& solid, double tol) {
  auto classifier = std::make_shared<BRepClass3d_SolidClassifier>(solid);
  return [classifier, tol](const std::vector<Point3>& pts) {
    std::vector<std::uint8_t> out(pts.size());
    for (size_t k = 0; k < pts.size(); ++k) {
      classifier->Perform(gp_Pnt(pts[k][0], pts[k][1], pts[k][2]), tol);
      const TopAbs_State s = classifier->State();
      out[k] = (s == TopAbs_IN || s == TopAbs_ON) ? 1 : 0;
    }
    return out;
  };
}

}  // namespace cadmedial
