"""CLI: `rollingdisk derive` and the CLI's error handling (exit 2, one line, no traceback)."""

import json
import subprocess
import sys

from rollingdisk.cli import main


def test_derive_json(capsys):
    assert main(["derive", "--json"]) == 0
    rows = json.loads(capsys.readouterr().out)
    eqs = {r["equation"] for r in rows}
    assert eqs >= {"(1)", "(13)", "(37)", "(38)", "(49)", "(33)", "(45)", "(57)"}
    assert all(r["status"] in ("confirmed", "misprint") for r in rows)
    bad = {r["equation"] for r in rows if r["status"] == "misprint"}
    assert {"(31) first form", "(33)", "(44)", "(45)", "(48)"} <= bad
    assert all(r["printed"] and r["correct"] for r in rows if r["status"] == "misprint")
    listed = [r["equation"] for r in rows]
    for eq in ("(37)", "(38)", "(49)"):  # checked once, with section 2
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
