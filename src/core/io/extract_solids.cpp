// Turning a shape into checked, closed solids.
//
// What extract_solids accepts, and why:
// - solids (also inside compounds and compsolids): checked as they are;
// - closed shells that are not solids: made solids (BRepBuilderAPI_MakeSolid, ShapeFix_Solid for
//   the orientation), since STEP/IGES exports often stop at the shell;
// - loose faces (IGES often holds only faces): sewn together; every shell that sewing makes must be
//   closed, or the whole shape is refused: a face left out would silently change the medial axis;
// - loose wires, edges and vertices (construction geometry): ignored, they bound no volume. When the
//   shape holds nothing else, the "no solid" message counts them so the user sees what was there.
// Edge, face and vertex numbers in messages are 1-based indices of TopExp::MapShapes over the solid
// (or shell), which is the numbering FreeCAD shows as Edge12, Face3, ...
// A solid that fails a check is healed where OpenCASCADE can (sewn, or given to ShapeFix:
// heal_shape.h) with a warning, and skipped beside other solids when it cannot be.
// Before any OpenCASCADE header: OCC_CATCH_SIGNALS below turns faults into Standard_Failure
// (read_shape.cpp says why).
#define OCC_CONVERT_SIGNALS
#include "extract_solids.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <BRepBuilderAPI_MakeSolid.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <ShapeFix_Solid.hxx>
#include <Standard_ErrorHandler.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Iterator.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Vertex.hxx>

#include "check_geometry.h"
#include "check_solid.h"
#include "heal_shape.h"
#include "read_shape.h"
#include "shape_text.h"

