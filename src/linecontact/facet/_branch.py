r"""The Maugis--Dugdale branch of a faceted wire on its facet: the kernels, no checks.

Units: lengths over the circumradius :math:`R`, loads per unit length over :math:`E h`
(compressive positive), :math:`\rho = R/h`, :math:`s = \sigma_0/E`. The wire's profile
measured from the facet it lies on is flat for :math:`|x| \le f` and a parabolic corner of
radius :math:`r` beyond (``docs/faceted.md``, Sec. 1):

.. math::

    g(x) = \frac{(|x| - f)_+^2}{2 r}, \qquad f = (1 - r)\sin(\pi/n)

(``r`` over ``R``). For a contact :math:`|x| < a` and a Dugdale zone :math:`a < |x| < c`
the bounded solution gives the load and the separation at :math:`c` (``docs/faceted.md``,
Secs. 2--3), with :math:`\cos\alpha = f/a`, :math:`S = \sqrt{a^2 - f^2}`,
:math:`K = \sqrt{c^2 - a^2}`, :math:`u = \operatorname{arccosh}(c/a)`:

.. math::

    F = \frac{E}{2r}\,(a^2\alpha - f S) - 2\sigma_0 K, \qquad
    h = G(a, c) + \frac{4\sigma_0 a}{\pi E} f_2(u),

.. math::

    r\,G = \frac{2}{\pi}\Big[\frac{\alpha}{2}(cK - a^2 u)
        + \frac{c^2 + f^2}{2}\arctan\frac{fK}{Sc} - f c\arctan\frac{K}{S}
        + \frac{f S}{2}u\Big] \quad (a > f), \qquad
    r\,G = \tfrac12 (c - f)_+^2 \quad (a \le f),

:math:`f_2 = u\sinh u - \cosh u\ln\cosh u` as for the round wire (``f = 0``, ``r = 1``
gives the Maugis--Dugdale line contact of :mod:`linecontact.closed_forms.maugis_dugdale`
term by term). A sharp corner (``r = 0``) keeps the contact on the facet (:math:`a \le f`)
and stops the Dugdale zone at the corner: :math:`c = f` wherever the free zone would
reach beyond it (the *corner-pinned* states).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from .. import closed_forms as _cf

#: Below this ``u`` the closed form of ``G`` cancels (its O(u) terms sum to O(u^3)); it is
#: then integrated by Gauss--Legendre over ``v`` in ``[0, u]`` (an analytic integrand).
_U_QUADRATURE = 0.3
_GL_X, _GL_W = np.polynomial.legendre.leggauss(24)
#: The Newton steps of :func:`solve_u` before it bisects every other step.
_NEWTON_STEPS = 40


def facet_half_width(sides: NDArray, r: NDArray) -> NDArray:
    """The flat half-width ``f = (1 - r) sin(pi/n)`` of the facet, over the circumradius."""
    return (1.0 - r) * np.sin(np.pi / sides)


def _edge(A: NDArray, f: NDArray) -> tuple[NDArray, NDArray]:
    """``S = sqrt(a^2 - f^2)``, ``alpha = arccos(f/a)`` (0 for ``a <= f``), exact near ``a = f``.

    ``(a - f)(a + f)`` and ``arctan2(S, f)``: ``arccos`` of the rounded ``f/a`` loses all of
    ``alpha`` within an ulp or two of the edge (``1 - f/a`` below the rounding of ``f/a``).
    """
    S = np.sqrt(np.maximum((A - f) * (A + f), 0.0))
    return S, np.arctan2(S, f)


def _x_minus_sin(x: NDArray) -> NDArray:
    """``x - sin x`` for ``x >= 0``, by its series below 0.2 (where the difference cancels)."""
    x2 = x * x
    series = (
        x * x2 / 6 * (1 - x2 / 20 * (1 - x2 / 42 * (1 - x2 / 72 * (1 - x2 / 110 * (1 - x2 / 156)))))
    )
    return np.where(x < 0.2, series, x - np.sin(x))


def _f2(u: NDArray) -> tuple[NDArray, dict[str, NDArray]]:
    """``f2(u) / cosh u`` (so that ``a f2 = c f2 / cosh u`` cannot overflow) and the pieces."""
    p = _cf._scaled(u)
    return p["F2"] / p["Ct"], p


def slope(x: NDArray, A: NDArray, f: NDArray, r: NDArray) -> NDArray:
    """The separation's slope at ``x > a > f`` from the profile (no Dugdale part), times ``r``."""
    k = np.sqrt(np.maximum(x * x - A * A, 0.0))
    S, al = _edge(A, f)
    return (2 / np.pi) * (k * al + x * np.arctan2(k * f, x * S) - f * np.arctan2(k, S))


