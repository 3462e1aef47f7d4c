// ShapeFix_Shape on one solid, and what it says it did, in words.
//
// Why only on what BRepCheck refuses: ShapeFix also changes valid shapes (tolerances, curves,
// pcurves it adds), and a valid part must be computed from the geometry the user gave.
// OpenCASCADE's readers run it themselves on import; this is for what comes out still invalid
// (a wire whose pcurves cross, faces inside out in their shell, a vertex off its edges' ends).
// Before any OpenCASCADE header, as in read_shape.cpp: OCC_CATCH_SIGNALS turns a fault inside
// ShapeFix into a Standard_Failure.
#define OCC_CONVERT_SIGNALS
#include "heal_shape.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <BRepBndLib.hxx>
#include <Bnd_Box.hxx>
#include <Message_Gravity.hxx>
#include <Message_Msg.hxx>
#include <Precision.hxx>
#include <ShapeExtend_BasicMsgRegistrator.hxx>
#include <ShapeFix_Shape.hxx>
#include <Standard_ErrorHandler.hxx>
#include <Standard_Failure.hxx>
#include <TCollection_AsciiString.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

namespace cadmedial {
namespace {

// ShapeFix names its messages by key and takes their text from OpenCASCADE's SHAPE.us resource
// file, which the CLI and the Python module do not load (FreeCAD may): without it a message reads
// "Unknown message invoked with the keyword <key>". The keys it sends on solids, in our words
// (the file's texts, shortened).
const std::pair<const char*, const char*> kPhrases[] = {
    {"FixWire.FixDegenerated.MSG0", "degenerate edges marked"},
    {"FixWire.FixDegenerated.MSG5", "a degenerate edge marked"},
    {"FixWire.FixCurve3d.Removed", "an edge with no curve removed"},
    {"FixAdvWire.FixSmall.MSG0", "small edges removed"},
    {"FixAdvWire.FixSmall.MSG5", "a small edge removed"},
    {"FixAdvWire.FixIntersection.MSG0", "a self-intersecting wire corrected"},
    {"FixAdvWire.FixIntersection.MSG5", "a self-intersecting edge corrected"},
    {"FixAdvWire.FixIntersection.MSG10", "intersecting edges corrected"},
    {"FixAdvWire.FixLacking.MSG0", "lacking edges inserted"},
    {"FixAdvWire.FixLacking.MSG5", "a lacking edge inserted"},
    {"FixAdvFace.FixMissingSeam.MSG0", "a missing seam edge added"},
    {"FixAdvFace.FixSmallAreaWire.MSG0", "a wire of zero area removed"},
    {"FixAdvFace.FixOrientation.MSG0", "a face given its natural bounds"},
    {"FixAdvFace.FixOrientation.MSG5", "a wire on a face reversed"},
    {"FixAdvFace.FixOrientation.MSG11", "a wire that cannot be oriented"},
    {"FixAdvFace.FixLoopWire.MSG0", "a looping wire split"},
    {"FixAdvFace.FixSpotFace.MSG0", "a spot face removed"},
    {"FixAdvFace.FixStripFace.MSG0", "a strip face removed"},
    {"FixWireframe.FixSmallEdges.MSG0", "a small edge removed"},
    {"FixWireframe.FixFixWireGaps.MSG0", "gaps in a wire closed"},
    {"Fix.SplitCommonVertex.MSG0", "wires sharing a vertex separated"},
    {"FixEdge.SameParameter.MSG0", "an edge's curves made to agree (same parameter)"},
    {"FixAdvShell.FixOrientation.MSG0", "faces oriented inconsistently in the shell, reoriented"},
    {"FixAdvShell.FixOrientation.MSG5", "faces oriented inconsistently in the shell, not corrected"},
    {"FixAdvShell.FixOrientation.MSG20", "faces that cannot be oriented in one shell"},
    {"FixAdvShell.FixOrientation.MSG30", "a shell connected improperly, split"},
    {"FixAdvShell.FixClosedFlag.MSG0", "the shell's closed flag corrected"},
    {"FixAdvSolid.FixShell.MSG10", "an open shell that cannot bound a solid"},
    {"FixAdvSolid.FixOrientation.MSG20", "the orientation of the solid's shells corrected"},
    {"FixAdvSolid.FixOrientation.MSG30", "a solid connected improperly, split"},
};

std::string phrase_of(const Message_Msg& msg) {
  std::string text = TCollection_AsciiString(msg.Original(), '?').ToCString();
  const std::string unknown = "Unknown message invoked with the keyword ";
  if (text.rfind(unknown, 0) == 0) {
    const std::string key = text.substr(unknown.size());
    for (const auto& [k, phrase] : kPhrases)
      if (key == k) return phrase;
    return key;  // a key this table lacks: still says where in ShapeFix
  }
  // The resource file is loaded (FreeCAD): its own text, as a phrase.
  if (!text.empty()) text[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(text[0])));
  return text;
}

// Collects ShapeFix's messages (all gravities: its "warnings" are the fixes it made), each phrase
// once with how often it came.
class Collector : public ShapeExtend_BasicMsgRegistrator {
 public:
  void Send(const Handle(Standard_Transient)&, const Message_Msg& msg, const Message_Gravity) override { add(msg); }
  void Send(const TopoDS_Shape&, const Message_Msg& msg, const Message_Gravity) override { add(msg); }
  void Send(const Message_Msg& msg, const Message_Gravity) override { add(msg); }

