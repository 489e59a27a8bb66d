"""The atlas: everything about one disk in one HTML page (``rollingdisk atlas``)."""

from rollingdisk.atlas.build import (
    build_atlas as build_atlas,
)

__all__ = ["build_atlas"]
