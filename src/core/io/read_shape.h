// Reading CAD files into OpenCASCADE shapes. (extract_solids.h, included here for the callers that
// have always found it here, extracts the valid closed solids of a shape.)
#pragma once

#include <string>
#include <vector>

#include <TopoDS_Shape.hxx>
#include <TopoDS_Solid.hxx>

#include "extract_solids.h"

namespace cadmedial {

/// Reads a STEP (.step/.stp), IGES (.iges/.igs) or BREP (.brep/.brp) file, chosen by extension.
/// Throws InvalidInput naming the file and the problem (missing, unreadable, empty, broken).
TopoDS_Shape read_shape_file(const std::string& path);

/// Reads OpenCASCADE BREP text (as FreeCAD's Shape.exportBrepToString() writes it).
/// Throws InvalidInput when the text does not parse or holds no shape.
TopoDS_Shape read_brep_string(const std::string& text);

namespace internal {
/// Installs OpenCASCADE's fault handlers once (SIGSEGV and the like become Standard_Failure
/// inside OCC_CATCH_SIGNALS), keeping the job-control signals' handlers.
void enable_reader_fault_recovery();
}  // namespace internal

}  // namespace cadmedial
