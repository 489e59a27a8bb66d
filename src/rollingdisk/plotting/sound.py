"""The whirr of Euler's disk as sound: a tone at the contact point's precession frequency.

The contact point of a disk rolling in place runs round its circle at the precession rate
``Omega = d psi/dt`` (eq. 2), so the toy's whirr has the frequency ``f = Omega / (2 pi)``
[Hz], rising to the end.  :func:`chirp` synthesizes it from a run of
:func:`rollingdisk.scenarios.euler_disk.run_euler_disk` by phase integration, ``phase(tau) =
2 pi int f dtau`` (no jumps in phase when ``f`` changes, unlike ``sin(2 pi f(t) t)``), with
the run's time compressed by ``speed`` and the pitch kept; :func:`write_wav` writes 16-bit
mono PCM with the standard library's :mod:`wave`, whole or not at all.

Only numpy at import; matplotlib when :func:`plot_chirp_frequency` draws.

Examples
--------
>>> from rollingdisk.scenarios.euler_disk import EulerDisk, run_euler_disk
>>> r = run_euler_disk(EulerDisk(alpha0=0.05, rolling_resistance=5e-3), predict=False)
>>> x = chirp(r, rate=8000, speed=4.0)
>>> x.dtype, bool(abs(x).max() <= 1.0)
(dtype('float64'), True)
"""

from __future__ import annotations

import math
import wave

import numpy as np

from rollingdisk.util.checks import check_int, check_real
from rollingdisk.util.errors import ParameterError, ParameterTypeError
from rollingdisk.util.files import atomic_file

__all__ = ["RATE", "RATE_RANGE", "MAX_SECONDS", "HARMONICS", "chirp", "sound_window",
           "precession_frequency", "write_wav", "read_wav", "plot_chirp_frequency"]

#: Default sample rate [Hz] (CD audio).
RATE = 44100
#: Allowed sample rates [Hz], inclusive.
RATE_RANGE = (8000, 192000)
#: Default longest sound [s]: a longer run keeps its end (where the whirr rises).
MAX_SECONDS = 120.0
#: Most samples one sound may have (about 10 minutes at 48 kHz; 0.4 GB of float64).
MAX_SAMPLES = 30_000_000
#: Relative amplitudes of the harmonics ``f, 2 f, 3 f``: the fundamental dominates (it is
#: the precession frequency), the overtones make the low start audible on small speakers.
HARMONICS = (1.0, 0.35, 0.15)
#: Fade-in and fade-out [s] (no click at the ends).
FADE = 0.02
#: A harmonic is faded out between these fractions of the Nyquist frequency ``rate/2``.
NYQUIST_FADE = (0.8, 0.95)


def _check_result(result):
    from rollingdisk.scenarios.euler_disk import EulerDiskResult

    if not isinstance(result, EulerDiskResult):
        raise ParameterTypeError(f"result must be an EulerDiskResult (run_euler_disk), got "
                                 f"{type(result).__name__}")
    if result.t.size < 2 or not result.t[-1] > result.t[0]:
        raise ParameterError("result: the run has fewer than two distinct times; there is "
                             "nothing to sound")
    return result


def _check_rate(rate):
    return check_int("rate", rate, low=RATE_RANGE[0], high=RATE_RANGE[1])


def _check_speed(speed, max_seconds):
    speed = check_real("speed", speed, low=0.0, high=1e6, low_open=True)
    max_seconds = check_real("max_seconds", max_seconds, low=0.0, high=3600.0,
                             low_open=True)
    return speed, max_seconds


def precession_frequency(result) -> tuple[np.ndarray, np.ndarray]:
    """Times [s] and frequencies ``Omega / (2 pi)`` [Hz] of a run, at every recorded step.

    ``Omega`` is in units of ``sqrt(g/a)``, so ``f = Omega / (2 pi sqrt(a/g))``.
    """
    r = _check_result(result)
    unit = r.toy.time_unit
    return r.t * unit, np.asarray(r.Omega, dtype=float) / (2.0 * math.pi * unit)


def sound_window(result, speed: float = 1.0, max_seconds: float = MAX_SECONDS
                 ) -> tuple[float, float]:
    """The run's time span [s] that :func:`chirp` sounds: ``(t_start, t_end)``, the whole
    run when it lasts at most ``speed * max_seconds``, else its last ``speed * max_seconds``
    seconds."""
    speed, max_seconds = _check_speed(speed, max_seconds)
    t, _ = precession_frequency(result)
    return max(float(t[0]), float(t[-1]) - speed * max_seconds), float(t[-1])


