"""Writes the bad-input corpus of tests/data/bad/ (see README.md there) with FreeCAD's Part module.

Run with the interpreter FreeCAD 0.20 is built for, from anywhere:
    /usr/bin/python3 tests/data/bad/make_bad_inputs.py
Every file is small (a few KB) and deterministic; the files are committed, this script documents
how they were made.
"""
import os
import sys

sys.path.append("/usr/lib/freecad/lib")
import FreeCAD  # noqa: E402
import Part  # noqa: E402

V = FreeCAD.Vector
HERE = os.path.dirname(os.path.abspath(__file__))


def path(name):
    return os.path.join(HERE, name)


def brep(name, shape):
    with open(path(name), "w") as f:
        f.write(shape.exportBrepToString())


def polygon_face(points):
    return Part.Face(Part.makePolygon([V(*p) for p in points] + [V(*points[0])]))


# Empty file, with a STEP extension (the reader must not even try).
open(path("empty.step"), "w").close()

# A valid STEP box cut in the middle of its DATA section.
box = Part.makeBox(10, 20, 30)
box.exportStep(path("_box.step"))
with open(path("_box.step")) as f:
    text = f.read()
os.remove(path("_box.step"))
with open(path("truncated.step"), "w") as f:
    f.write(text[: len(text) // 2])

# STEP files with no solid: a wire only, a face only.
Part.makePolygon([V(0, 0, 0), V(10, 0, 0), V(10, 10, 0)]).exportStep(path("wire_only.step"))
Part.makePlane(10, 10).exportStep(path("face_only.step"))

# An open shell: a box without its top face.
brep("open_shell.brep", Part.Shell(box.Faces[:5]))

# Two faces that do not meet (a loose compound of faces, far apart).
brep("two_faces_apart.brep", Part.makeCompound([
    Part.makePlane(10, 10), Part.makePlane(10, 10, V(0, 0, 50))]))

# A non-manifold edge: a box's shell plus a fin on its edge y = 0, z = 0, fused so that the three
# faces share that edge, as one shell.
fin = polygon_face([(0, 0, 0), (10, 0, 0), (10, -10, 0), (0, -10, 0)])
brep("nonmanifold_edge.brep", Part.Shell(box.Shells[0].generalFuse([fin])[0].Faces))

# A self-intersecting solid: a prism on a crossed ("bow tie") quadrilateral, its side faces cross.
bow = polygon_face([(0, 0, 0), (10, 10, 0), (10, 0, 0), (0, 30, 0)])
brep("self_intersecting.brep", bow.extrude(V(0, 0, 5)))

# A compound of two overlapping solids (each one valid on its own).
brep("overlapping_solids.brep", Part.makeCompound([
    Part.makeBox(10, 10, 10), Part.makeBox(10, 10, 10, V(5, 5, 5))]))

# A zero-volume solid: a 10 mm cube squashed flat (z scaled by 0): a Solid whose faces all lie in
# z = 0.
flatten = FreeCAD.Matrix()
flatten.scale(1, 1, 0)
brep("zero_volume.brep", Part.makeBox(10, 10, 10).transformGeometry(flatten))

# degenerate_edge.brep (a face with a zero-length edge) is written by make_degenerate_edge.cpp:
# Part refuses to make such an edge.

# Tiny and huge solids: the same 1 x 2 x 3 box shape scaled to 1e-6 and 1e6.
brep("tiny_box.brep", Part.makeBox(1e-6, 2e-6, 3e-6))
brep("huge_box.brep", Part.makeBox(1e6, 2e6, 3e6))

# A sliver face narrower than the sample spacing: a 20 x 20 x 10 block with a 1e-3 step on top.
block = Part.makeBox(20, 20, 10).fuse(Part.makeBox(20, 10, 10.001)).removeSplitter()
brep("sliver_face.brep", block)
print("wrote", sorted(os.listdir(HERE)))
