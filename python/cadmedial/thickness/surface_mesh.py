"""The surface points of a thickness analysis: a fine, conforming triangulation of the solids'
faces, each triangle knowing its B-rep face.

OpenCASCADE's BRepMesh (through Part's Face.tessellate) follows the curvature but leaves planar
faces as a few long triangles; the values are per vertex, so those triangles are split until no
side is longer than ``max_edge``. Splitting is decided per side (a side is split when it is long,
whichever triangle looks at it), so the mesh stays conforming across triangles and across faces.
"""

from dataclasses import dataclass, field

import numpy as np
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components
from scipy.spatial import cKDTree

from .. import _core
from .delaunay_flips import flip_until_delaunay
from .mesh_sides import mesh_sides
from .surface_projection import CLOSED_FORMS, project_on_surface


@dataclass
class SurfaceMesh:
    """points (N, 3) float64; triangles (T, 3) int64, outward by the right-hand rule;
    triangle_face (T,) int64 index into shape.Faces (name "Face%d" % (i + 1));
    point_solid (N,) int64 index of the solid each point lies on (into the solids given);
    face_names list of the names of shape.Faces."""
    points: np.ndarray
    triangles: np.ndarray
    triangle_face: np.ndarray
    point_solid: np.ndarray
    face_names: list = field(default_factory=list)

    def triangle_areas(self):
        """(T,) area of each triangle."""
        a, b, c = (self.points[self.triangles[:, i]] for i in range(3))
        return 0.5 * np.linalg.norm(np.cross(b - a, c - a), axis=1)

    def point_areas(self):
        """(N,) the surface area each point stands for: a third of each triangle around it
        (sums to the mesh's area)."""
        area = np.zeros(len(self.points))
        np.add.at(area, self.triangles.ravel(), np.repeat(self.triangle_areas() / 3.0, 3))
        return area

    def triangle_normals(self):
        """(T, 3) outward unit normals."""
        a, b, c = (self.points[self.triangles[:, i]] for i in range(3))
        n = np.cross(b - a, c - a)
        return n / np.maximum(np.linalg.norm(n, axis=1), 1e-300)[:, None]

    def point_faces(self):
        """List of N sorted lists: the faces each point lies on (several on a B-rep edge)."""
        pairs = np.unique(np.column_stack([self.triangles.ravel(),
                                           np.repeat(self.triangle_face, 3)]), axis=0)
        out = [[] for _ in range(len(self.points))]
        for p, f in pairs.tolist():
            out[p].append(f)
        return out


_sides = mesh_sides  # the name convex_edges imports


