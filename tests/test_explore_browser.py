"""The explorer in a real browser: Debian's headless Chromium driven by Selenium.

The page must show, for the point clicked on the map, exactly the library's numbers
(rd.steady_motion, rd.stability; the page keeps them at full precision in data-value
attributes), draw the 3D view, and give the library's reason where no steady motion
exists; every file it loads comes from the explorer's server (the page's script and the view
module it loads), none from the network.  The browser is the shared headless Chromium
(tests/browser.py), skipped where it or selenium (the ``browser`` extra) is missing.

Set ``ROLLINGDISK_SCREENSHOT=docs/gallery/explorer.png`` to keep a screenshot of the page.
"""

from __future__ import annotations

import math
import os
import time

import pytest

import browser
import rollingdisk as rd

pytest.importorskip("selenium.webdriver")

from selenium.webdriver.common.action_chains import ActionChains  # noqa: E402
from selenium.webdriver.common.by import By  # noqa: E402
from selenium.webdriver.support.ui import Select  # noqa: E402

from rollingdisk.explore import make_server  # noqa: E402

#: The map's plot box in canvas pixels (MARGIN in view.js, the canvas size in index.html).
BOX = {"x0": 58, "y0": 14, "w": 560 - 58 - 12, "h": 460 - 14 - 44}


@pytest.fixture(scope="module")
def page(chromium):
    srv = make_server(0.17, "rough", "127.0.0.1", 0)
    srv.start_in_thread()
    browser.set_viewport(chromium, 1300, 980)
    try:
        browser.requests(chromium)  # from here on: the page's own
        chromium.get(srv.url)
        yield chromium
    finally:
        srv.shutdown()
        srv.server_close()


def wait_for(driver, script, timeout=120.0):
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        value = driver.execute_script(script)
        if value:
            return value
        time.sleep(0.05)
    raise AssertionError(f"timed out waiting for: {script}")


def click_map(driver, theta0, y, y_range):
    """Click the map at (theta0, y) (data coordinates of the plot)."""
    canvas = driver.find_element(By.ID, "map")
    px = BOX["x0"] + theta0 / (0.5 * math.pi) * BOX["w"]
    py = BOX["y0"] + (1 - (y - y_range[0]) / (y_range[1] - y_range[0])) * BOX["h"]
    size = canvas.size  # the offset is from the element's centre, border included
    ActionChains(driver).move_to_element_with_offset(
        canvas, int(round(px + 1 - size["width"] / 2)),
        int(round(py + 1 - size["height"] / 2))).click().perform()


def shown(driver) -> dict:
    return driver.execute_script(
        "const out = {}; for (const e of document.querySelectorAll('#numbers [data-field]'))"
        " out[e.dataset.field] = e.dataset.value; return out;")


def test_click_shows_the_library_numbers_and_draws_3d(page):
    wait_for(page, "return document.getElementById('map').dataset.ready === '1'")
    click_map(page, 0.7, 1.4, (0.0, 3.0))  # the (theta0, omega30) map, stable region
    wait_for(page, "return document.getElementById('steady').dataset.exists === 'true'")
    box = page.find_element(By.ID, "steady")
    theta0 = float(box.get_attribute("data-theta0"))
    omega30 = float(box.get_attribute("data-value"))
    assert box.get_attribute("data-name") == "omega30"
    assert abs(theta0 - 0.7) < 0.01 and abs(omega30 - 1.4) < 0.02  # where we clicked
    m = rd.steady_motion(rd.Disk(0.17), "rough", theta0, Omega0=omega30 / math.cos(theta0))
    s = rd.stability(m)
    values = shown(page)
    for key, truth in (("Omega0", m.Omega0), ("omega20", m.omega20), ("omega30", m.omega30),
                       ("r_C", m.r_C), ("r_P", m.r_P), ("varpi2", s.varpi2),
                       ("period", s.period), ("mu_required", m.mu_required)):
        assert math.isclose(float(values[key]), truth, rel_tol=1e-9, abs_tol=1e-12), key
    assert values["stable"] == "true" and s.stable

    # the 3D view: simulated frames, a drawn disk (many pixels off the background)
    wait_for(page, "return document.getElementById('view').dataset.frames")
    painted = page.execute_script(
        "const c = document.getElementById('view'), d = c.getContext('2d')"
        ".getImageData(0, 0, c.width, c.height).data; let n = 0;"
        "for (let i = 0; i < d.length; i += 4)"
        "  if (Math.abs(d[i] - 0xee) + Math.abs(d[i+1] - 0xf1) + Math.abs(d[i+2] - 0xf5) > 60) n++;"
        "return n;")
    assert painted > 2000
    first = page.execute_script("return document.getElementById('view').toDataURL()")
    time.sleep(0.5)  # it plays: the picture changes
    assert page.execute_script("return document.getElementById('view').toDataURL()") != first

    # the friction slider: below mu_required the motion slides
    page.execute_script("const s = document.getElementById('mu'); s.value = '0';"
                        "s.dispatchEvent(new Event('input'));")
    assert page.find_element(By.ID, "rolls").text == "slides at once"
    page.execute_script("const s = document.getElementById('mu'); s.value = '0.6';"
                        "s.dispatchEvent(new Event('input'));")
    assert page.find_element(By.ID, "rolls").text == "rolls"

    # every file came from the explorer's server, the view module among them
    base = page.current_url.split("?")[0]
    urls = browser.assert_local(page, base)
    assert base + "view.js" in urls and base + "explore.js" in urls, urls
    assert browser.console_errors(page) == []

    shot = os.environ.get("ROLLINGDISK_SCREENSHOT")
    if shot:
        page.save_screenshot(shot)


