"""Headless Chromium for the browser tests, written once: the system's browser and driver
(/usr/bin/chromium, /usr/bin/chromedriver; selenium-manager is never asked for them and
nothing is downloaded), a throw-away profile, and the DevTools log of every request the
browser makes, from which :func:`assert_local` checks that a page asked nothing of the
network, and :func:`console_errors` that its scripts raised nothing.  A test that needs a
browser is skipped where either binary or selenium (the ``browser`` extra) is missing.

The module-wide fixture ``chromium`` (tests/conftest.py) hands out one browser per test
module; :func:`chromium` opens another where a test needs its own.
"""

from __future__ import annotations

import contextlib
import json
import tempfile
from pathlib import Path

import pytest

CHROMIUM = Path("/usr/bin/chromium")
CHROMEDRIVER = Path("/usr/bin/chromedriver")

#: Chromium's switches: headless, no sandbox (containers), and none of its own traffic
#: (updates, sync, first-run pages), so that every request logged is the page's.
FLAGS = ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
         "--disable-component-update", "--disable-sync", "--no-first-run")

#: Requests that never leave the browser: its own pages and inline documents.
INTERNAL = ("chrome:", "data:", "about:", "blob:")


@contextlib.contextmanager
def chromium(width: int = 1280, height: int = 900):
    """A headless Chromium with a ``width`` x ``height`` CSS-pixel window that logs every
    request; quit and its profile removed on exit.  Skips the test where the browser, its
    driver or selenium is missing."""
    if not (CHROMIUM.exists() and CHROMEDRIVER.exists()):
        pytest.skip(f"needs {CHROMIUM} and {CHROMEDRIVER}")
    webdriver = pytest.importorskip("selenium.webdriver")
    from selenium.webdriver.chrome.service import Service

    options = webdriver.ChromeOptions()
    options.binary_location = str(CHROMIUM)
    with tempfile.TemporaryDirectory(prefix="rd-chromium-") as profile:
        for flag in (*FLAGS, f"--window-size={width},{height}", f"--user-data-dir={profile}"):
            options.add_argument(flag)
        options.set_capability("goog:loggingPrefs", {"performance": "ALL", "browser": "ALL"})
        driver = webdriver.Chrome(service=Service(executable_path=str(CHROMEDRIVER)),
                                  options=options)
        try:
            yield driver
        finally:
            driver.quit()


def set_viewport(driver, width: int, height: int) -> None:
    """Resize the window so that the page's viewport is ``width`` x ``height`` CSS pixels
    (headless windows have no chrome, but check and correct)."""
    driver.set_window_size(width, height)
    inner = driver.execute_script("return [window.innerWidth, window.innerHeight]")
    if inner != [width, height]:
        driver.set_window_size(2 * width - inner[0], 2 * height - inner[1])


def requests(driver) -> list[str]:
    """The URLs the browser asked for since the last call (its DevTools log), those that
    never leave the browser (:data:`INTERNAL`) aside."""
    urls = [e["params"]["request"]["url"] for e in
            (json.loads(entry["message"])["message"] for entry in driver.get_log("performance"))
            if e.get("method") == "Network.requestWillBeSent"]
    return [u for u in urls if not u.startswith(INTERNAL)]


def assert_local(driver, *allowed: str) -> list[str]:
    """Every request since the last look starts with one of ``allowed`` (the page's own
    server or folder): nothing was asked of the network.  The URLs, for further checks."""
    urls = requests(driver)
    for url in urls:
        assert url.startswith(allowed), f"{url} is outside {allowed}"
    return urls


def console_errors(driver) -> list[str]:
    """The errors the page's scripts raised or logged since the last call (a module that
    failed to load, an exception), a missing ``favicon.ico`` aside."""
    return [e["message"] for e in driver.get_log("browser")
            if e["level"] == "SEVERE" and "favicon.ico" not in e["message"]]
