# Typed public API of cadmedial (see __init__.py for the docs).
import enum
import os
from typing import Any, Callable, Dict, Iterator, List, NamedTuple, Optional, Tuple, Union

import numpy as np
import numpy.typing as npt

from . import _core
from ._core import Cancelled as Cancelled
from ._core import Error as Error
from ._core import GeometryError as GeometryError
from ._core import InvalidInput as InvalidInput

__version__: str

class _BrepExportable:
    def exportBrepToString(self) -> str: ...

Source = Union[str, os.PathLike[str], bytes, _BrepExportable, _core.Shape]
ProgressCallback = Callable[[str, float], Optional[bool]]

class SamplingPlan(NamedTuple):
    spacing: float
    estimated_samples: int

class FaceKind(enum.IntEnum):
    VORONOI = 0
    EDGE = 1
    CORNER = 2

class Faces:
    offsets: npt.NDArray[np.int32]
    indices: npt.NDArray[np.int32]
    def __init__(self, offsets: npt.NDArray[np.int32], indices: npt.NDArray[np.int32]) -> None: ...
    def __len__(self) -> int: ...
    def __getitem__(self, f: int) -> npt.NDArray[np.int32]: ...
    def __iter__(self) -> Iterator[npt.NDArray[np.int32]]: ...
    def sizes(self) -> npt.NDArray[np.int32]: ...
    def triangulate(self) -> Tuple[npt.NDArray[np.int32], npt.NDArray[np.int32]]: ...

class MedialAxisResult:
    mesh: _core.MedialMesh
    stats: dict[str, Any]
    vertices: npt.NDArray[np.float64]
    radius: npt.NDArray[np.float64]
    faces: Faces
    face_kind: npt.NDArray[np.uint8]
    face_solid: npt.NDArray[np.int32]
    edges: npt.NDArray[np.int32]
    edge_solid: npt.NDArray[np.int32]
    def __init__(self, mesh: _core.MedialMesh, stats: dict[str, Any]) -> None: ...
    @property
    def num_vertices(self) -> int: ...
    @property
    def num_faces(self) -> int: ...
    @property
    def num_edges(self) -> int: ...
    def triangles(self) -> npt.NDArray[np.int32]: ...
    def save(self, path: Union[str, os.PathLike[str]]) -> None: ...
    def to_brep(self) -> str: ...

def read_shape(source: Source) -> _core.Shape: ...
def plan_sampling(source: Source, spacing: Optional[float] = ..., samples: Optional[int] = ...) -> SamplingPlan: ...
def compute(
    source: Source,
    spacing: Optional[float] = ...,
    samples: Optional[int] = ...,
    theta: float = ...,
    rho: float = ...,
    progress: Optional[ProgressCallback] = ...,
    plain_medial: bool = ...,
    adapt: bool = ...,
    refine: Optional[bool] = ...,
    min_feature: Optional[float] = ...,
    simplify: Union[None, float, str] = ...,
) -> MedialAxisResult: ...
def simplify(result: MedialAxisResult, tolerance: Union[float, str], source: Optional[Source] = ...,
             progress: Optional[ProgressCallback] = ...) -> MedialAxisResult: ...
def load(path: Union[str, os.PathLike[str]]) -> MedialAxisResult: ...

from . import batch as batch  # a callable module: cadmedial.batch(inputs, out_dir, ...) -> batch.BatchResult

class _StructureModule:
    # cadmedial.structure: a callable subpackage, loaded on first use.
    INSIDE: int
    SEAM: int
    RIM: int
    FREE: int
    TUBE: int
    AxisStructure: type[_AxisStructure]
    def __call__(
        self,
        result: MedialAxisResult,
        spacing: Optional[float] = ...,
        merge_slivers: bool = ...,
        rim_radius: float = ...,
        sliver_area: float = ...,
        reach: float = ...,
        tube_length: float = ...,
        join: float = ...,
        shape: Optional[Source] = ...,
    ) -> _AxisStructure: ...
    def structure(
        self,
        result: MedialAxisResult,
        spacing: Optional[float] = ...,
        merge_slivers: bool = ...,
        rim_radius: float = ...,
        sliver_area: float = ...,
        reach: float = ...,
        tube_length: float = ...,
        join: float = ...,
        shape: Optional[Source] = ...,
    ) -> _AxisStructure: ...

class _AxisStructure:
    # cadmedial.structure.AxisStructure (the package is typed here: it loads on first use)
    face_sheet: npt.NDArray[np.int64]
    face_curve: npt.NDArray[np.int64]
    edges: npt.NDArray[np.int64]
    edge_kind: npt.NDArray[np.uint8]
    edge_kind_names: Dict[int, str]
    sheets: List[Dict[str, Any]]
    seams: List[Dict[str, Any]]
    junctions: List[Dict[str, Any]]
    rims: List[Dict[str, Any]]
    free: List[Dict[str, Any]]
    curves: List[Dict[str, Any]]
    spacing: float
    def to_dict(self) -> Dict[str, Any]: ...
    def counts(self) -> Dict[str, int]: ...

structure: _StructureModule
