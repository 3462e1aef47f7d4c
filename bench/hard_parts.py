"""Seeded generator of random hard solids (issue 32 item 6).

    /usr/bin/python3 bench/hard_parts.py --seeds 0-299 -o bench/out/hard/

generate(seed) -> (shape, meta); family = seed % len(FAMILIES). meta["solids"][i]["euler"] is each
solid's Euler characteristic by construction (1 - handles + cavities), not measured from the B-rep.
"""
import argparse
import json
import math
import os
import random
import sys

sys.path.append("/usr/lib/freecad/lib")
import FreeCAD  # noqa: E402,F401
import Part  # noqa: E402
from FreeCAD import Vector as V  # noqa: E402


def box(x, y, z, at=(0, 0, 0)):
    return Part.makeBox(x, y, z, V(*at))


def smd_chip(r):
    L = r.uniform(0.5, 6.0)
    w, t = L * r.uniform(0.3, 0.6), L * r.uniform(0.15, 0.4)
    cap = L * r.uniform(0.1, 0.25)
    body = box(L - 2 * cap, w, t, (cap, 0, 0))
    caps = [box(cap, w, t, (0, 0, 0)), box(cap, w, t, (L - cap, 0, 0))]
    return [body] + caps, [1, 1, 1], dict(L=L, w=w, t=t, cap=cap)


def gullwing(r):
    L = r.uniform(1.0, 10.0)
    w, t = L * r.uniform(0.4, 0.8), L * r.uniform(0.1, 0.3)
    th = L * r.uniform(0.005, 0.02)
    n = r.randint(1, 4)
    body = box(L, w, t, (0, 0, th * 2))
    solids = [body]
    lw = L / (2 * n + 1) * 0.8
    reach = w * r.uniform(0.15, 0.3)
    for side in (0, 1):
        for k in range(n):
            x = L * (2 * k + 1.1) / (2 * n + 1)
            y0 = w if side == 0 else -reach
            ys = 1 if side == 0 else -1
            # flat strip at body mid height out, down, and a foot: three boxes fused
            zmid = th * 2 + t / 2
            out = box(lw, reach / 2, th, (x, w if side == 0 else -reach / 2, zmid))
            yd = (w + reach / 2 - th) if side == 0 else (-reach / 2)
            down = box(lw, th, zmid - 0 + th, (x, yd, 0))
            yf = (w + reach / 2 - th) if side == 0 else (-reach)
            foot = box(lw, reach / 2 + th, th, (x, yf, 0))
            lead = out.fuse(down).fuse(foot).removeSplitter()
            solids.append(Part.Solid(lead.Solids[0]) if lead.Solids else lead)
            del y0, ys
    return solids, [1] * len(solids), dict(L=L, w=w, t=t, lead=th, n=n)


def can(r):
    R = r.uniform(1.0, 20.0)
    H = R * r.uniform(0.5, 3.0)
    wall = 2 * R * r.uniform(0.0005, 0.01)
    bottom = r.random() < 0.6
    outer = Part.makeCylinder(R, H)
    inner = Part.makeCylinder(R - wall, H + 2 * wall, V(0, 0, wall if bottom else -wall))
    s = outer.cut(inner)
    holes = r.randint(0, 3) if bottom else 0
    for k in range(holes):
        a = 2 * math.pi * k / max(holes, 1)
        hr = R * r.uniform(0.05, 0.15)
        s = s.cut(Part.makeCylinder(hr, 3 * wall, V(0.5 * R * math.cos(a), 0.5 * R * math.sin(a), -wall)))
    chi = (1 - holes) if bottom else 0
    return [s.Solids[0]], [chi], dict(R=R, H=H, wall=wall, bottom=bottom, holes=holes)


def bracket(r):
    L = r.uniform(10, 100)
    t = L * r.uniform(0.005, 0.03)
    W = L * r.uniform(0.2, 0.6)
    H = L * r.uniform(0.2, 0.8)
    s = box(L, W, t).fuse(box(t, W, H)).removeSplitter()
    s = Part.Solid(s.Solids[0])
    ri = t * r.uniform(0.5, 3.0)
    inner = [e for e in s.Edges if abs(e.Length - W) < 1e-9 * L and abs(e.Vertexes[0].X - t) < 1e-9 * L
             and abs(e.Vertexes[0].Z - t) < 1e-9 * L]
    if inner:
        s = s.makeFillet(ri, inner)
    n = r.randint(0, 4)
    for k in range(n):
        hr = min(W, L) * r.uniform(0.03, 0.08)
        s = s.cut(Part.makeCylinder(hr, 3 * t, V(L * (0.3 + 0.6 * k / max(n, 1)) , W / 2, -t)))
    return [s.Solids[0]], [1 - n], dict(L=L, t=t, W=W, H=H, fillet=ri, holes=n)


def ribbed(r):
    L = r.uniform(10, 100)
    W = L * r.uniform(0.3, 1.0)
    T = L * r.uniform(0.01, 0.05)
    rib = L * r.uniform(0.003, 0.02)
    hr = L * r.uniform(0.02, 0.2)
    n = r.randint(2, 12)
    s = box(L, W, T)
    for k in range(n):
        s = s.fuse(box(rib, W, hr, ((k + 0.5) * L / n, 0, T)))
    s = s.removeSplitter()
    return [s.Solids[0]], [1], dict(L=L, W=W, T=T, rib=rib, rib_h=hr, ribs=n)


