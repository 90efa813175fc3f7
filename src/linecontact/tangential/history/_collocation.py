"""The incremental solver: the stick condition solved step by step by collocation.

``method="incremental"`` of :func:`~linecontact.tangential.history.tangential_history`: at
each step the stick zone :math:`|x| < c` keeps its relative displacement, the traction in the
slip zones is the friction stress in the step's direction, and ``c`` is the root of the
force balance. It knows no superposition rule and no memory rule.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ...sie import _log_moment_vector as _log_moments
from .._core import _solver
from ._laws import _Law

#: Collocation nodes the incremental solver starts each step with (it doubles them until
#: the Chebyshev tail of the step's solution is at round-off).
N_INCREMENTAL = 64
#: The largest size the incremental solver doubles to: a reversal by a fraction ``r`` of
#: the full-slip load puts the new stick zone within :math:`\approx r^2/8` of the edge, whose
#: logarithmic source then needs :math:`\approx 70/r` nodes (``docs/load-histories.md``).
N_MAX_INCREMENTAL = 4096
_N_GAUSS = 16  # Gauss-Legendre nodes per piece of the slip annulus (friction work)


@dataclass(frozen=True)
class _Incremental:
    r"""States :math:`q = s B(x) + \sum_k \psi_k(x)`, :math:`\psi_k` bounded on :math:`|x| < c_k`.

    :math:`\psi_k(x) = \sqrt{1 - t^2} \sum_j b_{kj} U_j(t)`, :math:`t = x/c_k`; per step, a tuple of
    ``(c_k, b_k)`` (nested intervals, the step's own stick zone last).
    """

    law: _Law
    sign: NDArray  # (steps,)
    parts: tuple  # per step: tuple of (c_k, b_k)

    def _each(self, steps: NDArray, fn) -> NDArray:
        return np.stack([fn(self.sign[j], self.parts[j]) for j in steps.reshape(-1)]).reshape(
            steps.shape + (-1,)
        )

    def traction(self, x: NDArray, steps: NDArray) -> NDArray:
        law = self.law

        xc = np.clip(x, -2.0, 2.0)  # zero beyond the contact; no overflow

        def one(s, parts):
            q = s * np.where(np.abs(xc) <= 1.0, law.B(np.clip(xc, -1.0, 1.0)), 0.0)
            return q + sum((_psi(b, c, xc) for c, b in parts), np.zeros_like(xc))

        return self._each(steps, one)

    def slip(self, x: NDArray, steps: NDArray) -> NDArray:
        law = self.law
        x0 = np.zeros(1)

        xc = np.clip(x, -2.0, 2.0)

        def one(s, parts):
            el = _el(law, s, parts, xc) - _el(law, s, parts, x0)
            return np.where(np.abs(x) > 1.0, np.nan, el)

        return self._each(steps, one)

    def displacement(self) -> NDArray:
        """D/a with the datum a: minus the relative displacement at the centre."""
        x0 = np.zeros(1)
        return np.array(
            [-_el(self.law, s, p, x0)[0] for s, p in zip(self.sign, self.parts, strict=True)]
        )


def _psi(b: NDArray, c: float, x: NDArray) -> NDArray:
    """psi(x) = sqrt(1 - t^2) sum_j b_j U_j(t) = sum_j b_j sin((j + 1) theta), t = x/c."""
    t = x / c
    th = np.arccos(np.clip(t, -1.0, 1.0))
    val = np.sin(np.arange(1, b.size + 1) * th[..., None]) @ b
    return np.where(np.abs(t) < 1.0, val, 0.0)


def _h_psi(b: NDArray, c: float, x: NDArray) -> NDArray:
    r"""The Hilbert transform of :math:`\psi`, inside and outside its interval.

    :math:`\frac1\pi \mathrm{PV}\!\int \frac{\psi(\xi)}{\xi - x} d\xi = -\sum_j b_j e_{j+1}(x/c)`.

    :math:`e_k = T_k(y)` inside (Clenshaw), :math:`e_k = \rho^k` with
    :math:`\rho = \operatorname{sign}(y)/(|y| + \sqrt{y^2 - 1})` outside (Horner): O(n) vector
    operations.
    """
    y = np.asarray(x, float) / c
    inside = np.abs(y) <= 1.0
    coef = np.concatenate([[0.0], b])
    out = np.empty_like(y)
    out[inside] = -np.polynomial.chebyshev.chebval(y[inside], coef)
    yo = y[~inside]
    rho = np.sign(yo) / (np.abs(yo) + np.sqrt((np.abs(yo) - 1) * (np.abs(yo) + 1)))
    out[~inside] = -np.polynomial.polynomial.polyval(rho, coef)
    return out


def _el(law: _Law, s: float, parts, x: NDArray) -> NDArray:
    """(2/pi) int q(xi) ln|x - xi| dxi: the relative displacement up to a constant."""
    out = s * law.logB(np.clip(x, -1e6, 1e6))
    for c, b in parts:
        out = out + c * (_log_moments(x / c, b.size) @ b + math.log(c) * (np.pi / 2) * b[0])
    return (2 / np.pi) * out


def _graded(cut: list[float]) -> list[tuple[float, float]]:
    r"""Pieces between the cuts, each graded geometrically towards both of its ends.

    The slips have algebraic-logarithmic end behaviour (:math:`(1 - x) \ln(1 - x)` at the
    contact edge, :math:`(x - c)^{3/2}` where a stick zone ended): halving the pieces towards
    the ends keeps the Gauss--Legendre error of each at round-off.
    """
    out: list[tuple[float, float]] = []
    for lo, hi in zip(cut, cut[1:], strict=False):
        mid = (lo + hi) / 2
        half = (hi - lo) / 2
        left = [lo + half * 0.5**k for k in range(30, 0, -1)]
        right = [hi - half * 0.5**k for k in range(1, 31)]
        edges = [lo, *left, mid, *right, hi]
        out += [(a, b) for a, b in zip(edges, edges[1:], strict=False) if b > a]
    return out


def _size_for(c: float, nn: int, sizes: list[int], at_least: int = 0) -> int:
    r"""The next size for a stick zone :math:`|x| < c`: at least twice ``nn``, or ``at_least``.

    A reversal's log sources sit at :math:`x = \pm a`, :math:`t = \pm a/c`: the coefficients fall
    like :math:`\exp(-k \operatorname{arccosh}(1/c))`, so about
    :math:`40/\operatorname{arccosh}(1/c)` of them reach round-off.
    """
    rate = math.acosh(1.0 / c) if 0 < c < 1 else 1.0
    need = max(40.0 / max(rate, 1e-300), at_least or 2 * nn)
    return next((m for m in sizes if m >= need), sizes[-1])


def _root(force, nn: int, guess: float) -> float:
    """The stick-zone half-width where ``force(c, nn)`` vanishes, in ``(0, 1]``.

    Bracketed near ``guess`` (the root at a coarser size: ``1 - c`` changes by a small
    factor between sizes) when it brackets, else on the whole interval.
    """
    from scipy.optimize import brentq

    kw = dict(args=(nn,), xtol=1e-16, rtol=1e-15, maxiter=300)
    if 0 < guess < 1:
        u = 1.0 - guess
        lo, hi = max(1.0 - 4 * u, 1e-300), 1.0 - u / 4
        f_lo, f_hi = force(lo, nn), force(hi, nn)
        if f_lo * f_hi < 0:
            return float(brentq(force, lo, hi, **kw))
    return float(brentq(force, 1e-300, 1.0, **kw))


def _incremental(
    law: _Law, loads: NDArray, n: int, stop_tol: float | None = None
) -> dict[str, Any]:
    r"""Solve the stick condition at each step from the previous state (no memory rule).

    Step ``j`` moves the load monotonically to ``T_j``, in the direction ``s``. Unknown:
    the stick zone :math:`|x| < c` and the traction there. Outside it the traction is :math:`s B`,
    so every part of the previous state that reaches beyond ``c`` is replaced; the new
    part :math:`\phi` on :math:`|x| < c` keeps the relative displacement of the stick zone:
    :math:`H\phi = (s_\text{prev} - s) HB + \sum H\psi_k` over the replaced parts on :math:`|x| < c`
    (smooth: each replaced part is evaluated inside its own interval), bounded at :math:`\pm c`.
    ``c`` is the root of the force balance.

    With ``stop_tol``, the solve stops after the first step that misses it (its error
    estimate or a residual above it, as the caller's ``tol``): the steps after it are
    left unsolved, for a caller that raises on that step.
    """
    check_t = np.cos(np.pi * (np.arange(16) + 0.25) / 16)
    gl_x, gl_w = np.polynomial.legendre.leggauss(_N_GAUSS)
    steps = loads.size
    Tf = law.T_full
    sign = np.zeros(steps)
    c_out = np.ones(steps)
    parts_out: list[tuple[tuple[float, NDArray], ...]] = []
    direction = np.zeros(steps, int)
    sliding = np.zeros(steps, bool)
    loss = np.zeros(steps)
    res_stick = np.zeros(steps)
    res_adm = np.zeros(steps)
    tail = np.zeros(steps)
    n_used = np.zeros(steps, int)
    s_prev, r_prev, d_prev = 0.0, 0.0, 0
    parts_prev: tuple[tuple[float, NDArray], ...] = ()
    sizes = [n]
    while sizes[-1] < N_MAX_INCREMENTAL:
        sizes.append(min(2 * sizes[-1], N_MAX_INCREMENTAL))

    def split(cc):
        keep = tuple(p for p in parts_prev if p[0] <= cc)
        gone = tuple(p for p in parts_prev if p[0] > cc)
        return keep, gone

    def rhs(cc, s, x):
        _, gone = split(cc)
        f = (s_prev - s) * law.HB(x)
        for c, b in gone:
            f = f + _h_psi(b, c, x)
        return f

    def solve(cc, s, nn):
        t = _solver(nn).collocation_unit
        return _solver(nn).solve(rhs(cc, s, cc * t), values=False).coefficients

    for j, r in enumerate(loads.tolist()):
        if r == r_prev:
            sign[j], c_out[j] = s_prev, c_out[j - 1] if j else 1.0
            parts_out.append(parts_prev)
            direction[j] = d_prev
            sliding[j] = sliding[j - 1] if j else False
            n_used[j] = n_used[j - 1] if j else 0
            loss[j] = math.nan if sliding[j] else 0.0
            continue
        s = 1.0 if r > r_prev else -1.0
        target = r * Tf
        resultant = [(np.pi / 2) * c * b[0] for c, b in parts_prev]
        T_prev = s_prev * Tf + sum(resultant, 0.0)

        def force(cc, nn, s=s, target=target, resultant=resultant, T_prev=T_prev, pp=parts_prev):
            if cc >= 1.0:
                return T_prev - target  # full stick: nothing changes
            kept = zip(resultant, pp, strict=True)
            keep = sum((f for f, p in kept if p[0] <= cc), 0.0)
            return s * Tf + keep + cc * (np.pi / 2) * solve(cc, s, nn)[0] - target

        slid = abs(r) >= 1.0 and np.sign(r) == s
        parts: tuple[tuple[float, NDArray], ...]
        if slid:
            cj, parts = 0.0, ()
        else:
            nn, cj = sizes[0], math.nan
            while True:
                cj = _root(force, nn, cj)
                bj = solve(cj, s, nn)
                tail[j] = float(np.max(np.abs(bj[-3:])) / max(np.max(np.abs(bj)), 1.0))
                if tail[j] <= 1e-15 or nn >= sizes[-1]:
                    break
                nn = _size_for(cj, nn, sizes)
            # at the closure of a loop the force is flat between the older branch's stick
            # zone and this one's: take the largest root (not slipped in this step). Each
            # edge is tried at the size its own closeness to the contact edge needs.
            for edge in sorted(p[0] for p in parts_prev if cj < p[0] < 1.0):
                n_edge = _size_for(edge, nn, sizes, at_least=nn)
                if abs(force(edge, n_edge)) > 1e-13 * Tf:
                    break
                cj, nn = edge, n_edge
                bj = solve(cj, s, nn)
                tail[j] = float(np.max(np.abs(bj[-3:])) / max(np.max(np.abs(bj)), 1.0))
            n_used[j] = nn
            keep, _ = split(cj)
            parts = (*keep, (cj, bj))
            xc = cj * check_t
            check_T = np.cos(np.arange(1, nn + 1)[None, :] * np.arccos(check_t)[:, None])
            res_stick[j] = float(np.max(np.abs(-(check_T @ bj) - rhs(cj, s, xc))))
        # the friction work in the slip annulus c_j < |x| < 1 (both sides: twice), split at
        # the ends of the parts, where the slips have their kinks
        cut = sorted({cj, 1.0} | {c for c, _ in (*parts_prev, *parts) if cj < c < 1.0})
        # The work density is B |ds| (the slip runs along the friction, s ds >= 0): a slip
        # against it is a violation of the friction law (measured in viol), not negative
        # work, so the loss is never negative (round-off made it -5.6e-38 at 1e-12 of full
        # slip, Coulomb friction)
        w = 0.0
        viol = 0.0
        x0 = np.zeros(1)
        el_new0, el_old0 = _el(law, s, parts, x0), _el(law, s_prev, parts_prev, x0)
        for lo, hi in _graded(cut):
            xg = lo + (hi - lo) * (gl_x + 1) / 2
            wg = (hi - lo) / 2 * gl_w
            el_new, el_old = _el(law, s, parts, xg), _el(law, s_prev, parts_prev, xg)
            ds = (el_new - el_new0) - (el_old - el_old0)
            w += 2 * float(np.sum(wg * law.B(xg) * np.maximum(s * ds, 0.0)))
            viol = max(viol, float(np.max(-s * ds, initial=0.0)))
        if cj > 0:
            # the traction in the stick zone must not exceed the friction law
            xs = cj * np.cos(np.pi * (np.arange(64) + 0.5) / 64)
            q = s * law.B(xs) + sum((_psi(b, c, xs) for c, b in parts), np.zeros_like(xs))
            viol = max(viol, float(np.max(np.abs(q) - law.B(xs), initial=0.0)))
        sign[j], c_out[j] = s, cj
        parts_out.append(parts)
        direction[j] = int(s)
        sliding[j] = slid
        loss[j] = math.nan if slid else w
        res_adm[j] = viol
        s_prev, parts_prev, d_prev = s, parts, int(s)
        r_prev = math.copysign(1.0, r) if slid else r
        if stop_tol is not None and not (
            tail[j] <= stop_tol and max(res_stick[j], res_adm[j]) <= max(stop_tol, 1e-10)
        ):
            break
    return dict(
        sign=sign,
        c=c_out,
        parts=tuple(parts_out),
        direction=direction,
        sliding=sliding,
        loss=loss,
        residual_stick=res_stick,
        residual_admissible=res_adm,
        error_estimate=tail,
        n_collocation=n_used,
    )
