from typing import Any, Dict, List, Optional

import numpy as np
import numpy.typing as npt

Pattern = Dict[str, Any]

def read(path: str, format: str = "auto") -> Pattern:
    """A pattern file (FreeSewing, GarmentCode, pattern JSON) as a pattern dict."""

def write_json(pattern: Pattern, path: str) -> None:
    """Writes a pattern dict as a pattern JSON file."""

def svg(pattern: Pattern) -> str:
    """The pattern drawn at 1:1 in millimetres, as `tapeline pattern export --svg`."""

def dxf(pattern: Pattern) -> str:
    """The pattern as a DXF-AAMA / ASTM D6673 file, as `tapeline pattern export --dxf`."""

def png(pattern: Pattern, pixels_per_mm: float = 2.0) -> bytes:
    """The pattern drawn as PNG bytes, as `tapeline pattern export --png`."""

def raster(pattern: Pattern, pixels_per_mm: float = 2.0) -> npt.NDArray[np.uint8]:
    """The pattern drawn as an RGBA array (height, width, 4), top row first."""

def check(pattern: Pattern) -> Pattern:
    """The pattern dict as the library reads and writes it (InvalidInput naming a fault)."""

class Database:
    """A SQLite pattern database; path None: the per-user default."""
    def __init__(
        self, path: Optional[str] = None, read_only: bool = False, create: bool = True
    ) -> None: ...
    @property
    def path(self) -> str: ...
    def __len__(self) -> int: ...
    def __contains__(self, name: str) -> bool: ...
    def list(
        self,
        name: str = "",
        designer: str = "",
        garment_type: str = "",
        size: str = "",
        tags: List[str] = [],
    ) -> List[Dict[str, Any]]: ...
    def get(self, name: str) -> Pattern: ...
    def store(self, pattern: Pattern, replace: bool = False) -> Dict[str, Any]: ...
    def import_file(
        self, path: str, format: str = "auto", replace: bool = False
    ) -> Dict[str, Any]: ...
    def remove(self, name: str) -> bool: ...
    def close(self) -> None: ...
    def __enter__(self) -> "Database": ...
    def __exit__(self, *args: Any) -> None: ...
