"""The explorer's server (rollingdisk.explore): its JSON against the library, its refusals,
its survival, and the command that runs it.

Sources of truth: the library's own single-point API (rd.steady_motion, rd.stability:
the page must show exactly those numbers), the closed form of varpi^2 evaluated on a whole
grid by a different code path (rd.varpi2_circle), and the contact condition of the drawn
disk (its lowest rim point lies on the plane, at the contact point P of the trajectory).
"""

from __future__ import annotations

import json
import math
import os
import signal
import socket
import subprocess
import sys
import threading
import urllib.error
import urllib.parse
import urllib.request
from argparse import ArgumentParser
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import rollingdisk as rd
from rollingdisk.explore import api, make_server, server
from rollingdisk.explore.command import configure, is_loopback, run

SRC = Path(__file__).resolve().parents[1] / "src"


@pytest.fixture(scope="module")
def base_url():
    srv = make_server(0.17, "rough", "127.0.0.1", 0)
    srv.start_in_thread()
    host, port = srv.server_address[:2]
    yield f"http://{host}:{port}"
    srv.shutdown()
    srv.server_close()


#: Seconds a request may take before the test calls the server hung: a guard against a hang,
#: not a measure of speed (a request may have to wait for a cold compile on a loaded machine).
HANG = 600


def get(base_url, path, params=None, *, raw_query=None):
    query = raw_query if raw_query is not None else urllib.parse.urlencode(params or {})
    try:
        with urllib.request.urlopen(f"{base_url}{path}?{query}", timeout=HANG) as res:
            return res.status, json.loads(res.read())
    except urllib.error.HTTPError as err:
        return err.code, json.loads(err.read())


def close(a, b, tol=1e-9):
    if a is None or b is None:
        return a is None and b is None
    return math.isclose(a, b, rel_tol=tol, abs_tol=tol)


# ---------------------------------------------------------------- the library's numbers
CASES = [
    ("rough", 0.17, 0.5, "omega30", 1.5),
    ("rough", 0.17, 0.3, "omega30", 0.4),      # unstable
    ("rough", 0.0, 1.0, "Omega0", -2.0),
    ("rough", 1.3, 0.9, "r_C", -0.75),     # a bar leaning away from the centre
    ("rough", 0.17, -0.4, "r_P", -1.2),
    ("smooth", 0.17, 0.7, "omega30", 2.5),
    ("smooth", 2.0, 0.2, "Omega0", 0.3),
]


def library(ground, h, theta0, name, value):
    disk = rd.Disk(h)
    if name == "omega30":  # eq. (3): omega30 = Omega0 cos(theta0)
        m = rd.steady_motion(disk, ground, theta0, Omega0=value / math.cos(theta0))
    else:
        m = rd.steady_motion(disk, ground, theta0, **{name: value})
    return m, rd.stability(m)


@pytest.mark.parametrize("ground,h,theta0,name,value", CASES)
def test_steady_equals_library(base_url, ground, h, theta0, name, value):
    status, out = get(base_url, "/api/steady",
                      {"ground": ground, "h": h, "theta0": theta0, name: value})
    assert status == 200 and out["exists"] is True
    m, s = library(ground, h, theta0, name, value)
    for key in ("Omega0", "omega0", "omega20", "omega30", "r_C", "r_P", "F_y", "mu_required"):
        assert close(out[key], getattr(m, key)), key
    assert out["motion"] == m.motion
    assert close(out["varpi2"], s.varpi2)
    assert out["stable"] is s.stable
    assert close(out["period"], s.period) and close(out["growth_rate"], s.growth_rate)
    # the least friction to roll is |F_t|/F_z with F_x = 0, F_z = 1 (eq. 19), F_y eq. (27)
    assert close(out["mu_required"], abs(m.r_C) * m.Omega0 ** 2 if ground == "rough" else 0.0)


@settings(max_examples=40, deadline=None)
@given(ground=st.sampled_from(api.GROUNDS), h=st.floats(0.0, 5.0),
       theta0=st.floats(0.01, 1.55), omega30=st.floats(0.05, 5.0))
def test_steady_equals_library_anywhere(ground, h, theta0, omega30):
    q = {"ground": [ground], "h": [repr(h)], "theta0": [repr(theta0)], "omega30": [repr(omega30)]}
    out = api.steady_payload(q)
    m, s = library(ground, h, theta0, "omega30", omega30)
    assert close(out["Omega0"], m.Omega0) and close(out["omega20"], m.omega20)
    assert close(out["r_P"], m.r_P) and close(out["varpi2"], s.varpi2)


