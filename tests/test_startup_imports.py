"""Each command loads only what its work needs (issue #33): a short ``simulate`` imports
neither numba, scipy.integrate, xarray, zarr, dask, matplotlib nor sympy; a small sweep
builds and writes its dataset without dask; and no process outlives the command that
started it.  No timing is asserted: which modules load is a property of the code, how long
they take is the machine's (benchmarks/startup.py measures that)."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

#: Runs the console script's entry in this interpreter, then writes the top-level names of
#: the loaded modules (and dask.array, which is what costs) to the file argv[1].
_PROBE = r"""
import json, sys
out, argv = sys.argv[1], sys.argv[2:]
from rollingdisk.cli.entry import main
try:
    status = main(argv)
finally:
    mods = sorted({m.split(".")[0] for m in sys.modules} | ({"dask.array"} & set(sys.modules)))
    with open(out, "w") as f:
        json.dump({"modules": mods, "submodules": sorted(sys.modules)}, f)
sys.exit(status)
"""

HEAVY = {"numba", "xarray", "zarr", "dask", "dask.array", "matplotlib", "sympy", "pandas"}

SIMULATE = ["simulate", "--h", "0.17", "--theta0", "0.5", "--Omega0", "1.7", "--perturb",
            "1e-4", "--t-end", "100", "--json"]


def _env(tmp_path, cold=False, **extra):
    """The test's environment; ``cold``: an empty compile cache in ``tmp_path``."""
    env = dict(os.environ, **extra)
    if cold:
        env["NUMBA_CACHE_DIR"] = str(tmp_path / "numba-cache")
    src = str(Path(__file__).resolve().parents[1] / "src")
    env["PYTHONPATH"] = src + os.pathsep + env.get("PYTHONPATH", "")
    return env


def _loaded(tmp_path, argv, timeout=600):
    """Run ``rollingdisk ARGV`` in a fresh interpreter; (the top-level modules it loaded,
    every module name, its completed process)."""
    out = tmp_path / "modules.json"
    res = subprocess.run([sys.executable, "-c", _PROBE, str(out), *argv], cwd=tmp_path,
                         env=_env(tmp_path), capture_output=True, text=True, timeout=timeout)
    assert res.returncode == 0, res.stderr[-2000:]
    data = json.loads(out.read_text())
    return set(data["modules"]), set(data["submodules"]), res


@pytest.mark.parametrize("argv, allowed", [
    (["--help"], set()),
    (["steady", "--h", "0.17", "--theta0", "30deg", "--Omega0", "2"], set()),
    (["thresholds", "--h", "0.17"], set()),
    (SIMULATE, set()),
])
def test_cheap_commands_load_no_heavy_module(tmp_path, argv, allowed):
    mods, subs, _ = _loaded(tmp_path, argv)
    assert (mods | subs) & HEAVY <= allowed, sorted((mods | subs) & HEAVY)


def test_short_simulate_needs_neither_compiler_nor_scipy_integrate(tmp_path):
    """The short run goes uncompiled (engine/jit.py: the work is below LOAD_WORTH), so
    numba is not even imported; scipy's integrators are not the path either."""
    mods, subs, res = _loaded(tmp_path, SIMULATE)
    assert "numba" not in mods and "scipy.integrate" not in subs
    assert json.loads(res.stdout)["status"] == "completed"


def test_small_sweep_writes_its_store_without_dask_array(tmp_path):
    """The sweep needs numba (its kernel), xarray and zarr (its store), but not dask:
    rollingdisk.results.xrload defers xarray's duck-array checks of dask and pint."""
    out = tmp_path / "s.zarr"
    mods, subs, res = _loaded(tmp_path, [
        "sweep", "--ground", "rough", "--h", "0.17", "--theta0", "0.3:1.2:2",
        "--omega30", "2:6:2", "--t-end", "1", "--out", str(out), "--json"])
    assert json.loads(res.stdout)["n"] == 4
    assert {"xarray", "zarr"} <= mods
    assert not {"dask", "pint", "matplotlib", "sympy"} & mods


