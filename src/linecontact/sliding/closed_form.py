r"""The closed form of steady sliding (``docs/sliding.md``): two equations in ``(u1, u2)``.

The separation conditions in closed form, their Jacobian, the safeguarded Newton iteration
that solves them per point, and the eccentricity, load and moment they give
(:mod:`linecontact.sliding` states the equations, axes and units).
"""

from __future__ import annotations

import numpy as np

from .. import _numerics as _num
from .. import closed_forms as _cf


def _f1(u):
    """f1 = sinh u cosh u - u (Baney & Hui), by its series below u = 0.5.

    Arrays or NumPy scalars (a scalar evaluates only the branch it takes).
    """
    small = u < 0.5
    if isinstance(small, np.ndarray):
        if not small.any():  # (the usual batch: one branch, the same values as np.where's)
            with np.errstate(over="ignore"):
                return 0.5 * np.sinh(2 * u) - u
        if small.all():
            return _cf._f1_series(u)
        ub = np.where(small, 1.0, u)
        with np.errstate(over="ignore"):
            out = 0.5 * np.sinh(2 * ub) - ub
        out[small] = _cf._f1_series(u[small])  # (the series where it is taken only)
        return out
    if small:
        return _cf._f1_series(u)
    if u < 350.0:  # sinh(2u) is finite (and no errstate is needed, ~1.5 us each)
        return 0.5 * np.sinh(2 * u) - u
    with np.errstate(over="ignore"):
        return 0.5 * np.sinh(2 * u) - u


def _cf_parts(u1, u2):
    """G1, G2 (the brackets of the separation conditions) and their u-derivatives."""
    sh1, sh2 = np.sinh(u1), np.sinh(u2)
    ch1, ch2 = np.cosh(u1), np.cosh(u2)
    cd = np.cosh(0.5 * (u1 - u2))
    # ell = ln(cosh sigma / cosh delta), cosh sigma - cosh delta = 2 sinh(u1/2) sinh(u2/2)
    ell = np.log1p(2 * np.sinh(0.5 * u1) * np.sinh(0.5 * u2) / cd)
    Sb = 0.5 * (sh1 + sh2)  # cosh(delta) sinh(sigma)
    Cb = 0.5 * (ch1 + ch2)  # cosh(delta) cosh(sigma)
    G1 = u1 * Sb - Cb * ell
    G2 = u2 * Sb - Cb * ell
    # d ell/du1 = (tanh sigma - tanh delta)/2, so Cb d ell/du1 = sinh(u2)/2 (and mirror)
    w1 = -0.5 * (sh1 * ell + sh2)
    w2 = -0.5 * (sh2 * ell + sh1)
    dG1 = (Sb + 0.5 * u1 * ch1 + w1, 0.5 * u1 * ch2 + w2)
    dG2 = (0.5 * u2 * ch1 + w1, Sb + 0.5 * u2 * ch2 + w2)
    return G1, G2, dG1, dG2, Sb


def _cf_eval(ab, kap, r, u1, u2):
    """Residuals E1 (over h1), E2 (over h2) and the 2x2 Jacobian in (u1, u2)."""
    return _cf_eval_parts(ab, kap, r, u1, u2)[:6]


def _cf_eval_parts(ab, kap, r, u1, u2):
    """:func:`_cf_eval` and the pieces the slope along the branch needs (:func:`_cf_slope`).

    Returns ``E1, E2, J11, J12, J21, J22, (f1(u1), f1(u2), G1, G2, Sb)``.
    """
    G1, G2, dG1, dG2, Sb = _cf_parts(u1, u2)
    a2 = ab * ab
    f11, f12 = _f1(u1), _f1(u2)
    E1 = (a2 * f11 + kap * ab * G1) / r - 1
    E2 = a2 * f12 + kap * ab * G2 - 1
    # (sh * sh, not sh ** 2: a NumPy scalar's power is pow(), not always the product)
    sh1, sh2 = np.sinh(u1), np.sinh(u2)
    J11 = (a2 * 2 * (sh1 * sh1) + kap * ab * dG1[0]) / r
    J12 = kap * ab * dG1[1] / r
    J21 = kap * ab * dG2[0]
    J22 = a2 * 2 * (sh2 * sh2) + kap * ab * dG2[1]
    return E1, E2, J11, J12, J21, J22, (f11, f12, G1, G2, Sb)


def _initial_u(ab, kap, r):
    """Each edge as if the contact were symmetric with its own range (normal closed form)."""
    sr = np.sqrt(r)
    if not isinstance(ab, np.ndarray):
        u2, _, _ = _cf._u_of_abar(ab, kap)
        u1, _, _ = _cf._u_of_abar(ab / sr, kap / sr)
        return u1, u2
    # both edges as one batch (the points are independent; fewer calls on small batches)
    u, _, _ = _cf._u_of_abar(np.concatenate([ab / sr, ab]), np.concatenate([kap / sr, kap]))
    return u[: ab.size], u[ab.size :]


_BIG = float(np.finfo(float).max)


