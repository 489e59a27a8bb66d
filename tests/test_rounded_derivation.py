"""The rounded disk's equations (rollingdisk.model.rim) against two sympy derivations.

Newton-Euler (rollingdisk.symbolic.rounded.derive_rounded: the contact found as the lowest
point of the rim arc, the balances of rollingdisk.symbolic.derivation with a general body
of revolution) and Lagrange's equations with multipliers in the inertial frame
(lagrange_rounded); and the inertia integrated over the body.  Sympy takes about a minute.
"""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp

from rollingdisk.model.rim import rim_contact, rim_inertia, rounded_omega_dot

pytestmark = pytest.mark.slow


def test_inertia_is_the_integral_over_the_body():
    from rollingdisk.symbolic.rounded import rho, rounded_inertia

    V, k1, k2, h = rounded_inertia()
    f = sp.lambdify((h, rho), [k1, k2], "mpmath")
    rng = np.random.default_rng(2)
    for _ in range(50):
        hh = rng.uniform(0.0, 3.0)
        r = rng.uniform(0.0, min(hh, 1.0))
        want = [float(x) for x in f(hh, r)] if r > 0 else None
        got = rim_inertia(hh, r)
        if want is not None:
            assert np.allclose(got, want, rtol=1e-13, atol=0)
    assert sp.simplify(k1.subs(rho, 0) - (sp.Rational(1, 4) + h**2 / 3)) == 0
    assert sp.simplify(k2.subs(rho, 0) - sp.Rational(1, 2)) == 0
    assert sp.simplify(k1.subs({rho: 1, h: 1}) - sp.Rational(2, 5)) == 0


@pytest.mark.parametrize("ground", ["rough", "smooth"])
def test_kernels_agree_with_newton_euler_and_lagrange(ground):
    from rollingdisk.symbolic.rounded import derive_rounded, lagrange_rounded, rounded_lambdified

    assert derive_rounded().energy_rate == 0  # eq. (12) holds for the rounded body
    ne = rounded_lambdified()[f"{ground}_omega_dot"]
    rng = np.random.default_rng(17)
    worst_ne = worst_la = 0.0
    for _ in range(60):
        h = rng.uniform(0.0, 2.0)
        rho = rng.uniform(0.0, min(h, 1.0))
        th = rng.uniform(-1.3, 1.3)
        w = rng.normal(size=3)
        k1, k2 = rim_inertia(h, rho)
        hp = rim_contact(h, rho, th)[0]
        got = np.array(rounded_omega_dot(ground == "rough", h, rho, k1, k2, th, *w))
        scale = max(1.0, np.max(np.abs(got)))
        worst_ne = max(worst_ne, np.max(np.abs(got - np.array(ne(hp, rho, k1, k2, th, *w))))
                       / scale)
        la = np.array(lagrange_rounded(ground, hp, rho, k1, k2, th, *w))
        worst_la = max(worst_la, np.max(np.abs(got - la)) / scale)
    assert worst_ne <= 1e-13
    assert worst_la <= 1e-12
