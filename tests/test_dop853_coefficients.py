"""The DOP853 table the library owns (rollingdisk.engine.dop853_coefficients).

Sources of truth: the order conditions a Runge-Kutta method of order 8 must satisfy (the
quadrature conditions sum b_i c_i^(k-1) = 1/k for k <= 8, row sums of A equal to c, and the
embedded estimators being differences of a lower-order method: their weights sum to zero),
independent of any code; and scipy's own table where scipy still ships it.
"""

import importlib

import numpy as np
import pytest

from rollingdisk.engine import dop853_coefficients as d


def test_row_sums_of_A_are_the_nodes():
    # c_i = sum_j a_ij for every stage, the dense-output stages included
    n = d.N_STAGES_EXTENDED
    np.testing.assert_allclose(d.A[:n, :n].sum(axis=1), d.C[:n], rtol=0, atol=1e-15)


@pytest.mark.parametrize("k", range(1, 9))
def test_quadrature_conditions_to_order_8(k):
    b, c = d.B, d.C[: d.N_STAGES]
    assert abs(float(np.sum(b * c ** (k - 1))) - 1.0 / k) < 1e-15


def test_tree_conditions_of_orders_3_and_4():
    A, b, c = d.A[: d.N_STAGES, : d.N_STAGES], d.B, d.C[: d.N_STAGES]
    assert abs(b @ A @ c - 1 / 6) < 1e-15
    assert abs(b @ (c * (A @ c)) - 1 / 8) < 1e-15
    assert abs(b @ A @ (c * c) - 1 / 12) < 1e-15
    assert abs(b @ A @ A @ c - 1 / 24) < 1e-15


def test_error_estimators_are_differences_of_consistent_methods():
    assert abs(float(d.E3.sum())) < 1e-15 and abs(float(d.E5.sum())) < 1e-15


def test_the_same_numbers_as_scipy_where_scipy_has_them():
    try:
        s = importlib.import_module("scipy.integrate._ivp.dop853_coefficients")
    except ImportError:  # pragma: no cover - a scipy without the private table
        pytest.skip("this scipy has no private DOP853 table")
    for name in ("A", "B", "C", "E3", "E5", "D"):
        np.testing.assert_array_equal(getattr(d, name), getattr(s, name), err_msg=name)
