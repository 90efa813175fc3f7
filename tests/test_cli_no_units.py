"""The command line does no unit arithmetic: ``Cylinder`` is the only SI layer (issue 21).

Every module ``src/linecontact/cli/*.py`` is read with :mod:`ast` (from the source tree, not
run) and the test fails on a *product or quotient that involves an SI scale*. Precisely:

* a **product or quotient** is a binary operation ``x * y``, ``x / y`` or ``x // y``, an
  augmented assignment ``x *= y``, ``x /= y`` or ``x //= y``, or a call of a function named
  ``multiply``, ``divide``, ``true_divide`` or ``floor_divide`` (``np.multiply(x, y)``, ...);
  its **operands** are ``x`` and ``y`` (the call's positional arguments);
* an operand **involves an SI scale** when any node inside it (the whole subexpression, so
  ``x * (2 * cyl.radius)`` and ``p.F * Eh * args.length`` count) is

  - a name or an attribute whose name is one of :data:`SI_NAMES` (``radius``, ``modulus``,
    ``adhesion_range``, ``cohesive_stress``, ``Eh``, ``E``, ``R``, ``length``, ``load``,
    ``tau0``, ``height``, ``s0``, ``w1``, ...: the cylinder's scales, the SI inputs and the
    fibre length as the command line spells them: ``R``, ``args.radius``, ``cyl.modulus``),
  - a name, an attribute or a string constant (a subscript's key: ``params["a_m"]``) that
    ends in an SI unit suffix (:data:`SI_SUFFIX`: ``a_m``, ``tau0_Pa``, ``F_N_per_m``, ...),
  - an attribute of a name ``cyl`` or ``cylinder`` (``cyl.anything``).

Arithmetic on the paper's groups (``a_over_R``, ``rho``, ``s``, ``np.pi / 4 * A``) is not
concerned: the shells may form nondimensional numbers; what they may not do is convert
between the groups and SI units, or form totals over a fibre length. Those are the SI
layer's (``Cylinder``'s methods and their SI results; the results' ``total(length)`` for the
totals, and ``Cylinder.total``).

The rule goes by names: a product of two plain numbers that no name marks as SI
(``x * y``) is not seen. ``test_the_rule_catches`` holds the forms the command line used
before (``git show 472a40c:src/linecontact/cli/normal.py`` has 48 of them).
"""

from __future__ import annotations

import ast
import re
from pathlib import Path

import pytest

SRC = Path(__file__).resolve().parents[1] / "src" / "linecontact"
CLI = SRC / "cli"
#: the shells' modules and the operations they are built from (the commands' code)
SHELL_FILES = sorted([*CLI.glob("*.py"), *(SRC / "operations").glob("*.py")])

#: the names of SI scales, SI inputs and the fibre length as the shells spell them
SI_NAMES = frozenset(
    {
        "radius",
        "modulus",
        "adhesion_range",
        "cohesive_stress",
        "work_of_adhesion",
        "equilibrium_spacing",
        "Eh",
        "Ea",
        "E",
        "R",
        "h",
        "h1",
        "h2",
        "z0",
        "sigma0",
        "s0",
        "w1",
        "w2",
        "tau0",
        "L",
        "length",
        "load",
        "height",
        "tip_height",
        "push",
    }
)
#: a name (or a key) with an SI unit in it, as the output columns are named
SI_SUFFIX = re.compile(r"_(m|m2|Pa|N|N_m|N_per_m|J|J_per_m|J_per_m2)$")
_CYLINDER = frozenset({"cyl", "cylinder"})
_OPS = (ast.Mult, ast.Div, ast.FloorDiv)
_FUNCS = frozenset({"multiply", "divide", "true_divide", "floor_divide"})


def _si_node(node: ast.AST) -> str | None:
    """What in ``node`` names an SI scale (None: nothing)."""
    for n in ast.walk(node):
        if isinstance(n, ast.Name) and (n.id in SI_NAMES or SI_SUFFIX.search(n.id)):
            return n.id
        if isinstance(n, ast.Attribute):
            if n.attr in SI_NAMES or SI_SUFFIX.search(n.attr):
                return ast.unparse(n)
            if isinstance(n.value, ast.Name) and n.value.id in _CYLINDER:
                return ast.unparse(n)
        if isinstance(n, ast.Constant) and isinstance(n.value, str) and SI_SUFFIX.search(n.value):
            return repr(n.value)
    return None


def _operands(node: ast.AST) -> list[ast.AST] | None:
    if isinstance(node, ast.BinOp) and isinstance(node.op, _OPS):
        return [node.left, node.right]
    if isinstance(node, ast.AugAssign) and isinstance(node.op, _OPS):
        return [node.target, node.value]
    if isinstance(node, ast.Call):
        f = node.func
        name = f.attr if isinstance(f, ast.Attribute) else getattr(f, "id", None)
        if name in _FUNCS:
            return list(node.args)
    return None


def unit_arithmetic(source: str) -> list[str]:
    """``'line: expression (names X)'`` for each product or quotient on an SI scale."""
    found = []
    for node in ast.walk(ast.parse(source)):
        ops = _operands(node)
        if ops is None:
            continue
        for op in ops:
            what = _si_node(op)
            if what is not None:
                line = getattr(node, "lineno", 0)
                found.append(f"{line}: {ast.unparse(node)}  (names {what})")
                break
    return sorted(found, key=lambda s: int(s.split(":")[0]))


@pytest.mark.parametrize("path", SHELL_FILES, ids=lambda p: f"{p.parent.name}/{p.name}")
def test_cli_does_no_unit_arithmetic(path: Path) -> None:
    found = unit_arithmetic(path.read_text(encoding="utf-8"))
    assert not found, f"{path.name} converts units itself:\n" + "\n".join(found)


@pytest.mark.parametrize(
    "code",
    [
        "a_m = np.multiply(r.a_over_R, R)",
        "F = p.F_pulloff_over_Eh * Eh * args.length",
        "x = cyl.modulus * cyl.adhesion_range",
        "x = values * E * a_m",
        "x = args.a / cyl.radius",
        "x = res.dissipation * args.length",
        "x = params['T_full_slip_N_per_m'] * 2",
        "x = np.divide(args.load, scale)",
        "x = 2 * (1 + cylinder.radius)",
        "x *= args.length",
    ],
)
def test_the_rule_catches(code: str) -> None:
    assert unit_arithmetic(code)


@pytest.mark.parametrize(
    "code",
    [
        "x = values / ((np.pi / 4) * args.mu * A)",
        "t = np.pi / 4 * a * a * rho + 2 * s * rho",
        "x = cyl.contact(load=args.load, length=args.length)",
        "n = 2 * len(values)",
    ],
)
def test_the_rule_spares(code: str) -> None:
    assert not unit_arithmetic(code)
