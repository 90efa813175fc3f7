"""Computing one block of a sweep by the operation's own code, in this process.

Each point is one call of the operation (:mod:`linecontact.operations`) with typed values:
the same checks and the same records as the command line, never its text. Where the
innermost swept flag is one of the operation's declared ``rows`` (``--load``,
``--tangential-load``), a row of points is one call. A point without a state (a load below
the pull-off, a solver that missed its tolerance, an input outside the domain) is a record of
NaN with its ``state`` and ``reason``; it never fails the block.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from .._fingerprint import code_digest
from ._block import Block, assemble, call, meta
from ._plan import Plan

__all__ = ["Block", "evaluate"]


def evaluate(p: Plan, index: int, block: tuple[slice, ...], *, fast: bool = True) -> Block:
    """The records of the block ``block`` (number ``index``) of the plan ``p``.

    ``fast=False``: point by point even where a whole block is one call (for the tests that
    compare the two).
    """
    block_ = _evaluate(p, index, block, fast)
    block_.code = code_digest()
    return block_


def _evaluate(p: Plan, index: int, block: tuple[slice, ...], fast: bool) -> Block:
    from ._fast import pulloff_block

    if fast:
        whole = pulloff_block(p, index, block)
        if whole is not None:
            return whole
    shape = tuple(s.stop - s.start for s in block)
    n = math.prod(shape)
    said: list[tuple[str, str]] = []
    pieces: list[tuple[np.ndarray, dict[str, np.ndarray], int]] = []  # flat idx, columns, recs
    failed: dict[int, tuple[str, str]] = {}
    first_at: dict[str, Any] = {}
    units: dict[str, str] = {}
    parameters: dict[str, Any] = {}
    axis_values = [a.values[s] for a, s in zip(p.axes, block, strict=True)]
    flat = np.arange(n).reshape(shape) if shape else np.zeros((), int)
    vec = next((k for k, a in enumerate(p.axes) if a.dest == p.vector), None)
    rows: list[tuple[Any, Any]] | None = [((), flat)] if not shape else None
    if rows is None:
        if vec is None:
            rows = [(ix, flat[ix]) for ix in np.ndindex(*shape)]
        else:
            moved = np.moveaxis(flat, vec, -1)
            rows = [(ix, moved[ix]) for ix in np.ndindex(*moved.shape[:-1])]
    for ix, idx in rows:
        values: dict[str, Any] = {}
        idx = np.atleast_1d(idx)
        if vec is None:
            for k, a in enumerate(p.axes):
                values[a.dest] = axis_values[k][ix[k]]
        else:
            others = [k for k in range(len(p.axes)) if k != vec]
            for k, at in zip(others, list(ix), strict=True):
                values[p.axes[k].dest] = axis_values[k][int(at)]
            values[p.axes[vec].dest] = list(axis_values[vec])
        table, state, reason = call(p, values, said)
        if table is None and vec is not None and len(idx) > 1:  # find the point(s) at fault
            for j, i in enumerate(idx.tolist()):
                one = dict(values)
                one[p.axes[vec].dest] = axis_values[vec][j]
                t1, s1, r1 = call(p, one, said)
                if t1 is None:
                    failed[int(i)] = (s1, r1)
                else:
                    pieces.append((np.array([i]), dict(t1.columns), 1))
                    if not parameters:
                        first_at = dict(one)
                    meta(t1, units, parameters)
            continue
        if table is None:
            for i in idx:
                failed[int(i)] = (state, reason)
            continue
        if not parameters:
            first_at = dict(values)
        meta(table, units, parameters)
        recs = table.size if vec is None else 1
        if vec is not None and table.size != len(idx):
            raise RuntimeError(
                f"linecontact {p.command} gave {table.size} records for {len(idx)} values of "
                f"{p.axes[vec].flag}"
            )
        pieces.append((idx, dict(table.columns), recs))
    data = assemble(shape, n, pieces, failed)
    return Block(index, data, units, parameters, said, first_at)
