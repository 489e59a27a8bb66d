"""The Taylor jets of the equations of motion: the series the Taylor method
(:mod:`rollingdisk.engine.taylor`) and the sweeps' batch Taylor kernels step with.

The reduced system ``(theta, omega1, omega2, omega3)`` (eq. 2 with eq. 38 on rough / eq. 49
on smooth ground) is polynomial in ``sin theta``, ``cos theta`` and the rates, with one
quotient (``tan theta``; on smooth ground also the factor ``1/(k1 + y_P^2)``), and
``X_C, Y_C, psi, phi`` are its quadratures (eqs. 1, 2, 37).  Its Taylor coefficients at a
point follow from the coefficients of lower order by the classic recurrences of automatic
differentiation (products are Cauchy convolutions; ``s' = c theta'``, ``c' = -s theta'``;
quotients by back-substitution), so a jet of order p costs O(p^2) arithmetic and two
sines/cosines.

The recurrences restate eqs. (1), (2), (37), (38) and (49) term by term (a product of
series for each product in the kernels of :mod:`rollingdisk.model.equations`), so
``tests/test_simulate_taylor.py`` holds them to those kernels: the first coefficient is the
right-hand side, twice the second its derivative along the flow (a complex step through
the kernels), the polynomial agrees with a tight ``solve_ivp`` on the numpy right-hand
side.  Here too: the polynomial of a step evaluated (Horner), the normal force along it
(eq. 11), its roots, and the step size of Jorba & Zou.

Functions here are compiled by :mod:`rollingdisk.engine.numba_core` and traced into vector
lanes by :mod:`rollingdisk.engine.lanes`; the module itself needs only numpy.
"""

from __future__ import annotations

import math

import numpy as np

from rollingdisk.engine.roots import (
    ILLINOIS_MAXITER,
    _illinois_converged,
    _illinois_trial,
)

# eq. (10), under the name the compiled namespace (numba_core) binds its compiled version by
from rollingdisk.model.geometry import inertia as _inertia


def _signed_h(h, th0):
    """``h~ = h sgn(theta)`` with ``sgn(0) = +1`` (eq. 4, ``_geometry``): the half-thickness
    on the side of the contact."""
    return h if th0 >= 0.0 else -h


def where(c, a, b):
    """``a if c else b`` with both evaluated: written so, a choice is traceable into the
    vector lanes of :mod:`.lanes` (a select there)."""
    return a if c else b