def test_no_steady_motion_gives_the_library_reason(base_url):
    # Figure 4's dark region: at theta0 = 0.1 a rough steady circle needs r_C < r_C*
    # (eq. 32), which is about 0.039 for h = 0.17
    status, out = get(base_url, "/api/steady",
                      {"ground": "rough", "h": 0.17, "theta0": 0.1, "r_C": 0.5})
    assert status == 200 and out["exists"] is False
    with pytest.raises(rd.NoSteadyMotion) as exc:
        rd.steady_motion(rd.Disk(0.17), "rough", 0.1, r_C=0.5)
    assert out["reason"] == str(exc.value)
    assert "r_C < 0.0386" in out["reason"]
    # smooth ground: C is at rest in every steady circle
    status, out = get(base_url, "/api/steady",
                      {"ground": "smooth", "h": 0.17, "theta0": 0.5, "r_C": 0.5})
    assert status == 200 and out["exists"] is False and "at rest" in out["reason"]


# ------------------------------------------------------------------------------ the map
@pytest.mark.parametrize("ground", api.GROUNDS)
def test_map_theta0_omega30_is_the_sign_of_varpi2(base_url, ground):
    status, out = get(base_url, "/api/map", {"ground": ground, "h": 0.4, "n": 31,
                                             "plane": "theta0-omega30"})
    assert status == 200
    TH, W = np.meshgrid(out["x"]["values"], out["y"]["values"])
    v2 = rd.varpi2_circle(0.4, ground, TH, W)  # eq. (45) / (55), vectorized path
    codes = np.array(out["codes"])
    assert codes.shape == (31, 31)
    decided = np.abs(v2) > 1e-9
    assert np.array_equal(codes[decided], np.where(v2[decided] > 0, rd.STABLE, rd.UNSTABLE))
    assert 0 < (codes == rd.UNSTABLE).sum() < codes.size  # both classes on this map


def test_map_mu_required_is_the_clicked_motions(base_url):
    status, out = get(base_url, "/api/map", {"h": 0.17, "n": 7, "plane": "theta0-Omega0"})
    assert status == 200
    for j in (0, 3, 6):
        for i in (1, 5):
            th, W = out["x"]["values"][i], out["y"]["values"][j]
            m = rd.steady_motion(rd.Disk(0.17), "rough", th, Omega0=W)
            assert close(out["mu_required"][j][i], m.mu_required)
            assert out["codes"][j][i] == (rd.STABLE if rd.stability(m).stable else rd.UNSTABLE)


def test_map_figure4_plane(base_url):
    status, out = get(base_url, "/api/map", {"h": 0.17, "n": 41, "plane": "theta0-r_C",
                                             "ymax": 1})
    assert status == 200
    TH, RC = np.meshgrid(out["x"]["values"], out["y"]["values"])
    codes = np.array(out["codes"])
    assert np.array_equal(codes, rd.existence_codes(0.17, TH, RC))
    mu = np.array([[np.nan if v is None else v for v in row] for row in out["mu_required"]])
    assert np.array_equal(np.isnan(mu), codes == rd.NO_MOTION)
    assert {0, 1, 2} <= set(codes.ravel().tolist())
    status, out = get(base_url, "/api/map", {"ground": "smooth", "plane": "theta0-r_C", "n": 5})
    assert status == 200 and not np.any(out["codes"])