def holes_plate(r):
    L = r.uniform(10, 200)
    W = L * r.uniform(0.5, 1.0)
    T = L * r.uniform(0.01, 0.05)
    n = r.randint(20, 200)
    nx = int(math.ceil(math.sqrt(n * L / W)))
    ny = int(math.ceil(n / nx))
    px, py = L / nx, W / ny
    hole = min(px, py) * r.uniform(0.2, 0.45)
    square = r.random() < 0.4
    cutters = []
    for k in range(n):
        cx, cy = (k % nx + 0.5) * px, (k // nx + 0.5) * py
        if square:
            cutters.append(box(2 * hole, 2 * hole, 3 * T, (cx - hole, cy - hole, -T)))
        else:
            cutters.append(Part.makeCylinder(hole, 3 * T, V(cx, cy, -T)))
    s = box(L, W, T).cut(Part.makeCompound(cutters))
    return [s.Solids[0]], [1 - n], dict(L=L, W=W, T=T, holes=n, hole=hole, square=square)


def wedge(r):
    L = r.uniform(5, 50)
    ang = math.radians(r.uniform(5, 25))
    H = L * math.tan(ang)
    W = L * r.uniform(0.3, 1.5)
    w = Part.makePolygon([V(0, 0, 0), V(L, 0, 0), V(L, 0, H), V(0, 0, 0)])
    s = Part.Face(w).extrude(V(0, W, 0))
    s = Part.Solid(s)
    c = min(H, W) * r.uniform(0.02, 0.2)
    edges = [e for e in s.Edges if abs(e.Vertexes[0].X - L) < 1e-9 * L and abs(e.Vertexes[-1].X - L) < 1e-9 * L
             and abs(e.Length - W) < 1e-9 * L]
    if edges and r.random() < 0.8:
        try:
            s = s.makeChamfer(c, edges[:1])
        except Exception:
            pass
    return [s.Solids[0]], [1], dict(L=L, angle_deg=math.degrees(ang), W=W, chamfer=c)


def bosses(r):
    L = r.uniform(10, 100)
    s = box(L, L * r.uniform(0.4, 1), L * r.uniform(0.2, 0.6))
    top = s.BoundBox.ZMax
    n = r.randint(1, 6)
    for k in range(n):
        f = L * 10 ** r.uniform(-3, -2)
        x, y = r.uniform(0.1, 0.9) * L, r.uniform(0.1, 0.9) * s.BoundBox.YMax
        if r.random() < 0.5:
            s = s.fuse(Part.makeCylinder(f, f * r.uniform(0.5, 3), V(x, y, top)))
        else:
            s = s.cut(box(f * r.uniform(3, 20), f, f, (x, y, top - f)))
    s = s.removeSplitter()
    return [s.Solids[0]], [1], dict(L=L, features=n)


def assembly(r):
    n = r.randint(2, 6)
    solids, x = [], 0.0
    for k in range(n):
        a = r.uniform(1, 10)
        if r.random() < 0.5:
            solids.append(box(a, r.uniform(1, 10), r.uniform(1, 10), (x, 0, 0)))
        else:
            c = Part.makeCylinder(a / 2, r.uniform(1, 10), V(x + a / 2, a / 2, 0))
            solids.append(c)
        x += a
    return solids, [1] * n, dict(n=n)


def splines(r):
    L = r.uniform(5, 50)
    secs = []
    for k in range(4):
        rad = L * r.uniform(0.1, 0.4)
        secs.append(Part.Wire(Part.makeCircle(rad, V(r.uniform(-0.1, 0.1) * L, 0, k * L / 3))))
    s = Part.makeLoft(secs, True, False)
    s = Part.Solid(s) if s.ShapeType != "Solid" else s
    return [s], [1], dict(L=L)


FAMILIES = [("smd_chip", smd_chip), ("gullwing", gullwing), ("can", can), ("bracket", bracket),
            ("ribbed_plate", ribbed), ("holes_plate", holes_plate), ("wedge", wedge),
            ("bosses_slots", bosses), ("assembly", assembly), ("spline_fillet", splines)]


def generate(seed):
    name, fn = FAMILIES[seed % len(FAMILIES)]
    tries = []
    for attempt in range(10):
        derived = seed if attempt == 0 else seed * 1000 + attempt
        r = random.Random(derived)
        try:
            solids, eulers, params = fn(r)
            shape = Part.makeCompound(solids) if len(solids) > 1 else solids[0]
            if not shape.isValid() or any(not s.isValid() or s.Volume <= 0 for s in shape.Solids) \
                    or len(shape.Solids) != len(eulers):
                raise ValueError("invalid shape")
            break
        except Exception as e:  # noqa: BLE001 - recorded in meta
            tries.append({"seed": derived, "error": str(e)})
    else:
        raise RuntimeError("seed %d: no valid shape in 10 tries" % seed)
    meta = {"seed": seed, "family": name, "used_seed": derived, "failed_tries": tries,
            "params": params, "diagonal": shape.BoundBox.DiagonalLength,
            "solids": [{"euler": e} for e in eulers]}
    return shape, meta


def parse_seeds(s):
    a, _, b = s.partition("-")
    return list(range(int(a), int(b or a) + 1))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--seeds", default="0-299")
    ap.add_argument("-o", "--out", required=True)
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    man = []
    for seed in parse_seeds(a.seeds):
        shape, meta = generate(seed)
        meta["file"] = "seed_%03d.brep" % seed
        shape.exportBrep(os.path.join(a.out, meta["file"]))
        man.append(meta)
    json.dump(man, open(os.path.join(a.out, "manifest.json"), "w"), indent=1)


if __name__ == "__main__":
    main()
