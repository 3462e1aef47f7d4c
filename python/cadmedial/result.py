"""The result of a medial axis computation: numpy views over the engine's mesh."""

import enum
import os

import numpy as np


class FaceKind(enum.IntEnum):
    """What produced a face (values of MedialAxisResult.face_kind)."""
    VORONOI = 0  # a Voronoi facet dual to a selected Delaunay edge (3, 4.2.6)
    EDGE = 1     # a completion triangle at a convex edge (4.2.2)
    CORNER = 2   # a completion triangle at a non-concave corner (4.2.3)


class Faces:
    """Polygons of different sizes in CSR form: face f is indices[offsets[f]:offsets[f+1]].

    A sequence of int32 arrays (len, indexing, iteration) that does not copy them.
    """

    def __init__(self, offsets, indices):
        self.offsets = offsets  # (F+1,) int32
        self.indices = indices  # (M,) int32

    def __len__(self):
        return len(self.offsets) - 1

    def __getitem__(self, f):
        if not -len(self) <= f < len(self):
            raise IndexError("face %d out of range for %d faces" % (f, len(self)))
        f %= len(self)
        return self.indices[self.offsets[f]:self.offsets[f + 1]]

    def __iter__(self):
        for f in range(len(self)):
            yield self.indices[self.offsets[f]:self.offsets[f + 1]]

    def sizes(self):
        """(F,) number of vertices of each face."""
        return np.diff(self.offsets)

    def triangulate(self):
        """Fans every polygon from its first vertex.

        Returns (triangles, face): (T, 3) int32 vertex indices and (T,) int32 index of the face
        each triangle comes from, T = sum(sizes() - 2), triangles of a face consecutive.
        """
        per_face = np.maximum(self.sizes() - 2, 0)
        face = np.repeat(np.arange(len(self), dtype=np.int32), per_face)
        first_of_face = np.cumsum(per_face) - per_face
        j = np.arange(len(face)) - np.repeat(first_of_face, per_face)
        start = self.offsets[:-1][face]
        triangles = np.stack([self.indices[start],
                              self.indices[start + j + 1],
                              self.indices[start + j + 2]], axis=1).astype(np.int32, copy=False)
        return triangles, face


class MedialAxisResult:
    """The medial mesh of one compute() (or load()).

    vertices    (V, 3) float64 positions
    radius      (V,) float64 medial radius: distance to the nearest boundary sample
    faces       Faces: the polygons (Voronoi facets and completion triangles)
    face_kind   (F,) uint8 FaceKind of each face
    face_solid  (F,) int32 index of the input solid each face belongs to
    edges       (E, 2) int32 vertex indices of the 1-D edges: segments of the axis that no face
                carries, where the axis is a curve (a torus's core circle)
    edge_solid  (E,) int32 index of the input solid each edge belongs to
    stats       dict: samples, vertices, faces, edges, spacing, timings {stage: seconds},
                peak_rss_mb, warnings, skipped (what the shape held beside its solids and
                was left out), solids (per-solid figures); empty for a loaded file
    Arrays are read-only views into the engine's mesh.
    """

    def __init__(self, mesh, stats):
        self.mesh = mesh  # cadmedial._core.MedialMesh
        self.stats = stats
        self.vertices = mesh.vertices
        self.radius = mesh.radius
        self.faces = Faces(mesh.face_start, mesh.face_vertices)
        self.face_kind = mesh.kind
        self.face_solid = mesh.solid
        self.edges = mesh.edges
        self.edge_solid = mesh.edge_solid

    @property
    def num_vertices(self):
        return self.mesh.num_vertices

    @property
    def num_faces(self):
        return self.mesh.num_faces

    @property
    def num_edges(self):
        return self.mesh.num_edges

    def triangles(self):
        """(T, 3) int32 fan triangulation of the faces (see Faces.triangulate)."""
        return self.faces.triangulate()[0]

    def save(self, path):
        """Writes .ply (binary, with radius, kind and solid, and the edges with their solid), .obj
        (edges as `l` lines) or .ma (edges as extra `e` lines), chosen by extension."""
        self.mesh.save(os.fspath(path))

    def to_brep(self):
        """BREP text of a compound with one planar face per polygon and one straight edge per
        1-D edge (for FreeCAD's Part)."""
        return self.mesh.to_brep()

    def __repr__(self):
        return "<cadmedial.MedialAxisResult %d vertices, %d faces, %d edges>" % (
            self.num_vertices, self.num_faces, self.num_edges)