def _taper(f, lo, hi):
    """1 below ``lo``, a raised cosine down to 0 at ``hi``, 0 above (element-wise)."""
    s = np.clip((f - lo) / (hi - lo), 0.0, 1.0)
    return 0.5 * (1.0 + np.cos(np.pi * s))


def chirp(result, rate: int = RATE, speed: float = 1.0, max_seconds: float = MAX_SECONDS,
          *, harmonics=HARMONICS) -> np.ndarray:
    """The whirr of a run: a tone at ``f(t) = Omega(t) / (2 pi)`` [Hz] along the run.

    Parameters
    ----------
    result : EulerDiskResult
        From :func:`rollingdisk.scenarios.euler_disk.run_euler_disk`.
    rate : int
        Sample rate [Hz], in :data:`RATE_RANGE` (8000 to 192000).
    speed : float
        Time compression, ``> 0``: one second of sound is ``speed`` seconds of the run
        (1: real time).  The pitch is the run's: at sound time ``tau`` the frequency is
        ``f(t_start + speed tau)``.
    max_seconds : float
        Longest sound [s], in ``(0, 3600]``; a longer run keeps its end
        (:func:`sound_window`).
    harmonics : sequence of float
        Amplitudes of ``f, 2 f, 3 f, ...`` (``>= 0``, the first ``> 0``).

    Returns
    -------
    ndarray
        Samples in ``[-1, 1]`` (float64), sample ``k`` at run time ``t_start + k speed /
        rate`` [s].

    Notes
    -----
    Phase by integration: ``phase_k = 2 pi sum f / rate`` (trapezoidal rule over the
    samples, ``f`` interpolated linearly in the run's recorded steps), harmonic ``j`` at
    ``j phase``.  Envelope: a loudness ``0.3 + 0.7 v_P / max v_P`` following the contact
    point's speed (the toy gets louder as it goes down), raised-cosine fades of
    :data:`FADE` seconds at both ends, and each harmonic faded out between 0.8 and 0.95 of
    the Nyquist frequency (``rate / 2``; a frequency above it would alias: it is silent
    instead, and its phase stops at the Nyquist frequency).
    """
    r = _check_result(result)
    rate = _check_rate(rate)
    speed, max_seconds = _check_speed(speed, max_seconds)
    amps = np.asarray(harmonics, dtype=float)
    if amps.ndim != 1 or amps.size == 0 or not np.all(np.isfinite(amps)) \
            or np.any(amps < 0) or amps[0] <= 0:
        raise ParameterError(f"harmonics must be finite amplitudes >= 0 with the first > 0, "
                             f"got {harmonics!r}")
    t, f = precession_frequency(r)
    t0, t1 = sound_window(r, speed, max_seconds)
    n = int(math.floor((t1 - t0) * rate / speed)) + 1
    if n > MAX_SAMPLES:
        raise ParameterError(f"max_seconds: {n} samples at rate {rate} exceed "
                             f"{MAX_SAMPLES}; lower max_seconds or rate")
    ts = t0 + np.arange(n) * (speed / rate)  # the run's time of each sample [s]
    fs = np.interp(ts, t, f)
    nyquist = 0.5 * rate
    step = np.minimum(fs, nyquist) / rate  # cycles per sample
    phase = 2.0 * math.pi * (np.cumsum(step) - 0.5 * (step[0] + step))
    out = np.zeros(n)
    lo, hi = NYQUIST_FADE
    for j, a in enumerate(amps, start=1):
        if a > 0:
            out += a * _taper(j * fs, lo * nyquist, hi * nyquist) * np.sin(j * phase)
    vp = np.asarray(r.contact_speed, dtype=float)
    vmax = float(np.max(vp)) if np.all(np.isfinite(vp)) and np.max(vp) > 0 else 1.0
    loud = 0.3 + 0.7 * np.interp(ts, t, vp) / vmax
    tau = np.arange(n) / rate
    edge = np.minimum(tau, tau[-1] - tau) / FADE
    fade = 0.5 * (1.0 - np.cos(np.pi * np.clip(edge, 0.0, 1.0)))
    return np.clip(0.9 * out * loud * fade / amps.sum(), -1.0, 1.0)


