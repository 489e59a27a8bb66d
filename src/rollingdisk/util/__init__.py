"""Below the model: the library's errors, validators of the public boundary, atomic files,
signals, progress and lazy re-exports."""

from rollingdisk.util.lazy import attach as _attach

__getattr__, __dir__, __all__ = _attach(__name__, {
    "ParameterError": "rollingdisk.util.errors",
    "ParameterTypeError": "rollingdisk.util.errors",
    "INPUT_ERRORS": "rollingdisk.util.errors",
    "check_real": "rollingdisk.util.checks",
    "check_int": "rollingdisk.util.checks",
})
