"""The whirr of Euler's disk as a WAV file (rollingdisk.plotting.sound, ``euler-disk
--sound``).

The truth is the run itself: the number of cycles the file holds over a window is the
integral of ``Omega / (2 pi)`` over the run times that window stands for (computed here by
the trapezoidal rule on the run's own steps), counted by zero crossings of the pure tone
and found as the peak of a short-window FFT of the default tone; the file is read back with
the standard library's ``wave``.
"""

import dataclasses
import json
import math
import wave

import numpy as np
import pytest

from rollingdisk.cli.app import main
from rollingdisk.plotting.sound import (
    NYQUIST_FADE,
    chirp,
    plot_chirp_frequency,
    read_wav,
    sound_window,
    write_wav,
)
from rollingdisk.scenarios.euler_disk import EulerDisk, run_euler_disk
from rollingdisk.util.errors import ParameterError

RATE = 22050
SPEED = 2.0  # time-compressed: one second of sound is two of the run
#: A short run (started low, 10 times the toy's rolling resistance): 3.7 s, 22 -> 160 Hz.
FAST = dict(alpha0=0.05, rolling_resistance=5e-3)


@pytest.fixture(scope="module")
def run():
    r = run_euler_disk(EulerDisk(**FAST), predict=False)
    assert r.end == "fell-flat"
    return r


def _hz(r):
    unit = r.toy.time_unit
    return r.t * unit, r.Omega / (2 * math.pi * unit)


def _mean_frequency(r, t_a, t_b):
    """Mean of Omega/2pi over run times [t_a, t_b] [s] (trapezoidal on the run's steps)."""
    t, f = _hz(r)
    grid = np.concatenate([[t_a], t[(t > t_a) & (t < t_b)], [t_b]])
    fg = np.interp(grid, t, f)
    return float(np.sum(0.5 * (fg[1:] + fg[:-1]) * np.diff(grid)) / (t_b - t_a))


def _zero_crossings(x, rate):
    """Times [s] of the upward zero crossings (linearly interpolated)."""
    i = np.flatnonzero((x[:-1] < 0) & (x[1:] >= 0))
    return (i + x[i] / (x[i] - x[i + 1])) / rate


def _fft_peak(x, rate):
    w = x * np.hanning(x.size)
    spec = np.abs(np.fft.rfft(w, 1 << 18))
    k = int(np.argmax(spec))
    a, b, c = np.log(spec[k - 1:k + 2])  # parabolic interpolation of the log peak
    return (k + 0.5 * (a - c) / (a - 2 * b + c)) * rate / (1 << 18)


def test_wav_round_trip_and_frequency_at_two_instants(run, tmp_path):
    t_start, t_end = sound_window(run, SPEED)
    assert (t_start, t_end) == (0.0, pytest.approx(run.t_end_s))
    path = tmp_path / "chirp.wav"
    x = chirp(run, rate=RATE, speed=SPEED)
    assert x.size == math.floor(run.t_end_s * RATE / SPEED) + 1
    assert np.max(np.abs(x)) <= 1.0
    write_wav(path, x, RATE)
    # valid PCM: RIFF/WAVE, mono, 16 bit, uncompressed, every sample there
    raw = path.read_bytes()
    assert raw[:4] == b"RIFF" and raw[8:12] == b"WAVE"
    with wave.open(str(path), "rb") as w:
        assert (w.getnchannels(), w.getsampwidth(), w.getframerate(), w.getcomptype(),
                w.getnframes()) == (1, 2, RATE, "NONE", x.size)
    y, rate = read_wav(path)
    assert rate == RATE and np.max(np.abs(y - x)) <= 0.5 / 32767 + 1e-12
    assert not list(tmp_path.glob(".*tmp*"))  # written atomically: nothing left behind
    pure = chirp(run, rate=RATE, speed=SPEED, harmonics=(1.0,))
    t, f = _hz(run)
    for target in (50.0, 120.0):
        t_run = float(np.interp(target, f, t))  # f rises monotonically on this run
        k, half = int(round(t_run / SPEED * RATE)), int(8 / target * RATE)  # 8 cycles a side
        # the pure tone: cycles between the first and the last upward zero crossing of the
        # window, against the integral of Omega/2pi over the run times they stand for
        tc = (k - half) / RATE + _zero_crossings(pure[k - half:k + half], RATE)
        zc = (tc.size - 1) / (tc[-1] - tc[0])
        assert zc == pytest.approx(_mean_frequency(run, tc[0] * SPEED, tc[-1] * SPEED),
                                   rel=1e-4)
        # the file (harmonics on): its short-window spectrum peaks at the fundamental
        want = _mean_frequency(run, (k - half) * SPEED / RATE, (k + half) * SPEED / RATE)
        assert _fft_peak(y[k - half:k + half], RATE) == pytest.approx(want, rel=0.02)


