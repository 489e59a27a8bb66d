"""State layouts of the equations of motion on each ground, named as in the paper."""

from __future__ import annotations

import numpy as np

from rollingdisk.model.disk import check_ground
from rollingdisk.util.checks import real_array
from rollingdisk.util.errors import ParameterError

__all__ = ["ROUGH_STATE", "SMOOTH_STATE", "state_names", "state_index"]



#: Names of the rough-ground state components, in order.
ROUGH_STATE = ("X_C", "Y_C", "psi", "theta", "phi", "omega1", "omega2", "omega3")


#: Names of the smooth-ground state components, in order.
SMOOTH_STATE = ("X_C", "Y_C", "V_X", "V_Y", "psi", "theta", "phi", "omega1", "omega2", "omega3")


def state_names(ground: str) -> tuple[str, ...]:
    """The names of the state components for ``ground`` (``"rough"`` or ``"smooth"``)."""
    return ROUGH_STATE if check_ground(ground) == "rough" else SMOOTH_STATE


def state_index(ground: str, name: str) -> int:
    """Index of the component ``name`` in the state vector of ``ground``."""
    names = state_names(ground)
    if name not in names:
        raise ParameterError(f"name must be one of {names} on {ground} ground, got {name!r}")
    return names.index(name)


def reduced_state(rough, y):
    """``(theta, omega1, omega2, omega3)`` out of a state vector of either ground, or of a
    reduced state (4 components, returned as they are)."""
    if y.shape[0] == 4:
        return y[0], y[1], y[2], y[3]
    if rough:
        return y[3], y[5], y[6], y[7]
    return y[5], y[7], y[8], y[9]


_reduced_state = reduced_state  # the name the kernels and compiled namespaces call it by


def _shape_error(ground: str, y, name: str = "y") -> ParameterError:
    names = state_names(ground)
    return ParameterError(f"{name} must have {len(names)} components on {ground} ground "
                          f"({', '.join(names)}), got {np.shape(y)}")


def as_state(ground: str, y, name: str = "y") -> np.ndarray:
    """``y`` as a float array of states: right length, finite (never a silent NaN).

    A non-number raises :class:`~rollingdisk.util.errors.ParameterTypeError`; a wrong
    shape, NaN, an infinity or an integer beyond floating-point range (``10**400``)
    :class:`~rollingdisk.util.errors.ParameterError`, each naming ``name``.
    """
    y = real_array(name, y)
    if y.shape[:1] != (len(state_names(ground)),):
        raise _shape_error(ground, y, name)
    if not np.all(np.isfinite(y)):
        raise ParameterError(f"{name} must be finite (no NaN or infinity)")
    return y


_as_state = as_state  # the name model.coulomb and ivp.hybrid import
