r"""Tangential load histories with memory: reversals, hysteresis loops, the loss per cycle.

A tangential force ``T(t)`` varies back and forth on a contact of fixed half-width ``a``
(from the normal problem; ``B = 0``, so ``T`` does not change the pressure). The slip zones
remember the path: a reversal starts new slip zones at the edges while the old ones freeze
with their slip locked in. Two friction laws, as for the initiation of sliding
(:mod:`linecontact.tangential.initiation`): the constant friction stress ``tau0`` (the
paper's nano-scale law) and Coulomb friction on the Hertz contact.

Two solvers that share nothing but the problem:

* ``method="closed-form"``: the Masing (Mindlin--Deresiewicz) memory rules. After a
  reversal at ``T_m`` the change of the state is the monotone solution for twice the
  friction stress under the load change ``T - T_m`` (the problem is linear in the friction
  stress), so every state is a sum of monotone solutions over a stack of turning points; a
  branch that passes its predecessor's turning point closes a loop and erases both
  (``docs/load-histories.md``). Closed forms for every term (traction, slip, displacement,
  energy dissipated).
* ``method="incremental"``: at each step the stick condition is solved directly with the
  Gauss--Chebyshev collocation of :class:`linecontact.sie.BoundedSolver`, from the previous
  traction: the traction in the slip zones is the friction stress in the step's direction,
  the stick zone ``|x| < c`` keeps its relative displacement, and ``c`` is the root of the
  force balance. It knows no superposition rule and no memory rule.

Units: lengths over ``a``, forces per unit length over ``E a``, stresses over ``E``, slips
and displacements over ``a``, energies per unit length over ``E a^2``; for Coulomb friction
loads also over ``mu F``, with :math:`p_0 = E a/(2R)`.

Conventions: ``T`` is the force on the cylinder along ``+x`` (either sign), the traction is
the one the cylinder exerts on the substrate (its integral is ``T``). The **slip**
``s(x)`` is the tangential displacement of the cylinder's surface point relative to the
substrate's, minus that at the centre ``x = 0`` (which never slips before gross sliding):
well defined at every step, even after a slide. The **displacement** ``D`` of the cylinder
relative to the substrate carries the datum of plane strain (remote points move by
``T/(pi E) ln(rho)`` for a datum depth ``rho``); the one reported takes ``rho = a``. The
datum adds ``kappa T`` to ``D``, which adds :math:`\kappa\oint T\,dT = 0` to a loop's area:
the energy dissipated does not depend on it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any, ClassVar

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import domain as _domain
from .._validation import RAISE, FailurePolicy, check_array, check_solver_options, failure_policy
from ..errors import ConvergenceError
from ..results import Result, as_output
from ..sie import _log_moment_vector as _log_moments
from ..sie import chebyshev_log_expansion
from ._core import _solver, _xlogy
from .initiation import _init_slip_closed

__all__ = [
    "CoulombCyclicLoss",
    "CoulombTangentialHistory",
    "CyclicLoss",
    "TangentialHistory",
    "cyclic_loss",
    "cyclic_loss_coulomb",
    "tangential_history",
    "tangential_history_coulomb",
]

#: Collocation nodes the incremental solver starts each step with (it doubles them until
#: the Chebyshev tail of the step's solution is at round-off).
N_INCREMENTAL = 64
#: The largest size the incremental solver doubles to: a reversal by a fraction ``r`` of
#: the full-slip load puts the new stick zone within ``~ r^2/8`` of the edge, whose
#: logarithmic source then needs ``~ 70/r`` nodes (``docs/load-histories.md``).
N_MAX_INCREMENTAL = 4096
_N_GAUSS = 16  # Gauss-Legendre nodes per piece of the slip annulus (friction work)
#: The friction work of the incremental solver differences displacements of order one over
#: the slip annulus ``c < |x| < a`` at the peaks: its relative round-off grows like
#: ``eps (1 - c/a)^(-3/2)`` (measured: 4e-7 at ``1 - c/a = 5e-7``, Coulomb friction).
_EPS_LOSS = float(np.finfo(float).eps)
_T_LIMIT = 1e12  # |T| over the scale: keeps every intermediate quantity finite

_STICK = "stick"
_STICK_SLIP = "stick-slip"
_SLIDING = "sliding"


# --------------------------------------------------------------------------------------------
# the monotone solution of each friction law, in its own units: lengths over a, stresses
# over the friction scale (tau0, or mu p0), loads over the full-slip load (r = T/T_full),
# slips and displacements over a (stress scale)/E, energies over E a^2 (stress scale/E)^2


def _series(x, coef_of_k, k0: int, kmax: int):
    """sum_{k = k0..kmax} coef_of_k(k) x^k (small x: the closed forms cancel there)."""
    out = np.zeros_like(x)
    p = x**k0
    for k in range(k0, kmax + 1):
        out = out + coef_of_k(k) * p
        p = p * x
    return out


class _Law:
    """One friction law: full-slip load, monotone closed forms, and the collocation pieces."""

    name: str
    T_full: float  # full-slip load over (stress scale) a

    def stick(self, r):
        """Stick-zone half-width over a at the monotone load r = T/T_full in [0, 1]."""
        raise NotImplementedError

    def displacement(self, r):
        """Monotone displacement D/a (datum a) over (stress scale)/E."""
        raise NotImplementedError

    def virgin_loss(self, r):
        """Energy dissipated by monotone loading from 0 to r, over E a^2 (scale/E)^2."""
        raise NotImplementedError

    def traction(self, x, r):
        """Monotone traction over the stress scale; x and r broadcast."""
        raise NotImplementedError

    def slip(self, x, r):
        """Monotone slip relative to the centre, over a (scale)/E (nan beyond |x| = 1)."""
        raise NotImplementedError

    # collocation pieces: the slip-zone traction B(x) (times the direction) and transforms
    def B(self, x):
        raise NotImplementedError

    def HB(self, x):
        """(1/pi) PV int_{-1}^{1} B(xi)/(xi - x) dxi for |x| < 1."""
        raise NotImplementedError

    def logB(self, x):
        """int_{-1}^{1} B(xi) ln|x - xi| dxi."""
        raise NotImplementedError


class _Constant(_Law):
    name = "constant"
    T_full = 2.0

    def stick(self, r):
        return np.sqrt(np.clip((1 - r) * (1 + r), 0.0, None))

    def displacement(self, r):
        # (4/pi) [r (1 + ln 2) - ((1 + r) ln(1 + r) - (1 - r) ln(1 - r))/2]
        r = np.asarray(r, float)
        odd = _xlogy(1 + r, 1 + r) - _xlogy(1 - r, 1 - r)
        return (4 / np.pi) * (r * (1 + math.log(2)) - odd / 2)

    def virgin_loss(self, r):
        # (8/pi) h(r), h = ((1+r) ln(1+r) + (1-r) ln(1-r))/2 - r^2/2 = sum_{k>=2} r^2k/(2k(2k-1))
        r = np.abs(np.asarray(r, float))
        small = r < 0.3
        rs = np.where(small, r, 0.0)
        h_series = _series(rs * rs, lambda k: 1.0 / (2 * k * (2 * k - 1)), 2, 18)
        h_direct = (_xlogy(1 + r, 1 + r) + _xlogy(1 - r, 1 - r)) / 2 - r * r / 2
        return (8 / np.pi) * np.where(small, h_series, h_direct)

    def traction(self, x, r):
        d = self.stick(r)
        ax = np.abs(x)
        inner = (2 / np.pi) * np.arctan2(r, np.sqrt(np.clip(d * d - x * x, 0.0, None)))
        return np.where(ax <= 1.0, np.where(ax < d, inner, 1.0), 0.0)

    def slip(self, x, r):
        d = self.stick(r)
        ax = np.abs(x)
        xs = np.clip(ax, d, 1.0)
        with np.errstate(divide="ignore", invalid="ignore"):
            val = (4 / np.pi) * _init_slip_closed(xs, d)
        return np.where(ax > 1.0, np.nan, np.where(ax <= d, 0.0, val))

    def B(self, x):
        return np.ones_like(x)

    def HB(self, x):
        return -(2 / np.pi) * np.arctanh(x)

    def logB(self, x):
        return _xlogy(1 + x, np.abs(1 + x)) + _xlogy(1 - x, np.abs(1 - x)) - 2.0


class _Coulomb(_Law):
    name = "coulomb"
    T_full = np.pi / 2

    def stick(self, r):
        return np.sqrt(np.clip(1 - r, 0.0, None))

    def displacement(self, r):
        # Q (1/2 + ln 2) + (1 - Q) ln(1 - Q)/2
        r = np.asarray(r, float)
        return r * (0.5 + math.log(2)) + _xlogy(1 - r, 1 - r) / 2

    def virgin_loss(self, r):
        # (pi/2) h_c(Q), h_c = (1-Q) ln(1-Q)/2 + Q/2 - Q^2/4 = sum_{k>=3} Q^k/(2k(k-1))
        r = np.abs(np.asarray(r, float))
        small = r < 0.25
        rs = np.where(small, r, 0.0)
        h_series = _series(rs, lambda k: 1.0 / (2 * k * (k - 1)), 3, 30)
        h_direct = _xlogy(1 - r, 1 - r) / 2 + r / 2 - r * r / 4
        return (np.pi / 2) * np.where(small, h_series, h_direct)

    def traction(self, x, r):
        d = self.stick(r)
        xc = np.clip(x, -1.0, 1.0)
        q = np.sqrt(1 - xc * xc) - np.sqrt(np.clip(d * d - x * x, 0.0, None))
        return np.where(np.abs(x) <= 1.0, q, 0.0)

    def slip(self, x, r):
        # x^2 - d^2 (e^{-2v}/2 + v + 1/2), cosh v = |x|/d, outside the stick zone
        d = self.stick(r)
        ax = np.abs(x)
        with np.errstate(divide="ignore", invalid="ignore"):
            y = np.where(d > 0, np.clip(ax, d, 1.0) / np.where(d > 0, d, 1.0), 1.0)
        v = np.arccosh(y)
        val = ax * ax - d * d * (np.exp(-2 * v) / 2 + v + 0.5)
        return np.where(ax > 1.0, np.nan, np.where(ax <= d, 0.0, val))

    def B(self, x):
        return np.sqrt(np.clip(1 - x * x, 0.0, None))

    def HB(self, x):
        return -x

    def logB(self, x):
        c0, e = chebyshev_log_expansion(x, 2)
        return (np.pi / 2) * (e[..., 2] / 2 + c0)


_LAWS: dict[str, _Law] = {"constant": _Constant(), "coulomb": _Coulomb()}


# --------------------------------------------------------------------------------------------
# the Masing memory rules


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


# --------------------------------------------------------------------------------------------
# the incremental solver: the stick condition solved step by step by collocation


@dataclass(frozen=True)
class _Incremental:
    """States ``q = s B(x) + sum_k psi_k(x)``, each ``psi_k`` bounded on ``|x| < c_k``.

    ``psi_k(x) = sqrt(1 - t^2) sum_j b_kj U_j(t)``, ``t = x/c_k``; per step, a tuple of
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
    """(1/pi) PV int psi(xi)/(xi - x) dxi = -sum_j b_j e_{j+1}(x/c), inside and outside.

    ``e_k = T_k(y)`` inside (Clenshaw), ``e_k = rho^k`` with
    ``rho = sign(y)/(|y| + sqrt(y^2 - 1))`` outside (Horner): O(n) vector operations.
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
    """Pieces between the cuts, each graded geometrically towards both of its ends.

    The slips have algebraic-logarithmic end behaviour (``(1 - x) ln(1 - x)`` at the
    contact edge, ``(x - c)^(3/2)`` where a stick zone ended): halving the pieces towards
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
    """The next size for a stick zone ``|x| < c``: at least twice ``nn``, or ``at_least``.

    A reversal's log sources sit at ``x = +-a``, ``t = +-a/c``: the coefficients fall like
    ``exp(-arccosh(1/c) k)``, so about ``40/arccosh(1/c)`` of them reach round-off.
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


def _incremental(law: _Law, loads: NDArray, n: int) -> dict[str, Any]:
    """Solve the stick condition at each step from the previous state (no memory rule).

    Step ``j`` moves the load monotonically to ``T_j``, in the direction ``s``. Unknown:
    the stick zone ``|x| < c`` and the traction there. Outside it the traction is ``s B``,
    so every part of the previous state that reaches beyond ``c`` is replaced; the new
    part ``phi`` on ``|x| < c`` keeps the relative displacement of the stick zone:
    ``H phi = (s_prev - s) HB + sum of H psi_k over the replaced parts`` on ``|x| < c``
    (smooth: each replaced part is evaluated inside its own interval), bounded at ``+-c``.
    ``c`` is the root of the force balance.
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


