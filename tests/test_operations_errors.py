"""The operations' refusals carry the parameter they refuse (issue 32: no regex over messages).

Every refusal an operation raises itself names its parameter in the error
(:class:`~linecontact.errors.ParameterError`), so that each shell says it in its own spelling
(the flag on the command line, the field beside it on a page); the HTTP API's fallback, the
first flag in the message, is left for the library's own errors that name none.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

import linecontact
from linecontact import operations
from linecontact.errors import ParameterError

OPERATIONS = Path(linecontact.__file__).parent / "operations"


def _literal_text(node: ast.AST) -> str:
    """The literal parts of a message (constants and the constant parts of f-strings)."""
    if isinstance(node, ast.Constant) and isinstance(node.value, str):
        return node.value
    if isinstance(node, ast.JoinedStr):
        return "".join(v.value for v in node.values if isinstance(v, ast.Constant))
    if isinstance(node, ast.BinOp):
        return _literal_text(node.left) + _literal_text(node.right)
    if isinstance(node, ast.IfExp):
        return _literal_text(node.body) + _literal_text(node.orelse)
    return ""


def test_no_refusal_of_an_operation_names_a_flag_only_in_its_message():
    unnamed = []
    for path in sorted(OPERATIONS.glob("*.py")):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if not (isinstance(node, ast.Raise) and isinstance(node.exc, ast.Call)):
                continue
            func = node.exc.func
            if isinstance(func, ast.Name) and func.id == "ValueError" and node.exc.args:
                if "--" in _literal_text(node.exc.args[0]):
                    unnamed.append(f"{path.name}:{node.lineno}")
    assert not unnamed, f"ValueError naming a flag only in its words: {unnamed}"


@pytest.mark.parametrize(
    ("name", "values", "parameter"),
    [
        # the parameter named is the one given, not the first flag of the message
        ("curve", dict(R_over_h=100, sigma0_over_E=0.01, F_max=1.0), "--F-max"),
        ("curve", dict(R_over_h=100, sigma0_over_E=0.01, F_max_over_Eh=1.0), "--F-max-over-Eh"),
        (
            "fit-adhesion",
            dict(half_width=5e-9, radius=50e-9, modulus=5e10, z0=3e-10),
            "--half-width",
        ),
        (
            "slide-init",
            dict(R_over_h=100, sigma0_over_E=0.01, F_over_Eh=1.0, mu=0.3, T_over_Ea=[0.1]),
            "--mu",
        ),
        ("pulloff", dict(radius=50e-9, modulus=5e10, work_of_adhesion=0.1), "--work-of-adhesion"),
        ("push", dict(R_over_h2=100, h1_over_h2=2), "--sigma0-over-E"),
        (
            "pulloff",
            dict(radius=50e-9, cylinder_material="unobtainium", substrate_material="SiO2", h=3e-10),
            "--cylinder-material",
        ),
    ],
)
def test_a_refusal_names_its_parameter(name, values, parameter):
    with pytest.raises(ParameterError) as err:
        operations.call(name, values)
    assert err.value.parameter == parameter
    assert parameter in str(err.value)  # and says it in its words