def test_long_run_keeps_its_end(run):
    x = chirp(run, rate=8000, speed=1.0, max_seconds=1.0)
    assert x.size == 8001
    t_start, t_end = sound_window(run, 1.0, 1.0)
    assert t_end - t_start == pytest.approx(1.0)
    # the last quarter second: the end of the run, the highest pitch
    want = _mean_frequency(run, t_end - 0.25, t_end)
    tc = _zero_crossings(chirp(run, 8000, 1.0, 1.0, harmonics=(1.0,))[-2000:], 8000)
    assert (tc.size - 1) / (tc[-1] - tc[0]) == pytest.approx(want, rel=0.03)


def test_frequencies_above_nyquist_are_silent(run):
    """Omega scaled up 60 times (9.6 kHz at the end) at 8 kHz sampling: where the tone
    passes 0.95 of the Nyquist frequency (4 kHz) the file is silent, not aliased."""
    fast = dataclasses.replace(run, Omega=run.Omega * 60.0)
    x = chirp(fast, rate=8000, speed=1.0, harmonics=(1.0,))
    t, f = _hz(fast)
    ts = np.arange(x.size) / 8000
    fs = np.interp(ts, t, f)
    assert fs.max() > 8000
    assert np.all(x[fs > NYQUIST_FADE[1] * 4000] == 0.0)
    assert np.max(np.abs(x[fs < 0.5 * 4000])) > 0.1


@pytest.mark.parametrize("kw, name", [
    ({"speed": 0.0}, "speed"), ({"speed": -2.0}, "speed"), ({"speed": math.nan}, "speed"),
    ({"rate": 100}, "rate"), ({"rate": 10**6}, "rate"), ({"max_seconds": 0.0}, "max_seconds"),
    ({"harmonics": (0.0, 1.0)}, "harmonics"),
])
def test_bad_chirp_input(run, kw, name):
    with pytest.raises(ParameterError, match=name):
        chirp(run, **kw)


def test_bad_input_types(run, tmp_path):
    with pytest.raises(TypeError, match="result"):
        chirp(3)
    with pytest.raises(TypeError, match="rate"):
        chirp(run, rate="fast")
    with pytest.raises(ParameterError, match="rate"):
        write_wav(tmp_path / "a.wav", np.zeros(10), 7999)
    for bad in (np.zeros((2, 3)), np.array([0.0, math.nan]), np.zeros(0)):
        with pytest.raises(ParameterError, match="samples"):
            write_wav(tmp_path / "a.wav", bad, 8000)
    with pytest.raises(ParameterError, match="path"):
        write_wav(tmp_path / "missing" / "a.wav", np.zeros(10), 8000)
    assert not (tmp_path / "a.wav").exists()


def test_frequency_plot(run):
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib.figure import Figure

    out = plot_chirp_frequency(run, Figure(), speed=SPEED)
    x, y = out["lines"]["frequency"].get_data()
    t, f = _hz(run)
    np.testing.assert_allclose(np.interp(run.t_end_s + x, t, f), y, rtol=1e-9)
    assert x[-1] == pytest.approx(0.0, abs=1e-12) and y[-1] == pytest.approx(f[-1])


CLI = ["euler-disk", "--quiet", "--alpha0", "0.05", "--rolling-resistance", "5e-3a"]


def test_cli_sound_and_air_laws(tmp_path, capsys):
    wav = tmp_path / "chirp.wav"
    # air runs fit over alpha in (0.01, 0.05): started at 0.08
    air = [*CLI, "--alpha0", "0.08"]
    assert main([*air, "--air", "--json", "--sound", str(wav), "--sound-speed", "4"]) == 0
    s = json.loads(capsys.readouterr().out)
    assert s["sound"] == str(wav) and s["parameters"]["air_law"] == "film"
    assert s["parameters"]["c_air"] > 0 and s["parameters"]["c_boundary_layer"] == 0
    y, rate = read_wav(wav)
    assert rate == 44100 and y.size == math.floor(s["t_end_s"] * rate / 4) + 1
    assert main([*air, "--air", "boundary-layer", "--json"]) == 0
    s = json.loads(capsys.readouterr().out)
    assert s["parameters"]["air_law"] == "boundary-layer"
    assert s["parameters"]["c_boundary_layer"] > 0 and s["dissipated"]["air"] > 0


@pytest.mark.parametrize("argv, word", [
    (["--air", "moffatt"], "--air"), (["--sound-speed", "0"], "sound_speed"),
    (["--sound", "/nonexistent-folder/x.wav"], "--sound"),
])
def test_cli_bad_sound_input_exit_2(capsys, argv, word):
    assert main([*CLI, *argv]) == 2
    err = capsys.readouterr().err
    assert len(err.strip().splitlines()) == 1 and word in err and "Traceback" not in err
