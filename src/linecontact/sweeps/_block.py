"""A block of a sweep's records: the arrays of its points, their units and warnings.

:class:`Block` is what a worker returns; :func:`assemble` puts the records of the points
(or rows of points) computed into arrays of the block's shape, a point without a state a
record of NaN with its ``state`` and ``reason``.
"""

from __future__ import annotations

import functools
import json
import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ..output import unit_of
from ._plan import Plan, parse

__all__ = ["Block", "assemble", "template"]


@dataclass
class Block:
    """The records of one block: arrays of the block's shape (and records, where many).

    Attributes
    ----------
    index : int
        The block's number in the plan.
    data : dict of str to ndarray
        One array per record key, shape ``block shape`` or ``block shape + (records,)``.
    units : dict of str to str
        The unit of each record key.
    parameters : dict
        The provenance parameters of the block's first computed point.
    warnings : list of (str, str)
        The distinct warnings its points gave: the category's name and the message.
    """

    index: int
    data: dict[str, np.ndarray]
    units: dict[str, str] = field(default_factory=dict)
    parameters: dict[str, Any] = field(default_factory=dict)
    warnings: list[tuple[str, str]] = field(default_factory=list)


@functools.lru_cache(maxsize=8)
def template(p: Plan) -> Any:
    return parse(p.command, p.template_words())


def _column(v: np.ndarray) -> np.ndarray:
    """A record column as a sweep stores it: float, bool, or text (objects)."""
    kind = v.dtype.kind
    if kind == "b":
        return v.astype(bool)
    if kind in "fiu":
        return v.astype(float)
    try:
        kinds = {type(x) for x in set(v.tolist())}  # few distinct values: cheap
    except TypeError:  # lists (unhashable): JSON text
        kinds = {list}
    none = v == np.array(None)
    if kinds <= {str, type(None)}:
        out = v.astype(object)
        out[none] = ""
        return out
    if kinds <= {int, float, type(None)}:
        return np.where(none, math.nan, v).astype(float)
    return np.array(
        ["" if x is None else x if isinstance(x, str) else json.dumps(x) for x in v.tolist()],
        dtype=object,
    )


def _fill(kind: str) -> Any:
    return {"b": False, "f": math.nan}.get(kind, "")


def meta(table: Any, units: dict[str, str], parameters: dict[str, Any]) -> None:
    for k in table.columns:
        if k not in units:
            units[k] = table.units.get(k) or unit_of(k)
    if not parameters:
        parameters.update(table.provenance()["parameters"])


def assemble(
    shape: tuple[int, ...],
    n: int,
    pieces: list[tuple[np.ndarray, dict[str, np.ndarray], int]],
    failed: dict[int, tuple[str, str]],
) -> dict[str, np.ndarray]:
    recs = max([r for _, _, r in pieces], default=1)
    cols: dict[str, np.ndarray] = {}
    for idx, columns, r in pieces:
        for k, v in columns.items():
            v = _column(np.asarray(v))
            if k not in cols:
                cols[k] = np.full((n, recs), _fill(v.dtype.kind), dtype=v.dtype)
            target = cols[k]
            if target.dtype != v.dtype and target.dtype.kind != "O":
                if v.dtype.kind == "O":
                    cols[k] = target = target.astype(object)
                else:
                    v = v.astype(target.dtype)
            if r == 1:
                target[idx, 0] = v
            else:
                target[idx[0], : len(v)] = v
    for k in ("state", "reason"):
        if k not in cols:
            fill = "ok" if k == "state" else ""
            cols[k] = np.full((n, recs), fill, dtype=object)
        if cols[k].dtype.kind != "O":
            cols[k] = cols[k].astype(object)
    for i, (state, reason) in failed.items():
        for v in cols.values():
            v[i, :] = _fill(v.dtype.kind)
        cols["state"][i, :] = state
        cols["reason"][i, :] = reason
    out = {}
    for k, v in cols.items():
        out[k] = v.reshape(*shape, recs) if recs > 1 else v.reshape(shape)
    return out
