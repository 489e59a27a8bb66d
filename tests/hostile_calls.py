"""Valid calls of every public name of every public subpackage, and the hostile values put
in them one argument at a time (shared by ``tests/test_hostile_api.py``).

The contract (issues 18 and 36): a public function given a hostile value either works or
raises ``TypeError``/``ValueError`` (the library's ``ParameterTypeError``/``ParameterError``
subclass them); and a call whose inputs are all finite never answers NaN at a single point
(a float, a 0-d array, or a tuple of them): outside its domain it refuses, naming the
parameter.  Arrays in, arrays out may mark points outside the domain with NaN (the maps).
"""

from __future__ import annotations

import decimal
import importlib
import inspect
import math
import random
from decimal import Decimal

import numpy as np

import rollingdisk as rd

#: The public subpackages (and modules) whose every public name is driven.
MODULES = ("rollingdisk", "rollingdisk.sweep", "rollingdisk.plotting",
           "rollingdisk.theory.exact", "rollingdisk.scenarios.euler_disk",
           "rollingdisk.scenarios.toss", "rollingdisk.phases.flight",
           "rollingdisk.phases.impact",
           "rollingdisk.phases.motion", "rollingdisk.results", "rollingdisk.model")

LONG_NAME = "a" * 300


def _masked(values, mask):
    return np.ma.masked_array(np.asarray(values, dtype=float), mask=mask)


#: Values no public argument accepts everywhere; each is put in one argument at a time.
#: ``(label, factory)``: a factory, so a mutable value is fresh for every call.
HOSTILE = (
    ("None", lambda: None), ("'x'", lambda: "x"), ("''", lambda: ""),
    ("huge str", lambda: "7" * 100_000), ("'/'", lambda: "/"), ("long name", lambda: LONG_NAME),
    ("nan", lambda: math.nan), ("inf", lambda: math.inf), ("-inf", lambda: -math.inf),
    ("-0.0", lambda: -0.0), ("5e-324", lambda: 5e-324), ("1e308", lambda: 1e308),
    ("10**400", lambda: 10**400), ("-10**400", lambda: -10**400), ("-1", lambda: -1),
    ("-1.0", lambda: -1.0), ("0", lambda: 0), ("-3.2", lambda: -3.2), ("1e300", lambda: 1e300),
    ("Decimal(nan)", lambda: Decimal("nan")), ("Decimal(1e400)", lambda: Decimal("1e400")),
    ("Decimal(0.3)", lambda: Decimal("0.3")), ("Decimal(snan)", lambda: Decimal("snan")),
    ("masked 0-d", lambda: np.ma.masked_array(0.3, mask=True)),
    ("masked [0.3, 0.5]", lambda: _masked([0.3, 0.5], [False, True])),
    ("unmasked [0.3]", lambda: _masked([0.3], [False])),
    ("array(0.3)", lambda: np.array(0.3)), ("array(nan)", lambda: np.array(math.nan)),
    ("array(10)", lambda: np.array(10)), ("array([])", lambda: np.array([])),
    ("zeros((3, 7))", lambda: np.zeros((3, 7))), ("[]", lambda: []),
    ("[1.0, 2.0]", lambda: [1.0, 2.0]),
    ("()", lambda: ()), ("{}", lambda: {}), ("object()", lambda: object()), ("True", lambda: True),
    ("False", lambda: False), ("1j", lambda: 1j), ("complex(0.3, 0)", lambda: complex(0.3, 0)),
    ("b'x'", lambda: b"x"), ("float64(-2)", lambda: np.float64(-2.0)),
    ("int64 max", lambda: np.int64(2**63 - 1)), ("DISK", lambda: _fixtures()["DISK"]),
    ("GROUND", lambda: _fixtures()["GROUND"]),
)


def _finite_number(value) -> bool:
    """Whether ``value`` is a finite real input (so a NaN out of it would be a bug)."""
    if isinstance(value, (bool, str, bytes)) or value is None:
        return isinstance(value, bool)
    if isinstance(value, Decimal):
        return value.is_finite()
    if isinstance(value, complex):
        return False
    try:
        arr = np.ma.getdata(np.asarray(value))
    except Exception:  # noqa: BLE001 - not an array at all
        return False
    if arr.dtype.kind not in "iuf" or arr.size == 0:
        return arr.dtype.kind in "iuf"
    try:
        return bool(np.all(np.isfinite(arr.astype(float))))
    except OverflowError:
        return False


