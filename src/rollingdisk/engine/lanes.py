"""Vector lanes for the sweeps' batch Taylor kernel: the reduced jets, their step size, their
sampler, the energy and the common step, ``LANES`` trajectories per machine instruction.

Nothing here is a second copy of a formula.  The scalar sources of
:mod:`rollingdisk.engine.taylor_jets` (``_tay_jet4_rough``, ``_tay_jet4_smooth``,
``_tay_step_size``, ``_tay_sample``), ``_energy_sc`` and the common step
:func:`rollingdisk.sweep.batch_taylor._tay_plain` are *traced*: each is run once, at compile
time, on values of :class:`_Vec` instead of floats, and every arithmetic operation it
performs emits the same operation on an LLVM vector ``<LANES x double>`` (one trajectory per
lane).  The loops over the orders run in Python during the trace, so the code is unrolled for
the order P, which is therefore a compile-time constant (``numba.literally``); array
elements become vector loads and stores of the lane layout ``(row, k, lane)``.  The result is
a numba intrinsic: it is compiled and cached with the numba function that calls it
(:func:`rollingdisk.sweep.batch.run_batch_lanes`).

The same operations as the scalar kernel, in the same order, with the same ``contract``
flag where numba_core compiles with it (the jet and the sampler), and numba's
``max``/``min`` (``select(b > a, b, a)``: a NaN second argument is ignored).  sin, cos,
log and exp are fdlibm's polynomials in the lanes (within 1 ulp of libm, tested): LLVM's
vector intrinsics would call libm lane by lane, 8 calls per vector, which took a third of
the jet's time.  The summaries therefore agree with the scalar kernel's to round-off, not
bit for bit (LLVM also fuses some multiply-adds of the unrolled code differently);
tests/test_sweep_lanes.py holds the verdicts equal and the frequencies within 1e-12.

Two things a trace cannot do are given by the caller: the sign of theta (``h~ = h sgn
theta``, eq. 4) is fixed for a run, so every lane receives its signed h~ and
``_signed_h`` is traced as the identity; and the sweeps control all four components with
one finite atol, so ``math.isfinite(atol)`` is traced as True.
"""

from __future__ import annotations

import math
import types as _pytypes

from llvmlite import ir
from numba import types
from numba.core import cgutils
from numba.extending import intrinsic

#: Trajectories per vector: 8 doubles fill an AVX-512 register (two AVX2 registers, four
#: NEON registers: LLVM splits a wider vector where the machine has narrower ones).
LANES = 8
#: The highest order traced (tolerance 1e-17): the unrolled jet grows as P^2, and a finer
#: tolerance than the sweeps use runs the scalar kernel.
MAX_ORDER = 20
_F64 = ir.DoubleType()
_VT = ir.VectorType(_F64, LANES)
_I64 = ir.IntType(64)
#: The fast-math flags of the functions traced: those numba_core compiles with ``contract``
#: (the jet and the sampler), none for the others (the energy, compiled without).
_CONTRACT = ("contract",)


class _Trace:
    """The builder a trace emits into (one per intrinsic call being compiled)."""

    builder: ir.IRBuilder | None = None
    flags: tuple = ()


def _b() -> ir.IRBuilder:
    return _Trace.builder


def _splat(x: float) -> ir.Constant:
    return ir.Constant(_VT, [float(x)] * LANES)


def _val(x):
    if isinstance(x, _Vec):
        return x.v
    if isinstance(x, (int, float)) and not isinstance(x, bool):
        return _splat(x)
    raise TypeError(f"cannot trace a value of type {type(x).__name__}")


def _intr(name: str, *args):
    fn = cgutils.get_or_insert_function(_b().module,
                                        ir.FunctionType(_VT, [_VT] * len(args)),
                                        f"llvm.{name}.v{LANES}f64")
    return _Vec(_b().call(fn, [_val(a) for a in args]))


