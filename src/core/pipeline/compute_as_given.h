// The pipeline on a shape as given (compute_medial_axis.cpp), before compute_healed.cpp's retry.
#pragma once

#include <TopoDS_Shape.hxx>

#include "compute_medial_axis.h"

namespace cadmedial {

/// compute_medial_axis without the healing retry: throws FailedBRepCheck (io/read_shape.h) when
/// BRepCheck_Analyzer, which runs beside the first triangulation, refuses a solid.
ComputeResult compute_as_given(const TopoDS_Shape& shape, const ComputeParams& params, const Progress& progress);

}  // namespace cadmedial
