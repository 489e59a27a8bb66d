"""Image files: the resolutions and formats accepted, and a figure written whole or not at
all.
"""

from __future__ import annotations

from rollingdisk.util.checks import check_int
from rollingdisk.util.errors import ParameterError, ParameterTypeError

__all__ = ["DPI_RANGE", "IMAGE_FORMATS", "check_dpi", "image_format", "save_figure"]

#: Resolutions accepted for images and animations, in dots per inch: below 20 the text is
#: unreadable, above 600 a figure of the library runs to hundreds of megabytes.
DPI_RANGE = (20, 600)

#: Image formats :func:`save_figure` writes (matplotlib's own backends, no LaTeX needed).
IMAGE_FORMATS = ("png", "pdf", "svg")


def check_dpi(dpi, name: str = "dpi") -> int:
    """``dpi`` as an int in :data:`DPI_RANGE`, or :class:`~rollingdisk.ParameterError`.

    Parameters
    ----------
    dpi : int
        Dots per inch.
    name : str
        The parameter's name for the message.

    Returns
    -------
    int
    """
    return check_int(name, dpi, low=DPI_RANGE[0], high=DPI_RANGE[1])


def image_format(path, name: str = "out") -> str:
    """The image format of ``path`` by its suffix, one of :data:`IMAGE_FORMATS`.

    Parameters
    ----------
    path : path-like
        The image file.
    name : str
        The parameter's name for the message.

    Returns
    -------
    str
        ``"png"``, ``"pdf"`` or ``"svg"``.

    Raises
    ------
    ParameterError
        For any other suffix (or none).
    """
    import os

    try:
        suffix = os.path.splitext(os.fspath(path))[1].lower().lstrip(".")
    except TypeError:
        raise ParameterTypeError(f"{name} must be a file name, got {type(path).__name__} "
                                 f"{path!r}") from None
    if suffix not in IMAGE_FORMATS:
        raise ParameterError(f"{name} must end in one of "
                             f"{', '.join('.' + f for f in IMAGE_FORMATS)}, got {str(path)!r}")
    return suffix


def save_figure(fig, path, *, dpi: int = 110):
    """Write ``fig`` to ``path`` whole or not at all (a temporary file, renamed at the end).

    Parameters
    ----------
    fig : matplotlib Figure
    path : path-like
        ``.png``, ``.pdf`` or ``.svg`` (:data:`IMAGE_FORMATS`); its folder must exist.
    dpi : int
        Resolution, in :data:`DPI_RANGE`.

    Returns
    -------
    Path
        ``path``.
    """
    from pathlib import Path

    from rollingdisk.util.files import atomic_file, check_writable

    fmt = image_format(path)
    dpi = check_dpi(dpi)
    target = check_writable(path, name="out")
    with atomic_file(target, mode=None) as tmp:
        fig.savefig(tmp, dpi=dpi, format=fmt)
    return Path(path)
