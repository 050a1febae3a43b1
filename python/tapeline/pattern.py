"""Sewing patterns as dicts (the pattern JSON format) and the SQLite pattern database."""
from ._tapeline import pattern as _p

read = _p.read
write_json = _p.write_json
svg = _p.svg
dxf = _p.dxf
png = _p.png
raster = _p.raster
check = _p.check
Database = _p.Database

__all__ = ["read", "write_json", "svg", "dxf", "png", "raster", "check", "Database"]