def _nan_at_a_point(result) -> bool:
    """NaN in a single-point result: a float, a 0-d array or a tuple/list of them."""
    if isinstance(result, (tuple, list)) and 0 < len(result) <= 16:
        return any(_nan_at_a_point(r) for r in result)
    if isinstance(result, (float, np.floating)):
        return math.isnan(result)
    if isinstance(result, np.ndarray) and result.ndim == 0 and result.dtype.kind == "f":
        return bool(np.isnan(result))
    return False


_CACHE: dict = {}


def _fixtures() -> dict:
    """Inputs of the valid calls, built once (a short run of each kind)."""
    if _CACHE:
        return _CACHE
    from rollingdisk.phases import impact as imp
    from rollingdisk.scenarios import euler_disk as ed
    from rollingdisk.theory import exact

    disk = rd.Disk(0.17)
    motion = rd.steady_motion(disk, "rough", theta0=0.5236, r_C=0.5)
    y_rough = np.asarray(motion.initial_state(), dtype=float)
    y_smooth = rd.rolling_state(disk, y_rough)
    ground = rd.Coulomb(0.3)
    free = np.array([0, 0, 1.5, 0, 0.3, 0, 0, 0, 0, 1, 0, 0], dtype=float)
    falling = free.copy()
    falling[2] = disk.h * math.sin(0.3) + math.cos(0.3) - 1e-4  # just below touchdown
    falling[8] = -1.0
    _CACHE.update(
        DISK=disk, MOTION=motion, Y_ROUGH=y_rough, Y_SMOOTH=y_smooth, GROUND=ground,
        FREE=free, FALLING=falling, CONTACT=imp.lowest_point(disk, falling),
        TRAJ=rd.simulate_steady(motion, 2.0, perturb=1e-3),
        CTRAJ=rd.simulate_coulomb(disk, ground, (0.0, 0.3), y_smooth),
        EXACT=exact.exact_steady(motion, kick=0.01),
        TOY=ed.EulerDisk(alpha0=0.3),
        STAB=rd.stability(motion),
    )
    return _CACHE


