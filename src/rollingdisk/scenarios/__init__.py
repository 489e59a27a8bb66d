"""Applications built on the phases: the coin toss (:mod:`.toss`), the hand toss
(:mod:`.hand_toss`), edge odds against thickness (:mod:`.odds`) and Euler's disk run to
its end (:mod:`.euler_disk`).

The function ``toss`` is ``rollingdisk.toss`` (or ``rollingdisk.scenarios.toss.toss``): a
package attribute named like its submodule ``toss`` would be the module once the submodule
is imported.
"""

from rollingdisk.util.lazy import attach as _attach

__getattr__, __dir__, __all__ = _attach(__name__, {
    "toss_ensemble": "rollingdisk.scenarios.toss",
    "HandLaunch": "rollingdisk.scenarios.hand_toss",
    "caught_ensemble": "rollingdisk.scenarios.hand_toss",
    "table_ensemble": "rollingdisk.scenarios.hand_toss",
    "CaughtResult": "rollingdisk.scenarios.hand_toss",
    "same_side_probability": "rollingdisk.scenarios.hand_toss",
    "edge_odds": "rollingdisk.scenarios.odds",
    "EdgeOdds": "rollingdisk.scenarios.odds",
    "AIR_VISCOSITY": "rollingdisk.scenarios.euler_disk",
    "END_KINDS": "rollingdisk.scenarios.euler_disk",
    "FIT_WINDOW": "rollingdisk.scenarios.euler_disk",
    "FIT_WINDOW_AIR": "rollingdisk.scenarios.euler_disk",
    "EulerDisk": "rollingdisk.scenarios.euler_disk",
    "EulerDiskResult": "rollingdisk.scenarios.euler_disk",
    "creep_factor": "rollingdisk.scenarios.euler_disk",
    "predicted_end_time": "rollingdisk.scenarios.euler_disk",
    "predicted_exponents": "rollingdisk.scenarios.euler_disk",
    "run_euler_disk": "rollingdisk.scenarios.euler_disk",
})
