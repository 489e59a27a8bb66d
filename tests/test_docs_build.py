"""The documentation site builds offline with warnings as errors and documents every name.

A copy of ``docs/`` and ``examples/`` is built in a temporary folder (the worktree's source
tree untouched; ``src`` linked in), with ``-W --keep-going``.  Then: every name of
``rollingdisk.__all__`` and of the public modules' ``__all__`` has its own page, no two
pages differ only in case (they would be one file on macOS and Windows), and every example
of the gallery has a page with its figure.
"""

import importlib
import os
import shutil
import subprocess
import sys
import time
from pathlib import Path

import pytest

import browser
import rollingdisk

for _mod in ("sphinx", "numpydoc", "myst_parser", "sphinx_gallery"):
    pytest.importorskip(_mod)

pytestmark = pytest.mark.slow

ROOT = Path(__file__).resolve().parents[1]
GENERATED = ("_build", "auto_examples", "api", "sg_execution_times.rst")


@pytest.fixture(scope="module")
def built(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("site")
    shutil.copytree(ROOT / "docs", tmp / "docs", ignore=lambda d, names: [
        n for n in names if Path(d) == ROOT / "docs" and n in GENERATED])
    shutil.copytree(ROOT / "examples", tmp / "examples")
    (tmp / "src").symlink_to(ROOT / "src", target_is_directory=True)
    env = {**os.environ, "PYTHONPATH": str(ROOT / "src"), "MPLBACKEND": "Agg"}
    res = subprocess.run(
        [sys.executable, "-m", "sphinx", "-W", "--keep-going", "-b", "html",
         "-d", str(tmp / "doctrees"), str(tmp / "docs"), str(tmp / "html")],
        cwd=tmp, env=env, capture_output=True, text=True, timeout=900)
    return res, tmp / "html"


def test_build_without_warnings(built):
    res, html = built
    assert res.returncode == 0, res.stderr[-6000:]
    assert "WARNING" not in res.stderr and "ERROR" not in res.stderr, res.stderr[-6000:]
    assert (html / "index.html").is_file()


def _page(html: Path, name: str) -> Path | None:
    for candidate in (f"{name}.html", f"{name}-function.html"):
        if (html / "api" / "generated" / candidate).is_file():
            return html / "api" / "generated" / candidate
    return None


def test_every_public_name_has_a_page(built):
    _, html = built
    names = [f"rollingdisk.{n}" for n in rollingdisk.__all__]
    for mod in ("theory.exact", "sweep", "scenarios.euler_disk", "plotting", "symbolic"):
        module = importlib.import_module(f"rollingdisk.{mod}")
        names += [f"rollingdisk.{mod}.{n}" for n in module.__all__  # documented once: at
                  if getattr(rollingdisk, n, None) is not getattr(module, n)]  # the top
    missing = [n for n in names if _page(html, n) is None]
    assert not missing, missing
    for n in names:  # the page is about that name
        assert n.rpartition(".")[2] in _page(html, n).read_text(encoding="utf-8")


def test_pages_differ_in_more_than_case(built):
    _, html = built
    files = [p.name for p in (html / "api" / "generated").glob("*.html")]
    assert len({f.lower() for f in files}) == len(files)


def test_every_example_has_a_gallery_page_with_a_figure(built):
    _, html = built
    for path in sorted((ROOT / "examples").glob("plot_*.py")):
        page = html / "auto_examples" / f"{path.stem}.html"
        assert page.is_file(), path.name
        assert f"sphx_glr_{path.stem}_001.png" in page.read_text(encoding="utf-8"), path.name
        assert (html / "_images" / f"sphx_glr_{path.stem}_001.png").is_file(), path.name


# ---------------------------------------------------------------------------------------
# the built site in a real browser: the shared headless Chromium (tests/browser.py)
# ---------------------------------------------------------------------------------------
def _wait(driver, script: str, timeout: float = 30.0):
    """Poll ``script`` (a JavaScript expression) until it is truthy; its value."""
    end = time.monotonic() + timeout
    while True:
        value = driver.execute_script(f"return ({script});")
        if value or time.monotonic() > end:
            return value
        time.sleep(0.2)


def test_math_renders_offline(built, chromium):
    """The derived equations are typeset by the MathJax shipped with the site: MathJax's
    output elements appear, no TeX source is left showing, and every request the page
    makes is for a file of the site."""
    _, html = built
    browser.requests(chromium)
    chromium.get((html / "equations.html").as_uri())
    n = _wait(chromium, "document.querySelectorAll('mjx-container').length")
    assert n and n >= 40, n
    text = chromium.execute_script("return document.body.innerText")
    assert "\\frac" not in text and "\\sqrt" not in text
    urls = browser.assert_local(chromium, html.as_uri() + "/")
    assert any("mathjax" in u for u in urls), urls


def test_search_finds_euler(built, chromium):
    _, html = built
    chromium.get((html / "search.html").as_uri() + "?q=Euler")
    hits = _wait(chromium, "document.querySelectorAll('#search-results li').length")
    assert hits and hits >= 3, hits
    titles = chromium.execute_script(
        "return [...document.querySelectorAll('#search-results li a')].map(a => a.textContent)")
    assert any("Euler" in t for t in titles), titles


def test_cli_reference_lists_every_command(built, chromium):
    from rollingdisk.cli.app import COMMANDS

    _, html = built
    browser.requests(chromium)
    chromium.get((html / "cli.html").as_uri())
    heads = chromium.execute_script(
        "return [...document.querySelectorAll('h2')].map(h => h.textContent)")
    for name, _module, _text in COMMANDS:
        assert any(f"rollingdisk {name}" in h for h in heads), (name, heads)
    body = chromium.execute_script("return document.body.innerText")
    assert "--t-end" in body and "--disk" in body
    browser.assert_local(chromium, html.as_uri() + "/")