def calls() -> dict:
    """``"module:name" -> (callable, args, kwargs)``: a valid call of each driven name."""
    f = _fixtures()
    disk, motion, ground = f["DISK"], f["MOTION"], f["GROUND"]
    y_rough, y_smooth, traj = f["Y_ROUGH"], f["Y_SMOOTH"], f["TRAJ"]
    free, falling, toy = f["FREE"], f["FALLING"], f["TOY"]
    si_thresholds = rd.thresholds(rd.Disk.from_dimensions(radius=0.01, thickness=0.002,
                                                          mass=0.005))
    out = {
        "rollingdisk": {
            "Disk": ((0.17,), {"radius": 0.03, "mass": 0.4}),
            "state_names": (("rough",), {}),
            "state_index": (("rough", "theta"), {}),
            "equations_of_motion": ((disk, "rough"), {}),
            "omega_dot": ((disk, "rough", 0.5, 0.1, 0.2, 0.3), {}),
            "contact_force": ((disk, "rough", y_rough), {}),
            "energy": ((disk, "rough", y_rough), {}),
            "contact_point": ((disk, "rough", y_rough), {}),
            "velocity_of_C": ((disk, "rough", y_rough), {}),
            "parse_length": (("3cm",), {"name": "radius"}),
            "parse_mass": (("7.5g",), {"name": "mass"}),
            "parse_acceleration": (("9.81 m/s^2",), {"name": "gravity"}),
            "NamedDisk": (("coin", 0.01, 0.002, 0.005, "test"), {}),
            "disk_from_options": ((), {"diameter": "23.25mm", "thickness": "2.33mm",
                                       "mass": "7.5g"}),
            "si_fields": ((si_thresholds,), {}),
            "steady_motion": ((disk, "rough", 0.5236), {"r_C": 0.5}),
            "straight_line": ((disk, "rough", 2.0), {}),
            "Omega0_sq": ((0.17, 0.5, 0.5), {}),
            "r_C_star": ((0.17, 0.5), {}),
            "se_circle_radius": ((0.17, 0.5), {}),
            "mu_required_map": ((0.17, 0.5, 0.5), {}),
            "Stability": ((0.2,), {}),
            "stability": ((motion,), {}),
            "varpi2_closed_form": ((0.17, "rough", 0.5, -0.2, 0.6), {}),
            "varpi2_linearized": ((motion,), {}),
            "reduced_jacobian": ((0.17, "rough", 0.5, -0.2, 0.6), {}),
            "varpi2_circle": ((0.17, "rough", 0.5, 0.6), {}),
            "varpi2_rough_rC": ((0.17, 0.5, 0.5), {}),
            "circle_coefficients": ((0.17, "rough", 0.5), {}),
            "critical_omega30_sq": ((0.17, "rough", 0.5), {}),
            "stable_for_all_omega30": ((0.17, "rough", 0.5), {}),
            "thresholds": ((0.17,), {}),
            "rounded_steady_motion": ((rd.Disk(0.17, rim_radius=0.05), "rough", 0.5),
                                      {"Omega0": 2.0}),
            "rounded_varpi2": ((rd.Disk(0.17, rim_radius=0.05), "rough", 0.5, -0.2, 0.6), {}),
            "rounded_thresholds": ((rd.Disk(0.17, rim_radius=0.05),), {}),
            "existence_codes": ((0.17, [0.3, 0.5], [0.2, 0.5]), {}),
            "varpi2_zero_surface": ((0.17, "smooth", 0.5), {}),
            "example_motions": ((0.17,), {}),
            "exact_motion": ((disk, "rough", y_rough + [0, 0, 0, 0, 0, 0.01, 0, 0]), {}),
            "exact_steady": ((motion,), {"kick": 0.01}),
            "Trajectory": ((disk, "rough", traj.t, traj.y, "completed", "", 10, 100),
                           {"t_event": 1.0, "wall_time": 0.1}),
            "Transition": ((1.0, "rolling", "sliding"), {}),
            "LiftOff": ((disk, "rough"), {"side": 1.0}),
            "EdgeContact": ((disk, "rough"), {"side": 1.0}),
            "FellFlat": ((disk, "rough"), {"side": 1.0}),
            "guard_events": ((disk, "rough", y_rough), {}),
            "simulate": ((disk, "rough", (0.0, 0.5), y_rough),
                         {"method": "auto", "rtol": 1e-8, "t_eval": [0.0, 0.25, 0.5]}),
            "simulate_steady": ((motion, 0.5), {"perturb": 1e-3, "method": "auto"}),
            "energy_drift": ((traj,), {}),
            "oscillation_frequency": ((traj,), {"min_periods": 2}),
            "growth_rate": ((traj,), {"max_amplitude": 1e-6}),
            "fit_circle": (([1.0, 0.0, -1.0, 0.0], [0.0, 1.0, 0.0, -1.0]), {}),
            "compare_with_theory": ((traj,), {"stability": f["STAB"]}),
            "coulomb_rhs": ((disk, ground, "rolling", y_smooth), {}),
            "coulomb_contact": ((disk, ground, "rolling", y_smooth), {}),
            "coulomb_energy": ((disk, y_smooth), {}),
            "rolling_state": ((disk, y_rough), {}),
            "Coulomb": ((0.3,), {"mu_k": 0.2, "rolling_resistance": rd.RollingResistance(1e-3),
                                 "pivot": rd.PivotFriction(1e-3), "air": rd.AirDrag(1e-3)}),
            "RollingResistance": ((1e-3,), {}),
            "PivotFriction": ((1e-3,), {}),
            "AirDrag": ((1e-3,), {}),
            "angular_velocity_xyz": ((0.5, 0.1, 0.2, 0.3), {}),
            "simulate_coulomb": ((disk, ground, (0.0, 0.2), y_smooth), {"max_steps": 200}),
            "slip_direction": ((disk, ground, y_smooth), {}),
            "energy_balance": ((f["CTRAJ"],), {}),
            "simulate_to_rest": ((disk, ground, (0.0, 0.5), free), {"e": 0.5, "max_wall": 5.0}),
            "toss": ((disk, 1.5, 0.0, 1.0, 0.3), {"e": 0.5, "t_end": 0.5}),
            "toss_ensemble": ((disk, 2, 0), {"t_end": 0.5, "max_wall": 5.0,
                                             "results": "toss.jsonl"}),
            "edge_odds": (((0.3,), 1, 0), {"e": 0.5, "mu": 0.5, "max_wall": 5.0,
                                            "t_end": 0.5, "results": "edge-odds"}),
        },
        "rollingdisk.sweep": {
            "SweepGrid": (("rough",), {"h": (0.17,), "theta0": (0.3, 0.5),
                                      "omega30": (1.0, 2.0)}),
            "Perturbation": ((), {"kick": (1e-3,), "tilt": (0.0,)}),
            "run_sweep": ((_grid(), 0.5), {"out": "s.zarr", "chunk": 4, "rtol": 1e-6,
                                          "atol": 1e-6, "max_steps": 10_000}),
            "basin_sweep": ((_grid(), 0.5), {"kick_max": 0.1, "rounds": 2, "chunk": 4,
                                            "out": "b.zarr"}),
            "open_sweep": (("s.zarr",), {}),
        },
        "rollingdisk.plotting": {
            "check_dpi": ((110,), {}),
            "image_format": (("x.png",), {}),
            "trajectory_series": ((traj, "theta"), {}),
            "body_frame": ((0.1, 0.5), {}),
            "disk_pose": ((0.17, 0.0, 0.0, 0.1, 0.5, 0.2), {"n": 16, "Z_C": 0.6}),
            "poses": ((traj,), {"n_frames": 4, "n": 8}),
            "check_animation": ((), {"n_frames": 60, "fps": 15, "dpi": 70, "size": (5.0, 4.4)}),
            "writer_for": (("a.gif", 15), {}),
        },
        "rollingdisk.theory.exact": {
            "exact_motion": ((disk, "rough", y_rough + [0, 0, 0, 0, 0, 0.01, 0, 0]),
                             {"time_limit": 5.0, "max_evals": 20_000, "max_terms": 1024}),
            "exact_steady": ((motion,), {"perturb": 0.0, "kick": 0.01, "psi0": 0.0,
                                         "phi0": 0.0}),
            "backbone": ((motion, [0.01, 0.02]), {}),
            "thin_disk_omega3": ((0.4, 0.5, 0.1, 0.3), {}),
        },
        "rollingdisk.scenarios.euler_disk": {
            "EulerDisk": ((), {"radius": 0.0375, "thickness": 0.0127, "mass": 0.45,
                               "mu": 0.3, "creep": 1000.0, "rolling_resistance": 5e-4,
                               "air_viscosity": 1.81e-5, "alpha0": 0.3, "omega_eps": 1e-6}),
            "run_euler_disk": ((toy,), {"alpha_end": 0.1, "t_max": 50.0, "max_steps": 20_000,
                                        "max_wall_time": 10.0, "fit_window": (0.002, 0.02),
                                        "predict": False, "kick": 0.0}),
            "predicted_exponents": ((toy,), {"window": (0.002, 0.02), "n": 8}),
            "creep_factor": ((0.01, 0.1), {}),
            "predicted_end_time": ((toy,), {"alpha_end": 1e-3}),
            "dissipation_laws": ((toy,), {}),
        },
        "rollingdisk.scenarios.toss": {
            "toss": ((disk, 1.5, 0.0, 1.0, 0.3), {"e": 0.5, "mu": 0.5, "t_end": 0.5,
                                                  "max_wall": 5.0}),
            "TossDistribution": ((), {"lift": (0.5, 2.5), "velocity": (0.0, 4.0),
                                      "spin": (-10.0, 10.0)}),
            "toss_ensemble": ((disk, 2, 0), {"t_end": 0.5, "max_wall": 5.0, "e": 0.5,
                                             "results": "toss.jsonl"}),
            "energy_barrier": ((0.17,), {}),
        },
        "rollingdisk.phases.flight": {
            "free_flight": ((disk, free, 0.1), {}),
            "free_energy": ((disk, free), {}),
            "angular_momentum": ((disk, free), {"about": [0.0, 0.0, 0.0]}),
            "lowest_point": ((disk, free), {"tol": 1e-12}),
            "touchdown_time": ((disk, free), {"inside_tol": 1e-12}),
        },
        "rollingdisk.phases.impact": {
            "contact_delassus": ((disk, 0.3), {"side": 1, "cos_sign": 1}),
            "impact": ((disk, falling, f["CONTACT"], 0.5, 0.3), {"mode_tol": 1e-9}),
            "rim_change_ratio": ((0.17,), {}),
            "free_state_from_rolling": ((disk, "rough", y_rough), {}),
            "rolling_state_from_free": ((disk, "rough", _free_of(disk, y_rough)),
                                        {"atol": 1e-9}),
        },
        "rollingdisk.phases.motion": {
            "simulate_to_rest": ((disk, ground, (0.0, 0.5), free),
                                 {"e": 0.5, "max_wall": 5.0, "max_segments": 200,
                                  "alpha_flat": 1e-3, "v_capture": 1e-3, "rtol": 1e-8,
                                  "atol": 1e-10}),
            "ModeChange": ((0.1, "rolling", "sliding"), {}),
            "flat_friction": ((0.1, 0.2), {}),
        },
        "rollingdisk.results": {
            "energy_drift": ((traj,), {}),
            "oscillation_frequency": ((traj,), {"min_periods": 2}),
            "growth_rate": ((traj,), {"theta_ref": 0.5236, "max_amplitude": 1e-6}),
            "fit_circle": (([1.0, 0.0, -1.0, 0.0], [0.0, 1.0, 0.0, -1.0]), {}),
            "compare_with_theory": ((traj,), {"stability": f["STAB"]}),
            "Transition": ((1.0, "rolling", "sliding"), {}),
        },
        "rollingdisk.model": {
            "check_ground": (("rough",), {}),
            "check_h": ((0.17,), {}),
            "h_tilde": ((0.17, 0.5), {}),
            "check_any_ground": ((ground,), {}),
            "ground_name": ((ground,), {}),
        },
    }
    table = {}
    for module, names in out.items():
        mod = importlib.import_module(module)
        for name, (args, kwargs) in names.items():
            table[f"{module}:{name}"] = (getattr(mod, name), args, kwargs)
    return table


