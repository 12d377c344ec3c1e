"""The house's import rules, read from the code: no import cycle, and each subpackage keeps the layering
its ``__init__`` docstring states.

The graph has one node per module of ``seal_cli`` and an edge for every ``import`` the module can run:
at module level *and* inside functions (a lazy import still makes one module need the other). Imports
under ``if TYPE_CHECKING:`` never run and only name types, so they are not edges.
"""

from __future__ import annotations

import ast
import re
from collections.abc import Iterator
from pathlib import Path

import pytest

import seal_cli

PACKAGE = Path(seal_cli.__file__).resolve().parent
SUBPACKAGES = ("frames", "language", "planning", "maps", "sensing", "ros", "sefm", "sim", "bench", "cli")
BASE = ("errors", "fileio", "yamlnodes", "resources", "cache", "names")
"""Top-level modules every subpackage may import."""


def module_files(root: Path = PACKAGE) -> dict[str, Path]:
    """Dotted module name → file, for every module of the package under ``root``."""
    files = {}
    for path in sorted(root.rglob("*.py")):
        parts = [root.name, *path.relative_to(root).with_suffix("").parts]
        if parts[-1] == "__init__":
            parts.pop()
        files[".".join(parts)] = path
    return files


def _runtime_nodes(tree: ast.AST) -> Iterator[ast.Import | ast.ImportFrom]:
    """The import statements of a module that can run: every one but those under ``if TYPE_CHECKING:``."""
    for node in ast.iter_child_nodes(tree):
        if isinstance(node, ast.If) and "TYPE_CHECKING" in ast.unparse(node.test):
            yield from (n for branch in node.orelse for n in _runtime_nodes(ast.Module([branch], [])))
            continue
        if isinstance(node, ast.Import | ast.ImportFrom):
            yield node
        yield from _runtime_nodes(node)


def _importer_package(module: str, path: Path) -> str:
    return module if path.name == "__init__.py" else module.rpartition(".")[0]


def imported_names(module: str, path: Path) -> Iterator[str]:
    """Every dotted name a module imports (``from a import b`` gives ``a.b``), relative imports resolved."""
    for node in _runtime_nodes(ast.parse(path.read_text(encoding="utf-8"), str(path))):
        if isinstance(node, ast.Import):
            yield from (alias.name for alias in node.names)
            continue
        base = node.module or ""
        if node.level:
            anchor = _importer_package(module, path).split(".")
            anchor = anchor[: len(anchor) - node.level + 1]
            base = ".".join([*anchor, base] if base else anchor)
        yield from (f"{base}.{alias.name}" for alias in node.names)


def _owner(name: str, modules: dict[str, Path]) -> str | None:
    """The module a dotted name lives in (``seal_cli.maps.model.Map`` → ``seal_cli.maps.model``)."""
    while name and name not in modules:
        name = name.rpartition(".")[0]
    return name or None


def import_graph(modules: dict[str, Path] | None = None) -> dict[str, set[str]]:
    """Module → the package modules it imports. ``from seal_cli.maps import model`` is an edge to
    ``seal_cli.maps.model`` alone: the package's ``__init__`` runs too, but is needed only when one
    of its own names is imported."""
    modules = module_files() if modules is None else modules
    graph: dict[str, set[str]] = {}
    for module, path in modules.items():
        owners = {_owner(name, modules) for name in imported_names(module, path)}
        graph[module] = {o for o in owners if o is not None and o != module}
    return graph


def cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected components with more than one module (Tarjan), each sorted."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    found: list[list[str]] = []

    def visit(v: str) -> None:
        index[v] = low[v] = len(index)
        stack.append(v)
        on_stack.add(v)
        for w in sorted(graph.get(v, ())):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                found.append(sorted(component))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return found


def _words(clause: str) -> set[str]:
    return {w for w in re.split(r"[\s,]+|\bor\b|\band\b", clause) if w}


def layering(package: str) -> tuple[set[str] | None, set[str]]:
    """(the only subpackages and base modules it may import, or None for no such list; the ones it must
    never import), as the first paragraph after the title of the subpackage's docstring says: "Imports
    frames and language; never sefm, sim, bench or cli." """
    doc = ast.get_docstring(ast.parse((PACKAGE / package / "__init__.py").read_text(encoding="utf-8"))) or ""
    rule = " ".join(doc.split())
    never = re.search(r"\b(?:[Nn]ever|anything but) (?:imports? )?([a-z_, ]+?)(?:\.|;|$)", rule)
    only = re.search(r"\bImports ([a-z_,() ]+?) only\b", rule)
    allowed = None
    if only:
        allowed = _words(re.sub(r"\([^)]*\)", "", only.group(1)))
    return allowed, _words(never.group(1)) if never else set()