def test_deferred_dask_entry_answers_as_xarray_once_dask_array_is_imported(tmp_path):
    """With dask.array imported, xarray sees dask arrays as dask arrays through the
    deferred entry (a chunked DataArray stays lazy and computes the same values)."""
    pytest.importorskip("dask.array")
    code = (
        "import numpy as np\n"
        "from rollingdisk.results.xrload import xr, dask_deferred\n"
        "assert dask_deferred()\n"
        "from xarray.namedarray.pycompat import array_type\n"
        "assert array_type('dask') == ()\n"
        "import dask.array as da\n"
        "assert array_type('dask') == (da.Array,)\n"
        "a = xr.DataArray(da.arange(6, chunks=2), dims='x')\n"
        "assert a.chunks == ((2, 2, 2),)\n"
        "assert (a * 2).sum().compute().item() == 30\n"
        "from xarray.namedarray.utils import is_duck_dask_array\n"
        "assert is_duck_dask_array(a.data) and not is_duck_dask_array(np.ones(2))\n"
        "try:\n"
        "    import pint\n"
        "except ImportError:\n"
        "    pint = None\n"
        "if pint is not None:\n"
        "    assert array_type('pint') == (pint.Quantity,)\n")
    res = subprocess.run([sys.executable, "-c", code], env=_env(tmp_path), cwd=tmp_path,
                         capture_output=True, text=True, timeout=300)
    assert res.returncode == 0, res.stderr[-2000:]


def _children_of(pid: int) -> list[int]:
    """Processes whose parent is ``pid`` (psutil if installed, else /proc)."""
    try:
        import psutil
    except ImportError:
        psutil = None
    if psutil is not None:
        try:
            return [p.pid for p in psutil.Process(pid).children(recursive=True)]
        except psutil.NoSuchProcess:
            return []
    found = []
    for d in Path("/proc").iterdir():
        if d.name.isdigit():
            try:
                fields = (d / "stat").read_text().rsplit(")", 1)[1].split()
            except OSError:
                continue
            if int(fields[1]) == pid:
                found.append(int(d.name))
    return found


def _with_marker(marker: str) -> list[int]:
    """Live processes whose environment or command line carries ``marker``."""
    hits = []
    for d in Path("/proc").iterdir():
        if not d.name.isdigit() or int(d.name) == os.getpid():
            continue
        try:
            blob = (d / "environ").read_bytes() + (d / "cmdline").read_bytes()
            state = (d / "stat").read_text().rsplit(")", 1)[1].split()[0]
        except OSError:
            continue
        if marker.encode() in blob and state != "Z":
            hits.append(int(d.name))
    return hits


@pytest.mark.skipif(not Path("/proc").is_dir(), reason="needs /proc")
@pytest.mark.parametrize("argv", [
    SIMULATE,
    # a run long enough to load (and, with the empty cache, compile: 10-60 s) the
    # compiled code
    pytest.param([*SIMULATE[:-3], "--t-end", "3000", "--json"], marks=pytest.mark.slow),
])
def test_no_process_outlives_a_cold_cache_command(tmp_path, argv):
    """With an empty compile cache (NUMBA_CACHE_DIR in tmp_path) the command leaves no
    process behind: every process it started (found by a marker in their inherited
    environment) is gone when it returns."""
    marker = f"ROLLINGDISK_TEST_MARKER_{os.getpid()}_{tmp_path.name}"
    env = _env(tmp_path, cold=True, **{marker: "1"})
    proc = subprocess.Popen([sys.executable, "-m", "rollingdisk", *argv], env=env,
                            cwd=tmp_path, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            text=True)
    seen_children = set()
    while proc.poll() is None:
        seen_children.update(_children_of(proc.pid))
        try:
            proc.wait(timeout=0.2)
        except subprocess.TimeoutExpired:
            pass
    out, err = proc.communicate()
    assert proc.returncode == 0, err[-2000:]
    assert json.loads(out)["status"] == "completed"
    left = _with_marker(marker)
    assert not left, f"processes left running after the command: {left}"
    assert not [p for p in seen_children if Path(f"/proc/{p}").exists()
                and p in _with_marker(marker)]
