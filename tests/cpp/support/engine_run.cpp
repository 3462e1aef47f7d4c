#include "support/engine_run.h"

#include <fstream>
#include <map>
#include <memory>

namespace cadmedial::test {

ComputeParams params_with_spacing(double spacing) {
  ComputeParams params;
  params.sampling.spacing = spacing;
  return params;
}

const ComputeResult& medial_axis_of(const std::string& key, const std::function<TopoDS_Shape()>& make,
                                    double spacing) {
  return medial_axis_of(key + "@" + std::to_string(spacing), make, params_with_spacing(spacing));
}

const ComputeResult& medial_axis_of(const std::string& key, const std::function<TopoDS_Shape()>& make,
                                    const ComputeParams& params) {
  static std::map<std::string, std::unique_ptr<ComputeResult>> cache;
  auto& slot = cache[key];
  if (!slot) slot = std::make_unique<ComputeResult>(compute_medial_axis(make(), params));
  return *slot;
}

std::string model_path(const std::string& relative) {
  const std::string path = std::string(CADMEDIAL_SOURCE_DIR) + "/../shared/data/models/" + relative;
  return std::ifstream(path).good() ? path : std::string();
}

}  // namespace cadmedial::test