# --------------------------------------------------------------------------------------------
# results


@dataclass(frozen=True)
class _History(Result):
    """Shared fields and methods of the two history results (one point per step)."""

    step: NDArray
    T_over_Ea: NDArray
    T_over_T_full_slip: NDArray
    c_over_a: NDArray
    slip_direction: NDArray
    state: NDArray
    memory: NDArray
    displacement_over_a: NDArray
    dissipation_over_Ea2: NDArray
    method: str
    n_collocation: NDArray
    residual_stick: NDArray
    residual_admissible: NDArray
    error_estimate: NDArray
    converged: NDArray
    _states: Any = field(repr=False)
    _scale: float = field(repr=False)

    def _steps(self, steps) -> NDArray:
        n = self.step.size
        idx = np.arange(n) if steps is None else np.asarray(steps)
        if idx.dtype.kind not in "iu" or np.any((idx < -n) | (idx >= n)):
            raise ValueError(
                f"steps must be integer indices in [-{n}, {n - 1}] (as for a NumPy array), "
                f"got {steps!r}"
            )
        return np.where(idx < 0, idx + n, idx)

    def traction(self, x_over_a: ArrayLike, steps: ArrayLike | None = None) -> NDArray:
        """Shear traction ``q/E`` at ``x/a`` after each step: shape ``(steps, m)``.

        ``steps`` (indices into the history, default all) selects the steps.
        """
        x = check_array("x_over_a", x_over_a, low=-np.inf).reshape(-1)
        return self._scale * self._states.traction(x, self._steps(steps))

    def slip(self, x_over_a: ArrayLike, steps: ArrayLike | None = None) -> NDArray:
        """Accumulated slip ``s/a`` at ``x/a`` after each step (relative to the centre).

        Zero in the part of the stick zone that never slipped, constant in time wherever
        the surfaces stick, ``nan`` outside the contact; shape ``(steps, m)``.
        """
        x = check_array("x_over_a", x_over_a, low=-np.inf).reshape(-1)
        return self._scale * self._states.slip(x, self._steps(steps))

    def zones(self) -> list[list[tuple[float, float, str]]]:
        """The zones of ``0 <= x/a <= 1`` after each step (the contact is symmetric).

        Each zone is ``(from, to, kind)``: ``"stick"`` (never slipped), ``"locked+"`` /
        ``"locked-"`` (slipped earlier, last along ``+x`` / ``-x``, stuck now), ``"slip+"``
        / ``"slip-"`` (slipping at the end of the step), ``"sliding"`` (the whole contact).
        Only the closed-form (Masing) states know the frozen zones; for the incremental
        solver the stick zone is reported as one zone ``"stick"``.
        """
        out = []
        for j in range(self.step.size):
            if self.state[j] == _SLIDING:
                out.append([(0.0, 1.0, _SLIDING)])
                continue
            if self.state[j] == _STICK:
                out.append([(0.0, 1.0, _STICK)])
                continue
            zs: list[tuple[float, float, str]] = []
            if isinstance(self._states, _Masing):
                coef, r = self._states.coef[j], self._states.r[j]
                keep = coef != 0
                coef, r = coef[keep], r[keep]
                # the stick zones nest; round-off must not turn two equal ones round
                d = np.minimum(np.maximum.accumulate(self._states.law.stick(r)), 1.0)
                bounds = [0.0, *d.tolist(), 1.0]
                kinds = [_STICK] + [("locked+" if c > 0 else "locked-") for c in coef[:-1]]
                kinds.append("slip+" if coef[-1] > 0 else "slip-")
                for lo, hi, kind in zip(bounds[:-1], bounds[1:], kinds, strict=True):
                    if hi > lo:
                        zs.append((lo, hi, kind))
            else:
                cj = float(self.c_over_a[j])
                zs.append((0.0, cj, _STICK))
                if cj < 1.0:
                    zs.append((cj, 1.0, "slip+" if self.slip_direction[j] > 0 else "slip-"))
            out.append(zs)
        return out


