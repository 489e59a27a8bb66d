"""The public API is the README's and no more.

Source of truth: the table between ``<!-- public-api -->`` markers in README.md, written for
people; ``rollingdisk.__all__`` must list exactly its names, each must exist, and none of the
validators or internals (``check_*``, ``h_tilde``, names starting with ``_``) may leak.
"""

import re
from pathlib import Path

import rollingdisk as rd

README = Path(__file__).resolve().parents[1] / "README.md"


def _documented() -> list[str]:
    text = README.read_text()
    block = text.split("<!-- public-api -->")[1].split("<!-- /public-api -->")[0]
    names = []
    for line in block.splitlines()[2:]:
        cells = line.split("|")
        if len(cells) > 2:
            names += re.findall(r"`([A-Za-z_][A-Za-z0-9_]*)`", cells[2])
    return names


def test_all_is_exactly_the_documented_api():
    documented = _documented()
    assert len(documented) == len(set(documented)), "a name is listed twice in the README"
    assert sorted(rd.__all__) == sorted(documented)


def test_every_public_name_exists_and_no_internal_leaks():
    for name in rd.__all__:
        assert hasattr(rd, name), name
        assert not name.startswith("_") and not name.startswith("check_"), name
    assert "h_tilde" not in rd.__all__ and "check_real" not in rd.__all__


def test_version_comes_from_the_package_metadata():
    from importlib.metadata import version

    assert rd.__version__ == version("rollingdisk")