def _grid():
    from rollingdisk.sweep import SweepGrid

    return SweepGrid("rough", h=(0.17,), theta0=(0.5,), omega30=(1.0, 2.0))


def _free_of(disk, y):
    from rollingdisk.phases import impact as imp

    return imp.free_state_from_rolling(disk, "rough", y)


#: Public callables not driven, and why (a name is driven once, where it is defined).
SKIPPED_KINDS = {
    "an exception class": ("ParameterError", "ParameterTypeError", "NoSteadyMotion"),
    "takes no arguments (and compiles for a minute)": ("jit_compile",),
    "a result record, built by the function that returns it": (
        "SteadyMotion", "Thresholds", "ExampleMotions", "ExactMotion", "TheoryComparison",
        "GuardEvent", "Backbone", "EulerDiskResult", "TossResult", "EnsembleResult",
        "LowestPoint", "ImpactResult", "MotionResult", "FlightSegment", "FlatSegment",
        "ImpactRecord", "DiskPose", "MapPlot"),
    "draws with matplotlib (slow; its arguments are checked by the helpers driven here)": (
        "save_figure", "plot_existence_map", "plot_stability_map", "plot_all_omega30_stable",
        "plot_varpi2_surface", "plot_varpi2_curves", "plot_paths", "plot_theta",
        "plot_energy_error", "plot_contact_forces", "plot_trajectory", "plot_euler_disk",
        "plot_nonlinear_map", "plot_basin_map", "plot_exact_theta", "plot_rosette",
        "plot_backbone", "plot_exact", "figure4", "figure5", "figure6", "figure7", "figure8",
        "paper_figures", "draw_disk", "animate", "animation_html", "plot_edge_odds"),
}
SKIPPED = {name: why for why, names in SKIPPED_KINDS.items() for name in names}


