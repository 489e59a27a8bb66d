"""The one root finder of the integrators: the Illinois variant of regula falsi.

Every guard and event of a simulation is located by it: on the DOP853 dense output
(:func:`rollingdisk.engine.dop853._guard_root`), on the Taylor step polynomial
(:func:`rollingdisk.engine.taylor._tay_locate`) and on scipy's dense output
(:mod:`rollingdisk.ivp.drivers`).  The sweeps' batch kernels, which find a theta
crossing every few steps on one polynomial whose derivative is free, use Newton kept in
the bracket instead (:func:`rollingdisk.engine.taylor_jets._tay_poly_root`; it starts from
:func:`illinois_trial` and stops by :func:`illinois_converged`).  The callers differ
only in the function they evaluate, so the rule is split into three numba-compilable
pieces that each caller's loop calls (passing the function in would keep the uncompiled
path from re-binding it):

    while not illinois_converged(xa, xb):
        xc = illinois_trial(xa, xb, fa, fb)
        fc = f(xc)
        xa, xb, fa, fb, flag = illinois_update(xa, xb, fa, fb, xc, fc, flag)

The bracket ``[xa, xb]`` keeps ``f(xa)`` of the sign of ``fa`` (and nonzero) and ``f(xb)`` of
the other sign or zero; when the same end moves twice in a row the function value kept at
the other end is halved (Dowell & Jarratt, BIT 11 (1971) 168), which restores superlinear
convergence.  The root is the last admissible point ``xa``.
"""

#: Iterations at most (the bracket shrinks to round-off well before).
ILLINOIS_MAXITER = 200


def illinois_converged(xa, xb):
    """True when the bracket ``[xa, xb]`` is within round-off (4e-16 relative)."""
    return xb - xa <= 4e-16 * max(1.0, abs(xa), abs(xb))


def illinois_trial(xa, xb, fa, fb):
    """The next trial point: the secant through the ends, or the midpoint if it falls
    outside the open bracket."""
    xc = (xa * fb - xb * fa) / (fb - fa)
    if not (xa < xc < xb):
        xc = 0.5 * (xa + xb)
    return xc


def illinois_update(xa, xb, fa, fb, xc, fc, flag):
    """The bracket after evaluating ``fc = f(xc)``: ``(xa, xb, fa, fb, flag)``, ``flag`` -1
    if ``xa`` moved, +1 if ``xb`` moved (the Illinois halving of the other end's value)."""
    if (fc > 0.0) == (fa > 0.0) and fc != 0.0:
        if flag == -1:
            fb *= 0.5
        return xc, xb, fc, fb, -1
    if flag == 1:
        fa *= 0.5
    return xa, xc, fa, fc, 1


#: The names by which the compiled loops call the rule (their namespaces bind the compiled
#: versions by these names).
_illinois_converged, _illinois_trial, _illinois_update = (illinois_converged, illinois_trial,
                                                          illinois_update)
