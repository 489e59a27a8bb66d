"""Contact geometry (eq. 4): which rim edge touches, and where, at inclination theta."""

from __future__ import annotations

import numpy as np

from rollingdisk.util.checks import real_array

__all__ = ["h_tilde", "inertia", "K2"]



def h_tilde(h, theta):
    """``h~ = h sgn(theta)``: which rim edge touches the plane (eq. 4).

    Parameters
    ----------
    h : float or array_like
        Half-thickness.
    theta : float or array_like
        Inclination [rad]; broadcast with ``h``.

    Returns
    -------
    float or ndarray
        ``+h`` for ``theta >= 0`` (``theta = 0`` counts as the limit ``0+``), ``-h`` for
        ``theta < 0``: the convention of the kernels, defined once in
        :func:`contact_geometry` below.

    Examples
    --------
    >>> h_tilde(0.2, -0.5), h_tilde(0.2, 0.0)
    (-0.2, 0.2)
    """
    ht = contact_geometry(real_array("h", h), real_array("theta", theta))[0]
    return float(ht) if np.ndim(ht) == 0 else ht



#: ``k2^2 = 1/2``: the squared radius of gyration about the axis, units ``a^2`` (eq. 10),
#: the same for every thickness.
K2 = 0.5


# ---------------------------------------------------------------------------------------
# kernels: plain arithmetic, numba-compilable, element-wise on arrays
# ---------------------------------------------------------------------------------------
def inertia(h):
    """``(k1^2, k2^2)``: the squared radii of gyration of a disk of half-thickness ``h`` about
    a diameter through C and about its axis, in units of ``a^2`` (eq. 10): ``k1^2 = 1/4 +
    h^2/3``, ``k2^2 = 1/2``.

    The library's one place for eq. (10): every kernel, map and property takes it from here.
    Element-wise on arrays; numba-compilable.

    Examples
    --------
    >>> inertia(0.0)
    (0.25, 0.5)
    """
    # 0.5 written here, not K2: the compiled loops bind this function's code into their own
    # namespaces, where only the names of its kernels travel with it
    return 0.25 + h * h / 3.0, 0.5


def contact_geometry(h, theta):
    """``h~, sin, cos, tan, y_P, z_P`` at inclination ``theta`` (eq. 4, a = 1).

    This is the library's one definition of ``h~ = h sgn(theta)`` (which rim edge touches
    the plane); every other place takes ``h~`` from here
    (:func:`rollingdisk.model.geometry.h_tilde`,
    the maps of :mod:`rollingdisk.theory.steady` and :mod:`rollingdisk.theory.oscillations`).
    Convention:
    ``theta = 0`` counts as the limit ``theta -> 0+``, so ``h~ = +h`` there (and ``-0.0``
    too).  For ``h = 0`` nothing depends on it; for ``h > 0``, ``theta = 0`` (the disk on
    the line of its rim edge) is outside the theory, and a simulation stops there (the
    edge-contact guard).  Only the real part of ``theta`` decides the sign, so that the
    complex-step derivatives of :func:`rollingdisk.reduced_jacobian` pass through, and the
    expression compiles with numba, element-wise on arrays.
    """
    ht = h * np.sign(np.sign(np.real(theta)) + 0.5)  # sgn with sgn(0) = +1
    s = np.sin(theta)
    c = np.cos(theta)
    y_P = s - ht * c  # eq. (4)
    z_P = -(c + ht * s)  # eq. (4)
    return ht, s, c, s / c, y_P, z_P


#: The kernels under the names by which the kernels of :mod:`rollingdisk.model.equations`
#: and :mod:`rollingdisk.model.coulomb` call them: the compiled namespaces
#: (:mod:`rollingdisk.engine.numba_core`, :mod:`rollingdisk.engine.pycore`, the Coulomb
#: loop) bind the compiled functions by these names.
_inertia = inertia
_geometry = contact_geometry
