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
from ._checks import _check_common
from .closed_form import _cf_outputs, _closed_form, _newton2

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


def _phi_at(lab, kap, r):
    """Phi = (2/pi) F/(E h2), dPhi/dabar, u1, u2 at abar = exp(lab) (closed form).

    Flat arrays or NumPy scalars. Each call starts from the symmetric guesses (robust; warm
    starts from a distant abar can lead Newton astray).
    """
    ab = np.exp(lab)
    one = _num._full(ab, 1.0)  # the closed form depends on abar and kappa only: R/h2 = 1
    A = ab * np.sqrt(2.0)
    s = kap * (np.pi / 4) / np.sqrt(2.0)
    u1, u2, _, _ = _closed_form(A, one, r, s)
    _, F, _, dphi = _cf_outputs(A, one, r, s, u1, u2)
    return F * (2 / np.pi), dphi, u1, u2


_LAB_LO = np.log(1e-9)  # abar below which the load is indistinguishable from its a -> 0 limit


_LAB_DEEP = -300.0  # the lower end of a contact-for-load bracket at a zero-width minimum


_GRID = np.linspace(0.0, 1.0, 41)  # the grid in ln abar that brackets the load minimum


def _phi_grid(labs, kap, r):
    """Phi and dPhi/dabar on the grid ``labs`` (grid, points), as one batch per chunk.

    The grid values of a few points at a time are solved together (a scalar call evaluates
    its 41 grid values in one vectorised solve instead of 41 scalar ones).
    """
    G, P = labs.shape
    phis = np.empty((G, P))
    dphis = np.empty((G, P))
    step = max(1, (1 << 16) // G)
    for c in range(0, P, step):
        sl = slice(c, min(c + step, P))
        m = sl.stop - sl.start
        ph, dph, _, _ = _phi_at(
            labs[:, sl].reshape(-1),
            np.broadcast_to(kap[sl], (G, m)).reshape(-1),
            np.broadcast_to(r[sl], (G, m)).reshape(-1),
        )
        phis[:, sl] = ph.reshape(G, m)
        dphis[:, sl] = dph.reshape(G, m)
    return phis, dphis


def _secant_step(xp, fp, x, fx, lo, hi, ph, kap, r):
    """One step of the secant on dPhi inside its bracket (bisection otherwise), per point."""
    where = _num._where
    nx = x - fx * (x - xp) / (fx - fp)
    ok = (abs(nx) < np.inf) & (nx > lo) & (nx < hi)
    nx = where(ok, nx, 0.5 * (lo + hi))
    ph, fn, _, _ = _phi_at(nx, kap, r)
    xp, fp, x, fx = x, fx, nx, fn
    up = fx > 0
    hi = where(up, x, hi)
    lo = where(up, lo, x)
    stop = ~(abs(x - xp) > 1e-10 * _num._maximum(1.0, abs(x))) | (fx == 0)
    return (xp, fp, x, fx, lo, hi, ph), stop


def _pulloff_flat(kap, r):
    """Minimum of Phi(abar) along the branch: grid in ln abar, then a secant on dPhi.

    Flat arrays or NumPy scalars (the grid is solved as a batch either way).
    """
    scalar = not isinstance(kap, np.ndarray)
    X1, X2, _ = _zero_width(kap, r)
    phi0 = -0.5 * kap * (X1 + X2)
    # upper end: Hertz dominates beyond abar ~ 1 + kappa
    lab_hi = np.log(3.0 + 3.0 * kap)
    kv, rv = np.atleast_1d(kap), np.atleast_1d(r)
    labs = _LAB_LO + _GRID[:, None] * (np.atleast_1d(lab_hi) - _LAB_LO)[None, :]
    phis, dphis = _phi_grid(labs, kv, rv)
    # interior minimum: bracket the smallest grid value
    k = np.argmin(phis, axis=0)
    cols = np.arange(kv.size)
    interior = (k > 0) & (k < _GRID.size - 1)
    kk = np.clip(k, 1, _GRID.size - 2)
    # the secant on dPhi starts from the grid values at the bracket's ends (kept inside the
    # bracket, bisection otherwise); the load is flat at its minimum, so locating it to
    # 1e-10 in ln(abar) gives the load to rounding
    start = (
        labs[kk - 1, cols],
        dphis[kk - 1, cols],
        labs[kk + 1, cols],
        dphis[kk + 1, cols],
        labs[kk - 1, cols],
        labs[kk + 1, cols],
        phis[kk + 1, cols],
    )
    if scalar:
        start, interior = _num._scalars(*(v[0] for v in start)), bool(interior[0])
    (_, _, lab_min, _, _, _, ph), _ = _num._iterate(
        _secant_step, start, (kap, r), 100, done=not interior if scalar else ~interior
    )
    interior = interior & (ph < phi0)
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
    adhesive zones ``-c1 < x < c2`` of the touching state carry
    ``F = -sigma0 (c1 + c2)``; the pull-off force is that minimum, and the rule for the
    label is that of :func:`linecontact.pull_off` (a snap-off lets go from a contact
    half-width of at least the shorter adhesion range, :data:`SNAP_OFF_MIN_WIDTH_OVER_H`,
    or more than 1 % below the zero-width load,
    :data:`linecontact.normal.ZERO_WIDTH_LOAD_RTOL`).
    At ``h1 = h2`` this is the pull-off of :func:`linecontact.pull_off`.

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
    if scalar:  # the same kernels on NumPy scalars (the grid is a batch of 41 either way)
        rho, r, s = _num._scalars(rho, r, s)
    else:
        rho, r, s = (np.ascontiguousarray(v, float).reshape(-1) for v in (rho, r, s))
    kap = _cf._kappa(rho, s)
    where = _num._where
    # h1/h2 far from 1 (1e-300, 1e12) overflows on the way to a finite answer; a result that
    # is not finite is reported below
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
        d = _pulloff_flat(kap, r)
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
