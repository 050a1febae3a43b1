from enum import Enum
from typing import Any, Dict, List, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

# A source or target: a vertex index (a row of V), or (face, (b0, b1, b2)): a point of face F[face]
# with barycentric coordinates over its corners F[face][0..2].
SurfacePoint = Union[int, Tuple[int, Sequence[float]]]
Sources = Union[SurfacePoint, Sequence[SurfacePoint]]
Path = Tuple[npt.NDArray[np.float64], float]

def methods() -> List[str]:
    """The method names distances() takes."""

def distances(
    V: npt.ArrayLike,
    F: npt.ArrayLike,
    sources: Sources,
    method: str = "exact-mmp",
    window: int = 8,
    with_report: bool = False,
) -> Union[npt.NDArray[np.float64], Tuple[npt.NDArray[np.float64], Dict[str, Any]]]:
    """Distance from the sources to every row of V by a named method (see methods()); with
    with_report, (distances, report dict)."""

def distance_matrix(
    V: npt.ArrayLike, F: npt.ArrayLike, sources: Sequence[int], threads: int = 0
) -> npt.NDArray[np.float64]:
    """Exact distances from each source vertex to every row of V, shape (len(sources), len(V));
    rows computed in parallel on `threads` threads (0: all)."""

class HeatMultiSource(Enum):
    min_of_single_sources = ...
    cgal_joint = ...

class PointCloudProjection(Enum):
    mls = ...
    plane = ...

class PointCloudKnn(Enum):
    automatic = ...
    cgal = ...
    nanoflann = ...

class CurvatureFlowSolver(Enum):
    eigen_normal_ldlt = ...
    eigen_sparse_qr = ...
    eigen_lscg = ...
    ceres = ...

class ExactMmpOptions:
    max_distance: float
    target_vertices: List[int]
    prune_with_vertex_distances: bool
    keep_windows: bool
    max_propagated_windows: int
    def to_dict(self) -> Dict[str, Any]: ...

class HeatOptions:
    intrinsic_delaunay: bool
    multi_source: HeatMultiSource
    degenerate_face_tolerance: float
    reject_degenerate_faces: bool
    def to_dict(self) -> Dict[str, Any]: ...

class CurvatureFlowOptions:
    sample_spacing: float
    sample_count: int
    step: float
    tolerance: float
    update_tolerance: float
    max_iterations: int
    endpoint_weight: float
    solver: CurvatureFlowSolver
    straighten: bool
    interpolate_normals: bool
    def to_dict(self) -> Dict[str, Any]: ...

class PointCloudOptions:
    cell_size: float
    neighbours: int
    window: int
    manifold_dimension: int
    projection: PointCloudProjection
    knn: PointCloudKnn
    sample_spacing: float
    cut_locus_guard: bool
    near_source_samples: int
    anchor_slides: int
    def to_dict(self) -> Dict[str, Any]: ...

class ExactMmpSolver:
    """Exact polyhedral geodesics (MMP). Keyword arguments: the fields of ExactMmpOptions."""
    def __init__(self, V: npt.ArrayLike, F: npt.ArrayLike, **options: Any) -> None: ...
    def distances(self, sources: Sources) -> npt.NDArray[np.float64]: ...
    def distance(self, source: Sources, target: SurfacePoint) -> float: ...
    def path(self, source: Sources, target: SurfacePoint) -> Path: ...
    @property
    def report(self) -> Dict[str, Any]: ...
    @property
    def mesh_report(self) -> Dict[str, Any]: ...
    @property
    def options(self) -> Dict[str, Any]: ...

class HeatSolver:
    """The heat method, factorised once. Keyword arguments: the fields of HeatOptions."""
    def __init__(self, V: npt.ArrayLike, F: npt.ArrayLike, **options: Any) -> None: ...
    def distances(self, sources: Sources) -> npt.NDArray[np.float64]: ...
    @property
    def report(self) -> Dict[str, Any]: ...
    @property
    def options(self) -> Dict[str, Any]: ...

class CurvatureFlowPathSolver:
    """Geodesic paths by curvature flow; path() takes the fields of CurvatureFlowOptions."""
    def __init__(self, V: npt.ArrayLike, F: npt.ArrayLike) -> None: ...
    def path(
        self, source: SurfacePoint, target: SurfacePoint, smooth: bool = False, **options: Any
    ) -> Path: ...
    @property
    def report(self) -> Dict[str, Any]: ...

class PointCloudSolver:
    """Geodesics on points of any dimension. Keyword arguments: the fields of PointCloudOptions."""
    def __init__(self, P: npt.ArrayLike, **options: Any) -> None: ...
    def distances(self, source: int) -> npt.NDArray[np.float64]: ...
    def path(self, source: int, target: int) -> Path: ...
    @property
    def report(self) -> Dict[str, Any]: ...
    @property
    def dimension(self) -> int: ...
