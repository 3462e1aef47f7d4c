"""Quality measures of a medial mesh against its solid (FreeCAD Part shape), all in numpy/scipy.

Approximations (stated again in docs/RESULTS.md):
 * The solid's surface S is a dense random sample of FreeCAD's tessellation (deflection 5e-4 of
   the bounding-box diagonal, so points are within that of the exact surface), face by face,
   with outward triangle normals.
 * Union of medial balls U = union of B(c_i, r_i) over the output vertices. For a surface point y,
   e(y) = min_i (|y - c_i| - r_i) is the signed distance to U when y is outside U (exact for a
   union of balls). Candidates: the 8 centres nearest y and the 4 nearest y +- d n
   (n the tessellation normal) for depths d = h/2 * 1.5^m up to the largest radius: a ball
   touching y has its centre near y + r n. A missed ball can only make e(y) larger (pessimistic).
   "uncovered" = max_y max(e(y), 0): surface no ball reaches.
   S -> boundary of U: |e(y)|; inside U, -e(y) = max_i (r_i - |y - c_i|) is a lower bound of the
   distance to the union's boundary.
 * "stick out" = max_i (r_i - d(c_i, S)), d from the surface sample (k-d query within 1 % of it): overestimates d by at most 1 % plus
   the sample's covering radius, so stick-out is underestimated by at most that (reported).
 * Hausdorff(S, boundary U) = max of the two above. Pockets of the union's boundary deep inside
   the solid (parts of the solid no ball covers that do not reach the surface) are not measured.
"""
import numpy as np
from scipy.spatial import cKDTree


def tessellate(shape, diag):
    """(P (n,3), T (m,3), oriented): FreeCAD's tessellation face by face, each face's triangles
    turned so that their normals agree with the face's outward normal (Face.normalAt) at the
    centroid of its largest triangle; oriented is False when some face could not be checked."""
    Ps, Ts, off, oriented = [], [], 0, True
    for face in shape.Faces:
        pts, tris = face.tessellate(5e-4 * diag)
        if not tris:
            continue
        p = np.array([[q.x, q.y, q.z] for q in pts], float)
        t = np.array(tris, int).reshape(-1, 3)
        n = np.cross(p[t[:, 1]] - p[t[:, 0]], p[t[:, 2]] - p[t[:, 0]])
        k = int(np.argmax(np.einsum("ij,ij->i", n, n)))
        try:
            from FreeCAD import Vector
            u, v = face.Surface.parameter(Vector(*p[t[k]].mean(0)))
            m = face.normalAt(u, v)
            if n[k] @ np.array([m.x, m.y, m.z]) < 0:
                t = t[:, ::-1]
        except Exception:  # noqa: BLE001 - a face without a normal there: orientation unknown
            oriented = False
        Ps.append(p)
        Ts.append(t + off)
        off += len(p)
    if not Ps:
        return np.zeros((0, 3)), np.zeros((0, 3), int), False
    return np.vstack(Ps), np.vstack(Ts), oriented


def sample_triangles(P, T, n, rng, normals=False):
    a, b, c = P[T[:, 0]], P[T[:, 1]], P[T[:, 2]]
    cr = np.cross(b - a, c - a)
    area = 0.5 * np.linalg.norm(cr, axis=1)
    if area.sum() <= 0:
        return np.zeros((0, 3)), 0.0
    k = rng.choice(len(T), n, p=area / area.sum())
    u, v = rng.random(n), rng.random(n)
    flip = u + v > 1
    u[flip], v[flip] = 1 - u[flip], 1 - v[flip]
    Y = a[k] + u[:, None] * (b[k] - a[k]) + v[:, None] * (c[k] - a[k])
    if normals:
        return Y, float(area.sum()), cr[k] / (2 * area[k][:, None])
    return Y, float(area.sum())


