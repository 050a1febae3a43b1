"""Geodesic distances and paths on triangle meshes and point clouds (tapeline.geodesic)."""
from ._tapeline import geodesic as _g

distances = _g.distances
distance_matrix = _g.distance_matrix
methods = _g.methods
ExactMmpSolver = _g.ExactMmpSolver
HeatSolver = _g.HeatSolver
CurvatureFlowPathSolver = _g.CurvatureFlowPathSolver
PointCloudSolver = _g.PointCloudSolver
ExactMmpOptions = _g.ExactMmpOptions
HeatOptions = _g.HeatOptions
CurvatureFlowOptions = _g.CurvatureFlowOptions
PointCloudOptions = _g.PointCloudOptions
HeatMultiSource = _g.HeatMultiSource
PointCloudProjection = _g.PointCloudProjection
PointCloudKnn = _g.PointCloudKnn
CurvatureFlowSolver = _g.CurvatureFlowSolver

__all__ = [
    "distances",
    "distance_matrix",
    "methods",
    "ExactMmpSolver",
    "HeatSolver",
    "CurvatureFlowPathSolver",
    "PointCloudSolver",
    "ExactMmpOptions",
    "HeatOptions",
    "CurvatureFlowOptions",
    "PointCloudOptions",
    "HeatMultiSource",
    "PointCloudProjection",
    "PointCloudKnn",
    "CurvatureFlowSolver",
]