class _Mask:
    """A lane-wise comparison: only :func:`_where`, ``max`` and ``min`` may use it; a
    Python branch on it (``if``, ``a if c else b``) would follow one lane, so it raises."""

    __slots__ = ("m",)

    def __init__(self, m):
        self.m = m

    def __bool__(self):
        raise TypeError("a branch on a vector comparison cannot be traced: use where")


class _Vec:
    """A ``<LANES x double>`` value; arithmetic emits the LLVM instruction."""

    __slots__ = ("v",)

    def __init__(self, v):
        self.v = v

    def _bin(self, other, op, swap=False):
        a, b = _val(self), _val(other)
        if swap:
            a, b = b, a
        return _Vec(getattr(_b(), op)(a, b, flags=_Trace.flags))

    def __add__(self, o):
        return self._bin(o, "fadd")

    def __radd__(self, o):
        return self._bin(o, "fadd", True)

    def __sub__(self, o):
        return self._bin(o, "fsub")

    def __rsub__(self, o):
        return self._bin(o, "fsub", True)

    def __mul__(self, o):
        return self._bin(o, "fmul")

    def __rmul__(self, o):
        return self._bin(o, "fmul", True)

    def __truediv__(self, o):
        return self._bin(o, "fdiv")

    def __rtruediv__(self, o):
        return self._bin(o, "fdiv", True)

    def __neg__(self):
        return _Vec(_b().fneg(self.v, flags=_Trace.flags))

    def __abs__(self):
        return _intr("fabs", self)

    def _cmp(self, o, op, swap=False):
        a, b = _val(self), _val(o)
        if swap:
            a, b = b, a
        return _Mask(_b().fcmp_ordered(op, a, b))

    def __lt__(self, o):
        return self._cmp(o, "<")

    def __le__(self, o):
        return self._cmp(o, "<=")

    def __gt__(self, o):
        return self._cmp(o, ">")

    def __ge__(self, o):
        return self._cmp(o, ">=")

    def __eq__(self, o):
        return self._cmp(o, "==")

    __hash__ = None


def _select(m: _Mask, a, b) -> _Vec:
    return _Vec(_b().select(m.m, _val(a), _val(b)))


def _where(c, a, b):
    """``a if c else b`` lane by lane (``taylor_jets.where``)."""
    if isinstance(c, _Mask):
        return _select(c, a, b)
    return a if c else b


def _max(a, b):
    """numba's ``max(a, b)`` of floats: ``b if b > a else a``."""
    if not isinstance(a, _Vec) and not isinstance(b, _Vec):
        return max(a, b)
    return _select(_Vec(_val(b)) > _Vec(_val(a)), b, a)


def _min(a, b):
    """numba's ``min(a, b)`` of floats: ``b if b < a else a``."""
    if not isinstance(a, _Vec) and not isinstance(b, _Vec):
        return min(a, b)
    return _select(_Vec(_val(b)) < _Vec(_val(a)), b, a)


class _Arr:
    """An array of the lane layout ``(*shape, LANES)`` seen by a trace: an element is a
    vector; loads are made once and stores remembered (nothing else writes the array
    during the call), so the trace is straight-line code over SSA values."""

    __slots__ = ("ptr", "shape", "base", "memo")

    def __init__(self, ptr, shape, base=0, memo=None):
        self.ptr = ptr
        self.shape = tuple(shape)
        self.base = base
        self.memo = {} if memo is None else memo

    def _offset(self, idx):
        idx = idx if isinstance(idx, tuple) else (idx,)
        off, stride = 0, 1
        strides = []
        for n in reversed(self.shape):
            strides.append(stride)
            stride *= n
        strides.reverse()
        for i, (k, n) in enumerate(zip(idx, self.shape)):
            if not 0 <= k < n:
                raise IndexError(f"index {k} out of range {n} in a traced array")
            off += k * strides[i]
        return self.base + off, len(idx)

    def _ptr(self, off):
        p = _b().gep(self.ptr, [ir.Constant(_I64, off * LANES)])
        return _b().bitcast(p, _VT.as_pointer())

    def __getitem__(self, idx):
        off, nd = self._offset(idx)
        if nd < len(self.shape):
            return _Arr(self.ptr, self.shape[nd:], off, self.memo)
        if off not in self.memo:
            self.memo[off] = _Vec(_b().load(self._ptr(off), align=8))
        return self.memo[off]

    def __setitem__(self, idx, value):
        off, nd = self._offset(idx)
        if nd != len(self.shape):
            raise IndexError("a traced store takes one element")
        v = _Vec(_val(value))
        _b().store(v.v, self._ptr(off), align=8)
        self.memo[off] = v