def _tay_rows_rough(h, th, w1, w2, w3, A, P):
    """The jet of the reduced system ``(theta, omega1, omega2, omega3)`` on rough ground
    (eq. 2 with eq. 38): coefficients 1..P of the rows ``th, w1, w2, w3`` from their
    values at index 0.

    ``A`` (at least 7 rows): the series of sin, cos, tan theta, tan(theta) omega3, and the
    three sums of eq. (38) below.  At order k every convolution is split into its interior
    terms (indices 1..k-1 on both sides, all known from lower orders), summed in one loop
    with nine independent accumulators, and its two end terms (index 0 or k), added once
    the order-k values they need exist: one loop of independent sums instead of nine
    dependent ones (the step is bound by throughput, not by the latency of each sum).
    ``k theta_k = omega1_{k-1}`` (eq. 2) replaces the derivative of the series of theta.
    """
    ht = _signed_h(h, th[0])
    h2 = h * h
    S, C, T, PW3, L, G, H = A[0], A[1], A[2], A[3], A[4], A[5], A[6]
    e1 = 1.0 / (15.0 + 16.0 * h2)
    e2 = 1.0 / (3.0 + 8.0 * h2)
    g2 = (2.0 / 3.0) * (3.0 + 4.0 * h2)
    cl = 3.0 + 16.0 * h2
    for k in range(P):
        s_ = 0.0
        c_ = 0.0
        t_ = 0.0
        pw = 0.0
        m1 = 0.0
        m2 = 0.0
        pl = 0.0
        d2 = 0.0
        d3 = 0.0
        for j in range(1, k):
            i = k - j
            dth = w1[j - 1]  # j theta_j
            s_ += dth * C[i]
            c_ += dth * S[i]
            t_ += C[j] * T[i]
            pw += T[j] * w3[i]
            m1 += w2[j] * w3[i]
            m2 += w3[j] * w3[i]
            pl += T[j] * L[i]
            d2 += G[j] * w1[i]
            d3 += H[j] * w1[i]
        if k == 0:
            S[0] = math.sin(th[0])
            C[0] = math.cos(th[0])
            T[0] = S[0] / C[0]
            PW3[0] = T[0] * w3[0]
            m1 = w2[0] * w3[0]
            m2 = w3[0] * w3[0]
        else:
            # s' = c theta', c' = -s theta'; tan theta = s/c
            dth = w1[k - 1]
            S[k] = (s_ + dth * C[0]) / k
            C[k] = -(c_ + dth * S[0]) / k
            T[k] = (S[k] - t_ - C[k] * T[0]) / C[0]
            PW3[k] = pw + T[0] * w3[k] + T[k] * w3[0]
            m1 += w2[0] * w3[k] + w2[k] * w3[0]
            m2 += 2.0 * w3[0] * w3[k]
        L[k] = 12.0 * ht * m1 - cl * m2
        G[k] = 4.0 * ht * w2[k] + g2 * w3[k]
        H[k] = -6.0 * e2 * w2[k] + 4.0 * ht * e2 * w3[k] + PW3[k]
        yp = S[k] - ht * C[k]  # eq. (4)
        if k == 0:
            pl = T[0] * L[0]
            d2 = G[0] * w1[0]
            d3 = H[0] * w1[0]
        else:
            pl += T[0] * L[k] + T[k] * L[0]
            d2 += G[0] * w1[k] + G[k] * w1[0]
            d3 += H[0] * w1[k] + H[k] * w1[0]
        kk = 1.0 / (k + 1)
        th[k + 1] = w1[k] * kk  # eq. (2)
        # eq. (38)
        w1[k + 1] = (18.0 * m1 + pl - 12.0 * ht * m2 + 12.0 * yp) * e1 * kk
        w2[k + 1] = -d2 * e2 * kk
        w3[k + 1] = d3 * kk


def _tay_rows_smooth(h, th, w1, w2, w3, A, P):
    """:func:`_tay_rows_rough` on smooth ground (eq. 2 with eq. 49); ``A`` (at least 11
    rows).

    eq. (49): ``d1 = N / D`` with ``N = (k2 w2 - k1 w3 p) w3 + y_P + y_P z_P w1^2`` and
    ``D = k1 + y_P^2`` (the quotient by back-substitution, ``y_P^2`` kept as a series),
    ``d2 = 0``, ``d3 = (-k2 w2 + k1 w3 p) w1 / k1``.
    """
    ht = _signed_h(h, th[0])
    k1 = _inertia(h)[0]  # eq. (10)
    k2 = 0.5
    S, C, T, PW3, YP, ZP = A[0], A[1], A[2], A[3], A[4], A[5]
    YZ, W11, YY, G, D1 = A[6], A[7], A[8], A[9], A[10]
    for k in range(P):
        if k == 0:
            S[0] = math.sin(th[0])
            C[0] = math.cos(th[0])
            T[0] = S[0] / C[0]
        else:
            a = 0.0
            b = 0.0
            for j in range(1, k + 1):
                a += w1[j - 1] * C[k - j]  # j theta_j = omega1_{j-1}
                b += w1[j - 1] * S[k - j]
            S[k] = a / k
            C[k] = -b / k
            a = S[k]
            for j in range(1, k + 1):
                a -= C[j] * T[k - j]
            T[k] = a / C[0]
        YP[k] = S[k] - ht * C[k]  # eq. (4)
        ZP[k] = -(C[k] + ht * S[k])
        pw = 0.0
        yz = 0.0
        ww = 0.0
        yy = 0.0
        for j in range(k + 1):
            pw += T[j] * w3[k - j]
            yz += YP[j] * ZP[k - j]
            ww += w1[j] * w1[k - j]
            yy += YP[j] * YP[k - j]
        PW3[k] = pw
        YZ[k] = yz
        W11[k] = ww
        YY[k] = yy
        G[k] = k2 * w2[k] - k1 * pw
        num = YP[k]
        d3 = 0.0
        for j in range(k + 1):
            num += G[j] * w3[k - j] + YZ[j] * W11[k - j]
            d3 -= G[j] * w1[k - j]
        for j in range(1, k + 1):
            num -= YY[j] * D1[k - j]
        D1[k] = num / (k1 + YY[0])
        kk = 1.0 / (k + 1)
        th[k + 1] = w1[k] * kk  # eq. (2)
        w1[k + 1] = D1[k] * kk
        w2[k + 1] = 0.0
        w3[k + 1] = d3 / k1 * kk


