"""The Masing (Mindlin--Deresiewicz) memory rules: the states as sums of monotone terms.

``method="closed-form"`` of :func:`~linecontact.tangential.history.tangential_history`:
after a reversal the change of the state is the monotone solution for twice the friction
stress under the load change; a branch that passes its predecessor's turning point closes a
loop and erases both (``docs/load-histories.md``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ._laws import _Law


@dataclass(frozen=True)
class _Masing:
    """The states of a history as sums of monotone terms: q = sum_k coef_k Q(x; r_k)."""

    law: _Law
    coef: NDArray  # (steps, K): 1 (virgin term) or 2 (reversal terms), with the sign
    r: NDArray  # (steps, K): argument of the monotone solution, in [0, 1]

    def traction(self, x: NDArray, steps: NDArray) -> NDArray:
        c, r = self.coef[steps][..., None], self.r[steps][..., None]
        return np.sum(c * self.law.traction(np.clip(x, -2.0, 2.0), r), axis=-2)

    def slip(self, x: NDArray, steps: NDArray) -> NDArray:
        c, r = self.coef[steps][..., None], self.r[steps][..., None]
        xc = np.clip(x, -2.0, 2.0)  # beyond the contact: nan; no overflow of x*x
        s = np.sum(np.where(c != 0, c * self.law.slip(xc, r), 0.0), axis=-2)
        return np.where(np.abs(x) > 1.0, np.nan, s)


def _passes(t: float, turning_point: float, dirn: int) -> bool:
    """Whether the load ``t``, moving in ``dirn``, closes the loop at ``turning_point``.

    Passing it closes the loop; reaching it exactly does not (the state is the same, and the
    stick zone reported is this branch's), except at full slip, where reaching it slides.
    """
    return (t - turning_point) * dirn > 0 or (t == turning_point and abs(t) >= 1.0)


def _masing(law: _Law, loads: NDArray) -> dict[str, Any]:
    """Walk the load sequence (over the full-slip load) with the Masing memory rules.

    Returns per step the terms of the state (coefficient and argument), the slip direction,
    the number of turning points held, whether the contact slides, and the energy
    dissipated in the step (over E a^2 (scale/E)^2).
    """
    n = loads.size
    stack: list[float] = []
    prev, direction = 0.0, 0
    dirs = np.zeros(n, int)
    depth = np.zeros(n, int)
    sliding = np.zeros(n, bool)
    loss = np.zeros(n)
    Wv = law.virgin_loss

    def branch_loss(start: float | None, t0: float, t1: float) -> float:
        # energy dissipated on the branch from the turning point ``start`` (None: virgin)
        # while the load moves from t0 to t1 (monotone)
        if start is None:
            w = float(Wv(abs(t1)) - Wv(abs(t0)))
        else:
            w = float(2 * (Wv(abs(t1 - start) / 2) - Wv(abs(t0 - start) / 2)))
        return max(w, 0.0)  # a difference of two close values can round below zero

    # the terms of the turning points held: term k of turning point k (the first is the
    # virgin term, the others reversal terms), kept in step with the stack
    row_c: list[float] = []
    row_r: list[float] = []

    def push(tp: float) -> None:
        if stack:
            dt = tp - stack[-1]
            row_c.append(math.copysign(2.0, dt))
            row_r.append(abs(dt) / 2)
        else:
            row_c.append(math.copysign(1.0, tp))
            row_r.append(abs(tp))
        stack.append(tp)

    def pop(k: int) -> None:
        del stack[-k:], row_c[-k:], row_r[-k:]

    rows: list[tuple[list[float], list[float]]] = []
    for j, t in enumerate(loads.tolist()):
        slid = False
        w = 0.0
        if t != prev:
            dirn = 1 if t > prev else -1
            if direction != 0 and dirn != direction:
                push(prev)
            direction = dirn
            pos = prev
            while True:
                if len(stack) >= 2 and _passes(t, stack[-2], dirn):
                    # the branch from stack[-1] reaches the turning point before it: the
                    # loop closes, both are erased, the path continues on the older branch
                    w += branch_loss(stack[-1], pos, stack[-2])
                    pos = stack[-2]
                    pop(2)
                    continue
                if len(stack) == 1 and _passes(t, -stack[-1], dirn):
                    # the first reversal's branch reaches the mirror of the first extreme:
                    # the state is the virgin one there
                    w += branch_loss(stack[-1], pos, -stack[-1])
                    pos = -stack[-1]
                    pop(1)
                    continue
                break
            if not stack and abs(t) >= 1.0:
                slid = True
                t = math.copysign(1.0, t)
                w = math.nan  # the gross-sliding distance (and its loss) is not determined
            else:
                w += branch_loss(stack[-1] if stack else None, pos, t)
            prev = t
        elif j > 0:
            slid = bool(sliding[j - 1])
            if slid:
                w = math.nan  # held at full slip: it slides on, by a distance not determined
        if stack:
            cur = (2.0 * direction, abs(prev - stack[-1]) / 2)
        else:
            cur = (math.copysign(1.0, prev) if prev != 0 else 0.0, abs(prev))
        rows.append(([*row_c, cur[0]], [*row_r, cur[1]]))
        dirs[j] = direction if prev != 0 or stack else 0
        depth[j] = len(stack)
        sliding[j] = slid
        loss[j] = w
    K = int(depth.max()) + 1
    coef = np.zeros((n, K))
    r = np.zeros((n, K))
    for j, (rc, rr) in enumerate(rows):
        coef[j, : len(rc)] = rc
        r[j, : len(rr)] = rr
    return dict(coef=coef, r=r, direction=dirs, depth=depth, sliding=sliding, loss=loss)
