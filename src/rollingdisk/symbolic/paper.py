"""The paper's printed equations of section 2, (37), (38) and (49), checked against the derivation.

Owns these printed formulas (typed in here only, and only to be compared with
:func:`rollingdisk.symbolic.derivation.derive`; the library never uses them) and their rows,
:func:`checks_sections_1_2`.  The comparison is :func:`rollingdisk.symbolic.identity.same`
(re-exported here); the printed statements of sections 3-4 are in
:mod:`rollingdisk.symbolic.printed`.
"""

from __future__ import annotations

from functools import lru_cache

import sympy as sp

from . import derivation as dv
from .derivation import (
    F_x,
    F_y,
    F_z,
    M_x,
    M_y,
    M_z,
    derive,
    dw1,
    dw2,
    dw3,
    h,
    ht,
    omega1,
    omega2,
    omega3,
    psi,
    theta,
    v_Cx,
    v_Cy,
    v_Cz,
)
from .identity import same
from .rows import EquationCheck

__all__ = ["PRINTED_38", "PRINTED_49",
           "EquationCheck", "checks_sections_1_2", "same"]


# The printed reduced equations, in the symbols of :mod:`.derivation` (typed in here only).
_s, _c, _p = sp.sin(theta), sp.cos(theta), sp.tan(theta)
_y_P, _z_P = _s - ht * _c, -(_c + ht * _s)  # printed (4)
_k1, _k2 = sp.Rational(1, 4) + h**2 / 3, sp.Rational(1, 2)  # printed (10)

#: eq. (38) as printed: (domega1, domega2, domega3)/dt on rough ground.
PRINTED_38 = sp.Matrix([
    (6 * (3 + 2 * ht * _p) * omega2 * omega3 - ((3 + 16 * h**2) * _p + 12 * ht) * omega3**2
     + 12 * (_s - ht * _c)) / (15 + 16 * h**2),
    -(4 * ht * omega2 + sp.Rational(2, 3) * (3 + 4 * h**2) * omega3) * omega1 / (3 + 8 * h**2),
    (-6 * omega2 / (3 + 8 * h**2) + (_p + 4 * ht / (3 + 8 * h**2)) * omega3) * omega1,
])

#: eq. (49) as printed: (domega1, domega2, domega3)/dt on smooth ground.
PRINTED_49 = sp.Matrix([
    ((_k2 * omega2 - _k1 * omega3 * _p) * omega3 + _y_P + _y_P * _z_P * omega1**2)
    / (_k1 + _y_P**2),
    0,
    (-_k2 * omega2 + _k1 * omega3 * _p) * omega1 / _k1,
])


def _row(eq, quantity, derived, printed, correct_text=""):
    ok, how = same(derived, printed)
    if ok:
        return EquationCheck(eq, quantity, "confirmed", how)
    return EquationCheck(eq, quantity, "misprint", how, printed=str(printed),
                         correct=correct_text or str(derived))


