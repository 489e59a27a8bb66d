"""The air film under Euler's disk, derived from lubrication theory.

Outside the numeric core (sympy; scipy for the one quadrature).  Each step is a function
that returns its sympy result, so the tests can substitute back:

1. :func:`film_profile` - the velocity across a thin gap of height ``h`` (walls at rest and
   at speed ``U``), its flux and its dissipation per unit area: Poiseuille part
   ``h^3 |grad p|^2 / (12 mu)`` plus Couette part ``mu U^2 / h``, no cross term.
2. :func:`disk_kinematics` - the disk rolling in place near flat: ``Omega^2 sin(alpha) =
   4 g/a`` (thin disk, exact), ``E = (3/2) M g a sin(alpha)``; the thick disk's
   ``Omega^2 alpha -> 12/(3 + 4 h^2) g/a`` and ``E - E_flat ~ e1 M g a alpha``; and the speed
   of the disk's lower face, ``O(a Omega alpha^2)``: the walls are (to leading order) at
   rest, the film is a *squeeze* film.  ``Omega = d psi/dt`` (the library's convention,
   eqs. 2-3) is the precession rate of the contact point.
3. :func:`reynolds_problem` - the gap ``h = alpha (a + r cos(phi - Omega t))`` (polar
   coordinates about the projection of the centre; zero at the contact point ``r = a,
   phi = Omega t + pi``), ``dh/dt = alpha Omega Y`` in the co-rotating frame, and the
   Reynolds equation ``div(h^3 grad p) = 12 mu dh/dt`` made dimensionless:
   ``div(x^3 grad P) = y`` on the disk ``x^2 + y^2 < 2 x`` (``x = 1 + X``, the distance
   from the tangent at the contact point), ``P = 0`` on the rim, ``p = 12 mu Omega P /
   alpha^2``.
4. :func:`reynolds_solution` - its solution: ``P = -y/x + q`` with ``q`` harmonic in R^5
   (``div(x^3 grad .) = x^3 Delta_5`` for functions of the 4-D radius ``x`` and ``y``),
   found by the Kelvin inversion that maps the disk onto the exterior of a cylinder,
   ``x' > 1/2``, and a Fourier sine transform along it::

       q*(r, z) = 2/(pi r) int_0^inf k K0(k/2) K1(k r) / K1(k/2) sin(k z) dk,
       q(x, y) = R'^3 q*(x/R^2, y/R^2),  R' = 1/R, R^2 = x^2 + y^2.

   It is the solution of least singularity at the contact point (``P ~ 2/y`` along the
   rim, a finite dissipation); any other adds a homogeneous solution with infinite
   dissipation.
5. :func:`film_constant` - the dissipation ``Phi = int h^3 |grad p|^2/(12 mu) dA = K mu a^3
   Omega^2 / alpha``, ``K = 12 I``, ``I = -int P y dA = pi/3 - J`` with ``J`` one double
   quadrature (Bessel functions): **K = 1.28113** (no logarithmic divergence at the
   contact line).  Moffatt's estimate (gap ``h``, shear speed ``a Omega`` everywhere) is
   ``2 pi`` exactly (:func:`moffatt_shear_constant`), 4.90 times larger.
6. :func:`decay_law` - the energy balance ``dE/dt = -Phi`` with ``E`` and ``Omega`` of rolling
   near flat: ``alpha^3 = 3 K w mu a (t0 - t) / (e1 M)``, ``t0 = e1 alpha0^3 M / (3 K w mu a)``
   (thin disk ``t0 = alpha0^3 M / (8 K mu a)``); exponents ``alpha ~ (t0 - t)^(1/3)``,
   ``Omega ~ (t0 - t)^(-1/6)``; for any power law ``Phi ~ Omega^m alpha^-j`` the exponents
   are ``p = 1/(1 + m/2 + j)``, ``q = -p/2`` (Bildsten's boundary layer: ``m = 5/2, j = 0``,
   ``p = 4/9``, ``q = -2/9``).

See ``docs/errata-models.md`` for the verdict on Moffatt's quoted spin time.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache

import sympy as sp

__all__ = ["film_profile", "disk_kinematics", "reynolds_problem", "reynolds_solution",
           "pressure", "film_constant", "moffatt_shear_constant", "decay_law",
           "boundary_layer_law", "FilmProfile", "DiskKinematics", "ReynoldsProblem",
           "ReynoldsSolution", "DecayLaw", "BoundaryLayerLaw"]

# symbols shared by the steps
z, h, mu, U, G = sp.symbols("z h mu U G", real=True)  # G = dp/dx (one gradient component)
alpha, Omega, a, g, M, t = sp.symbols("alpha Omega a g M t", positive=True)
r, phi = sp.symbols("r phi", real=True)
x, y = sp.symbols("x y", real=True)
k = sp.Symbol("k", positive=True)


# ------------------------------------------------------------------ 1. the film
@dataclass(frozen=True)
class FilmProfile:
    """Thin-gap flow between ``z = 0`` (at rest) and ``z = h`` (speed ``U``), pressure
    gradient ``G`` along the flow: ``u(z)``, the flux ``q`` and the dissipation per area."""

    u: sp.Expr
    flux: sp.Expr
    dissipation: sp.Expr
    poiseuille: sp.Expr
    couette: sp.Expr


def film_profile() -> FilmProfile:
    """Solve ``mu u'' = G`` with ``u(0) = 0``, ``u(h) = U`` (lubrication, Stokes flow in a
    gap thin compared with its length); return the flux ``int_0^h u dz = -h^3 G/(12 mu)
    + U h/2`` and the dissipation ``int_0^h mu u'^2 dz = h^3 G^2/(12 mu) + mu U^2/h``."""
    c1, c2 = sp.symbols("c1 c2")
    u = G * z**2 / (2 * mu) + c1 * z + c2
    sol = sp.solve([u.subs(z, 0), u.subs(z, h) - U], [c1, c2], dict=True)[0]
    u = sp.simplify(u.subs(sol))
    flux = sp.simplify(sp.integrate(u, (z, 0, h)))
    diss = sp.simplify(sp.integrate(mu * sp.diff(u, z) ** 2, (z, 0, h)))
    pois = sp.simplify(diss.subs(U, 0))
    couette = sp.simplify(diss.subs(G, 0))
    return FilmProfile(u, flux, diss, pois, couette)


