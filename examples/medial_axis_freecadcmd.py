# Headless FreeCAD: open a STEP file, compute its medial axis as a parametric MedialAxis object,
# save an .FCStd. With the addon installed (tools/install_addon.sh):
#
#   CADMEDIAL_INPUT=part.step CADMEDIAL_OUTPUT=part_medial.FCStd freecadcmd medial_axis_freecadcmd.py
#
# (freecadcmd passes no arguments to scripts, hence the environment variables; optional:
# CADMEDIAL_SAMPLES, without it 20000 and finer where the axis's topology needs it, as the
# program's default.) Exits with status 2 and a message when anything fails.
import os
import sys

import FreeCAD as App
import Part

import cadmedial.app


def main():
    source = os.environ.get("CADMEDIAL_INPUT")
    target = os.environ.get("CADMEDIAL_OUTPUT")
    if not source or not target:
        raise ValueError("set CADMEDIAL_INPUT (a STEP file) and CADMEDIAL_OUTPUT (an .FCStd file)")
    samples = os.environ.get("CADMEDIAL_SAMPLES")
    samples = int(samples) if samples else None  # None: the default density, refined

    doc = App.newDocument("Medial")
    part = doc.addObject("Part::Feature", "Part")
    part.Shape = Part.read(source)
    feature = cadmedial.app.make_medial_axis(part, samples=samples, shape=True)
    print("%s: %d samples, %d vertices, %d faces, %d edges, radius %.4g to %.4g mm, %.2f s%s"
          % (os.path.basename(source), feature.SampleCount, feature.VertexCount,
             feature.FaceCount, feature.EdgeCount, feature.RadiusMin.Value,
             feature.RadiusMax.Value, feature.ComputeTime,
             ", refined %d times for the topology" % feature.Refinements if feature.Refinements else ""))
    doc.saveAs(os.path.abspath(target))
    print("saved", target)


try:
    main()
    code = 0
except Exception as error:  # one line for the user, not a traceback
    print("medial_axis_freecadcmd: %s" % error, file=sys.stderr)
    code = 2
sys.stdout.flush()
sys.stderr.flush()
os._exit(code)  # freecadcmd would turn sys.exit into status 0