@dataclass(frozen=True)
class TangentialHistory(_History):
    r"""A tangential load history with constant friction stress ``tau0`` (one point per step).

    Attributes
    ----------
    step : ndarray of int
        1, 2, ... (the state before step 1 is unloaded and has never slipped).
    T_over_Ea : ndarray
        The load at the end of the step, ``T/(E a)`` (either sign).
    T_over_T_full_slip : ndarray
        ``T/(2 a tau0)``.
    c_over_a : ndarray
        Half-width of the stick zone ``|x| < c`` at the end of the step (``1`` unloaded or at
        a turning point just reached from rest; ``nan`` when sliding).
    slip_direction : ndarray of int
        ``+1`` / ``-1``: the direction of the slip in the step's slip zones (the direction
        the load moved); ``0`` before any load.
    state : ndarray of str
        ``"stick"`` (unloaded), ``"stick-slip"`` or ``"sliding"`` (the load reached
        ``2 a tau0`` on the virgin branch: gross sliding).
    memory : ndarray of int
        Turning points held in memory (the closed-form states; ``-1`` for the incremental
        solver, which keeps none).
    displacement_over_a : ndarray
        ``D/a``, the cylinder's displacement relative to the substrate with the datum at
        depth ``a`` (``nan`` when sliding; after a slide it excludes the sliding distance,
        which a force-controlled history does not determine).
    dissipation_over_Ea2 : ndarray
        Energy dissipated by friction in the step, per unit length over ``E a^2`` (``nan``
        for a step that slides).
    tau0_over_E : float
    method : str
        ``"closed-form"`` (Masing rules) or ``"incremental"`` (collocation, step by step).
    n_collocation : int
        Nodes of the incremental solver (0 for the closed form).
    residual_stick : ndarray
        Largest residual of the stick condition at 16 points other than the collocation
        points, over ``tau0`` (0 for the closed form).
    residual_admissible : ndarray
        Largest violation of the friction law: ``|q|`` above ``tau0`` in the stick zone, or
        slip against the traction in the slip zone (over ``tau0`` and ``a tau0/E``; 0 for
        the closed form).
    error_estimate : ndarray
        Chebyshev tail of the step's stick-zone solution over its largest coefficient.
    converged : ndarray of bool
    """

    inputs: ClassVar[tuple[str, ...]] = ("tau0_over_E", "method", "n_collocation")

    tau0_over_E: float = 0.0


