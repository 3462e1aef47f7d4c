"""Writes the final solids of a FreeCAD document as a BREP file, for the engine to read:

    /usr/bin/python3 fcstd.py DOCUMENT.FCStd OUT.brep

Run as a script in its own process (FreeCAD is slow to import and must not be imported in a Dask
worker); it imports nothing of cadmedial. Exit status 2 with one 'cadmedial: error:' line when the
document holds no solid."""

import sys

sys.path.append("/usr/lib/freecad/lib")


def final_solids(path):
    """The solids of the document's top-level objects (no parent): a PartDesign Body's shape is its
    tip's; legacy PartDesign, the last feature (as bench/results_part.py reads the shared models)."""
    import FreeCAD  # before Part: it sets up the paths Part needs
    # FreeCAD creates PartDesign objects by importing the Python module "PartDesign", which only
    # FreeCAD's own start-up provides (the compiled one is _PartDesign): without it openDocument
    # silently drops every Body, Pad and Pocket.
    try:
        import _PartDesign
        sys.modules.setdefault("PartDesign", _PartDesign)
    except ImportError:
        pass
    doc = FreeCAD.openDocument(path)
    try:
        try:
            doc.recompute()
        except Exception:
            pass  # the saved shapes are still there
        solids = []
        for obj in doc.Objects:
            if obj.InList or not hasattr(obj, "Shape"):
                continue
            if obj.TypeId in ("App::Origin", "App::Line", "App::Plane") or obj.TypeId.startswith("Sketcher"):
                continue
            found = obj.Shape.Solids
            tip = getattr(obj, "Tip", None)
            if not found and tip is not None and hasattr(tip, "Shape"):
                found = tip.Shape.Solids  # a Body saved without its own shape
            solids.extend(found)
        kinds = sorted({o.TypeId for o in doc.Objects})
    finally:
        FreeCAD.closeDocument(doc.Name)
    if not solids:
        raise ValueError("no top-level object holds a solid (object types: %s)" % ", ".join(kinds))
    return solids


def main(argv):
    if len(argv) != 2:
        sys.stderr.write("usage: fcstd.py DOCUMENT.FCStd OUT.brep\n")
        return 2
    source, target = argv
    try:
        solids = final_solids(source)
        import Part
        Part.makeCompound(solids).exportBrep(target)
    except Exception as e:  # FreeCAD raises bare Exception subclasses for unreadable documents
        sys.stderr.write("cadmedial: error: %s: %s\n" % (source, str(e).replace("\n", " ")))
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