@lru_cache(maxsize=1)
def checks_sections_1_2() -> tuple[EquationCheck, ...]:
    """Check eqs. (1)-(13), (37), (38), (49) against :func:`derive` (cached)."""
    d = derive()
    rows: list[EquationCheck] = []
    s, c, p = sp.sin(theta), sp.cos(theta), sp.tan(theta)
    Omega = omega3 / c
    y_P = s - ht * c  # printed (4)
    z_P = -(c + ht * s)
    k1 = sp.Rational(1, 4) + h**2 / 3  # printed (10)
    k2 = sp.Rational(1, 2)

    # (1): the inertial velocity of C is Rz(psi) v_C
    vel = dv._Rz(psi) * sp.Matrix([v_Cx, v_Cy, v_Cz])
    printed1 = sp.Matrix([v_Cx * sp.cos(psi) - v_Cy * sp.sin(psi),
                          v_Cx * sp.sin(psi) + v_Cy * sp.cos(psi), v_Cz])
    rows.append(_row("(1)", "dX_C/dt, dY_C/dt, dZ_C/dt", vel, printed1))
    # (2), (3)
    rows.append(_row("(2)", "dpsi/dt, dtheta/dt, dphi/dt",
                     sp.Matrix(d.frame_rates), sp.Matrix([Omega, omega1, omega2 - omega3 * p])))
    psidot, phidot = sp.symbols("psidot phidot", real=True)
    printed3 = sp.Matrix([phidot + psidot * s, psidot * c])  # omega2 = omega + Omega sin...
    rows.append(_row("(3)", "omega2, omega3 from Omega, omega",
                     sp.Matrix(d.angular_velocity[1:]), printed3))
    # (4), (5)
    rows.append(_row("(4)", "contact point y_P, z_P in Cxyz",
                     sp.Matrix(d.contact_point), sp.Matrix([y_P, z_P])))
    rows.append(_row("(5)", "contact point X_P - X_C, Y_P - Y_C",
                     sp.Matrix(d.contact_point_inertial),
                     sp.Matrix([-y_P * sp.sin(psi), y_P * sp.cos(psi)])))
    # (6), (7)
    printed6 = sp.Matrix([v_Cx - omega2 + ht * omega3, v_Cy - omega1 * z_P, v_Cz + omega1 * y_P])
    rows.append(_row("(6)", "contact-point velocity v_P in Cxyz",
                     sp.Matrix(d.contact_velocity), printed6))
    rows.append(_row("(7)", "Z_C = -z_P, v_Cz = -omega1 y_P",
                     sp.Matrix(d.centre_height), sp.Matrix([-z_P, -omega1 * y_P])))
    # (8): residuals m(dv/dt - ...) - F
    dvx, dvy, dvz = sp.symbols("dv_Cx dv_Cy dv_Cz", real=True)
    printed8 = sp.Matrix([dvx - v_Cy * Omega - F_x, dvy + v_Cx * Omega - F_y, dvz + 1 - F_z])
    rows.append(_row("(8)", "momentum balance in Cxyz", sp.Matrix(d.newton), printed8))
    # (9)
    printed9 = sp.Matrix([
        k1 * dw1 - ((k2 * omega2 - k1 * omega3 * p) * omega3 - z_P * F_y + y_P * F_z + M_x),
        k2 * dw2 - (-F_x + M_y * c + M_z * s),
        k1 * dw3 - ((-k2 * omega2 + k1 * omega3 * p) * omega1 + ht * F_x - M_y * s + M_z * c),
    ])
    rows.append(_row("(9)", "angular-momentum balance about C in C xi eta zeta",
                     sp.Matrix(d.euler), printed9))
    # (10), (11)
    rows.append(_row("(10)", "radii of gyration k1^2, k2^2",
                     sp.Matrix(d.inertia), sp.Matrix([k1, k2])))
    rows.append(_row("(11)", "normal force F_z", d.normal_force,
                     1 + z_P * omega1**2 - y_P * dw1))
    # (12): dE/dt - (v_P . F_t + omega . M) vanishes along (8)-(9)
    rows.append(_row("(12)", "energy rate dE/dt = v_P.F_t + omega.M", d.energy_rate, 0))
    printed13 = ((v_Cx**2 + v_Cy**2 + v_Cz**2) / 2 + k1 * (omega1**2 + omega3**2) / 2
                 + k2 * omega2**2 / 2 - z_P)
    rows.append(_row("(13)", "total energy E", d.energy, printed13))
    # (37)
    rows.append(_row("(37)", "v_Cx, v_Cy on rough ground",
                     sp.Matrix(d.rough_velocity_of_C),
                     sp.Matrix([omega2 - ht * omega3, -omega1 * (c + ht * s)])))
    # (38)
    rows.append(_row("(38)", "domega/dt on rough ground",
                     sp.Matrix(d.rough_omega_dot), PRINTED_38))
    # (49)
    rows.append(_row("(49)", "domega/dt on smooth ground",
                     sp.Matrix(d.smooth_omega_dot), PRINTED_49))
    return tuple(rows)
