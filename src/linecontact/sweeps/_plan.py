"""A sweep's plan: the operation, its fixed flags, the swept flags and their values, blocks.

The command line of a sweep is the operation's (:mod:`linecontact.operations`: its declared
parameters, their units and counts), with several values (or ranges ``start:stop:num[:log]``)
for the flags to sweep. :func:`plan` splits it: the flags with one value stay as typed; each
flag with several values becomes an :class:`Axis`, a dimension of the result named as the
flag without dashes (``--work-of-adhesion`` -> ``work_of_adhesion``), in the unit its
declaration gives. The points are the outer product of the axes, in the order the flags were
given, cut into blocks (:func:`blocks`) that are computed, stored and resumed as wholes.
"""

from __future__ import annotations

import functools
import hashlib
import json
import math
import re
from dataclasses import dataclass
from typing import Any

from .. import operations
from .._fingerprint import code_digest
from ..operations import Inputs, Operation, Parameter
from ._ranges import MAX_SWEEP_POINTS, count_values, flag_values

__all__ = [
    "MAX_BLOCKS",
    "SWEEPABLE",
    "Axis",
    "Plan",
    "blocks",
    "count_blocks",
    "plan",
    "template",
    "typed",
]

#: Most blocks one sweep is cut into (each is kept, resumed and scheduled as a whole): a
#: point-by-point sweep of many points gets larger blocks.
MAX_BLOCKS = 100_000

#: The operations a sweep runs (``history`` takes a sequence of loads: sweep ``cycle``); the
#: parameters each takes a row of points of in one call are its declared ``rows``.
SWEEPABLE: tuple[str, ...] = (
    "normal",
    "pulloff",
    "curve",
    "slide",
    "slide-init",
    "roll",
    "cycle",
    "push",
    "fit-adhesion",
    "fit-friction",
)

#: The subcommands' output options: a sweep writes its own store (``-o``), never these.
_OUTPUT_FLAGS = ("--format", "--json", "--indent", "--plot", "-o", "--output")

#: A word that is a flag (not a number, a negative number or a range).
_FLAG = re.compile(r"^--?[A-Za-z]")


@dataclass(frozen=True)
class Axis:
    """One swept flag: a dimension of the result.

    Attributes
    ----------
    flag : str
        The flag as typed (``"--radius"``).
    name : str
        The dimension's name: the flag without dashes (``"radius"``).
    dest : str
        The attribute of the subcommand's parsed arguments.
    values : tuple
        The values, in order (numbers, or words for a flag of words).
    unit : str
        The unit the flag takes (``"1"`` for a group, ``""`` for words).
    many : bool
        The flag takes several values (its dest is a list).
    """

    flag: str
    name: str
    dest: str
    values: tuple[Any, ...]
    unit: str
    many: bool


@dataclass(frozen=True)
class Plan:
    """What a sweep computes: everything a worker needs, and nothing else (picklable).

    Attributes
    ----------
    command : str
        The subcommand (``"pulloff"``).
    fixed : tuple of str
        Its words with one value each, as typed.
    axes : tuple of Axis
        The swept flags, outermost first.
    argv : tuple of str
        The sweep's command line (for the provenance block).
    chunk_points : int
        The most points of one block.
    vector : str or None
        The dest of the innermost axis the subcommand takes in one call (None: point by
        point).
    """

    command: str
    fixed: tuple[str, ...]
    axes: tuple[Axis, ...]
    argv: tuple[str, ...]
    chunk_points: int
    vector: str | None

    @property
    def shape(self) -> tuple[int, ...]:
        """The number of values of each axis."""
        return tuple(len(a.values) for a in self.axes)

    @property
    def size(self) -> int:
        """The number of points."""
        return math.prod(self.shape)

    @property
    def dims(self) -> tuple[str, ...]:
        """The names of the axes."""
        return tuple(a.name for a in self.axes)

    def identity(self) -> str:
        """What makes two runs the same sweep: the command, its values, the blocks."""
        text = json.dumps(
            {
                "command": self.command,
                "fixed": self.fixed,
                "axes": [(a.flag, [repr(v) for v in a.values]) for a in self.axes],
                "chunk_points": self.chunk_points,
            }
        )
        return hashlib.sha256(text.encode()).hexdigest()

    def key(self) -> str:
        """What makes two runs give the same numbers: the sweep and the code that computes it.

        :meth:`identity` and the digest of the code (:func:`linecontact._fingerprint
        .code_digest`: the package's modules, its version, Python, NumPy and SciPy). Blocks
        or a store of another key are never combined with this sweep's.
        """
        text = json.dumps({"sweep": self.identity(), "code": code_digest()})
        return hashlib.sha256(text.encode()).hexdigest()

    def template_words(self) -> list[str]:
        """The subcommand's words with each axis at its first value."""
        words = list(self.fixed)
        for a in self.axes:
            words += [a.flag, repr(a.values[0]) if a.unit else str(a.values[0])]
        return words


