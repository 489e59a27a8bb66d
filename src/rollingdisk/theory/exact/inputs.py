"""The checks at the public boundary of the exact motions: the ground, the initial state,
arrays of real numbers and the names of the work budget, each failing with a
``ParameterError`` or ``ParameterTypeError`` that names the parameter.
"""

from __future__ import annotations

import numpy as np

from rollingdisk.model.state import state_index, state_names
from rollingdisk.util.errors import ParameterError, ParameterTypeError

_RATE_MAX = 1e50  # |omega_i| above this: the quadrature's products (q^2, ...) overflow


def _check_ground(ground) -> str:
    if not isinstance(ground, str):
        raise ParameterTypeError(f"ground must be the string 'rough' or 'smooth', got "
                                 f"{type(ground).__name__} {ground!r}")
    if ground not in ("rough", "smooth"):
        raise ParameterError(f"ground must be 'rough' or 'smooth' for an exact motion "
                             f"(the Coulomb ground is not integrable), got {ground!r}")
    return ground


def _check_state(ground: str, y0) -> np.ndarray:
    """``y0`` as one finite float state with rates in range, or a named error."""
    names_ = state_names(ground)
    y = _real_array("y0", y0)
    if y.shape != (len(names_),):
        raise ParameterError(f"y0 must be one state of {len(names_)} components "
                             f"({', '.join(names_)}) on {ground} ground, got shape {y.shape}")
    if not np.all(np.isfinite(y)):
        raise ParameterError("y0 must be finite (no NaN or infinity)")
    it = state_index(ground, "theta")
    rate = float(np.max(np.abs(y[it + 2:it + 5])))
    if rate > _RATE_MAX:
        raise ParameterError(f"y0 is out of range: rates |omega_i| up to {_RATE_MAX:g} "
                             f"sqrt(g/a) can be followed (beyond, omega^2 and its products "
                             f"overflow), got {rate:g}")
    return y


def _real_array(name: str, value, max_size: int = 1_000_000) -> np.ndarray:
    """``value`` as a float array: ParameterTypeError for anything but real numbers
    (strings, None, booleans, complex), ParameterError for ints beyond the float range."""
    try:
        raw = np.asarray(value)
    except (TypeError, ValueError):  # ragged nesting
        raise ParameterTypeError(f"{name} must be an array of real numbers, got "
                                 f"{type(value).__name__}") from None
    if raw.size > max_size:
        raise ParameterError(f"{name}: at most {max_size} values, got {raw.size}")
    if raw.dtype.kind == "O":
        flat = raw.ravel()
        for v in flat:
            if isinstance(v, bool) or not isinstance(v, (int, float, np.integer,
                                                         np.floating)):
                raise ParameterTypeError(f"{name} must be an array of real numbers, got an "
                                         f"element of type {type(v).__name__}")
        try:
            return np.array([float(v) for v in flat], dtype=float).reshape(raw.shape)
        except OverflowError:
            raise ParameterError(f"{name} must be finite: a value is beyond the "
                                 f"floating-point range (|value| > 1.8e308)") from None
    if raw.dtype.kind in "iuf":
        return raw.astype(float)
    raise ParameterTypeError(f"{name} must be an array of real numbers, got dtype "
                             f"{raw.dtype} ({type(value).__name__})")


def _check_budget_keys(budget: dict) -> None:
    extra = set(budget) - {"time_limit", "max_evals", "max_terms"}
    if extra:
        raise ParameterTypeError(f"unexpected keyword argument(s) {', '.join(sorted(extra))}"
                                 f"; the budget is time_limit, max_evals, max_terms")
