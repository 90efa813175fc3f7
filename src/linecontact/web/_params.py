"""Request parameters: the operations' declared parameters, typed (:mod:`linecontact.operations`).

A parameter is named as its declaration names it, the CLI flag without its dashes, ``-`` as
``_`` (``work_of_adhesion``, ``R_over_h``, ``cylinder_material``); a name no operation
declares is refused (422), never ignored. Several values: repeat the parameter or separate
the values by commas. A switch: ``true``/``1`` (or no value) gives it, ``false``/``0`` leaves
it out. The values go to the operation typed (:func:`values_of`), never as a command line. No
parameter names a file on the server: the output, figure and data inputs are not parameters
(an uploaded CSV is the ``data`` field of a form, kept in a temporary file).
"""

from __future__ import annotations

import math
import re
from collections.abc import Iterable
from typing import Any

from .. import operations
from ..errors import ParameterError

__all__ = [
    "COMMANDS",
    "MAX_POINTS",
    "ParameterError",
    "parameters_of",
    "points_of",
    "sweep_hint",
    "values_of",
]

#: The operations the API runs: every one of the catalogue (not the figures, the citation,
#: the sweeps or the server itself, which are the command line's).
COMMANDS = tuple(operations.FAMILIES)

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

#: A negative number (``-1``, ``-.5``, ``-1e-3``, ``-inf``), never a unit typed after a number.
_NUMBER = re.compile(r"^-(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$|^-(inf|infinity|nan)$", re.IGNORECASE)


_KINDS = {"number": "number", "integer": "integer", "text": "string", "switch": "boolean"}


def parameters_of(command: str) -> list[dict[str, Any]]:
    """The parameters of ``command``: name, flag, kind, several values, choices, unit, help."""
    return [
        {
            "name": p.key,
            "flag": f"{p.metavar} ..." if p.positional else p.option,  # materials NAME ...
            "kind": _KINDS[p.kind],
            "many": p.many != "one",
            "choices": list(p.choices) if p.choices else None,
            "unit": p.unit,
            "help": p.help,
        }
        for p in operations.get(command).parameters
        if not p.shell_only and p.option not in _NOT_PARAMETERS
    ]


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


def points_of(command: str, values: dict[str, Any]) -> tuple[int, str | None]:
    """The number of points a request asks for, estimated before it is computed.

    The values of each parameter that takes several, the ``NUM`` of a range
    (``a_over_R_range=START,STOP,NUM``) and the counts of a curve (``num``,
    ``num_noncontact``) or a map (``n_mu`` times ``n_y``), multiplied: an upper bound, as
    the operation computes one point per value.

    Returns
    -------
    points : int
        The estimate.
    parameter : str or None
        The request parameter that asks for the most (None: no parameter asks for several).
    """
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
