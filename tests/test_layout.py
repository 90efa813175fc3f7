"""The house: imports run one way down the floors, and no module imports itself in a circle.

Floors (docs/architecture.md): the base (versions, errors, input checks, the result base),
the numerical core and the closed forms, the problems, the SI layer, the shells (output,
CLI, figures), and the package's front door. A module may import from its own floor or below,
never above; and the import graph has no cycle.
"""

import ast
import pkgutil
from pathlib import Path

import pytest

import linecontact

FLOORS = {
    "base": [
        "linecontact._version",
        "linecontact._moved",
        "linecontact._interrupt",
        "linecontact._files",
        "linecontact._fingerprint",
        "linecontact._progress",
        "linecontact._docs",
        "linecontact._threads",
        "linecontact.errors",
        "linecontact._validation",
        "linecontact.domain",
        "linecontact.results",
        "linecontact.units",
        "linecontact.output",
        "linecontact.geometry",
    ],
    "core": [
        "linecontact._numerics",
        "linecontact._least_squares",
        "linecontact.sie",
        "linecontact.closed_forms",
        "linecontact.materials",
        "linecontact.presets",
    ],
    "problems": [
        "linecontact.normal",
        "linecontact.sliding",
        "linecontact.tangential",
        "linecontact.push",
        "linecontact.lennard_jones",
        "linecontact.lennard_jones_groups",
        "linecontact.laws",
        "linecontact.adhesion_map",
        "linecontact.facet",
        "linecontact.sphere",
        "linecontact.bent_wire",
    ],
    "si": [
        "linecontact.cylinder",
        "linecontact.inverse",
        "linecontact._pull_off_model",
        "linecontact.fits",
        "linecontact.uncertainty",
        "linecontact.measurements",
    ],
    "operations": ["linecontact.operations"],
    "shells": [
        "linecontact.reading",
        "linecontact.cli",
        "linecontact.figures",
        "linecontact.sweeps",
        "linecontact.web",
    ],
    "front": ["linecontact", "linecontact.__main__"],
}
ORDER = list(FLOORS)


def _modules() -> dict[str, Path]:
    root = Path(linecontact.__file__).parent
    mods = {"linecontact": root / "__init__.py"}
    for m in pkgutil.walk_packages(linecontact.__path__, "linecontact."):
        rel = m.name.split(".")[1:]
        path = root.joinpath(*rel)
        mods[m.name] = path / "__init__.py" if m.ispkg else path.with_suffix(".py")
    return mods


MODULES = _modules()


def _floor(name: str) -> str:
    best = None
    for floor, prefixes in FLOORS.items():
        for p in prefixes:
            if (name == p or name.startswith(p + ".")) and (best is None or len(p) > best[1]):
                best = (floor, len(p))
    assert best is not None, f"{name} is on no floor: add it to FLOORS and docs/architecture.md"
    return best[0]


def _imports(name: str) -> set[str]:
    """The linecontact modules that ``name`` imports (at any depth of its code)."""
    path = MODULES[name]
    package = name if path.name == "__init__.py" else name.rpartition(".")[0]
    out = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            out |= {a.name for a in node.names if a.name.split(".")[0] == "linecontact"}
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                parts = package.split(".")
                base = ".".join(parts[: len(parts) - node.level + 1])
                base = f"{base}.{node.module}" if node.module else base
            else:
                base = node.module or ""
            if base.split(".")[0] != "linecontact":
                continue
            for alias in node.names:
                sub = f"{base}.{alias.name}"
                out.add(sub if sub in MODULES else base)
    out.discard(name)
    return out


GRAPH = {name: _imports(name) for name in MODULES}


def test_every_module_is_on_a_floor():
    for name in MODULES:
        _floor(name)


@pytest.mark.parametrize("name", sorted(MODULES))
def test_imports_run_down(name):
    here = ORDER.index(_floor(name))
    up = sorted(t for t in GRAPH[name] if ORDER.index(_floor(t)) > here)
    assert not up, f"{name} ({_floor(name)}) imports from a higher floor: {up}"


def test_no_import_circle():
    state: dict[str, int] = {}
    stack: list[str] = []

    def visit(n: str) -> None:
        state[n] = 1
        stack.append(n)
        for t in sorted(GRAPH[n]):
            # a package's __init__ importing its own submodules is not a circle; a submodule
            # importing its package's __init__ would be
            if state.get(t) == 1:
                cycle = stack[stack.index(t) :] + [t]
                raise AssertionError("import circle: " + " -> ".join(cycle))
            if t not in state:
                visit(t)
        stack.pop()
        state[n] = 2

    for n in sorted(GRAPH):
        if n not in state:
            visit(n)


