"""The atlas page, ``index.html``: the numbers of a built atlas put into the HTML templates
shipped in ``rollingdisk/atlas/templates/`` (:class:`string.Template`, ``${name}``
placeholders; the page's style is ``style.css``, set inline so the page has no external
resource).  Every number is formatted here, with its unit; text that comes from a run
(statuses, messages, file names) is HTML-escaped here before it goes into a template.
"""

from __future__ import annotations

import html
import math
from functools import cache
from importlib import resources
from string import Template

from rollingdisk.model.disk import check_h

#: Units of the page (HTML): the paper's, ``m = a = g = 1``.
_T = "&radic;(a/g)"
_W = "&radic;(g/a)"

#: Sections of the page: (anchor, title) for the table of contents.
_SECTIONS = (("thresholds", "Stability thresholds"),
             ("existence", "Where steady circles exist"),
             ("stability", "Stability of steady circles"),
             ("all-omega30", "Stable for every &omega;<sub>30</sub>"),
             ("motions", "Two steady circles, simulated"),
             ("exact", "The stable circle at finite amplitude"),
             ("to-rest", "Past the guards: a disk let go to rest"),
             ("euler-disk", "Euler's disk"),
             ("learn-more", "Learn more"),
             ("files", "Files"))


@cache
def _text(name: str) -> str:
    """The template file ``name``, without the newline that ends the file."""
    text = resources.files(__package__).joinpath("templates", name).read_text(encoding="utf-8")
    return text[:-1] if text.endswith("\n") else text


def _render(name: str, **values) -> str:
    """The template ``name`` filled in with ``values`` (and the page's units ``unit_t``,
    ``unit_w``); a placeholder without a value raises ``KeyError``."""
    return Template(_text(name)).substitute(unit_t=_T, unit_w=_W, **values)


def _fmt(x, nd=4):
    if x is None:
        return "&ndash;"
    if isinstance(x, bool):
        return "yes" if x else "no"
    return f"{x:.{nd}g}"


def _deg(x, nd=4):
    """An angle in radians, shown in degrees."""
    return "&ndash;" if x is None else f"{math.degrees(x):.{nd}g}&deg;"


def _img(src: str, alt: str, width: int | None = None) -> str:
    """An image that opens at full size when tapped (a phone shrinks it to the screen)."""
    w = f' width="{width}"' if width else ""
    return f'<a href="{src}"><img src="{src}" alt="{html.escape(alt)}"{w}></a>'


def _index_html(h, thr: dict, motions: dict, names: list) -> str:
    """The atlas page: every section in order, with relative image paths only."""
    hv = check_h(h)  # h, or a Disk with or without a physical scale
    disk = h if hasattr(h, "radius") else None
    e = html.escape
    return _render(
        "index.html", css=_text("style.css"), **_head_values(h, hv),
        answers=_answers(disk, thr, motions),
        threshold_rows=_threshold_rows(thr, disk),
        img_existence=_img("existence.png", "existence map on rough ground"),
        img_stability=_img("stability.png", "stability maps"),
        img_varpi2=_img("varpi2.png", "varpi squared against omega30"),
        img_all_omega30=_img("all_omega30.png", "regions stable for every omega30"),
        motion_stable=_motion_block(motions["stable"], "stable"),
        motion_unstable=_motion_block(motions["unstable"], "unstable"),
        **_exact_values(motions["exact"]),
        **_to_rest_values(motions["to_rest"], _object(disk)),
        **_euler_values(motions["euler_disk"], _ran_as_euler_disk(disk, motions)),
        files=" &middot; ".join(f'<a href="{e(n)}">{e(n)}</a>' for n in names))