def _parameter(op: Operation, flag: str) -> Parameter | None:
    """The parameter ``flag`` names (its flag or an old spelling; None: none)."""
    if not flag.startswith("--"):
        return None
    try:
        return op.parameter(flag[2:].replace("-", "_"))
    except ValueError:
        return None


def _unit(p: Parameter) -> str:
    """The unit of an axis: the declared SI unit, ``"1"`` for a group, ``""`` for words."""
    if p.kind not in ("number", "integer"):
        return ""
    return p.unit or "1"


def typed(command: str, words: list[str]) -> dict[str, Any]:
    """The typed values of the operation ``command`` for its ``words`` (flags and values).

    A word that is no flag of it, or a value of the wrong kind or count, is a ValueError
    that names the flag as the command line says it.
    """
    op = operations.get(command)
    out: dict[str, Any] = {}
    for flag, values in _split(words):
        p = _parameter(op, flag)
        if p is None or p.shell_only:
            raise ValueError(
                f"{flag} is not a flag of linecontact {command} (linecontact {command} --help "
                "lists them)"
            )
        if p.kind == "switch":
            if values:
                raise ValueError(f"argument {flag}: ignored explicit argument {values[0]!r}")
            out[p.name] = True
            continue
        if (
            not values
            or (p.many == "one" and len(values) > 1)
            or (p.many == "triple" and len(values) != 3)
        ):
            n = len(values)
            raise ValueError(
                p.refusal(values, f"argument {flag}: expected one argument")
                if n == 0 or p.many != "one"
                else f"{flag} takes one value, got {n}: a sweep's several values of a flag "
                "are its axis"
            )
        try:
            out[p.name] = p.convert(values, flag)
        except ValueError as exc:
            raise ValueError(p.refusal(values, str(exc))) from None
    return out


@functools.lru_cache(maxsize=8)
def template(p: Plan) -> Inputs:
    """The operation's inputs at the plan's fixed values and each axis's first value."""
    op = operations.get(p.command)
    return Inputs(op, typed(p.command, p.template_words()), words=[p.command, *p.template_words()])


def _split(words: list[str]) -> list[tuple[str, list[str]]]:
    """``words`` as (flag, its values) in order (``--flag=value`` split)."""
    out: list[tuple[str, list[str]]] = []
    for w in words:
        if _FLAG.match(w) and not re.match(r"^-(inf|infinity|nan)$", w, re.IGNORECASE):
            flag, eq, value = w.partition("=")
            out.append((flag, [value] if eq else []))
        elif not out:
            raise ValueError(f"unexpected word {w!r} before the first flag")
        else:
            out[-1][1].append(w)
    return out