def _nan_to_num(x):
    """``np.nan_to_num`` (nan to 0, infinities to the largest floats), also for NumPy scalars."""
    if isinstance(x, np.ndarray):
        return np.nan_to_num(x)
    if x != x:
        return np.float64(0.0)
    return _num._minimum(_num._maximum(x, -_BIG), _BIG)


def _direction(u1, u2, E1, E2, J11, J12, J21, J22, tol, umax):
    """The damped Newton step of :func:`_newton2` from an accepted point (elementwise).

    Returns the direction, the largest step length that keeps ``u`` positive (at most 3/4 of
    the way to 0) and below ``umax``, and whether the point is done: its residual is below
    ``tol`` or the step is at rounding level.
    """
    where = _num._where
    det = J11 * J22 - J12 * J21
    d1 = (-E1 * J22 + E2 * J12) / det
    d2 = (-E2 * J11 + E1 * J21) / det
    # fall back to the diagonal (each residual is monotone in its own u) if singular (the
    # `if`s skip work that would change nothing: the rare cases are rare in a batch too)
    bad = ~((abs(d1) < np.inf) & (abs(d2) < np.inf))
    if bad.any():
        d1 = _nan_to_num(where(bad, -E1 / J11, d1))
        d2 = _nan_to_num(where(bad, -E2 / J22, d2))
    lam = 1.0
    for d, u in ((d1, u1), (d2, u2)):
        neg = d < -0.75 * u
        if neg.any():
            lam = where(neg, _num._minimum(lam, 0.75 * u / where(neg, -d, 1.0)), lam)
        big = u + d > umax
        if big.any():
            lam = where(big, _num._minimum(lam, (umax - u) / where(big, d, 1.0)), lam)
    tiny = (abs(d1) <= 4e-16 * _num._maximum(u1, 1e-3)) & (
        abs(d2) <= 4e-16 * _num._maximum(u2, 1e-3)
    )
    done = ~(_num._maximum(abs(E1), abs(E2)) > tol) | tiny
    return d1, d2, lam + 0.0 * u1, done


def _newton2(evaluate, u1, u2, params, *, nextra=0, maxiter=60, tol=1e-15, floor=2e-14, umax=300.0):
    """Damped Newton for two residuals in (u1, u2) > 0, per point (flat arrays or scalars).

    ``evaluate(u1, u2, *params)`` returns ``(E1, E2, J11, J12, J21, J22, *extra)`` with
    ``nextra`` extra quantities. Steps are limited to keep ``u`` positive and halved (at most
    12 times) while they do not reduce the larger residual; below ``floor`` (rounding level)
    any step is accepted. A point stops when its residual is below ``tol``, its step is at
    rounding level or no step reduces its residual, or after ``maxiter`` Newton steps.

    Each iteration evaluates one trial point (a full step or a halved one) of every point
    still active; a point that stops leaves the loop (:func:`linecontact._numerics._iterate`),
    so one slow point does not keep the batch iterating. Returns ``u1, u2, |E1|, |E2|`` and
    the extras of the last evaluation at the returned ``u``.
    """
    where = _num._where
    ev = tuple(evaluate(u1, u2, *params))
    d1, d2, lam, done = _direction(u1, u2, *ev[:6], tol, umax)
    zero = 0.0 * lam
    ncur = 6 + nextra
    nstate = 2 + ncur + 5

    def step(*args):
        u1, u2 = args[0], args[1]
        cur = args[2 : 2 + ncur]
        d1, d2, lam, tries, steps = args[2 + ncur : nstate]
        n1 = u1 + lam * d1
        n2 = u2 + lam * d2
        r = evaluate(n1, n2, *args[nstate:])
        nrm = _num._maximum(abs(cur[0]), abs(cur[1]))
        nn = _num._maximum(abs(r[0]), abs(r[1]))
        ok = (abs(nn) < np.inf) & ((nn < nrm) | (nn <= floor))
        # every trial accepted (the usual case in a batch): the trial's arrays themselves
        every = isinstance(ok, np.ndarray) and bool(ok.all())
        every = every and all(isinstance(a, np.ndarray) and a.shape == ok.shape for a in r)
        if every:
            cur, u1, u2 = tuple(r), n1, n2
        else:
            cur = tuple(where(ok, a, b) for a, b in zip(r, cur, strict=True))
            u1, u2 = where(ok, n1, u1), where(ok, n2, u2)
        # a step at rounding level: quadratic convergence leaves nothing to gain
        small = (abs(lam * d1) <= 1e-12 * _num._maximum(u1, 1e-3)) & (
            abs(lam * d2) <= 1e-12 * _num._maximum(u2, 1e-3)
        )
        nd1, nd2, nlam, converged = _direction(u1, u2, *cur[:6], tol, umax)
        # thirteen trials that do not reduce the residual: it is at its rounding floor
        give_up = ~ok & (tries >= 12)
        steps = steps + where(ok, 1.0, 0.0)
        stop = (ok & (small | converged | (steps >= maxiter))) | give_up
        if every:
            return (u1, u2, *cur, nd1, nd2, nlam, 0.0 * tries, steps), stop
        d1, d2 = where(ok, nd1, d1), where(ok, nd2, d2)
        lam = where(ok, nlam, 0.5 * lam)
        tries = where(ok, 0.0, tries + 1)
        return (u1, u2, *cur, d1, d2, lam, tries, steps), stop

    state = (u1, u2, *ev, d1, d2, lam, zero, zero)
    (u1, u2, E1, E2, *rest), _ = _num._iterate(step, state, tuple(params), 13 * maxiter, done)
    return u1, u2, abs(E1), abs(E2), tuple(rest[4 : 4 + nextra])


