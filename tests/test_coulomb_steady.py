"""mu_required of rough steady motions against the numeric core (contact force at the state)."""

import math

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

import rollingdisk as rd
from conftest import SIGN
from rollingdisk.model.ground import Coulomb
from rollingdisk.util.errors import ParameterError


@settings(max_examples=120, deadline=None)
@given(h=st.floats(0.0, 3.0), theta=st.floats(0.02, 1.45), sign=SIGN,
       Omega0=st.floats(0.2, 8.0), osign=SIGN)
def test_mu_required_equals_force_ratio(h, theta, sign, Omega0, osign):
    disk = rd.Disk(h)
    try:
        m = rd.steady_motion(disk, "rough", sign * theta, Omega0=osign * Omega0)
    except ParameterError:
        return
    y = rd.rolling_state(disk, m.initial_state(psi0=0.7))
    c = rd.coulomb_contact(disk, Coulomb(1.0), "rolling", y)
    ratio = c["F_t"] / c["F_z"]
    assert math.isclose(m.mu_required, ratio, rel_tol=1e-9, abs_tol=1e-11)
    assert m.as_dict()["mu_required"] == m.mu_required


def test_mu_required_map_matches_steady_motions():
    h = 0.3
    th = np.linspace(0.1, 1.4, 7)
    r = np.linspace(-3, 3, 9)
    TH, R = np.meshgrid(th, r, indexing="ij")
    mp = rd.mu_required_map(h, TH, R)
    n_ok = 0
    for i in range(th.size):
        for j in range(r.size):
            try:
                m = rd.steady_motion(rd.Disk(h), "rough", th[i], r_C=r[j])
            except ParameterError:
                assert np.isnan(mp[i, j])
                continue
            n_ok += 1
            assert math.isclose(mp[i, j], m.mu_required, rel_tol=1e-12, abs_tol=1e-14)
    assert n_ok > 20
    assert rd.straight_line(rd.Disk(h), "rough", 2.0).mu_required == 0.0
