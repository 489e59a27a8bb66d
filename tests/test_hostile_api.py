"""Hostile input to every public function: only TypeError or ValueError may come out.

Each public callable of every public subpackage that takes arguments is called with
sensible valid arguments (one table, :func:`hostile_calls.calls`), then with one argument
at a time replaced by a hostile value (None, a string, NaN, infinities, an int beyond
floating-point range, a negative number, an empty list, a wrong-shaped array, a Disk or a
ground where a number is expected, ...).
The call may succeed (vectorized formulas may return NaN outside their domain) or raise a
``TypeError`` or ``ValueError`` (the library's ``ParameterTypeError`` and
``ParameterError`` subclass them); an ``AttributeError``, ``IndexError``,
``OverflowError``, ``ZeroDivisionError``, ... is a bug (issue 18, item 7).
"""

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import hostile_calls as hc
import rollingdisk as rd

# hostile values may take a vectorized formula outside floating-point range: NaN, not an error
pytestmark = pytest.mark.filterwarnings("ignore::RuntimeWarning")

#: The driven names of ``rollingdisk.__all__``: ``"rollingdisk:name"`` of the one table.
ROOT = sorted(t for t in hc.calls() if t.startswith("rollingdisk:"))
#: Results of runs, hostile where a number, a disk or a ground is expected: with the values
#: of :data:`hostile_calls.HOSTILE`, what the hypothesis search below puts in.
RUNS = (("MOTION", lambda: hc._fixtures()["MOTION"]), ("TRAJ", lambda: hc._fixtures()["TRAJ"]))


@pytest.mark.parametrize("target", ROOT)
@settings(max_examples=120, deadline=None, derandomize=True,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])
@given(data=st.data())
def test_hostile_argument_raises_only_type_or_value_errors(target, table, tmp_path, monkeypatch,
                                                           data):
    monkeypatch.chdir(tmp_path)  # outputs named by hostile values land here
    func, args, kwargs = table[target]
    kind, key = data.draw(st.sampled_from(hc.slots(args, kwargs)), label="slot")
    _, make = data.draw(st.sampled_from(hc.HOSTILE + RUNS), label="hostile value")
    args, kwargs = list(args), dict(kwargs)
    if kind == "arg":
        args[key] = make()
    else:
        kwargs[key] = make()
    try:
        func(*args, **kwargs)
    except (TypeError, ValueError):
        pass


def test_simulate_y0_beyond_floating_point_range():
    y0 = list(hc._fixtures()["Y_ROUGH"])
    y0[0] = 10**400
    with pytest.raises(ValueError, match="y0"):
        rd.simulate(hc._fixtures()["DISK"], "rough", (0.0, 0.5), y0)


# ---------------------------------------------------------------------------------------
# every public name of every public subpackage (issue 36): tests/hostile_calls.py
# ---------------------------------------------------------------------------------------

#: Targets whose contract is known to break (none today), each with a case below that
#: xfails while it breaks and fails once it is fixed: target -> (reason, a breaking (slot,
#: value)); the arguments in PENDING_SLOTS (all of them where a target is not there) are
#: left out of the runs above, its other arguments are held like everything else.
PENDING_TARGETS: dict = {}
PENDING_SLOTS: dict = {}

#: Targets where NaN at a single point is a documented answer, not a refusal.
NAN_ANSWERS = {
    "rollingdisk:critical_omega30_sq": "NaN = no positive root: stable for every omega30",
    "rollingdisk:varpi2_zero_surface": "NaN = no positive root (critical_omega30_sq)",
}


@pytest.fixture(scope="module")
def table(tmp_path_factory):
    """The valid calls, with a sweep store to open (a tiny dataset: open_sweep loads any)."""
    import xarray as xr

    calls = hc.calls()
    store = tmp_path_factory.mktemp("store") / "s.zarr"
    xr.Dataset({"x": ("i", [1.0, 2.0])}).to_zarr(store)
    func, _, kwargs = calls["rollingdisk.sweep:open_sweep"]
    calls["rollingdisk.sweep:open_sweep"] = (func, (str(store),), kwargs)
    return calls


def _broken(table, triples):
    out = []
    for target, slot, label in triples:
        if target in PENDING_TARGETS and slot in PENDING_SLOTS.get(target, {slot}):
            continue
        why = hc.one_call(target, slot, label, table)
        if why and not (target in NAN_ANSWERS and why.endswith("NaN from finite input")):
            out.append(why)
    return out


def test_every_public_name_of_every_subpackage_is_driven_or_skipped(table):
    missing = [n for n in hc.public_callables()
               if n not in table and n.split(":")[1] not in hc.SKIPPED]
    assert missing == []
    assert not set(PENDING_TARGETS) - set(table)


def test_valid_calls_of_the_subpackages_work(table, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    slow = {"rollingdisk.sweep:run_sweep", "rollingdisk.sweep:basin_sweep"}
    for target, (func, args, kwargs) in sorted(table.items()):
        if target not in slow:
            func(*args, **kwargs)


@pytest.mark.filterwarnings("ignore")
def test_a_seeded_sample_of_hostile_calls_keeps_the_contract(table, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)  # outputs named by hostile values land here
    heavy = {"rollingdisk.sweep:run_sweep", "rollingdisk.sweep:basin_sweep"}
    names = [n for n in sorted(table) if n not in heavy]
    assert _broken(table, hc.sample(20261128, 3 * len(names), table, names)) == []


@pytest.mark.slow
@pytest.mark.filterwarnings("ignore")
def test_every_hostile_value_in_every_argument_of_every_subpackage(table, tmp_path,
                                                                   monkeypatch):
    """The whole product: every driven target x argument x hostile value (>= 10,000 calls,
    deterministic): 0 exceptions but TypeError/ValueError, 0 NaN at a point from finite
    input."""
    monkeypatch.chdir(tmp_path)
    triples = [(target, slot, label) for target in sorted(table)
               for slot in hc.slots(*table[target][1:])
               for label, _ in hc.HOSTILE]
    assert len(triples) >= 10_000
    broken = _broken(table, triples)
    assert broken == [], f"{len(broken)} of {len(triples)} calls:\n" + "\n".join(broken[:60])


@pytest.mark.parametrize("target", sorted(PENDING_TARGETS))
def test_pending_cases_still_break(target, table, tmp_path, monkeypatch):
    reason, (slot, label) = PENDING_TARGETS[target]
    monkeypatch.chdir(tmp_path)
    if hc.one_call(target, slot, label, table) is not None:
        pytest.xfail(reason)
    pytest.fail(f"{target} now keeps the contract: drop it from PENDING_TARGETS ({reason})")


@pytest.mark.parametrize(("h", "theta0"), [(0.17, 0.5), (0.17, 0.05), (2.0, 1.2), (0.0, 0.3),
                                           (0.17, -0.4)])
def test_the_refused_radii_are_exactly_those_without_a_circle(h, theta0):
    """The range a refusal of ``varpi2_rough_rC`` names is the set where eq. (31) gives
    ``Omega0^2 > 0``: checked on the map (arrays in, NaN marks) at radii either side."""
    star = float(rd.r_C_star(h, theta0))
    for r in (star - 1.0, star - 1e-3, star + 1e-3, star + 1.0):
        positive = float(rd.Omega0_sq(np.array([h]), theta0, r)[0]) > 0
        try:
            rd.varpi2_rough_rC(h, theta0, r)
            refused = None
        except ValueError as exc:
            refused = str(exc)
        assert (refused is None) == positive, (r, refused)
        if refused:
            side = ">" if "r_C >" in refused else "<"
            assert (r > star) != (side == ">"), refused  # r lies on the refused side