def profile_gap(A: NDArray, C: NDArray, u: NDArray, f: NDArray, r: NDArray) -> NDArray:
    """``r G(a, c)``: the profile's part of the separation at ``c`` (times ``r``)."""
    on = A > f
    flat = 0.5 * np.maximum(C - f, 0.0) ** 2
    if not np.any(on):
        return flat
    K = A * np.sinh(u)
    S, al = _edge(A, f)
    closed = (2 / np.pi) * (
        0.5 * al * (C * K - A * A * u)
        + 0.5 * (C * C + f * f) * np.arctan2(f * K, S * C)
        - f * C * np.arctan2(K, S)
        + 0.5 * f * S * u
    )
    small = on & (u < _U_QUADRATURE)
    if np.any(small):
        # G = int_0^u slope(a cosh v) a sinh v dv, Gauss--Legendre on [0, u]
        v = 0.5 * u[..., None] * (_GL_X + 1.0)
        Ab, fb, rb = A[..., None], f[..., None], r[..., None]
        integrand = slope(Ab * np.cosh(v), Ab, fb, rb) * Ab * np.sinh(v)
        quad = 0.5 * u * np.einsum("...k,k->...", integrand, _GL_W)
        closed = np.where(small, quad, closed)
    return np.where(on, closed, flat)


def hertz_load(A: NDArray, f: NDArray, r: NDArray) -> NDArray:
    """``r P_H / (E R)``: the load of the bounded solution without adhesion (times ``r``)."""
    # a^2 alpha - f S = a^2 (2 alpha - sin 2 alpha) / 2 (f = a cos alpha, S = a sin alpha),
    # which cancels to O(alpha^3) just past the facet's edge
    _, al = _edge(A, f)
    return np.where(A > f, 0.25 * A * A * _x_minus_sin(2.0 * al), 0.0)


def _residual(A, u, f, r, rho, s):
    """``ln`` of the separation at ``c`` over ``h`` and its derivative in ``u``."""
    C = A * np.cosh(u)
    sh = np.sinh(u)
    aF2, p = _f2(u)
    af2 = C * aF2  # a f2(u), overflow-free
    ln_cosh = p["L"]
    df2 = u * np.cosh(u) - sh * ln_cosh
    sharp = r == 0
    rs = np.where(sharp, 1.0, r)
    G = profile_gap(A, C, u, f, rs) / rs
    on = A > f
    dG = np.where(
        on,
        slope(C, A, f, rs) / rs,
        np.maximum(C - f, 0.0) / rs,
    )
    G = np.where(sharp, 0.0, G)
    dG = np.where(sharp, 0.0, dG)
    coef = (4 / np.pi) * s * rho
    sep = rho * G + coef * af2  # the separation at c over h
    dsep = rho * dG * A * sh + coef * A * df2
    # in logarithms: the separation grows like e^{2u} at large u, its log like 2u
    return np.log(sep), dsep / sep