def test_no_motion_region_shows_the_reason(page):
    Select(page.find_element(By.ID, "plane")).select_by_value("theta0-r_C")
    # the change handler clears data-ready at once and sets it when the new map is drawn
    wait_for(page, "return document.getElementById('map').dataset.ready === '1'")
    assert page.find_element(By.ID, "ymax").get_attribute("value") == "2"
    click_map(page, 0.1, 1.5, (-2.0, 2.0))  # Figure 4's dark region: r_C > r_C* at 5.7 deg
    wait_for(page, "return document.getElementById('steady').dataset.exists === 'false'")
    box = page.find_element(By.ID, "steady")
    theta0, r_C = float(box.get_attribute("data-theta0")), float(box.get_attribute("data-value"))
    with pytest.raises(rd.NoSteadyMotion) as exc:
        rd.steady_motion(rd.Disk(0.17), "rough", theta0, r_C=r_C)
    reason = page.find_element(By.ID, "reason")
    assert reason.is_displayed()
    assert reason.text == "No steady motion: " + str(exc.value)
    assert not page.execute_script("return document.getElementById('view').dataset.frames")


def test_a_phone_wide_page_has_no_sideways_scroll_and_its_map_still_answers(page):
    """At 420 CSS pixels (a phone) the page is one column no wider than the screen, and a
    click on the scaled-down map still asks for the point under the finger."""
    page.set_window_size(420, 900)
    try:
        page.get(page.current_url)
        wait_for(page, "return document.getElementById('map').dataset.ready === '1'")
        wide = page.execute_script(
            "return [document.documentElement.scrollWidth, window.innerWidth,"
            " Math.max(...[...document.querySelectorAll('body *')].map("
            "e => e.getBoundingClientRect().right))]")
        assert wide[0] <= wide[1] and wide[2] <= wide[1] + 0.5, wide
        canvas = page.find_element(By.ID, "map")
        scale = canvas.size["width"] / 560  # shown narrower than its 560 pixels
        assert scale < 1
        theta0, omega30 = 0.7, 1.4
        px = (BOX["x0"] + theta0 / (0.5 * math.pi) * BOX["w"]) * scale
        py = (BOX["y0"] + (1 - omega30 / 3.0) * BOX["h"]) * scale
        ActionChains(page).move_to_element_with_offset(
            canvas, int(round(px - canvas.size["width"] / 2)),
            int(round(py - canvas.size["height"] / 2))).click().perform()
        wait_for(page, "return document.getElementById('steady').dataset.exists === 'true'")
        box = page.find_element(By.ID, "steady")
        tol = 2.0 / scale  # a CSS pixel of the scaled map, in canvas pixels, twice
        assert abs(float(box.get_attribute("data-theta0")) - theta0) < tol * 0.5 * math.pi \
            / BOX["w"]
        assert abs(float(box.get_attribute("data-value")) - omega30) < tol * 3.0 / BOX["h"]
    finally:
        page.set_window_size(1300, 980)


def test_a_coin_shows_si_values_and_fits_a_phone():
    """``explore --disk euro-1``: a click on the map at 420 CSS pixels shows the steady
    motion's SI values beside the paper's (the coin's scales times the library's numbers),
    and the page still has no sideways scroll."""
    coin = rd.disk_from_options(disk="euro-1")
    srv = make_server(coin.h, "rough", "127.0.0.1", 0, disk=coin)
    srv.start_in_thread()
    try:
        with browser.chromium(420, 900) as driver:
            browser.set_viewport(driver, 420, 900)
            driver.get(srv.url)
            wait_for(driver, "return document.getElementById('map').dataset.ready === '1'")
            canvas = driver.find_element(By.ID, "map")
            scale = canvas.size["width"] / 560
            px = (BOX["x0"] + 0.7 / (0.5 * math.pi) * BOX["w"]) * scale
            py = (BOX["y0"] + (1 - 1.4 / 3.0) * BOX["h"]) * scale
            ActionChains(driver).move_to_element_with_offset(
                canvas, int(round(px - canvas.size["width"] / 2)),
                int(round(py - canvas.size["height"] / 2))).click().perform()
            wait_for(driver,
                     "return document.getElementById('steady').dataset.exists === 'true'")
            got = shown(driver)
            m = rd.steady_motion(coin, "rough", float(got["theta0"]),
                                 omega30=float(got["omega30"]))
            ts = float(coin.time_to_si(1.0))
            assert float(got["si:Omega0 [rad/s]"]) == pytest.approx(m.Omega0 / ts, rel=1e-9)
            assert float(got["si:r_C [mm]"]) == pytest.approx(1e3 * m.r_C * 0.011625,
                                                              rel=1e-9)
            wide = driver.execute_script(
                "return [document.documentElement.scrollWidth, window.innerWidth]")
            assert wide[0] <= wide[1], wide
            browser.assert_local(driver, srv.url.split("?")[0])
    finally:
        srv.shutdown()
        srv.server_close()
