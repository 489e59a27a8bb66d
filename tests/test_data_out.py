"""Data out (issue 19): trajectories and Euler's-disk runs as xarray / pandas with units.

Sources of truth: the definitions of the paper's units (time sqrt(a/g), length a, speed
sqrt(a g), angular speed sqrt(g/a), force m g, energy m g a), applied by hand here to the
trajectory's own dimensionless arrays; the CF conventions (``units`` and ``long_name`` on
every variable, ``flag_values`` / ``flag_meanings`` on a categorical one).
"""

import io
import math

import numpy as np
import pytest

import rollingdisk as rd
from rollingdisk.scenarios.euler_disk import EulerDisk, run_euler_disk

A, M, G = 0.05, 0.4, 9.80665
SCALED = rd.Disk.from_dimensions(radius=A, thickness=0.017, mass=M)
T = math.sqrt(A / G)
BY_HAND = {"time": T, "length": A, "speed": math.sqrt(A * G), "angular_speed": 1 / T,
           "force": M * G, "energy": M * G * A, "angle": 1.0, "dimensionless": 1.0}
KIND = {"t": "time", "X_C": "length", "Y_C": "length", "X_P": "length", "Y_P": "length",
        "psi": "angle", "theta": "angle", "phi": "angle", "omega1": "angular_speed",
        "omega2": "angular_speed", "omega3": "angular_speed", "F_x": "force", "F_y": "force",
        "F_z": "force", "E": "energy", "V_X": "speed", "V_Y": "speed", "mode": "dimensionless"}
SI = {"time": "s", "length": "m", "speed": "m/s", "angular_speed": "rad/s", "force": "N",
      "energy": "J", "angle": "rad", "dimensionless": "1"}
PAPER = {"time": "sqrt(a/g)", "length": "a", "speed": "sqrt(a g)",
         "angular_speed": "sqrt(g/a)", "force": "m g", "energy": "m g a", "angle": "rad",
         "dimensionless": "1"}


def _kind(name):
    return "energy" if name.startswith("dissipated_") else KIND[name]


@pytest.fixture(scope="module")
def runs():
    m = rd.steady_motion(SCALED, "rough", 0.5, Omega0=2.0)
    smooth = rd.steady_motion(SCALED, "smooth", 0.5, Omega0=2.5)
    g = rd.Coulomb(0.1, 0.08, rolling_resistance=1e-3)  # too little friction: it slides
    return {
        "rough": rd.simulate_steady(m, 3.0, perturb=1e-3),
        "smooth": rd.simulate_steady(smooth, 3.0, perturb=1e-3),
        "coulomb": rd.simulate_coulomb(SCALED, g, (0, 3),
                                       rd.rolling_state(SCALED, m.initial_state())),
        "plain": rd.simulate_steady(rd.steady_motion(rd.Disk(h=0.17), "rough", 0.5,
                                                     Omega0=2.0), 3.0),
        "no_mass": rd.simulate_steady(rd.steady_motion(rd.Disk(h=0.17, radius=A), "rough",
                                                       0.5, Omega0=2.0), 3.0),
    }


@pytest.mark.parametrize("name", ["rough", "smooth", "coulomb"])
def test_xarray_in_si_with_attrs_on_every_variable(runs, name):
    tr = runs[name]
    ds = tr.to_xarray()
    cols = tr.as_columns()
    for k in (tr.dissipated or {}):
        cols[f"dissipated_{k}"] = tr.dissipated[k]
    assert set(ds.variables) == set(cols)
    for var, values in cols.items():
        da = ds[var]
        assert da.attrs["units"] == SI[_kind(var)], var
        assert da.attrs["long_name"], var
        np.testing.assert_allclose(da.values, np.asarray(values, float) * BY_HAND[_kind(var)],
                                   rtol=1e-14, atol=0, err_msg=var)
    assert ds.attrs["radius_si"] == A and ds.attrs["status"] == tr.status
    assert ds.attrs["h"] == SCALED.h


