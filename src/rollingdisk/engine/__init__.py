"""The numerical engine: DOP853 (compiled or not) and the Taylor method, vector lanes, root
location on dense output, and the compile policy (:mod:`.jit`: when compiled code is worth
loading, how a cold cache is filled).  The only layer besides the sweeps' kernels that
imports numba, and it does so lazily.
"""

from rollingdisk.util.lazy import attach as _attach

__getattr__, __dir__, __all__ = _attach(__name__, {
    "jit_compile": "rollingdisk.engine.jit",
})
