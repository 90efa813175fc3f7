r"""The Maugis--Dugdale line contact of Baney & Hui and Johnson & Greenwood.

Units as in :mod:`linecontact.closed_forms`.

Maugis--Dugdale line contact
----------------------------
With :math:`m = c/a = \cosh u` the bounded contact pressure is

.. math::

    p(x) = \frac{E}{2R}\sqrt{a^2 - x^2}
           - \frac{2\sigma_0}{\pi}\arctan\sqrt{\frac{c^2 - a^2}{a^2 - x^2}}, \quad |x| < a,

and :math:`p = -\sigma_0` for :math:`a < |x| < c`. Equilibrium and the separation
:math:`h` at :math:`x = c` give (Baney & Hui 1997, Eqs. 22--23; Johnson & Greenwood 2008)

.. math::

    F = \frac{\pi E a^2}{4R} - 2\sigma_0\sqrt{c^2 - a^2}, \qquad
    h = \frac{a^2}{2R}\,f_1(u) + \frac{4\sigma_0 a}{\pi E}\,f_2(u),

:math:`f_1 = \sinh u\cosh u - u`, :math:`f_2 = u\sinh u - \cosh u\ln\cosh u`.

The whole family depends on one group: with :math:`\bar a = (a/R)\sqrt{R/(2h)}` and
:math:`\kappa = (4/\pi)(\sigma_0/E)\sqrt{2R/h}` the separation condition reads
:math:`\bar a^2 f_1 + \kappa\bar a f_2 = 1` and :math:`F/(Eh) = (\pi/2)(\bar a^2 -
\kappa\bar a\sinh u)`. The load has exactly one stationary point along the contact branch,
at the ``u`` where :math:`\kappa = 2\sinh u/\sqrt{L^2 f_1 + 2L\sinh u\,f_2}`,
:math:`L = \ln\cosh u` (see ``docs/derivations.md``), a decreasing function of ``u`` from
infinity to zero; this makes the pull-off search a bracketed one-dimensional root.

All functions here are evaluated in forms scaled by :math:`e^{-u}` so that they neither
overflow for vanishing contact width (:math:`u \to \infty`) nor cancel near the JKR end
(:math:`u \to 0`).

References
----------
J. M. Baney, C.-Y. Hui, "A cohesive zone model for the adhesion of cylinders",
J. Adhesion Sci. Technol. 11 (1997) 393--406. doi:10.1163/156856197X00796
K. L. Johnson, J. A. Greenwood, "A Maugis analysis of adhesive line contact",
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

from .._numerics import _full, _is_scalar, _iterate, _maximum, _minimum, _scalars, _where

#: ``ln 2``: the zero-width end of the family (Eq. 14) and the large-``u`` asymptotes.
LN2 = float(np.log(2.0))


# --------------------------------------------------------------------------------------------
# scaled elementary functions of u = arccosh(c/a)

#: f1(u) = sinh u cosh u - u = u^3 sum_{k>=1} c_k (u^2)^(k-1), c_k = 4^k/(2k+1)!, used below
#: u = 1 (where the closed form cancels); twelve terms leave a truncation of ~1e-20 relative.
#: (int / int is correctly rounded in Python: each c_k is the double nearest to it.)
_F1_SERIES = tuple(4**k / math.factorial(2 * k + 1) for k in range(12, 0, -1))


def _f1_series(u):
    """The series of f1 = sinh u cosh u - u (Horner, highest power first); for |u| <= 1."""
    x = u * u
    acc = _F1_SERIES[0]
    for c in _F1_SERIES[1:]:
        acc = acc * x + c
    return acc * (x * u)


def _small_u(u, q):
    r""":math:`L = \ln\cosh u` and ``F1`` below :math:`u = 1`, by series.

    There :math:`1 - q^2 - 4uq` cancels.
    """
    sh = np.sinh(u / 2)
    return np.log1p(2 * sh * sh), 4 * q * _f1_series(u)


def _large_u(u, q):
    """``L`` and ``F1`` from u = 1 on (no overflow as u -> inf)."""
    return u + np.log1p(q) - LN2, 1 - q * q - 4 * u * q


def _scaled(u: NDArray) -> dict[str, NDArray]:
    r"""Overflow-free pieces ``F1``, ``F2``, ``St``, ``Ct``, ``L`` and ``q``.

    :math:`F_1 = 4 e^{-2u} f_1`, :math:`F_2 = 2 e^{-u} f_2`, :math:`S_t = 2e^{-u} \sinh u`,
    :math:`C_t = 2 e^{-u} \cosh u`, :math:`L = \ln\cosh u` and the exponential :math:`q = e^{-2u}`.
    ``u`` is an array or a NumPy scalar (see :func:`_where`); a scalar evaluates only the
    branch (series or not) that it takes.
    """
    q = np.exp(-2 * u)
    St = -np.expm1(-2 * u)
    Ct = 1 + q
    small = u < 1.0
    if isinstance(small, np.ndarray):
        Ls, F1s = _small_u(np.where(small, u, 0.0), q)  # no overflow of the series at large u
        Ll, F1l = _large_u(u, q)
        L = np.where(small, Ls, Ll)
        F1 = np.where(small, F1s, F1l)
    else:
        L, F1 = _small_u(u, q) if small else _large_u(u, q)
    F2 = u * St - Ct * L
    return {"q": q, "St": St, "Ct": Ct, "L": L, "F1": F1, "F2": F2}


def _x_of_u(kap: NDArray, p: dict[str, NDArray]) -> NDArray:
    """X = abar e^u / 2 solving X^2 F1 + kappa X F2 = 1."""
    F1, F2 = p["F1"], p["F2"]
    kF2 = kap * F2
    return 2.0 / (kF2 + np.sqrt(kF2 * kF2 + 4 * F1))


def _abar_dln(u, kap, p):
    """X, e^{-u}, abar and d ln(abar)/du at u, from the pieces ``p`` of :func:`_scaled`."""
    X = _x_of_u(kap, p)
    e = np.exp(-u)
    St = p["St"]
    abar = 2 * X * e
    # d ln abar / du = -(X St^2 + kappa (u Ct - St L)/2) / (X F1 + kappa F2/2)
    dln = -(X * St * St + kap * (u * p["Ct"] - St * p["L"]) / 2) / (X * p["F1"] + kap * p["F2"] / 2)
    return X, e, abar, dln


def _branch_point(u: NDArray, kap: NDArray) -> dict[str, NDArray]:
    """Everything along the contact branch at parameter u, for group kappa (scaled units).

    Returns abar, Phi = (2/pi) F/(Eh), d ln(abar)/du and dPhi/du.
    """
    p = _scaled(u)
    X, e, abar, dln = _abar_dln(u, kap, p)
    St = p["St"]
    kX = kap * X
    phi = 4 * X * X * e * e - kX * St
    # dPhi/du = 2 abar^2 dln - kappa X (dln St + Ct); the load falls as u grows (a shrinks)
    # on the stable part of the branch, where dPhi/du < 0
    dphi = 2 * abar * abar * dln - kX * (dln * St + p["Ct"])
    return {"abar": abar, "phi": phi, "X": X, "dln": dln, "dphi": dphi, **p}


def _kappa_stationary(u: NDArray) -> NDArray:
    """Kappa at which the load is stationary at u: 2 St / sqrt(L^2 F1 + 2 L St F2)."""
    p = _scaled(np.asarray(u, dtype=float))
    L = p["L"]
    return 2 * p["St"] / np.sqrt(L * L * p["F1"] + 2 * L * p["St"] * p["F2"])


# --------------------------------------------------------------------------------------------
# the contact branch at a given width


_W_LO = float(np.log(1e-60))  # bracket of _u_of_abar in w = ln u (c - a ~ u^2 a / 2)
_W_HI = float(np.log(750.0))


def _abar_step(w, lo, hi, prev, target, kap):
    """One bracketed Newton step of ln abar(u) = target in w = ln u (errors ignored by caller).

    ``prev`` is the size of the previous Newton step (0 after any other step).
    """
    u = np.exp(w)
    _, _, abar, dln = _abar_dln(u, kap, _scaled(u))
    r = np.log(abar) - target  # decreasing in w
    lo = _where(r > 0, w, lo)
    hi = _where(r <= 0, w, hi)
    w_new = w - r / (dln * u)
    # (abs(x) < inf is isfinite(x), also for NumPy scalars, where np.isfinite costs ~0.7 us)
    bad = ~(abs(w_new) < np.inf) | (w_new < lo) | (w_new > hi)
    w_new = _where(bad, 0.5 * (lo + hi), w_new)
    done = abs(r) <= 2e-16
    w_new = _where(done, w, w_new)
    step = abs(w_new - w)
    wmax = _maximum(abs(w_new), 1.0)
    # Newton converges quadratically: with C = step/prev^2 observed over the last two Newton
    # steps, about C step^2 is left after this one; once that is below rounding another
    # evaluation has nothing to add (it saves one of the usual four)
    newton = ~(bad | done)
    quad = newton & (step < prev) & (step * step * step <= 1e-17 * prev * prev * wmax)
    stop = done | (step <= 1e-15 * wmax) | quad
    return (w_new, lo, hi, _where(newton, step, 0.0)), stop


def _u_guess(abar, kap):
    """Initial u for abar(u; kappa) = abar from the asymptotes of the two ends."""
    X_inf = 2.0 / (kap * LN2 + np.sqrt(kap * kap * LN2 * LN2 + 4))
    u_large = np.log(_maximum(2 * X_inf / abar, 1.0 + 1e-12))
    # small u: (2/3) abar^2 u^3 + kappa abar u^2 / 2 = 1  -> take the larger of the two roots
    u_small = _minimum(
        (1.5 / (abar * abar)) ** (1 / 3), np.sqrt(2.0 / _maximum(kap * abar, 1e-300))
    )
    return _minimum(_maximum(_where(u_large > 1.0, u_large, u_small), 1e-9), 700.0)


def _solve_abar(abar, kap, *, maxiter: int = 60):
    """u, separation residual, iterations and the branch point at u (flat arrays or scalars).

    The caller silences the floating-point warnings of the extreme widths (``np.errstate``
    over, divide and invalid; :func:`_u_of_abar` does), as ``normal_contact`` does once for
    all its work (an ``errstate`` costs ~1.5 us, a fair part of a scalar call).
    """
    target = np.log(abar)
    w0 = np.log(_u_guess(abar, kap))
    lo, hi = _full(w0, _W_LO), _full(w0, _W_HI)
    (w, _, _, _), it = _iterate(_abar_step, (w0, lo, hi, _full(w0, 0.0)), (target, kap), maxiter)
    u = np.exp(w)
    bp = _branch_point(u, kap)
    # separation residual (gap(c) - gap(a))/h - 1 = abar^2 f1 + kappa abar f2 - 1 at the
    # given abar, in the scaled form (Y = abar e^u / 2)
    Y = abar * np.exp(_minimum(u, 700.0)) / 2
    res = abs(Y * Y * bp["F1"] + kap * Y * bp["F2"] - 1)
    return u, res, it, bp


def _u_of_abar(
    abar: NDArray, kap: NDArray, *, maxiter: int = 60
) -> tuple[NDArray, NDArray, NDArray]:
    """Solve abar(u; kappa) = abar for u by bracketed Newton in w = ln u.

    Returns (u, separation residual (gap at c minus h, over h), iterations used). Arrays of
    any shape (broadcast together) or scalars; each point stops as soon as it has converged.
    """
    with np.errstate(over="ignore", divide="ignore", invalid="ignore"):
        if _is_scalar(abar, kap):
            u, res, it, _ = _solve_abar(*_scalars(abar, kap), maxiter=maxiter)
            return u, res, it
        abar, kap = np.broadcast_arrays(np.asarray(abar, float), np.asarray(kap, float))
        shape = abar.shape
        u, res, it, _ = _solve_abar(abar.reshape(-1), kap.reshape(-1), maxiter=maxiter)
    return u.reshape(shape), res.reshape(shape), it.reshape(shape)


# --------------------------------------------------------------------------------------------
# the load minimum


_WS_LO = float(np.log(1e-10))  # bracket of _u_stationary in w = ln u: kappa_s(lo) > kappa
_WS_HI = float(np.log(1e9))


def _stationary_step(w, lo, hi, lk):
    """One bracketed Newton step of ln kappa_s(u) = ln kappa in w = ln u.

    With D = L^2 F1 + 2 L St F2 and kappa_s = 2 St / sqrt(D), the derivatives of the scaled
    pieces are St' = 2q, L' = St/Ct, F1' = 2 St^2 - 2 F1 and F2' = 2q (u + L).
    """
    u = np.exp(w)
    p = _scaled(u)
    q, St, L, F1, F2 = p["q"], p["St"], p["L"], p["F1"], p["F2"]
    LSt = L * St
    D = L * L * F1 + 2 * LSt * F2
    g = np.log(2 * St / np.sqrt(D)) - lk  # decreasing in w
    dL = St / p["Ct"]
    dD = (
        2 * L * dL * F1
        + L * L * (2 * St * St - 2 * F1)
        + 2 * (dL * St + 2 * q * L) * F2
        + 4 * LSt * q * (u + L)
    )
    dg = u * (2 * q / St - dD / (2 * D))
    lo = _where(g > 0, w, lo)
    hi = _where(g > 0, hi, w)
    w_new = w - g / dg
    bad = ~np.isfinite(w_new) | (w_new < lo) | (w_new > hi)
    w_new = _where(bad, 0.5 * (lo + hi), w_new)
    done = g == 0
    w_new = _where(done, w, w_new)
    # converged: a step at rounding level, or a bracket shrunk to nothing (a root beyond the
    # bracket's end, for kappa < 2e-9, leaves u at that end, as the bisection did)
    tiny = 1e-15 * np.maximum(1.0, np.abs(w))
    stop = done | (np.abs(w_new - w) <= tiny) | (hi - lo <= tiny)
    return (w_new, lo, hi), stop


def _u_stationary(kap: NDArray | np.float64) -> NDArray | np.float64:
    r"""The :math:`u` of the single load minimum for the group :math:`\kappa > 0`.

    :math:`\kappa_s(u)` (:func:`_kappa_stationary`) decreases from infinity (as
    :math:`2\sqrt2\, u^{-3/2}`) to zero (as :math:`2/\sqrt{u^2 - \ln^2 2}`): a bracketed Newton
    iteration in :math:`w = \ln u` on :math:`\ln\kappa_s = \ln\kappa` starts from these asymptotes
    and falls back on bisection whenever a step would leave the bracket. Arrays or scalars.
    """
    scalar = _is_scalar(kap)
    shape = np.shape(kap)
    kap = np.float64(kap) if scalar else np.asarray(kap, dtype=float).reshape(-1)
    with np.errstate(over="ignore", divide="ignore", invalid="ignore", under="ignore"):
        u_small = (2 * np.sqrt(2.0) / kap) ** (2 / 3)
        u_large = np.sqrt(4 / (kap * kap) + LN2 * LN2)
        u0 = _where(u_small < 1.0, u_small, u_large)
        w0 = np.minimum(np.maximum(np.log(u0), _WS_LO), _WS_HI)
        w = _stationary_plain(w0, np.log(kap))
        u = np.exp(w)
    return u if scalar else u.reshape(shape)


#: Plain Newton steps that :func:`_stationary_plain` takes on every point before it checks
#: them (from the asymptotes three steps reach rounding for every kappa of 1e-9 to 1e12,
#: the fourth is the check).
_FAST_STEPS = 4


def _plain_pieces(u: NDArray) -> tuple[NDArray, ...]:
    """``q``, ``St``, ``Ct``, ``L``, ``F1``, ``F2`` of :func:`_scaled` at the load minimum.

    In fewer operations than :func:`_scaled`: ``F1 = St Ct - 4 u q`` in closed form also
    below ``u = 1``, where it cancels (relative error ~1e-16 / u^2); at the load minimum
    it enters only with a weight ~u^2: against ``2 L St F2`` in ``D = L^2 F1 + 2 L St F2``
    (``L ~ u^2/2``, ``St ~ 2u``, ``F2 ~ u^2``), and against ``(kappa F2)^2`` in ``X``
    (:func:`_x_of_u`; ``kappa ~ 2 sqrt(2) u^(-3/2)`` there), so its error stays at rounding
    in both. Not for the contact branch at a given width, where ``F1`` may dominate.
    """
    q = np.exp(-2 * u)
    St = -np.expm1(-2 * u)
    Ct = 1 + q
    sh = np.sinh(0.5 * u)  # inf beyond u ~ 1420, where the other branch is taken
    L = _where(u < 1.0, np.log1p(2 * sh * sh), u + np.log1p(q) - LN2)
    F1 = St * Ct - 4 * u * q
    F2 = u * St - Ct * L
    return q, St, Ct, L, F1, F2


def _at_minimum(u, kap) -> tuple:
    """Abar, X, Ct and Phi = (2/pi) F/(Eh) at the load minimum ``u`` (see :func:`_branch_point`).

    By :func:`_plain_pieces`; flat arrays or NumPy scalars.
    """
    _, St, Ct, _, F1, F2 = _plain_pieces(u)
    kF2 = kap * F2
    X = 2.0 / (kF2 + np.sqrt(kF2 * kF2 + 4 * F1))
    Xe = X * np.exp(-u)
    return 2 * Xe, X, Ct, 4 * Xe * Xe - kap * X * St


def _stationary_newton(w: NDArray, lk: NDArray) -> tuple[NDArray, NDArray]:
    """One plain Newton step of ln kappa_s(u) = ln kappa in w = ln u (flat arrays or scalars).

    The step of :func:`_stationary_step` without its bracket, on pieces of fewer
    operations: ``F1 = St Ct - 4 u q`` in closed form also below ``u = 1``, where it cancels
    (relative error ~1e-16 / u^2) but enters ``D = L^2 F1 + 2 L St F2`` with the weight
    ~u^2 of ``L^2 F1`` against ``2 L St F2`` (``L ~ u^2/2``, ``St ~ 2u``, ``F2 ~ u^2``): its
    error in ``D`` stays at rounding. Returns the new ``w`` and the size of the step.
    """
    u = np.exp(w)
    q, St, Ct, L, F1, F2 = _plain_pieces(u)
    LSt = L * St
    D = L * L * F1 + 2 * LSt * F2
    g = np.log(2 * St / np.sqrt(D)) - lk
    dL = St / Ct
    dD = (
        2 * L * dL * F1
        + L * L * (2 * St * St - 2 * F1)
        + 2 * (dL * St + 2 * q * L) * F2
        + 4 * LSt * q * (u + L)
    )
    dw = g / (u * (2 * q / St - dD / (2 * D)))
    return w - dw, dw


def _stationary_plain(w0, lk):
    """W = ln u of the load minimum: plain Newton, checked, bracketed where it is not enough.

    Flat arrays or NumPy scalars (the same steps: a point alone and in a batch agree to
    rounding).

    :data:`_FAST_STEPS` plain steps (:func:`_stationary_newton`) on every point, with no
    bracket and no bookkeeping of which points are done; a point whose last step is at
    rounding (the criterion of :func:`_stationary_step`) has converged, and any other (a
    step that left the range, or Newton slower than quadratic there) is solved again from its
    start by the bracketed iteration of :func:`_stationary_step`.
    """
    w = w0
    for _ in range(_FAST_STEPS):
        w, dw = _stationary_newton(w, lk)
    ok = (abs(dw) <= 1e-15 * _maximum(1.0, abs(w))) & (w >= _WS_LO) & (w <= _WS_HI)
    if not isinstance(ok, np.ndarray):
        if not ok:
            lo, hi = _full(w0, _WS_LO), _full(w0, _WS_HI)
            (w, _, _), _ = _iterate(_stationary_step, (w0, lo, hi), (lk,), 100)
        return w
    if not ok.all():
        bad = ~ok
        w0b = w0[bad]
        lo, hi = np.full(w0b.shape, _WS_LO), np.full(w0b.shape, _WS_HI)
        (w[bad], _, _), _ = _iterate(_stationary_step, (w0b, lo, hi), (lk[bad],), 100)
    return w