def _split_long_sides(points, triangles, tri_face, max_edge, project):
    """One round of splitting every side longer than max_edge at its midpoint (1, 2 or 3 sides
    of a triangle: 2, 3 or 4 triangles, orientation kept). ``project(points, face)`` moves new
    points that lie inside a curved face onto it. Returns (points, triangles, tri_face, done)."""
    sides, tri_side = _sides(triangles)
    length = np.linalg.norm(points[sides[:, 0]] - points[sides[:, 1]], axis=1)
    # Only the longest side of a triangle is split (Rivara's longest-edge bisection): splitting
    # every long side of BRepMesh's long strips on cylinders cuts them into ever thinner slivers
    # (a tube took a million points for 30,000 samples).
    longest = np.zeros(len(sides), bool)
    longest[tri_side[np.arange(len(triangles)), np.argmax(length[tri_side], axis=1)]] = True
    split = (length > max_edge) & longest
    if not split.any():
        return points, triangles, tri_face, True
    mid_index = np.full(len(sides), -1, dtype=np.int64)
    mid_index[split] = len(points) + np.arange(split.sum())
    mids = 0.5 * (points[sides[split, 0]] + points[sides[split, 1]])
    # A side inside one face (both its triangles on that face) gets its midpoint on the surface;
    # a side on a B-rep edge keeps the chord's midpoint, so both faces make the same point.
    side_faces = np.full((len(sides), 2), -1, dtype=np.int64)
    flat_side, flat_tri = tri_side.ravel(), np.repeat(np.arange(len(triangles)), 3)
    side_faces[flat_side, 0] = tri_face[flat_tri]
    side_faces[flat_side[::-1], 1] = tri_face[flat_tri[::-1]]
    inside = (side_faces[:, 0] == side_faces[:, 1])[split]
    mids[inside] = project(mids[inside], side_faces[split, 0][inside])
    points = np.vstack([points, mids])

    s = split[tri_side]                    # (T, 3) which sides a-b, b-c, c-a are split
    m = mid_index[tri_side]                # their midpoints
    count = s.sum(axis=1)
    out_tris, out_face = [triangles[count == 0]], [tri_face[count == 0]]
    rows = np.arange(len(triangles))

    def rolled(sel, start):
        i = rows[sel]
        k = [(start + j) % 3 for j in range(3)]
        v = [triangles[i, kj] for kj in k]
        mm = [m[i, kj] for kj in k]
        return v, mm, tri_face[i]

    one = count == 1
    if one.any():
        start = np.argmax(s[one], axis=1)  # the split side becomes a-b
        (a, b, c), (mab, _, _), f = rolled(one, start)
        out_tris += [np.column_stack([a, mab, c]), np.column_stack([mab, b, c])]
        out_face += [f, f]
    two = count == 2
    if two.any():
        start = (np.argmin(s[two], axis=1) + 1) % 3  # the kept side becomes c-a
        (a, b, c), (mab, mbc, _), f = rolled(two, start)
        # The quad a, mab, mbc, c is cut from the midpoint of the longer split side (as
        # longest-edge bisection would), so the cut is the shorter diagonal's neighbour.
        rows_two = rows[two]
        k = [(start + j) % 3 for j in range(3)]
        ab_longer = (length[tri_side[rows_two, k[0]]] >= length[tri_side[rows_two, k[1]]])
        t1 = np.where(ab_longer[:, None], np.column_stack([mab, b, mbc]), np.column_stack([mab, b, mbc]))
        t2 = np.where(ab_longer[:, None], np.column_stack([mab, mbc, c]), np.column_stack([a, mab, mbc]))
        t3 = np.where(ab_longer[:, None], np.column_stack([a, mab, c]), np.column_stack([a, mbc, c]))
        out_tris += [t1, t2, t3]
        out_face += [f, f, f]
    three = count == 3
    if three.any():
        (a, b, c), (mab, mbc, mca), f = rolled(three, np.zeros(three.sum(), dtype=np.int64))
        out_tris += [np.column_stack([a, mab, mca]), np.column_stack([mab, b, mbc]),
                     np.column_stack([mca, mbc, c]), np.column_stack([mab, mbc, mca])]
        out_face += [f] * 4
    return points, np.vstack(out_tris), np.concatenate(out_face), False


def _merge_coincident(points, triangles, tol):
    """Points closer than tol made one (faces tessellated one by one repeat their edges'
    points). Returns (points, triangles)."""
    pairs = cKDTree(points).query_pairs(tol, output_type="ndarray")
    n = len(points)
    graph = coo_matrix((np.ones(len(pairs)), (pairs[:, 0], pairs[:, 1])), shape=(n, n))
    _, label = connected_components(graph, directed=False)
    first = np.full(label.max() + 1, -1, dtype=np.int64)
    first[label[::-1]] = np.arange(n)[::-1]
    keep = np.sort(first)
    new_index = np.empty(label.max() + 1, dtype=np.int64)
    new_index[label[keep]] = np.arange(len(keep))
    return points[keep], new_index[label[triangles]]


