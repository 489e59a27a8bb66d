"""CLI: `rollingdisk derive` and the CLI's error handling (exit 2, one line, no traceback)."""

import json
import subprocess
import sys

from rollingdisk.cli.app import main


def test_derive_json_section_2(capsys):
    """The CLI passes the rows through as strict JSON; section 2 only (the full check of
    every equation is tested in test_derivation.py and test_sections34.py)."""
    assert main(["derive", "--sections", "2", "--json"]) == 0
    rows = json.loads(capsys.readouterr().out)
    eqs = {r["equation"] for r in rows}
    assert eqs >= {"(1)", "(13)", "(37)", "(38)", "(49)"}
    assert all(r["status"] in ("confirmed", "misprint") for r in rows)
    listed = [r["equation"] for r in rows]
    for eq in ("(37)", "(38)", "(49)"):  # checked once
        assert listed.count(eq) == 1, eq


def test_derive_table(capsys):
    assert main(["derive", "--sections", "2"]) == 0
    out = capsys.readouterr().out
    assert "(38)" in out and "equations checked" in out


def test_unknown_command_is_one_line_exit_2(capsys):
    assert main(["fly"]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "invalid choice" in err


def test_no_command_prints_help_exit_2(capsys):
    assert main([]) == 2
    assert "usage" in capsys.readouterr().err


def test_python_dash_m_entry_point():
    res = subprocess.run([sys.executable, "-m", "rollingdisk", "--help"], capture_output=True,
                         text=True)
    assert res.returncode == 0 and "derive" in res.stdout
