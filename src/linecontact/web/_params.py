"""Request parameters as the subcommands' flags: ``radius=50e-9`` is ``--radius 50e-9``.

A parameter is named as the CLI flag without its dashes, ``-`` as ``_`` (``work_of_adhesion``,
``R_over_h``, ``cylinder_material``). Several values: repeat the parameter or separate the
values by commas. A switch: ``true``/``1`` (or no value) gives the flag, ``false``/``0``
leaves it out. No parameter names a file on the server: the output, figure and data flags are
not parameters (an uploaded CSV is the ``data`` field of a form, kept in a temporary file).
"""

from __future__ import annotations

import argparse
import functools
import re
from collections.abc import Iterable
from typing import Any

from ..cli import COMMANDS as _CLI_COMMANDS

__all__ = ["COMMANDS", "ParameterError", "argv_of", "parameters_of"]

#: The subcommands the API runs: those that compute and print records (not the figures, the
#: citation, the sweeps or the server itself).
COMMANDS = tuple(
    c for c in _CLI_COMMANDS if c not in ("paper", "figures", "cite", "sweep", "serve")
)

#: Flags that name files or shape the output: never request parameters.
_NOT_PARAMETERS = frozenset(
    {
        "--output",
        "--format",
        "--json",
        "--indent",
        "--plot",
        "--data",
        "--outdir",
        "--image-format",
        "--size",
        "--progress",
        "--workers",
        "--help",
    }
)


#: A negative number (``-1``, ``-.5``, ``-1e-3``, ``-inf``): the only values that start with '-'.
_NUMBER = re.compile(r"^-(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$|^-(inf|infinity|nan)$", re.IGNORECASE)


class ParameterError(ValueError):
    """A request parameter that is no parameter of the command, named as the user typed it."""

    def __init__(self, parameter: str, message: str) -> None:
        super().__init__(message)
        self.parameter = parameter


@functools.lru_cache(maxsize=32)
def _actions(command: str) -> dict[str, argparse.Action]:
    from ..cli import build_parser

    sub = build_parser([command]).get_default("_subparsers").choices[command]
    out: dict[str, argparse.Action] = {}
    for a in sub._actions:
        longs = [s for s in a.option_strings if s.startswith("--")]
        if not longs or a.help == argparse.SUPPRESS or longs[0] in _NOT_PARAMETERS:
            continue
        for s in longs:
            out[s] = a
    return out


def parameters_of(command: str) -> list[dict[str, Any]]:
    """The parameters of ``command``: name, flag, kind, several values, choices, help."""
    seen: set[int] = set()
    out = []
    for flag, a in _actions(command).items():
        if id(a) in seen:
            continue
        seen.add(id(a))
        kind = (
            "boolean"
            if a.nargs == 0
            else "number"
            if a.type is float
            else "integer"
            if a.type is int
            else "string"
        )
        out.append(
            {
                "name": flag[2:].replace("-", "_"),
                "flag": flag,
                "kind": kind,
                "many": a.nargs not in (None, 0),
                "choices": list(a.choices) if a.choices else None,
                "help": a.help or "",
            }
        )
    return out


def argv_of(command: str, items: Iterable[tuple[str, str]]) -> list[str]:
    """The command line of ``command`` for the request parameters ``items`` (name, value)."""
    if command not in COMMANDS:
        raise ParameterError(
            "command", f"no such command {command!r}: one of {', '.join(COMMANDS)}"
        )
    actions = _actions(command)
    values: dict[str, list[str]] = {}
    order: list[str] = []
    for name, value in items:
        flag = "--" + name.replace("_", "-")
        if flag not in actions:
            raise ParameterError(
                name,
                f"{name!r} is not a parameter of {command} (GET /api/v1/openapi.json lists them)",
            )
        if flag not in values:
            order.append(flag)
            values[flag] = []
        values[flag] += [v for v in re.split(r"[,\s]+", value.strip()) if v] if value else []
    argv: list[str] = []
    for flag in order:
        a, vals = actions[flag], values[flag]
        name = flag[2:].replace("-", "_")
        for v in vals:  # a value is never read as a flag (``load=1 -o /etc/x``)
            if v.startswith("-") and not _NUMBER.match(v):
                raise ParameterError(
                    name, f"{name}: a value may start with '-' only as a number, got {v!r}"
                )
        if a.nargs == 0:
            if not vals or vals[-1].lower() in ("1", "true", "yes", "on"):
                argv.append(flag)
            elif vals[-1].lower() not in ("0", "false", "no", "off"):
                raise ParameterError(name, f"{name} is a switch: true or false, got {vals[-1]!r}")
            continue
        if not vals:
            raise ParameterError(name, f"{name} needs a value")
        if a.nargs is None and len(vals) > 1:
            raise ParameterError(name, f"{name} takes one value, got {len(vals)}")
        argv += [flag, *vals]
    return argv