def surface_mesh(shape, solids, max_edge, deflection, exact=None):
    """SurfaceMesh of ``solids`` (faces of ``shape``): BRepMesh at ``deflection`` (linear), then
    sides split until none is longer than ``max_edge``. Degenerate triangles are dropped.
    ``exact``: the solids as _core shapes (read_brep_string), or None; with them, midpoints on
    faces with no closed form (B-splines...) are put on the face by the engine's exact distance,
    all at once, where its nearest point lies on that face (elsewhere, and without them, by
    OpenCASCADE's projection one point at a time: 0.2 ms each, 3.4 s of dm1-id-214's 4.5 s)."""
    faces = list(shape.Faces)
    index_of = {}
    for i, face in enumerate(faces):
        index_of.setdefault(face.hashCode(), i)
    chunks, tri_chunks, face_chunks, solid_of_face, local_of_face = [], [], [], {}, {}
    offset = 0
    for s, solid in enumerate(solids):
        for k, face in enumerate(solid.Faces):
            i = index_of.get(face.hashCode())
            if i is None:  # a solid made from a shell here: its faces are the shell's
                i = len(faces)
                faces.append(face)
                index_of[face.hashCode()] = i
            if i in solid_of_face:
                continue
            solid_of_face[i], local_of_face[i] = s, k  # k: the face's number in the engine's map
            pts, tris = face.tessellate(deflection)
            if not tris:
                continue
            chunks.append(np.array([tuple(p) for p in pts], dtype=np.float64))
            tri_chunks.append(np.asarray(tris, dtype=np.int64) + offset)
            face_chunks.append(np.full(len(tris), i, dtype=np.int64))
            offset += len(pts)
    points = np.vstack(chunks)
    tri_face = np.concatenate(face_chunks)
    diag = float(np.linalg.norm(points.max(axis=0) - points.min(axis=0)))
    points, triangles = _merge_coincident(points, np.vstack(tri_chunks), 1e-9 * diag)

    def project(p, face_index):
        out = p.copy()
        others = []  # (face, indices) of surfaces with no closed form
        for f in np.unique(face_index):
            surface = faces[f].Surface
            kind = type(surface).__name__
            if kind == "Plane":  # a chord's midpoint is on it
                continue
            sel = np.nonzero(face_index == f)[0]
            if kind in CLOSED_FORMS or exact is None:
                out[sel] = project_on_surface(surface, p[sel])
            else:
                others.append((f, sel))
        for s in sorted({solid_of_face[f] for f, _ in others}):
            mine = [(f, sel) for f, sel in others if solid_of_face[f] == s]
            at = np.concatenate([sel for _, sel in mine])
            want = np.concatenate([np.full(len(sel), local_of_face[f]) for f, sel in mine])
            _, foot, face, _ = _core.boundary_distance(exact[s], p[at],
                                                       np.full(len(at), max_edge))
            hit = face == want
            out[at[hit]] = foot[hit]
            missed = np.zeros(len(p), bool)
            missed[at[~hit]] = True
            for f, sel in mine:
                rest = sel[missed[sel]]
                if len(rest):
                    out[rest] = project_on_surface(faces[f].Surface, p[rest])
        return out

    done = False
    triangles = flip_until_delaunay(points, triangles, tri_face)
    while not done:
        points, triangles, tri_face, done = _split_long_sides(points, triangles, tri_face,
                                                             max_edge, project)
        triangles = flip_until_delaunay(points, triangles, tri_face)
    a, b, c = (points[triangles[:, i]] for i in range(3))
    good = np.linalg.norm(np.cross(b - a, c - a), axis=1) > 1e-12 * diag * diag
    triangles, tri_face = triangles[good], tri_face[good]
    face_solid = np.array([solid_of_face.get(i, 0) for i in range(len(faces))], dtype=np.int64)
    point_solid = np.zeros(len(points), dtype=np.int64)
    point_solid[triangles.ravel()] = np.repeat(face_solid[tri_face], 3)
    names = ["Face%d" % (i + 1) for i in range(len(faces))]
    return SurfaceMesh(points, triangles, tri_face, point_solid, names)