def _tay_jet4_rough(h, y, J, A, P):
    """``J`` (4, P + 1): the jet of the reduced state ``y = (theta, omega1, omega2,
    omega3)`` on rough ground (:func:`_tay_rows_rough`), as the sweeps use it."""
    for i in range(4):
        J[i, 0] = y[i]
    _tay_rows_rough(h, J[0], J[1], J[2], J[3], A, P)


def _tay_jet4_smooth(h, y, J, A, P):
    """:func:`_tay_jet4_rough` on smooth ground (:func:`_tay_rows_smooth`)."""
    for i in range(4):
        J[i, 0] = y[i]
    _tay_rows_smooth(h, J[0], J[1], J[2], J[3], A, P)


# Why one long function (issue 17: compiled kernels are exempt from the ~80-line rule): the
# Taylor coefficients of all eight rough-ground states, order by order, compiled by numba
# (numba_core).  It is the innermost loop of the Taylor method (O(P^2) per step); the
# recurrences of the reduced rows and of the quadratures are fused into one pass over the
# orders so that each convolution is computed once and shared, in scratch rows of A that
# live in this frame.  Split per state, each piece would recompute or pass those partial
# series, and nopython offers no closure or object to share them cheaply (a two-pass
# version is slower: docs/performance.md); tests/test_simulate_taylor.py holds the jet to
# the model's kernels.
def _tay_jet_rough(h, y, J, A, P):
    """:func:`_tay_jet` on rough ground (eqs. 1, 2, 37, 38), the convolutions fused.

    The recurrences of :func:`_tay_rows_rough` and those of the quadratures X_C, Y_C, psi,
    phi in one loop: at order k every convolution is split into its interior terms
    (indices 1..k-1 on both sides, all known from lower orders), summed in one loop with
    15 independent accumulators, and its two end terms (index 0 or k), added once the
    order-k values they need exist.  The step is bound by throughput, not by the latency
    of each running sum, so one pass with independent sums beats two (reduced rows, then
    quadratures).  ``k theta_k = omega1_{k-1}`` and ``k psi_k = (omega3/c)_{k-1}``
    (eq. 2) replace the derivatives of the series of theta and psi.
    """
    for i in range(y.shape[0]):
        J[i, 0] = y[i]
    ht = _signed_h(h, y[3])
    h2 = h * h
    S, C, T, Q = A[0], A[1], A[2], A[3]
    PW3, ZP, SP, CP = A[4], A[6], A[7], A[8]
    L, VY, G, H, VX = A[11], A[12], A[16], A[17], A[18]
    w1 = J[5]
    w2 = J[6]
    w3 = J[7]
    e1 = 1.0 / (15.0 + 16.0 * h2)
    e2 = 1.0 / (3.0 + 8.0 * h2)
    g2 = (2.0 / 3.0) * (3.0 + 4.0 * h2)
    cl = 3.0 + 16.0 * h2
    for k in range(P):
        s_ = 0.0
        c_ = 0.0
        sp = 0.0
        cp = 0.0
        t_ = 0.0
        q_ = 0.0
        pw = 0.0
        m1 = 0.0
        m2 = 0.0
        pl = 0.0
        d2 = 0.0
        d3 = 0.0
        vy = 0.0
        dx = 0.0
        dy = 0.0
        for j in range(1, k):
            i = k - j
            dth = w1[j - 1]  # j theta_j
            dps = Q[j - 1]  # j psi_j
            s_ += dth * C[i]
            c_ += dth * S[i]
            sp += dps * CP[i]
            cp += dps * SP[i]
            t_ += C[j] * T[i]
            q_ += C[j] * Q[i]
            pw += T[j] * w3[i]
            m1 += w2[j] * w3[i]
            m2 += w3[j] * w3[i]
            pl += T[j] * L[i]
            d2 += G[j] * w1[i]
            d3 += H[j] * w1[i]
            vy += w1[j] * ZP[i]
            dx += VX[j] * CP[i] - VY[j] * SP[i]
            dy += VX[j] * SP[i] + VY[j] * CP[i]
        if k == 0:
            S[0] = math.sin(y[3])
            C[0] = math.cos(y[3])
            SP[0] = math.sin(y[2])
            CP[0] = math.cos(y[2])
            T[0] = S[0] / C[0]
            Q[0] = w3[0] / C[0]
            PW3[0] = T[0] * w3[0]
            m1 = w2[0] * w3[0]
            m2 = w3[0] * w3[0]
        else:
            # s' = c theta', c' = -s theta' (and of psi); tan theta = s/c, psi' = omega3/c
            dth = w1[k - 1]
            dps = Q[k - 1]
            S[k] = (s_ + dth * C[0]) / k
            C[k] = -(c_ + dth * S[0]) / k
            SP[k] = (sp + dps * CP[0]) / k
            CP[k] = -(cp + dps * SP[0]) / k
            T[k] = (S[k] - t_ - C[k] * T[0]) / C[0]
            Q[k] = (w3[k] - q_ - C[k] * Q[0]) / C[0]
            PW3[k] = pw + T[0] * w3[k] + T[k] * w3[0]
            m1 += w2[0] * w3[k] + w2[k] * w3[0]
            m2 += 2.0 * w3[0] * w3[k]
        L[k] = 12.0 * ht * m1 - cl * m2
        G[k] = 4.0 * ht * w2[k] + g2 * w3[k]
        H[k] = -6.0 * e2 * w2[k] + 4.0 * ht * e2 * w3[k] + PW3[k]
        VX[k] = w2[k] - ht * w3[k]  # eqs. (1), (37): v_Cx = omega2 - h~ omega3
        yp = S[k] - ht * C[k]  # eq. (4)
        ZP[k] = -(C[k] + ht * S[k])
        if k == 0:
            pl = T[0] * L[0]
            d2 = G[0] * w1[0]
            d3 = H[0] * w1[0]
            VY[0] = w1[0] * ZP[0]  # v_Cy = omega1 z_P
            dx = VX[0] * CP[0] - VY[0] * SP[0]
            dy = VX[0] * SP[0] + VY[0] * CP[0]
        else:
            pl += T[0] * L[k] + T[k] * L[0]
            d2 += G[0] * w1[k] + G[k] * w1[0]
            d3 += H[0] * w1[k] + H[k] * w1[0]
            VY[k] = vy + w1[0] * ZP[k] + w1[k] * ZP[0]
            dx += (VX[0] * CP[k] - VY[0] * SP[k]) + (VX[k] * CP[0] - VY[k] * SP[0])
            dy += (VX[0] * SP[k] + VY[0] * CP[k]) + (VX[k] * SP[0] + VY[k] * CP[0])
        kk = 1.0 / (k + 1)
        J[3, k + 1] = w1[k] * kk  # eq. (2)
        J[2, k + 1] = Q[k] * kk
        J[4, k + 1] = (w2[k] - PW3[k]) * kk
        # eq. (38)
        J[5, k + 1] = (18.0 * m1 + pl - 12.0 * ht * m2 + 12.0 * yp) * e1 * kk
        J[6, k + 1] = -d2 * e2 * kk
        J[7, k + 1] = d3 * kk
        J[0, k + 1] = dx * kk
        J[1, k + 1] = dy * kk