@dataclass(frozen=True)
class CoulombTangentialHistory(_History):
    r"""A tangential load history of a Hertz line contact with Coulomb friction ``mu``.

    As :class:`TangentialHistory`, with ``T_over_T_full_slip = T_over_muF = T/(mu F)`` and the
    stresses of the diagnostics over ``mu p0``.
    """

    inputs: ClassVar[tuple[str, ...]] = ("mu", "a_over_R", "method", "n_collocation")

    T_over_muF: NDArray = field(default_factory=lambda: np.zeros(0))
    mu: float = 0.0
    a_over_R: float = 0.0


def _check_method(method: str, n: int, tol: float) -> None:
    if method not in ("closed-form", "incremental"):
        raise ValueError(f"method must be 'closed-form' or 'incremental', got {method!r}")
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or not 4 <= n <= 4096:
        raise ValueError(f"n must be an integer in [4, 4096], got {n!r}")
    check_solver_options(n, tol, n_max=N_MAX_INCREMENTAL)


def _loads(name: str, value: ArrayLike) -> NDArray:
    arr = check_array(
        name, value, low=-_T_LIMIT, low_inclusive=True, high=_T_LIMIT, high_inclusive=True
    )
    if arr.ndim > 1:
        raise ValueError(f"{name} must be a sequence of loads (1-D), got shape {arr.shape}")
    arr = arr.reshape(-1)
    if arr.size == 0:
        raise ValueError(f"{name} must hold at least one load, got an empty sequence")
    return arr