class _Splat:
    """A per-call scalar seen as an array whose every element is its vector splat (the
    sweeps' ``atolv``: one atol for the four components)."""

    def __init__(self, v: _Vec):
        self.v = v

    def __getitem__(self, idx):
        return self.v


def _i64v():
    return ir.VectorType(_I64, LANES)


def _rint(x: _Vec) -> _Vec:
    return _intr("rint", x)


def _to_bits(x: _Vec):
    return _b().bitcast(x.v, _i64v())


def _from_bits(i) -> _Vec:
    return _Vec(_b().bitcast(i, _VT))


def _ivec(k: int):
    return ir.Constant(_i64v(), [k] * LANES)


# fdlibm's kernels (FreeBSD msun k_sin.c, k_cos.c, e_log.c, e_exp.c), error below 1 ulp on
# their reduced ranges; tests/test_sweep_lanes.py holds them to numpy's libm within 2 ulp.
_S = (-1.66666666666666324348e-01, 8.33333333332248946124e-03, -1.98412698298579493134e-04,
      2.75573137070700676789e-06, -2.50507602534068634195e-08, 1.58969099521155010221e-10)
_C = (4.16666666666666019037e-02, -1.38888888888741095749e-03, 2.48015872894767294178e-05,
      -2.75573143513906633035e-07, 2.08757232129817482790e-09, -1.13596475577881948265e-11)
_LG = (6.666666666666735130e-01, 3.999999999940941908e-01, 2.857142874366239149e-01,
       2.222219843214978396e-01, 1.818357216161805012e-01, 1.531383769920937332e-01,
       1.479819860511658591e-01)
_P = (1.66666666666666019037e-01, -2.77777777770155933842e-03, 6.61375632143793436117e-05,
      -1.65339022054652515390e-06, 4.13813679705723846039e-08)
_LN2_HI, _LN2_LO = 6.93147180369123816490e-01, 1.90821492927058770002e-10
_PIO2_1, _PIO2_1T = 1.57079632673412561417e+00, 6.07710050650619224932e-11


def _sincos(x: _Vec):
    """``(sin x, cos x)``: ``x = n pi/2 + r`` (Cody-Waite, two parts of pi/2: exact for the
    tilts here, |n| <= 1), then the kernels on |r| <= pi/4 and the quadrant n mod 4."""
    n = _rint(x * (2.0 / math.pi))
    r = (x - n * _PIO2_1) - n * _PIO2_1T
    z = r * r
    sr = _S[1] + z * (_S[2] + z * (_S[3] + z * (_S[4] + z * _S[5])))
    s = r + (z * r) * (_S[0] + z * sr)
    hz = 0.5 * z
    w = 1.0 - hz
    cr = z * (_C[0] + z * (_C[1] + z * (_C[2] + z * (_C[3] + z * (_C[4] + z * _C[5])))))
    c = w + (((1.0 - w) - hz) + z * cr)
    q = _b().and_(_b().fptosi(n.v, _i64v()), _ivec(3))
    q1 = _Mask(_b().icmp_signed("==", _b().and_(q, _ivec(1)), _ivec(1)))
    q2 = _Mask(_b().icmp_signed("==", _b().and_(q, _ivec(2)), _ivec(2)))
    q3 = _Mask(_b().icmp_signed("==", _b().and_(_b().add(q, _ivec(1)), _ivec(2)), _ivec(2)))
    sv = _select(q1, c, s)
    cv = _select(q1, s, c)
    return _select(q2, -sv, sv), _select(q3, -cv, cv)


