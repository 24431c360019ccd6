"""The layout shows the architecture: imports point one way, from the CLI down to the notation;
no module uses another's private names; no module of the package names a shipped text."""

from __future__ import annotations

import ast
import re
from pathlib import Path

import pytest

PACKAGE = Path(__file__).parent.parent / "quasicentral"

#: rank of each layer: a module may import its own layer's modules and lower ranks only.
LAYERS = {
    "quasicentral.files": 0, "quasicentral.progress": 0,
    "quasicentral.notation": 1,
    "quasicentral.engine": 2, "quasicentral.models": 2,
    "quasicentral.studies": 3,
    "quasicentral.documents": 4,
    "quasicentral.api": 5, "quasicentral.cli": 5, "quasicentral.pytest_plugin": 6,
}


def _layer(module: str) -> str | None:
    for prefix in sorted(LAYERS, key=len, reverse=True):
        if module == prefix or module.startswith(prefix + "."):
            return prefix
    return None


def _modules():
    for path in sorted(PACKAGE.rglob("*.py")):
        if "__pycache__" in path.parts or (PACKAGE / "texts") in path.parents:  # the shipped texts are data
            continue
        rel = path.relative_to(PACKAGE.parent).with_suffix("")
        parts = rel.parts[:-1] if rel.name == "__init__" else rel.parts
        yield ".".join(parts), path


MODULES = list(_modules())


def _imports(tree: ast.AST):
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            for a in node.names:
                yield a.name, None, a.asname or a.name.split(".")[0]
        elif isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
            for a in node.names:
                yield node.module, a.name, a.asname or a.name


@pytest.mark.parametrize("module,path", MODULES, ids=[m for m, _ in MODULES])
def test_imports_point_downward(module, path):
    mine = _layer(module)
    if mine is None:  # the package's __init__: lazy attributes only
        return
    tree = ast.parse(path.read_text())
    for target, name, _ in _imports(tree):
        full = f"{target}.{name}" if name and _layer(f"{target}.{name}") else target
        theirs = _layer(full)
        if theirs is None or theirs == mine:
            continue
        assert LAYERS[theirs] < LAYERS[mine], f"{module} imports {full}: {theirs} is not below {mine}"


@pytest.mark.parametrize("module,path", MODULES, ids=[m for m, _ in MODULES])
def test_no_private_name_across_modules(module, path):
    tree = ast.parse(path.read_text())
    bound = {}
    for target, name, alias in _imports(tree):
        if not target.startswith("quasicentral"):
            continue
        assert not (name or "").startswith("_"), f"{module} imports the private {target}.{name}"
        bound[alias] = f"{target}.{name}" if name else target
    for node in ast.walk(tree):
        if isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name) and node.value.id in bound:
            if node.attr.startswith("_") and not node.attr.startswith("__"):
                raise AssertionError(f"{module} uses the private {bound[node.value.id]}.{node.attr}")


SHIPPED = re.compile(r"brepta|\bfig(?:ure)?\s*\d|\bpendulum:", re.I)


