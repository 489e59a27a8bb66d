"""The notebook view (rollingdisk.explore.widget): a notebook executed by nbclient creates the
widget of a 1-euro coin, clicks through the widget's model (the trait ``selected``, as the
browser sets it) and checks the numbers it sends equal the library's
(:func:`rollingdisk.steady_motion`, :func:`rollingdisk.stability`) to 1e-9; and the ES module
drawn in a real browser (Debian's Chromium) with a fake anywidget model: the map and the 3D
view are painted, a click on the map sets ``selected`` on the model, and the page asks
nothing of the network.
"""

from __future__ import annotations

import http.server
import json
import os
import shutil
import threading
import time
from pathlib import Path

import numpy as np
import pytest

import browser

ROOT = Path(__file__).resolve().parents[1]

pytest.importorskip("anywidget")


def test_the_module_ships_with_the_package():
    from rollingdisk.explore.widget import ESM_PATH

    assert ESM_PATH.is_file() and "export default" in ESM_PATH.read_text()
    assert "import " not in ESM_PATH.read_text().split("export default")[0].replace(
        "// No import", "")  # self-contained: nothing to fetch


def test_a_click_in_python_sends_the_librarys_numbers():
    import rollingdisk as rd
    from rollingdisk.explore.widget import widget

    w = widget("euro-1")
    assert w.disk["radius_m"] == pytest.approx(0.011625)
    w.selected = [0.4, 1.5]
    m = rd.steady_motion(rd.disk_from_options(disk="euro-1"), "rough", 0.4, omega30=1.5)
    s = rd.stability(m)
    assert w.motion["Omega0"] == pytest.approx(m.Omega0, abs=1e-9)
    assert w.motion["varpi2"] == pytest.approx(s.varpi2, abs=1e-9)
    ts = rd.disk_from_options(disk="euro-1").time_to_si(1.0)
    assert w.motion["si"]["Omega0 [rad/s]"] == pytest.approx(m.Omega0 / ts, rel=1e-12)
    assert len(w.frames["X_C"]) == len(w.frames["t"]) > 10
    assert len(w.frames["axis"]) == len(w.frames["e1"]) == 3 * len(w.frames["t"])


def test_a_click_is_answered_as_the_served_explorer_answers_it():
    """The widget and the served page draw the same records: a click in the notebook gets
    exactly what /api/steady and /api/simulate send for that point."""
    import rollingdisk as rd
    from rollingdisk.explore import api
    from rollingdisk.explore.widget import FRAMES, KICK, T_END, traits, widget

    coin = rd.disk_from_options(disk="euro-1")
    w = widget(coin)
    w.selected = [0.4, 1.5]
    defaults = {"h": coin.h, "ground": "rough", "disk": coin}
    q = {"theta0": ["0.4"], "omega30": ["1.5"]}
    assert w.motion == api.steady_payload(q, defaults)
    assert w.frames == api.simulate_payload({**q, "kick": [str(KICK)], "t_end": [str(T_END)],
                                             "points": [str(FRAMES)]}, defaults)
    assert traits(coin, selected=(0.4, 1.5)) == {k: getattr(w, k) for k in (
        "disk", "map", "selected", "motion", "frames")}  # the traits, without anywidget
    w.selected = [0.4, 0.0]  # a straight line off the static-equilibrium tilt: no steady
    with pytest.raises(rd.NoSteadyMotion) as exc:  # motion, the library's reason, no play
        rd.steady_motion(coin, "rough", 0.4, Omega0=0.0)  # omega30 = Omega0 cos(theta0)
    assert w.motion["exists"] is False and w.motion["reason"] == str(exc.value)
    assert w.frames == {}