def _closed_form(A, rho, r, s, u1=None, u2=None, *, slope=False):
    """u1, u2 and residuals of the closed-form separation conditions, flat arrays.

    With ``slope`` also ``(dPhi/dabar, du1/dabar, du2/dabar)`` at the solution
    (:func:`_cf_slope`, from Newton's last evaluation there: the same values, one
    evaluation fewer).
    """
    ab = A * np.sqrt(rho / 2)
    kap = _cf._kappa(rho, s)
    if u1 is None or u2 is None:
        u1, u2 = _initial_u(ab, kap, r)
    if not slope:
        u1, u2, e1, e2, _ = _newton2(_cf_evaluate, u1, u2, (ab, kap, r))
        return u1, u2, e1, e2
    u1, u2, e1, e2, ev = _newton2(_cf_evaluate_parts, u1, u2, (ab, kap, r), nextra=9)
    return u1, u2, e1, e2, _cf_slope(ab, kap, r, u1, u2, (*ev[:4], ev[4:]))


def _cf_evaluate(u1, u2, ab, kap, r):
    """:func:`_cf_eval` in the argument order of :func:`_newton2`."""
    return _cf_eval(ab, kap, r, u1, u2)


def _cf_evaluate_parts(u1, u2, ab, kap, r):
    """:func:`_cf_eval_parts` for :func:`_newton2`: the Jacobian and the pieces as extras."""
    E1, E2, J11, J12, J21, J22, parts = _cf_eval_parts(ab, kap, r, u1, u2)
    return E1, E2, J11, J12, J21, J22, J11, J12, J21, J22, *parts


def _cf_outputs(A, rho, r, s, u1, u2):
    """e, F, M, dF/da from u1, u2 (closed form; also used for the stability of any method)."""
    ab = A * np.sqrt(rho / 2)
    kap = _cf._kappa(rho, s)
    ecc = (2 * s / np.pi) * (u1 - u2)
    F = _cf_load(ab, kap, u1, u2)
    # M = (sigma0 a^2 / 4)(sinh 2u1 - sinh 2u2) = sigma0 a^2 cosh(2 sigma) sinh(2 delta) / 2
    M = 0.5 * s * A * A * rho * np.cosh(u1 + u2) * np.sinh(u1 - u2)
    dPhi, _, _ = _cf_slope(ab, kap, r, u1, u2)
    return ecc, F, M, dPhi


def _cf_load(ab, kap, u1, u2):
    """F/(E h2) = (pi/2)(abar^2 - kappa abar (sinh u1 + sinh u2)/2) (closed form)."""
    sh1, sh2 = np.sinh(u1), np.sinh(u2)
    return (np.pi / 2) * (ab * ab - kap * ab * 0.5 * (sh1 + sh2))


def _cf_slope(ab, kap, r, u1, u2, ev=None):
    """dPhi/dabar along the branch and du1/dabar, du2/dabar (flat arrays or NumPy scalars).

    Implicit differentiation of the closed-form separation conditions at a solution
    ``(u1, u2)`` at ``abar``; ``Phi = (2/pi) F/(E h2)``. The tangent also predicts the
    solution at a nearby width (the pull-off and load searches start Newton there).
    ``ev``: ``(J11, J12, J21, J22, parts)`` of :func:`_cf_eval_parts` at this point, where
    the caller has them.
    """
    if ev is None:
        ev = _cf_eval_parts(ab, kap, r, u1, u2)[2:]
    J11, J12, J21, J22, (f11, f12, G1, G2, Sb) = ev
    b1 = (2 * ab * f11 + kap * G1) / r
    b2 = 2 * ab * f12 + kap * G2
    det = J11 * J22 - J12 * J21
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        du1 = -(b1 * J22 - b2 * J12) / det
        du2 = -(b2 * J11 - b1 * J21) / det
        dPhi = 2 * ab - kap * Sb - kap * ab * 0.5 * (np.cosh(u1) * du1 + np.cosh(u2) * du2)
    return dPhi, du1, du2


def _cf_coefficients(A, s, u1, u2, n):
    """Chebyshev-U coefficients b_j (j < n) of pbar/E on [-1, 1] (closed form)."""
    k = np.arange(1, n + 1)
    q1 = np.exp(-u1)[:, None]
    q2 = np.exp(-u2)[:, None]
    with np.errstate(under="ignore"):
        b = (2 * s[:, None] / np.pi) * (q2**k - (-q1) ** k) / k
    b[:, 0] += 0.5 * A
    return b
