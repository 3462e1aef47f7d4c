// Turning a shape into checked, closed solids: what is accepted, healed, skipped and refused.
#pragma once

#include <string>
#include <vector>

#include <TopoDS_Shape.hxx>
#include <TopoDS_Solid.hxx>

#include "../errors.h"

namespace cadmedial {

/// The solids of a shape, in TopExp_Explorer order. Closed shells that are not yet solids are made
/// solids; every solid is checked (BRepCheck_Analyzer, closedness, positive volume).
/// What fails is healed where OpenCASCADE can: a solid whose shell is open is sewn, one that
/// BRepCheck refuses is given to ShapeFix (heal_shape.h), and kept if it is then valid; each such
/// repair is described in `warnings` ("solid 3: wire 235 is invalid (...); healed by ShapeFix").
/// A solid that cannot be healed (no shell, zero volume, still open or invalid) is skipped, with a
/// warning naming it, when other solids are left; when none is, throws InvalidInput saying which
/// solid, face or edge is wrong (the first one's), or that there is no solid.
/// Open shells and faces that stay open after sewing are refused when they are all the shape
/// holds; beside at least one solid they are construction surfaces: skipped, and described in
/// `skipped` when given.
std::vector<TopoDS_Solid> extract_solids(const TopoDS_Shape& shape, std::vector<std::string>* skipped = nullptr,
                                         std::vector<std::string>* warnings = nullptr);

/// What a deferred check throws: BRepCheck_Analyzer refused a solid that extract_solids, run
/// without deferring, would try to heal. Its message is the refusal's, unhealed.
class FailedBRepCheck : public InvalidInput {
 public:
  using InvalidInput::InvalidInput;
};

/// A solid whose BRepCheck_Analyzer run extract_solids left for later: that run is most of its
/// time, and the pipeline does it on its second thread while CGAL triangulates.
struct DeferredCheck {
  TopoDS_Solid solid;
  std::string name;  ///< as extract_solids' messages name the solid ("solid 2 (made from shell 1)")
};
/// extract_solids with every check but BRepCheck_Analyzer's done; those are added to `deferred`
/// (and not healed: a solid they refuse throws FailedBRepCheck, and the caller starts again with
/// the shape that extract_solids without deferring gives).
std::vector<TopoDS_Solid> extract_solids(const TopoDS_Shape& shape, std::vector<std::string>* skipped,
                                         std::vector<DeferredCheck>& deferred,
                                         std::vector<std::string>* warnings = nullptr);
/// Throws FailedBRepCheck, with the words extract_solids uses for an invalid solid, for the first
/// solid that BRepCheck_Analyzer refuses.
void run_deferred_checks(const std::vector<DeferredCheck>& checks);

}  // namespace cadmedial