# ------------------------------------------------------------------ 2. the disk
@dataclass(frozen=True)
class DiskKinematics:
    """Rolling in place near flat (centre and contact point at rest).

    ``Omega2_thin``: ``Omega^2`` of the thin disk (exact in ``alpha``); ``E_thin``: its
    energy above the table; ``Omega2_alpha_thick``: ``lim Omega^2 alpha`` for half-thickness
    ``hh`` (units of ``a``, ``g/a``); ``e1_thick``: ``dE/dalpha`` at ``alpha = 0`` (units
    ``M g a``); ``wall_speed``: the largest horizontal speed of the disk's lower face,
    leading order in ``alpha``."""

    Omega2_thin: sp.Expr
    E_thin: sp.Expr
    Omega2_alpha_thick: sp.Expr
    e1_thick: sp.Expr
    wall_speed: sp.Expr


def _rolling_in_place(hh):
    """Newton-Euler for the disk rolling in place, tilt ``alpha`` (units m = a = g = 1).

    Frame at the instant: contact P on the -y side, axis ``n = (0, -sin a, cos a)``,
    in-plane direction to the rim ``d = (0, -cos a, -sin a)``.  C and P at rest, so
    ``omega`` is along ``CP = d - hh n``; the axis precesses, ``dn/dt = Omega z x n =
    omega x n``, which fixes ``|omega|``.  Steady: ``dL/dt = Omega z x L = CP x (0, 0, 1)``
    (C at rest: the contact force is the weight).  Returns ``(Omega^2, E)``."""
    s, c = sp.sin(alpha), sp.cos(alpha)
    n = sp.Matrix([0, -s, c])
    d = sp.Matrix([0, -c, -s])
    ex = sp.Matrix([1, 0, 0])
    ez = sp.Matrix([0, 0, 1])
    CP = d - hh * n
    lam = sp.Symbol("lam")
    w = lam * CP
    lam_s = sp.solve(sp.simplify((w.cross(n) - Omega * ez.cross(n))[0]), lam)[0]
    w = w.subs(lam, lam_s)
    k1, k2 = sp.Rational(1, 4) + hh**2 / 3, sp.Rational(1, 2)  # eq. (10), units a^2
    L = k1 * (w.dot(d) * d + w.dot(ex) * ex) + k2 * w.dot(n) * n
    balance = Omega * ez.cross(L) - CP.cross(ez)
    if sp.simplify(balance[1]) != 0 or sp.simplify(balance[2]) != 0:  # pragma: no cover
        raise AssertionError("rolling in place: the balance has more than one component")
    O2 = sp.Symbol("O2", positive=True)
    Om2 = sp.solve(sp.simplify(balance[0]).subs(Omega, sp.sqrt(O2)), O2)[0]
    z_C = -CP[2]
    E = z_C + sp.Rational(1, 2) * w.dot(L)
    return sp.simplify(Om2), sp.simplify(E.subs(Omega**2, Om2))


