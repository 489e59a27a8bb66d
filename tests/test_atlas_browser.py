"""The atlas page in a real browser: Debian's headless Chromium driven by Selenium.

A quick atlas (``build_atlas(0.17, tmp, quick=True)``) is opened from disk.  Sources of
truth are the browser's own layout: the table of contents links to ids that exist on the
page; at a phone's width (420 px) nothing overflows horizontally and the body text computes
to at least 14 px; every image decoded (``naturalWidth > 0``); the viewport meta tag is
there.  Nothing is downloaded: the driver and the browser are the system's
(/usr/bin/chromedriver, /usr/bin/chromium); selenium-manager is never asked for them.
Skipped where either is missing or selenium is not installed (the ``browser`` extra).

Set ``ROLLINGDISK_ATLAS_SCREENSHOTS=DIR`` to keep screenshots at 1200 px and 420 px.
"""

from __future__ import annotations

import os
import tempfile
from pathlib import Path

import pytest

CHROMIUM = Path("/usr/bin/chromium")
CHROMEDRIVER = Path("/usr/bin/chromedriver")

if not (CHROMIUM.exists() and CHROMEDRIVER.exists()):
    pytest.skip("needs /usr/bin/chromium and /usr/bin/chromedriver", allow_module_level=True)
webdriver = pytest.importorskip("selenium.webdriver")

from selenium.webdriver.chrome.service import Service  # noqa: E402

from rollingdisk.atlas.build import build_atlas  # noqa: E402

# building the atlas (about 20 s on 2 cores) and starting Chromium take well over 10 s
pytestmark = pytest.mark.slow

PHONE, DESKTOP = 420, 1200


@pytest.fixture(scope="module", params=["dimensionless", "euro-1"])
def atlas(request, tmp_path_factory):
    """A quick atlas of the default dimensionless disk, and of a 1-euro coin (SI)."""
    import matplotlib

    import rollingdisk as rd

    matplotlib.use("Agg")
    disk = 0.17 if request.param == "dimensionless" else rd.disk_from_options(disk="euro-1")
    return build_atlas(disk, tmp_path_factory.mktemp("atlas") / "atlas", quick=True,
                       progress=False)


def test_a_coin_atlas_answers_in_si(atlas):
    """SI where the disk has a size, the paper's units alone where it has none."""
    page = atlas.index.read_text(encoding="utf-8")
    if atlas.disk is not None and atlas.disk.radius is not None:
        assert "m/s" in page and "rad/s" in page and " mm " in page
    else:
        assert "rad/s" not in page and "m/s" not in page


@pytest.fixture(scope="module")
def driver():
    options = webdriver.ChromeOptions()
    options.binary_location = str(CHROMIUM)
    profile = tempfile.TemporaryDirectory(prefix="rd-chromium-")
    for flag in ("--headless=new", "--no-sandbox", "--disable-gpu",
                 "--disable-background-networking", "--disable-component-update",
                 "--disable-sync", "--no-first-run", f"--window-size={DESKTOP},900",
                 f"--user-data-dir={profile.name}"):
        options.add_argument(flag)
    drv = webdriver.Chrome(service=Service(executable_path=str(CHROMEDRIVER)),
                           options=options)
    try:
        yield drv
    finally:
        drv.quit()
        profile.cleanup()


def _open(driver, atlas, width: int):
    """Load the page with a viewport ``width`` CSS pixels wide; wait for every image."""
    driver.set_window_size(width, 900)
    # the window's outer size includes no chrome in headless mode, but check and correct
    inner = driver.execute_script("return window.innerWidth")
    if inner != width:
        driver.set_window_size(2 * width - inner, 900)
    driver.get(atlas.index.as_uri())
    driver.set_script_timeout(30)
    driver.execute_async_script(
        "const done = arguments[arguments.length - 1];"
        "Promise.all([...document.images].map(i => i.complete ? 0 :"
        " new Promise(r => { i.onload = i.onerror = r; }))).then(() => done(true));")


def _screenshot(driver, name: str):
    keep = os.environ.get("ROLLINGDISK_ATLAS_SCREENSHOTS")
    if keep:
        Path(keep).mkdir(parents=True, exist_ok=True)
        driver.save_screenshot(str(Path(keep) / name))


def test_table_of_contents_links_resolve(driver, atlas):
    _open(driver, atlas, DESKTOP)
    links = driver.execute_script(
        "return [...document.querySelectorAll('nav.toc a')].map(a => a.getAttribute('href'))")
    assert len(links) >= 8, links
    ids = driver.execute_script(
        "return [...document.querySelectorAll('[id]')].map(e => e.id)")
    for href in links:
        assert href.startswith("#"), href
        assert href[1:] in ids, f"{href} names no element of the page"
    # following a link scrolls to its section
    driver.execute_script("document.querySelector('nav.toc a[href=\"#euler-disk\"]').click()")
    top = driver.execute_script(
        "return document.getElementById('euler-disk').getBoundingClientRect().top")
    assert abs(top) < 5, top
    _screenshot(driver, f"atlas_{DESKTOP}.png")


def test_viewport_meta(driver, atlas):
    _open(driver, atlas, DESKTOP)
    content = driver.execute_script(
        "const m = document.querySelector('meta[name=viewport]'); return m && m.content")
    assert content is not None
    assert "width=device-width" in content and "initial-scale=1" in content


def test_every_image_loads(driver, atlas):
    _open(driver, atlas, DESKTOP)
    images = driver.execute_script(
        "return [...document.images].map(i => [i.getAttribute('src'), i.naturalWidth])")
    names = {src for src, _ in images}
    assert {"existence.png", "stability.png", "motion_stable.gif", "euler_disk.png"} <= names
    for src, width in images:
        assert width > 0, f"{src} did not load"


def test_phone_width_no_horizontal_overflow_readable_text(driver, atlas):
    _open(driver, atlas, PHONE)
    inner = driver.execute_script("return window.innerWidth")
    assert inner == PHONE
    scroll = driver.execute_script("return document.documentElement.scrollWidth")
    assert scroll <= inner + 1, f"the page is {scroll} px wide in a {inner} px window"
    # body text, paragraphs and table cells compute to at least 14 px
    sizes = driver.execute_script(
        "const px = e => parseFloat(getComputedStyle(e).fontSize);"
        "return [px(document.body)].concat("
        "[...document.querySelectorAll('p, li, td, th')].map(px))")
    assert min(sizes) >= 14.0, min(sizes)
    # and no image is wider than the window
    widest = driver.execute_script(
        "return Math.max(...[...document.images].map(i => i.getBoundingClientRect().right))")
    assert widest <= inner + 1
    _screenshot(driver, f"atlas_{PHONE}.png")
