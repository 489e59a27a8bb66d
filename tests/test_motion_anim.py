"""The drawn whole motion (plotting/motion_anim.py) against independent truth.

Sources of truth: the ballistic centre in flight, ``R_C(t) = R_C(t0) + V (t - t0) -
(t - t0)^2/2 Z`` (g = 1); the contact constraint on a rim edge, the lowest point of the
cylinder at height 0 (``Z_C = sqrt(1 - eta_Z^2) + h |eta_Z|``, eq. 7); a disk lying flat
has ``Z_C = h`` and a vertical axis; no drawn point goes below the plane.
"""

import math

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402

import rollingdisk as rd  # noqa: E402
from rollingdisk.phases.motion import (  # noqa: E402
    FlatSegment,
    FlightSegment,
    simulate_to_rest,
)
from rollingdisk.plotting.motion_anim import (  # noqa: E402
    animate_motion,
    motion_paths,
    motion_phases,
    motion_poses,
)
from rollingdisk.util.errors import ParameterError, ParameterTypeError  # noqa: E402

H = 0.3
N_FRAMES = 400


@pytest.fixture(scope="module")
def result():
    """A thick disk dropped tilted: flights, bounces, a contact phase, falls flat, rests."""
    s0 = [0.0, 0.0, 1.6, 0.0, 0.12, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]
    res = simulate_to_rest(rd.Disk(H), rd.Coulomb(0.5), (0.0, 100.0), s0, e=0.3)
    kinds = {type(s) for s in res.segments}
    assert res.status == "at-rest" and FlightSegment in kinds and FlatSegment in kinds
    assert len(kinds) == 3  # a contact Trajectory too
    return res


@pytest.fixture(scope="module")
def frames(result):
    return motion_poses(result, N_FRAMES)


def _inside(result, cls):
    """``(segment, t0, t1)`` of the segments of class ``cls`` (None: contact)."""
    out = []
    for s in result.segments:
        if isinstance(s, FlightSegment):
            span, c = (s.t0, s.t1), FlightSegment
        else:
            span, c = (float(s.t[0]), float(s.t[-1])), type(s)
        if (cls is None and c not in (FlightSegment, FlatSegment)) or c is cls:
            out.append((s, *span))
    return out


def test_times_even_over_the_run(result, frames):
    tf, poses = frames
    assert len(poses) == tf.size == N_FRAMES
    assert tf[0] == 0.0 and tf[-1] == result.t_end
    assert np.allclose(np.diff(tf), result.t_end / (N_FRAMES - 1), rtol=0, atol=1e-12)


def test_flight_is_ballistic(result, frames):
    tf, poses = frames
    n = 0
    for seg, t0, t1 in _inside(result, FlightSegment):
        s0 = seg.state0
        for i in np.nonzero((tf > t0) & (tf < t1))[0]:
            tau = tf[i] - t0
            want = [s0[0] + s0[6] * tau, s0[1] + s0[7] * tau,
                    s0[2] + s0[8] * tau - 0.5 * tau * tau]
            assert np.allclose(poses[i].center, want, rtol=0, atol=1e-12)
            n += 1
    assert n >= 20


def _lowest(pose):
    ez = pose.axis[2]
    return pose.center[2] - H * abs(ez) - math.sqrt(max(0.0, 1.0 - ez * ez))


def test_contact_touches_the_plane(result, frames):
    tf, poses = frames
    n = 0
    for _, t0, t1 in _inside(result, None):
        for i in np.nonzero((tf > t0) & (tf < t1))[0]:
            assert abs(_lowest(poses[i])) <= 1e-9
            assert abs(poses[i].contact[2]) <= 1e-9
            n += 1
    assert n >= 20


def test_flat_lies_on_its_face(result, frames):
    tf, poses = frames
    n = 0
    for _, t0, t1 in _inside(result, FlatSegment):
        for i in np.nonzero((tf > t0) & (tf <= t1))[0]:
            assert poses[i].center[2] == pytest.approx(H, abs=1e-12)
            assert abs(poses[i].axis[2]) == pytest.approx(1.0, abs=1e-12)
            n += 1
    assert n >= 3
    # the last frame (at rest) is the final state
    assert np.allclose(poses[-1].center, result.final_state[:3], atol=1e-12)


def test_nothing_below_the_plane(frames):
    _, poses = frames
    for p in poses:
        assert p.rims[:, 2].min() >= -1e-9
        assert _lowest(p) >= -1e-9


def test_phases_and_paths(result, frames):
    tf, _ = frames
    ph = motion_phases(result, tf)
    assert ph[0] == "flight" and ph[-1] == "rest" and "flat" in ph
    t, XP, YP, XC, YC = motion_paths(result)
    assert np.all(np.diff(t) >= 0.0)
    # P exists only on a rim edge: NaN in flight
    fl = _inside(result, FlightSegment)[0]
    inside = (t > fl[1]) & (t < fl[2])
    assert inside.any() and np.all(np.isnan(XP[inside])) and np.all(np.isfinite(XC[inside]))


def test_gif_is_whole(result, tmp_path):
    from PIL import Image

    out = animate_motion(result, tmp_path / "m.gif", n_frames=5, fps=5, dpi=30,
                         title="drop")
    assert out.is_file()
    with Image.open(out) as im:
        assert im.n_frames == 5
    assert sorted(p.name for p in tmp_path.iterdir()) == ["m.gif"]  # no temporary left


def test_bad_input_is_named(result, tmp_path):
    with pytest.raises(ParameterTypeError, match="result"):
        motion_poses("not a result")
    with pytest.raises(ParameterError, match="n_frames"):
        motion_poses(result, 1)
    with pytest.raises(ParameterError, match="out"):
        animate_motion(result, tmp_path / "m.txt", n_frames=2)
    with pytest.raises(ParameterError, match="fps"):
        animate_motion(result, tmp_path / "m.gif", n_frames=2, fps=0)
    with pytest.raises(ParameterTypeError, match="result"):
        animate_motion(None, tmp_path / "m.gif")
    assert list(tmp_path.iterdir()) == []
