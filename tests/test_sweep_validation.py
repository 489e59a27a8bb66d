"""run_sweep and basin_sweep check every argument at the boundary (issue 18 item 6): a
hostile value of any one argument raises TypeError or ValueError naming that argument,
before any work (no partial folder, nothing integrated)."""

import math
import os
import tempfile
from decimal import Decimal

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from rollingdisk.util.errors import ParameterError, ParameterTypeError

sweep = pytest.importorskip("rollingdisk.sweep")

GRID = sweep.SweepGrid("rough", h=0.17, theta0=[0.5], omega30=[2.0])
NAN, INF = math.nan, math.inf
COMMON = {
    "t_end": [-5, 0, 0.0, -0.0, NAN, INF, -INF, Decimal("0.5"), "1", None, True, 1j,
              np.array([1.0, 2.0]), [1.0], 1e10, 10 ** 400],
    "rtol": [NAN, -1e-9, 0.0, 2.0, 1e-20, "1e-9", None, Decimal("1e-9"), INF, False],
    "atol": [NAN, -1e-9, 0.0, 2.0, "1e-9", None, INF, True],
    "max_steps": [-1, 0, 1.5, NAN, "10", None, True, 10 ** 13, INF, Decimal(10)],
    "chunk": [0, -3, 2.5, "8", None, True, NAN, 10 ** 9],
    "workers": [0, -1, 1.5, "2", True, NAN, 10 ** 6],
    "executor": ["bogus", None, 1, "", "Serial", ["serial"], np.array(["serial", "dask"])],
    "method": ["rk4", None, 3, "", "TAYLOR"],
    "progress": [1, "x", 3.0],
    "out": ["x.csv", 5, "/no/such/folder/x.zarr", 3.5, b"x.zarr"],
    "grid": [None, "rough", 1, {"ground": "rough"}],
}
HOSTILE = {
    "run_sweep": COMMON | {
        "perturbation": [1.0, "x", (1e-3,), {"kick": 1e-3}],
        "dask_address": [5, b"tcp://x:1", "tcp://127.0.0.1:1"],  # the last: with serial
    },
    "basin_sweep": COMMON | {
        "executor": COMMON["executor"] + ["dask"],
        "kick_max": [0, -1, NAN, INF, 101, "1", None, Decimal("0.5"), True],
        "rounds": [0, 61, 1.5, "3", None, True, NAN],
    },
}
VALID = {
    "t_end": [0.5, 1.0], "rtol": [1e-6, 1e-9], "atol": [1e-6, 1e-9], "max_steps": [1000, 50],
    "chunk": [1, 7], "workers": [None, 1], "executor": ["serial", "threads"],
    "method": ["taylor", "dop853"], "progress": [None, print],
}
NAMES = {"run_sweep": sweep.run_sweep, "basin_sweep": sweep.basin_sweep}


@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(data=st.data())
def test_hostile_arguments_raise_type_or_value_errors_naming_them(data):
    func = data.draw(st.sampled_from(sorted(NAMES)))
    name = data.draw(st.sampled_from(sorted(HOSTILE[func])))
    value = data.draw(st.sampled_from(HOSTILE[func][name]))
    kw = {k: data.draw(st.sampled_from(v)) for k, v in VALID.items()}
    with tempfile.TemporaryDirectory() as tmp:
        kw["out"] = os.path.join(tmp, "s.zarr")
        kw[name] = value
        grid = kw.pop("grid", GRID)
        t_end = kw.pop("t_end")
        with pytest.raises((TypeError, ValueError)) as err:
            NAMES[func](grid, t_end, **kw)
        assert isinstance(err.value, (ParameterError, ParameterTypeError))
        assert name in str(err.value), (name, value, str(err.value))
        assert os.listdir(tmp) == []  # refused before any work


@settings(max_examples=200, deadline=None)
@given(func=st.sampled_from(sorted(NAMES)),
       t_end=st.one_of(st.floats(max_value=0.0), st.floats(min_value=1.0000001e9),
                       st.integers(max_value=0), st.integers(min_value=10 ** 9 + 1)),
       rtol=st.one_of(st.floats(max_value=9.9e-16), st.floats(min_value=1.0000001),
                      st.just(NAN)))
def test_out_of_range_numbers(func, t_end, rtol):
    """t_end outside (0, 1e9] or rtol outside [1e-15, 1]: always refused (NaN included)."""
    with pytest.raises(ParameterError, match="t_end|rtol"):
        NAMES[func](GRID, t_end, rtol=rtol)


def test_the_reported_cases():
    """Issue 18 item 6, case by case, with the allowed range in the message."""
    with pytest.raises(ParameterError, match=r"t_end must lie in \(0, 1e\+09\]"):
        sweep.basin_sweep(GRID, -5)
    with pytest.raises(ParameterError, match=r"t_end .*\(0, 1e\+09\]"):
        sweep.basin_sweep(GRID, 0)
    with pytest.raises(ParameterError, match="t_end must be a finite"):
        sweep.basin_sweep(GRID, NAN)
    with pytest.raises(ParameterTypeError, match="t_end"):
        sweep.basin_sweep(GRID, Decimal("0.5"))
    with pytest.raises(ParameterError, match="executor"):
        sweep.basin_sweep(GRID, 1.0, executor="bogus")
    with pytest.raises(ParameterError, match="dask.*not supported"):
        sweep.basin_sweep(GRID, 1.0, executor="dask")
    with pytest.raises(ParameterError, match="rtol"):
        sweep.basin_sweep(GRID, 1.0, rtol=NAN)
    with pytest.raises(ParameterError, match=r"max_steps must be an integer in \[1, "):
        sweep.run_sweep(GRID, 1.0, max_steps=-1)
    with pytest.raises(ParameterError, match="kick_max"):
        sweep.basin_sweep(GRID, 1.0, kick_max=0)