def _object(disk) -> str | None:
    """What the disk is, in words: ``"the 1-euro coin"`` for a disk of the named-disk table
    (:data:`rollingdisk.model.units.DISKS`, the words before the colon of its source; same
    radius and thickness, any mass), ``"this disk"`` for another disk with a physical size,
    ``None`` without one."""
    from rollingdisk.model.units import DISKS

    a = getattr(disk, "radius", None)
    if a is None:
        return None
    for nd in DISKS.values():
        if math.isclose(a, nd.radius, rel_tol=1e-12) and math.isclose(disk.h, nd.h,
                                                                        rel_tol=1e-12):
            label = nd.source.split(":")[0].strip()
            return label if label.startswith(("a ", "the ")) else f"the {label}"
    return "this disk"


def _title(h, hv) -> str:
    """What the atlas is about: the object and its size when it has one, its h always."""
    a = getattr(h, "radius", None)
    if a is None:
        return f"a disk of half-thickness h = {hv:.4g}"
    what = _object(h)
    size = (f"radius {a * 1e3:.4g} mm and thickness {2 * hv * a * 1e3:.4g} mm "
            f"(h = {hv:.4g})")
    return f"a disk of {size}" if what == "this disk" else f"{what}: {size}"


def _head_values(h, hv) -> dict:
    """The page's head, introduction, units (the SI conversion when the disk has a
    physical scale) and table of contents."""
    a = getattr(h, "radius", None)
    units_si = ""
    if a is not None:
        T = math.sqrt(a / h.gravity)
        units_si = _render("units_si.html", a_mm=f"{a * 1e3:.4g}", g=f"{h.gravity:.4g}",
                           T=f"{T:.4g}", rate=f"{1.0 / T:.4g}", a=f"{a:.4g}")
    what = _object(h)
    page_title = (f"rollingdisk atlas, h = {hv:.4g}" if what in (None, "this disk") else
                  f"rollingdisk atlas of {what}, h = {hv:.4g}")
    return {"h": f"{hv:.4g}", "title": _title(h, hv), "two_h": f"{2 * hv:.4g}",
            "page_title": html.escape(page_title, quote=False),
            "se_tilt": _deg(math.atan(hv)), "units_si": units_si,
            "toc_items": "\n".join(f'<li><a href="#{a}">{t}</a></li>' for a, t in _SECTIONS)}


def _threshold_rows(thr: dict, disk=None) -> str:
    """One row per steady motion; the threshold of |omega20| and of |omega30| in columns of
    their own (each row has one of them); in rad/s too when the disk has a size."""
    a = getattr(disk, "radius", None)
    w_si = None if a is None else math.sqrt(disk.gravity / a)  # sqrt(g/a) in rad/s
    rows = [
        ("rough", "straight line in the SE position", "42", "omega20",
         thr["rough"]["straight_line_omega20_sq"]),
        ("rough", "circle in the SE position", "43", "omega30",
         thr["rough"]["se_circle_omega30_sq"]),
        ("smooth", "straight line", "53", "omega20", thr["smooth"]["straight_line_omega20_sq"]),
        ("smooth", "spin in place", "57", "omega30", thr["smooth"]["spin_omega30_sq"]),
    ]

    def cell(which, key, v):
        if which != key:
            return '<td class="empty">&ndash;</td>'
        sym = "&omega;<sub>20</sub>" if key == "omega20" else "&omega;<sub>30</sub>"
        si = "" if w_si is None else f"<br>= {_fmt(math.sqrt(v) * w_si)} rad/s"
        return (f'<td>{_fmt(math.sqrt(v))} <span class="note">({sym}&sup2; &gt; '
                f'{_fmt(v)})</span>{si}</td>')

    return "\n".join(
        f"<tr><td>{g}</td><td class=\"text\">{what}</td><td>({eq})</td>"
        f"{cell('omega20', key, v)}{cell('omega30', key, v)}</tr>"
        for g, what, eq, key, v in rows)