def public_callables() -> list[str]:
    """``"module:name"`` of every public class or function of :data:`MODULES`, each once
    (under the first module that lists it; a re-export is the same object)."""
    seen, out = set(), []
    for module in MODULES:
        mod = importlib.import_module(module)
        for name in mod.__all__:
            obj = getattr(mod, name)
            if not (inspect.isfunction(obj) or inspect.isclass(obj)):
                continue
            if id(obj) in seen:
                continue
            seen.add(id(obj))
            out.append(f"{module}:{name}")
    return out


def slots(args, kwargs) -> list:
    return [("arg", i) for i in range(len(args))] + [("kw", k) for k in kwargs]


def one_call(target: str, slot, label: str, table: dict):
    """Call ``target`` with the hostile value ``label`` in ``slot``; return ``None`` when the
    contract holds, else a line saying how it broke."""
    func, args, kwargs = table[target]
    value = dict(HOSTILE)[label]()
    args, kwargs = list(args), dict(kwargs)
    if slot[0] == "arg":
        args[slot[1]] = value
    else:
        kwargs[slot[1]] = value
    where = f"{target}({slot[1]}={label})"
    try:
        result = func(*args, **kwargs)
    except (TypeError, ValueError):
        return None
    except decimal.DecimalException as exc:  # not a ValueError subclass in every case
        return f"{where}: {type(exc).__name__}: {exc}"
    except Exception as exc:  # noqa: BLE001 - the point of the test
        return f"{where}: {type(exc).__name__}: {str(exc)[:120]}"
    if _finite_number(value) and _nan_at_a_point(result):
        return f"{where}: NaN from finite input"
    return None


def sample(seed: int, n: int, table: dict, names=None):
    """``n`` seeded ``(target, slot, label)`` triples, spread evenly over the targets."""
    rng = random.Random(seed)
    names = sorted(table) if names is None else names
    labels = [label for label, _ in HOSTILE]
    for k in range(n):
        target = names[k % len(names)]
        _, args, kwargs = table[target]
        yield target, rng.choice(slots(args, kwargs)), rng.choice(labels)
