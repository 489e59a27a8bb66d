"""The atlas page in a real browser: Debian's headless Chromium driven by Selenium.

A quick atlas (``build_atlas(0.17, tmp, quick=True)``, and of a 1-euro coin) is opened from
disk.  Sources of truth are the browser's own layout: the table of contents links to ids
that exist on the page; at a phone's width (420 px) nothing overflows horizontally and the
body text computes to at least 14 px; every image decoded (``naturalWidth > 0``); the
viewport meta tag is there; at a laptop's 1280 x 800 the coin atlas's first screen, without
scrolling, names the coin and shows 0.197 m/s, and every request the browser makes (its
DevTools log) is for a file of the atlas.  The browser is the shared headless Chromium
(tests/browser.py), skipped where it or selenium (the ``browser`` extra) is missing.

Set ``ROLLINGDISK_ATLAS_SCREENSHOTS=DIR`` to keep screenshots at 1200 px and 420 px, and the
coin atlas's first screen (``atlas_coin_1280x800.png`` and its text).
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest

import browser
from rollingdisk.atlas.build import build_atlas

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
def driver(chromium):
    browser.set_viewport(chromium, DESKTOP, 900)
    return chromium


def _open(driver, atlas, width: int):
    """Load the page with a viewport ``width`` CSS pixels wide; wait for every image."""
    browser.set_viewport(driver, width, 900)
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


LAPTOP = (1280, 800)

#: The text of the page that lies in the viewport (no scrolling): every text node's
#: client rectangles that intersect the window, of elements that are rendered.
_FIRST_SCREEN = """
const w = window.innerWidth, h = window.innerHeight, out = [];
const walk = document.createTreeWalker(document.body, NodeFilter.SHOW_TEXT);
for (let n = walk.nextNode(); n; n = walk.nextNode()) {
  const el = n.parentElement, st = el && getComputedStyle(el);
  if (!st || st.visibility !== 'visible' || st.display === 'none') continue;
  const r = document.createRange(); r.selectNodeContents(n);
  for (const b of r.getClientRects())
    if (b.width > 0 && b.height > 0 && b.top >= 0 && b.bottom <= h && b.left >= 0
        && b.right <= w) { out.push(n.textContent); break; }
}
return out.join(' ');
"""


def test_first_screen_of_the_coin_atlas(driver, atlas):
    """At a laptop's 1280 x 800 the first screen names the coin and gives its speed of
    stable straight rolling, 0.197 m/s; the page asks nothing of the network."""
    if atlas.disk is None or atlas.disk.radius is None:
        pytest.skip("the answers lead the atlas of a disk with a size")
    width, height = LAPTOP
    browser.set_viewport(driver, width, height)
    browser.requests(driver)  # drop what earlier pages asked for
    driver.get(atlas.index.as_uri())
    driver.set_script_timeout(30)
    driver.execute_async_script(
        "const done = arguments[arguments.length - 1];"
        "Promise.all([...document.images].map(i => i.complete ? 0 :"
        " new Promise(r => { i.onload = i.onerror = r; }))).then(() => done(true));")
    assert driver.execute_script("return [window.innerWidth, window.innerHeight]") == [
        width, height]
    assert driver.execute_script("return window.scrollY") == 0
    first = " ".join(driver.execute_script(_FIRST_SCREEN).split())
    _screenshot(driver, "atlas_coin_1280x800.png")
    keep = os.environ.get("ROLLINGDISK_ATLAS_SCREENSHOTS")
    if keep:
        (Path(keep) / "atlas_coin_first_screen.txt").write_text(first, encoding="utf-8")
    assert "euro" in first and "1-euro coin" in driver.title
    assert "0.197 m/s" in first
    # every request the browser made is for a file beside the page: none leaves the machine
    urls = browser.assert_local(driver, atlas.out_dir.as_uri() + "/")
    assert atlas.index.as_uri() in urls and any(u.endswith(".png") for u in urls), urls