def _motion_block(m: dict, kind: str) -> str:
    """The page's section of one simulated steady circle."""
    verdict = _render(
        "verdict_stable.html" if m["stable"] else "verdict_unstable.html",
        varpi2=_fmt(m["varpi2"]), varpi=_fmt(m["varpi"]), period=_fmt(m["period"]),
        growth_rate=_fmt(m["growth_rate"]), measured=_fmt(m["measured"]))
    return _render(
        "motion.html", kind=kind, title=kind.capitalize(), verdict=verdict,
        theta0=_deg(m["theta0"]), Omega0=_fmt(m["Omega0"]), omega20=_fmt(m["omega20"]),
        omega30=_fmt(m["omega30"]), r_C=_fmt(m["r_C"]), r_P=_fmt(m["r_P"]),
        si_row=_si_row(m), kick=_fmt(m["kick"], 2), t_end=_fmt(m["t_end"]),
        status=html.escape(m["status"]), max_theta_dev=_deg(m["max_theta_dev"], 3),
        energy_error=_fmt(m["energy_error"], 2),
        img_plots=_img(f"motion_{kind}.png", f"{kind} motion plots", 620),
        img_gif=_img(f"motion_{kind}.gif", f"{kind} motion animation", 350))


def _si_row(m: dict) -> str:
    """The motion's row in SI (rad/s, m) when its disk has a size, else nothing."""
    if m.get("Omega0_si") is None:
        return ""
    cells = "".join(f"<td>{_fmt(m[k])} {u}</td>" for k, u in (
        ("Omega0_si", "rad/s"), ("omega20_si", "rad/s"), ("omega30_si", "rad/s"),
        ("r_C_si", "m"), ("r_P_si", "m")) if m.get(k) is not None)
    return f'\n<tr><td class="text">SI</td>{cells}</tr>'


def _exact_values(ex: dict) -> dict:
    """The stable circle's exact motion at finite amplitude."""
    return {"exact_kick": _fmt(ex["kick"], 3), "exact_theta_min": _deg(ex["theta_min"], 6),
            "exact_theta_max": _deg(ex["theta_max"], 6), "exact_period": _fmt(ex["period"], 8),
            "exact_linear_period": _fmt(ex["linear_period"], 8),
            "exact_delta_psi": _deg(ex["delta_psi"], 6),
            "exact_frequency_at_largest": _fmt(ex["frequency_at_largest"], 5),
            "exact_largest_amplitude": _deg(ex["largest_amplitude"], 3),
            "exact_img": _img("exact.png",
                              "exact motion: theta over a period, rosette, backbone")}


def _to_rest_values(m: dict, what: str | None = None) -> dict:
    """The section "Past the guards": the run :data:`~rollingdisk.atlas.steps.TO_REST` (of
    the disk ``what`` names, when the atlas has a disk with a size) and its numbers."""
    gif = (_img("to_rest.gif", "a thick disk let go: it bounces, rocks and settles", 350)
           if m["gif"] else '<p class="note">(The quick atlas draws no animation here.)</p>')
    e = html.escape
    t_si, z_si = m.get("t_end_si"), m.get("Z_C_si")
    return {"rest_what": "A thick disk" if what is None else what[0].upper() + what[1:],
            "rest_t_end_si": "" if t_si is None else f" = {_fmt(t_si, 3)} s",
            "rest_Z_C_si": "" if z_si is None else f" = {_fmt(z_si * 1e3, 3)} mm",
            "rest_e": _fmt(m["e"], 3), "rest_h": _fmt(m["h"], 3), "rest_mu": _fmt(m["mu"], 3),
            "rest_Z_C": _fmt(m["Z_C"], 3), "rest_theta": _deg(m["theta"], 3),
            "rest_n_rim": m["n_rim"], "rest_n_flights": m["n_flights"],
            "rest_n_rim_change": m["n_rim_change"],
            "rest_flat": " and falls flat" if m["n_face"] else "",
            "rest_status": e(m["status"]), "rest_t_end": _fmt(m["t_end"]),
            "rest_message": e(m["message"]),
            "rest_energy_initial": _fmt(m["energy_initial"]),
            "rest_energy_final": _fmt(m["energy_final"]),
            "rest_impact_loss": _fmt(m["impact_loss"]), "rest_n_impacts": m["n_impacts"],
            "rest_dissipated": _fmt(m["dissipated"]),
            "rest_energy_balance": _fmt(m["energy_balance"], 2),
            "rest_n_segments": m["n_segments"], "rest_wall_time": f"{m['wall_time']:.2g}",
            "rest_gif": gif}


