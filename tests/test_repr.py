"""Results in a notebook (issue 19): short reprs, HTML tables with units, an inline animation.

Source of truth: each result's own fields (the table must list them, with the unit the
paper's definitions give: time sqrt(a/g), angular speed sqrt(g/a), energy m g a, and the SI
units when the disk has a scale), read back with the standard library's HTML parser.
"""

from html.parser import HTMLParser

import matplotlib
import pytest

matplotlib.use("Agg")

import rollingdisk as rd  # noqa: E402
from rollingdisk.scenarios.euler_disk import EulerDisk, run_euler_disk  # noqa: E402
from rollingdisk.util.display import MAX_REPR  # noqa: E402

SCALED = rd.Disk.from_dimensions(radius=0.0375, thickness=0.0127, mass=0.45)


class _Table(HTMLParser):
    """Rows of the first table: a list of lists of cell texts (header row first)."""

    def __init__(self):
        super().__init__()
        self.rows, self._cell, self.tables, self.caption, self._in_caption = [], None, 0, "", False

    def handle_starttag(self, tag, attrs):
        if tag == "table":
            self.tables += 1
        elif tag == "tr":
            self.rows.append([])
        elif tag in ("td", "th"):
            self._cell = ""
        elif tag == "caption":
            self._in_caption = True

    def handle_endtag(self, tag):
        if tag in ("td", "th"):
            self.rows[-1].append(self._cell)
            self._cell = None
        elif tag == "caption":
            self._in_caption = False

    def handle_data(self, data):
        if self._cell is not None:
            self._cell += data
        elif self._in_caption:
            self.caption += data


def _table(obj) -> dict:
    p = _Table()
    p.feed(obj._repr_html_())
    p.close()
    assert p.tables == 1 and p.caption
    header, *body = p.rows
    assert header[:3] == ["field", "value", "unit"]
    assert all(len(r) == len(header) for r in body)
    return {r[0]: dict(zip(header[1:], r[1:])) for r in body}


@pytest.fixture(scope="module")
def results():
    m = rd.steady_motion(SCALED, "rough", 0.5, Omega0=2.0)
    m0 = rd.steady_motion(rd.Disk(h=0.17), "rough", 0.5, r_C=0.5)
    tr = rd.simulate_steady(m0, 30.0, perturb=1e-6)
    tc = rd.simulate_coulomb(SCALED, rd.Coulomb(0.2, 0.15), (0, 5),
                             rd.rolling_state(SCALED, m.initial_state()))
    return {
        "steady": m, "steady_dimensionless": m0,
        "stability": rd.stability(m0),
        "unstable": rd.stability(rd.example_motions(0.17).unstable),
        "thresholds": rd.thresholds(SCALED), "thresholds_h": rd.thresholds(0.17),
        "trajectory": tr, "coulomb": tc,
        "trajectory_scaled": rd.simulate_steady(m, 2.0),
        "exact": rd.exact_steady(m, kick=0.01),
        "comparison": rd.compare_with_theory(tr),
        "euler": run_euler_disk(EulerDisk(alpha0=0.05), predict=False, t_max=20.0),
    }


def test_no_repr_over_the_limit(results):
    for name, r in results.items():
        text = repr(r)
        assert len(text) <= MAX_REPR, (name, len(text))
        assert "array(" not in text, name


def test_stability_repr_says_stable_and_period(results):
    text = repr(results["stability"])
    assert "stable=True" in text and "period=" in text
    text = repr(results["unstable"])
    assert "stable=False" in text and "growth_rate=" in text


@pytest.mark.parametrize("name,fields", [
    ("steady", {"theta0": "rad", "Omega0": "sqrt(g/a)", "r_C": "a", "F_y": "m g"}),
    ("steady_dimensionless", {"omega20": "sqrt(g/a)", "v_C": "sqrt(a g)"}),
    ("stability", {"varpi2": "g/a", "period": "sqrt(a/g)", "stable": "1"}),
    ("thresholds", {"rough_straight_line_omega20_sq": "g/a",
                    "rough_straight_line_speed": "sqrt(a g)"}),
    ("thresholds_h", {"smooth_spin_omega30_sq": "g/a"}),
    ("trajectory", {"status": "", "t_end": "sqrt(a/g)", "E_end": "m g a"}),
    ("coulomb", {"transitions": "", "t_end": "sqrt(a/g)"}),
    ("exact", {"period": "sqrt(a/g)", "theta_max": "rad", "E": "m g a"}),
    ("comparison", {"varpi2": "g/a", "rel_error": "1", "predicted": "sqrt(g/a)"}),
    ("euler", {"t_end": "sqrt(a/g)", "Omega_end": "sqrt(g/a)", "status": ""}),
])
def test_html_tables_list_the_fields_with_units(results, name, fields):
    table = _table(results[name])
    for field, unit in fields.items():
        assert field in table, (name, field, sorted(table))
        assert table[field]["unit"] == unit, (name, field, table[field])


@pytest.mark.parametrize("name,field,si_unit,factor", [
    ("steady", "Omega0", "rad/s", 1 / (0.0375 / 9.80665) ** 0.5),
    ("steady", "F_y", "N", 0.45 * 9.80665),
    ("thresholds", "rough_straight_line_speed", "m/s", (0.0375 * 9.80665) ** 0.5),
    ("exact", "period", "s", (0.0375 / 9.80665) ** 0.5),
    ("trajectory_scaled", "t_end", "s", (0.0375 / 9.80665) ** 0.5),
    ("euler", "t_end", "s", (0.0375 / 9.80665) ** 0.5),
])
def test_html_tables_give_si_beside_the_paper_units(results, name, field, si_unit, factor):
    row = _table(results[name])[field]
    assert row["SI unit"] == si_unit
    assert float(row["SI value"]) == pytest.approx(float(row["value"]) * factor, rel=1e-5)


def test_tables_without_scale_have_no_si_column(results):
    for name in ("steady_dimensionless", "trajectory", "thresholds_h", "comparison"):
        assert all("SI value" not in row for row in _table(results[name]).values())


def test_animation_html_is_inline(results):
    from rollingdisk.plotting.animation import animation_html

    html = animation_html(results["trajectory_scaled"], n_frames=2, dpi=20, size=(2.0, 2.0))
    assert "data:image/png;base64" in html and "<script" in html
    with pytest.raises(rd.ParameterError, match="n_frames"):
        animation_html(results["trajectory_scaled"], n_frames=1)
