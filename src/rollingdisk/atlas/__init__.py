"""The atlas: everything about one disk in one HTML page (``rollingdisk atlas``)."""

from rollingdisk.util.lazy import attach as _attach

__getattr__, __dir__, __all__ = _attach(__name__, {
    "build_atlas": "rollingdisk.atlas.build",
})
