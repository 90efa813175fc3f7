"""Request parameters: the operations' declared parameters, typed (:mod:`linecontact.operations`).

A parameter is named as its declaration names it, the CLI flag without its dashes, ``-`` as
``_`` (``work_of_adhesion``, ``R_over_h``, ``cylinder_material``); a name no operation
declares is refused (422), never ignored. Several values: repeat the parameter or separate
the values by commas. A switch: ``true``/``1`` (or no value) gives it, ``false``/``0`` leaves
it out. The values go to the operation typed (:func:`values_of`), never as a command line. No
parameter names a file on the server: the output, figure and data inputs are not parameters
(an uploaded CSV is the ``data`` field of a form, kept in a temporary file). The commands
that are no operation yet (``map``, ``materials``) still run their command line
(:func:`argv_of`).
"""

from __future__ import annotations

import argparse
import functools
import math
import re
from collections.abc import Iterable
from typing import Any

from .. import operations
from ..cli import COMMANDS as _CLI_COMMANDS

__all__ = [
    "COMMANDS",
    "MAX_POINTS",
    "ParameterError",
    "argv_of",
    "is_operation",
    "parameters_of",
    "points_of",
    "sweep_hint",
    "values_of",
]

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


#: The most points one request may ask for: a larger study is a sweep (``linecontact sweep``).
#: 10,000 points of ``normal`` are about 3 MB of JSON and half a second of one worker.
MAX_POINTS = 10_000

#: The commands ``linecontact sweep`` runs (the others run on the command line).
_SWEPT = frozenset(
    {"normal", "pulloff", "curve", "slide", "slide-init", "roll", "cycle", "push"}
    | {"fit-adhesion", "fit-friction"}
)

#: Integer flags that set how many points a command computes, with their defaults (those of
#: ``--quick`` second): ``curve``'s two branches add up, the map's grid multiplies.
_COUNTS: dict[str, tuple[str, dict[str, tuple[int, int]]]] = {
    "curve": ("sum", {"--num": (200, 200), "--num-noncontact": (40, 40)}),
    "map": ("product", {"--n-mu": (17, 4), "--n-y": (81, 41)}),
}


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


def is_operation(command: str) -> bool:
    """Whether ``command`` is an operation of the catalogue (else a command line is run)."""
    return command in operations.FAMILIES


_KINDS = {"number": "number", "integer": "integer", "text": "string", "switch": "boolean"}


def parameters_of(command: str) -> list[dict[str, Any]]:
    """The parameters of ``command``: name, flag, kind, several values, choices, unit, help."""
    if is_operation(command):
        return [
            {
                "name": p.key,
                "flag": p.option,
                "kind": _KINDS[p.kind],
                "many": p.many != "one",
                "choices": list(p.choices) if p.choices else None,
                "unit": p.unit,
                "help": p.help,
            }
            for p in operations.get(command).parameters
            if not p.shell_only and p.option not in _NOT_PARAMETERS
        ]
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
                "unit": "",
                "help": a.help or "",
            }
        )
    return out


def values_of(command: str, items: Iterable[tuple[str, str]]) -> dict[str, Any]:
    """The typed values of the operation ``command`` for the request parameters ``items``.

    Each name must be a parameter the operation declares (its key, or an old spelling),
    each value of its kind and count: else a :class:`ParameterError` naming it as given.
    """
    op = operations.get(command)
    texts: dict[str, list[str]] = {}
    typed: dict[str, list[str]] = {}  # the values as the request gave them
    keys: dict[str, str] = {}
    for name, value in items:
        try:
            p = op.parameter(name)
        except ValueError:
            p = None
        if p is None or p.shell_only or p.option in _NOT_PARAMETERS:
            raise ParameterError(
                name,
                f"{name!r} is not a parameter of {command} (GET /api/v1/openapi.json lists them)",
            )
        keys.setdefault(p.name, name)
        texts.setdefault(p.name, [])
        texts[p.name] += [v for v in re.split(r"[,\s]+", value.strip()) if v] if value else []
        typed.setdefault(p.name, []).append(value)
    out: dict[str, Any] = {}
    for pname, vals in texts.items():
        p, name = op.parameter(pname), keys[pname]
        if p.kind == "switch":
            out[pname] = p.convert(vals[-1] if vals else True, name)
            continue
        if not vals:
            raise ParameterError(name, f"{name} needs a value")
        if p.many == "one" and len(vals) > 1:
            raise ParameterError(name, _one_value(name, typed[pname], p.kind == "number"))
        try:
            out[pname] = p.convert(vals, name)
        except ValueError as exc:
            raise ParameterError(name, p.refusal(vals, str(exc))) from None
    return out


def argv_of(command: str, items: Iterable[tuple[str, str]]) -> list[str]:
    """The command line of ``command`` for the request parameters ``items`` (name, value)."""
    if command not in COMMANDS:
        raise ParameterError(
            "command", f"no such command {command!r}: one of {', '.join(COMMANDS)}"
        )
    actions = _actions(command)
    values: dict[str, list[str]] = {}
    typed: dict[str, list[str]] = {}  # the values as the request gave them
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
        typed.setdefault(flag, []).append(value)
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
            raise ParameterError(name, _one_value(name, typed[flag], a.type is float))
        argv += [flag, *vals]
    return argv