def disk_kinematics() -> DiskKinematics:
    """Derive the near-flat relations (:func:`_rolling_in_place`) and the wall speed."""
    hh = sp.Symbol("hh", nonnegative=True)
    Om2_0, E_0 = _rolling_in_place(0)
    Om2_h, E_h = _rolling_in_place(hh)
    lim = sp.simplify(sp.limit(Om2_h * alpha, alpha, 0))
    e1 = sp.simplify(sp.diff(sp.series(E_h, alpha, 0, 2).removeO(), alpha))
    # the disk's lower face (thin disk): point C + rho (cos b ex + sin b (in-plane d-perp));
    # its velocity omega x (point - C) with omega = -Omega sin(alpha) d; horizontal part
    s, c = sp.sin(alpha), sp.cos(alpha)
    d = sp.Matrix([0, -c, -s])
    ex = sp.Matrix([1, 0, 0])
    rho, b = sp.symbols("rho b", real=True)
    w = -Omega * s * d
    v = w.cross(rho * (sp.cos(b) * ex + sp.sin(b) * d))
    vh2 = sp.simplify(v[0] ** 2 + v[1] ** 2)
    lead = sp.simplify(sp.series(sp.sqrt(vh2.subs(rho, a)), alpha, 0, 3).removeO())
    return DiskKinematics(sp.nsimplify(sp.simplify(Om2_0)), sp.nsimplify(sp.simplify(E_0)),
                          lim, e1, lead)


# ------------------------------------------------------------------ 3. Reynolds
@dataclass(frozen=True)
class ReynoldsProblem:
    """``gap``: ``h(r, phi, t)``; ``squeeze``: ``dh/dt`` in the co-rotating frame, as a
    function of ``x, y`` (units ``alpha Omega a``); ``operator``: ``P -> div(x^3 grad P)``;
    ``source``: its right-hand side ``y``; ``pressure_scale``: ``p / P``."""

    gap: sp.Expr
    squeeze: sp.Expr
    source: sp.Expr
    pressure_scale: sp.Expr

    @staticmethod
    def operator(P):
        """``div(x^3 grad P)`` (dimensionless Reynolds operator)."""
        return sp.diff(x**3 * sp.diff(P, x), x) + sp.diff(x**3 * sp.diff(P, y), y)