def signed_distance_to_balls(Y, N, C, R, h, k=4, bounded=True):
    """e(y) = min_i (|y - c_i| - r_i) over candidate balls: the 8 centres nearest y, and the k
    centres nearest y + d n and y - d n (n the surface normal at y) within d of that point, for
    depths d from h/2 to the largest radius in steps of ratio 1.5 (a ball touching y has its
    centre near y + r n, where n points inwards: within d/2 of y + d n for r in [d, 1.5 d]).
    Candidate search, so e(y) can only be overestimated (a ball missed). The bound d makes the
    query on the outer side, where no centre lies, cost almost nothing (the k-d tree prunes it):
    far from a sheet-like set of centres an unbounded k-nearest query is slow."""
    # Coincident centres (many Voronoi vertices on a cylinder's axis) make k-d queries crawl.
    scale = max(np.abs(C).max(), 1e-12) * 1e-9
    _, keep = np.unique(np.round(np.c_[C, R] / scale), axis=0, return_index=True)
    C, R = C[keep], R[keep]
    tree = cKDTree(C, balanced_tree=False, compact_nodes=False)
    _, j = tree.query(Y, min(8, len(C)))
    j = j.reshape(len(Y), -1)
    best = (np.linalg.norm(Y[:, None, :] - C[j], axis=2) - R[j]).min(1)
    d = h / 2
    kk = min(k, len(C))
    while d < 1.5 * R.max():
        for sgn in (1.0, -1.0):
            dist, j = tree.query(Y + sgn * d * N, kk, distance_upper_bound=d if bounded else np.inf)
            j = j.reshape(len(Y), -1)
            found = np.isfinite(dist.reshape(len(Y), -1)[:, 0])
            if not found.any():
                continue
            jf = j[found]
            # Missing neighbours come back as index len(C): give them an infinite value.
            jc = np.minimum(jf, len(C) - 1)
            val = np.linalg.norm(Y[found][:, None, :] - C[jc], axis=2) - R[jc]
            val[jf == len(C)] = np.inf
            best[found] = np.minimum(best[found], val.min(1))
        d *= 1.5
    return best


def reconstruction_error(shape, diag, V, R, h, n_surface=30_000, seed=0):
    rng = np.random.default_rng(seed)
    P, T, oriented = tessellate(shape, diag)
    Y, area, N = sample_triangles(P, T, n_surface, rng, normals=True)
    spacing = np.sqrt(area / n_surface)
    e = signed_distance_to_balls(Y, N, V, R, h)
    e_abs = np.abs(e)
    # eps: ties (a cylinder axis point is equidistant from a whole ring) make exact queries crawl;
    # d is then within 1 % of the distance to the sample.
    d_c = cKDTree(Y, balanced_tree=False, compact_nodes=False).query(V, eps=0.01)[0]
    stick = R - d_c
    uncovered = max(float(e.max()), 0.0)
    stick_max = max(float(stick.max()), 0.0)
    to_boundary = float(e_abs.max())
    return {
        # Outward normals when every face's triangles could be oriented, else None.
        "surface": (Y, N if oriented else None, spacing),
        "surface_points": n_surface,
        "surface_sample_spacing": float(spacing),
        "uncovered_max": uncovered,
        "uncovered_p99": float(max(np.percentile(e, 99), 0)),
        "to_union_boundary_max": to_boundary,
        "stick_out_max": stick_max,
        "stick_out_p99": float(max(np.percentile(stick, 99), 0)),
        "hausdorff": max(to_boundary, stick_max),
    }, (P, T)


def mesh_triangles(faces_start, faces_idx):
    """Fan triangulation of polygon faces given CSR arrays."""
    tris = []
    for f in range(len(faces_start) - 1):
        s, t = faces_start[f], faces_start[f + 1]
        for q in range(s + 1, t - 1):
            tris.append((faces_idx[s], faces_idx[q], faces_idx[q + 1]))
    return np.array(tris, int).reshape(-1, 3)


def sample_mesh(V, T, spacing, rng, cap=600_000):
    a, b, c = V[T[:, 0]], V[T[:, 1]], V[T[:, 2]]
    area = 0.5 * np.linalg.norm(np.cross(b - a, c - a), axis=1)
    n = int(min(cap, max(1000, area.sum() / spacing ** 2)))
    pts, _ = sample_triangles(V, T[area > 0], n, rng) if (area > 0).any() else (V, 0)
    return np.vstack([V, pts])


def topology(offsets, indices, face_solid, edges=None, edge_solid=None, num_vertices=None):
    """Per solid: connected components and V - E + F of the output (faces and 1-D edges; an edge
    that is also a face side counts once)."""
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components
    offsets = np.asarray(offsets, np.int64)
    indices = np.asarray(indices, np.int64)
    edges = np.zeros((0, 2), np.int64) if edges is None else np.asarray(edges, np.int64).reshape(-1, 2)
    edge_solid = np.zeros(0, np.int64) if edge_solid is None else np.asarray(edge_solid, np.int64)
    face_solid = np.asarray(face_solid, np.int64)
    sizes = np.diff(offsets)
    face_of = np.repeat(np.arange(len(sizes)), sizes)
    k = np.arange(len(indices))
    nxt = k + 1
    last = offsets[1:] - 1
    nxt[last[sizes > 0]] = offsets[:-1][sizes > 0]
    n = int(num_vertices) if num_vertices is not None else int(max(indices.max(initial=-1), edges.max(initial=-1))) + 1
    out = {}
    for s in np.union1d(face_solid, edge_solid):
        fm = face_solid == s
        km = fm[face_of]
        em = edges[edge_solid == s]
        a = np.concatenate([indices[k[km]], em[:, 0]])
        b = np.concatenate([indices[nxt[km]], em[:, 1]])
        e = np.unique(np.c_[np.minimum(a, b), np.maximum(a, b)], axis=0)
        verts = np.unique(np.concatenate([indices[km], em.ravel()]))
        g = coo_matrix((np.ones(len(e)), (e[:, 0], e[:, 1])), shape=(n, n))
        _, lab = connected_components(g, directed=False)
        comps = len(np.unique(lab[verts]))
        out[int(s)] = {"components": comps, "euler": int(len(verts) - len(e) + fm.sum())}
    return out