def _one_value(name: str, typed: list[str], number: bool) -> str:
    """Why a parameter that takes one value got several: a decimal comma, a unit typed."""
    text = ", ".join(repr(v) for v in typed)
    said = f"{name} takes one value, got {text}"
    if not number or len(typed) != 1:
        return said
    value = typed[0].strip()
    if re.fullmatch(r"[-+]?\d*,\d+", value):
        return f"{said}: a decimal comma? write {value.replace(',', '.')}, with a point"
    m = re.fullmatch(r"([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s+(\S+)", value)
    if m and not _NUMBER.match(m.group(2)) and not re.fullmatch(r"[\d.eE+-]+", m.group(2)):
        return f"{said}: give the number alone ({m.group(1)}), in SI units (no unit typed)"
    return said


def points_of(command: str, request: list[str] | dict[str, Any]) -> tuple[int, str | None]:
    """The number of points a request asks for (its typed values, or its command line)."""
    if isinstance(request, dict):
        return _points_of_values(command, request)
    return _points_of_argv(command, request)


def _points_of_values(command: str, values: dict[str, Any]) -> tuple[int, str | None]:
    """:func:`points_of` for the typed values of an operation (:func:`values_of`)."""
    op = operations.get(command)
    factors: list[tuple[int, str]] = []
    for name, v in values.items():
        p = op.parameter(name)
        if p.many == "several":
            factors.append((len(v), p.key))
        elif p.many == "triple" and name.endswith("_range"):
            factors.append((_count(str(v[2])), p.key))
    how, counts = _COUNTS.get(command, ("product", {}))
    if counts:
        got = []
        for flag, (default, quick_default) in counts.items():
            p = op.parameter(flag[2:].replace("-", "_"))
            v = values.get(p.name)
            quick = bool(values.get("quick"))
            got.append(
                (_count(str(v)) if v is not None else quick_default if quick else default, p.key)
            )
        n = sum(v for v, _ in got) if how == "sum" else math.prod(v for v, _ in got)
        key = max(got)[1] if how == "product" else got[0][1]
        factors.append((n, key))
    total = math.prod(n for n, _ in factors)
    if not factors or max(factors)[0] <= 1:
        return total, None
    return total, max(factors)[1]


def _points_of_argv(command: str, argv: list[str]) -> tuple[int, str | None]:
    """The number of points ``command argv`` asks for, estimated before it is computed.

    The values of each flag that takes several, the ``NUM`` of a range (``--a-over-R-range
    START STOP NUM``) and the counts of a curve (``--num``, ``--num-noncontact``) or a map
    (``--n-mu`` times ``--n-y``), multiplied: an upper bound, as the command computes one
    point per value (a value the command refuses counts one; the command says why).

    Parameters
    ----------
    command : str
        The subcommand.
    argv : list of str
        Its flags and values, as :func:`argv_of` gives them.

    Returns
    -------
    points : int
        The estimate.
    parameter : str or None
        The request parameter that asks for the most (None: no parameter asks for several).
    """
    actions = _actions(command)
    given: dict[str, list[str]] = {}
    current: str | None = None
    for word in argv:
        if word.startswith("--") and word in actions:
            current = "--" + _name_of(actions[word]).replace("_", "-")
            given.setdefault(current, [])
        elif current is not None:
            given[current].append(word)
    factors: list[tuple[int, str]] = []
    for flag, vals in given.items():
        a = actions[flag]
        name = _name_of(a)
        if a.nargs == "+":
            factors.append((len(vals), name))
        elif a.nargs == 3 and a.dest.endswith("_range") and len(vals) == 3:
            factors.append((_count(vals[2]), name))
    how, counts = _COUNTS.get(command, ("product", {}))
    if counts:
        quick = "--quick" in given
        values = []
        for flag, (default, quick_default) in counts.items():
            got = given.get(flag)
            values.append((_count(got[-1]) if got else quick_default if quick else default, flag))
        n = sum(v for v, _ in values) if how == "sum" else math.prod(v for v, _ in values)
        flag = max(values)[1] if how == "product" else next(iter(counts))
        factors.append((n, _name_of(actions[flag])))
    total = math.prod(n for n, _ in factors)
    if not factors or max(factors)[0] <= 1:
        return total, None
    return total, max(factors)[1]


def _name_of(action: argparse.Action) -> str:
    return [s for s in action.option_strings if s.startswith("--")][0][2:].replace("-", "_")


def _count(value: str) -> int:
    """A count as the command would read it (1 where it would refuse it)."""
    try:
        x = float(value)
    except ValueError:
        return 1
    return max(1, int(x)) if math.isfinite(x) else 1


def sweep_hint(command: str) -> str:
    """Where a study larger than a request runs: a sweep, or the command line."""
    if command in _SWEPT:
        return f"a larger study is a sweep: `linecontact sweep {command} ...` (docs/sweeps.md)"
    return f"a larger study runs on the command line: `linecontact {command} ...`"
