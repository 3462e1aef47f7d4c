#include "shape_text.h"

#include <sstream>

#include <BRep_Tool.hxx>
#include <Geom_Curve.hxx>

namespace cadmedial::internal {

std::string failure_text(const Standard_Failure& e) {
  const char* m = e.GetMessageString();
  std::string text = (m && *m) ? m : "";
  std::string type = e.DynamicType()->Name();
  return text.empty() ? type : type + ": " + text;
}

std::string point_text(const gp_Pnt& p) {
  std::ostringstream s;
  s.precision(6);
  s << "(" << p.X() << ", " << p.Y() << ", " << p.Z() << ")";
  return s.str();
}

std::string edge_location(const TopoDS_Edge& edge) {
  try {
    double first = 0, last = 0;
    Handle(Geom_Curve) curve = BRep_Tool::Curve(edge, first, last);
    if (curve.IsNull()) return "";
    return " near " + point_text(curve->Value(0.5 * (first + last)));
  } catch (const Standard_Failure&) {
    return "";
  }
}

}  // namespace cadmedial::internal