def _log(x: _Vec) -> _Vec:
    """``log x`` (fdlibm's e_log: x = 2^e m, m in [sqrt(2)/2, sqrt(2)), log(1 + f) by a
    rational approximation in s = f/(2 + f)); inf at inf and 0, -inf at 0, NaN below 0."""
    bits = _to_bits(x)
    e = _b().sub(_b().lshr(bits, _ivec(52)), _ivec(1023))
    m = _from_bits(_b().or_(_b().and_(bits, _ivec((1 << 52) - 1)), _ivec(1023 << 52)))
    big = m > math.sqrt(2.0)
    m = _select(big, m * 0.5, m)
    ef = _Vec(_b().sitofp(e, _VT))
    ef = _select(big, ef + 1.0, ef)
    f = m - 1.0
    s = f / (2.0 + f)
    z = s * s
    w = z * z
    t1 = w * (_LG[1] + w * (_LG[3] + w * _LG[5]))
    t2 = z * (_LG[0] + w * (_LG[2] + w * (_LG[4] + w * _LG[6])))
    hfsq = 0.5 * f * f
    y = ef * _LN2_HI - ((hfsq - (s * (hfsq + (t2 + t1)) + ef * _LN2_LO)) - f)
    y = _select(x == math.inf, math.inf, y)
    y = _select(x == 0.0, -math.inf, y)
    return _select(x >= 0.0, y, math.nan)


def _exp(x: _Vec) -> _Vec:
    """``exp x`` (fdlibm's e_exp: x = n ln 2 + r, |r| <= ln2/2, exp r rational in r^2, times
    2^n); inf above 709.78, 0 below -708, NaN at NaN."""
    n = _rint(x * 1.44269504088896338700e+00)
    hi = x - n * _LN2_HI
    lo = n * _LN2_LO
    r = hi - lo
    t = r * r
    c = r - t * (_P[0] + t * (_P[1] + t * (_P[2] + t * (_P[3] + t * _P[4]))))
    y = 1.0 - ((lo - (r * c) / (2.0 - c)) - hi)
    ni = _b().fptosi(_select(x > 700.0, 0.0, _select(x < -700.0, 0.0, n)).v, _i64v())
    y = y * _from_bits(_b().shl(_b().add(ni, _ivec(1023)), _ivec(52)))
    y = _select(x > 709.78, math.inf, y)
    y = _select(x < -708.0, 0.0, y)
    return _select(x == x, y, x)


class _VecMath:
    """``math`` for a trace: sin, cos, log and exp in the vector lanes (fdlibm's
    polynomials; libm, which has no vector entry points numba can reach everywhere, would
    be called lane by lane: 8 calls per vector)."""

    @staticmethod
    def sin(x):
        return _sincos(x)[0]

    @staticmethod
    def cos(x):
        return _sincos(x)[1]

    @staticmethod
    def log(x):
        return _log(x)

    @staticmethod
    def exp(x):
        return _exp(x)

    @staticmethod
    def isfinite(x):
        return True  # the sweeps' atol (module docstring)


@intrinsic
def _lane_math(typingctx, which, x, out):
    """``out[:, lane] = f(x[:, lane])`` for ``which`` in {"sin", "cos", "log", "exp"}
    (tests; rows of LANES)."""
    if not isinstance(which, types.StringLiteral):
        return None
    name = which.literal_value
    sig = types.void(which, x, out)

    def codegen(context, builder, sig, args):
        xa = context.make_array(sig.args[1])(context, builder, args[1])
        oa = context.make_array(sig.args[2])(context, builder, args[2])
        rows = builder.extract_value(xa.shape, 0)
        _Trace.builder = builder
        try:
            with cgutils.for_range(builder, rows) as loop:
                off = builder.mul(loop.index, ir.Constant(_I64, LANES))
                px = builder.bitcast(builder.gep(xa.data, [off]), _VT.as_pointer())
                po = builder.bitcast(builder.gep(oa.data, [off]), _VT.as_pointer())
                v = getattr(_VecMath, name)(_Vec(builder.load(px, align=8)))
                builder.store(v.v, po, align=8)
        finally:
            _Trace.builder = None
        return context.get_dummy_value()

    return sig, codegen