def _area(module: str) -> str:
    """The subpackage or top-level module a module belongs to (``seal_cli.maps.formats.x`` → ``maps``)."""
    parts = module.split(".")
    return parts[1] if len(parts) > 1 else ""


# -- the tests ----------------------------------------------------------------------------------------
def test_the_graph_sees_lazy_imports_and_ignores_type_only_ones(tmp_path: Path) -> None:
    root = tmp_path / "pkg"
    (root / "sub").mkdir(parents=True)
    (root / "__init__.py").write_text("")
    (root / "sub" / "__init__.py").write_text("")
    (root / "a.py").write_text("def f():\n    from pkg.b import g\n    return g\n")
    (root / "b.py").write_text("from typing import TYPE_CHECKING\nif TYPE_CHECKING:\n    from pkg.a import f\n"
                               "from . import c\n")
    (root / "c.py").write_text("from pkg.sub import d\n")
    (root / "sub" / "d.py").write_text("import pkg.a\n")
    graph = import_graph(module_files(root))
    assert graph["pkg.a"] == {"pkg.b"}
    assert graph["pkg.b"] == {"pkg.c"}          # the TYPE_CHECKING import is no edge
    assert graph["pkg.c"] == {"pkg.sub.d"}      # reaching a module through its package is no edge to the package
    assert cycles(graph) == [["pkg.a", "pkg.b", "pkg.c", "pkg.sub.d"]]


@pytest.fixture(scope="module")
def package_graph() -> dict[str, set[str]]:
    """The package's import graph, read once for the tests of this module (parsing every file takes seconds)."""
    return import_graph()


@pytest.fixture(scope="module")
def package_imports() -> dict[str, list[str]]:
    """Every dotted name each module of the package imports (:func:`imported_names`), read once."""
    return {module: list(imported_names(module, path)) for module, path in module_files().items()}


def test_no_import_cycles(package_graph: dict[str, set[str]]) -> None:
    found = cycles(package_graph)
    assert not found, "import cycles (lazy imports count): " + "; ".join(" ↔ ".join(c) for c in found)


def test_every_subpackage_states_its_layering() -> None:
    for package in SUBPACKAGES:
        allowed, never = layering(package)
        assert allowed is not None or never or "anything" in (ast.get_docstring(ast.parse(
            (PACKAGE / package / "__init__.py").read_text(encoding="utf-8"))) or ""), \
            f"seal_cli/{package}/__init__.py states no import rule"
        unknown = (allowed or set()) | never
        assert unknown <= set(SUBPACKAGES) | set(BASE), f"{package}: {unknown - set(SUBPACKAGES) - set(BASE)}"


@pytest.mark.parametrize("package", SUBPACKAGES)
def test_subpackages_keep_their_layering(package: str, package_graph: dict[str, set[str]]) -> None:
    graph = package_graph
    allowed, never = layering(package)
    broken = []
    for module, deps in sorted(graph.items()):
        if _area(module) != package:
            continue
        for dep in sorted(deps):
            area = _area(dep)
            if area in (package, ""):
                continue
            if area in never or (allowed is not None and area not in allowed):
                broken.append(f"{module} imports {dep}")
    assert not broken, f"seal_cli/{package}/__init__.py's rule is broken: " + "; ".join(broken)


def test_base_modules_import_only_base_modules(package_graph: dict[str, set[str]]) -> None:
    graph = package_graph
    bad = sorted(f"{m} imports {d}" for m, deps in graph.items() if _area(m) in BASE
                 for d in deps if _area(d) not in BASE)
    assert not bad


def test_only_the_version_is_taken_from_the_public_api_inside_the_package(
        package_imports: dict[str, list[str]]) -> None:
    """``seal_cli/__init__.py`` loads its names lazily from every subpackage (``_HOMES``): a module that
    took one of them from the facade would close a cycle the graph cannot see."""
    bad = sorted(f"{module} imports {name}" for module, names in package_imports.items() for name in names
                 if name.rpartition(".")[0] == "seal_cli" and name.rpartition(".")[2] in seal_cli._WHERE)
    assert not bad


def test_nothing_imports_cli(package_graph: dict[str, set[str]]) -> None:
    graph = package_graph
    users = sorted(f"{m} → {d}" for m, deps in graph.items() for d in deps
                   if _area(d) == "cli" and _area(m) != "cli" and m != "seal_cli.__main__")
    assert not users


def test_engine_modules_never_import_typer_or_rich(package_imports: dict[str, list[str]]) -> None:
    bad = []
    for module, names in package_imports.items():
        if _area(module) == "cli":
            continue
        for name in names:
            if name.split(".")[0] in ("typer", "rich", "click"):
                bad.append(f"{module} imports {name}")
    assert not bad
