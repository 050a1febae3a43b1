"""Sewing patterns as dicts (the pattern JSON format) and the SQLite pattern database."""
from ._tapeline import pattern as _p

read = _p.read
write_json = _p.write_json
svg = _p.svg
check = _p.check
Database = _p.Database

__all__ = ["read", "write_json", "svg", "check", "Database"]
