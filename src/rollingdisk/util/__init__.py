"""Below the model: the library's errors, validators of the public boundary, atomic files."""

from rollingdisk.util.checks import (
    check_int as check_int,
)
from rollingdisk.util.checks import (
    check_real as check_real,
)
from rollingdisk.util.errors import (
    INPUT_ERRORS as INPUT_ERRORS,
)
from rollingdisk.util.errors import (
    ParameterError as ParameterError,
)
from rollingdisk.util.errors import (
    ParameterTypeError as ParameterTypeError,
)

__all__ = [
    "ParameterError",
    "ParameterTypeError",
    "INPUT_ERRORS",
    "check_real",
    "check_int",
]