def _history(
    law: _Law, r: NDArray, scale: float, method: str, n: int, tol: float, policy: FailurePolicy
) -> dict[str, Any]:
    """The fields shared by both results, for loads r over the full-slip load."""
    steps = r.size
    if method == "closed-form":
        m = _masing(law, r)
        states: Any = _Masing(law, m["coef"], m["r"])
        last = np.take_along_axis(
            m["r"], (np.count_nonzero(m["coef"], axis=1) - 1)[:, None].clip(0), axis=1
        )[:, 0]
        c = law.stick(last)
        D = np.sum(m["coef"] * law.displacement(m["r"]), axis=1)
        zeros = np.zeros(steps)
        diag = dict(
            n_collocation=np.zeros(steps, int),
            residual_stick=zeros,
            residual_admissible=zeros,
            error_estimate=zeros,
            converged=np.ones(steps, bool),
        )
        depth = m["depth"]
    else:
        m = _incremental(law, r, n)
        states = _Incremental(law, m["sign"], m["parts"])
        c = m["c"].copy()
        D = states.displacement()
        conv = (
            (m["error_estimate"] <= tol)
            & (m["residual_stick"] <= max(tol, 1e-10))
            & (m["residual_admissible"] <= max(tol, 1e-10))
        )
        diag = dict(
            n_collocation=m["n_collocation"],
            residual_stick=m["residual_stick"],
            residual_admissible=m["residual_admissible"],
            error_estimate=m["error_estimate"],
            converged=conv,
        )
        depth = np.full(steps, -1)
        if policy == "raise" and not conv.all():
            j = int(np.flatnonzero(~conv)[0])
            raise ConvergenceError(
                f"the incremental solver missed tol={tol:g} at step {j + 1} (T/T_full = "
                f"{float(r[j])!r}: error estimate {m['error_estimate'][j]:.2e}, stick residual "
                f"{m['residual_stick'][j]:.2e}, friction-law violation "
                f"{m['residual_admissible'][j]:.2e}, n={int(m['n_collocation'][j])}): a load "
                "change this small (or this close to the previous turning point) needs more "
                f"than {N_MAX_INCREMENTAL} nodes; use method='closed-form'"
            )
    sliding = m["sliding"]
    unloaded = (m["direction"] == 0) & ~sliding
    state = np.where(sliding, _SLIDING, np.where(unloaded, _STICK, _STICK_SLIP))
    c = np.where(sliding, np.nan, np.where(unloaded, 1.0, c))
    D = np.where(sliding, np.nan, D)
    return dict(
        step=np.arange(1, steps + 1),
        c_over_a=c,
        slip_direction=m["direction"],
        state=state,
        memory=depth,
        displacement_over_a=scale * D,
        dissipation_over_Ea2=scale * scale * m["loss"],
        method=method,
        _states=states,
        _scale=scale,
        **diag,
    )


def tangential_history(
    tau0_over_E: float,
    T_over_Ea: ArrayLike,
    *,
    method: str = "closed-form",
    n: int = N_INCREMENTAL,
    tol: float = 1e-6,
    on_failure: FailurePolicy = RAISE,
    **deprecated: Any,
) -> TangentialHistory:
    r"""States of the contact along a tangential load history, constant friction stress ``tau0``.

    The load starts from zero on a contact that has never slipped and moves monotonically
    from each value of ``T_over_Ea`` to the next; a change of direction is a reversal.

    Parameters
    ----------
    tau0_over_E : float
        Friction stress over the composite modulus, in ``[1e-12, 1]``.
    T_over_Ea : array_like, 1-D
        The loads ``T/(E a)`` at the ends of the steps, either sign. Full slip is
        ``|T| = 2 a tau0``: a load that reaches it slides (``state == "sliding"``); the
        history then continues from the full-slip load.
    method : {"closed-form", "incremental"}
        Masing memory rules with closed forms (exact), or the stick condition solved
        step by step by collocation (``docs/load-histories.md``).
    n : int
        Collocation nodes of the incremental solver.
    tol : float
        Tolerance of the incremental solver on its error estimate and residuals.
    on_failure : {"raise", "report"}
        An incremental step that misses ``tol`` raises
        :class:`~linecontact.errors.ConvergenceError` (``"raise"``, default), or is flagged
        in ``converged`` (``"report"``); README, "Conventions". A load at or beyond full
        slip is no failure here: the step slides (``state == "sliding"``) under either
        policy. Replaces the deprecated ``raise_on_failure`` (``False`` is ``"report"``).

    Returns
    -------
    TangentialHistory
        One point per step; :meth:`~TangentialHistory.traction`,
        :meth:`~TangentialHistory.slip` and :meth:`~TangentialHistory.zones` give the
        distributions.

    Examples
    --------
    Load to 0.8 of full slip, reverse to -0.4, load again beyond 0.8 to 0.9: the loop closes
    at 0.8 and is erased, and the state at 0.9 is the virgin one:

    >>> h = tangential_history(0.01, [0.016, -0.008, 0.018])
    >>> [round(c, 6) for c in h.c_over_a]
    [0.6, 0.8, 0.43589]
    >>> h.memory.tolist()
    [0, 1, 0]
    >>> virgin = tangential_history(0.01, [0.018])
    >>> bool(abs(h.displacement_over_a[2] - virgin.displacement_over_a[0]) < 1e-15)
    True
    """
    t0 = _domain.scalar("tau0_over_E", tau0_over_E)
    _check_method(method, n, tol)
    policy = failure_policy(on_failure, where="tangential_history", **deprecated)
    T = _loads("T_over_Ea", T_over_Ea)
    r = T / (2 * t0)
    fields_ = _history(_LAWS["constant"], r, t0, method, n, tol, policy)
    return TangentialHistory(T_over_Ea=T, T_over_T_full_slip=r, tau0_over_E=t0, **fields_)


