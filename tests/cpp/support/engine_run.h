// Runs the engine once per (solid, spacing) in a test process and keeps the result: the tests of
// one solid share its medial axis. (Under ctest every test is its own process and recomputes.)
#pragma once

#include <functional>
#include <string>

#include <TopoDS_Shape.hxx>

#include "core/pipeline/compute_medial_axis.h"

namespace cadmedial::test {

/// Default parameters (theta 5, rho 8) with an explicit sample spacing.
ComputeParams params_with_spacing(double spacing);

/// compute_medial_axis(make(), params_with_spacing(spacing)), computed on the first call for `key`.
const ComputeResult& medial_axis_of(const std::string& key, const std::function<TopoDS_Shape()>& make,
                                    double spacing);

/// The same for explicit params (e.g. a target sample count), keyed by `key`.
const ComputeResult& medial_axis_of(const std::string& key, const std::function<TopoDS_Shape()>& make,
                                    const ComputeParams& params);

/// CADMEDIAL_SOURCE_DIR "/../shared/data/models/" + relative; empty when the file is absent.
std::string model_path(const std::string& relative);

}  // namespace cadmedial::test
