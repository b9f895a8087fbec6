"""The import graph goes one way (ARCHITECTURE.md).

The imports are read from the source (``ast``), so the test sees lazy imports inside functions too:
an upward import is a mistake wherever it is written. The few lazy imports across siblings that the
architecture allows (the numeric conversions build exact objects on request; ``classify`` hands float
matrices to the numeric classifier) are listed in ``LAZY_ALLOWED``.
"""

from __future__ import annotations

import ast
import subprocess
import sys
from pathlib import Path

import pytest

import pgsym

ROOT = Path(pgsym.__file__).parent

# layer of a module, by its dotted name below pgsym ("" = the package itself)
BASE = {"errors", "limits", "kinds", "atomic", "csv_cells", "ring", "escaping", "_lazy"}
LAYERS = ["base", "core", "numeric", "vision", "proofs", "exercises", "cli"]
# which layers each layer may import (at load or lazily)
ALLOWED = {
    "base": {"base"},
    "core": {"base", "core"},
    "numeric": {"base", "numeric"},
    "vision": {"base", "numeric", "vision"},
    "proofs": {"base", "core", "proofs"},
    "exercises": {"base", "core", "proofs", "exercises"},
    "cli": set(LAYERS),
    "package": set(LAYERS),  # pgsym/__init__.py resolves public names lazily from every layer
}
# lazy (function-level) imports allowed across siblings: (importing layer, imported layer)
LAZY_ALLOWED = {("numeric", "core"), ("vision", "core"), ("core", "numeric")}


def layer(module: str) -> str:
    """'pgsym.numeric.plane' → 'numeric'; 'pgsym.conics' → 'core'."""
    parts = module.split(".")[1:]
    if not parts or parts == ["__init__"]:
        return "package"
    head = parts[0]
    if head in ("numeric", "vision", "proofs", "exercises", "cli"):
        if head == "vision" and parts[1:] == ["errors"]:
            return "vision"
        return head
    return "base" if head in BASE else "core"


def _module_name(path: Path) -> str:
    rel = path.relative_to(ROOT.parent).with_suffix("")
    parts = list(rel.parts)
    if parts[-1] == "__init__":
        parts.pop()
    return ".".join(parts)