def tangential_history_coulomb(
    mu: float,
    a_over_R: float,
    T_over_muF: ArrayLike,
    *,
    method: str = "closed-form",
    n: int = N_INCREMENTAL,
    tol: float = 1e-6,
    on_failure: FailurePolicy = RAISE,
    **deprecated: Any,
) -> CoulombTangentialHistory:
    r"""States of a Hertz line contact with Coulomb friction along a tangential load history.

    The Mindlin--Deresiewicz rules for the line contact (Cattaneo--Mindlin for each
    branch). Parameters as in :func:`tangential_history`, with

    Parameters
    ----------
    mu : float
        Coefficient of friction.
    a_over_R : float
        Hertz half-width over the radius (``p0 = E a/(2R)``, ``F = pi E a^2/(4R)``).
    T_over_muF : array_like, 1-D
        The loads over ``mu F``, either sign; ``|T| >= mu F`` slides.
    method, n, tol, on_failure
        As in :func:`tangential_history`.

    Returns
    -------
    CoulombTangentialHistory

    Examples
    --------
    >>> h = tangential_history_coulomb(0.3, 0.01, [0.5, -0.5])
    >>> [round(c, 12) for c in h.c_over_a]
    [0.707106781187, 0.707106781187]
    """
    m = _domain.scalar("mu", mu)
    A = _domain.scalar("a_over_R", a_over_R)
    _check_method(method, n, tol)
    policy = failure_policy(on_failure, where="tangential_history_coulomb", **deprecated)
    Q = _loads("T_over_muF", T_over_muF)
    scale = m * A / 2  # mu p0 / E
    fields_ = _history(_LAWS["coulomb"], Q, scale, method, n, tol, policy)
    return CoulombTangentialHistory(
        T_over_Ea=(np.pi / 4) * m * A * Q,
        T_over_T_full_slip=Q,
        T_over_muF=Q,
        mu=m,
        a_over_R=A,
        **fields_,
    )


# --------------------------------------------------------------------------------------------
# cyclic loading


@dataclass(frozen=True)
class _Cyclic(Result):
    T_amplitude_over_Ea: NDArray | float
    T_amplitude_over_T_full_slip: NDArray | float
    W_over_Ea2: NDArray | float
    c_over_a: NDArray | float
    state: NDArray | str
    method: str

    def loop(self, num: int = 101) -> dict[str, NDArray]:
        r"""The steady hysteresis loop: ``T/(E a)`` and ``D/a`` from ``+T*`` down and back.

        Returns arrays of shape ``points.shape + (2 num - 1,)``: the unloading branch from
        ``+T*`` to ``-T*`` then the reloading branch back to ``+T*`` (``nan`` for sliding
        points). The datum of ``D`` is at depth ``a``.
        """
        if isinstance(num, bool) or not isinstance(num, (int, np.integer)) or num < 2:
            raise ValueError(f"num must be an integer >= 2, got {num!r}")
        law, scale = self._law_scale()
        r = np.asarray(self.T_amplitude_over_T_full_slip, float)[..., None]
        r = np.where(r < 1, r, np.nan)
        u = np.linspace(0.0, 1.0, num)
        down = r * (1 - 2 * u)  # +r to -r
        up = r * (2 * u[1:] - 1)  # -r to +r
        g = law.displacement
        D_peak = g(r)
        D_down = D_peak - 2 * g((r - down) / 2)
        D_up = -D_peak + 2 * g((up + r) / 2)
        T = np.concatenate([down, up], axis=-1) * (law.T_full * scale)
        D = np.concatenate([D_down, D_up], axis=-1) * scale
        return {"T_over_Ea": T, "displacement_over_a": D}

    def _law_scale(self):  # pragma: no cover - defined by the subclasses
        raise NotImplementedError