def _tay_quadratures_smooth(J, A, P):
    """The rows ``X_C, Y_C, V_X, V_Y, psi, phi`` of the full smooth jet from its reduced
    rows (:func:`_tay_rows_smooth`; cos theta and tan(theta) omega3 in ``A[1]``, ``A[3]``):
    eq. (2), and eq. (8) with ``F_x = F_y = 0`` (V constant).  ``A[13]``: psi'."""
    C, PW3, Q = A[1], A[3], A[13]
    w2 = J[8]
    w3 = J[9]
    for k in range(P):
        b = w3[k]  # psi' = omega3/c (eq. 2)
        for j in range(1, k + 1):
            b -= C[j] * Q[k - j]
        Q[k] = b / C[0]
        kk = 1.0 / (k + 1)
        J[4, k + 1] = Q[k] * kk
        J[6, k + 1] = (w2[k] - PW3[k]) * kk
        J[0, k + 1] = J[2, k] * kk  # X_C' = V_X, V' = 0
        J[1, k + 1] = J[3, k] * kk
        J[2, k + 1] = 0.0
        J[3, k + 1] = 0.0


def _tay_jet(rough, h, y, J, A, P):
    """Fill ``J[:, 0..P]`` with the Taylor coefficients of the solution through the full
    state ``y`` (layout of :mod:`rollingdisk.model.equations`); ``A`` (at least 19 rows) holds
    the auxiliary series.

    Rough ground: :func:`_tay_jet_rough`, the reduced rows and the quadratures in one fused
    loop (rather than the reduced jet :func:`_tay_rows_rough` followed by a separate
    quadrature pass).  Smooth ground: the
    reduced rows (:func:`_tay_rows_smooth`), then the quadratures from them."""
    if rough:
        _tay_jet_rough(h, y, J, A, P)
        return
    for i in range(y.shape[0]):
        J[i, 0] = y[i]
    _tay_rows_smooth(h, J[5], J[7], J[8], J[9], A, P)
    _tay_quadratures_smooth(J, A, P)


