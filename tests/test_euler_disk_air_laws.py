"""Euler's disk with Bildsten's boundary-layer air law (rollingdisk.scenarios.euler_disk,
``air_law="boundary-layer"``), and the spin-down comparison of the dissipation laws.

Sources of truth: the chain rule on the energy (eq. 13) against the powers; the
dimensional law ``Phi = pi sqrt(mu rho) a^4 Omega^(5/2)`` (Bildsten 2002) against the
dimensionless power; the closed-form exponents 4/9, -2/9 of ``P ~ Omega^(5/2)`` on the
family (``p = 1/(1 + m/2 + j)``, ``docs/errata-models.md``).  The right-hand side against
the sympy sliding system with the moment of ``BoundaryLayerAirDrag`` is in
``tests/test_euler_disk.py``, beside the film's (one lambdified system for both).
"""

import math

import numpy as np
import pytest

from rollingdisk.model.air_models import BoundaryLayerAirDrag
from rollingdisk.scenarios.euler_disk import (
    AIR_DENSITY,
    AIR_VISCOSITY,
    EulerDisk,
    dissipation_laws,
    predicted_exponents,
    run_euler_disk,
)
from rollingdisk.scenarios.euler_kernels import _energy, _rhs
from rollingdisk.util.errors import ParameterError

BL = dict(rolling_resistance=0.0, air_viscosity=AIR_VISCOSITY, air_law="boundary-layer")


def _random_reduced(rng):
    theta = rng.choice([-1.0, 1.0]) * rng.uniform(0.05, 1.5)
    return np.array([*rng.uniform(-1, 1, 2), theta, *rng.uniform(-3, 3, 3), 0.0, 0.0, 0.0])


def test_boundary_layer_energy_rate_equals_powers():
    rng = np.random.default_rng(12)
    for _ in range(40):
        h = rng.uniform(0, 1)
        c_roll, c_bl = rng.uniform(0, 0.05), rng.uniform(0, 0.05)
        x = _random_reduced(rng)
        dx, F_z, _ = _rhs(h, rng.uniform(0, 1), 0.1, c_roll, 0.0, 1e-6, x, c_bl=c_bl)
        d = 1e-30
        rate = np.imag(_energy(h, x + 1j * d * dx)) / d
        assert rate == pytest.approx(-dx[6:].sum(), rel=1e-9, abs=1e-12)
        assert dx[8] >= 0.0


def test_coefficient_is_bildsten_law_in_si():
    """The dimensionless power c Omega^(5/2), taken to SI (power unit m g^(3/2) a^(1/2)),
    is Bildsten's Phi = pi sqrt(mu rho) a^4 Omega_SI^(5/2)."""
    toy = EulerDisk(**BL)
    Om = 7.3  # units sqrt(g/a)
    P = toy.c_boundary_layer * Om ** 2.5
    a, m, g = toy.radius, toy.mass, toy.gravity
    P_si = P * m * g ** 1.5 * a ** 0.5
    Om_si = Om * math.sqrt(g / a)
    phi = math.pi * math.sqrt(AIR_VISCOSITY * 1.204) * a ** 4 * Om_si ** 2.5
    assert P_si == pytest.approx(phi, rel=1e-12)
    assert toy.c_air == 0.0 and EulerDisk(air_viscosity=AIR_VISCOSITY).c_boundary_layer == 0.0
    assert AIR_DENSITY == 1.204


def test_predicted_exponents_tend_to_four_ninths():
    """P ~ Omega^(5/2) ~ alpha^(-5/4) and E - E_inf ~ alpha on the family: alpha ~
    tau^(4/9), Omega ~ tau^(-2/9) as the window shrinks to 0."""
    p = predicted_exponents(EulerDisk(**BL), window=(1e-7, 1e-6))
    assert p["alpha"] == pytest.approx(4 / 9, abs=1e-3)
    assert p["Omega"] == pytest.approx(-2 / 9, abs=1e-3)
    assert p["contact_speed"] == pytest.approx(-2 / 9, abs=1e-3)


def test_boundary_layer_run_exponents_match_prediction():
    """The toy with the boundary layer alone (no rolling resistance, so the air law sets the
    decay) over alpha in (0.01, 0.05), above the crossover tilt alpha_c = 4.8e-3 where the
    law applies: fitted exponents equal the steady family's to 2e-2, near 4/9 and -2/9."""
    toy = EulerDisk(**BL)
    assert BoundaryLayerAirDrag.crossover_tilt(AIR_VISCOSITY, AIR_DENSITY, toy.radius,
                                               toy.gravity) < 0.01
    r = run_euler_disk(toy, fit_window=(0.01, 0.05))
    assert r.status == "completed" and r.end == "fell-flat", r.message
    assert r.energy_balance <= 1e-9
    assert r.dissipated["air"][-1] > 0.3 and r.dissipated["rolling_resistance"][-1] == 0.0
    for name in ("alpha", "Omega", "contact_speed"):
        assert r.exponents[name] == pytest.approx(r.predicted[name], abs=2e-2), name
    assert r.predicted["alpha"] == pytest.approx(4 / 9, abs=5e-3)
    assert r.predicted["Omega"] == pytest.approx(-2 / 9, abs=5e-3)
    # the end: later than the adiabatic decay by the few % the disk lags the family
    assert r.predicted_t_end < r.t_end < 1.1 * r.predicted_t_end


def test_dissipation_laws_and_default_window():
    laws = dissipation_laws()
    assert list(laws) == ["rolling resistance", "squeeze film", "boundary layer",
                          "rolling resistance + film"]
    assert laws["rolling resistance"].c_air == 0 == laws["rolling resistance"].c_boundary_layer
    assert laws["squeeze film"].rolling_resistance == 0 < laws["squeeze film"].c_air
    assert laws["boundary layer"].c_boundary_layer > 0 == laws["boundary layer"].c_air
    with pytest.raises(TypeError, match="toy"):
        dissipation_laws(3)
    r = run_euler_disk(EulerDisk(alpha0=0.06, **BL), predict=False)
    assert r.fit_window == (0.01, 0.05)


@pytest.mark.parametrize("kw, name", [({"air_law": "moffatt"}, "air_law"),
                                      ({"air_law": 3}, "air_law"),
                                      ({"air_density": 0.0}, "air_density")])
def test_bad_air_parameters(kw, name):
    with pytest.raises(ParameterError, match=name):
        EulerDisk(**kw)


def test_spin_down_comparison_draws_fitted_slopes():
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib.figure import Figure

    from rollingdisk.plotting.spin_down import plot_spin_down_comparison

    runs = {"boundary layer": run_euler_disk(EulerDisk(alpha0=0.06, **BL)),
            "boundary layer + rolling resistance": run_euler_disk(
                EulerDisk(alpha0=0.06, **{**BL, "rolling_resistance": 2e-3}))}
    out = plot_spin_down_comparison(runs, fig=Figure())
    for label, r in runs.items():
        for name in ("alpha", "Omega"):
            line = out["lines"][f"{label}/{name}_fit"]
            x, y = line.get_data()
            assert np.polyfit(np.log(x), np.log(y), 1)[0] == pytest.approx(
                r.exponents[name], rel=1e-9)
            assert f"{r.exponents[name]:+.3f}" in line.get_label()
            assert f"{r.predicted[name]:+.3f}" in line.get_label()
    with pytest.raises(ParameterError, match="results"):
        plot_spin_down_comparison([], fig=Figure())
    with pytest.raises(TypeError, match="results"):
        plot_spin_down_comparison([3], fig=Figure())