@dataclass(frozen=True)
class CyclicLoss(_Cyclic):
    r"""Cyclic tangential loading between ``-T*`` and ``+T*``, constant friction stress.

    Attributes
    ----------
    T_amplitude_over_Ea : ndarray or float
        ``T*/(E a)``.
    T_amplitude_over_T_full_slip : ndarray or float
        ``r = T*/(2 a tau0)``.
    W_over_Ea2 : ndarray or float
        Energy dissipated per cycle per unit length over ``E a^2`` (steady loop):
        :math:`(32/\pi)(\tau_0/E)^2 h(r)`, :math:`h = [(1+r)\ln(1+r) + (1-r)\ln(1-r)
        - r^2]/2`; ``nan`` when sliding (the gross-sliding loss is not computed).
    c_over_a : ndarray or float
        Stick-zone half-width at the peaks, :math:`\sqrt{1 - r^2}` (``nan`` sliding).
    state : ndarray of str or str
        ``"stick-slip"``, or ``"sliding"`` at or above full slip (``r >= 1``).
    tau0_over_E : ndarray or float
    method : str
        ``"closed-form"`` or ``"incremental"`` (three steps of the incremental solver per
        amplitude, the loss as the friction work over the last two).
    """

    inputs: ClassVar[tuple[str, ...]] = ("tau0_over_E", "method")

    tau0_over_E: NDArray | float = 0.0

    def _law_scale(self):
        return _LAWS["constant"], np.asarray(self.tau0_over_E, float)[..., None]


@dataclass(frozen=True)
class CoulombCyclicLoss(_Cyclic):
    r"""Cyclic tangential loading of a Hertz line contact with Coulomb friction.

    As :class:`CyclicLoss` with ``T_amplitude_over_T_full_slip = T_amplitude_over_muF =
    Q = T*/(mu F)`` and :math:`W/(E a^2) = (\pi/2)\mu^2(a/R)^2
    [(1-Q)\ln(1-Q)/2 + Q/2 - Q^2/4]`, the stick zone :math:`\sqrt{1 - Q}` at the peaks.
    """

    inputs: ClassVar[tuple[str, ...]] = ("mu", "a_over_R", "method")

    T_amplitude_over_muF: NDArray | float = 0.0
    mu: NDArray | float = 0.0
    a_over_R: NDArray | float = 0.0

    def _law_scale(self):
        return _LAWS["coulomb"], (
            np.asarray(self.mu, float) * np.asarray(self.a_over_R, float) / 2
        )[..., None]


def _loss_roundoff(law: _Law, r: float) -> float:
    """Relative round-off of the incremental solver's loss per cycle at the amplitude ``r``.

    ``eps (1 - c/a)^(-3/2)`` with ``c`` the stick zone at the peaks (``_EPS_LOSS``): an upper
    bound of the measured error (Coulomb: ``3e-16 Q^(-3/2)``; constant stress: lower).
    """
    # 1 - c/a without cancellation: 1 - c^2 = r^2 (constant stress) or r (Coulomb)
    u = r * r if law.name == "constant" else r
    gap = u / (1.0 + math.sqrt(max(1.0 - u, 0.0)))
    return math.inf if gap <= 0 else _EPS_LOSS * gap**-1.5


def _too_small(tol: float, r: float, estimate: float, n: int) -> str:
    """The message of an amplitude too small for the incremental solver."""
    return (
        f"the incremental solver missed tol={tol:g} at the amplitude {r!r} of the full-slip "
        f"load (estimate {estimate:.2e}, n={n}): an amplitude this small needs more than "
        f"{N_MAX_INCREMENTAL} nodes; use method='closed-form'"
    )


def _cyclic(law: _Law, r: NDArray, scale: NDArray, method: str, n: int, tol: float):
    """W over E a^2, the stick zone and the state for amplitudes r over the full-slip load."""
    sliding = r >= 1.0
    rr = np.where(sliding, 0.0, r)
    if method == "closed-form":
        w = 4 * law.virgin_loss(rr)
    else:
        w = np.empty(r.shape)
        # refused at once: an amplitude whose slip annulus is too thin for the loss to be
        # resolved to tol (the solver would spend seconds and miss tol, or lose the loss to
        # round-off); the tolerance is checked before the solver is entered
        for i, ri in np.ndenumerate(rr):
            if not sliding[i]:
                est = _loss_roundoff(law, float(ri))
                if not est <= tol:
                    raise ConvergenceError(_too_small(tol, float(ri), est, N_MAX_INCREMENTAL))
        for i, ri in np.ndenumerate(rr):
            if sliding[i]:
                w[i] = np.nan
                continue
            m = _incremental(law, np.array([ri, -ri, ri]), n)
            bad = max(m["error_estimate"].max(), m["residual_stick"].max())
            if not bad <= tol:
                raise ConvergenceError(
                    _too_small(tol, float(ri), bad, int(m["n_collocation"].max()))
                )
            w[i] = m["loss"][1] + m["loss"][2]
    W = np.where(sliding, np.nan, scale * scale * w)
    c = np.where(sliding, np.nan, law.stick(rr))
    state = np.where(sliding, _SLIDING, _STICK_SLIP)
    return W, c, state


