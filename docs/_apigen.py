"""Write the API reference's index (``docs/api/index.rst``) from the public namespace.

Every name of ``rollingdisk.__all__`` is listed under its public path (``rollingdisk.Disk``),
plus the members of the public modules ``rollingdisk.theory.exact``, ``rollingdisk.sweep``,
``rollingdisk.scenarios.euler_disk``, ``rollingdisk.plotting`` and ``rollingdisk.symbolic``;
autosummary then generates
one page per name under ``docs/api/generated/``.  No private module path is written down: a name's
topic is read from the module that defines it (its ``__module__``, or for a constant the
module whose ``__all__`` holds it), so the index follows the package when modules move, and
a name no rule places still gets its page, under "Other public names".
"""

from __future__ import annotations

import importlib
import inspect
import sys
from pathlib import Path

#: Topics, in page order: (key, title, one-line description).
TOPICS = (
    ("disk", "Disk and equations of motion",
     "The disk model, its physical units, the equations of motion of section 2 and the "
     "library's input errors. Described in :doc:`../notation`."),
    ("steady", "Steady motions and stability",
     "Steady motions (section 3), their small oscillations and stability (section 4), "
     "thresholds, and the regions where they exist. Described in :doc:`../equations` and "
     ":doc:`../errata`."),
    ("simulation", "Simulation",
     "Nonlinear simulation with guard events, the trajectory it returns, and measurements "
     "compared with the theory. Described in :doc:`../simulation` and :doc:`../outcomes`."),
    ("friction", "Friction: real ground",
     "Coulomb friction with rolling and sliding, rolling resistance, pivoting friction, air "
     "drag; the hybrid simulation and its energy balance; the motion past the guards. "
     "Described in :doc:`../friction`, :doc:`../impacts` and :doc:`../motion`."),
    ("exact", "Exact motions", "The integrable disk by quadrature: ``rollingdisk.theory.exact``. "
     "Described in :doc:`../exact`."),
    ("sweep", "Sweeps", "Many runs as one dataset: ``rollingdisk.sweep``. Described in "
     ":doc:`../sweeps`."),
    ("euler_disk", "Euler's disk", "The toy run to its end: ``rollingdisk.scenarios.euler_disk``."),
    ("plotting", "Plotting", "Maps and trajectory plots (matplotlib): "
                             "``rollingdisk.plotting``. The paper's figures: :doc:`../figures`."),
    ("symbolic", "Derivations (sympy)",
     "The Newton-Euler derivation of the equations of motion and the check of every printed "
     "equation of the paper against it: ``rollingdisk.symbolic`` (what ``rollingdisk derive`` "
     "runs; the derived equations are shown on the page 'The equations of sections 3 and 4, "
     "derived')."),
    ("other", "Other public names", "Names no topic rule places (yet)."),
)

#: Module path components (any level, the innermost first) -> topic.
MODULE_TOPICS = {
    "errors": "disk", "util": "disk", "disk": "disk", "equations": "disk", "model": "disk",
    "steady": "steady", "regions": "steady",
    "theory": "steady", "oscillations": "steady", "exact": "exact",
    "trajectory": "simulation", "events": "simulation", "simulation": "simulation",
    "jit": "simulation", "measure": "simulation", "engine": "simulation",
    "results": "simulation", "ivp": "simulation",
    "ground": "friction", "coulomb": "friction", "hybrid": "friction", "motion": "friction",
    "toss": "friction", "scenarios": "friction", "phases": "friction",
}

#: Names placed by their meaning rather than by the module that holds them.
NAME_TOPICS = {
    "COULOMB_STATE": "friction", "MODE_NAMES": "friction", "coulomb_rhs": "friction",
    "coulomb_contact": "friction", "coulomb_energy": "friction", "rolling_state": "friction",
    "mu_required_map": "friction",
}

#: Public modules documented member by member, under their own topic (topic -> module).
MODULES = {"exact": "theory.exact", "sweep": "sweep", "euler_disk": "scenarios.euler_disk",
           "plotting": "plotting", "symbolic": "symbolic"}


