"""``rollingdisk toss`` and ``simulate --until-rest``: the commands past the guards (the
physics is tested in tests/test_motion.py and tests/test_impact.py).

Sources of truth: a reproducible seed gives the same counts twice; the counts add up to the
tosses asked for and the frequencies to one; the energy balance closes over every phase of a
run to rest; bad input is one line and exit 2.
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


def test_simulate_until_rest_goes_past_the_guards(capsys):
    """A disk let go at theta = 0.3 falls: without --until-rest the run stops at the guard
    (fell-flat); with it, it lands on its face, slides, and the energy balance closes over
    rolling, sliding, the face impact and the flat phase."""
    base = ["simulate", "--ground", "coulomb", "--mu", "0.5", "--h", "0.1", "--state",
            "theta=0.3", "--t-end", "100", "--json"]
    assert main(base) == 0
    stopped = json.loads(capsys.readouterr().out)
    assert stopped["status"] == "fell-flat"
    assert main([*base, "--until-rest", "--restitution", "0.3"]) == 0
    rec = json.loads(capsys.readouterr().out)
    assert rec["status"] == "at-rest" and rec["t_end"] < 100
    assert rec["n_impacts"] >= 1 and rec["impact_loss"] > 0
    assert rec["energy_balance"] <= 1e-9
    assert [x["to"] for x in rec["transitions"]][-2:] == ["flat", "rest"]


def test_until_rest_animates_the_whole_motion(tmp_path, capsys):
    from PIL import Image

    gif = tmp_path / "rest.gif"
    assert main(["simulate", "--ground", "coulomb", "--mu", "0.5", "--h", "0.1", "--state",
                 "theta=0.3", "--t-end", "100", "--until-rest", "--animate", str(gif),
                 "--json"]) == 0
    rec = json.loads(capsys.readouterr().out)
    assert rec["animation"] == str(gif) and rec["status"] == "at-rest"
    with Image.open(gif) as im:
        assert im.n_frames > 10
    assert main(["simulate", "--ground", "coulomb", "--mu", "0.5", "--h", "0.1", "--state",
                 "theta=0.3", "--t-end", "1", "--animate", str(tmp_path / "x.gif")]) == 2
    assert "--until-rest" in capsys.readouterr().err


def test_until_rest_needs_coulomb_ground(capsys):
    assert main(["simulate", "--h", "0.1", "--theta0", "30deg", "--Omega0", "1",
                 "--t-end", "1", "--until-rest"]) == 2
    assert "--ground coulomb" in capsys.readouterr().err