def _imports(path: Path, name: str | None = None) -> list[tuple[str, bool]]:
    """(imported pgsym module, at load?) for every import statement of the file."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    name = name or _module_name(path)
    package = name if path.name == "__init__.py" else name.rsplit(".", 1)[0]
    found: list[tuple[str, bool]] = []

    def visit(node: ast.AST, top: bool) -> None:
        for child in ast.iter_child_nodes(node):
            inner = top and not isinstance(child, (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda))
            if isinstance(child, ast.If) and "TYPE_CHECKING" in ast.unparse(child.test):
                continue  # annotations only
            if isinstance(child, ast.ImportFrom):
                if child.level:
                    base = package.split(".")
                    base = base[: len(base) - (child.level - 1)]
                    target = ".".join(base + ([child.module] if child.module else []))
                else:
                    target = child.module or ""
                if target.startswith("pgsym"):
                    if child.module is None or target in ("pgsym", package):
                        found.extend((f"{target}.{a.name}", inner) for a in child.names)
                    else:
                        found.append((target, inner))
            elif isinstance(child, ast.Import):
                found.extend((a.name, inner) for a in child.names if a.name.startswith("pgsym"))
            visit(child, inner)

    visit(tree, True)
    return found


SOURCES = sorted(ROOT.rglob("*.py"))


@pytest.mark.parametrize("path", SOURCES, ids=lambda p: str(p.relative_to(ROOT.parent)))
def test_imports_go_one_way(path: Path) -> None:
    me = layer(_module_name(path))
    wrong = []
    for target, at_load in _imports(path):
        theirs = layer(target)
        if theirs in ALLOWED[me] or (not at_load and (me, theirs) in LAZY_ALLOWED):
            continue
        wrong.append(f"{target} ({theirs}, {'at load' if at_load else 'lazily'})")
    assert not wrong, f"{_module_name(path)} ({me}) imports a layer it must not: {wrong}"


def test_layer_rules_catch_an_upward_import(tmp_path: Path) -> None:
    # the checker itself: a lazy import of the exercises inside a core module is found and is not allowed
    fake = tmp_path / "fake.py"
    fake.write_text("import sympy\n\ndef f():\n    from .exercises import sheets\n    return sheets\n")
    found = _imports(fake, "pgsym.fake")
    assert found == [("pgsym.exercises", False)]
    assert layer("pgsym.fake") == "core" and layer("pgsym.exercises") not in ALLOWED["core"]
    assert ("core", "exercises") not in LAZY_ALLOWED


# -- names that moved up a layer ---------------------------------------------------------------------------

# A module that lost names to a higher layer keeps the old spellings with ``pgsym._lazy.moved_names``: each use
# warns (DeprecationWarning, naming the new home), and the new home is imported only then, after the old module
# has loaded. Every such forward is listed here (old module → new home) and nothing inside the package may use
# an old spelling, so no import of the package goes through one.
MOVED = {"pgsym.invariants": "pgsym.proofs.invariance"}


def _moved_forwards() -> dict[str, tuple[str, set[str]]]:
    """Old module → (new home, the old names) for every ``moved_names(...)`` call of the package."""
    found = {}
    for path in SOURCES:
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Call) and getattr(node.func, "id", None) == "moved_names":
                names = set(ast.literal_eval(node.args[2]))
                for kw in node.keywords:
                    if kw.arg == "renamed":
                        names |= set(ast.literal_eval(kw.value))
                found[_module_name(path)] = (ast.literal_eval(node.args[1]), names)
    return found


def test_names_moved_up_a_layer_are_listed_and_unused_inside_the_package() -> None:
    forwards = _moved_forwards()
    assert {old: new for old, (new, _) in forwards.items()} == MOVED
    used = []
    for path in SOURCES:
        tree = ast.parse(path.read_text(encoding="utf-8"))
        name = _module_name(path)
        package = name if path.name == "__init__.py" else name.rsplit(".", 1)[0]
        for node in ast.walk(tree):
            if isinstance(node, ast.ImportFrom):
                base = package.split(".")[: len(package.split(".")) - (node.level - 1)] if node.level else []
                target = ".".join(base + ([node.module] if node.module else []))
                old = forwards.get(target)
                if old is not None:
                    used += [f"{name}: {target}.{a.name}" for a in node.names if a.name in old[1]]
            elif isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name):
                old = next((v for k, v in forwards.items() if k.rsplit(".", 1)[1] == node.value.id), None)
                if old is not None and node.attr in old[1]:
                    used.append(f"{name}: {node.value.id}.{node.attr}")
    assert not used, f"old spellings of moved names used inside the package: {used}"


# -- facts about an operation live in its entry of the table ---------------------------------------------

# Modules that still test an operation's name instead of reading its entry, and why (empty it, never add to it).
OPERATION_NAME_TESTS: dict[str, str] = {}


def _operation_name_tests(tree: ast.AST) -> list[int]:
    """Lines comparing ``x.op`` (or ``op``) with a string or a tuple of strings."""
    found = []
    for node in ast.walk(tree):
        if not isinstance(node, ast.Compare):
            continue
        left = node.left
        named_op = getattr(left, "attr", None) == "op" or getattr(left, "id", None) == "op"
        if not named_op:
            continue
        for c in node.comparators:
            items = c.elts if isinstance(c, (ast.Tuple, ast.List, ast.Set)) else [c]
            if items and all(isinstance(e, ast.Constant) and isinstance(e.value, str) for e in items):
                found.append(node.lineno)
    return found


def test_facts_about_an_operation_are_read_from_the_table() -> None:
    # ``node.op == "join"`` outside the table is a fact about the operation written elsewhere; give its entry a field
    wrong = []
    for path in SOURCES:
        rel = str(path.relative_to(ROOT.parent))
        if rel == "pgsym/proofs/operations.py" or rel in OPERATION_NAME_TESTS:
            continue
        wrong += [f"{rel}:{n}" for n in _operation_name_tests(ast.parse(path.read_text(encoding="utf-8")))]
    assert not wrong, f"operation names tested outside pgsym/proofs/operations.py: {wrong}"
    # the check itself finds both spellings, and the modules listed above still need their entry
    sample = ast.parse('if node.op == "join" or p.op in ("meet", "polar") or node.kind == "point": pass')
    assert _operation_name_tests(sample) == [1, 1]
    for rel in OPERATION_NAME_TESTS:
        assert _operation_name_tests(ast.parse((ROOT.parent / rel).read_text(encoding="utf-8"))), f"{rel} is done"


# -- no cycles ------------------------------------------------------------------------------------------------

# Cycles known and being removed elsewhere, each with its reason; every other cycle fails the test.
KNOWN_CYCLES: dict[frozenset[str], str] = {}


def import_graph() -> dict[str, set[str]]:
    """Module → the package's modules it imports (at load or inside a function), from the source."""
    names = {_module_name(p): p for p in SOURCES}

    def owner(target: str) -> str:
        # ``from pgsym.conics import Conic`` names a module attribute: walk up to the module
        while target and target not in names:
            target = target.rpartition(".")[0]
        return target

    return {name: {owner(t) for t, _ in _imports(path)} - {name, ""} for name, path in names.items()}