def _energy_sc(rough, ht, k1, k2, s, c, y):
    """E of the reduced state ``y`` with ``sin theta = s``, ``cos theta = c`` given (eqs. 13,
    37, 7; a = 1); on smooth ground the part of E that does not contain the constant
    V_X, V_Y (conserved by itself)."""
    w1, w2, w3 = y[1], y[2], y[3]
    y_P = s - ht * c  # eq. (4)
    z_P = -(c + ht * s)
    v_Cz = -w1 * y_P  # eq. (7)
    if rough:
        v_Cx = w2 - ht * w3  # eq. (37)
        v_Cy = w1 * z_P
        kin = 0.5 * (v_Cx * v_Cx + v_Cy * v_Cy + v_Cz * v_Cz)
    else:
        kin = 0.5 * v_Cz * v_Cz
    return kin + 0.5 * k1 * (w1 * w1 + w3 * w3) + 0.5 * k2 * w2 * w2 - z_P


def _tay_normal(h, J, A, P, N):
    """``N[0..P-1]``: the series of the normal force ``F_z = 1 + z_P omega1^2 - y_P
    d omega1/dt`` (eq. 11) along the step, from the jet of :func:`_tay_jet4_rough` or
    :func:`_tay_jet4_smooth` (both keep the series of sin and cos theta in ``A[0]``,
    ``A[1]``, to order P - 1); ``A[11..13]`` are work rows (the reduced jets use rows
    0..10).  The lift-off guard as a polynomial: sampled and located inside a step at the
    cost of a Horner sum."""
    ht = _signed_h(h, J[0, 0])
    S, C = A[0], A[1]
    YP, ZP, W = A[11], A[12], A[13]
    w1 = J[1]
    for k in range(P):
        YP[k] = S[k] - ht * C[k]  # eq. (4)
        ZP[k] = -(C[k] + ht * S[k])
        ww = 0.0
        for j in range(k + 1):
            ww += w1[j] * w1[k - j]
        W[k] = ww
        a = 1.0 if k == 0 else 0.0
        for j in range(k + 1):
            a += ZP[j] * W[k - j] - YP[j] * (k - j + 1) * w1[k - j + 1]
        N[k] = a