namespace cadmedial {

using internal::check_geometry;
using internal::diagonal;
using internal::edge_location;
using internal::enable_reader_fault_recovery;
using internal::failure_text;
using internal::first_check_failure;
using internal::open_or_nonmanifold_edge;
using internal::signed_volume;

namespace {

void run_check(const DeferredCheck& check) {
  BRepCheck_Analyzer analyzer(check.solid);
  if (!analyzer.IsValid()) throw FailedBRepCheck(check.name + ": " + first_check_failure(check.solid, analyzer));
}

std::vector<TopoDS_Shell> sew_faces(const std::vector<TopoDS_Face>& faces, double relative_tolerance = 1e-6,
                                    double* used_tolerance = nullptr);
TopoDS_Solid solid_from_closed_shell(const TopoDS_Shell& shell);

// A solid whose one shell is open (its faces do not share their edges, or a gap lies between
// them) made of its faces sewn, at a millionth of its size as loose faces are, then at a
// ten-thousandth: a gap that size is far below any sample spacing, and the warning gives the
// tolerance that closed it. Null when sewing does not give one closed shell.
TopoDS_Solid sewn_solid(const TopoDS_Solid& solid, double& tolerance) {
  std::vector<TopoDS_Face> faces;
  for (TopExp_Explorer ex(solid, TopAbs_FACE); ex.More(); ex.Next()) faces.push_back(TopoDS::Face(ex.Current()));
  for (double relative : {1e-6, 1e-4}) {
    try {
      const std::vector<TopoDS_Shell> shells = sew_faces(faces, relative, &tolerance);
      if (shells.size() == 1) return solid_from_closed_shell(shells.front());
      return TopoDS_Solid();  // several shells: sewing cannot tell which bound a void
    } catch (const InvalidInput&) {
      // still open, or non-manifold: try the wider tolerance
    } catch (const Standard_Failure&) {
      return TopoDS_Solid();  // sewing broke on its geometry (a curve of zero range): not healable
    }
  }
  return TopoDS_Solid();
}

TopoDS_Solid healed_or_refused(const TopoDS_Solid& solid, const std::string& name, const std::string& failure,
                               std::vector<std::string>* warnings);

// The checks of `solid` but BRepCheck's: every shell closed and manifold, a positive volume.
// Returns it, reversed when its volume came out negative (faces oriented inward). When `may_heal`,
// a solid whose shell is open is sewn, and one whose volume is zero (half of it inside out) is
// given to ShapeFix, each said in `warnings`. Throws InvalidInput naming the defect.
TopoDS_Solid closed_solid(TopoDS_Solid solid, const std::string& name, std::vector<std::string>* warnings,
                          bool may_heal) {
  TopTools_IndexedMapOfShape edge_index;
  TopExp::MapShapes(solid, TopAbs_EDGE, edge_index);
  int nshells = 0;
  std::string open;
  for (TopExp_Explorer sx(solid, TopAbs_SHELL); sx.More(); sx.Next()) {
    ++nshells;
    if (open.empty()) open = open_or_nonmanifold_edge(sx.Current(), edge_index);
  }
  if (nshells == 0) throw InvalidInput(name + ": has no shell (an empty solid)");
  if (!open.empty()) {
    double tolerance = 0;
    const TopoDS_Solid sewn = may_heal && nshells == 1 ? sewn_solid(solid, tolerance) : TopoDS_Solid();
    if (sewn.IsNull()) throw InvalidInput(name + ": " + open);
    solid = closed_solid(sewn, name, nullptr, false);
    if (warnings)
      warnings->push_back(name + ": " + open + "; closed by sewing its faces (tolerance " + message_number(tolerance) + ")");
    return solid;
  }

  // Orientation first: an inside-out solid (negative volume) is fixed by reversing it, and only
  // then checked, so that BRepCheck does not refuse it for its orientation.
  const double volume = signed_volume(solid);
  const double d = diagonal(solid);
  // Relative to the box: a volume this small against d^3 is a flat shape, or one whose parts
  // cancel out (half of it inside out: ShapeFix may orient its faces as one).
  const double tiny = 1e-12 * d * d * d;
  if (!std::isfinite(volume) || std::abs(volume) <= tiny) {
    const std::string failure = name + ": has zero volume (flat, or partly inside out)";
    if (!may_heal) throw InvalidInput(failure);
    return healed_or_refused(solid, name, failure, warnings);
  }
  if (volume < 0) solid.Reverse();
  return solid;
}

// What ShapeFix makes of `solid` (refused for `failure`, which names it) if that is one solid,
// closed, valid for BRepCheck and of the same size; said in `warnings`. Else throws InvalidInput
// with `failure` and why it could not be healed.
TopoDS_Solid healed_or_refused(const TopoDS_Solid& solid, const std::string& name, const std::string& failure,
                               std::vector<std::string>* warnings) {
  const HealedSolid healed = heal_solid(solid);
  std::string why_not = healed.fixes;
  if (!healed.solid.IsNull()) {
    try {
      const TopoDS_Solid fixed = closed_solid(healed.solid, name, nullptr, false);
      const BRepCheck_Analyzer again(fixed);
      const double d = diagonal(solid), d_fixed = diagonal(fixed);
      if (!again.IsValid()) {
        why_not = "still invalid after ShapeFix: " + first_check_failure(fixed, again);
      } else if (!(std::abs(d_fixed - d) <= 1e-3 * d)) {
        // Healing that moved the part's extent changed the part, not its representation.
        why_not = "ShapeFix changed its size (diagonal " + message_number(d) + " to " + message_number(d_fixed) + ")";
      } else {
        if (warnings)
          warnings->push_back(failure + "; healed by ShapeFix" + (healed.fixes.empty() ? "" : " (" + healed.fixes + ")"));
        return fixed;
      }
    } catch (const InvalidInput& e) {
      const std::string what = e.what(), prefix = name + ": ";
      why_not = "ShapeFix left it broken: " + (what.rfind(prefix, 0) == 0 ? what.substr(prefix.size()) : what);
    }
  }
  throw InvalidInput(failure + "; ShapeFix cannot heal it" + (why_not.empty() ? "" : " (" + why_not + ")"));
}

// `solid` if BRepCheck_Analyzer finds it valid, else healed_or_refused with BRepCheck's first
// complaint about the solid as given.
TopoDS_Solid valid_solid(const TopoDS_Solid& solid, const std::string& name, std::vector<std::string>* warnings) {
  const BRepCheck_Analyzer analyzer(solid);
  if (analyzer.IsValid()) return solid;
  return healed_or_refused(solid, name, name + ": " + first_check_failure(solid, analyzer), warnings);
}

// Checks a solid, healing it where OpenCASCADE can (closed_solid, valid_solid). BRepCheck_Analyzer's
// check is added to `deferred` when given, else run here.
TopoDS_Solid checked_solid(TopoDS_Solid solid, const std::string& name, std::vector<DeferredCheck>* deferred,
                           std::vector<std::string>* warnings) {
  solid = closed_solid(solid, name, warnings, true);
  if (!deferred) return valid_solid(solid, name, warnings);
  deferred->push_back({solid, name});
  return solid;
}

// check_geometry on `shape`; when it refuses a shape of several solids, on each of them: returns,
// per solid of `solids`, "" or why its own geometry is refused (its edges numbered over it).
// Throws check_geometry's refusal when the shape is one solid, or when the defect is not in the
// solids (a shell or face beside them), so that what was refused before still is.
std::vector<std::string> solids_with_broken_geometry(const TopoDS_Shape& shape, const std::vector<TopoDS_Solid>& solids,
                                                     const std::vector<TopoDS_Shell>& shells,
                                                     const std::vector<TopoDS_Face>& faces) {
  std::vector<std::string> why(solids.size());
  try {
    check_geometry(shape);
    return why;
  } catch (const InvalidInput&) {
    if (solids.size() < 2) throw;
    bool in_a_solid = false;
    for (std::size_t i = 0; i < solids.size(); ++i) {
      try {
        check_geometry(solids[i]);
      } catch (const InvalidInput& e) {
        why[i] = e.what();
        in_a_solid = true;
      }
    }
    BRep_Builder builder;
    TopoDS_Compound rest;
    builder.MakeCompound(rest);
    for (const TopoDS_Shell& s : shells) builder.Add(rest, s);
    for (const TopoDS_Face& f : faces) builder.Add(rest, f);
    bool rest_sane = true;
    try {
      check_geometry(rest);
    } catch (const InvalidInput&) {
      rest_sane = false;
    }
    if (!in_a_solid || !rest_sane) throw;
  }
  return why;
}

TopoDS_Solid solid_from_closed_shell(const TopoDS_Shell& shell) {
  // ShapeFix_Solid::SolidFromShell orients the shell so that the solid has its material inside.
  ShapeFix_Solid fix;
  TopoDS_Solid solid = fix.SolidFromShell(shell);
  if (solid.IsNull()) solid = BRepBuilderAPI_MakeSolid(shell).Solid();
  return solid;
}

// What a shape holds at its top level (inside compounds), sorted by kind.
struct Parts {
  std::vector<TopoDS_Solid> solids;
  std::vector<TopoDS_Shell> shells;
  std::vector<TopoDS_Face> faces;
  int loose_wires = 0, loose_edges = 0, loose_vertices = 0;
};

void collect(const TopoDS_Shape& shape, Parts& parts) {
  switch (shape.ShapeType()) {
    case TopAbs_COMPOUND:
    case TopAbs_COMPSOLID:
      for (TopoDS_Iterator it(shape); it.More(); it.Next()) collect(it.Value(), parts);
      break;
    case TopAbs_SOLID: parts.solids.push_back(TopoDS::Solid(shape)); break;
    case TopAbs_SHELL: parts.shells.push_back(TopoDS::Shell(shape)); break;
    case TopAbs_FACE: parts.faces.push_back(TopoDS::Face(shape)); break;
    case TopAbs_WIRE: ++parts.loose_wires; break;
    case TopAbs_EDGE: ++parts.loose_edges; break;
    case TopAbs_VERTEX: ++parts.loose_vertices; break;
    default: break;
  }
}

// Shells made by sewing the loose faces; throws when they do not close. `relative_tolerance` is
// against the faces' diagonal; the tolerance used goes to `used_tolerance` when given.
std::vector<TopoDS_Shell> sew_faces(const std::vector<TopoDS_Face>& faces, double relative_tolerance,
                                    double* used_tolerance) {
  BRep_Builder builder;
  TopoDS_Compound all;
  builder.MakeCompound(all);
  double max_tol = 0.0;
  for (const TopoDS_Face& f : faces) {
    builder.Add(all, f);
    for (TopExp_Explorer vx(f, TopAbs_VERTEX); vx.More(); vx.Next())
      max_tol = std::max(max_tol, BRep_Tool::Tolerance(TopoDS::Vertex(vx.Current())));
  }
  // The files' own tolerance (IGES readers set it from the file's resolution), and at least a
  // millionth of the size: gaps below that are round-off of the exporter, not holes.
  const double tol = std::max({1e-7, relative_tolerance * diagonal(all), 2.0 * max_tol});
  if (used_tolerance) *used_tolerance = tol;
  BRepBuilderAPI_Sewing sewing(tol);
  for (const TopoDS_Face& f : faces) sewing.Add(f);
  sewing.Perform();
  const bool one = faces.size() == 1;
  const std::string what = std::to_string(faces.size()) + (one ? " loose face" : " loose faces");
  if (sewing.NbFreeEdges() > 0)
    throw InvalidInput(what + " (not in any solid or shell)" + (one ? " does" : " do") + " not sew into closed shells: " +
                       std::to_string(sewing.NbFreeEdges()) + " edges stay open, e.g. one" +
                       edge_location(sewing.FreeEdge(1)));
  if (sewing.NbMultipleEdges() > 0)
    throw InvalidInput(what + " (not in any solid or shell) sew into a non-manifold shape: " +
                       std::to_string(sewing.NbMultipleEdges()) + " edges have more than two faces, e.g. one" +
                       edge_location(sewing.MultipleEdge(1)));
  Parts sewn;
  collect(sewing.SewedShape(), sewn);
  if (!sewn.faces.empty())
    throw InvalidInput(what + " (not in any solid or shell): " + std::to_string(sewn.faces.size()) +
                       " face(s) do not join any other after sewing");
  return sewn.shells;
}

std::vector<TopoDS_Solid> extract_solids(const TopoDS_Shape& shape, std::vector<std::string>* skipped,
                                         std::vector<DeferredCheck>* deferred, std::vector<std::string>* warnings) {
  if (shape.IsNull()) throw InvalidInput("the shape is empty (null)");
  enable_reader_fault_recovery();
  try {
    // A fault inside OpenCASCADE on broken geometry (sewing or checking a shape that the reader
    // left half-built) becomes a Standard_Failure, caught below (see enable_reader_fault_recovery).
    OCC_CATCH_SIGNALS
    Parts parts;
    collect(shape, parts);
    // Geometry no check may touch (the messages number its edges over the whole shape); in an
    // assembly, only the solids that hold it are left out (below).
    const std::vector<std::string> broken = solids_with_broken_geometry(shape, parts.solids, parts.shells, parts.faces);

    std::vector<TopoDS_Solid> solids;
    std::vector<std::string> open_parts;  // refused only when nothing else is there
    // Solids that cannot be healed: skipped beside others (an assembly with one empty solid is
    // still the other parts), refused when they are all there is. Each is numbered among all
    // the shape's solids, as FreeCAD numbers them, whether or not an earlier one was skipped.
    std::vector<std::string> rejected;
    int candidates = 0;
    auto add = [&](const TopoDS_Solid& solid, const std::string& origin) {
      const std::string name = "solid " + std::to_string(++candidates) + origin;
      try {
        solids.push_back(checked_solid(solid, name, deferred, warnings));
      } catch (const FailedBRepCheck&) {
        throw;
      } catch (const InvalidInput& e) {
        rejected.push_back(e.what());
      }
    };
    for (std::size_t i = 0; i < parts.solids.size(); ++i) {
      if (broken[i].empty()) {
        add(parts.solids[i], "");
      } else {
        rejected.push_back("solid " + std::to_string(++candidates) + ": " + broken[i]);
      }
    }

    // Shells that are not inside a solid: each must be closed; then it becomes a solid. STEP
    // exporters often write a part as a shell whose faces do not share their edges (each face has
    // its own copy): sewing closes such a shell, and only a shell that stays open is refused.
    for (std::size_t i = 0; i < parts.shells.size(); ++i) {
      TopTools_IndexedMapOfShape edge_index;
      TopExp::MapShapes(parts.shells[i], TopAbs_EDGE, edge_index);
      const std::string why = open_or_nonmanifold_edge(parts.shells[i], edge_index);
      if (!why.empty()) {
        std::vector<TopoDS_Face> faces;
        for (TopExp_Explorer ex(parts.shells[i], TopAbs_FACE); ex.More(); ex.Next()) faces.push_back(TopoDS::Face(ex.Current()));
        std::vector<TopoDS_Shell> sewn;
        try {
          sewn = sew_faces(faces);
        } catch (const InvalidInput&) {
          const std::string msg = "shell " + std::to_string(i + 1) + " (not a solid): " + why + "; sewing does not close it";
          open_parts.push_back(msg);
          continue;
        }
        for (const TopoDS_Shell& shell : sewn)
          add(solid_from_closed_shell(shell), " (sewn from shell " + std::to_string(i + 1) + ")");
        continue;
      }
      add(solid_from_closed_shell(parts.shells[i]), " (made from shell " + std::to_string(i + 1) + ")");
    }

    if (!parts.faces.empty()) {
      try {
        for (const TopoDS_Shell& shell : sew_faces(parts.faces)) add(solid_from_closed_shell(shell), " (sewn from loose faces)");
      } catch (const FailedBRepCheck&) {
        throw;
      } catch (const InvalidInput& e) {
        open_parts.push_back(e.what());
      }
    }
    if (!rejected.empty()) {
      if (solids.empty()) throw InvalidInput(rejected.front());
      if (warnings)
        for (const std::string& why : rejected)
          warnings->push_back(why + "; skipped: the axis is that of the other solids (the result numbers them without it)");
    }
    if (!open_parts.empty()) {
      if (solids.empty()) throw InvalidInput(open_parts.front());
      if (skipped) skipped->insert(skipped->end(), open_parts.begin(), open_parts.end());
    }

    if (solids.empty()) {
      std::string held;
      auto count = [&held](int n, const char* one, const char* many) {
        if (n == 0) return;
        held += (held.empty() ? "" : ", ") + std::to_string(n) + " " + (n == 1 ? one : many);
      };
      count(parts.loose_wires, "loose wire", "loose wires");
      count(parts.loose_edges, "loose edge", "loose edges");
      count(parts.loose_vertices, "loose vertex", "loose vertices");
      throw InvalidInput("holds no solid, closed shell or face" + (held.empty() ? std::string() : " (only " + held + ")"));
    }
    return solids;
  } catch (const Standard_Failure& e) {
    throw InvalidInput("checking the solids failed: " + failure_text(e));
  }
}

}  // namespace

std::vector<TopoDS_Solid> extract_solids(const TopoDS_Shape& shape, std::vector<std::string>* skipped,
                                         std::vector<std::string>* warnings) {
  return extract_solids(shape, skipped, nullptr, warnings);
}

std::vector<TopoDS_Solid> extract_solids(const TopoDS_Shape& shape, std::vector<std::string>* skipped,
                                         std::vector<DeferredCheck>& deferred, std::vector<std::string>* warnings) {
  return extract_solids(shape, skipped, &deferred, warnings);
}

void run_deferred_checks(const std::vector<DeferredCheck>& checks) {
  enable_reader_fault_recovery();
  try {
    OCC_CATCH_SIGNALS
    for (const DeferredCheck& check : checks) run_check(check);
  } catch (const Standard_Failure& e) {
    throw InvalidInput("checking the solids failed: " + failure_text(e));
  }
}

}  // namespace cadmedial
