"""Files of a thickness analysis: per-point values (PLY, CSV), regions and faces (CSV)."""

import csv
import os

import numpy as np

from ..colormap import colors_of


def _replace(path, write):
    # Written to a temporary file and renamed, as the program's other outputs: never a partial file.
    tmp = path + ".part"
    write(tmp)
    os.replace(tmp, path)


def write_points_csv(result, path):
    """x, y, z, thickness, counted (0/1: left out as a corner when 0), one row per point."""
    def write(tmp):
        with open(tmp, "w", newline="") as f:
            out = csv.writer(f)
            out.writerow(["x", "y", "z", "thickness", "counted"])
            for p, v, c in zip(result.points.tolist(), result.values.tolist(),
                               result.counted.tolist()):
                out.writerow(["%.9g" % p[0], "%.9g" % p[1], "%.9g" % p[2], "%.9g" % v, int(c)])
    _replace(path, write)


def write_points_ply(result, path, low=None, high=None):
    """Binary PLY of the surface mesh: vertex x y z thickness (doubles), red green blue (uchar,
    viridis from low to high, default the counted range), counted (uchar); face vertex_indices
    and face (the B-rep face index, 0-based)."""
    low = result.statistics["min"] if low is None else low
    high = result.statistics["max"] if high is None else high
    rgb = (colors_of(result.values, low or 0.0, high or 1.0) * 255 + 0.5).astype(np.uint8)
    n, t = len(result.points), len(result.triangles)
    vertex = np.zeros(n, dtype=[("x", "<f8"), ("y", "<f8"), ("z", "<f8"), ("thickness", "<f8"),
                                ("red", "u1"), ("green", "u1"), ("blue", "u1"),
                                ("counted", "u1")])
    vertex["x"], vertex["y"], vertex["z"] = result.points.T
    vertex["thickness"] = result.values
    vertex["red"], vertex["green"], vertex["blue"] = rgb.T
    vertex["counted"] = result.counted
    face = np.zeros(t, dtype=[("n", "u1"), ("v", "<i4", (3,)), ("face", "<i4")])
    face["n"], face["v"], face["face"] = 3, result.triangles, result.triangle_face
    header = ("ply\nformat binary_little_endian 1.0\ncomment cadmedial wall thickness\n"
              "element vertex %d\nproperty double x\nproperty double y\nproperty double z\n"
              "property double thickness\nproperty uchar red\nproperty uchar green\n"
              "property uchar blue\nproperty uchar counted\nelement face %d\n"
              "property list uchar int vertex_indices\nproperty int face\nend_header\n" % (n, t))

    def write(tmp):
        with open(tmp, "wb") as f:
            f.write(header.encode("ascii"))
            f.write(vertex.tobytes())
            f.write(face.tobytes())
    _replace(path, write)


def write_points(result, path):
    """By extension: .csv or .ply; ValueError otherwise."""
    ext = os.path.splitext(path)[1].lower()
    if ext == ".csv":
        write_points_csv(result, path)
    elif ext == ".ply":
        write_points_ply(result, path)
    else:
        raise ValueError("%s: the values are written as .ply or .csv" % path)


def face_table(result):
    """List of dicts, one per B-rep face with counted points: face, area, min, max, mean
    (area-weighted over its counted points; a point on an edge counts for each face)."""
    tri_area = np.zeros(len(result.triangles))
    a, b, c = (result.points[result.triangles[:, i]] for i in range(3))
    tri_area = 0.5 * np.linalg.norm(np.cross(b - a, c - a), axis=1)
    rows = []
    order = np.argsort(result.triangle_face, kind="stable")
    faces, starts = np.unique(result.triangle_face[order], return_index=True)
    ends = np.append(starts[1:], len(order))
    for f, lo, hi in zip(faces.tolist(), starts.tolist(), ends.tolist()):
        tris = result.triangles[order[lo:hi]]
        pts = np.unique(tris.ravel())
        pts = pts[result.counted[pts]]
        area = float(tri_area[order[lo:hi]].sum())
        if len(pts) == 0:
            rows.append({"face": result.face_names[f], "area": area, "min": None, "max": None,
                         "mean": None})
            continue
        w = np.zeros(len(result.points))
        np.add.at(w, tris.ravel(), np.repeat(tri_area[order[lo:hi]] / 3.0, 3))
        v, wp = result.values[pts], w[pts]
        rows.append({"face": result.face_names[f], "area": area, "min": float(v.min()),
                     "max": float(v.max()), "mean": float((v * wp).sum() / max(wp.sum(), 1e-300))})
    return rows


def write_regions_csv(result, path):
    """kind, extreme, x, y, z, faces (space-separated), area, min, max: one row per region."""
    def write(tmp):
        with open(tmp, "w", newline="") as f:
            out = csv.writer(f)
            out.writerow(["kind", "extreme", "x", "y", "z", "faces", "area", "min", "max"])
            for g in result.thin_regions + result.thick_regions:
                out.writerow([g["kind"], "%.6g" % g["extreme"]] + ["%.6g" % x for x in g["at"]]
                             + [" ".join(g["faces"]), "%.6g" % g["area"], "%.6g" % g["min"],
                                "%.6g" % g["max"]])
    _replace(path, write)


def write_faces_csv(result, path):
    """face, area, min, max, mean: one row per B-rep face (see face_table)."""
    fmt = lambda x: "" if x is None else "%.6g" % x

    def write(tmp):
        with open(tmp, "w", newline="") as f:
            out = csv.writer(f)
            out.writerow(["face", "area", "min", "max", "mean"])
            for row in face_table(result):
                out.writerow([row["face"]] + [fmt(row[k]) for k in ("area", "min", "max", "mean")])
    _replace(path, write)