# ------------------------------------------------------------------------- simulation
def test_simulate_pose_touches_the_plane_at_P(base_url):
    status, out = get(base_url, "/api/simulate", {"ground": "rough", "h": 0.3, "theta0": 0.6,
                                                  "omega30": 1.2, "kick": 0.05, "t_end": 20,
                                                  "points": 200})
    assert status == 200 and out["status"] == "completed"
    assert len(out["t"]) == 200 and out["t"][-1] == 20.0
    assert math.isclose(out["theta"][0], 0.65, abs_tol=1e-7)  # theta(0) = theta0 + kick
    a = np.linspace(0.0, 2.0 * np.pi, 3601)
    for k in (0, 57, 199):
        C = np.array([out["X_C"][k], out["Y_C"][k], out["Z_C"][k]])
        eta, e1, e2 = (np.array(out[n][3 * k:3 * k + 3]) for n in ("axis", "e1", "e2"))
        assert abs(eta @ e1) < 1e-6 and abs(eta @ e2) < 1e-6 and abs(e1 @ e2) < 1e-6
        rims = [C + s * 0.3 * eta + np.outer(np.cos(a), e1) + np.outer(np.sin(a), e2)
                for s in (-1, 1)]
        pts = np.concatenate(rims)
        low = pts[np.argmin(pts[:, 2])]
        assert abs(low[2]) < 1e-5  # the disk stands on the plane Z = 0 (eq. 7)
        assert np.hypot(low[0] - out["X_P"][k], low[1] - out["Y_P"][k]) < 5e-3  # P, eq. (5)


def test_simulate_bounds_the_work(base_url):
    status, out = get(base_url, "/api/simulate", {"theta0": 0.5, "Omega0": 20, "t_end": 200,
                                                  "points": 4000, "kick": 0})
    assert status == 200
    assert out["n_steps"] <= api.SIM_MAX_STEPS and len(out["t"]) <= api.POINTS_MAX + 1
    status, out = get(base_url, "/api/simulate", {"theta0": 0.1, "r_C": 0.0386})  # Omega0 26.8
    assert status == 400 and "too fast" in out["error"]


# ------------------------------------------------------------------------ bad requests
BAD = [
    ("/api/map", "n=500", "n must be an integer in [2, 121]"),
    ("/api/map", "n=abc", "n must be an integer"),
    ("/api/map", "plane=xy", "plane must be one of"),
    ("/api/map", "ground=icy", "ground must be one of rough, smooth"),
    ("/api/map", "h=-1", "h must lie in [0, 100]"),
    ("/api/map", "h=nan", "h must be a finite number"),
    ("/api/map", "h=1&h=2", "h given 2 times"),
    ("/api/map", "ymax=0", "ymax must lie in"),
    ("/api/steady", "theta0=0.5", "give exactly one of omega30, Omega0, r_C, r_P"),
    ("/api/steady", "theta0=0.5&Omega0=1&r_C=1", "give exactly one"),
    ("/api/steady", "omega30=1", "theta0 is required"),
    ("/api/steady", "theta0=1.6&omega30=1", "theta0 must lie in (-1.5708, 1.5708)"),
    ("/api/steady", "theta0=0&omega30=1", "theta0 must lie in (-pi/2, 0) or (0, pi/2)"),
    ("/api/steady", "theta0=0.5&omega30=inf", "omega30 must be a finite number"),
    ("/api/steady", "theta0=0.5&omega30=1e300", "omega30 must lie in"),
    ("/api/steady", "theta0=%ff&omega30=1", "theta0 must be a number"),
    ("/api/steady", "theta0=0.5&omega30=1&bogus=2", "unknown parameter 'bogus'"),
    ("/api/steady", "ground=smooth&theta0=0.5&r_C=0", "give Omega0 instead"),
    ("/api/simulate", "theta0=0.5&omega30=1&t_end=500", "t_end must lie in (0, 200]"),
    ("/api/simulate", "theta0=0.5&omega30=1&t_end=0", "t_end must lie in (0, 200]"),
    ("/api/simulate", "theta0=0.5&omega30=1&points=5000", "points must be an integer in [2, 4000]"),
    ("/api/simulate", "theta0=0.5&omega30=1&kick=1", "kick must lie in [-0.5, 0.5]"),
    ("/api/simulate", "theta0=1.5&omega30=1&kick=0.1", "perturb must lie in"),
    ("/api/simulate", "theta0=0.5&Omega0=50", "Omega0 must lie in [-20, 20]"),
    ("/api/simulate", "theta0=0.1&r_C=0.5", "no steady circle"),
]


@pytest.mark.parametrize("path,query,message", BAD)
def test_bad_requests_are_400_with_one_line(base_url, path, query, message):
    status, out = get(base_url, path, raw_query=query)
    assert status == 400
    assert set(out) == {"error"} and message in out["error"], out
    assert "\n" not in out["error"] and "Traceback" not in out["error"]
    status, out = get(base_url, "/api/steady", {"theta0": 0.5, "omega30": 1.5})
    assert status == 200 and out["exists"]  # and it serves on


