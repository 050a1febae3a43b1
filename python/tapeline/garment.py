"""A body dressed in a pattern (placement, sewing along geodesic strings, the drape and its quality
gates) and the fabric library."""
from ._tapeline import garment as _g

dress = _g.dress
bindings_from_body = _g.bindings_from_body
fabrics = _g.fabrics
fabric = _g.fabric
DressOptions = _g.DressOptions
PlacementOptions = _g.PlacementOptions
SewingOptions = _g.SewingOptions
DrapeOptions = _g.DrapeOptions
RelaxOptions = _g.RelaxOptions
FoldOptions = _g.FoldOptions

__all__ = ["dress", "bindings_from_body", "fabrics", "fabric", "DressOptions", "PlacementOptions", "SewingOptions",
           "DrapeOptions", "RelaxOptions", "FoldOptions"]