def write_wav(path, samples, rate: int = RATE) -> None:
    """Write ``samples`` (in ``[-1, 1]``, clipped) as a 16-bit mono PCM WAV file, whole or
    not at all (:func:`rollingdisk.util.files.atomic_file`).

    Raises :class:`ParameterError` for a rate outside :data:`RATE_RANGE`, samples that are
    not a non-empty 1-D array of finite numbers, or a destination that cannot be written.
    """
    from rollingdisk.util.files import check_writable

    rate = _check_rate(rate)
    try:
        x = np.asarray(samples, dtype=float)
    except (TypeError, ValueError):
        raise ParameterTypeError(f"samples must be an array of numbers, got "
                                 f"{type(samples).__name__}") from None
    if x.ndim != 1 or x.size == 0 or not np.all(np.isfinite(x)):
        raise ParameterError("samples must be a non-empty 1-D array of finite numbers")
    target = check_writable(path, name="path")
    pcm = np.round(np.clip(x, -1.0, 1.0) * 32767.0).astype("<i2")
    with atomic_file(target, "wb") as fh:
        with wave.open(fh, "wb") as w:
            w.setnchannels(1)
            w.setsampwidth(2)
            w.setframerate(rate)
            w.writeframes(pcm.tobytes())


def read_wav(path) -> tuple[np.ndarray, int]:
    """Samples and rate of a 16-bit mono PCM WAV file, the inverse of :func:`write_wav`
    (sample ``/ 32767``, clipped to ``[-1, 1]``)."""
    with wave.open(str(path), "rb") as w:
        if w.getnchannels() != 1 or w.getsampwidth() != 2 or w.getcomptype() != "NONE":
            raise ParameterError(f"path: {path} is not 16-bit mono PCM")
        rate = w.getframerate()
        data = w.readframes(w.getnframes())
    return np.clip(np.frombuffer(data, dtype="<i2").astype(float) / 32767.0, -1.0, 1.0), rate


def plot_chirp_frequency(result, fig=None, *, rate: int = RATE, speed: float = 1.0,
                         max_seconds: float = MAX_SECONDS) -> dict:
    """The whirr's frequency ``Omega / (2 pi)`` [Hz] (log scale) against the time to the
    end ``t - t_end`` [s] (0 at the end), the span :func:`chirp` sounds shaded, the audible
    floor (20 Hz) and, when the tone comes near it, the Nyquist frequency of ``rate``.

    Returns
    -------
    dict
        ``fig``, ``ax`` and ``lines`` (``"frequency"``: the curve).
    """
    from rollingdisk.plotting.euler_plot import _thin
    from rollingdisk.plotting.style import _pyplot

    r = _check_result(result)
    rate = _check_rate(rate)
    t, f = precession_frequency(r)
    t0, t1 = sound_window(r, speed, max_seconds)
    if fig is None:
        fig = _pyplot().figure(figsize=(6.4, 3.6))
    ax = fig.subplots()
    ok = f > 0
    i = np.flatnonzero(ok)[_thin(int(np.count_nonzero(ok)))]
    (line,) = ax.semilogy(t[i] - t1, f[i], color="C1", lw=1.4, label=r"$\Omega/2\pi$")
    ax.axvspan(t0 - t1, 0.0, color="C0", alpha=0.1,
               label=f"sounded: {t1 - t0:.3g} s of the run in {(t1 - t0) / speed:.3g} s")
    ax.axhline(20.0, color="0.5", ls=":", lw=1, label="20 Hz (audible above)")
    if f[ok].size and f[ok].max() > 0.4 * rate:
        ax.axhline(0.5 * rate, color="C3", ls="--", lw=1, label=f"Nyquist {rate / 2:g} Hz")
    ax.set_xlabel(r"time to the end $t - t_{end}$ [s]")
    ax.set_ylabel(r"frequency $\Omega/2\pi$ [Hz]")
    ax.set_title(f"the whirr: the contact point's precession, {f[-1]:.3g} Hz at the end "
                 f"({r.end or r.status}, t_end = {t1:.4g} s)", fontsize=9)
    ax.legend(loc="upper left", fontsize=8)
    fig.tight_layout()
    return {"fig": fig, "ax": ax, "lines": {"frequency": line}}