def reynolds_problem() -> ReynoldsProblem:
    """The Reynolds equation ``div(h^3 grad p) = 12 mu dh/dt`` (mass balance with the flux
    of :func:`film_profile` at ``U = 0``) for the precessing wedge, made dimensionless.

    ``h = alpha (a + r cos(phi - Omega t))``; with ``theta = phi - Omega t``, ``X = r cos
    theta / a``, ``Y = r sin theta / a``: ``h = alpha a (1 + X)``, ``dh/dt = alpha Omega a
    Y``.  Scaling lengths by ``a`` and ``p = 12 mu Omega P / alpha^2`` leaves
    ``div(x^3 grad P) = y`` with ``x = 1 + X``, ``y = Y``."""
    gap = alpha * (a + r * sp.cos(phi - Omega * t))
    dhdt = sp.diff(gap, t)
    th = sp.Symbol("theta", real=True)
    dhdt_rot = sp.simplify(dhdt.subs(phi, th + Omega * t))  # alpha Omega r sin(theta)
    X, Y = sp.symbols("X Y", real=True)
    squeeze = sp.simplify(dhdt_rot.subs(r * sp.sin(th), a * Y) / (alpha * Omega * a))
    squeeze = squeeze.subs(Y, y)
    # dimensional check of the scaling: h = alpha a x, d/dX = (1/a) d/dx
    P = sp.Function("P")(x, y)
    p = 12 * mu * Omega / alpha**2 * P
    hx = alpha * a * x
    lhs = (sp.diff(hx**3 * sp.diff(p, x) / a, x) + sp.diff(hx**3 * sp.diff(p, y) / a, y)) / a
    rhs = 12 * mu * alpha * Omega * a * y
    ratio = sp.simplify(lhs / rhs - ReynoldsProblem.operator(P) / y)
    if ratio != 0:  # pragma: no cover - a wrong scaling is a bug in this derivation
        raise AssertionError(f"Reynolds scaling does not reduce: {ratio}")
    return ReynoldsProblem(gap, squeeze, y, 12 * mu * Omega / alpha**2)


@dataclass(frozen=True)
class ReynoldsSolution:
    """``particular``: ``-y/x``; ``mode``: the Fourier mode ``K1(k r) sin(k z)/r`` of
    ``q*`` (harmonic in R^5 about the axis r = 0); ``amplitude``: its weight ``A(k)`` so
    that ``int_0^inf A sin(k z) dk`` is the boundary value of ``q*`` on ``r = 1/2``;
    ``boundary_value``: that value, ``2 z / (1/4 + z^2)^(3/2)``; ``kelvin``: ``q`` from
    ``q*``; ``laplace5``: the 5-D Laplacian in (4-D radius, axis)."""

    particular: sp.Expr
    mode: sp.Expr
    amplitude: sp.Expr
    boundary_value: sp.Expr

    @staticmethod
    def laplace5(f, rr, zz):
        """``f_rr + 3 f_r / r + f_zz`` (axisymmetric Laplacian in R^4 x R)."""
        return sp.diff(f, rr, 2) + 3 * sp.diff(f, rr) / rr + sp.diff(f, zz, 2)

    @staticmethod
    def kelvin(fstar):
        """``q(x, y) = R^-3 q*(x/R^2, y/R^2)`` (Kelvin transform in R^5) of a sympy
        function ``fstar(r, z)``."""
        R2 = x**2 + y**2
        return R2 ** sp.Rational(-3, 2) * fstar(x / R2, y / R2)


def reynolds_solution() -> ReynoldsSolution:
    """The pieces of ``P = -y/x + q`` (module docstring, step 4).

    On the rim ``x^2 + y^2 = 2x`` the particular part is ``-y/x = -2y/R^2``, so ``q = 2y/R^2``
    there; the Kelvin transform maps the rim onto ``r = 1/2`` with ``q* = R'^-3 q =
    2 z/(1/4 + z^2)^(3/2)``.  Its sine transform is ``(2/pi) int_0^inf q* sin(kz) dz = (4/pi)
    k K0(k/2)`` (``int_0^inf (b^2 + z^2)^(-1/2) cos(kz) dz = K0(kb)``, integrated by parts),
    and each mode continues off the cylinder as ``K1(k r)/r``, the decaying solution of
    ``f'' + 3 f'/r - k^2 f = 0``."""
    rr, zz = sp.symbols("r_ z_", positive=True)
    mode = sp.besselk(1, k * rr) / rr * sp.sin(k * zz)
    amp = 4 / sp.pi * k * sp.besselk(0, k / 2)
    bv = 2 * zz / (sp.Rational(1, 4) + zz**2) ** sp.Rational(3, 2)
    return ReynoldsSolution(-y / x, mode, amp, bv)