def solid_euler(solid):
    """Euler characteristic of a solid from its B-rep: half that of its boundary surface(s).

    Boundary: V - E + sum over faces of (2 - wires), degenerate edges (sphere poles) not counted;
    a face with w wires is a disc with w - 1 holes (seam edges cut a periodic face into a disc,
    they count once as edges)."""
    V = len(solid.Vertexes)
    E = sum(1 for e in solid.Edges if not e.Degenerated)
    F = sum(2 - len(f.Wires) for f in solid.Faces)
    # Vertices only on degenerate edges (poles) are vertices of the cell complex too.
    return (V - E + F) // 2


def classify(solids, points, tol):
    """Per solid (FreeCAD Part solids), a uint8 array over the points: 1 inside, 2 on the boundary
    (within tol), 0 outside. OpenCASCADE's solid classifier, built once per solid
    (cadmedial._core.classify_points: what Shape.isInside(p, tol, checkFace) computes, but
    isInside builds the classifier again for every point); points outside a solid's bounding
    box are outside it without a query."""
    import cadmedial
    from cadmedial import _core
    points = np.asarray(points, float).reshape(-1, 3)
    out = []
    for solid in solids:
        bb = solid.BoundBox
        lo = np.array([bb.XMin, bb.YMin, bb.ZMin]) - tol
        hi = np.array([bb.XMax, bb.YMax, bb.ZMax]) + tol
        near = ((points >= lo) & (points <= hi)).all(1)
        state = np.zeros(len(points), np.uint8)
        if near.any():
            state[near] = _core.classify_points(cadmedial.read_shape(solid), points[near], tol)
        out.append(state)
    return out


def side_from_surface(X, Y, N_out, spacing):
    """Per point: 1 inside, 0 outside, -1 undecided, from the 3 surface samples y nearest it:
    decided only when the point x is farther than 3 sample spacings from all of them (the
    tessellation is within 5e-4 of the diagonal of the surface, far less), x - y is within 60
    degrees of the normal at every y (x faces those tangent planes, it is not beside them, off an
    edge the samples missed), and all three agree on the side."""
    d, j = cKDTree(Y, balanced_tree=False, compact_nodes=False).query(X, 3)
    side = np.einsum("ijk,ijk->ij", X[:, None, :] - Y[j], N_out[j])
    facing = (np.abs(side) >= 0.5 * d).all(1)
    out = np.full(len(X), -1, int)
    ok = (d[:, 0] > 3 * spacing) & facing
    out[ok & (side < 0).all(1)] = 1
    out[ok & (side > 0).all(1)] = 0
    return out


def leakage(solid_shapes, V, tol, n=1500, seed=0, surface=None):
    """(share of n random vertices outside every solid, n, how many OpenCASCADE's classifier
    settled). surface = (Y, N_out, spacing) of a single solid: vertices far from it are settled by
    side_from_surface, the others by the classifier (on the boundary counts as inside)."""
    rng = np.random.default_rng(seed)
    idx = rng.choice(len(V), min(n, len(V)), replace=False)
    X = V[idx]
    state = np.full(len(X), -1, int)
    if surface is not None and len(solid_shapes) == 1:
        state = side_from_surface(X, *surface)
    todo = state < 0
    if todo.any():
        inside = [st > 0 for st in classify(solid_shapes, X[todo], tol)]
        state[todo] = np.logical_or.reduce(inside).astype(int) if inside else 0
    # On the boundary counts as inside: the classifier misses it next to an edge once the solid
    # carries a tessellation (the measures before this one made it), e.g. a completion vertex,
    # a sample of radius 0 (as1_pe_203 at 20k). The few points called outside are checked by
    # their distance to the solids.
    import FreeCAD
    import Part
    for i in np.where(state == 0)[0]:
        v = Part.Vertex(FreeCAD.Vector(*X[i]))
        if any(s.distToShape(v)[0] <= tol for s in solid_shapes):
            state[i] = 1
    return float((state == 0).mean()), len(idx), int(todo.sum())


