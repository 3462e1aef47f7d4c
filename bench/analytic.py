"""The analytic test solids (FreeCAD Part) and dense samples of their exact inner medial axes.

Same solids and sizes as tests/cpp/support/exact_cases.cpp: box 10x8x6, plate 20x10x1, wedge
(triangular prism), cylinder R=2 H=8, disc R=5 H=2, sphere R=3, torus 5/1.5.

Exact axis samples:
 * convex polytope (box, plate, wedge): the axis is the set where the two smallest face-plane
   distances tie. Random points of the solid are projected onto the bisector plane of their two
   nearest planes; a projection is kept when those two still are the nearest (to 1e-9).
 * solids of revolution: the axis is a surface of revolution of curves in the meridian half-plane
   (rho, z), so the distance of a point to it is the 2D distance of (rho, z) to those curves,
   sampled every 1e-4 of the size.
"""
import numpy as np


def make_shape(name):
    import Part
    from FreeCAD import Vector
    if name == "box":
        return Part.makeBox(10, 8, 6)
    if name == "plate":
        return Part.makeBox(20, 10, 1)
    if name == "wedge":
        pts = [Vector(0, 0, 0), Vector(6, 0, 0), Vector(2, 5, 0), Vector(0, 0, 0)]
        return Part.Face(Part.makePolygon(pts)).extrude(Vector(0, 0, 4))
    if name == "cylinder":
        return Part.makeCylinder(2, 8)
    if name == "disc":
        return Part.makeCylinder(5, 2)
    if name == "sphere":
        return Part.makeSphere(3)
    if name == "torus":
        return Part.makeTorus(5, 1.5)
    raise KeyError(name)


NAMES = ["box", "plate", "wedge", "cylinder", "disc", "sphere", "torus"]


def _planes(name):
    """(normals (k,3), offsets (k,)): inside iff n.x <= b."""
    if name in ("box", "plate"):
        a, b, c = (10, 8, 6) if name == "box" else (20, 10, 1)
        n = np.array([[-1, 0, 0], [1, 0, 0], [0, -1, 0], [0, 1, 0], [0, 0, -1], [0, 0, 1]], float)
        return n, np.array([0, a, 0, b, 0, c], float)
    tri = np.array([[0, 0], [6, 0], [2, 5]], float)
    ns, bs = [], []
    for i in range(3):
        p, q = tri[i], tri[(i + 1) % 3]
        d = q - p
        n = np.array([d[1], -d[0], 0.0]) / np.hypot(*d)   # outward for a counter-clockwise triangle
        ns.append(n)
        bs.append(n[:2] @ p)
    ns += [[0, 0, -1], [0, 0, 1]]
    bs += [0, 4]
    return np.array(ns, float), np.array(bs, float)


def _polytope_axis(name, n_random=800_000, seed=1):
    N, B = _planes(name)
    rng = np.random.default_rng(seed)
    lo = np.array([0, 0, 0.0])
    hi = {"box": [10, 8, 6], "plate": [20, 10, 1], "wedge": [6, 5, 4]}[name]
    x = lo + rng.random((n_random, 3)) * np.array(hi, float)
    d = B[None, :] - x @ N.T
    x, d = x[(d >= 0).all(1)], d[(d >= 0).all(1)]
    order = np.argsort(d, axis=1)
    i, j = order[:, 0], order[:, 1]
    m = N[i] - N[j]
    t = ((B[i] - B[j]) - np.einsum("ij,ij->i", m, x)) / np.einsum("ij,ij->i", m, m)
    y = x + t[:, None] * m
    dy = B[None, :] - y @ N.T
    di = dy[np.arange(len(y)), i]
    ok = (dy >= -1e-9).all(1) & (dy >= di[:, None] - 1e-9).all(1)
    return y[ok]


