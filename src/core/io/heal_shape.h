// Repairing a solid that BRepCheck_Analyzer refuses, with OpenCASCADE's shape healing (ShapeFix).
#pragma once

#include <string>

#include <TopoDS_Solid.hxx>

namespace cadmedial {

struct HealedSolid {
  TopoDS_Solid solid;  ///< null when ShapeFix failed, or gave no solid or several
  /// What ShapeFix reports it did, as phrases joined by "; " ("faces were incorrectly oriented in
  /// the shell, corrected"), or why it gave no solid. "" when it reported nothing (it still may
  /// have changed tolerances or curves: those fixes are not reported).
  std::string fixes;
};

/// ShapeFix_Shape on `solid` (its wires, faces, shells and the solid itself), at a precision
/// relative to its size. The caller checks the result again: healing may leave it invalid.
/// Never throws: an OpenCASCADE failure inside ShapeFix gives a null solid.
HealedSolid heal_solid(const TopoDS_Solid& solid);

}  // namespace cadmedial
