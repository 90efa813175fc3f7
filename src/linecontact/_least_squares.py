"""Weighted least squares in bounded log parameters: one fit, and a batch of refits at once.

Generic numerics (no physics): a model ``fun`` maps rows of parameters to rows of values.
:func:`_solve` is one trust-region fit (:func:`scipy.optimize.least_squares`);
:func:`_refit_rows` solves many fits of the same model to different data at once, one call
of the vectorised model per step (the bootstrap of :func:`linecontact.fits.fit_pull_off`).
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
from numpy.typing import NDArray


def _solve(
    model: Callable[[NDArray], NDArray],
    Fd: NDArray,
    sig: NDArray,
    start: NDArray,
    lo: NDArray,
    hi: NDArray,
):
    """One weighted least-squares fit of ``model(p)`` to ``Fd`` (trust-region reflective).

    The log parameters ``p`` within ``[lo, hi]``, to round-off; the fit itself, and the
    bootstrap refits that :func:`_refit_rows` leaves. Returns the
    :func:`scipy.optimize.least_squares` result.
    """
    from scipy.optimize import least_squares

    return least_squares(
        lambda p: (model(p) - Fd) / sig,
        np.clip(start, lo + 1e-9, hi - 1e-9),
        bounds=(lo, hi),
        method="trf",
        x_scale=1.0,
        xtol=1e-15,
        ftol=1e-15,
        gtol=1e-15,
        max_nfev=2000,
    )


#: the bootstrap's batch of refits: the central-difference step in the log parameters, the
#: step that ends a refit (in the log parameters: relative in w and z0), the most steps, and
#: the step below which a refit takes Newton steps (Gauss--Newton ones before, as _solve)
_REFIT_DIFF = 1e-5
_REFIT_XTOL = 1e-8
_REFIT_STEPS = 60
_REFIT_NEWTON = 1e-2


def _rows_or_nan(fun: Callable[[NDArray], NDArray], P: NDArray, m: int) -> NDArray:
    """``fun(P)``, with nan in the rows where it raises ``ValueError`` (found by halving)."""
    try:
        return np.asarray(fun(P), float)
    except ValueError:
        if len(P) == 1:
            return np.full((1, m), np.nan)
        k = len(P) // 2
        return np.concatenate([_rows_or_nan(fun, P[:k], m), _rows_or_nan(fun, P[k:], m)])


def _refit_rows(
    fun: Callable[[NDArray], NDArray],
    Fd: NDArray,
    sig: NDArray,
    start: NDArray,
    lo: NDArray,
    hi: NDArray,
) -> NDArray:
    """All the bootstrap refits at once: one least-squares fit per row of ``Fd``, batched.

    Damped Gauss--Newton steps (Levenberg--Marquardt), then Newton steps on the full Hessian
    of the cost once a row's step is below :data:`_REFIT_NEWTON` and the Hessian positive
    definite (quadratic convergence at any residual), in the log parameters, every row
    a step at a time through one call of the vectorised model ``fun`` (``P`` of shape
    ``(k, n)`` to forces ``(k, m)``) at the rows and their finite differences; a parameter
    on a bound of ``[lo, hi]`` that the gradient pushes out stays there. A row ends when
    its step falls below :data:`_REFIT_XTOL` (the optimum to round-off, as :func:`_solve`
    finds it). Returns the parameters, shape ``(k, n)``; nan in the rows left to
    :func:`_solve`: a model that raised or gave a non-finite force on the way, a singular
    step, or more than :data:`_REFIT_STEPS` steps.
    """
    k, m = Fd.shape
    n = start.size
    eye = np.eye(n)
    pairs = [(i, j) for i in range(n) for j in range(i + 1, n)]
    offsets = _REFIT_DIFF * np.concatenate(
        [np.zeros((1, n)), eye, -eye] + [eye[[i]] + eye[[j]] for i, j in pairs]
    )

    def forces(P):  # the weighted residuals (k, m), their gradients and Hessians in P
        Y = _rows_or_nan(fun, (P[:, None, :] + offsets).reshape(-1, n), m)
        Y = Y.reshape(len(P), len(offsets), m).transpose(0, 2, 1) / sig[:, None]
        y0, yp, ym = Y[:, :, 0], Y[:, :, 1 : 1 + n], Y[:, :, 1 + n : 1 + 2 * n]
        Hr = np.zeros((len(P), m, n, n))
        Hr[:, :, range(n), range(n)] = (yp - 2 * y0[:, :, None] + ym) / _REFIT_DIFF**2
        for c, (i, j) in enumerate(pairs):
            Hr[:, :, i, j] = Hr[:, :, j, i] = (
                Y[:, :, 1 + 2 * n + c] - yp[:, :, i] - yp[:, :, j] + y0
            ) / _REFIT_DIFF**2
        return y0, (yp - ym) / (2 * _REFIT_DIFF), Hr

    P = np.tile(np.clip(start, lo + 1e-9, hi - 1e-9), (k, 1))
    with np.errstate(all="ignore"):
        y0, j0, h0 = forces(P[:1])  # every row starts at the same point
    r = y0 - Fd / sig
    J = np.broadcast_to(j0, (k, m, n)).copy()
    Hr = np.broadcast_to(h0, (k, m, n, n)).copy()
    cost = np.sum(r * r, axis=1)
    lam = np.full(k, 1e-3)
    near = np.zeros(k, bool)
    out = np.full((k, n), np.nan)
    act = np.flatnonzero(np.isfinite(cost) & np.all(np.isfinite(Hr), axis=(1, 2, 3)))
    for _ in range(_REFIT_STEPS):
        if act.size == 0:
            break
        Pa, ra, Ja = P[act], r[act], J[act]
        g = np.einsum("kmi,km->ki", Ja, ra)
        A = np.einsum("kmi,kmj->kij", Ja, Ja)
        H = A + np.einsum("km,kmij->kij", ra, Hr[act])
        newton = near[act] & np.all(np.linalg.eigvalsh(H) > 0, axis=1)
        B = np.where(newton[:, None, None], H, A)
        free = ~(((Pa <= lo) & (g > 0)) | ((Pa >= hi) & (g < 0)))
        B = B * free[:, :, None] * free[:, None, :]
        d = np.diagonal(B, axis1=1, axis2=2)  # the damping, at least 1e-6 of the stiffest
        d = np.where(free, np.maximum(d, 1e-6 * np.max(d, axis=1, keepdims=True) + 1e-300), 1.0)
        M = B + (lam[act, None] * d)[:, :, None] * eye
        try:
            dp = -np.linalg.solve(M, (g * free)[:, :, None])[:, :, 0]
        except np.linalg.LinAlgError:  # a singular row: the rows still open go one by one
            break
        with np.errstate(all="ignore"):
            # a step past a bound: that parameter to the bound, the others solved again
            cut = ((Pa + dp < lo) | (Pa + dp > hi)) & np.any(free, axis=1, keepdims=True)
            if np.any(cut):
                dc = np.where(cut, np.clip(Pa + dp, lo, hi) - Pa, 0.0)
                rhs = -(g * free) - np.einsum("kij,kj->ki", M, dc)
                keep = ~cut[:, :, None] & ~cut[:, None, :]
                Mc = np.where(keep, M, 0.0) + cut[:, :, None] * eye
                dp = dc + np.linalg.solve(Mc, np.where(cut, 0.0, rhs)[:, :, None])[:, :, 0]
            Pn = np.clip(Pa + dp, lo, hi)
            rn, Jn, Hn = forces(Pn)
        rn = rn - Fd[act] / sig
        cn = np.sum(rn * rn, axis=1)
        bad = ~(np.isfinite(cn) & np.all(np.isfinite(Hn), axis=(1, 2, 3)))
        good = ~bad & (cn < cost[act])
        idx = act[good]
        P[idx], r[idx], J[idx], cost[idx] = Pn[good], rn[good], Jn[good], cn[good]
        Hr[idx] = Hn[good]
        lam[act] = np.where(good, np.maximum(0.1 * lam[act], 1e-12), 10 * lam[act])
        near[idx] = np.max(np.abs(Pn[good] - Pa[good]), axis=1) < _REFIT_NEWTON
        done = ~bad & (np.max(np.abs(Pn - Pa), axis=1) <= _REFIT_XTOL)
        out[act[done]] = P[act[done]]
        act = act[~done & ~bad]
    return out