def solve_u(
    A: NDArray,
    f: NDArray,
    r: NDArray,
    rho: NDArray,
    s: NDArray,
    u0: NDArray | None = None,
    maxiter: int = 400,
):
    """``u = arccosh(c/a)`` on the branch at ``a`` (flat arrays, ``s > 0``) and the residual.

    A bracketed Newton iteration in ``t = ln sinh u`` on the logarithm of the separation
    over ``h``, increasing in ``t``: the separation grows like ``u^2`` for a thin zone and
    like ``e^u`` or ``e^{2u}`` for a wide one, so the logarithm is nearly linear in ``t`` at
    both ends. The residual returned is that logarithm. Where a sharp corner stops the Dugdale
    zone, ``u`` is that of ``c = f``. ``u0``: a starting point (a neighbour's ``u``).
    """
    P = A.size
    lo = np.full(P, -np.inf)
    hi = np.full(P, np.inf)
    start = np.ones(P) if u0 is None else np.where(np.isfinite(u0) & (u0 > 0), u0, 1.0)
    t = np.log(np.sinh(start))
    res = np.full(P, np.inf)
    active = np.ones(P, bool)
    # a sharp corner: the zone stops at c = f where the separation there is below h (the
    # free zone would pass the corner, for a weak adhesion far past it: no iteration then)
    sharp = (r == 0) & (A <= f)
    uf = np.arccosh(np.maximum(f / np.where(A > 0, A, 1.0), 1.0))
    pinned = np.zeros(P, bool)
    if np.any(sharp):
        k = np.nonzero(sharp)[0]
        with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
            Phi_f = _residual(A[k], uf[k], f[k], r[k], rho[k], s[k])[0]
        pinned[k] = (uf[k] == 0) | (Phi_f <= 0)
        active &= ~pinned
    for it in range(maxiter):
        idx = np.nonzero(active)[0]
        if idx.size == 0:
            break
        ti = t[idx]
        with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
            ui = np.arcsinh(np.exp(ti))
            Phi, dPhi = _residual(A[idx], ui, f[idx], r[idx], rho[idx], s[idx])
            dPhi = dPhi * np.tanh(ui)
        Phi = np.where(np.isnan(Phi), np.inf, Phi)
        res[idx] = Phi
        lo[idx] = np.where(Phi < 0, ti, lo[idx])
        hi[idx] = np.where(Phi >= 0, ti, hi[idx])
        with np.errstate(divide="ignore", invalid="ignore"):
            tn = ti - Phi / dPhi
        # a Newton step of 1e-14 ends it: the next is below the rounding of the residual
        # (the step's test only near the root: where the separation jumps by orders, at a
        # corner far sharper than h, a tiny step is no convergence; the bracket closes there)
        done = (np.abs(Phi) <= 2e-16) | (
            np.isfinite(tn)
            & (np.abs(tn - ti) <= 1e-14 * np.maximum(1.0, np.abs(ti)))
            & (np.abs(Phi) <= 1e-6)
        )
        closed = np.isfinite(lo[idx]) & np.isfinite(hi[idx])
        done |= closed & (hi[idx] - lo[idx] <= 1e-15 * np.maximum(1.0, np.abs(ti)))
        mid = np.where(closed, 0.5 * (lo[idx] + hi[idx]), np.where(Phi < 0, ti + 2.0, ti - 2.0))
        bad = ~np.isfinite(tn) | (tn < lo[idx]) | (tn > hi[idx])
        # every fourth step a bisection of a closed bracket: Newton crawls where the
        # separation's slope jumps (where the zone reaches a corner, c = f); past
        # _NEWTON_STEPS every other step, whatever the residual: there Newton wanders in the
        # residual's rounding noise (a zone ending just past a corner, c - f << f, or a
        # contact just past the facet's edge, a - f << f) and the bracket must close
        bisect = np.where(it < _NEWTON_STEPS, (it % 4 == 3) & (np.abs(Phi) > 1e-8), it % 2 == 1)
        bad |= closed & bisect
        tn = np.where(bad, mid, tn)
        t[idx] = np.where(done, ti, tn)
        active[idx] = ~done
    with np.errstate(over="ignore"):  # t -> inf: a zone unbounded but for a sharp corner
        u = np.arcsinh(np.exp(t))
    # (and where the iteration passed it)
    pinned |= sharp & (u > uf)
    u = np.where(pinned, uf, u)
    res = np.where(pinned, 0.0, res)
    return u, np.abs(res), ~active | pinned, pinned


def load(A: NDArray, u: NDArray, f: NDArray, r: NDArray, rho: NDArray, s: NDArray) -> NDArray:
    """``F / (E h)`` on the branch at ``(a, u)``."""
    rs = np.where(r == 0, 1.0, r)
    PH = np.where(r == 0, 0.0, hertz_load(A, f, rs) / rs)
    return rho * (PH - 2.0 * s * A * np.sinh(u))
