// `cadmedial info`: what the engine would see in a file, and how densely it would sample it.
#include <BRepBndLib.hxx>
#include <BRepGProp.hxx>
#include <Bnd_Box.hxx>
#include <GProp_GProps.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>

#include <cstdio>
#include <sstream>

#include "commands.h"
#include "core/features/solid_euler.h"
#include "core/pipeline/compute_medial_axis.h"
#include "load_solids.h"

namespace cadmedial::cli {
namespace {

std::size_t count(const TopoDS_Shape& shape, TopAbs_ShapeEnum type) {
  TopTools_IndexedMapOfShape map;
  TopExp::MapShapes(shape, type, map);
  return static_cast<std::size_t>(map.Extent());
}

std::string box_text(const TopoDS_Shape& shape) {
  Bnd_Box box;
  // The exact box: BRepBndLib::Add would widen it by the shape's tolerance.
  BRepBndLib::AddOptimal(shape, box, /*useTriangulation=*/false, /*useShapeTolerance=*/false);
  if (box.IsVoid()) return "empty";
  double x0, y0, z0, x1, y1, z1;
  box.Get(x0, y0, z0, x1, y1, z1);
  std::ostringstream s;
  s.precision(6);
  s << "[" << x0 << ", " << y0 << ", " << z0 << "] .. [" << x1 << ", " << y1 << ", " << z1 << "]";
  return s.str();
}

}  // namespace

int run_info(const Args& args) {
  check_params(args.params);
  const LoadedSolids loaded = load_solids(args.input);
  std::ostringstream out;
  out.precision(6);
  out << args.input << ": " << loaded.solids.size() << (loaded.solids.size() == 1 ? " solid\n" : " solids\n");
  for (std::size_t i = 0; i < loaded.solids.size(); ++i) {
    const TopoDS_Solid& s = loaded.solids[i];
    GProp_GProps volume, area;
    BRepGProp::VolumeProperties(s, volume);
    BRepGProp::SurfaceProperties(s, area);
    out << "  solid " << i + 1 << ": faces " << count(s, TopAbs_FACE) << ", edges " << count(s, TopAbs_EDGE)
        << ", vertices " << count(s, TopAbs_VERTEX) << ", volume " << volume.Mass() << ", area " << area.Mass()
        << ", box " << box_text(s) << ", Euler characteristic " << solid_euler_characteristic(s)
        << " (its medial axis's when right)\n";
  }
  out << "  bounding box: " << box_text(loaded.compound) << "\n";
  const SamplingPlan plan = plan_sampling(loaded.compound, args.params.sampling);
  out << "  sampling plan: spacing " << plan.spacing << ", about " << plan.estimated_samples << " samples"
      << (args.params.sampling.refine_topology ? ", finer for a solid whose axis comes out with another topology" : "")
      << "\n";
  std::fputs(out.str().c_str(), stdout);
  return 0;
}

}  // namespace cadmedial::cli
