"""The layered house: the package's import graph against its contract (docs/architecture.md).

Source of truth: the layers the architecture states, read off every ``import`` in ``src/``
(module level and inside functions alike) with :mod:`ast`:

    util < model < theory < engine < results < ivp < phases < scenarios
         < {sweep, plotting, symbolic} < {atlas, explore} < cli

A module imports only from its own subpackage or from a lower layer; the root package
``rollingdisk`` (its public API) counts as the layer of the highest subpackage it
re-exports.  There is no import cycle; only ``engine`` (and the sweeps' compiled kernels,
``sweep.batch*``) imports numba; the numeric core imports neither sympy nor matplotlib, and
``import rollingdisk`` loads none of them.  The rooms stay small: limits on the lines of a
subpackage, a module, a package ``__init__`` and a command, and no private name imported
across subpackages.
"""

import ast
import os
import subprocess
import sys
from pathlib import Path

SRC = Path(__file__).resolve().parents[1] / "src"
PKG = SRC / "rollingdisk"

LAYERS = {"util": 0, "model": 1, "theory": 2, "engine": 3, "results": 4, "ivp": 5,
          "phases": 6, "scenarios": 7, "sweep": 8, "plotting": 8, "symbolic": 8, "atlas": 9,
          "explore": 9, "cli": 10}
ROOT_LAYER = LAYERS["scenarios"]  # rollingdisk/__init__ names model .. scenarios
CORE = ("util", "model", "theory", "engine", "results", "ivp", "phases", "scenarios")
#: Modules of the root package besides its ``__init__``: the table of moved paths.
ROOT_MODULES = ("__main__", "_moved")


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
             and m.split(".")[1] not in ROOT_MODULES]
    assert not loose, f"modules outside every layer: {loose}"


def test_imports_never_run_up_a_layer():
    mods, graph, lines = _graph()
    bad = []
    for m, targets in graph.items():
        if m in ("rollingdisk", "rollingdisk._moved", "rollingdisk.__main__"):
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


def test_only_the_engine_imports_numba():
    outside = {m for m in _importers_of("numba")
               if not m.startswith(("rollingdisk.engine.", "rollingdisk.sweep.batch"))}
    assert not outside, f"numba imported outside rollingdisk.engine: {sorted(outside)}"


def test_the_core_never_imports_sympy_or_matplotlib():
    core = {m for pkg in ("sympy", "matplotlib", "mpl_toolkits")
            for m in _importers_of(pkg) if _layer(m)[1] in CORE}
    assert not core, f"the numeric core imports sympy/matplotlib: {sorted(core)}"


def test_import_rollingdisk_loads_no_numba_sympy_or_matplotlib():
    code = ("import sys\n"
            "sys.modules['sympy'] = None\nsys.modules['matplotlib'] = None\n"
            "import rollingdisk, rollingdisk.theory.exact, rollingdisk.scenarios.euler_disk\n"
            "import rollingdisk.sweep\n"
            "assert 'numba' not in sys.modules, 'import rollingdisk must not load numba'\n")
    env = dict(os.environ, PYTHONPATH=str(SRC))  # this checkout, whatever is installed
    res = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env)
    assert res.returncode == 0, res.stderr


def _lazy_table(path):
    """The ``{name: module}`` table a package ``__init__`` hands to ``util.lazy.attach``."""
    for node in ast.parse(path.read_text()).body:
        if (isinstance(node, ast.Assign) and isinstance(node.value, ast.Call)
                and getattr(node.value.func, "id", "") == "_attach"):
            table = node.value.args[1]
            if isinstance(table, ast.Name):  # the root names its table _EXPORTS
                return _lazy_table_named(path, table.id)
            return ast.literal_eval(table)
    return None


def _lazy_table_named(path, name):
    for node in ast.parse(path.read_text()).body:
        if isinstance(node, ast.Assign) and getattr(node.targets[0], "id", "") == name:
            return ast.literal_eval(node.value)
    raise AssertionError(f"{path}: no {name}")


