"""Each constant and closed form once: the source of the package is read, not run.

The Maugis strength ``16/(9 sqrt 3)`` lives in ``materials.py`` (``MAUGIS_STRENGTH``), the
group ``kappa = (4/pi)(sigma0/E) sqrt(2R/h)`` in ``closed_forms/groups.py`` (``_kappa``), and
the closed forms of JKR and the rigid pull-off in ``closed_forms/jkr.py`` (``_jkr``,
``_jkr_pull_off``, ``_rigid_pull_off``, ...): any other
module writing them again fails here. Every expression of every module under
``src/linecontact`` is normalised by ``ast.unparse`` (so that parentheses, spacing and
strings or comments do not matter) and matched against each spelling.
"""

from __future__ import annotations

import ast
import math
import re
from pathlib import Path

import pytest

import linecontact

ROOT = Path(linecontact.__file__).parent

_NUM = r"(?:\.0*)?"
#: the Maugis strength 16/(9 sqrt 3); kappa = (4/pi) s sqrt(2 R/h); the JKR load's
#: sqrt(2 pi E w a); the JKR pull-off -(3/4)(4 pi w^2 E R)^(1/3); the rigid pull-off
#: -2 sqrt(2) w sqrt(R/h).
#: (name, its one home as (module path, enclosing definitions), patterns of ast.unparse text)
RULES = {
    "Maugis strength": (
        ("materials.py", ("MAUGIS_STRENGTH",)),
        [
            rf"\b9{_NUM}\s*\*\s*(?:\w+\.)*sqrt\(3{_NUM}\)",  # 9 * sqrt(3), 9.0 * np.sqrt(3.0)
            rf"(?:\w+\.)*sqrt\(3{_NUM}\)\s*\*\s*9{_NUM}\b",  # sqrt(3) * 9
            rf"\b16{_NUM}\s*/\s*9{_NUM}\s*/",  # 16 / 9 / sqrt(3)
            rf"\b9{_NUM}\s*\*\s*3{_NUM}\s*\*\*\s*0?\.5\b",  # 9 * 3 ** 0.5
        ],
    ),
    "kappa": (
        ("closed_forms/groups.py", ("_kappa",)),
        [rf"\b4{_NUM}\s*/\s*(?:\w+\.)?pi\b.*sqrt\(2{_NUM}\s*\*"],
    ),
    "JKR load": (
        ("closed_forms/jkr.py", ("_strip_pull_off", "_jkr_half_width")),
        [rf"sqrt\(2{_NUM}\s*\*\s*(?:\w+\.)?pi\s*\*"],
    ),
    "JKR pull-off": (
        ("closed_forms/jkr.py", ("_jkr_pull_off",)),
        [rf"0?\.75\s*\*\s*(?:\w+\.)?cbrt\(4{_NUM}\s*\*\s*(?:\w+\.)?pi"],
    ),
    "rigid pull-off": (
        ("closed_forms/jkr.py", ("_rigid_pull_off",)),
        [rf"\b2{_NUM}\s*\*\s*(?:\w+\.)*sqrt\(2{_NUM}\)\s*\*"],
    ),
}

#: numbers that are the Maugis strength or its inverse written out (1.0264, 0.9743)
_STRENGTH = 16.0 / (9.0 * math.sqrt(3.0))


def _sources() -> dict[str, ast.Module]:
    return {
        p.relative_to(ROOT).as_posix(): ast.parse(p.read_text(encoding="utf-8"))
        for p in sorted(ROOT.rglob("*.py"))
    }