def test_long_query_unknown_page_and_bug_are_answered(base_url, monkeypatch):
    status, out = get(base_url, "/api/map", raw_query="h=" + "1" * 3000)
    assert status == 400 and "query too long" in out["error"]
    status, out = get(base_url, "/nope", {})
    assert status == 404 and "/api/map" in out["error"]

    def broken(query, defaults):
        raise RuntimeError("secret detail")

    monkeypatch.setitem(server.ENDPOINTS, "/api/steady", broken)
    status, out = get(base_url, "/api/steady", {})
    assert status == 500 and "internal error" in out["error"]
    assert "secret detail" not in out["error"]  # the traceback stays in the server log
    monkeypatch.undo()
    assert get(base_url, "/api/steady", {"theta0": 0.5, "omega30": 1})[0] == 200


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(params=st.dictionaries(
    st.sampled_from(["ground", "h", "plane", "n", "theta0", "omega30", "Omega0", "r_C",
                     "kick", "t_end", "points", "ymax", "x"]),
    st.one_of(st.text(max_size=12), st.floats(allow_nan=True).map(repr),
              st.integers(-10**6, 10**6).map(str)), max_size=5),
    path=st.sampled_from(list(server.ENDPOINTS)))
def test_hostile_queries_never_500(params, path):
    fn = server.ENDPOINTS[path]
    q = {k: [v] for k, v in params.items()}
    if path == "/api/simulate":
        q["t_end"] = ["1"]  # keep the fuzzing fast; t_end itself is checked above
    if path == "/api/map":
        q["n"] = ["3"]
    try:
        out = fn(q, {"h": 0.17, "ground": "rough"})
    except api.ApiError as exc:
        assert str(exc) and "\n" not in str(exc)
    else:
        json.dumps(out, allow_nan=False)  # strict JSON