def test_coulomb_mode_is_flagged(runs):
    ds = runs["coulomb"].to_xarray()
    assert ds.mode.attrs["flag_values"] == [0, 1]
    assert ds.mode.attrs["flag_meanings"] == "rolling sliding"
    assert set(np.unique(ds.mode.values)) <= {0, 1}
    assert ds.attrs["ground"] == "coulomb" and ds.attrs["ground_mu_s"] == 0.1
    assert runs["coulomb"].transitions  # it does slide: the mode is not constant


def test_without_a_scale_the_paper_units_are_named(runs):
    tr = runs["plain"]
    for ds in (tr.to_xarray(), runs["rough"].to_xarray(si=False)):
        for var in ds.variables:
            assert ds[var].attrs["units"] == PAPER[_kind(var)], var
            assert ds[var].attrs["long_name"]
    np.testing.assert_array_equal(tr.to_xarray().theta.values, tr.theta)
    np.testing.assert_array_equal(tr.to_xarray().t.values, tr.t)


def test_radius_without_mass_converts_what_it_can(runs):
    ds = runs["no_mass"].to_xarray()
    assert ds.t.attrs["units"] == "s" and ds.X_C.attrs["units"] == "m"
    assert ds.F_z.attrs["units"] == "m g" and ds.E.attrs["units"] == "m g a"
    np.testing.assert_array_equal(ds.F_z.values, runs["no_mass"].F_z)


@pytest.mark.parametrize("name", ["rough", "coulomb", "plain"])
def test_dataframe_matches_the_dataset(runs, name):
    tr = runs[name]
    df, ds = tr.to_dataframe(), tr.to_xarray()
    assert set(df.columns) == set(ds.variables)
    for col in df.columns:
        np.testing.assert_array_equal(df[col].to_numpy(), ds[col].values)
        assert df.attrs["units"][col] == ds[col].attrs["units"]
        assert df.attrs["long_name"][col] == ds[col].attrs["long_name"]


def test_csv_header_carries_units(runs):
    tr = runs["smooth"]
    cols = tr.as_columns()
    for si, units in ((False, PAPER), (True, SI)):
        header = tr.csv_header(si=si)
        names = [h.split(" [")[0] for h in header.split(",")]
        assert names == list(cols)
        assert header.split(",") == [f"{n} [{units[KIND[n]]}]" for n in cols]
    # the SI columns hold SI values; a written file reads back with its header
    si_cols = tr.as_columns(si=True)
    np.testing.assert_allclose(si_cols["F_z"], cols["F_z"] * M * G, rtol=1e-15)
    buf = io.StringIO()
    np.savetxt(buf, np.column_stack(list(si_cols.values())), delimiter=",",
               header=tr.csv_header(si=True), comments="", fmt="%.17g")
    import pandas as pd

    back = pd.read_csv(io.StringIO(buf.getvalue()))
    assert list(back.columns)[0] == "t [s]" and list(back.columns)[-1] == "V_Y [m/s]"
    np.testing.assert_allclose(back["t [s]"].to_numpy(), tr.t * T, rtol=1e-15)
    assert tr.column_units()["omega1"] == "sqrt(g/a)"


def test_euler_disk_result_out():
    r = run_euler_disk(EulerDisk(alpha0=0.05), predict=False, t_max=20.0)
    toy = r.toy
    T_toy = math.sqrt(toy.radius / toy.gravity)
    ds = r.to_xarray()
    for var in ds.variables:
        assert ds[var].attrs["units"] and ds[var].attrs["long_name"], var
    units = {"t": "s", "alpha": "rad", "Omega": "rad/s", "contact_speed": "m/s",
             "slip_speed": "m/s", "F_z": "N", "E": "J"}
    for var, u in units.items():
        assert ds[var].attrs["units"] == u
    np.testing.assert_allclose(ds.t.values, r.t * T_toy, rtol=1e-14)
    np.testing.assert_allclose(ds.Omega.values, r.Omega / T_toy, rtol=1e-14)
    np.testing.assert_allclose(ds.E.values, r.E * toy.mass * toy.gravity * toy.radius,
                               rtol=1e-14)
    assert ds.dissipated_slip.attrs["units"] == "J"
    df = r.to_dataframe(si=False)
    assert df.attrs["units"]["t"] == "sqrt(a/g)"
    np.testing.assert_array_equal(df["alpha"].to_numpy(), r.alpha)