def _qstar(rr, zz, epsrel=1e-10):
    """``q*(r, z)``, ``r >= 1/2``, by QAWF (Fourier integral over [0, inf))."""
    from scipy import integrate, special

    if zz == 0.0:
        return 0.0
    sgn = 1.0 if zz > 0 else -1.0

    def f(kk):  # k K0(k/2) K1(k r) / K1(k/2), scaled Bessel functions (no underflow)
        return (kk * special.k0e(kk / 2) * special.k1e(kk * rr) / special.k1e(kk / 2)
                * math.exp(-kk * rr))

    val = integrate.quad(f, 0.0, math.inf, weight="sin", wvar=abs(zz), epsabs=1e-13,
                         limlst=200)[0]
    return sgn * 2.0 / (math.pi * rr) * val


def pressure(xx: float, yy: float) -> float:
    """Dimensionless film pressure ``P(x, y)`` (module docstring, step 4) at a point of the
    disk ``x^2 + y^2 < 2x``; ``p = 12 mu Omega P / alpha^2`` (gauge, ambient = 0).
    ``P < 0`` where the gap opens (``y > 0``)."""
    R2 = xx * xx + yy * yy
    return -yy / xx + R2 ** -1.5 * _qstar(xx / R2, yy / R2)


@lru_cache(maxsize=1)
def film_constant() -> tuple[float, float, float]:
    """``(K, I, J)``: ``Phi = K mu a^3 Omega^2 / alpha`` with ``K = 12 I``.

    ``I = int x^3 |grad P|^2 dA = -int P y dA`` (Green's identity, ``P = 0`` on the rim)
    ``= int y^2/x dA - int q y dA``.  The first is ``pi/3`` (sympy, exact); the second,
    by the Kelvin map (``dA = dA'/R'^4``) and ``int_R z sin(kz)/(r^2 + z^2)^(3/2) dz =
    2 k K0(k r)``, is ``J = (4/pi) int_0^inf k^2 K0(k/2)/K1(k/2) int_(k/2)^inf K0(s) K1(s)/s
    ds dk`` (scipy quadrature, relative error ~1e-12)."""
    from scipy import integrate, special

    xs, ys = sp.symbols("xs ys", positive=True)
    first = sp.integrate(sp.integrate(ys**2 / xs, (ys, -sp.sqrt(2 * xs - xs**2),
                                                    sp.sqrt(2 * xs - xs**2))), (xs, 0, 2))
    first = float(sp.nsimplify(sp.simplify(first)))

    def inner(b):
        return integrate.quad(lambda s: special.k0e(s) * special.k1e(s) * math.exp(-2 * s) / s,
                              b, math.inf, epsabs=0.0, epsrel=1e-13, limit=500)[0]

    def f(kk):
        return kk * kk * special.k0e(kk / 2) / special.k1e(kk / 2) * inner(kk / 2)

    J = 4 / math.pi * (integrate.quad(f, 0, 1, epsabs=0.0, epsrel=1e-12, limit=500)[0]
                       + integrate.quad(f, 1, math.inf, epsabs=0.0, epsrel=1e-12,
                                        limit=500)[0])
    I_ = first - J
    return 12.0 * I_, I_, J


def moffatt_shear_constant() -> sp.Expr:
    """Moffatt's estimate as an integral: the local gap ``h = alpha a (1 + X)`` sheared at
    speed ``a Omega`` everywhere, ``Phi = int mu (a Omega)^2 / h dA``; returns its constant
    ``int_disk dX dY/(1 + X)`` = ``2 pi`` (exact)."""
    X, Y = sp.symbols("X Y", real=True)
    inner = sp.integrate(1 / (1 + X), (Y, -sp.sqrt(1 - X**2), sp.sqrt(1 - X**2)))
    return sp.simplify(sp.integrate(sp.simplify(inner), (X, -1, 1)))


