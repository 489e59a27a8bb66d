"""Along an orbit of the exact motion: the normal force (eq. 11) as a function of
``theta``; a bounded orbit as Fourier series in ``u`` (``theta = m + d sin u``): time,
``psi``, ``phi`` and the centre's path integrated term by term, and the state at any time;
and a steady motion's state at any time in closed form (eqs. 15, 25).
"""

from __future__ import annotations

import math

import numpy as np

from rollingdisk.model.geometry import contact_geometry
from rollingdisk.model.state import state_index, state_names
from rollingdisk.theory.exact.quadrature import _EPS, _Budget, _BudgetSpent, _theta_coefficients

_CHUNK = 1 << 18  # complex numbers per block of a Fourier sum (4 MiB)


def _orbit_normal_force(rough, h, theta, w2, w3, q):
    a1, c1, _, _ = _theta_coefficients(rough, h, theta, w2, w3)
    y_P, z_P = contact_geometry(h, theta)[4:6]
    return 1.0 + z_P * q - y_P * (a1 + c1 * q)  # eq. (11)


class _Orbit:
    """The bounded motion as a function of ``u``: ``theta = m + d sin u``,
    ``dt/du = 1/sqrt(H)``; everything periodic in ``u`` except the secular parts of
    ``t``, ``psi``, ``phi`` and the rotation of the centre's path."""

    def __init__(self, fit, rough, h, y0, ground, budget: _Budget):
        self.fit, self.rough, self.h, self.ground = fit, rough, h, ground
        iy = {n: state_index(ground, n) for n in ("theta", "omega1", "psi", "phi")}
        theta0, w10 = y0[iy["theta"]], y0[iy["omega1"]]
        x0 = min(1.0, max(-1.0, fit.x(theta0)))
        u0 = math.asin(x0)
        if w10 < 0.0 or (w10 == 0.0 and x0 > 0.0):
            u0 = math.pi - u0
        self.u0 = u0
        self.psi0, self.phi0 = float(y0[iy["psi"]]), float(y0[iy["phi"]])
        self.Z0 = complex(y0[0], y0[1])
        self.V = complex(y0[2], y0[3]) if not rough else 0j
        self.y_layout = iy
        M = 64
        prev = None
        while True:
            budget.clock(f"the Fourier series (length {M})")
            res, floors = self._series(M)
            if prev is not None and self._tail_small(floors) and all(
                    abs(r - p) <= 2.0 * math.pi * 2.0 * (f + g)
                    for r, p, f, g in zip(res, prev[0], floors, prev[1])):
                break
            if 2 * M > budget.max_terms:
                raise _BudgetSpent(
                    f"the Fourier series in u did not reach its rounding floor with "
                    f"max_terms = {budget.max_terms} terms (the orbit passes close to an "
                    f"unstable steady motion: a near-separatrix)")
            prev, M = (res, floors), 2 * M
        self.T, self.dpsi, self.dphi = res

    # per-u quantities --------------------------------------------------------------
    def _local(self, u):
        fit = self.fit
        x = np.sin(u)
        theta = fit.m + fit.d * x
        w2, w3, _ = fit.functions(theta)
        H = fit.H(x)
        F = 1.0 / np.sqrt(H)  # dt/du
        w1 = fit.d * np.cos(u) * np.sqrt(H)  # d theta/dt
        c = np.cos(theta)
        return theta, w1, w2, w3, F, w3 / c, w2 - w3 * np.tan(theta)  # eqs. (2)

    def _series(self, M):
        """Fourier coefficients of ``dt/du``, ``dpsi/du``, ``dphi/du`` (and on rough ground
        of the centre's velocity) from ``M`` samples: O(M) memory (FFTs only).

        Returns ``((T, dpsi, dphi), floors)``: the floors are the rounding noise of each
        series' coefficients, propagated from the evaluation errors of the samples (the
        Chebyshev sums, ``1/sqrt(H)`` steep where ``H`` is small) plus the FFT's own."""
        u = 2.0 * np.pi * np.arange(M) / M
        theta, w1, w2, w3, F, Om, ph = self._local(u)
        n = np.fft.fftfreq(M, 1.0 / M)
        self.n = n
        fit = self.fit
        dH = 8.0 * _EPS * float(np.sum(np.abs(fit.cH)))
        d2 = 8.0 * _EPS * float(np.sum(np.abs(fit.c2)))
        d3 = 8.0 * _EPS * float(np.sum(np.abs(fit.c3)))
        c = np.abs(np.cos(theta))
        dF = 0.5 * F ** 3 * dH + _EPS * F
        dOm = d3 / c + _EPS * np.abs(Om)
        dph = d2 + d3 * np.abs(np.tan(theta)) + _EPS * np.abs(ph)
        samples = (F, Om * F, ph * F)
        errors = (dF, np.abs(Om) * dF + dOm * F, np.abs(ph) * dF + dph * F)
        coefs, floors = [], []
        for f, df in zip(samples, errors):
            cf = np.fft.fft(f) / M
            coefs.append(cf)
            floors.append(max(256.0 * _EPS * float(np.max(np.abs(cf))),
                              4.0 * float(np.mean(df))
                              + 8.0 * _EPS * math.log2(M) * float(np.sqrt(np.mean(f * f)))))
        self.cF, self.cOm, self.cph = coefs
        self.floors = floors
        T = 2.0 * np.pi * self.cF[0].real
        dpsi = 2.0 * np.pi * self.cOm[0].real
        dphi = 2.0 * np.pi * self.cph[0].real
        self.kappa = dpsi / (2.0 * np.pi)
        if self.rough:
            ht, s, cc, p, y_P, z_P = contact_geometry(self.h, theta)
            w = (w2 - ht * w3) * F + 1j * (w1 * z_P) * F  # (v_Cx + i v_Cy) dt/du, eq. (37)
            psi_per = self._periodic_on_grid(self.cOm)
            self.cG = np.fft.fft(w * np.exp(1j * psi_per)) / M
        self.M = M
        return (T, dpsi, dphi), floors

    def _tail_small(self, floors):
        """The coefficients beyond ``M/4`` are at their rounding floor (all three)."""
        k = np.abs(self.n) > self.M // 4
        return all(float(np.max(np.abs(c[k]))) <= f
                   for c, f in zip((self.cF, self.cOm, self.cph), floors))

    def _periodic_on_grid(self, c):
        """The zero-mean antiderivative of the Fourier series ``c`` at the ``M`` grid
        points ``u_j = 2 pi j / M``: one inverse FFT."""
        n = self.n
        nz = n != 0
        b = np.zeros_like(c)
        b[nz] = c[nz] / (1j * n[nz])
        return (np.fft.ifft(b) * n.size).real

    def _periodic(self, c, u):
        """The zero-mean antiderivative of the Fourier series ``c`` at any ``u``: a direct
        sum, in blocks of at most ``_CHUNK`` terms (bounded memory)."""
        n = self.n
        nz = n != 0
        b, k = c[nz] / (1j * n[nz]), n[nz]
        u = np.atleast_1d(np.asarray(u, float))
        out = np.empty(u.size)
        step = max(1, _CHUNK // max(1, k.size))
        for i in range(0, u.size, step):
            out[i:i + step] = (np.exp(1j * np.outer(u[i:i + step], k)) @ b).real
        return out

    def _t(self, u):
        return self.cF[0].real * (u - self.u0) + self._periodic(self.cF, u) \
            - self._periodic(self.cF, self.u0)

    def _u_of_t(self, t):
        t = np.atleast_1d(np.asarray(t, float))
        u = self.u0 + 2.0 * np.pi * t / self.T
        for _ in range(50):
            F = self._local(u)[4]
            du = (t - self._t(u)) / F
            u = u + du
            if np.max(np.abs(du)) <= 1e-15 * max(1.0, float(np.max(np.abs(u)))):
                break
        return u

    def _psi(self, u):
        return self.psi0 + self.cOm[0].real * (u - self.u0) + self._periodic(self.cOm, u) \
            - self._periodic(self.cOm, self.u0)

    def _phi(self, u):
        return self.phi0 + self.cph[0].real * (u - self.u0) + self._periodic(self.cph, u) \
            - self._periodic(self.cph, self.u0)

    def _Z(self, u, t):
        """Centre C as ``X_C + i Y_C`` (blocks of at most ``_CHUNK`` terms)."""
        if not self.rough:
            return self.Z0 + self.V * t  # smooth ground: V constant (eq. 8, F_x = F_y = 0)
        n, cG, kap = self.n, self.cG, self.kappa
        # psi(u) = psi_c + kappa u + psi_per(u), psi_c fixed by psi(u0) = psi0
        psi_c = self.psi0 - kap * self.u0 - self._periodic(self.cOm, self.u0)[0]
        k = n + kap
        res = np.abs(k) < 1e-12
        u = np.atleast_1d(u)
        ks = np.where(res, 1.0, k)
        E0 = np.exp(1j * ks * self.u0)
        coef = cG / (1j * ks)
        total = np.empty(u.size, complex)
        step = max(1, _CHUNK // max(1, ks.size))
        for i in range(0, u.size, step):
            uu = u[i:i + step]
            terms = (np.exp(1j * np.outer(uu, ks)) - E0) * coef
            terms = np.where(res, np.outer(uu - self.u0, cG), terms)
            total[i:i + step] = terms.sum(axis=1)
        return self.Z0 + np.exp(1j * psi_c) * total

    def state(self, t):
        scalar = np.ndim(t) == 0
        t = np.atleast_1d(np.asarray(t, float))
        out = np.empty((t.size, 8 if self.rough else 10))
        for i0 in range(0, t.size, 2048):
            tt = t[i0:i0 + 2048]
            u = self._u_of_t(tt)
            theta, w1, w2, w3 = self._local(u)[:4]
            Z = self._Z(u, tt)
            cols = {"X_C": Z.real, "Y_C": Z.imag, "psi": self._psi(u), "theta": theta,
                    "phi": self._phi(u), "omega1": w1, "omega2": w2, "omega3": w3}
            if not self.rough:
                cols["V_X"] = np.full(tt.size, self.V.real)
                cols["V_Y"] = np.full(tt.size, self.V.imag)
            for j, name in enumerate(state_names(self.ground)):
                out[i0:i0 + 2048, j] = cols[name]
        return out[0] if scalar else out


class _SteadyOrbit:
    """A steady motion: the state at any time in closed form (eqs. 15, 25)."""

    def __init__(self, rough, h, y0, ground):
        self.rough, self.ground, self.y0 = rough, ground, np.array(y0, float)
        it = state_index(ground, "theta")
        theta0, w2, w3 = y0[it], y0[it + 3], y0[it + 4]
        self.Omega, self.omega = w3 / math.cos(theta0), w2 - w3 * math.tan(theta0)
        if rough:
            ht, s, c, p, y_P, z_P = contact_geometry(h, theta0)
            self.v = complex(w2 - ht * w3, 0.0)  # eq. (37) with omega1 = 0
        self.fit = None

    def state(self, t):
        scalar = np.ndim(t) == 0
        t = np.atleast_1d(np.asarray(t, float))
        y = np.tile(self.y0, (t.size, 1))
        ip = state_index(self.ground, "psi")
        psi = self.y0[ip] + self.Omega * t
        y[:, ip] = psi
        y[:, ip + 2] = self.y0[ip + 2] + self.omega * t
        if self.rough:
            Z0 = complex(self.y0[0], self.y0[1])
            if abs(self.Omega) > 0.0:
                Z = Z0 + self.v * (np.exp(1j * psi) - np.exp(1j * self.y0[ip])) \
                    / (1j * self.Omega)
            else:
                Z = Z0 + self.v * np.exp(1j * self.y0[ip]) * t
        else:
            Z = complex(self.y0[0], self.y0[1]) + complex(self.y0[2], self.y0[3]) * t
        y[:, 0], y[:, 1] = Z.real, Z.imag
        return y[0] if scalar else y