def _euler_values(ed: dict, what: str | None = None) -> dict:
    """The section "Euler's disk", from the run's JSON summary, and the whirr under it: the
    frequency plot, the sound (when the run wrote one).  ``what`` names the disk run when it
    is the atlas's own (see :func:`_ran_as_euler_disk`), else it is the commercial toy."""
    p = ed["parameters"]
    rows = "\n".join(
        f"<tr><td>{name}</td><td>{_fmt(ed['exponents'][key])}</td>"
        f"<td>{_fmt(ed['predicted'][key])}</td></tr>"
        for key, name in (("alpha", "tilt &alpha;"), ("Omega", "precession rate &Omega;"),
                          ("contact_speed", "contact-point speed")))
    lo, hi = ed["fit_window_alpha"]
    alpha_end = ed.get("alpha_end")
    snd = ed.get("sound")
    audio = ""
    if snd:
        t0, t1 = snd["window_s"]
        audio = _render("euler_audio.html", seconds=f"{t1 - t0:.3g}",
                        file=html.escape(snd["file"]))
    return {"euler_what": ("The commercial toy" if what is None else
                           what[0].upper() + what[1:]),
            "euler_radius_m": f"{p['radius_m'] * 1e3:.4g}",
            "euler_thickness_m": f"{p['thickness_m'] * 1e3:.4g}", "euler_h": f"{p['h']:.4g}",
            "euler_mass_kg": f"{p['mass_kg']:.3g}", "euler_alpha0": _deg(p["alpha0"], 3),
            "euler_mu": f"{p['mu']:.3g}", "euler_creep": f"{p['creep']:.4g}",
            "euler_rolling_resistance": f"{p['rolling_resistance']:.3g}",
            "euler_end": f"{ed['end']}",
            "euler_at": f"&alpha; = {_deg(alpha_end, 3)} at " if alpha_end is not None else "",
            "euler_t_end_s": _fmt(ed["t_end_s"]), "euler_status": html.escape(ed["status"]),
            "euler_predicted_t_end_s": _fmt(ed["predicted_t_end_s"]),
            "euler_energy_balance": _fmt(ed["energy_balance"], 2),
            "euler_n_steps": f"{ed['n_steps']}", "euler_wall_time_s": f"{ed['wall_time_s']:.1f}",
            "euler_lo": f"{lo:g}", "euler_hi": f"{hi:g}", "euler_t0_s": _fmt(ed["t0_s"]),
            "euler_rows": rows,
            "euler_img": _img("euler_disk.png",
                              "Euler's disk: tilt, precession rate and contact-point speed"),
            "euler_audio": audio,
            "euler_chirp_img": _img("euler_disk_chirp.png",
                                    "the whirr's frequency against the time to the end")}


def _ran_as_euler_disk(disk, motions: dict) -> str | None:
    """The words for ``disk`` (:func:`_object`) when it is the disk the Euler's-disk run
    used (it has a radius and a mass), else ``None`` (the run is the commercial toy)."""
    if getattr(disk, "radius", None) is None or disk.mass is None:
        return None
    p = motions["euler_disk"]["parameters"]
    return _object(disk) if p["radius_m"] == disk.radius and p["mass_kg"] == disk.mass else None


#: How a disk lies at the end of the run to rest (``pose`` of the record).
_POSE = {"flat": "flat on a face", "upright": "upright on its tread",
         "rim": "on a rim edge"}