def test_the_checker_sees_imports():
    # the walk above would pass on an empty graph: check that it reads real arrows
    assert "linecontact.sie" in GRAPH["linecontact.normal.contact"]
    assert "linecontact.tangential._core" in GRAPH["linecontact.tangential.rolling"]
    assert "linecontact.normal" in GRAPH["linecontact.cylinder._cylinder"]
    assert GRAPH["linecontact.sie"] <= set(FLOORS["base"]) | {"linecontact._validation"}


#: No module is longer than this many lines (issue 21): a module that grows past it is split
#: along its seams into a package (as ``normal/`` and ``sliding/`` were).
MAX_LINES = 800

#: Exceptions, each with its size when the rule came in as a ceiling: they may shrink, never
#: grow. Empty since every module that was over the limit was split (issue 21); an entry is
#: taken off when its module is split or falls under the limit.
LONG_MODULES: dict[str, int] = {}


def _sizes() -> dict[str, int]:
    root = Path(linecontact.__file__).parent
    return {
        p.relative_to(root).as_posix(): len(p.read_text(encoding="utf-8").splitlines())
        for p in sorted(root.rglob("*.py"))
        if "__pycache__" not in p.parts
    }


SIZES = _sizes()


@pytest.mark.parametrize("path", sorted(SIZES))
def test_no_module_over_800_lines(path):
    lines = SIZES[path]
    ceiling = LONG_MODULES.get(path, MAX_LINES)
    why = (
        "LONG_MODULES: it may shrink, never grow"
        if path in LONG_MODULES
        else "split it along its seams into a package (docs/architecture.md)"
    )
    assert lines <= ceiling, f"linecontact/{path} has {lines} lines, over {ceiling}: {why}"


def test_long_modules_are_still_long():
    # an entry whose module fell under the limit is taken off, so that it cannot grow back;
    # one whose module is gone (split into a package) is ignored
    short = sorted(p for p in LONG_MODULES if p not in SIZES or SIZES[p] <= MAX_LINES)
    assert not short, f"take these off LONG_MODULES in tests/test_layout.py: {short}"
    assert max(SIZES.values()) <= max([MAX_LINES, *LONG_MODULES.values()])


def test_the_size_check_sees_modules():
    assert "normal/contact.py" in SIZES and "sliding/contact.py" in SIZES
    assert all(n > 0 for n in SIZES.values())


# --------------------------------------------------------------------------------------------
# no two-way tie between top-level folders (a floor of its own would hide one)


def _top(name: str) -> str:
    """The top-level module or package of ``name`` (``linecontact.cli`` for its modules)."""
    return ".".join(name.split(".")[:2])


def _ties(modules=None, imports=None) -> dict[tuple[str, str], list[tuple[str, str]]]:
    """Each pair of top-level folders that import each other, with one import each way."""
    modules = MODULES if modules is None else modules
    imports = _imports if imports is None else imports
    arrows: dict[tuple[str, str], tuple[str, str]] = {}
    for name in modules:
        for target in imports(name):
            a, b = _top(name), _top(target)
            if a != b and a != "linecontact" and b != "linecontact":
                arrows.setdefault((a, b), (name, target))
    return {
        (a, b): [arrows[(a, b)], arrows[(b, a)]] for (a, b) in arrows if a < b and (b, a) in arrows
    }


def test_no_two_way_tie_between_top_level_folders():
    ties = _ties()
    assert not ties, f"top-level folders that import each other (one import each way): {ties}"


def test_the_tie_check_sees_a_tie():
    # sweeps and the command line were tied (a sweep ran the subcommands' parsers), and
    # normal and lennard_jones (the law= keyword, deleted): a graph like theirs is seen
    graph = {
        "linecontact.sweeps._plan": {"linecontact.cli._options"},
        "linecontact.cli.sweep": {"linecontact.sweeps._plan"},
        "linecontact.normal.pulloff": {"linecontact.closed_forms"},
    }
    ties = _ties(graph, lambda name: graph[name])
    assert list(ties) == [("linecontact.cli", "linecontact.sweeps")]
