"""Generic numerics: scalar/array kernels and the per-point iteration driver.

This module knows no physics and holds no physical constant: it is the machinery that the
closed forms of :mod:`linecontact.closed_forms` and the solvers of the problems run on.

The kernels take either NumPy arrays (any shape) or NumPy scalars (``np.float64``): a scalar
call of the public functions runs the very same code on scalars, where an arithmetic operation
costs ~60 ns and an elementary function ~0.2 us instead of ~0.5 us on a 0-d array, and
``np.where`` (~2.5 us on 0-d arrays) is replaced by a plain conditional (:func:`_where`). A
point gives the same answer alone and in a batch to rounding, not always to the bit: on some
CPUs (AVX-512) NumPy's SIMD loops for ``exp``/``log`` on arrays round differently from its
scalar code (README, "Same answers on every machine"). And ``x ** 2`` is pow() for a scalar
but a product for an array: the kernels square by multiplying. :func:`_iterate` drives every
per-point iteration (Newton, bisection, secant): a point that has converged leaves the loop.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from ._validation import first_point, point_text


def _representable(what: str, value: NDArray, **params: NDArray) -> NDArray:
    """``value`` if it is finite everywhere; otherwise say which inputs overflow it."""
    if not np.all(np.isfinite(value)):
        _, at = first_point(~np.isfinite(value), **params)
        raise ValueError(f"{what} is beyond the floating-point range at {point_text(at)}")
    return value


def _where(cond, a, b):
    """``np.where(cond, a, b)``; a plain conditional when ``cond`` is a scalar.

    Both ``a`` and ``b`` have been evaluated by the caller either way, so the two forms give
    the same values (and the same floating-point warnings).
    """
    if isinstance(cond, (bool, np.bool_)):
        return a if cond else b
    return np.where(cond, a, b)


def _minimum(a, b):
    """``np.minimum(a, b)`` (nan wins), as a NumPy scalar without a ufunc call for scalars."""
    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        return np.minimum(a, b)
    return np.float64(a if (a <= b or a != a) else b)


def _maximum(a, b):
    """``np.maximum(a, b)`` (nan wins), as a NumPy scalar without a ufunc call for scalars."""
    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        return np.maximum(a, b)
    return np.float64(a if (a >= b or a != a) else b)


def _is_scalar(*values) -> bool:
    """True when every value is a scalar (Python or NumPy, or a 0-d array)."""
    return all(np.ndim(v) == 0 for v in values)


def _scalars(*values):
    """0-d arrays (and Python numbers) as ``np.float64`` scalars, for the scalar fast path."""
    return tuple(np.float64(v) for v in values)


def _full(like, value: float):
    """``value`` with the shape of ``like``: a NumPy scalar for a scalar ``like``."""
    return np.full(like.shape, value) if isinstance(like, np.ndarray) else np.float64(value)


def _iterate(step, state: tuple, params: tuple, maxiter: int, done=None):
    """Iterate ``state, stop = step(*state, *params)`` per point until it stops.

    ``state`` and ``params`` are tuples of NumPy scalars, or of 1-D arrays of one length. A point
    whose ``stop`` is true leaves the loop at once: later iterations work only on the
    points still active (so one point that converges slowly, or never, costs the work of one
    point, not that of the whole batch), and a point that reaches ``maxiter`` keeps its last
    state; the caller checks its residual.

    ``done`` (optional) marks the points that need no iteration at all.

    Returns
    -------
    state : tuple
        The final state of every point (scalars, or new arrays).
    iterations : int or ndarray of int
        Iterations used per point.
    """
    if not isinstance(state[0], np.ndarray):
        if done:
            return state, 0
        for k in range(1, maxiter + 1):  # noqa: B007 (k is the count returned)
            state, stop = step(*state, *params)
            if stop:
                return state, k
        return state, maxiter
    out = [np.array(v, dtype=float) for v in state]
    its = np.full(out[0].shape, maxiter)
    idx = np.arange(out[0].size)
    cur, par = state, params
    if done is not None:
        its[done] = 0
        idx = idx[~done]
        if idx.size == 0:
            return tuple(out), its
        cur = tuple(v[idx] for v in cur)
        par = tuple(p[idx] for p in par)
    for k in range(1, maxiter + 1):
        cur, stop = step(*cur, *par)
        if k == maxiter or stop.all():
            for o, v in zip(out, cur, strict=True):
                o[idx] = v
            its[idx[stop]] = k
            break
        if stop.any():
            # the masks as indices once (each array indexed by them: no mask scanned again)
            s_at, keep = np.flatnonzero(stop), np.flatnonzero(~stop)
            fin = idx[s_at]
            for o, v in zip(out, cur, strict=True):
                o[fin] = v.take(s_at, axis=0)
            its[fin] = k
            idx = idx[keep]
            cur = tuple(v.take(keep, axis=0) for v in cur)
            par = tuple(p.take(keep, axis=0) for p in par)
    return tuple(out), its


def _auto_sizes(sizes: NDArray, u: NDArray, tail: NDArray, tol: float, nsel: NDArray, solve):
    """The collocation size of each point for ``n="auto"``, solving again where it grows.

    The log source at the edge of an adhesive zone limits convergence to about
    ``exp(-1.5 u n)``: each point whose error estimate ``tail`` (at its size ``nsel``) exceeds
    ``tol`` moves to the first of ``sizes`` that reaches ``tol`` by that rate (at least the
    second), then one size up as long as its estimate still exceeds ``tol``.
    ``solve(nn, idx)`` solves the points ``idx`` (flat) at ``nn`` nodes and writes their
    results, ``tail`` among them, into the caller's arrays in place.

    Returns the size of each point.
    """
    need = np.log(1 / tol) / (1.5 * np.maximum(u, 1e-300))
    pending = tail > tol
    target = sizes[np.minimum(np.searchsorted(sizes, need), sizes.size - 1)]
    nsel = np.where(pending, np.maximum(target, sizes[1]), nsel)
    while pending.any():
        for nn in np.unique(nsel[pending]):
            solve(nn, np.nonzero(pending & (nsel == nn))[0])
        pending = pending & (tail > tol) & (nsel < sizes[-1])
        nsel = np.where(
            pending, sizes[np.minimum(np.searchsorted(sizes, nsel) + 1, sizes.size - 1)], nsel
        )
    return nsel
