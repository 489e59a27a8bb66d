"""Degenerate and invalid inputs: clear ValueErrors naming the parameter and the range."""

import math

import numpy as np
import pytest

import rollingdisk as rd


@pytest.mark.parametrize("bad", [-1, -1e-9, math.nan, math.inf, -math.inf, 1e200])
def test_disk_rejects_bad_h_value(bad):
    with pytest.raises(rd.ParameterError, match=r"h must .*\[0, 1e\+08\]"):
        rd.Disk(h=bad)


@pytest.mark.parametrize("bad", ["0.2", None, True, [0.1], 1j])
def test_disk_rejects_bad_h_type(bad):
    """A wrong type is a TypeError, as in numpy and scipy (issue 8, defect 3)."""
    with pytest.raises(rd.ParameterTypeError, match=r"h must .*\[0, 1e\+08\]"):
        rd.Disk(h=bad)


@pytest.mark.parametrize("name", ["radius", "mass", "gravity"])
@pytest.mark.parametrize("bad", [0.0, -1.0, math.nan, math.inf, "x"])
def test_disk_rejects_bad_scale(name, bad):
    with pytest.raises((ValueError, TypeError), match=name):
        rd.Disk(h=0.1, **{name: bad})


def test_disk_accepts_numpy_scalars_and_zero():
    assert rd.Disk(np.float64(0.5)).h == 0.5
    assert rd.Disk(0).h == 0.0
    assert isinstance(rd.Disk(np.int64(2)).h, float)


def test_disk_is_frozen():
    disk = rd.Disk(0.2)
    with pytest.raises(AttributeError):
        disk.h = 0.3


@pytest.mark.parametrize("bad", ["icy", "", None, "Rough"])
def test_unknown_ground(bad):
    disk = rd.Disk(0.1)
    with pytest.raises(ValueError, match=r"ground must be one of \('rough', 'smooth'\)"):
        rd.equations_of_motion(disk, bad)
    with pytest.raises(ValueError, match="ground"):
        rd.contact_force(disk, bad, np.zeros(8))


def test_wrong_state_length():
    with pytest.raises(ValueError, match="y must have 10 components on smooth ground"):
        rd.energy(rd.Disk(0.1), "smooth", np.zeros(8))


def test_units_need_a_scale_and_convert_consistently():
    disk = rd.Disk(0.1)
    with pytest.raises(ValueError, match="radius"):
        disk.length_to_si(1.0)
    coin = rd.Disk.from_dimensions(radius=0.05, thickness=0.01, mass=0.4, gravity=9.81)
    assert coin.h == pytest.approx(0.1)
    T = coin.time_unit
    assert T == pytest.approx(math.sqrt(0.05 / 9.81))
    # speed = length / time, angular speed = 1 / time, energy = force * length
    assert coin.speed_to_si(1.0) == pytest.approx(coin.length_to_si(1.0) / coin.time_to_si(1.0))
    assert coin.angular_speed_to_si(2.0) == pytest.approx(2.0 / T)
    assert coin.energy_to_si(1.0) == pytest.approx(coin.force_to_si(1.0) * coin.length_to_si(1.0))
    assert coin.force_to_si(1.0) == pytest.approx(0.4 * 9.81)


def test_h_tilde_and_static_equilibrium():
    disk = rd.Disk(0.3)
    assert disk.h_tilde(0.2) == 0.3 and disk.h_tilde(-0.2) == -0.3
    y_P, _ = disk.contact_point_xyz(disk.static_equilibrium_theta)
    assert abs(y_P) < 1e-15  # P right below C in the SE position (Figure 3b)


@pytest.mark.parametrize("measure", [rd.energy_drift, rd.oscillation_frequency, rd.growth_rate])
@pytest.mark.parametrize("bad", [None, 1.0, "traj", np.zeros((8, 3))])
def test_measurements_need_a_trajectory(measure, bad):
    """A measurement given anything but a Trajectory is a TypeError naming traj."""
    with pytest.raises(rd.ParameterTypeError, match="traj must be a rollingdisk.Trajectory"):
        measure(bad)
