from enum import Enum
from typing import Any, Dict, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

from . import garment as garment
from . import geodesic as geodesic
from . import pattern as pattern
from .garment import bindings_from_body as bindings_from_body
from .garment import dress as dress

class InvalidInput(ValueError):
    """Bad input: unreadable file, NaN coordinate, out-of-range index, unknown option value."""

class TopologyError(ValueError):
    """Well-formed input whose topology the algorithm refuses (strict mode, non-manifold)."""

class SolverFailure(RuntimeError):
    """A numerical solver gave no usable answer."""

def read_mesh(
    path: str, strict: bool = False, needle_angle_degrees: float = 1.0
) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.int64], Dict[str, Any]]:
    """(V, F, report) of a mesh file (.off, .obj, .ply, .stl), validated and repaired."""

def check_mesh(V: npt.ArrayLike, F: npt.ArrayLike, strict: bool = False) -> Dict[str, Any]:
    """The loader's report on (V, F): what it found and would repair."""

def measure(
    V: npt.ArrayLike,
    F: npt.ArrayLike,
    units: Optional[str] = None,
    up: str = "+Y",
    front: str = "+Z",
    pose: str = "A",
    landmarks: Optional[Dict[str, Any]] = None,
    name: str = "body",
) -> Dict[str, Any]:
    """The measurement JSON of `tapeline measure` (landmarks, girths, skin lengths) as a dict."""

class EaseMode(Enum):
    proportional = ...
    keep_mm = ...

class GradingOptions:
    seed: int
    population: int
    generations: int
    ease: EaseMode
    threads: int
    ceres_polish: bool
    ceres_iterations: int
    reference_length_mm: float
    neighbours: int
    min_fit_factor: float
    max_fit_factor: float
    split_girths: bool
    trim_aspect: float
    max_target_ratio: float
    def to_dict(self) -> Dict[str, Any]: ...

def grade(
    pattern: Dict[str, Any],
    base: Union[str, Dict[str, Any]],
    target: Union[str, Dict[str, Any]],
    freesewing_bindings: bool = True,
    **options: Any,
) -> Tuple[Dict[str, Any], Dict[str, Any]]:
    """A pattern graded from the base to the target measurements, as `tapeline grade`: (graded
    pattern dict, report with the fit and seam tables and the Pareto front as arrays)."""