def test_concurrent_requests(base_url):
    results = []

    def worker(i):
        results.append(get(base_url, "/api/steady", {"theta0": 0.1 + 0.01 * i, "omega30": 1})[0])

    threads = [threading.Thread(target=worker, args=(i,)) for i in range(12)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert results == [200] * 12


# ------------------------------------------------------------------------- the page
def test_static_files_are_local(base_url):
    for path, kind in (("/", "text/html"), ("/explore.js", "javascript"),
                       ("/view.js", "javascript"), ("/explore.css", "text/css")):
        with urllib.request.urlopen(base_url + path, timeout=HANG) as res:
            assert res.status == 200 and kind in res.headers["Content-Type"]
            text = res.read().decode()
        # nothing fetched from the network: no absolute URL anywhere in the page's files
        assert "http://" not in text and "https://" not in text and "//cdn" not in text


# ------------------------------------------------------------------------ the command
def _args(argv):
    parser = ArgumentParser()
    configure(parser.add_subparsers(dest="command"))
    return parser.parse_args(["explore", *argv])


def test_command_options():
    from rollingdisk.explore.command import _start_disk

    args = _args([])
    assert (args.h, args.ground, args.port, args.host, args.no_browser) == (
        None, "rough", 8765, None, False)
    assert _start_disk(args) == (rd.DEFAULT_H, None)  # no disk given: the default h
    assert args.handler is run
    with pytest.raises(SystemExit):
        _args(["--port", "70000"])
    assert is_loopback("127.0.0.1") and is_loopback("localhost") and is_loopback("::1")
    assert not is_loopback("0.0.0.0") and not is_loopback("192.168.1.2")


def test_run_stops_on_ctrl_c_with_130(monkeypatch, capsys):
    def interrupted(self, *a, **k):
        raise KeyboardInterrupt

    monkeypatch.setattr(server.ExplorerServer, "serve_forever", interrupted)
    assert run(_args(["--port", "0", "--no-browser"])) == 130
    out, err = capsys.readouterr()
    assert "serving http://127.0.0.1:" in out and "stopped" in err and "warning" not in err
    assert run(_args(["--port", "0", "--no-browser", "--host", "0.0.0.0"])) == 130
    assert "warning: binding 0.0.0.0, beyond localhost" in capsys.readouterr().err


def test_run_port_in_use_is_exit_2(capsys):
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        s.listen()
        port = s.getsockname()[1]
        assert run(_args(["--port", str(port), "--no-browser"])) == 2
    assert "cannot serve on 127.0.0.1" in capsys.readouterr().err


def test_python_m_serves_and_stops_on_sigint():
    env = {**os.environ, "PYTHONPATH": str(SRC)}
    proc = subprocess.Popen([sys.executable, "-m", "rollingdisk.explore", "--port", "0",
                             "--no-browser"], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            text=True, env=env)
    try:
        line = proc.stdout.readline()
        assert "serving http://127.0.0.1:" in line
        url = line.split("serving ")[1].split()[0]
        base = url.split("/?")[0]
        status, out = get(base, "/api/steady", {"theta0": 0.5, "omega30": 1.5})
        assert status == 200 and out["exists"]
        proc.send_signal(signal.SIGINT)
        _, err = proc.communicate(timeout=HANG)
    finally:
        if proc.poll() is None:
            proc.kill()
    assert proc.returncode == 130
    assert "Traceback" not in err and "stopped" in err


def test_static_files_are_package_data():
    import fnmatch
    import tomllib

    conf = tomllib.loads((SRC.parent / "pyproject.toml").read_text())
    globs = conf["tool"]["setuptools"]["package-data"]["rollingdisk.explore"]
    static = SRC / "rollingdisk" / "explore" / "static"
    files = sorted(p.name for p in static.iterdir())
    assert files == ["explore.css", "explore.js", "index.html", "view.js"]
    for name in files:  # each shipped in the wheel
        assert any(fnmatch.fnmatch(f"static/{name}", g) for g in globs), name


def _defined(js: str) -> set[str]:
    """Names a script defines at its top level: functions and constants."""
    import re

    return set(re.findall(r"^(?:export )?(?:async )?function (\w+)", js, re.M)) | set(
        re.findall(r"^(?:export )?(?:const|let) (\w+)", js, re.M))


def test_one_view_module_draws_for_the_page_and_the_widget():
    """The map, the numbers and the 3D view are drawn by one ES module, ``view.js``: the
    page's script loads it (as a module, served from the package) and draws nothing itself,
    the notebook widget's ESM is that very file, and no name is defined in both scripts."""
    from rollingdisk.explore.widget import ESM_PATH

    static = SRC / "rollingdisk" / "explore" / "static"
    page = (static / "index.html").read_text()
    script = (static / "explore.js").read_text()
    view = (static / "view.js").read_text()
    assert '<script type="module" src="explore.js"></script>' in page
    assert 'import * as view from "./view.js";' in script
    assert server.STATIC["/view.js"] == "view.js"
    assert ESM_PATH == static / "view.js"
    # the page's script asks and wires; every canvas call is the view module's
    for drawing in ("getContext", "fillRect", "fillText", "putImageData", "lineTo", "project("):
        assert drawing not in script and drawing in view, drawing
    for name in ("drawMap", "mapPoint", "showNumbers", "drawScene", "orbit", "playback",
                 "render"):
        assert name in _defined(view), name
    assert _defined(script) & _defined(view) == set()


def test_a_physical_disk_gets_si_values_beside_the_papers():
    """With ``--disk euro-1`` the steady motions of the coin's h come with SI values: the
    paper's times the coin's scales (a, sqrt(a/g), sqrt(g a)); another h has none."""
    coin = rd.disk_from_options(disk="euro-1")
    defaults = {"h": coin.h, "ground": "rough", "disk": coin}
    q = {"theta0": ["0.4"], "omega30": ["1.5"]}
    rec = api.steady_payload(q, defaults)
    m = rd.steady_motion(coin, "rough", 0.4, omega30=1.5)
    s = rd.stability(m)
    a, g = 0.011625, coin.gravity
    ts = (a / g) ** 0.5
    si = rec["si"]
    assert si["Omega0 [rad/s]"] == pytest.approx(m.Omega0 / ts, rel=1e-12)
    assert si["r_C [mm]"] == pytest.approx(1e3 * m.r_C * a, rel=1e-12)
    assert si["speed of C [m/s]"] == pytest.approx(m.v_C * (g * a) ** 0.5, rel=1e-12)
    assert si["period [s]"] == pytest.approx(s.period * ts, rel=1e-12)
    other = api.steady_payload({**q, "h": ["0.3"]}, defaults)
    assert "si" not in other
    assert "si" not in api.steady_payload(q, {"h": coin.h, "ground": "rough"})
