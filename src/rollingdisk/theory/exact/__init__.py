"""Exact motions by quadrature: the integrable disk at finite amplitude.

On both ideal grounds the reduced system (theta, omega1, omega2, omega3) of eq. (38)
(rough) or (49) (smooth) has ``d omega2/dt`` and ``d omega3/dt`` proportional to
``omega1 = d theta/dt``, and ``d omega1/dt`` affine in ``omega1^2``.  Along a motion
``omega2``, ``omega3`` and ``q = omega1^2`` are therefore functions of ``theta`` alone,
solving the *linear* system (``' = d/d theta``)::

    omega2' = D2(theta, omega2, omega3),   omega3' = D3(theta, omega2, omega3),
    q'      = 2 D1(theta, q, omega2, omega3),

where ``D2, D3`` are eq. (38)/(49)'s ``d omega2/dt, d omega3/dt`` at ``omega1 = 1`` and
``D1 = d omega1/dt`` (rough: ``D1`` is free of ``omega1``; smooth: affine in ``q``).  The
coefficients are taken from the very kernels of :mod:`rollingdisk.model.equations` (checked
against the sympy derivation); that they are proportional to ``omega1`` is checked against
the derivation by ``tests/test_exact.py``.  Integrating ``q`` rather than taking it from
the energy integral (13) avoids the cancellation of two O(1) energies at small amplitude;
eq. (13) is then an independent check.

How the quadratures are done
----------------------------
1. The linear system is integrated in ``theta`` from ``theta(0)`` both ways (scipy's DOP853,
   ``rtol = 1e-13``) to the first zero of ``q`` (a turning point, located on the dense
   output), to ``theta = 0`` (h > 0: the other rim edge touches) or to ``|theta| = pi/2``.
2. On the range ``[a, b]`` so found, ``omega2, omega3, q`` are Chebyshev series in
   ``x = (theta - m)/d`` (``m, d`` the midpoint and half-width), to the noise floor, and
   ``q = d^2 (1 + x)(1 - x) H(x)`` is divided exactly by its simple zeros at the turning
   points (Chebyshev division), leaving a smooth positive ``H``.
3. The substitution ``x = sin u`` (both ends turning) turns ``dt = d theta / omega1`` into
   ``dt = du / sqrt(H(sin u))``: no singularity at the turning points, and over a period
   (``u`` from 0 to 2 pi) the integrand is periodic and analytic, so the trapezoidal rule
   (an FFT) converges exponentially.  ``t(u)``, ``psi(u)``, ``phi(u)`` and the centre's
   path ``X_C + i Y_C`` (rough ground: ``dZ_C/du = e^{i psi} (v_Cx + i v_Cy) dt/du``,
   eqs. 1 and 37) are then Fourier series integrated term by term (FFTs and blocked
   sums: memory O(M); M doubles until the tail is at its rounding floor, at most
   ``max_terms``; ``docs/exact.md``, "Edges").  An orbit that ends
   is timed leg by leg with Gauss-Legendre after ``x = -cos w`` / ``x = cos w`` at its
   one turning point.

What ends a motion
------------------
``"bounded"`` (both ends are turning points and ``F_z > 0`` over ``[a, b]``), or the first
along the motion of: ``"lift-off"`` (``F_z`` of eq. 11, a function of ``theta`` on the
orbit, reaches 0), ``"edge-contact"`` (h > 0, ``theta`` reaches 0), ``"fell-flat"``
(``|theta|`` reaches pi/2) -- the guards of :mod:`rollingdisk.model.events`, with the time and
``theta`` where it happens.  A state exactly on a steady motion is ``"steady"``.  A
quadrature that spends its work budget (``time_limit``, ``max_evals``, ``max_terms``)
first is ``"not-converged"``, with a ``message``.

For ``h = 0`` on rough ground ``omega3(theta)`` is a Legendre-type function: see
:func:`thin_disk_omega3` and ``docs/exact.md``.

Where each part lives
---------------------
``quadrature`` the linear system in theta, its sweeps and the work budget; ``chebyshev``
the fit on ``[a, b]`` and the time along a leg; ``orbit`` the normal force along an orbit
and a bounded (or steady) orbit at any time; ``solve`` :func:`exact_motion` and
:func:`exact_steady`; ``result`` :class:`ExactMotion`; ``backbone_curve`` :func:`backbone`;
``thin_disk`` :func:`thin_disk_omega3`; ``inputs`` the checks of the public boundary.
"""

from rollingdisk.util.lazy import attach as _attach

__getattr__, __dir__, __all__ = _attach(__name__, {
    "ExactMotion": "rollingdisk.theory.exact.result",
    "exact_motion": "rollingdisk.theory.exact.solve",
    "exact_steady": "rollingdisk.theory.exact.solve",
    "Backbone": "rollingdisk.theory.exact.backbone_curve",
    "backbone": "rollingdisk.theory.exact.backbone_curve",
    "thin_disk_omega3": "rollingdisk.theory.exact.thin_disk",
    "EXACT_STATUSES": "rollingdisk.theory.exact.result",
    "NOT_CONVERGED_STATUS": "rollingdisk.theory.exact.result",
    "TIME_LIMIT": "rollingdisk.theory.exact.quadrature",
    "MAX_EVALS": "rollingdisk.theory.exact.quadrature",
    "MAX_TERMS": "rollingdisk.theory.exact.quadrature",
    "THIN_DISK_MAX_POINTS": "rollingdisk.theory.exact.thin_disk",
})
