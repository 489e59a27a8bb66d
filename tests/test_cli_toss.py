"""``rollingdisk toss``: the command's contract (the physics is in tests/test_motion.py).

Sources of truth: a reproducible seed gives the same counts twice; the counts add up to the
tosses asked for and the frequencies to one; bad input is one line and exit 2.
"""

import json

import pytest

from rollingdisk.cli import main


def test_toss_json_is_complete_and_reproducible(capsys):
    args = ["toss", "--h", "0.1", "--n", "3", "--seed", "0", "--max-wall", "5", "--json"]
    assert main(args) == 0
    first = json.loads(capsys.readouterr().out)
    assert main(args) == 0
    second = json.loads(capsys.readouterr().out)
    assert sum(first["counts"].values()) == 3
    assert sum(first["frequencies"].values()) == pytest.approx(1.0)
    assert first["counts"] == second["counts"]


@pytest.mark.parametrize("bad", [["--e", "1.5"], ["--e", "-0.1"], ["--mu", "nan"],
                                 ["--n", "0"], ["--max-wall", "0"], ["--h", "-1"]])
def test_bad_input_is_one_line_and_exit_2(bad, capsys):
    assert main(["toss", "--h", "0.1", *bad] if bad[0] != "--h" else ["toss", *bad]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("rollingdisk toss")