# Meridian curves (rho, z) of the revolved axes.
def _meridian_curves(name):
    s = np.linspace(0, 1, 20001)
    if name == "cylinder":  # R=2, H=8: axis segment z in [R, H-R], cones to the rims
        R, H = 2.0, 8.0
        seg = np.c_[0 * s, R + s * (H - 2 * R)]
        c1 = np.c_[R * s, R - R * s]          # rho = R - z, z in [0, R]
        c2 = np.c_[R * s, H - R + R * s]
        return np.vstack([seg, c1, c2])
    if name == "disc":  # R=5, H=2: mid-plane disc rho <= R - H/2, cones to the rims
        R, H = 5.0, 2.0
        disc = np.c_[(R - H / 2) * s, H / 2 + 0 * s]
        c1 = np.c_[R - H / 2 + (H / 2) * s, H / 2 - (H / 2) * s]
        c2 = np.c_[R - H / 2 + (H / 2) * s, H / 2 + (H / 2) * s]
        return np.vstack([disc, c1, c2])
    if name == "sphere":
        return np.array([[0.0, 0.0]])
    if name == "torus":
        return np.array([[5.0, 0.0]])
    raise KeyError(name)


def exact_axis(name):
    """(distance(points) -> array, axis_points (m,3)) for an analytic solid."""
    from scipy.spatial import cKDTree
    if name in ("box", "plate", "wedge"):
        pts = _polytope_axis(name)
        tree = cKDTree(pts, balanced_tree=False, compact_nodes=False)
        return (lambda q: tree.query(q)[0]), pts
    curves = _meridian_curves(name)
    tree = cKDTree(curves, balanced_tree=False, compact_nodes=False)

    def dist(q):
        return tree.query(np.c_[np.hypot(q[:, 0], q[:, 1]), q[:, 2]])[0]

    # 3D samples of the axis, area weighted (weight rho), random angles.
    rng = np.random.default_rng(2)
    if len(curves) == 1:
        rho, z = curves[0]
        if rho == 0:
            pts = np.array([[0.0, 0.0, z]])
        else:
            a = np.linspace(0, 2 * np.pi, 4000, endpoint=False)
            pts = np.c_[rho * np.cos(a), rho * np.sin(a), z + 0 * a]
        return dist, pts
    w = curves[:, 0] + 1e-3
    k = rng.choice(len(curves), 300_000, p=w / w.sum())
    a = rng.random(len(k)) * 2 * np.pi
    pts = np.c_[curves[k, 0] * np.cos(a), curves[k, 0] * np.sin(a), curves[k, 1]]
    return dist, pts


def convex_features(name, h):
    """(points every <= h/2 along the convex edges, non-concave corners) of an analytic solid."""
    def seg(a, b):
        k = max(1, int(np.ceil(np.linalg.norm(b - a) / (h / 2))))
        return a + np.linspace(0, 1, k + 1)[:, None] * (b - a)

    def circle(R, z):
        k = int(np.ceil(2 * np.pi * R / (h / 2)))
        t = np.linspace(0, 2 * np.pi, k, endpoint=False)
        return np.c_[R * np.cos(t), R * np.sin(t), z + 0 * t]

    if name in ("box", "plate", "wedge"):
        if name == "wedge":
            base = np.array([[0, 0], [6, 0], [2, 5]], float)
            H = 4.0
        else:
            a, b, H = (10, 8, 6) if name == "box" else (20, 10, 1)
            base = np.array([[0, 0], [a, 0], [a, b], [0, b]], float)
        k = len(base)
        bot = np.c_[base, np.zeros(k)]
        top = np.c_[base, np.full(k, H)]
        edges = [seg(bot[i], bot[(i + 1) % k]) for i in range(k)]
        edges += [seg(top[i], top[(i + 1) % k]) for i in range(k)]
        edges += [seg(bot[i], top[i]) for i in range(k)]
        return np.vstack(edges), np.vstack([bot, top])
    if name == "cylinder":
        return np.vstack([circle(2, 0), circle(2, 8)]), np.zeros((0, 3))
    if name == "disc":
        return np.vstack([circle(5, 0), circle(5, 2)]), np.zeros((0, 3))
    return np.zeros((0, 3)), np.zeros((0, 3))
