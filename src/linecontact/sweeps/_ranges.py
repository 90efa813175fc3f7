"""The values of a swept flag: numbers, ranges ``start:stop:num[:log]``, or words."""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np

__all__ = ["MAX_AXIS_VALUES", "MAX_SWEEP_POINTS", "count_values", "flag_values", "is_range"]

#: Most points one sweep may ask for (the outer product of its swept flags); whether they fit
#: in memory or on disk is estimated before the sweep starts (``sweeps._engine``).
MAX_SWEEP_POINTS = 10**9

#: Most values of one swept flag (its coordinate is held in memory while planning).
MAX_AXIS_VALUES = 10**7


def is_range(word: str) -> bool:
    """True when ``word`` is a range ``start:stop:num[:log]`` (not a number or a word)."""
    return ":" in word


def _number(flag: str, text: str, kind: type) -> float:
    try:
        value = float(text)
    except ValueError:
        raise ValueError(
            f"{flag} takes numbers or ranges start:stop:num[:log], got {text!r}"
        ) from None
    if kind is int:
        if not (math.isfinite(value) and value.is_integer()):
            raise ValueError(f"{flag} takes integers, got {text!r}")
    return value


def _range(flag: str, text: str, kind: type) -> np.ndarray:
    parts = text.split(":")
    log = len(parts) == 4 and parts[3].strip().lower() == "log"
    if len(parts) not in (3, 4) or (len(parts) == 4 and not log):
        raise ValueError(f"{flag}: a range is start:stop:num or start:stop:num:log, got {text!r}")
    start = _number(flag, parts[0], float)
    stop = _number(flag, parts[1], float)
    try:
        num_f = float(parts[2])
    except ValueError:
        num_f = math.nan
    if not (math.isfinite(num_f) and num_f.is_integer() and num_f >= 1):
        raise ValueError(f"{flag}: the range {text!r} needs num an integer >= 1, got {parts[2]!r}")
    num = int(num_f)
    if num > MAX_AXIS_VALUES:
        raise ValueError(
            f"{flag}: the range {text!r} asks for {num} values, more than {MAX_AXIS_VALUES} "
            "for one flag"
        )
    for name, v in (("start", start), ("stop", stop)):
        if not math.isfinite(v):
            raise ValueError(f"{flag}: the range {text!r} needs a finite {name}")
    if log:
        if start <= 0 or stop <= 0:
            raise ValueError(f"{flag}: a log range needs start and stop > 0, got {text!r}")
        if stop < start:
            raise ValueError(f"{flag}: a log range needs stop >= start, got {text!r}")
        if num == 1 or start == stop:
            values = np.full(num, start)
        else:  # increasing to the last bit, whatever the rounding of the powers
            values = np.maximum.accumulate(np.geomspace(start, stop, num))
    else:
        values = np.linspace(start, stop, num)
    if kind is int:
        rounded = np.round(values)
        if not np.all(rounded == values):
            raise ValueError(f"{flag} takes integers: the range {text!r} gives non-integers")
    return values


def count_values(flag: str, words: Sequence[str], kind: Any) -> int:
    """How many values ``words`` give ``flag``, without making them (a range: its ``num``).

    A range whose ``num`` is not a number counts one: :func:`flag_values` says what is wrong.
    """
    if kind not in (float, int):
        return len(words)
    n = 0
    for w in words:
        parts = w.split(":") if is_range(w) else []
        try:
            num = float(parts[2]) if len(parts) >= 3 else 1.0
        except ValueError:
            num = 1.0
        n += int(num) if math.isfinite(num) and num >= 1 else 1
    if n > MAX_AXIS_VALUES:
        raise ValueError(f"{flag} asks for {n} values, more than {MAX_AXIS_VALUES} for one flag")
    return n


def flag_values(flag: str, words: Sequence[str], kind: Any) -> list[Any]:
    """The values of ``flag`` that ``words`` give: each a number, a range, or a word.

    ``kind`` is the flag's type (``float``, ``int``; anything else: the words themselves).
    Numbers come back as Python floats or ints, in the order given, ranges expanded.
    """
    if not words:
        raise ValueError(f"{flag} needs at least one value")
    if kind not in (float, int):
        return list(words)
    out: list[Any] = []
    for w in words:
        vals = _range(flag, w, kind) if is_range(w) else np.array([_number(flag, w, kind)])
        out.extend(int(v) if kind is int else float(v) for v in vals)
    if len(out) > MAX_AXIS_VALUES:
        raise ValueError(
            f"{flag} asks for {len(out)} values, more than {MAX_AXIS_VALUES} for one flag"
        )
    return out
