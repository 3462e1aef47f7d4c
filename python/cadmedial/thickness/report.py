"""The one-page HTML report of a thickness analysis: picture, settings, statistics, histogram,
regions and faces."""

import base64
import html
import os

from .picture import render_png
from .writers import _replace, face_table

MAX_FACE_ROWS = 40


def _num(x, digits=4):
    return "&ndash;" if x is None else "%.*g" % (digits, x)


def _table(head, rows):
    out = ["<table><tr>" + "".join("<th>%s</th>" % h for h in head) + "</tr>"]
    for row in rows:
        out.append("<tr>" + "".join("<td>%s</td>" % c for c in row) + "</tr>")
    out.append("</table>")
    return "\n".join(out)


def report_html(result, title, png=None):
    """The report as a str (the picture inline as a PNG data URI). png: the picture's PNG bytes
    (FreeCAD's GUI passes its 3D view); default a matplotlib picture of the mesh."""
    s, st = result.settings, result.statistics
    low = s["min"] if s["min"] is not None else (st["min"] or 0.0)
    high = s["max"] if s["max"] is not None else (st["max"] or 1.0)
    if not high > low:
        high = low + 1.0
    png = base64.b64encode(render_png(result, low, high) if png is None else png).decode("ascii")
    verdict = "PASS" if result.passed else "FAIL"
    settings = _table(["setting", "value"], [
        ["minimum wall", _num(s["min"])], ["maximum wall", _num(s["max"])],
        ["corners", html.escape(s["corners"])], ["sample spacing", _num(s["spacing"])],
        ["corner band", _num(s["band"])], ["surface points", str(len(result.points))],
        ["solids", str(s["solids"])]])
    stats = _table(["statistic", "value"], [
        ["minimum", _num(st["min"])], ["maximum", _num(st["max"])],
        ["area-weighted mean", _num(st["mean"])],
        ["share of area below the minimum", _num(None if st["share_below_min"] is None
                                                 else 100 * st["share_below_min"], 3) + " %"],
        ["share of area above the maximum", _num(None if st["share_above_max"] is None
                                                 else 100 * st["share_above_max"], 3) + " %"],
        ["area counted / total", "%s / %s" % (_num(st["area"]), _num(st["area_total"]))]])
    edges, areas = st["histogram"]["edges"], st["histogram"]["area"]
    hist = _table(["thickness from", "to", "area", "share"], [
        [_num(edges[i]), _num(edges[i + 1]), _num(areas[i]),
         _num(100 * areas[i] / st["area"] if st["area"] else None, 3) + " %"]
        for i in range(len(areas))])
    regions = _table(["kind", "extreme", "at (x, y, z)", "faces", "area"], [
        [g["kind"], _num(g["extreme"]), "(%s)" % ", ".join(_num(x, 6) for x in g["at"]),
         html.escape(" ".join(g["faces"][:12]) + (" ..." if len(g["faces"]) > 12 else "")),
         _num(g["area"])] for g in result.thin_regions + result.thick_regions])
    faces = sorted(face_table(result), key=lambda r: (r["min"] is None, r["min"] or 0.0))
    face_rows = _table(["face", "min", "max", "mean", "area"], [
        [r["face"], _num(r["min"]), _num(r["max"]), _num(r["mean"]), _num(r["area"])]
        for r in faces[:MAX_FACE_ROWS]])
    return """<!DOCTYPE html>
<html><head><meta charset="utf-8"><title>Wall thickness: {title}</title>
<style>body{{font-family:sans-serif;margin:1.5em;max-width:1100px}}
table{{border-collapse:collapse;margin:0.5em 1em 1em 0;display:inline-table;vertical-align:top}}
td,th{{border:1px solid #bbb;padding:2px 8px;text-align:right}} th{{background:#eee}}
.verdict{{font-size:1.4em;font-weight:bold;color:{colour}}}</style></head><body>
<h1>Wall thickness: {title}</h1>
<p class="verdict">{verdict}: {nthin} thin region(s), {nthick} thick region(s)</p>
<p>Sphere thickness: the diameter of the largest ball inside the solid containing the point,
from the medial axis (cadmedial). Thin regions red, thick magenta.</p>
<img src="data:image/png;base64,{png}" style="max-width:100%">
<div>{settings}{stats}</div>
<h2>Histogram (area per thickness range, counted points)</h2>{hist}
<h2>Regions</h2>{regions}
<h2>Faces (thinnest first{more})</h2>{faces}
</body></html>
""".format(title=html.escape(title), verdict=verdict,
           colour="#080" if result.passed else "#c00", nthin=len(result.thin_regions),
           nthick=len(result.thick_regions), png=png, settings=settings, stats=stats, hist=hist,
           regions=regions, faces=face_rows,
           more=", first %d" % MAX_FACE_ROWS if len(faces) > MAX_FACE_ROWS else "")


def write_report(result, path, title, png=None):
    text = report_html(result, title, png)

    def write(tmp):
        with open(tmp, "w", encoding="utf-8") as f:
            f.write(text)
    _replace(os.fspath(path), write)