def _docstrings(tree):
    for node in ast.walk(tree):
        if isinstance(node, (ast.Module, ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            body = node.body
            if body and isinstance(body[0], ast.Expr) and isinstance(body[0].value, ast.Constant):
                yield body[0].value


@pytest.mark.parametrize("module,path", MODULES, ids=[m for m, _ in MODULES])
def test_no_module_names_a_shipped_text(module, path):
    """Texts bring their own folder: their ids, sections and figures live there, not here.
    (Docstrings may name them in examples.)"""
    tree = ast.parse(path.read_text())
    docs = {id(d) for d in _docstrings(tree)}
    for node in ast.walk(tree):
        if isinstance(node, ast.Constant) and isinstance(node.value, str) and id(node) not in docs:
            assert not SHIPPED.search(node.value), f"{module}:{node.lineno} names a shipped text: {node.value[:60]!r}"
        if isinstance(node, ast.Name) and "brepta" in node.id.lower():
            raise AssertionError(f"{module}:{node.lineno} names a shipped text: {node.id}")


#: the layers that hold no module-level mutable state (issue 26): their tables are read-only
STATELESS = ("quasicentral.notation", "quasicentral.engine", "quasicentral.documents")
_MUTABLE_CALLS = {"dict", "list", "set", "defaultdict", "OrderedDict", "Counter", "deque", "bytearray"}


def _mutable(value: ast.AST) -> bool:
    """A module-level value a caller could change in place: a dict, list or set display or
    comprehension, a call of their constructors, or an operation on one (``{...} | {...}``)."""
    if isinstance(value, (ast.Dict, ast.List, ast.Set, ast.DictComp, ast.ListComp, ast.SetComp)):
        return True
    if isinstance(value, ast.Call):
        return isinstance(value.func, ast.Name) and value.func.id in _MUTABLE_CALLS
    if isinstance(value, ast.BinOp):
        return _mutable(value.left) or _mutable(value.right)
    return False


@pytest.mark.parametrize("module,path", [(m, p) for m, p in MODULES if m.startswith(STATELESS)],
                         ids=[m for m, _ in MODULES if m.startswith(STATELESS)])
def test_no_module_level_mutable_state(module, path):
    """State lives in a workspace object: a module's tables are MappingProxyType, frozenset or
    tuple, and nothing at module level changes one in place (a test never needs a reset)."""
    tree = ast.parse(path.read_text())
    for node in tree.body:
        if isinstance(node, (ast.Assign, ast.AnnAssign)) and node.value is not None:
            targets = node.targets if isinstance(node, ast.Assign) else [node.target]
            names = [t.id for t in targets if isinstance(t, ast.Name)]
            assert not (names and names != ["__all__"] and _mutable(node.value)), \
                f"{module}:{node.lineno}: {names[0]} is a mutable module-level value (freeze it)"
            assert not any(isinstance(t, ast.Subscript) for t in targets), \
                f"{module}:{node.lineno}: a module-level table changed in place"
        if isinstance(node, ast.Expr) and isinstance(node.value, ast.Call) and isinstance(node.value.func, ast.Attribute) \
                and node.value.func.attr in ("update", "append", "extend", "add", "setdefault", "insert", "clear", "pop"):
            raise AssertionError(f"{module}:{node.lineno}: a module-level table changed in place")


def _graph() -> dict[str, set[str]]:
    """Which module imports which, function-local imports included (a cycle hides there)."""
    known = {m for m, _ in MODULES}
    graph = {}
    for module, path in MODULES:
        deps = set()
        for target, name, _ in _imports(ast.parse(path.read_text())):
            full = f"{target}.{name}" if name else target
            deps.add(full if full in known else target)
        # a submodule imports its own package on the way: not an edge of ours
        graph[module] = {d for d in deps & known if d != module and not module.startswith(d + ".")}
    return graph


def test_no_import_cycle():
    graph, state, stack, cycles = _graph(), {}, [], []

    def visit(m):
        state[m] = "open"
        stack.append(m)
        for d in sorted(graph[m]):
            if state.get(d) == "open":
                cycles.append(" → ".join(stack[stack.index(d):] + [d]))
            elif d not in state:
                visit(d)
        stack.pop()
        state[m] = "done"

    for m in sorted(graph):
        if m not in state:
            visit(m)
    assert not cycles, cycles


#: The sizes a reader can hold in mind (issue 26): a module does one job, a function one step.
#: The shipped texts' derivation modules are not counted — they are data, and follow their
#: paper's sections (brepta1953/s5.py is section 5), as ``MODULES`` leaves them out.
MAX_MODULE_LINES = 600
MAX_FUNCTION_LINES = 80


@pytest.mark.parametrize("module,path", MODULES, ids=[m for m, _ in MODULES])
def test_module_and_function_sizes(module, path):
    source = path.read_text()
    lines = source.count("\n") + (not source.endswith("\n"))
    assert lines <= MAX_MODULE_LINES, f"{module} has {lines} lines (at most {MAX_MODULE_LINES}): split it along its jobs"
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
            size = node.end_lineno - node.lineno + 1
            assert size <= MAX_FUNCTION_LINES, (
                f"{module}.{node.name} (line {node.lineno}) has {size} lines (at most {MAX_FUNCTION_LINES})")