def test_every_package_init_only_names_its_exports():
    """A subpackage's ``__init__`` is its docstring and one lazy table (PEP 562): no code, no
    import of its own modules, so importing a package costs nothing until a name is used;
    each name in the table is defined by the module it names."""
    import importlib

    for path in PKG.rglob("__init__.py"):
        if path.parent == PKG:
            continue  # the root: its table, __version__ and the finder of moved paths
        body = ast.parse(path.read_text()).body
        kinds = [type(n).__name__ for n in body]
        assert kinds in (["Expr", "ImportFrom", "Assign"], ["Expr"]), f"{path}: {kinds}"
    for path in PKG.rglob("__init__.py"):
        table = _lazy_table(path)
        if table is None:
            continue
        for name, module in table.items():
            assert hasattr(importlib.import_module(module), name), f"{path}: {name} @ {module}"


#: The limits of docs/architecture.md: no module over MODULE_LINES lines, coefficient tables
#: (data, not code) aside.
MODULE_LINES = 700
TABLES = ("rollingdisk.engine.dop853_coefficients",)


def _lines(path):
    return len(path.read_text().splitlines())


def test_no_module_over_its_limit():
    over = {m: _lines(p) for m, p in _modules().items()
            if m not in TABLES and _lines(p) > MODULE_LINES}
    assert not over, f"modules over {MODULE_LINES} lines: {over}"


def test_no_subpackage_holds_more_than_15_percent_of_the_lines():
    per = {}
    for m, p in _modules().items():
        per[_layer(m)[1]] = per.get(_layer(m)[1], 0) + _lines(p)
    total = sum(per.values())
    big = {k: round(v / total, 3) for k, v in per.items() if v > 0.15 * total}
    assert not big, f"subpackages over 15 % of {total} lines: {big}"


def test_package_init_and_command_modules_are_small():
    root = _lines(PKG / "__init__.py")
    assert root <= 200, f"rollingdisk/__init__.py has {root} lines"
    big = {p.name: _lines(p) for p in (PKG / "cli").glob("*.py") if _lines(p) > 300}
    assert set(big) <= {"_args.py"}, f"command modules over 300 lines: {big}"


def test_no_private_name_imported_across_subpackages():
    """``from rollingdisk.a.m import _name`` from outside ``a`` reaches past a's contract, and
    so does ``from rollingdisk.a import m as alias`` followed by ``alias._name``."""
    crossing = []
    for m, p in _modules().items():
        sub = _layer(m)[1]
        tree = ast.parse(p.read_text())
        aliases = {}  # local name -> module of another subpackage
        for node in ast.walk(tree):
            if isinstance(node, ast.ImportFrom) and node.module and not node.level:
                target = node.module.split(".")
                if len(target) > 1 and target[0] == "rollingdisk" and target[1] != sub:
                    crossing += [f"{m} <- {node.module}.{a.name}" for a in node.names
                                 if a.name.startswith("_") and not a.name.startswith("__")]
                if target[0] == "rollingdisk" and (len(target) > 1 and target[1] != sub
                                                   or len(target) == 1):
                    for a in node.names:
                        aliases[a.asname or a.name] = f"{node.module}.{a.name}"
            elif isinstance(node, ast.Import):
                for a in node.names:
                    target = a.name.split(".")
                    if target[0] == "rollingdisk" and len(target) > 1 and target[1] != sub:
                        aliases[a.asname or a.name] = a.name
        for node in ast.walk(tree):
            if (isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name)
                    and node.value.id in aliases and node.attr.startswith("_")
                    and not node.attr.startswith("__")):
                crossing.append(f"{m} <- {aliases[node.value.id]}.{node.attr}")
    assert not crossing, "\n".join(sorted(set(crossing)))


def test_no_package_name_is_also_one_of_its_submodules():
    """Importing ``pkg.x`` binds the module to ``pkg.x``: a lazy name ``x`` of the package
    (a function ``pkg.x``) would then be the module or the function by import order."""
    clash = []
    for path in PKG.rglob("__init__.py"):
        table = _lazy_table(path) or {}
        subs = {p.stem for p in path.parent.glob("*.py")} | {
            p.name for p in path.parent.iterdir() if (p / "__init__.py").exists()}
        clash += [f"{path.parent.name}.{n}" for n in table if n in subs]
    assert not clash, f"package names that are also submodules: {clash}"