class _VecNumpy:
    inf = math.inf
    nan = math.nan
    pi = math.pi


def _traced(names: tuple[str, ...], glb: dict | None = None) -> dict:
    """The scalar sources ``names`` in the module namespace ``glb`` (:mod:`.taylor_jets`'s by
    default; a numba function stands for its Python source) re-bound to a namespace in
    which ``math``, ``np``, ``max``, ``min`` and the helpers ``where``, ``_signed_h`` are
    the trace's."""
    if glb is None:
        from rollingdisk.engine import taylor_jets

        glb = taylor_jets.__dict__
    src = dict(glb)
    ns = dict(src)
    ns.update(math=_VecMath, np=_VecNumpy, max=_max, min=_min, where=_where,
              _signed_h=lambda h, th0: h)
    for name in names:
        f = getattr(src[name], "py_func", src[name])
        ns[name] = _pytypes.FunctionType(f.__code__, ns, f.__name__, f.__defaults__)
    return ns


_NAMES = ("_tay_jet4_rough", "_tay_jet4_smooth", "_tay_rows_rough", "_tay_rows_smooth",
          "_tay_step_size", "_tay_sample", "_energy_sc")


def _data(context, builder, ty, val):
    return context.make_array(ty)(context, builder, val).data


def _lane_jet_intrinsic(rough: bool):
    """The intrinsic ``jet(P, h, k1, k2, atol, rtol, Y, J, A, out)``: for every lane, the
    jet of the reduced state ``Y[:, lane]`` into ``J`` (4, P + 1, LANES) and ``A`` (14,
    P + 1, LANES) (``_tay_jet4_rough``/``_smooth``), then ``out[0]`` = the energy at the
    state (``_energy_sc``) and ``out[1]`` = the step size (``_tay_step_size``)."""
    jet_name = "_tay_jet4_rough" if rough else "_tay_jet4_smooth"

    def typer(typingctx, P, h, k1, k2, atol, rtol, Y, J, A, out):
        if not isinstance(P, types.IntegerLiteral):
            return None
        order = P.literal_value
        sig = types.void(P, h, k1, k2, atol, rtol, Y, J, A, out)

        def codegen(context, builder, sig, args):
            ns = _traced(_NAMES)
            ptr = [_data(context, builder, sig.args[i], args[i]) for i in range(6, 10)]
            vec = [_Arr(_data(context, builder, sig.args[i], args[i]), (1,))
                   for i in (1, 2, 3)]
            _Trace.builder = builder
            try:
                h_, k1_, k2_ = (v[0] for v in vec)
                at = _splat_value(builder, args[4])
                rt = _splat_value(builder, args[5])
                Yt = _Arr(ptr[0], (4,))
                Jt = _Arr(ptr[1], (4, order + 1))
                At = _Arr(ptr[2], (14, order + 1))
                Ot = _Arr(ptr[3], (2,))
                _Trace.flags = _CONTRACT
                ns[jet_name](h_, Yt, Jt, At, order)
                _Trace.flags = ()
                Ot[0] = ns["_energy_sc"](rough, h_, k1_, k2_, At[0, 0], At[1, 0], Yt)
                Ot[1] = ns["_tay_step_size"](Jt, order, _Splat(at), rt)
            finally:
                _Trace.builder = None
                _Trace.flags = ()
            return context.get_dummy_value()

        return sig, codegen

    typer.__name__ = f"lane_jet_{'rough' if rough else 'smooth'}"
    return intrinsic(typer)