# ------------------------------------------------------------------ 6. the decay
@dataclass(frozen=True)
class DecayLaw:
    """Adiabatic decay ``e1 M g a dalpha/dt = -Phi`` with ``Omega^2 alpha = w g/a``:
    ``alpha_cubed`` (``alpha^3`` against ``tau = t0 - t``), ``t0``, exponents ``p``
    (``alpha ~ tau^p``) and ``q`` (``Omega ~ tau^q``)."""

    alpha_cubed: sp.Expr
    t0: sp.Expr
    p: sp.Expr
    q: sp.Expr


def decay_law(K=None, w=4, e1=None) -> DecayLaw:
    """Integrate the energy balance with ``Phi = K mu a^3 Omega^2/alpha`` (sympy).

    Defaults: thin disk (``w = 4``, ``e1 = 3/2`` from :func:`disk_kinematics`), ``K``
    symbolic.  ``t0 = e1 alpha0^3 M / (3 K w mu a)``."""
    K = sp.Symbol("K", positive=True) if K is None else K
    e1 = sp.Rational(3, 2) if e1 is None else e1
    tau, al0, A = sp.symbols("tau alpha0 A", positive=True)
    Om2 = w * g / (a * A)
    # e1 M g a dalpha/dtau = Phi (tau = t0 - t runs backwards); separate the variables
    rate = K * mu * a**3 * Om2 / A / (e1 * M * g * a)  # dalpha/dtau
    tau_of_A = sp.integrate(1 / rate, (A, 0, A))
    a3 = sp.simplify(A**3 * tau / tau_of_A)  # tau_of_A is proportional to A^3
    t0 = sp.simplify(tau_of_A.subs(A, al0))
    p = sp.Rational(1, 3)
    if sp.simplify(A * sp.diff(tau_of_A, A) - tau_of_A / p) != 0:  # pragma: no cover
        raise AssertionError("alpha^3 is not linear in tau")
    return DecayLaw(a3, sp.simplify(t0), p, -p / 2)


@dataclass(frozen=True)
class BoundaryLayerLaw:
    """Bildsten's boundary layer, within the same estimate: ``delta = sqrt(nu/Omega)``
    replaces the gap; ``Phi = C mu a^2 (a Omega)^2 / delta`` (``C = pi``: one sheared wall
    over the disk's area, the estimate that gives Moffatt's film constant with a uniform
    gap).  ``exponents``: ``(p, q)``; ``crossover_alpha``: the tilt at which ``delta = a
    alpha`` on the rolling family (film law below it)."""

    dissipation: sp.Expr
    p: sp.Expr
    q: sp.Expr
    crossover_alpha: sp.Expr


def power_law_exponents(m, j):
    """``(p, q)`` of ``alpha ~ tau^p``, ``Omega ~ tau^q`` for ``Phi ~ Omega^m alpha^-j``
    with ``Omega^2 alpha`` constant and ``E - E_flat ~ alpha`` (sympy ODE solve)."""
    A = sp.Symbol("A", positive=True)
    m, j = sp.nsimplify(m), sp.nsimplify(j)
    # dalpha/dtau = alpha^(-m/2 - j): tau(alpha) = int_0^alpha s^(m/2 + j) ds
    tau_of_A = sp.integrate(A ** (m / 2 + j), (A, 0, A))
    p = sp.simplify(tau_of_A / (A * sp.diff(tau_of_A, A)))  # dlog(alpha)/dlog(tau)
    return p, -p / 2


def boundary_layer_law() -> BoundaryLayerLaw:
    """Derive the boundary-layer dissipation and its exponents (thin disk, ``w = 4``)."""
    nu, C, rho = sp.symbols("nu C rho", positive=True)
    delta = sp.sqrt(nu / Omega)
    Phi = (sp.pi * mu * a**2 * (a * Omega) ** 2 / delta).subs(nu, mu / rho)
    p, q = power_law_exponents(sp.Rational(5, 2), 0)
    w = 4
    ac = sp.solve(sp.Eq(sp.sqrt(nu / sp.sqrt(w * g / (a * alpha))), a * alpha), alpha)[0]
    return BoundaryLayerLaw(sp.simplify(Phi), p, q, sp.simplify(ac))