def _tay_sample(h, J, A, P, x, v):
    """``v = (theta, omega1, omega2, omega3, F_z)`` at ``x`` into the step of the reduced jet
    ``J`` (:func:`_tay_jet4_rough` / :func:`_tay_jet4_smooth`).

    Seven Horner sums in one loop (the four components, the series of sin and cos theta
    in ``A[0]``, ``A[1]`` and of d omega1/dt), F_z from them by eq. (11): ``1 + z_P omega1^2
    - y_P d omega1/dt``.  The sines come from their series (to order P - 1), not from
    ``sin(theta(x))``: no transcendental call per sample."""
    ht = _signed_h(h, J[0, 0])
    th = J[0, P]
    w1 = J[1, P]
    w2 = J[2, P]
    w3 = J[3, P]
    s = A[0, P - 1]
    c = A[1, P - 1]
    d1 = P * J[1, P]
    for k in range(P - 1, -1, -1):
        th = th * x + J[0, k]
        w1 = w1 * x + J[1, k]
        w2 = w2 * x + J[2, k]
        w3 = w3 * x + J[3, k]
        if k > 0:
            s = s * x + A[0, k - 1]
            c = c * x + A[1, k - 1]
            d1 = d1 * x + k * J[1, k]
    y_P = s - ht * c  # eq. (4)
    z_P = -(c + ht * s)
    v[0] = th
    v[1] = w1
    v[2] = w2
    v[3] = w3
    v[4] = 1.0 + z_P * w1 * w1 - y_P * d1  # eq. (11)


def _tay_poly(c, deg, x):
    """``sum_k c[k] x^k`` for k = 0..deg (Horner)."""
    v = c[deg]
    for k in range(deg - 1, -1, -1):
        v = v * x + c[k]
    return v


def _tay_poly_d(c, deg, x):
    """``(p(x), p'(x), e)`` of ``p = sum_k c[k] x^k``, k = 0..deg, by Horner's rule, with
    ``e = sum_k |c[k]| |x|^k``: the rounding error of the sum is at most about
    ``2 deg u e`` (u = 2^-53; Higham, Accuracy and Stability, sec. 5.1)."""
    p = c[deg]
    d = 0.0
    e = abs(p)
    ax = abs(x)
    for k in range(deg - 1, -1, -1):
        d = d * x + p
        p = p * x + c[k]
        e = e * ax + abs(c[k])
    return p, d, e