def _defining_module(package, name: str, obj) -> str:
    """Dotted path of the module that defines ``name`` (``""`` if none is found)."""
    mod = getattr(obj, "__module__", None) if (inspect.isclass(obj) or callable(obj)) else None
    if mod and mod.startswith(package.__name__ + "."):
        return mod
    for modname, module in sorted(sys.modules.items()):
        if (modname.startswith(package.__name__ + ".") and module is not None
                and name in getattr(module, "__all__", ())
                and getattr(module, name, None) is obj):
            return modname
    return ""


def topic_of(package, name: str) -> str:
    """The topic key of the top-level name ``name``."""
    if name in NAME_TOPICS:
        return NAME_TOPICS[name]
    modname = _defining_module(package, name, getattr(package, name))
    for part in reversed(modname.split(".")[1:]):
        if part in MODULE_TOPICS:
            return MODULE_TOPICS[part]
    return "other"


def module_members(module) -> list[str]:
    """Public names of ``module``: its ``__all__`` plus public functions and classes it
    defines but has not listed (``plotting.plot_exact``, ...)."""
    names = list(getattr(module, "__all__", ()))
    for n, obj in vars(module).items():
        if (not n.startswith("_") and n not in names
                and (inspect.isfunction(obj) or inspect.isclass(obj))
                and getattr(obj, "__module__", None) == module.__name__):
            names.append(n)
    return names


def api_entries() -> dict[str, list[str]]:
    """``{topic: [public dotted names]}`` of everything the reference documents."""
    import rollingdisk

    groups: dict[str, list[str]] = {key: [] for key, _, _ in TOPICS}
    for name in rollingdisk.__all__:
        groups[topic_of(rollingdisk, name)].append(f"rollingdisk.{name}")
    for topic, modname in MODULES.items():
        module = importlib.import_module(f"rollingdisk.{modname}")
        groups[topic].extend(f"rollingdisk.{modname}.{n}" for n in module_members(module)
                             if getattr(rollingdisk, n, None) is not getattr(module, n))
    return groups


def filename_map(groups: dict[str, list[str]] | None = None) -> dict[str, str]:
    """``autosummary_filename_map``: page names that differ from a name only in case.

    ``rollingdisk.Thresholds`` and ``rollingdisk.thresholds`` would be ``Thresholds.html``
    and ``thresholds.html``, one file on a case-insensitive file system (macOS, Windows).
    The class keeps its name; the function's page gets ``-function`` appended.
    """
    if groups is None:
        groups = api_entries()
    names = [n for group in groups.values() for n in group]
    by_lower: dict[str, list[str]] = {}
    for n in names:
        by_lower.setdefault(n.lower(), []).append(n)
    out = {}
    for same in by_lower.values():
        if len(same) < 2:
            continue
        keep = next((n for n in same if n.rpartition(".")[2][:1].isupper()), same[0])
        for n in same:
            if n != keep:
                out[n] = f"{n}-function"
    return out


def page_name(name: str, fmap: dict[str, str] | None = None) -> str:
    """The generated page of a public dotted name, without ``.html``."""
    fmap = filename_map() if fmap is None else fmap
    return fmap.get(name, name)


def render() -> str:
    groups = api_entries()
    lines = [
        ".. This file is generated by docs/_apigen.py at every build; do not edit.",
        "",
        "API reference",
        "=============",
        "",
        "Every public name, one page each, grouped by topic and listed under its public",
        "import path (``import rollingdisk as rd``; ``rd.Disk`` is ``rollingdisk.Disk``).",
        "Units are the paper's (``m = a = g = 1``) unless a name says otherwise.",
        "",
    ]
    for key, title, blurb in TOPICS:
        names = groups[key]
        if not names:
            continue
        lines += [title, "-" * len(title), "", blurb, "",
                  ".. autosummary::", "   :toctree: generated", ""]
        lines += [f"   {n}" for n in names]
        lines.append("")
    return "\n".join(lines)


def write_api_index(path: Path) -> bool:
    """Write the index at ``path`` if its content changed; return whether it did."""
    text = render()
    path = Path(path)
    if path.exists() and path.read_text(encoding="utf-8") == text:
        return False
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text, encoding="utf-8")
    return True
