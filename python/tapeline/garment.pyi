from typing import Any, Dict, List, Optional, Sequence, Tuple, Union

import numpy.typing as npt

Fabric = Union[str, Dict[str, Any]]

class PlacementOptions:
    gap_mm: float
    slice_mm: float
    layer_gap_mm: float
    def __init__(self, **fields: Any) -> None: ...

class SewingOptions:
    sew_seconds: float
    settle_seconds: float
    max_extra_seconds: float
    settle_damping_per_second: float
    string_offset_mm: float
    compliance: float
    length_mismatch: float
    weld_within_mm: float
    def __init__(self, **fields: Any) -> None: ...

class DrapeOptions:
    frame_seconds: float
    substeps: int
    iterations: int
    gravity: Tuple[float, float, float]
    damping_per_second: float
    body_clearance_mm: float
    self_collision: bool
    edge_edge_collision: bool
    untangle: bool
    tether_stretch: float
    threads: int
    max_speed_mm_s: float
    max_energy_growth: float
    def __init__(self, **fields: Any) -> None: ...

class RelaxOptions:
    max_iterations: int
    friction_from_iteration: int
    release_until_iteration: int
    tolerance_mm: float
    initial_step_seconds: float
    settle_iterations: int
    settle_fraction: float
    stall_rejections: int
    def __init__(self, **fields: Any) -> None: ...

class FoldOptions:
    max_rounds: int
    rings: int
    sweeps: int
    def __init__(self, **fields: Any) -> None: ...

class DressOptions:
    resolution_mm: float
    placement: PlacementOptions
    sewing: SewingOptions
    drape: DrapeOptions
    without_pieces: List[str]
    relax: bool
    relax_options: RelaxOptions
    relax_again_options: RelaxOptions
    body_points: bool
    smooth_folds: bool
    fold_options: FoldOptions
    fold_cycles: int
    sdf_cell_mm: float
    waistband: bool
    waistband_sag_mm: float
    def __init__(self, **fields: Any) -> None: ...

def dress(
    V: npt.ArrayLike,
    F: npt.ArrayLike,
    pattern: Dict[str, Any],
    *,
    units: Optional[str] = None,
    up: str = "+Y",
    front: str = "+Z",
    name: str = "body",
    fabric: Fabric = "cotton_jersey",
    base: Optional[Union[str, Dict[str, Any]]] = None,
    seed: int = 1,
    strict: bool = False,
    options: Optional[DressOptions] = None,
    **fields: Any,
) -> Dict[str, Any]:
    """The body dressed in the pattern as `tapeline dress` dresses it: 'V', 'F' (the welded
    garment in the body's coordinates and unit), 'uv', 'piece', 'piece_names', 'stretch',
    'report' (gates, quality, seams, pieces, timings), 'warnings', 'grading_notes'."""

def bindings_from_body(
    V: npt.ArrayLike,
    F: npt.ArrayLike,
    pattern: Dict[str, Any],
    *,
    units: Optional[str] = None,
    up: str = "+Y",
    front: str = "+Z",
    name: str = "body",
) -> Tuple[Dict[str, Any], Dict[str, float], List[str]]:
    """The pattern's girth bindings found by laying it on the body it was made for (as `tapeline
    grade --base-body`): (the pattern dict with them, the body's measurements {name: mm}, one note
    per girth)."""

def fabrics() -> List[Dict[str, Any]]:
    """The fabric library as fabric dicts (`tapeline fabric show`)."""

def fabric(fabric: Fabric) -> Dict[str, Any]:
    """The fabric dict of a library name, a .json fabric file or a fabric dict."""
