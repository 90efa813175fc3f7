r"""The Maugis--Dugdale sphere in the groups: the adhesive zone, the load and the approach.

Maugis (1992) wrote the Dugdale sphere in units of :math:`\pi w R` and
:math:`(\pi w R^2/K)^{1/3}`; here the same equations are in the library's groups, so that
no cube root of ``w`` enters and Hertz (``sigma0 = 0``) is a point of the family. With
:math:`\alpha = a/R`, :math:`x = c/R`, :math:`q = \sqrt{x^2 - \alpha^2}`,
:math:`\theta = \arctan(q/\alpha)`, :math:`\rho = R/h`, :math:`s = \sigma_0/E`
(``docs/sphere.md``):

- the gap at ``c`` is ``h`` (Maugis' Eq. 6.17):

  .. math:: \frac{\rho}{\pi}\left[\alpha q + (q^2 - \alpha^2)\theta\right]
            + \frac{4 s\rho}{\pi}\left[q\theta - x + \alpha\right] = 1,

- the load (Eq. 6.18), :math:`F/(E h R) = \tfrac43\rho\alpha^3 - 2 s\rho(\alpha q + x^2\theta)`,
- the approach (Eq. 6.19), :math:`\delta/h = \rho\alpha^2 - 2 s\rho q`.

Out of contact (``a = 0``, the gap ``g0`` at the centre), the zone's radius solves
:math:`\rho x^2/2 + 2(1 - 2/\pi) s\rho x = 1 - g_0/h`, the load is
:math:`-\pi s\rho x^2` and the approach :math:`-g_0/h - 2 s\rho x`: at ``g0 = 0`` the
contact branch's ``a -> 0`` end.

The left side of the gap condition increases with ``q`` (each bracket does), from ``-1`` at
``q = 0``: one root, found by Newton's method on its logarithm (bracketed), a few steps from
anywhere. Each difference that would cancel is written without it (``t - atan t`` by its
series, ``x - alpha = q^2/(x + alpha)``).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

#: Below it, ``t - atan t`` is summed from its series (15 terms: to rounding).
_SERIES = 0.25
_TERMS = 15


def _t_minus_atan(t: NDArray) -> NDArray:
    r""":math:`t - \arctan t` without cancellation (``t >= 0``)."""
    small = t < _SERIES
    ts = np.where(small, t, 0.0)
    t2 = ts * ts
    acc = np.zeros_like(ts)
    for j in range(_TERMS - 1, -1, -1):  # t^3 (1/3 - t^2 (1/5 - t^2 (1/7 - ...)))
        acc = 1 / (2 * j + 3) - t2 * acc
    series = acc * t2 * ts
    with np.errstate(invalid="ignore", over="ignore"):
        direct = t - np.arctan(t)
    return np.where(small, series, direct)


def _angles(alpha: NDArray, q: NDArray) -> tuple[NDArray, NDArray]:
    """``theta = atan(q/alpha)`` and ``x = sqrt(alpha^2 + q^2)``."""
    return np.arctan2(q, alpha), np.hypot(alpha, q)


def _brackets(alpha: NDArray, q: NDArray) -> tuple[NDArray, NDArray, NDArray, NDArray]:
    """The two brackets of the gap condition, ``A1``, ``A2``, and their ``q``-derivatives."""
    theta, x = _angles(alpha, q)
    with np.errstate(divide="ignore", invalid="ignore"):
        t = q / alpha
        near = alpha * alpha * _t_minus_atan(np.where(q < alpha, t, 0.0))
    # alpha q - alpha^2 theta: by the series where q < alpha (t < 1), directly beyond
    head = np.where(q < alpha, near, alpha * q - alpha * alpha * theta)
    A1 = head + q * q * theta
    A2 = q * theta - q * q / (x + alpha)
    with np.errstate(divide="ignore", invalid="ignore"):
        x2 = x * x
        dA1 = np.where(x2 > 0, 2 * q * theta + 2 * alpha * q * q / x2, 0.0)
        dA2 = np.where(x2 > 0, theta + q * alpha / x2 - q / x, 0.0)
    return A1, A2, dA1, dA2


def zone(alpha: NDArray, rho: NDArray, s: NDArray) -> tuple[NDArray, NDArray]:
    r"""``q`` of the gap condition at each point, and its residual (log of the left + 1).

    Newton's method on :math:`L(v) = \ln((\rho/\pi) A_1 + (4 s\rho/\pi) A_2)`,
    :math:`v = \ln q`: close to a log-sum of powers of ``q``, convex and increasing, so
    that its steps converge from anywhere in a few; a bracket that bisection keeps guards
    them. A point stops one step after its step falls below 1e-12 (quadratic convergence:
    then to rounding).
    """
    alpha, rho, s = np.broadcast_arrays(*(np.asarray(v, float) for v in (alpha, rho, s)))
    shape = alpha.shape
    alpha, rho, s = alpha.reshape(-1), rho.reshape(-1), s.reshape(-1)
    k1 = rho / np.pi
    k2 = 4 * s * rho / np.pi
    # an upper end where the left side is >= 0: q >= alpha and rho q^2/4 >= 1
    v_hi = np.log(np.maximum(alpha, 2 / np.sqrt(rho)))
    v_lo = np.full(alpha.shape, -800.0)  # q = 0 to rounding
    v = np.minimum(np.log(np.sqrt(2 / rho)), v_hi)  # the root at alpha = 0, s = 0
    last = np.zeros(alpha.shape, bool)
    act = np.arange(alpha.size)
    for _ in range(100):
        al, vv = alpha[act], v[act]
        q = np.exp(vv)
        A1, A2, dA1, dA2 = _brackets(al, q)
        total = k1[act] * A1 + k2[act] * A2
        with np.errstate(divide="ignore", invalid="ignore"):
            L = np.log(total)
            step = L / (q * (k1[act] * dA1 + k2[act] * dA2) / total)
        above = L > 0
        hi = np.where(above, np.minimum(v_hi[act], vv), v_hi[act])
        lo = np.where(above, v_lo[act], np.maximum(v_lo[act], vv))
        new = vv - step
        bad = ~np.isfinite(new) | (new < lo) | (new > hi)  # on an end: a step to rounding
        new = np.where(bad, 0.5 * (lo + hi), new)
        v[act], v_hi[act], v_lo[act] = new, hi, lo
        small = ~bad & (np.abs(step) <= 1e-12 * np.maximum(1.0, np.abs(vv)))
        stop = last[act] | (hi - lo <= 1e-15 * np.maximum(1.0, np.abs(vv)))
        last[act] = small
        act = act[~stop]
        if act.size == 0:
            break
    q = np.exp(v)
    A1, A2, _, _ = _brackets(alpha, q)
    with np.errstate(divide="ignore"):
        res = np.log(k1 * A1 + k2 * A2)
    return q.reshape(shape), res.reshape(shape)


def branch(alpha, rho, s) -> tuple[NDArray, NDArray, NDArray, NDArray, NDArray]:
    """``(c/R, F/(E h R), delta/h, q, residual)`` of the contact branch at ``a/R = alpha``."""
    alpha, rho, s = np.broadcast_arrays(*(np.asarray(v, float) for v in (alpha, rho, s)))
    q, res = zone(alpha, rho, s)
    theta, x = _angles(alpha, q)
    F = (4 / 3) * rho * alpha**3 - 2 * s * rho * (alpha * q + x * x * theta)
    delta = rho * alpha * alpha - 2 * s * rho * q
    return x, F, delta, q, res


def slopes(alpha, rho, s, q) -> tuple[NDArray, NDArray]:
    """``dF/d alpha`` and ``d delta/d alpha`` along the branch (``q`` its zone there)."""
    theta, x = _angles(alpha, q)
    _, _, dA1, dA2 = _brackets(alpha, q)
    k1, k2 = rho / np.pi, 4 * s * rho / np.pi
    with np.errstate(divide="ignore", invalid="ignore"):
        u = 2 * theta
        # dA1/d alpha = -alpha (2 theta - sin 2 theta), dA2/d alpha = -(alpha/x) q^2/(x (x + alpha))
        u_minus_sin = np.where(u < 0.5, _u_minus_sin(u), u - np.sin(u))
        Ha = k1 * (-alpha * u_minus_sin) + k2 * (-(alpha / x) * q * q / (x * (x + alpha)))
        Hq = k1 * dA1 + k2 * dA2
        dq = -Ha / Hq
    dF = (
        4 * alpha * alpha * rho
        - 4 * s * rho * alpha * theta
        - 4 * s * rho * (alpha + q * theta) * dq
    )
    dD = 2 * alpha * rho - 2 * s * rho * dq
    return dF, dD


def _u_minus_sin(u: NDArray) -> NDArray:
    r""":math:`u - \sin u` by its series (``u < 1/2``: 10 terms)."""
    u2 = u * u
    acc = np.zeros_like(u)
    fact = [6.0]
    for k in range(2, 11):
        fact.append(fact[-1] * (2 * k) * (2 * k + 1))
    for k in range(10, 0, -1):
        acc = 1 / fact[k - 1] - u2 * acc
    return acc * u2 * u


def separated(gap, rho, s) -> tuple[NDArray, NDArray, NDArray]:
    """``(c/R, F/(E h R), delta/h)`` out of contact, at the central gap over ``h``."""
    gap, rho, s = np.broadcast_arrays(*(np.asarray(v, float) for v in (gap, rho, s)))
    b = 2 * (1 - 2 / np.pi) * s * rho  # rho x^2/2 + b x = 1 - g: the root without cancellation
    rhs = 1 - gap
    x = 2 * rhs / (b + np.sqrt(b * b + 2 * rho * rhs))
    return x, -np.pi * s * rho * x * x, -gap - 2 * s * rho * x