def cyclic_loss(
    tau0_over_E: ArrayLike,
    T_amplitude_over_Ea: ArrayLike,
    *,
    method: str = "closed-form",
    n: int = N_INCREMENTAL,
    tol: float = 1e-6,
) -> CyclicLoss:
    r"""Energy dissipated per cycle of tangential loading between ``-T*`` and ``+T*``.

    Constant friction stress ``tau0``. The loop is steady from the first cycle (Masing):
    unloading from ``+T*`` and reloading from ``-T*`` are the monotone solution for
    ``2 tau0`` under the load change, and the loop closes at ``+T*``.

    Parameters
    ----------
    tau0_over_E : array_like
        Friction stress over the composite modulus, in ``[1e-12, 1]``.
    T_amplitude_over_Ea : array_like
        Amplitude ``T*/(E a)``, ``> 0``. At or above full slip (``2 tau0/E``) the point is
        reported as ``state == "sliding"`` with ``W_over_Ea2 = nan``.
    method : {"closed-form", "incremental"}
        The closed form, or the friction work of the incremental solver over one cycle.
    n, tol
        Nodes and tolerance of the incremental solver.

    Returns
    -------
    CyclicLoss
        Inputs broadcast together; scalars in, scalars out. :meth:`CyclicLoss.loop` draws
        the loop.

    Notes
    -----
    :math:`W = \frac{32}{\pi}\frac{\tau_0^2a^2}{E}\,h(r)`, :math:`r = T^*/(2a\tau_0)`,
    :math:`h = \frac12[(1+r)\ln(1+r) + (1-r)\ln(1-r)] - \frac{r^2}{2}
    = \sum_{k\ge2} \frac{r^{2k}}{2k(2k-1)}`: :math:`W \propto T^{*4}` at small amplitude
    (Coulomb friction: :math:`T^{*3}`), and
    :math:`W \to (32/\pi)(\ln 2 - 1/2)\tau_0^2 a^2/E` at full slip.

    Examples
    --------
    >>> w = cyclic_loss(0.01, [0.0002, 0.0004])
    >>> ratio = w.W_over_Ea2[1] / w.W_over_Ea2[0]
    >>> bool(15.99 < ratio < 16.01)       # ~ 2^4 at small amplitude
    True
    >>> cyclic_loss(0.01, 0.02).state
    'sliding'
    """
    _check_method(method, n, tol)
    t0 = _domain.check("tau0_over_E", tau0_over_E)
    A = check_array(
        "T_amplitude_over_Ea",
        T_amplitude_over_Ea,
        low=0.0,
        low_inclusive=False,
        high=_T_LIMIT,
        high_inclusive=True,
    )
    t0, A = np.broadcast_arrays(t0, A)
    scalar = A.ndim == 0
    r = A / (2 * t0)
    W, c, state = _cyclic(_LAWS["constant"], r, t0, method, n, tol)
    return CyclicLoss(
        as_output(A, scalar),
        as_output(r, scalar),
        as_output(W, scalar),
        as_output(c, scalar),
        as_output(state, scalar),
        method,
        tau0_over_E=as_output(t0, scalar),
    )


def cyclic_loss_coulomb(
    mu: ArrayLike,
    a_over_R: ArrayLike,
    T_amplitude_over_muF: ArrayLike,
    *,
    method: str = "closed-form",
    n: int = N_INCREMENTAL,
    tol: float = 1e-6,
) -> CoulombCyclicLoss:
    r"""Energy dissipated per cycle by a Hertz line contact with Coulomb friction.

    Mindlin--Deresiewicz for the line contact: :math:`W/(E a^2) = \frac{\pi}{2}\mu^2
    (a/R)^2\,[\frac12(1-Q)\ln(1-Q) + \frac{Q}{2} - \frac{Q^2}{4}]`, :math:`Q = T^*/(\mu F)`;
    :math:`\approx (\pi/24)\mu^2(a/R)^2 Q^3` at small amplitude, :math:`(\pi/8)\mu^2(a/R)^2`
    at full slip.

    Parameters
    ----------
    mu, a_over_R : array_like
        Coefficient of friction and Hertz half-width over the radius.
    T_amplitude_over_muF : array_like
        ``Q = T*/(mu F)``, ``> 0`` (``>= 1`` slides).
    method, n, tol
        As in :func:`cyclic_loss`.

    Returns
    -------
    CoulombCyclicLoss

    Examples
    --------
    >>> w = cyclic_loss_coulomb(0.3, 0.01, [0.001, 0.002])
    >>> bool(7.99 < w.W_over_Ea2[1] / w.W_over_Ea2[0] < 8.01)   # ~ 2^3
    True
    """
    _check_method(method, n, tol)
    m = _domain.check("mu", mu)
    A = _domain.check("a_over_R", a_over_R)
    Q = check_array(
        "T_amplitude_over_muF",
        T_amplitude_over_muF,
        low=0.0,
        low_inclusive=False,
        high=_T_LIMIT,
        high_inclusive=True,
    )
    m, A, Q = np.broadcast_arrays(m, A, Q)
    scalar = Q.ndim == 0
    scale = m * A / 2
    W, c, state = _cyclic(_LAWS["coulomb"], Q, scale, method, n, tol)
    return CoulombCyclicLoss(
        as_output((np.pi / 4) * m * A * Q, scalar),
        as_output(Q, scalar),
        as_output(W, scalar),
        as_output(c, scalar),
        as_output(state, scalar),
        method,
        T_amplitude_over_muF=as_output(Q, scalar),
        mu=as_output(m, scalar),
        a_over_R=as_output(A, scalar),
    )