def _where(tree: ast.Module) -> dict[ast.AST, str]:
    """Each node's enclosing definition: a function, a class or a module-level assignment."""
    owner: dict[ast.AST, str] = {}

    def visit(node: ast.AST, name: str) -> None:
        for child in ast.iter_child_nodes(node):
            here = name
            if isinstance(child, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
                here = child.name
            elif isinstance(child, (ast.Assign, ast.AnnAssign)) and name == "<module>":
                targets = child.targets if isinstance(child, ast.Assign) else [child.target]
                here = ",".join(t.id for t in targets if isinstance(t, ast.Name)) or name
            owner[child] = here
            visit(child, here)

    visit(tree, "<module>")
    return owner


def _expressions(tree: ast.Module):
    """The outermost expressions of every statement, strings left out (docstrings, messages)."""
    for node in ast.walk(tree):
        if isinstance(node, ast.stmt):
            for field in ("value", "test", "iter", "targets", "args", "returns"):
                sub = getattr(node, field, None)
                for e in sub if isinstance(sub, list) else [sub]:
                    if isinstance(e, ast.expr) and not isinstance(e, ast.JoinedStr):
                        yield e


def _text(e: ast.expr) -> str:
    """``ast.unparse`` with the string constants (and f-strings) blanked."""

    class Blank(ast.NodeTransformer):
        def visit_Constant(self, node: ast.Constant) -> ast.AST:  # noqa: N802
            return ast.Constant("") if isinstance(node.value, str) else node

        def visit_JoinedStr(self, node: ast.JoinedStr) -> ast.AST:  # noqa: N802
            return ast.Constant("")

    import copy

    return ast.unparse(Blank().visit(copy.deepcopy(e)))


def _found(patterns: list[str]) -> set[tuple[str, str, int]]:
    out = set()
    for path, tree in SOURCES.items():
        owner = _where(tree)
        for e in _expressions(tree):
            text = _text(e)
            if any(re.search(p, text) for p in patterns):
                out.add((path, owner.get(e, "<module>"), e.lineno))
    return out


SOURCES = _sources()


@pytest.mark.parametrize("what", sorted(RULES))
def test_written_once(what):
    (home_path, home_defs), patterns = RULES[what]
    found = _found(patterns)
    homes = {f for f in found if f[0] == home_path and f[1] in home_defs}
    home = f"{home_path}:{'/'.join(home_defs)}"
    assert homes, f"{what}: not found in its home {home} (the check is blind)"
    others = sorted(found - homes)
    assert not others, f"{what} is written again outside {home}: {others}"


@pytest.mark.parametrize(
    ("code", "what"),
    [
        ("s0 = 16 * w / (9 * np.sqrt(3) * z0)", "Maugis strength"),
        ("S = 16.0 / (9.0 * math.sqrt(3.0))", "Maugis strength"),
        ("h = 9 * sqrt(3) * z0 / 16", "Maugis strength"),
        ("h = np.sqrt(3) * 9 * z0 / 16", "Maugis strength"),
        ("S = 16 / 9 / 3 ** 0.5", "Maugis strength"),
        ("k = (4 / np.pi) * s * np.sqrt(2 * rho)", "kappa"),
        ("k = 4.0 / math.pi * float(s) * math.sqrt(2.0 * float(r))", "kappa"),
        (
            "F = np.pi * E * a ** 2 / (4 * R) - np.sqrt(2 * np.pi * w * E * a)",
            "JKR load",
        ),
        ("F = -0.75 * np.cbrt(4 * np.pi * w * w * E * R)", "JKR pull-off"),
        ("F = -2 * math.sqrt(2) * w * np.sqrt(R / h)", "rigid pull-off"),
    ],
)
def test_the_patterns_see_each_spelling(code, what):
    texts = [_text(e) for e in _expressions(ast.parse(code))]
    assert any(re.search(p, t) for p in RULES[what][1] for t in texts)


def test_text_is_not_code():
    code = 'raise ValueError(f"sigma0 = 16 w/(9 sqrt(3) z0) = {s!r}")\n"""16 / (9 * np.sqrt(3))"""'
    texts = [_text(e) for e in _expressions(ast.parse(code))]
    patterns = [p for _, pats in RULES.values() for p in pats]
    assert not any(re.search(p, t) for p in patterns for t in texts)


def test_the_strength_is_not_written_as_a_number():
    bad = []
    for path, tree in SOURCES.items():
        for node in ast.walk(tree):
            if isinstance(node, ast.Constant) and type(node.value) is float:
                for v in (_STRENGTH, 1 / _STRENGTH):
                    if abs(node.value / v - 1) < 1e-3:
                        bad.append((path, node.lineno, node.value))
    assert not bad, f"the Maugis strength written as a number: {bad}"


def test_the_aliases_are_the_constant():
    from linecontact import inverse, lennard_jones, materials

    assert materials.MAUGIS_STRENGTH == _STRENGTH
    assert materials.MAUGIS_H_OVER_Z0 == 1.0 / _STRENGTH
    assert lennard_jones.MAUGIS_MATCH_SIGMA0 is materials.MAUGIS_STRENGTH
    assert lennard_jones.MAUGIS_MATCH_H_OVER_Z0 is materials.MAUGIS_H_OVER_Z0
    assert inverse.S_LJ is materials.MAUGIS_STRENGTH
