"""A sweep's plan: the subcommand, its fixed flags, the swept flags and their values, blocks.

The command line of a sweep is the subcommand's own, with several values (or ranges
``start:stop:num[:log]``) for the flags to sweep. :func:`plan` splits it: the flags with
one value stay as typed; each flag with several values becomes an :class:`Axis`, a dimension
of the result named as the flag without dashes (``--work-of-adhesion`` -> ``work_of_adhesion``).
The points are the outer product of the axes, in the order the flags were given, cut into
blocks (:func:`blocks`) that are computed, stored and resumed as wholes.
"""

from __future__ import annotations

import argparse
import contextlib
import hashlib
import io
import json
import math
import re
from dataclasses import dataclass
from typing import Any

from .._fingerprint import code_digest
from ._ranges import MAX_SWEEP_POINTS, count_values, flag_values

__all__ = ["MAX_BLOCKS", "SWEEPABLE", "Axis", "Plan", "blocks", "count_blocks", "plan"]

#: Most blocks one sweep is cut into (each is kept, resumed and scheduled as a whole): a
#: point-by-point sweep of many points gets larger blocks.
MAX_BLOCKS = 100_000

#: The subcommands a sweep runs, and for each the flags whose several values its own code
#: takes in one call, one record per value (the sweep hands it a row of points at once).
SWEEPABLE: dict[str, frozenset[str]] = {
    "normal": frozenset({"--a-over-R", "--F-over-Eh", "--half-width", "--load"}),
    "pulloff": frozenset(),
    "curve": frozenset(),
    "slide": frozenset({"--a-over-R", "--F-over-Eh2", "--half-width", "--load"}),
    "slide-init": frozenset({"--d-over-a", "--T-over-Ea", "--T-over-muF", "--tangential-load"}),
    "roll": frozenset({"--d-over-a", "--T-over-Ea", "--T-over-muF", "--tangential-load"}),
    "cycle": frozenset(
        {"--T-amplitude-over-Ea", "--T-amplitude-over-muF", "--tangential-amplitude"}
    ),
    "push": frozenset({"--H-over-R", "--height", "--tip-height"}),
    "fit-adhesion": frozenset(),
    "fit-friction": frozenset(),
}

#: The subcommands' output options: a sweep writes its own store (``-o``), never these.
_OUTPUT_FLAGS = ("--format", "--json", "--indent", "--plot", "-o", "--output")

#: A word that is a flag (not a number, a negative number or a range).
_FLAG = re.compile(r"^--?[A-Za-z]")

#: Units of the flags whose help does not say them in brackets.
_UNITS = {"--radius": "m", "--modulus": "Pa", "--E1": "Pa", "--E2": "Pa", "--nu1": "1"}


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


def subparser(command: str) -> argparse.ArgumentParser:
    """The full parser of ``linecontact COMMAND``."""
    from ..cli import build_parser

    root = build_parser([command])
    sub: argparse.ArgumentParser = root.get_default("_subparsers").choices[command]
    return sub


def parse(command: str, words: list[str]) -> argparse.Namespace:
    """The parsed arguments of ``linecontact COMMAND WORDS``; a usage error is a ValueError."""
    from ..cli import build_parser
    from ..cli._options import record_flags

    root = build_parser([command])
    err = io.StringIO()
    try:
        with contextlib.redirect_stderr(err):
            args = root.parse_args([command, *words])
    except SystemExit as exc:
        text = err.getvalue().strip().splitlines()
        message = text[-1] if text else f"bad arguments for {command}"
        raise ValueError(message.split(": error: ", 1)[-1]) from exc
    record_flags(root.get_default("_subparsers").choices[command], args)
    args.command = command
    return args


def _unit(flag: str, action: argparse.Action, kind: Any) -> str:
    if kind not in (float, int):
        return ""
    if flag in _UNITS:
        return _UNITS[flag]
    if "-over-" in flag:
        return "1"
    m = re.search(r"\[([^\]%]+)\]", action.help or "")
    if m:
        return m.group(1)
    return "1"


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
    sp = subparser(command)
    actions = sp._option_string_actions
    fixed: list[str] = []
    axes: list[Axis] = []
    split = _split(words)
    _check_size(split, actions)  # before any range is expanded
    for flag, values in split:
        if flag in _OUTPUT_FLAGS:
            raise ValueError(
                f"{flag} is not for a sweep: it writes its labelled arrays to -o OUT (.zarr or .nc)"
            )
        action = actions.get(flag)
        if action is None:
            raise ValueError(
                f"{flag} is not a flag of linecontact {command} (linecontact {command} --help "
                "lists them)"
            )
        if not flag.startswith("--") or action.nargs not in (None, "+") or action.nargs == 0:
            fixed += [flag, *values]
            continue
        if isinstance(action, argparse._StoreConstAction | argparse._StoreTrueAction):
            fixed += [flag, *values]
            continue
        kind = action.type if action.type in (float, int) else str
        vals = flag_values(flag, values, kind)
        if action.choices is not None:
            bad = [v for v in vals if v not in action.choices]
            if bad:
                raise ValueError(
                    f"{flag}: invalid choice {bad[0]!r} (choose from "
                    f"{', '.join(map(str, action.choices))})"
                )
        if len(vals) == 1:
            fixed += [flag, repr(vals[0]) if kind in (float, int) else str(vals[0])]
            continue
        if any(a.flag == flag for a in axes):
            raise ValueError(f"{flag} is given twice")
        name = flag.lstrip("-").replace("-", "_")
        axes.append(
            Axis(
                flag, name, action.dest, tuple(vals), _unit(flag, action, kind), action.nargs == "+"
            )
        )
    size = math.prod(len(a.values) for a in axes)
    vector = None
    for a in reversed(axes):
        if a.flag in SWEEPABLE[command]:
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
    parse(command, p.template_words())  # every other flag checked by the subcommand's parser
    return p


def _check_size(split: list[tuple[str, list[str]]], actions: dict[str, Any]) -> None:
    """Refuse a sweep of more than :data:`MAX_SWEEP_POINTS` points before building its values.

    The values of each flag are counted from its words (a range ``start:stop:num`` counts
    ``num``), so that a sweep too large to plan is said at once, with its size.
    """
    counts: list[tuple[str, int]] = []
    for flag, values in split:
        action = actions.get(flag)
        if action is None or action.nargs not in (None, "+") or not values:
            continue
        kind = action.type if action.type in (float, int) else str
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