#: How Euler's disk ends (``end`` of its summary).
_END = {"fell-flat": "falls flat", "lift-off": "lifts off",
        "edge-contact": "touches with its other rim edge", "at-rest": "comes to rest"}


def _answers(disk, thr: dict, motions: dict) -> str:
    """The first screen of the atlas of a disk with a physical size: the speed above which it
    rolls straight and stable (eq. 42 converted with the disk's scale), how long it spins
    (its Euler's-disk run), how it falls (its run to rest); ``""`` without a size."""
    what = _object(disk)
    if what is None:
        return ""
    w2 = thr["rough"]["straight_line_omega20_sq"]  # omega20^2 > w2 [g/a], eq. (42)
    w = math.sqrt(w2)  # |omega20| [sqrt(g/a)]; the speed of C, v = a omega20 [sqrt(g a)]
    values = {"object": what, "Object": what[0].upper() + what[1:], "w2": _fmt(w2),
              "se_tilt": _deg(math.atan(disk.h)),
              "v": _fmt(w), "v_si": _fmt(float(disk.speed_to_si(w)), 3),
              "w_si": _fmt(float(disk.angular_speed_to_si(w)))}
    return _render("answers.html", spins=_spins(disk, motions), falls=_falls(motions),
                   **values)


def _spins(disk, motions: dict) -> str:
    """The answer "how long does it spin": its Euler's-disk run, with what it assumes."""
    ed = motions["euler_disk"]
    if _ran_as_euler_disk(disk, motions) is None:
        return ("<b>How long it spins</b> needs its mass (<code>--mass</code>): the "
                "Euler's disk section below shows the commercial toy.")
    p = ed["parameters"]
    end = _END.get(ed["end"], html.escape(str(ed["end"])))
    return (f"<b>Set spinning on its edge, it whirrs for {_fmt(ed['t_end_s'], 3)} s</b> and "
            f"{end} (t = {_fmt(ed['t_end'])} {_T}; the adiabatic decay along the steady "
            f"family predicts {_fmt(ed['predicted_t_end_s'], 3)} s): started spinning in "
            f"place at tilt &alpha;<sub>0</sub> = {_deg(p['alpha0'], 3)} from the table, "
            f"with creep friction (&mu; = {p['mu']:.3g}) and rolling resistance (length "
            f"{p['rolling_resistance']:.3g} a) as the only losses; see "
            '<a href="#euler-disk">Euler\'s disk</a>.')


def _falls(motions: dict) -> str:
    """The answer "how does it fall": the run to rest past the guards, and its outcome."""
    m = motions["to_rest"]
    pose = _POSE.get(m.get("pose"), "")
    t_si = m.get("t_end_si")
    when = (f"{_fmt(t_si, 3)} s ({_fmt(m['t_end'])} {_T})" if t_si is not None else
            f"t = {_fmt(m['t_end'])} {_T}")
    z = m.get("Z_C_si")
    height = f"{_fmt(z * 1e3, 3)} mm" if z is not None else f"{_fmt(m['Z_C'], 3)} a"
    return (f"<b>Let go tilted, it ends {pose}</b> (outcome <code>"
            f"{html.escape(m['status'])}</code>) after {when}: dropped from rest with its "
            f"centre {height} ({_fmt(m['Z_C'], 3)} a) above the table, tilted "
            f"{_deg(m['theta'], 3)} from upright, it bounces ({m['n_rim']} rim impacts in "
            f"{m['n_flights']} flights)"
            + (f", rocks over its tread ({m['n_rim_change']} rim changes)"
               if m["n_rim_change"] else "")
            + f"{' and lands on a face' if m['n_face'] else ''} (restitution e = "
            f"{_fmt(m['e'], 3)}, friction &mu; = {_fmt(m['mu'], 3)}); see "
            '<a href="#to-rest">Past the guards</a>.')
