"""Tapeline from Python: geodesic distances and paths, point clouds, body measurement, sewing
patterns, grading and dressing a body in a pattern.

Arrays in and out are numpy arrays: V float (n, 3), F integer (m, 3). Errors raise
InvalidInput / TopologyError (ValueError subclasses) and SolverFailure (a RuntimeError) with the
library's one-line messages. The GIL is released during the computations.
"""
from ._tapeline import (
    InvalidInput,
    SolverFailure,
    TopologyError,
    check_mesh,
    measure,
    read_mesh,
)
from . import garment, geodesic, pattern
from .garment import bindings_from_body, dress

try:
    from ._tapeline import EaseMode, GradingOptions, grade
except ImportError:  # built without Ceres or pagmo: no grading
    pass

__all__ = [name for name in [
    "InvalidInput",
    "SolverFailure",
    "TopologyError",
    "EaseMode",
    "GradingOptions",
    "bindings_from_body",
    "check_mesh",
    "dress",
    "garment",
    "grade",
    "geodesic",
    "measure",
    "pattern",
    "read_mesh",
] if name in globals()]
