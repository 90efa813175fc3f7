r"""A model curve placed on measured points: orthogonal least squares, batched.

Generic numerics (the physics is the model's): a curve :math:`c(s; p)` of arc length
:math:`s \in [-1, 1]` (over its half-length) and shape parameters :math:`p`, scaled by the
half-length :math:`l`, turned by :math:`\phi` and moved by :math:`(x_0, y_0)`:

.. math::

    P(s) = (x_0, y_0) + l\,R(\phi)\,c(s; p).

Each measured point :math:`d_i` stands for the curve's point :math:`s_i` nearest it (its
foot, the orthogonal projection: position noise along the curve says nothing of the
shape), except the first and last, which are the wire's ends, ``s = -1`` and ``s = 1``:
they fix its length. The parameters :math:`q = (p, half, x_0, y_0, \phi)` minimise the sum of
squared distances. Levenberg--Marquardt, with the feet moved by a Newton step at every
step (variable projection: at a foot the distance's derivative in :math:`q` is the normal
component of :math:`\partial P/\partial q`), for a batch of data sets at once (the
bootstrap's), each with its own damping.

A model offers ``solve(p)`` (shape ``(B, k)``) and ``at(s, names)`` giving, at the arc
lengths ``s`` (``(B, N)``), ``x``, ``y`` (the point), ``theta`` (the tangent's angle),
``kappa`` (the curvature) and the derivatives of ``x`` and ``y`` in each shape parameter.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

_MAXIT = 60
_XTOL = 1e-11
#: the cost's relative decrease that a Gauss--Newton step would bring, below which a fit is
#: done (the parameters then within about its square root, over their curvature, of it)
_FLAT = 1e-14
#: the largest Gauss--Newton step left at a converged fit, relative to the parameter (to one
#: below one)
_CONVERGED = 1e-7


@dataclass
class Placed:
    """The state of a batch of fits (rows: data sets)."""

    q: NDArray  # (B, k + 4): shape parameters, half, x0, y0, phi
    s: NDArray  # (B, N)
    r: NDArray  # (B, N, 2): the residual vectors d - P (normal ones at free feet)
    J: NDArray  # (B, N, 2, k + 4): dP/dq (normal components at free feet)
    normal: NDArray  # (B, N, 2)
    free: NDArray  # (B, N) bool: a foot inside the curve, not an end
    cost: NDArray  # (B,)
    steps: NDArray  # (B,) int
    converged: NDArray  # (B,) bool


def _evaluate(
    model: Any,
    lam_names: tuple[str, ...],
    q: NDArray,
    s: NDArray,
    d: NDArray,
    ends: NDArray,
    projections: int = 2,
) -> tuple[NDArray, ...]:
    """The residuals and the Jacobian at ``q``, the free feet first moved by Newton steps."""
    k = q.shape[1] - 4
    model.solve(q[:, :k])
    half, o, phi = q[:, k], q[:, k + 1 : k + 3], q[:, k + 3]
    cph, sph = np.cos(phi)[:, None], np.sin(phi)[:, None]
    # the points in the wire's frame
    rel = (d - o[:, None, :]) / half[:, None, None]
    px = cph * rel[..., 0] + sph * rel[..., 1]
    py = -sph * rel[..., 0] + cph * rel[..., 1]
    for _ in range(projections):
        v = model.at(s, ("x", "y", "theta", "kappa"))
        ex, ey = px - v["x"], py - v["y"]
        ct, st = np.cos(v["theta"]), np.sin(v["theta"])
        g = ct * ex + st * ey
        gp = v["kappa"] * (-st * ex + ct * ey) - 1.0
        step = np.where(gp < -0.1, g / gp, -g)  # far from a foot: a gradient step
        s = np.where(ends, s, np.clip(s - step, -1.0, 1.0))
    names = ("x", "y", "theta") + tuple(f"{a}_{p}" for p in lam_names for a in "xy")
    v = model.at(s, names)
    cx, cy = v["x"], v["y"]
    # back in the data's frame
    Px = o[:, 0, None] + half[:, None] * (cph * cx - sph * cy)
    Py = o[:, 1, None] + half[:, None] * (sph * cx + cph * cy)
    th = v["theta"] + phi[:, None]
    normal = np.stack([-np.sin(th), np.cos(th)], axis=-1)
    B, N = s.shape
    J = np.empty((B, N, 2, k + 4))
    for i, p in enumerate(lam_names):
        ax, ay = v[f"x_{p}"], v[f"y_{p}"]
        J[..., 0, i] = half[:, None] * (cph * ax - sph * ay)
        J[..., 1, i] = half[:, None] * (sph * ax + cph * ay)
    J[..., 0, k] = cph * cx - sph * cy
    J[..., 1, k] = sph * cx + cph * cy
    J[..., 0, k + 1], J[..., 1, k + 1] = 1.0, 0.0
    J[..., 0, k + 2], J[..., 1, k + 2] = 0.0, 1.0
    J[..., 0, k + 3] = -(Py - o[:, 1, None])
    J[..., 1, k + 3] = Px - o[:, 0, None]
    r = d - np.stack([Px, Py], axis=-1)
    free = ~ends & (np.abs(s) < 1.0)
    # at a free foot only the normal components count
    rn = np.einsum("bnc,bnc->bn", r, normal)
    Jn = np.einsum("bnc,bncq->bnq", normal, J)
    f3 = free[..., None]
    r = np.where(f3, rn[..., None] * normal, r)
    J = np.where(f3[..., None], normal[..., None] * Jn[..., None, :], J)
    cost = np.einsum("bnc,bnc->b", r, r)
    return s, r, J, normal, free, cost


def place(
    model: Any,
    shape_names: tuple[str, ...],
    d: NDArray,
    q0: NDArray,
    s0: NDArray,
    bounds: NDArray,
    *,
    maxit: int = _MAXIT,
    xtol: float = _XTOL,
    damping: float = 1e-3,
    projections: int = 2,
) -> Placed:
    """Fit the model to the data sets ``d`` (``(B, N, 2)``) from ``q0``, ``s0``.

    ``bounds`` (``(k + 4, 2)``): each parameter's range; a step is cut back into it. The
    first and last points are the ends. Returns the batch's :class:`Placed` state; a row
    converged when its last step moved no parameter by more than :data:`_XTOL` (relative to
    one, the parameters being of order one; ``xtol``), starting from the damping
    ``damping`` (small from a start near the solution: Gauss--Newton steps), the feet moved
    by ``projections`` Newton steps at each step (one, from feet already near theirs).
    """
    B, N, _ = d.shape
    ends = np.zeros((B, N), bool)
    ends[:, 0] = ends[:, -1] = True
    s0 = s0.copy()
    s0[:, 0], s0[:, -1] = -1.0, 1.0
    q = q0.copy()
    s, r, J, normal, free, cost = _evaluate(model, shape_names, q, s0, d, ends)
    mu = np.full(B, damping)
    steps = np.zeros(B, int)
    done = np.zeros(B, bool)
    nq = q.shape[1]
    lo, hi = bounds[:, 0], bounds[:, 1]
    for _ in range(maxit):
        A = np.einsum("bnci,bncj->bij", J, J)
        gvec = np.einsum("bnci,bnc->bi", J, r)
        diag = np.einsum("bii->bi", A)
        Ad = A + (mu[:, None] * np.maximum(diag, 1e-12))[:, :, None] * np.eye(nq)
        delta = np.linalg.solve(Ad, gvec[..., None])[..., 0]
        # what an undamped (Gauss--Newton) step would gain: nothing beyond rounding, done
        with np.errstate(all="ignore"):
            gn = np.linalg.solve(A + 1e-300 * np.eye(nq), gvec[..., None])[..., 0]
        small = np.all(np.abs(gn) <= _CONVERGED * np.maximum(1.0, np.abs(q)), axis=1)
        done |= (np.einsum("bi,bi->b", gvec, gn) <= _FLAT * cost) & small
        delta[done] = 0.0
        trial = np.clip(q + delta, lo, hi)
        s_t, r_t, J_t, n_t, f_t, c_t = _evaluate(model, shape_names, trial, s, d, ends, projections)
        better = (c_t <= cost) & ~done
        moved = np.max(np.abs(trial - q), axis=1)
        q = np.where(better[:, None], trial, q)
        s = np.where(better[:, None], s_t, s)
        r = np.where(better[:, None, None], r_t, r)
        J = np.where(better[:, None, None, None], J_t, J)
        normal = np.where(better[:, None, None], n_t, normal)
        free = np.where(better[:, None], f_t, free)
        cost = np.where(better, c_t, cost)
        mu = np.where(better, np.maximum(mu / 3.0, 1e-12), mu * 4.0)
        steps += ~done
        done |= (moved <= xtol) | (mu > 1e10)
        if np.all(done):
            break
    # the state at the final parameters (the model's tables, the feet once more), and
    # whether a Gauss--Newton step from there would still move a parameter
    s, r, J, normal, free, cost = _evaluate(model, shape_names, q, s, d, ends)
    A = np.einsum("bnci,bncj->bij", J, J)
    gvec = np.einsum("bnci,bnc->bi", J, r)
    with np.errstate(all="ignore"):
        last = np.linalg.solve(A + 1e-300 * np.eye(nq), gvec[..., None])[..., 0]
    converged = np.all(np.abs(last) <= _CONVERGED * np.maximum(1.0, np.abs(q)), axis=1)
    return Placed(q, s, r, J, normal, free, cost, steps, converged)