def _splat_value(builder, x) -> _Vec:
    """The LANES-vector of the double ``x``."""
    v = ir.Constant(_VT, ir.Undefined)
    for i in range(LANES):
        v = builder.insert_element(v, x, ir.Constant(_I64, i))
    return _Vec(v)


lane_jet_rough = _lane_jet_intrinsic(True)
lane_jet_smooth = _lane_jet_intrinsic(False)


@intrinsic
def lane_samples(typingctx, P, S, h, J, A, dt, V):
    """``V[m - 1, :, lane]`` = ``(theta, omega1, omega2, omega3, F_z)`` at ``dt m / S`` into
    the step (m = 1..S; ``_tay_sample`` and the sample points of ``_one_taylor``)."""
    if not isinstance(P, types.IntegerLiteral) or not isinstance(S, types.IntegerLiteral):
        return None
    order, ns_ = P.literal_value, S.literal_value
    sig = types.void(P, S, h, J, A, dt, V)

    def codegen(context, builder, sig, args):
        ns = _traced(_NAMES)
        p = [_data(context, builder, sig.args[i], args[i]) for i in range(2, 7)]
        _Trace.builder = builder
        _Trace.flags = _CONTRACT
        try:
            h_ = _Arr(p[0], (1,))[0]
            Jt = _Arr(p[1], (4, order + 1))
            At = _Arr(p[2], (14, order + 1))
            dt_ = _Arr(p[3], (1,))[0]
            Vt = _Arr(p[4], (ns_, 5))
            for m in range(1, ns_ + 1):
                x = dt_ * m / ns_ if m < ns_ else dt_
                ns["_tay_sample"](h_, Jt, At, order, x, Vt[m - 1])
        finally:
            _Trace.builder = None
            _Trace.flags = ()
        return context.get_dummy_value()

    return sig, codegen


@intrinsic
def lane_plain(typingctx, step, t_end, max_steps, grow_lo, grow_hi, side, c, EO, V, Y, rec,
                ok):
    """The common step in every lane at once: ``step``
    (:func:`rollingdisk.sweep.batch_taylor._tay_plain`, handed in by its caller so that this
    module need not import the one that imports it) traced, its arguments the lanes' arrays
    (``side`` (LANES,), ``c`` (3, LANES), ``EO`` (2, LANES): the energy and step size of
    :func:`lane_jet_rough`, ``V`` (S, 5, LANES), ``Y`` (4, LANES), ``rec`` (NREC, LANES),
    S and NREC the constants ``_SAMPLES`` and ``_NREC`` of ``step``'s module); ``ok[lane]``
    = its result: 1.0 where the lane took the step, 0.0 where the lane is left as it was,
    for the scalar step."""
    if not isinstance(step, types.Dispatcher):
        return None
    f = step.dispatcher.py_func
    sig = types.void(step, t_end, max_steps, grow_lo, grow_hi, side, c, EO, V, Y, rec, ok)

    def codegen(context, builder, sig, args):
        glb = f.__globals__
        ns = _traced((f.__name__,), glb)
        p = [_data(context, builder, sig.args[i], args[i]) for i in range(5, 12)]
        _Trace.builder = builder
        try:
            sc = [_splat_value(builder, context.cast(builder, args[i], sig.args[i],
                                                     types.float64)) for i in range(1, 5)]
            r = ns[f.__name__](*sc, _Arr(p[0], (1,))[0], _Arr(p[1], (3,)),
                               *(_Arr(p[2], (2,))[k] for k in range(2)),
                               _Arr(p[3], (glb["_SAMPLES"], 5)), _Arr(p[4], (4,)),
                               _Arr(p[5], (glb["_NREC"],)))
            _Arr(p[6], (1,))[0] = r
        finally:
            _Trace.builder = None
        return context.get_dummy_value()

    return sig, codegen