  std::string text() const {
    std::string out;
    for (const auto& [phrase, n] : counts_)
      out += (out.empty() ? "" : "; ") + phrase + (n > 1 ? " (" + std::to_string(n) + " times)" : "");
    return out;
  }

 private:
  void add(const Message_Msg& msg) {
    const std::string p = phrase_of(msg);
    auto it = std::find_if(counts_.begin(), counts_.end(), [&](const auto& c) { return c.first == p; });
    if (it == counts_.end()) counts_.emplace_back(p, 1);
    else ++it->second;
  }
  std::vector<std::pair<std::string, int>> counts_;  // in the order they came
};

double diagonal_of(const TopoDS_Shape& shape) {
  Bnd_Box box;
  BRepBndLib::Add(shape, box);
  return box.IsVoid() ? 0.0 : std::sqrt(box.SquareExtent());
}

}  // namespace

HealedSolid heal_solid(const TopoDS_Solid& solid) {
  HealedSolid out;
  Handle(Collector) messages = new Collector;
  try {
    OCC_CATCH_SIGNALS
    const double d = diagonal_of(solid);
    ShapeFix_Shape fix(solid);
    fix.SetMsgRegistrator(messages);
    // Relative to the part: OpenCASCADE's defaults (1e-7 and a tolerance of up to 1 model unit)
    // are absolute, too coarse for a part 1e-6 long and too fine for one 1e6 long. A tolerance
    // grown to a thousandth of the diagonal is still far below any sample spacing.
    if (d > 0 && std::isfinite(d)) {
      fix.SetPrecision(std::max(Precision::Confusion(), 1e-7 * d));
      fix.SetMaxTolerance(std::max(Precision::Confusion(), 1e-3 * d));
    }
    fix.Perform();
    const TopoDS_Shape result = fix.Shape();
    std::vector<TopoDS_Solid> solids;
    for (TopExp_Explorer ex(result, TopAbs_SOLID); ex.More(); ex.Next()) solids.push_back(TopoDS::Solid(ex.Current()));
    out.fixes = messages->text();
    if (solids.size() == 1) {
      out.solid = solids.front();
    } else {
      // Taking one of several pieces, or the shells of none, would silently change the part.
      const std::string why = solids.empty() ? "ShapeFix gave no solid" : "ShapeFix split it into " +
                                                                            std::to_string(solids.size()) + " solids";
      out.fixes = out.fixes.empty() ? why : why + " (" + out.fixes + ")";
    }
  } catch (const Standard_Failure& e) {
    // ShapeFix itself throws on some broken input (a trimmed curve of zero range, a face that is
    // not a face): then there is nothing it can heal.
    const char* m = e.GetMessageString();
    out.solid.Nullify();
    out.fixes = std::string("ShapeFix failed: ") + e.DynamicType()->Name() + (m && *m ? std::string(": ") + m : "");
  }
  return out;
}

}  // namespace cadmedial