def test_play_draws_a_disk_standing_on_the_plane_at_P():
    """The track :func:`play` sends: at each frame the drawn disk (centre C, axis eta,
    radii e1, e2) has its lowest rim point on the plane Z = 0 (eq. 7), at the trajectory's
    own contact point P (eq. 5, interpolated to the frame's time)."""
    import rollingdisk as rd
    from rollingdisk.explore.widget import play

    m = rd.steady_motion(rd.Disk(0.3), "rough", 0.6, omega30=1.2)
    tr = rd.simulate_steady(m, 8.0, perturb=0.05, t_eval=np.linspace(0.0, 8.0, 801))
    f = play(tr, n_frames=40).frames
    assert len(f["t"]) == 40 and f["t"][-1] == pytest.approx(8.0)
    a = np.linspace(0.0, 2.0 * np.pi, 3601)
    for k in (0, 17, 39):
        C = np.array([f["X_C"][k], f["Y_C"][k], f["Z_C"][k]])
        eta, e1, e2 = (np.array(f[n][3 * k:3 * k + 3]) for n in ("axis", "e1", "e2"))
        assert abs(eta @ e1) < 1e-6 and abs(eta @ e2) < 1e-6 and abs(e1 @ e2) < 1e-6
        pts = np.concatenate([C + s * 0.3 * eta + np.outer(np.cos(a), e1)
                              + np.outer(np.sin(a), e2) for s in (-1, 1)])
        low = pts[np.argmin(pts[:, 2])]
        assert abs(low[2]) < 1e-5
        P = [np.interp(f["t"][k], tr.t, tr.X_P), np.interp(f["t"][k], tr.t, tr.Y_P)]
        assert np.hypot(low[0] - P[0], low[1] - P[1]) < 5e-3
        assert f["X_P"][k] == pytest.approx(P[0], abs=1e-3)


def test_play_draws_a_toss_never_below_the_plane():
    """A motion to rest (a toss of a coin: flight, impacts, rolling) played: the first
    frame is the toss's initial state, and at every frame the drawn coin's lowest point is
    on or above the plane Z = 0, at the contact point P sent for it (its lowest point, the
    rim point nearest the plane)."""
    import rollingdisk as rd
    from rollingdisk.explore.widget import play

    coin = rd.disk_from_options(disk="euro-1")
    motion = rd.toss(coin, 3.0, 2.0, 5.0, 0.3).motion
    f = play(motion, n_frames=60).frames
    assert len(f["t"]) == 60 and f["Z_C"][0] == pytest.approx(3.0)  # tossed from Z_C = 3
    a = np.linspace(0.0, 2.0 * np.pi, 3601)
    for k in range(60):
        C = np.array([f["X_C"][k], f["Y_C"][k], f["Z_C"][k]])
        eta, e1, e2 = (np.array(f[n][3 * k:3 * k + 3]) for n in ("axis", "e1", "e2"))
        pts = np.concatenate([C + s * coin.h * eta + np.outer(np.cos(a), e1)
                              + np.outer(np.sin(a), e2) for s in (-1, 1)])
        low = pts[np.argmin(pts[:, 2])]
        assert low[2] > -1e-5, k
        if abs(eta[2]) < 0.999:  # not lying flat (then every point of a face is lowest)
            assert np.hypot(low[0] - f["X_P"][k], low[1] - f["Y_P"][k]) < 5e-3, k


def test_bad_input_is_named():
    from rollingdisk.explore.widget import play, widget
    from rollingdisk.util.errors import ParameterError, ParameterTypeError

    with pytest.raises(ParameterError, match="ground"):
        widget(0.1, ground="ice")
    with pytest.raises(ParameterTypeError, match="disk"):
        widget([0.1])
    with pytest.raises(ParameterTypeError, match="result"):
        play("a motion")