def _tay_poly_root(c, deg, sg, off, xa, xb, fa, fb):
    """Root in (xa, xb] of ``f(x) = sg * poly(c)(x) - off`` with ``f(xa)``, ``f(xb)`` of
    opposite signs (or ``f(xb) = 0``); returns the last admissible point found (``f`` of
    the sign of ``fa``, nonzero) within round-off of the root.

    Newton's method kept in the bracket: on a polynomial the derivative comes with the
    Horner sum, every evaluation narrows the bracket ``[xa, xb]``, and a step that leaves
    it bisects.  It stops where ``|f|`` is below the rounding error of its own Horner sum
    (:func:`_tay_poly_d`): closer than that the sign of ``f`` is noise, and near a slow
    crossing that band is far wider than the spacing of doubles.  If that last point is
    past the root, it steps back toward ``xa`` by doubling distances to the first
    admissible point.  From the secant point it needs a few evaluations, where the
    Illinois rule (:mod:`rollingdisk.engine.roots`, which narrows the bracket to the
    spacing of doubles) needs several times as many on the sweeps' theta crossings."""
    x = _illinois_trial(xa, xb, fa, fb)
    for _ in range(ILLINOIS_MAXITER):
        if _illinois_converged(xa, xb):
            break
        p, dp, e = _tay_poly_d(c, deg, x)
        fx = sg * p - off
        ok = (fx > 0.0) == (fa > 0.0) and fx != 0.0
        if ok:
            xa = x
        else:
            xb = x
        if abs(fx) <= 2.3e-16 * (2.0 * deg * e + abs(off)):
            if not ok:
                step = 2e-16 * max(1.0, abs(x))
                for _ in range(ILLINOIS_MAXITER):
                    xc = x - step
                    if xc <= xa:
                        break
                    fc = sg * _tay_poly(c, deg, xc) - off
                    if (fc > 0.0) == (fa > 0.0) and fc != 0.0:
                        xa = xc
                        break
                    step *= 2.0
            break
        xn = x - fx / (sg * dp)
        if not (xa < xn < xb):
            xn = 0.5 * (xa + xb)
        x = xn
    return xa


def _tay_eval(J, P, dt, out):
    """out = the Taylor polynomial of every component at ``dt`` (Horner, the components
    interleaved: independent chains rather than one long dependent one at a time)."""
    n = J.shape[0]
    for i in range(n):
        out[i] = J[i, P]
    for k in range(P - 1, -1, -1):
        for i in range(n):
            out[i] = out[i] * dt + J[i, k]


def _tay_eval_reduced(rough, J, P, dt, r):
    """r = ``(theta, omega1, omega2, omega3)`` of the Taylor polynomial at ``dt`` (Horner):
    all the guards need (:func:`rollingdisk.model.state._reduced_state` takes a 4-vector)."""
    i0 = 3 if rough else 5
    r[0] = J[i0, P]
    for i in range(1, 4):
        r[i] = J[i0 + 1 + i, P]
    for k in range(P - 1, -1, -1):
        r[0] = r[0] * dt + J[i0, k]
        for i in range(1, 4):
            r[i] = r[i] * dt + J[i0 + 1 + i, k]


def _tay_step_size(J, P, atolv, rtol):
    """Jorba & Zou's step size, as heyoka: ``rho / e^2 exp(-0.7/(P-1))`` with ``rho =
    min((s/||x^[P-1]||)^(1/(P-1)), (s/||x^[P]||)^(1/P))``, the norms (max) over the
    controlled components (finite ``atolv``); ``s = 1`` under absolute control (``rtol
    ||x|| <= min atol``), else ``||x||`` (the tolerance enters through the order P)."""
    xm = 0.0
    am = 0.0
    bm = 0.0
    at = np.inf
    for i in range(J.shape[0]):
        if math.isfinite(atolv[i]):
            xm = max(xm, abs(J[i, 0]))
            am = max(am, abs(J[i, P - 1]))
            bm = max(bm, abs(J[i, P]))
            at = min(at, atolv[i])
    scale = where(rtol * xm <= at, 1.0, xm)
    # in logarithms: two logs and one exp instead of two powers and an exp
    la = where(am > 0.0, math.log(scale / am) / (P - 1), np.inf)
    lb = where(bm > 0.0, math.log(scale / bm) / P, np.inf)
    return math.exp(min(la, lb) - 2.0 - 0.7 / (P - 1))
