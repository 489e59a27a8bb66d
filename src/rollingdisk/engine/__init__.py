"""The numerical engine: the written contract every model plugs into (:mod:`.contract`,
:func:`solve` over one DOP853 step loop, compiled or not), the disk's DOP853 and Taylor
method, vector lanes, root location on dense output, the method vocabulary
(:mod:`.methods`) and the compile policy (:mod:`.jit`: when compiled code is worth loading).
The only layer besides the sweeps' kernel that imports numba, and it does so lazily.
"""

from rollingdisk.util.lazy import attach as _attach

__getattr__, __dir__, __all__ = _attach(__name__, {
    "Model": "rollingdisk.engine.contract",
    "Solution": "rollingdisk.engine.contract",
    "solve": "rollingdisk.engine.driver",
    "METHODS": "rollingdisk.engine.methods",
    "jit_compile": "rollingdisk.engine.jit",
})