def plan(
    command: str, words: list[str], argv: list[str] | None = None, chunk_points: int | None = None
) -> Plan:
    """The plan of ``linecontact sweep COMMAND WORDS`` (``ValueError`` naming the flag)."""
    if command not in SWEEPABLE:
        raise ValueError(
            f"cannot sweep {command!r}: a sweep runs one of {', '.join(SWEEPABLE)} (history "
            "takes a sequence of loads: sweep cycle; map and the figures draw their own)"
        )
    op = operations.get(command)
    fixed: list[str] = []
    axes: list[Axis] = []
    split = _split(words)
    _check_size(split, op)  # before any range is expanded
    for flag, values in split:
        if flag in _OUTPUT_FLAGS:
            raise ValueError(
                f"{flag} is not for a sweep: it writes its labelled arrays to -o OUT (.zarr or .nc)"
            )
        par = _parameter(op, flag)
        if par is None or par.shell_only:
            raise ValueError(
                f"{flag} is not a flag of linecontact {command} (linecontact {command} --help "
                "lists them)"
            )
        if par.many == "triple" or par.kind == "switch":
            fixed += [flag, *values]
            continue
        kind = {"number": float, "integer": int}.get(par.kind, str)
        vals = flag_values(flag, values, kind)
        if par.choices is not None:
            bad = [v for v in vals if v not in par.choices]
            if bad:
                raise ValueError(
                    f"{flag}: invalid choice {bad[0]!r} (choose from "
                    f"{', '.join(map(str, par.choices))})"
                )
        if len(vals) == 1:
            fixed += [flag, repr(vals[0]) if kind in (float, int) else str(vals[0])]
            continue
        if any(a.flag == flag for a in axes):
            raise ValueError(f"{flag} is given twice")
        name = flag.lstrip("-").replace("-", "_")
        axes.append(Axis(flag, name, par.name, tuple(vals), _unit(par), par.many == "several"))
    size = math.prod(len(a.values) for a in axes)
    vector = None
    for a in reversed(axes):
        if a.dest in op.rows:
            vector = a.dest
            break
    whole = command == "pulloff" and "lennard-jones" not in fixed and all(a.unit for a in axes)
    if chunk_points is None:  # never the number of workers: a resumed run has the same blocks
        point_by_point = max(1, min(64, size // 64), -(-size // MAX_BLOCKS))
        chunk_points = 200_000 if vector is not None or whole else point_by_point
        shape = tuple(len(a.values) for a in axes)
        while count_blocks(shape, chunk_points) > MAX_BLOCKS:
            chunk_points *= 2
    elif isinstance(chunk_points, bool) or not (
        isinstance(chunk_points, int) and chunk_points >= 1
    ):
        raise ValueError(f"--chunk-points must be an integer >= 1, got {chunk_points!r}")
    elif (nb := count_blocks(tuple(len(a.values) for a in axes), chunk_points)) > MAX_BLOCKS:
        raise ValueError(
            f"--chunk-points {chunk_points}: the sweep's {size} points would make {nb} blocks, "
            f"more than {MAX_BLOCKS}: give a larger --chunk-points"
        )
    p = Plan(
        command,
        tuple(fixed),
        tuple(axes),
        tuple(argv if argv is not None else ["linecontact", "sweep", command, *words]),
        int(chunk_points),
        vector,
    )
    typed(command, p.template_words())  # every other flag checked against its declaration
    return p


def _check_size(split: list[tuple[str, list[str]]], op: Operation) -> None:
    """Refuse a sweep of more than :data:`MAX_SWEEP_POINTS` points before building its values.

    The values of each flag are counted from its words (a range ``start:stop:num`` counts
    ``num``), so that a sweep too large to plan is said at once, with its size.
    """
    counts: list[tuple[str, int]] = []
    for flag, values in split:
        par = _parameter(op, flag)
        if par is None or par.many == "triple" or par.kind == "switch" or not values:
            continue
        kind = {"number": float, "integer": int}.get(par.kind, str)
        n = count_values(flag, values, kind)
        if n > 1:
            counts.append((flag, n))
    size = math.prod(n for _, n in counts)
    if size > MAX_SWEEP_POINTS:
        dims = " x ".join(f"{f} ({n})" for f, n in counts)
        raise ValueError(
            f"the sweep has {size:.3g} points ({dims}), more than {MAX_SWEEP_POINTS:.0e}: "
            "sweep fewer values, or split it into several sweeps"
        )


def _cut(shape: tuple[int, ...], chunk_points: int) -> tuple[int, int]:
    """Where :func:`blocks` cuts a grid: the axis sliced and the slab's length on it."""
    inner = 1
    j = len(shape) - 1
    while j > 0 and inner * shape[j] <= chunk_points:
        inner *= shape[j]
        j -= 1
    if inner * shape[j] <= chunk_points:  # the whole grid is one block
        return -1, 0
    return j, max(1, chunk_points // inner)


def count_blocks(shape: tuple[int, ...], chunk_points: int) -> int:
    """The number of blocks :func:`blocks` makes, without making them."""
    if not shape:
        return 1
    j, step = _cut(shape, chunk_points)
    if j < 0:
        return 1
    return math.prod(shape[:j]) * -(-shape[j] // step)


def blocks(shape: tuple[int, ...], chunk_points: int) -> list[tuple[slice, ...]]:
    """The blocks of a grid of ``shape``: at most ``chunk_points`` points each.

    A block is one index on the outer axes, a slab on one axis and whole inner axes, so
    that the blocks tile the grid as the chunks of an N-d array.
    """
    if not shape:
        return [()]
    j, step = _cut(shape, chunk_points)
    if j < 0:
        return [tuple(slice(0, n) for n in shape)]
    out = []
    for outer in _product(shape[:j]):
        for start in range(0, shape[j], step):
            sl = [slice(i, i + 1) for i in outer]
            sl.append(slice(start, min(start + step, shape[j])))
            sl += [slice(0, n) for n in shape[j + 1 :]]
            out.append(tuple(sl))
    return out


def _product(shape: tuple[int, ...]) -> list[tuple[int, ...]]:
    out: list[tuple[int, ...]] = [()]
    for n in shape:
        out = [(*o, i) for o in out for i in range(n)]
    return out
