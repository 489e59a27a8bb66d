"""The layered house: the package's import graph against its contract (docs/architecture.md).

Source of truth: the layers the architecture states, read off every ``import`` in ``src/``
(module level and inside functions alike) with :mod:`ast`:

    util < model < theory < integrate < friction < {sweep, plotting, symbolic}
         < {atlas, explore} < cli

A module imports only from its own subpackage or from a lower layer; the root package
``rollingdisk`` (its public API) counts as the layer of the highest subpackage it
re-exports.  There is no import cycle; only ``integrate`` imports numba; the numeric core
imports neither sympy nor matplotlib, and ``import rollingdisk`` loads none of them.
"""

import ast
import os
import subprocess
import sys
from pathlib import Path

SRC = Path(__file__).resolve().parents[1] / "src"
PKG = SRC / "rollingdisk"

LAYERS = {"util": 0, "model": 1, "theory": 2, "integrate": 3, "friction": 4, "sweep": 5,
          "plotting": 5, "symbolic": 5, "atlas": 6, "explore": 6, "cli": 7}
ROOT_LAYER = LAYERS["friction"]  # rollingdisk/__init__ re-exports model .. friction
CORE = ("util", "model", "theory", "integrate", "friction")


def _modules():
    mods = {}
    for path in PKG.rglob("*.py"):
        rel = path.relative_to(SRC).with_suffix("")
        parts = list(rel.parts)
        if parts[-1] == "__init__":
            parts = parts[:-1]
        mods[".".join(parts)] = path
    return mods


def _imports(name, path):
    """Every (imported module, line) of ``path``, relative imports resolved."""
    is_pkg = path.name == "__init__.py"
    package = name if is_pkg else name.rpartition(".")[0]
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.Import):
            for a in node.names:
                yield a.name, node.lineno
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = package.split(".")
                base = base[:len(base) - node.level + 1]
                target = ".".join(base + ([node.module] if node.module else []))
            else:
                target = node.module or ""
            yield target, node.lineno
            for a in node.names:  # `from pkg import module`
                yield f"{target}.{a.name}", node.lineno


def _resolve(target, mods):
    while target and target not in mods:
        if "." not in target:
            return None
        target = target.rpartition(".")[0]
    return target


def _layer(mod):
    parts = mod.split(".")
    if len(parts) == 1:
        return ROOT_LAYER, "rollingdisk"
    sub = parts[1]
    return LAYERS.get(sub, -1), sub


def _graph():
    mods = _modules()
    graph = {m: set() for m in mods}
    lines = {}
    for m, p in mods.items():
        for target, line in _imports(m, p):
            t = _resolve(target, mods)
            if t is not None and t != m:
                graph[m].add(t)
                lines[(m, t)] = line
    return mods, graph, lines


def test_every_module_is_in_a_layer():
    mods = _modules()
    loose = [m for m in mods if m.count(".") == 1 and m.split(".")[1] not in LAYERS
             and m.split(".")[1] not in ("__main__",)]
    assert not loose, f"modules outside every layer: {loose}"


def test_imports_never_run_up_a_layer():
    mods, graph, lines = _graph()
    bad = []
    for m, targets in graph.items():
        if m in ("rollingdisk", "rollingdisk.__main__"):
            continue
        lm, sm = _layer(m)
        for t in targets:
            lt, st = _layer(t)
            if st == sm:
                continue
            if t == "rollingdisk" and lm > ROOT_LAYER:
                continue
            if lt >= lm:
                bad.append(f"{m}:{lines[(m, t)]} imports {t} ({st}, layer {lt} >= {sm}, {lm})")
    assert not bad, "imports that run up or across a layer:\n" + "\n".join(sorted(bad))


def test_no_import_cycles():
    mods, graph, _ = _graph()
    # packages import their own modules (re-exports): an edge from a module up to the
    # package that contains it is the package's own business, not a cycle of the design
    g = {m: {t for t in ts if not m.startswith(t + ".")} for m, ts in graph.items()}
    index, low, stack, on, comps, count = {}, {}, [], set(), [], [0]

    def visit(v):
        index[v] = low[v] = count[0]
        count[0] += 1
        stack.append(v)
        on.add(v)
        for w in g[v]:
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                comps.append(sorted(comp))

    for v in g:
        if v not in index:
            visit(v)
    assert not comps, f"import cycles: {comps}"


def _importers_of(package):
    mods = _modules()
    out = set()
    for m, p in mods.items():
        for target, _ in _imports(m, p):
            if target == package or target.startswith(package + "."):
                out.add(m)
    return out


def test_only_integrate_imports_numba():
    outside = {m for m in _importers_of("numba")
               if not m.startswith("rollingdisk.integrate.")}
    assert not outside, f"numba imported outside rollingdisk.integrate: {sorted(outside)}"


def test_the_core_never_imports_sympy_or_matplotlib():
    core = {m for pkg in ("sympy", "matplotlib", "mpl_toolkits")
            for m in _importers_of(pkg) if _layer(m)[1] in CORE}
    assert not core, f"the numeric core imports sympy/matplotlib: {sorted(core)}"


def test_import_rollingdisk_loads_no_numba_sympy_or_matplotlib():
    code = ("import sys\n"
            "sys.modules['sympy'] = None\nsys.modules['matplotlib'] = None\n"
            "import rollingdisk, rollingdisk.theory.exact, rollingdisk.friction.euler_disk\n"
            "import rollingdisk.sweep\n"
            "assert 'numba' not in sys.modules, 'import rollingdisk must not load numba'\n")
    env = dict(os.environ, PYTHONPATH=str(SRC))  # this checkout, whatever is installed
    res = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env)
    assert res.returncode == 0, res.stderr


def test_every_package_init_only_re_exports():
    """A subpackage's ``__init__`` holds its docstring, imports and ``__all__``, no code (the
    root adds ``__version__`` from the package metadata)."""
    allowed = (ast.Import, ast.ImportFrom, ast.Expr, ast.Assign, ast.AnnAssign, ast.Try)
    for path in PKG.rglob("__init__.py"):
        for node in ast.parse(path.read_text()).body:
            assert isinstance(node, allowed), f"{path}:{node.lineno} {type(node).__name__}"
            if isinstance(node, ast.Assign):
                names = [t.id for t in node.targets if isinstance(t, ast.Name)]
                assert names in (["__all__"], ["__version__"]), f"{path}:{node.lineno} {names}"