def convex_edge_points(solids, h, angle_deg=10.0):
    """Points every <= h/2 along the convex edges of the B-rep (dihedral turn > angle_deg) and
    the non-concave corners (a vertex with an incident convex edge), with the edges' total length.

    Convexity at the midpoint p of an edge between faces with outward normals n1, n2: the point
    p + eps (n2 - n1) is outside the solid for a convex edge, inside for a concave one (all the
    edges' probes classified in one batch)."""
    pts, corners, length = [], [], 0.0
    for solid in solids:
        edge_faces = {}
        for fi, f in enumerate(solid.Faces):
            for e in f.Edges:
                edge_faces.setdefault(e.hashCode(), []).append((fi, f))
        eps = 1e-3 * max(h, 1e-9)
        cand = []  # (edge, params, probe)
        for e in solid.Edges:
            if e.Degenerated:
                continue
            fl = edge_faces.get(e.hashCode(), [])
            if len(fl) != 2 or fl[0][0] == fl[1][0]:
                continue  # seam edge or non-manifold
            L = e.Length
            if L <= 0:
                continue
            k = max(1, int(np.ceil(L / (h / 2))))
            params = np.linspace(e.FirstParameter, e.LastParameter, k + 1)
            mid = e.valueAt(params[len(params) // 2])
            try:
                n = []
                for _, f in fl:
                    u, v = f.Surface.parameter(mid)
                    n.append(f.normalAt(u, v))
            except Exception:
                continue
            if n[0].getAngle(n[1]) < np.radians(angle_deg):
                continue
            q = mid + (n[1] - n[0]) * eps
            cand.append((e, params, (q.x, q.y, q.z)))
        if not cand:
            continue
        # Concave when q is strictly inside; q on the boundary (another face passes there: two
        # such probes on nist_ctc_04) counts as convex, as isInside(q, 1e-9, False) did.
        concave = classify([solid], [c[2] for c in cand], 1e-9)[0] == 1
        conv_vertices = set()
        for (e, params, _), is_concave in zip(cand, concave):
            if is_concave:
                continue
            length += e.Length
            pts.extend([[p.x, p.y, p.z] for p in (e.valueAt(t) for t in params)])
            for vx in e.Vertexes:
                conv_vertices.add((round(vx.X, 9), round(vx.Y, 9), round(vx.Z, 9)))
        corners.extend(conv_vertices)
    return np.array(pts, float).reshape(-1, 3), np.array(corners, float).reshape(-1, 3), length


def exact_wall(solid, at, reported, tol):
    """Twice the radius of the largest ball in the solid that touches its boundary at `at` (a
    point on it) from a face's side, its centre on the face's inward normal there: the wall's
    exact thickness at `at`, on the material's side. On an edge, the smaller over its two faces,
    as the engine's edge samples take the smaller of their two normals' balls. The balls along one
    normal nest, so their radius is bisected: a ball is in the solid while its centre is inside
    and its distance to the boundary is its radius. `reported`: the engine's thickness there,
    which bounds the search (twice it). None when `at` is on no face."""
    import FreeCAD
    import Part
    p = FreeCAD.Vector(*at)
    v = Part.Vertex(p)
    inward = []
    for f in solid.Faces:
        if f.distToShape(v)[0] > tol:
            continue
        u, w = f.Surface.parameter(p)
        # FreeCAD's normalAt is the face's outward normal (BRepGProp_Face: reversed with a
        # reversed face). A test step into the solid would not tell at a concave edge, where
        # a step along one face's outward normal can run into the other face's material.
        n = -f.normalAt(u, w)
        n.normalize()
        inward.append(n)
    if not inward:
        return None
    # Distances to the boundary: to a solid, a point inside it is at distance 0.
    boundary = Part.makeCompound(solid.Shells)
    radii = []
    for n in inward:
        lo, hi = 0.0, 2.0 * reported
        for _ in range(50):
            r = 0.5 * (lo + hi)
            c = p + n * r
            inside = solid.isInside(c, tol, True) and boundary.distToShape(Part.Vertex(c))[0] >= r * (1 - 1e-7)
            lo, hi = (r, hi) if inside else (lo, r)
            if hi - lo <= 1e-6 * reported:
                break
        radii.append(lo)
    return 2.0 * min(radii)