@pytest.mark.slow
def test_notebook_executes_and_matches_the_library(tmp_path):
    nbformat = pytest.importorskip("nbformat")
    nbclient = pytest.importorskip("nbclient")
    pytest.importorskip("ipykernel")
    cells = [
        "import rollingdisk as rd\nfrom rollingdisk.explore.widget import widget, play",
        "w = widget('euro-1')\nw",
        "w.selected = [0.4, 1.5]  # what a click on the map sets\n"
        "m = rd.steady_motion(rd.disk_from_options(disk='euro-1'), 'rough', 0.4, "
        "omega30=1.5)\ns = rd.stability(m)\n"
        "assert abs(w.motion['Omega0'] - m.Omega0) <= 1e-9\n"
        "assert abs(w.motion['varpi2'] - s.varpi2) <= 1e-9\n"
        "assert abs(w.motion['omega20'] - m.omega20) <= 1e-9\n"
        "print('numbers', w.motion['Omega0'], w.motion['varpi2'])",
        "p = play(rd.simulate_steady(m, 2.0))\nlen(p.frames['t'])",
    ]
    nb = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell(c) for c in cells])
    nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3",
                                 "language": "python"}
    old = os.environ.get("PYTHONPATH")
    os.environ["PYTHONPATH"] = str(ROOT / "src") + (os.pathsep + old if old else "")
    try:
        client = nbclient.NotebookClient(nb, timeout=300, kernel_name="python3",
                                         resources={"metadata": {"path": str(tmp_path)}})
        client.execute()
    finally:
        if old is None:
            os.environ.pop("PYTHONPATH")
        else:
            os.environ["PYTHONPATH"] = old
    outs = [o for c in nb.cells for o in c.get("outputs", [])]
    assert not [o for o in outs if o.output_type == "error"]
    views = [o for o in outs if "application/vnd.jupyter.widget-view+json" in o.get("data", {})]
    assert views, "the widget was displayed"
    text = "".join(o.get("text", "") for o in outs)
    assert "numbers" in text


# ----------------------------------------------------------------- the module in a browser
PAGE = """<!doctype html><meta charset="utf-8"><div id="el"></div><script type="module">
import view from "./widget.js";
const data = JSON.parse(document.getElementById("data").textContent);
const handlers = {};
const model = {
  get: (k) => data[k],
  set: (k, v) => { data[k] = v; (handlers["change:" + k] || []).forEach((f) => f()); },
  on: (ev, f) => { (handlers[ev] = handlers[ev] || []).push(f); },
  off: () => {},
  save_changes: () => { window.saved = (window.saved || 0) + 1; },
  send: () => {},
};
window.model = model;
view.render({ model, el: document.getElementById("el") });
window.rendered = true;
</script><script type="application/json" id="data">DATA</script>"""


@pytest.fixture(scope="module")
def served(tmp_path_factory):
    """The module and a page with a fake model (the traits of a real widget), served over
    HTTP from a temporary folder (a browser loads no ES module from file://)."""
    from rollingdisk.explore.widget import ESM_PATH, widget

    w = widget(0.17)
    w.selected = [0.5, 1.0]
    data = {k: getattr(w, k) for k in ("disk", "map", "motion", "frames")}
    data["selected"] = []
    tmp = tmp_path_factory.mktemp("widget")
    shutil.copy(ESM_PATH, tmp / "widget.js")
    (tmp / "index.html").write_text(PAGE.replace("DATA", json.dumps(data)))
    handler = lambda *a: http.server.SimpleHTTPRequestHandler(*a, directory=str(tmp))  # noqa: E731
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    threading.Thread(target=server.serve_forever, daemon=True).start()
    try:
        yield f"http://127.0.0.1:{server.server_address[1]}"
    finally:
        server.shutdown()


@pytest.mark.slow
def test_module_draws_and_a_click_round_trips(served, chromium):
    from selenium.webdriver.common.action_chains import ActionChains

    drv = chromium
    browser.set_viewport(drv, 900, 700)
    browser.requests(drv)  # from here on: the page's own
    drv.get(served + "/index.html")
    end = time.monotonic() + 30
    while not drv.execute_script("return window.rendered === true") and \
            time.monotonic() < end:
        time.sleep(0.2)
    painted = """const c = document.querySelector(arguments[0]);
        const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
        const seen = new Set();
        for (let i = 0; i < d.length; i += 4 * 97) seen.add(d[i] + ',' + d[i+1] + ',' + d[i+2]);
        return seen.size;"""
    assert drv.execute_script(painted, "canvas.rd-map") >= 3  # stable, unstable, none
    assert drv.execute_script(painted, "canvas.rd-3d") >= 3  # the disk on the plane
    canvas = drv.find_element("css selector", "canvas.rd-map")
    ActionChains(drv).move_to_element_with_offset(canvas, 30, -40).click().perform()
    sel = drv.execute_script("return window.model.get('selected')")
    assert isinstance(sel, list) and len(sel) == 2
    assert 0.0 < sel[0] < 1.5708 and drv.execute_script("return window.saved") == 1
    urls = browser.assert_local(drv, served)
    assert served + "/widget.js" in urls
    assert browser.console_errors(drv) == []