def cycles(graph: dict[str, set[str]]) -> list[set[str]]:
    """The strongly connected components of more than one module (Tarjan's algorithm, iterative)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    found: list[set[str]] = []
    for root in sorted(graph):
        if root in index:
            continue
        work = [(root, iter(sorted(graph[root])))]
        index[root] = low[root] = len(index)
        stack.append(root)
        on_stack.add(root)
        while work:
            v, edges = work[-1]
            w = next(edges, None)
            if w is not None:
                if w not in index:
                    index[w] = low[w] = len(index)
                    stack.append(w)
                    on_stack.add(w)
                    work.append((w, iter(sorted(graph.get(w, ())))))
                elif w in on_stack:
                    low[v] = min(low[v], index[w])
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[v])
            if low[v] == index[v]:
                component = set()
                while True:
                    w = stack.pop()
                    on_stack.discard(w)
                    component.add(w)
                    if w == v:
                        break
                if len(component) > 1:
                    found.append(component)
    return found


def levels(graph: dict[str, set[str]]) -> dict[str, int]:
    """The level of each module of an acyclic graph: 0 imports nothing of the package, else 1 + the highest below."""
    level: dict[str, int] = {}

    def of(name: str) -> int:
        if name not in level:
            level[name] = 1 + max((of(t) for t in graph.get(name, ())), default=-1)
        return level[name]

    for name in graph:
        of(name)
    return level


def test_the_cycle_check_finds_a_cycle_and_only_cycles() -> None:
    # a → b → c → a is one component of three; d → a hangs below it; e ↔ f is a second one; g alone is none
    graph = {"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}, "e": {"f"}, "f": {"e", "g"}, "g": set()}
    assert sorted(map(sorted, cycles(graph))) == [["a", "b", "c"], ["e", "f"]]
    assert cycles({"a": {"b"}, "b": {"c"}, "c": set(), "d": {"a", "c"}}) == []
    # levels of an acyclic graph: c imports nothing (0), b imports c (1), a imports b (2), d imports a and c (3)
    assert levels({"a": {"b"}, "b": {"c"}, "c": set(), "d": {"a", "c"}}) == {"a": 2, "b": 1, "c": 0, "d": 3}


def test_the_cycle_check_reads_lazy_imports(tmp_path: Path) -> None:
    # a lazy import inside a function closes a cycle as much as one at the top of the file
    (tmp_path / "low.py").write_text("def f():\n    from .high import g\n    return g\n")
    graph = {"pgsym.low": {t for t, _ in _imports(tmp_path / "low.py", "pgsym.low")}, "pgsym.high": {"pgsym.low"}}
    assert graph["pgsym.low"] == {"pgsym.high"}
    assert cycles(graph) == [{"pgsym.high", "pgsym.low"}]


def test_the_package_has_no_import_cycle() -> None:
    found = [c for c in cycles(import_graph()) if frozenset(c) not in KNOWN_CYCLES]
    assert not found, f"modules that import each other (imports inside functions included): {found}"


# the layers whose levels ARCHITECTURE.md lists (the exercises follow once their template registry is split)
LEVEL_LAYERS = ("base", "core", "numeric", "vision", "proofs", "exercises", "cli")


def level_section() -> str:
    """The "Module levels" section of ARCHITECTURE.md as the import graph gives it (``python
    tests/test_architecture.py`` prints it): per layer, the modules of each level."""
    graph = import_graph()
    shown = {m: {t for t in ts if layer(t) in LEVEL_LAYERS} for m, ts in graph.items() if layer(m) in LEVEL_LAYERS}
    level = levels(shown)
    lines = ["| layer | level | modules |", "|---|---|---|"]
    for lay in LEVEL_LAYERS:
        by_level: dict[int, list[str]] = {}
        for m, n in level.items():
            if layer(m) == lay:
                by_level.setdefault(n, []).append(m.removeprefix("pgsym."))
        for n in sorted(by_level):
            lines.append(f"| {lay} | {n} | {', '.join(f'`{m}`' for m in sorted(by_level[n]))} |")
    return "\n".join(lines)


def test_architecture_md_shows_the_levels_the_graph_gives() -> None:
    text = (ROOT.parent / "ARCHITECTURE.md").read_text(encoding="utf-8")
    start = text.index("<!-- levels: generated by tests/test_architecture.py -->")
    end = text.index("<!-- end of levels -->")
    shown = text[start:end].split("\n", 1)[1].strip()
    assert shown == level_section(), "ARCHITECTURE.md's module levels are stale: python tests/test_architecture.py"


@pytest.mark.parametrize("package", ["numeric", "vision"])
def test_numeric_and_vision_modules_load_without_sympy(package: str) -> None:
    modules = sorted(_module_name(p) for p in (ROOT / package).rglob("*.py"))
    code = ("import importlib, sys\n"
            f"for m in {modules!r}:\n"
            "    importlib.import_module(m)\n"
            "print(sorted(m for m in ('sympy', 'cv2', 'matplotlib') if m in sys.modules))\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "[]"


# -- one exact kit ----------------------------------------------------------------------------------------

# Functions of the core with the name of a helper of pgsym.ring that are not thin wrappers over it, and why.
NOT_A_COPY = {
    ("pgsym/matrices.py", "adjugate"): "the adjugate of a SymPy matrix of any size, by SymPy's Bareiss method",
    ("pgsym/space.py", "plane_through"): "the plane through three Point3 objects, by space.triple_cross (ring.det)",
}


def _kit_names() -> set[str]:
    from pgsym import ring

    return set(ring.__all__)


def test_no_helper_of_the_exact_kit_is_written_twice() -> None:
    # a module-level function named like a helper of pgsym.ring (``det``, ``_det3``, ``_cross``…) outside it
    # must delegate to it; float kernels on arrays (numeric, vision) are a different thing
    kit = _kit_names()
    copies = []
    for path in SOURCES:
        rel = str(path.relative_to(ROOT.parent))
        if path == ROOT / "ring.py" or {"numeric", "vision"} & set(path.parts):
            continue
        tree = ast.parse(path.read_text(encoding="utf-8"))
        for node in tree.body:
            if not isinstance(node, ast.FunctionDef):
                continue
            base = node.name.lstrip("_").rstrip("0123456789")
            if base not in kit or (rel, node.name) in NOT_A_COPY:
                continue
            if "ring." not in ast.unparse(node):
                copies.append(f"{rel}:{node.lineno} {node.name}")
    assert not copies, f"helpers of pgsym.ring written again instead of used: {copies}"


# Classes with ring arithmetic (``+`` and ``*``) outside pgsym.ring, and why each is not a second copy of
# its number types (a fraction of polynomials is ``ring.Quotient``, written once).
RING_LIKE = {
    ("pgsym/hierarchy.py", "_Dual"): "dual numbers a + bε: a Jacobian column by forward differentiation",
    ("pgsym/proofs/budget.py", "Cost"): "an estimate of the work of an expansion, not a number",
    ("pgsym/proofs/budget.py", "Metered"): "a polynomial that counts the term products formed with it, not a number",
    ("pgsym/proofs/by_evaluation.py", "_Degree"): "a bound on the degree in each parameter, not a number",
}


def test_ring_arithmetic_classes_are_written_once() -> None:
    found = set()
    for path in SOURCES:
        rel = str(path.relative_to(ROOT.parent))
        if path == ROOT / "ring.py" or {"numeric", "vision"} & set(path.parts):
            continue
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.ClassDef):
                methods = {f.name for f in node.body if isinstance(f, ast.FunctionDef)}
                if {"__add__", "__mul__"} <= methods:
                    found.add((rel, node.name))
    assert found == set(RING_LIKE), f"ring arithmetic outside pgsym.ring: {sorted(found - set(RING_LIKE))}"


if __name__ == "__main__":
    print(level_section())
