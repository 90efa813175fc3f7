r"""The pull-off of a sliding contact (:func:`sliding_pull_off`), in closed form.

The zero-width limit of the two adhesive zones, the load along the branch of sliding
contacts in ``ln(a)`` and its minimum (snap-off or zero-width, the rule of
:func:`linecontact.pull_off`).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _numerics as _num
from .. import closed_forms as _cf
from .._validation import (
    broadcast,
    first_point,
    point_text,
    scalar_or_array,
)
from ..errors import ConvergenceError
from ..normal import ZERO_WIDTH_LOAD_RTOL
from ..results import Result, as_output
from ..sie import _in_chunks
from ._checks import _check_common, _flat_points
from .closed_form import _cf_load, _closed_form, _newton2

#: As :data:`linecontact.normal.SNAP_OFF_MIN_WIDTH_OVER_H`: the pull-off is a snap-off when
#: the contact half-width at the load minimum is at least this many times the shorter of the
#: two adhesion ranges.
SNAP_OFF_MIN_WIDTH_OVER_H = 1.0


@dataclass(frozen=True)
class SlidingPullOff(Result):
    """The most tensile load a steadily sliding contact carries (load control).

    Attributes
    ----------
    F_pulloff_over_Eh2 : ndarray or float
        Pull-off force over ``E h2`` (negative).
    a_over_R_at_pulloff : ndarray or float
        Contact half-width at pull-off (0 for the zero-width mechanism).
    mechanism : ndarray of str or str
        ``"snap-off"`` (the contact lets go from a half-width of at least the shorter
        adhesion range) or ``"zero-width"`` (it peels below it first).
    F_zero_width_over_Eh2 : ndarray or float
        The load as the contact width vanishes (the two-zone analogue of Eq. 14).
    c1_over_R_zero_width, c2_over_R_zero_width : ndarray or float
        The adhesive zones of that limit state.
    """

    inputs: ClassVar[tuple[str, ...]] = ("R_over_h2", "h1_over_h2", "sigma0_over_E")

    F_pulloff_over_Eh2: NDArray | float
    a_over_R_at_pulloff: NDArray | float
    mechanism: NDArray | str
    F_zero_width_over_Eh2: NDArray | float
    c1_over_R_zero_width: NDArray | float
    c2_over_R_zero_width: NDArray | float
    R_over_h2: NDArray | float
    h1_over_h2: NDArray | float
    sigma0_over_E: NDArray | float


def _zero_width(kap, r):
    """The a -> 0 limit, X_i = (c_i/R) sqrt(R/(2 h2)).

    X2^2 + kappa S/2 ln(S/X1) = 1 and X1^2 + kappa S/2 ln(S/X2) = h1/h2 with S = X1 + X2
    (the separation conditions as u1, u2 -> inf at fixed c_i).
    """
    ln2 = _cf.LN2
    X2 = 2.0 / (kap * ln2 + np.sqrt(kap * kap * ln2 * ln2 + 4))
    X1 = 2.0 * r / (kap * ln2 + np.sqrt(kap * kap * ln2 * ln2 + 4 * r))

    def evaluate(x1, x2, k, r):
        S = x1 + x2
        L2 = np.log(S / x1)
        L1 = np.log(S / x2)
        E1 = (x1 * x1 + 0.5 * k * S * L1) / r - 1
        E2 = x2 * x2 + 0.5 * k * S * L2 - 1
        J11 = (2 * x1 + 0.5 * k * (L1 + 1)) / r
        J12 = 0.5 * k * (L1 - x1 / x2) / r
        J21 = 0.5 * k * (L2 - x2 / x1)
        J22 = 2 * x2 + 0.5 * k * (L2 + 1)
        return E1, E2, J11, J12, J21, J22

    X1, X2, e1, e2, _ = _newton2(evaluate, X1, X2, (kap, r))
    return X1, X2, np.maximum(e1, e2)


def _phi_at(lab, kap, r, start=None):
    """Phi = (2/pi) F/(E h2), dPhi/dabar, u1, u2, du1/dabar, du2/dabar at abar = exp(lab).

    Flat arrays or NumPy scalars (the closed form). Without ``start`` Newton starts from the
    symmetric guesses (robust from anywhere). ``start = (lab0, u1, u2, du1, du2)`` is this
    function's own solution and tangent at a nearby ``lab0``: Newton then starts from the
    tangent's prediction (a step or two instead of the symmetric guesses' search), and a
    point where that misses (a separation residual above 1e-12) is solved again from the
    symmetric guesses, so a start changes the solution by round-off at most.
    """
    ab = np.exp(lab)
    one = _num._full(ab, 1.0)  # the closed form depends on abar and kappa only: R/h2 = 1
    A = ab * np.sqrt(2.0)
    s = kap * (np.pi / 4) / np.sqrt(2.0)
    if start is None:
        u1, u2, _, _, sl = _closed_form(A, one, r, s, slope=True)
    else:
        u1, u2, e1, e2, sl = _closed_form(A, one, r, s, *_predict(lab, *start), slope=True)
        miss = ~(_num._maximum(e1, e2) <= 1e-12)
        if not isinstance(miss, np.ndarray):
            if miss:
                u1, u2, _, _, sl = _closed_form(A, one, r, s, slope=True)
        elif miss.any():
            i = np.flatnonzero(miss)
            u1[i], u2[i], _, _, sli = _closed_form(A[i], one[i], r[i], s[i], slope=True)
            for v, w in zip(sl, sli, strict=True):
                v[i] = w
    # as _cf_outputs computes the load (the same arithmetic, the same bits)
    F = _cf_load(A * np.sqrt(one / 2), _cf._kappa(one, s), u1, u2)
    return F * (2 / np.pi), *sl[:1], u1, u2, *sl[1:]


def _predict(lab, lab0, u1, u2, du1, du2):
    """The tangent's prediction of ``u1, u2`` at ``lab`` from the solution at ``lab0``.

    Linear in ``ln abar`` (``u ~ -ln abar`` as the width vanishes); where the prediction is
    not finite or falls below half the known ``u``, the known ``u`` itself.
    """
    where = _num._where
    h = (lab - lab0) * np.exp(lab0)
    g1, g2 = u1 + h * du1, u2 + h * du2
    ok1 = (abs(g1) < np.inf) & (g1 > 0.5 * u1)
    ok2 = (abs(g2) < np.inf) & (g2 > 0.5 * u2)
    return where(ok1, g1, u1), where(ok2, g2, u2)


_LAB_LO = np.log(1e-9)  # abar below which the load is indistinguishable from its a -> 0 limit


_LAB_DEEP = -300.0  # the lower end of a contact-for-load bracket at a zero-width minimum


#: Where the load is the zero-width load to this fraction of it, and its slope is below
#: this fraction of the size of its terms (``2 abar`` and ``kappa (cosh u1 + cosh u2)(1 +
#: abar)``, as in :func:`linecontact.sliding.contact._stable`), the load is flat to
#: round-off: as the width vanishes the slope is lost in the cancellation of its terms, and
#: any width there carries the minimum load to round-off (the search stops).
_FLAT = 1e-14

#: ... and anywhere, a slope below this fraction of the size of its terms is zero to
#: round-off: the width is at the minimum to round-off.
_NOISE = 4e-16


def _flat(lab, dphi, ph, phi0, kap, u1, u2):
    """Whether the load is flat to round-off at ``lab`` (see :data:`_FLAT`)."""
    ab = np.exp(lab)
    scale = 2 * ab + kap * (np.cosh(u1) + np.cosh(u2)) * (1 + ab)
    return (~(abs(dphi) > _FLAT * scale) & ~(abs(ph - phi0) > _FLAT * abs(phi0))) | ~(
        abs(dphi) > _NOISE * scale
    )


def _guess(kap, r, lab_hi):
    """A start for the minimum: the wider of the two symmetric minima (ranges h2 and h1).

    The minimum of the sliding load lies near the wider of the load minima of the normal
    contacts with the leading and the trailing range (found in closed form, a bracketed
    root per point); without adhesion, or beyond the search's ends, it is clipped to them.
    """
    sr = np.sqrt(r)
    if isinstance(kap, np.ndarray):
        k = np.where(kap > 0, kap, 1.0)
        kk = np.concatenate([k, k / sr])
        ab = _cf._branch_point(_cf._u_stationary(kk), kk)["abar"]
        lab2, lab1 = np.log(ab[: k.size]), np.log(ab[k.size :] * sr)
    else:
        k = kap if kap > 0 else np.float64(1.0)
        lab2 = np.log(_cf._branch_point(_cf._u_stationary(k), k)["abar"])
        lab1 = np.log(_cf._branch_point(_cf._u_stationary(k / sr), k / sr)["abar"] * sr)
    g = _num._maximum(lab1, lab2)
    g = _num._where(g == g, g, 0.5 * (_LAB_LO + lab_hi))
    return _num._minimum(_num._maximum(g, _LAB_LO), lab_hi)


def _propose(xm, Dm, x0, D0, x, D, lo, hi, nlo, nhi, lab_hi):
    """The next ``ln abar`` of the search (:func:`_minimum_step`) from its last three points.

    Inverse quadratic interpolation of dPhi/dabar in abar through the three, or the secant
    through the last two (in abar; in ``ln abar`` where that would pass zero width): near
    the minimum the slope is linear in abar, and in ``ln abar`` it is convex (the secant
    there crept to a minimum at small abar a fraction of the way a step; the secant alone,
    in abar, undershot for several steps before it converged).
    """
    where, mx, mn = _num._where, _num._maximum, _num._minimum
    dx = x - x0
    known = abs(dx) < np.inf
    step = where(known, abs(dx), 0.5)
    ab, ab0, abm = np.exp(x), np.exp(x0), np.exp(xm)
    s1 = (ab - ab0) / (D - D0)  # divided differences of abar(D), Newton's form
    secant = ab - D * s1
    q = secant + D * D0 * ((ab0 - abm) / (D0 - Dm) - s1) / (Dm - D)
    a_next = where((abs(q) < np.inf) & (q > 0), q, secant)
    xs = where(a_next > 0, np.log(mx(a_next, 1e-300)), x - D * dx / (D - D0))
    fin = abs(xs) < np.inf
    both = (nlo > 0) & (nhi > 0)
    inside = where(fin & (xs > lo) & (xs < hi), xs, 0.5 * (lo + hi))
    down = where(fin & (xs < x), mx(xs, x - 4 * step), x - 2 * step)
    up = where(fin & (xs > x), mn(xs, x + 4 * step), x + 2 * step)
    return where(both, inside, where(nlo > 0, mn(up, lab_hi), mx(down, _LAB_LO)))


def _minimum_step(
    xm, Dm, x0, D0, x, D, lo, hi, nlo, nhi, ph, u1, u2, du1, du2, kap, r, lab_hi, phi0
):
    """One step of the bracketed search for the zero of dPhi/dabar, per point.

    ``lo`` (``nlo`` = 1 once a slope there was negative) and ``hi`` (``nhi`` = 1 once one
    was positive) bracket the minimum; until both are found the search walks down (or up)
    from the start, by the interpolation where it points that way (at most four times the
    last step) or by doubling steps, never past ``_LAB_LO`` (``lab_hi``, where the load rises
    as Hertz's). Inside the bracket: the interpolation (:func:`_propose`), bisection where it
    would leave it. Each point is solved from the tangent at the last (:func:`_phi_at`). A
    point stops where the load is flat to round-off (:func:`_flat`), at a step below 1e-10 in
    ``ln abar``, or at an end of the range that the load still rises (falls) from.
    """
    mx = _num._maximum
    where = _num._where
    nx = _propose(xm, Dm, x0, D0, x, D, lo, hi, nlo, nhi, lab_hi)
    ph, Dn, u1, u2, du1, du2 = _phi_at(nx, kap, r, (x, u1, u2, du1, du2))
    neg, pos = Dn < 0, Dn > 0
    lo, nlo = where(neg, nx, lo), where(neg, 1.0, nlo)
    hi, nhi = where(pos, nx, hi), where(pos, 1.0, nhi)
    stop = (
        _flat(nx, Dn, ph, phi0, kap, u1, u2)
        | ~(abs(Dn) < np.inf)
        | (abs(nx - x) <= 1e-10 * mx(1.0, abs(nx)))
        | (pos & (nlo == 0) & (nx <= _LAB_LO))
        | (neg & (nhi == 0) & (nx >= lab_hi))
    )
    return (x0, D0, x, D, nx, Dn, lo, hi, nlo, nhi, ph, u1, u2, du1, du2), stop


def _pulloff_flat(kap, r):
    """Minimum of Phi(abar) along the branch: a bracketed secant on dPhi in ``ln abar``.

    Flat arrays or NumPy scalars. The load has one minimum along the branch (or none above
    the search's lower end ``_LAB_LO``, where it is indistinguishable from its zero-width
    limit): the search starts near it (:func:`_guess`), walks to a bracket and refines it
    to round-off (:func:`_minimum_step`); a minimum is interior when it lies inside
    ``(_LAB_LO, lab_hi)`` below the zero-width load.
    """
    X1, X2, _ = _zero_width(kap, r)
    phi0 = -0.5 * kap * (X1 + X2)
    # upper end: Hertz dominates beyond abar ~ 1 + kappa
    lab_hi = np.log(3.0 + 3.0 * kap)
    x = _guess(kap, r, lab_hi)
    ph, D, u1, u2, du1, du2 = _phi_at(x, kap, r)
    nan = _num._full(x, np.nan)
    one, zero = _num._full(x, 1.0), _num._full(x, 0.0)
    neg, pos = D < 0, D > 0
    start = (
        nan,
        nan,
        nan,
        nan,
        x,
        D,
        _num._full(x, _LAB_LO),
        lab_hi + zero,
        _num._where(neg, one, zero),
        _num._where(pos, one, zero),
        ph,
        u1,
        u2,
        du1,
        du2,
    )
    done = ~(kap > 0) | _flat(x, D, ph, phi0, kap, u1, u2) | ~(abs(D) < np.inf)
    if not isinstance(kap, np.ndarray):
        start, done = _num._scalars(*start), bool(done)
    state, _ = _num._iterate(_minimum_step, start, (kap, r, lab_hi, phi0), 100, done=done)
    lab_min, ph = state[4], state[10]
    interior = (lab_min > _LAB_LO) & (lab_min < lab_hi) & (ph < phi0)
    phi_min = _num._where(interior, ph, phi0)
    lab_min = _num._where(interior, lab_min, -np.inf)
    return dict(
        X1=X1,
        X2=X2,
        phi0=phi0,
        phi_min=phi_min,
        lab_min=lab_min,
        interior=interior,
        lab_hi=lab_hi,
    )


def sliding_pull_off(
    R_over_h2: ArrayLike, h1_over_h2: ArrayLike, sigma0_over_E: ArrayLike
) -> SlidingPullOff:
    r"""The most tensile load a steadily sliding contact carries (closed form).

    The load along the branch of sliding contacts has a minimum either inside the branch
    (``"snap-off"``) or as the contact width vanishes (``"zero-width"``), where the two
    adhesive zones :math:`-c_1 < x < c_2` of the touching state carry
    :math:`F = -\sigma_0 (c_1 + c_2)`; the pull-off force is that minimum, and the rule for the
    label is that of :func:`linecontact.pull_off` (a snap-off lets go from a contact
    half-width of at least the shorter adhesion range, :data:`SNAP_OFF_MIN_WIDTH_OVER_H`,
    or more than 1 % below the zero-width load,
    :data:`linecontact.normal.ZERO_WIDTH_LOAD_RTOL`).
    At :math:`h_1 = h_2` this is the pull-off of :func:`linecontact.pull_off`.

    Parameters
    ----------
    R_over_h2, h1_over_h2, sigma0_over_E : array_like
        As in :func:`sliding_contact`. Without adhesion (``sigma0_over_E = 0``) the
        pull-off force is 0, at zero width, as in :func:`linecontact.pull_off`.

    Returns
    -------
    SlidingPullOff
    """
    rho, r, s = _check_common(R_over_h2, h1_over_h2, sigma0_over_E)
    scalar = scalar_or_array(rho, r, s)
    rho, r, s = broadcast(R_over_h2=rho, h1_over_h2=r, sigma0_over_E=s)
    _cf._check_kappa(rho, s, "R_over_h2")
    shape = rho.shape
    # with scalar inputs the same kernels on NumPy scalars (the grid is a batch of 41 either way)
    rho, r, s = _flat_points(scalar, rho, r, s)
    kap = _cf._kappa(rho, s)
    where = _num._where
    # h1/h2 far from 1 (1e-300, 1e12) overflows on the way to a finite answer; a result that
    # is not finite is reported below
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
        # in chunks of points: bounded memory for any number of them
        d = _pulloff_flat(kap, r) if scalar else _in_chunks(_pulloff_flat, kap.size, kap, r)
        sq = np.sqrt(2 / rho)
        F0 = (np.pi / 2) * d["phi0"]
        Fmin = (np.pi / 2) * d["phi_min"]
        a_min = where(d["interior"], np.exp(d["lab_min"]) * sq, 0.0)
        # a snap-off lets go from a width of at least the shorter adhesion range, or more
        # than 1 % below the zero-width load (as in normal.pull_off)
        snap = d["interior"] & (
            (a_min >= SNAP_OFF_MIN_WIDTH_OVER_H * _num._minimum(1.0, r) / rho)
            | (F0 - Fmin > ZERO_WIDTH_LOAD_RTOL * abs(F0))
        )
    bad = ~((abs(F0) < np.inf) & (abs(Fmin) < np.inf) & (abs(a_min) < np.inf))
    if np.any(bad):
        _, at = first_point(bad, R_over_h2=rho, h1_over_h2=r, sigma0_over_E=s)
        raise ConvergenceError(
            f"sliding_pull_off did not converge at {point_text(at)}: the point is outside the "
            f"solver's range"
        )
    vals = dict(
        F_pulloff_over_Eh2=Fmin,
        a_over_R_at_pulloff=a_min,
        mechanism=where(snap, "snap-off", "zero-width"),
        F_zero_width_over_Eh2=F0,
        c1_over_R_zero_width=d["X1"] * sq,
        c2_over_R_zero_width=d["X2"] * sq,
        R_over_h2=rho,
        h1_over_h2=r,
        sigma0_over_E=s,
    )
    vals = {
        k: as_output(v if scalar else np.asarray(v).reshape(shape), scalar) for k, v in vals.items()
    }
    return SlidingPullOff(**vals)
