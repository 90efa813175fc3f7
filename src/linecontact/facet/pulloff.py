r"""Pull-off of a faceted wire and its contact under a load.

:func:`facet_pull_off` and :func:`facet_contact_for_load`.
The branch of :mod:`linecontact.facet.contact` may have more than one load minimum (one
with the contact inside the facet, one over the rounded corners), so the pull-off is found
by a scan of the whole branch in the contact half-width, refined around the lowest point
(``docs/faceted.md``, Sec. 4); the vanishing-width end is the closed form of Sec. 3.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import closed_forms as _cf
from .. import domain as _domain
from .._validation import (
    FailurePolicy,
    broadcast,
    failure_policy,
    first_point,
    point_text,
)
from ..errors import ConvergenceError, NoEquilibriumError, ParameterError
from ..normal.pulloff import _PullOffBase
from ..results import as_result
from . import _branch as _b
from .contact import INPUTS, FacetContact, _flat, branch, checked, contact_result, regions

#: The scan of the branch: widths below the facet's edge (over ``f``), just below it
#: (``1 - f`` decades) and beyond it over the corner (``_grid``: 96 widths, log-spaced).
_BELOW = np.logspace(-9, 0, 64, endpoint=False)
_EDGE = np.append(1.0 - np.logspace(-1, -13, 40), 1.0)  # and the edge (a sharp corner's end)
_BEYOND = np.logspace(-13, np.log10(4.0), 96)
#: Beyond the scan's widest width: four decades wider at a time, up to three times.
_WIDER = np.geomspace(1.0, 1e4, 48)
_EXTENSIONS = 3
#: Zooms of the bracket around the lowest point: each keeps 2 of 16 intervals.
_ZOOM_POINTS = 17
_ZOOMS = 16


def _grid(f: NDArray, r: NDArray) -> NDArray:
    """The scan's widths per point (NaN where a part does not apply), sorted."""
    below = f[:, None] * np.concatenate([_BELOW, _EDGE])[None, :]
    below = np.where(f[:, None] > 0, below, np.nan)
    # beyond the edge: from 1e-13 r to 4 r, or to the domain's widest contact where that is
    # farther (a small corner under a strong adhesion: the model's own branch, every width)
    lo = np.log(np.where(r > 0, 1e-13 * r, 1.0))  # in logarithms: r may be 1e-300
    hi = np.log(np.where(r > 0, np.maximum(4 * r, _domain.DOMAIN["facet_a_over_R"][2] - f), 2.0))
    steps = np.linspace(0.0, 1.0, _BEYOND.size)[None, :]
    beyond = f[:, None] + np.exp(lo[:, None] + (hi - lo)[:, None] * steps)
    beyond = np.where(r[:, None] > 0, beyond, np.nan)
    g = np.concatenate([below, beyond], axis=1)
    return np.sort(g, axis=1)  # NaN last


def _loads(A2: NDArray, f, r, rho, s, u0=None) -> tuple[NDArray, NDArray]:
    """The load and ``u`` at each width of ``A2`` (points x widths); ``u0`` a start per point."""
    K = A2.shape[1]
    ok = np.isfinite(A2).reshape(-1)  # the widths that apply: only they are solved
    F = np.full(ok.size, np.inf)
    u = np.full(ok.size, np.nan)
    if ok.any():
        fK, rK, rhoK, sK = (np.repeat(v, K)[ok] for v in (f, r, rho, s))
        start = None if u0 is None else np.repeat(u0, K)[ok]
        uo, _, Fo, _, conv, _ = branch(A2.reshape(-1)[ok], fK, rK, rhoK, sK, u0=start)
        F[ok] = np.where(conv, Fo, np.inf)
        u[ok] = uo
    return F.reshape(A2.shape), u.reshape(A2.shape)


def _zero_width(f, r, rho, s):
    """The vanishing-width end: ``c/R`` and ``F/(Eh)`` as ``a -> 0`` (a quadratic in ``c``)."""
    # rho [(c - f)_+^2/(2r) + (4/pi) s c ln 2] = 1; first with c <= f
    k = (4 / np.pi) * s * np.log(2.0) * rho
    with np.errstate(divide="ignore"):
        c_flat = np.where(k > 0, 1.0 / k, np.inf)
    inside = c_flat <= f
    # beyond the corner: (rho/(2r)) y^2 + k y + (k f - 1) = 0, y = c - f >= 0
    rs = np.where(r > 0, r, 1.0)
    with np.errstate(over="ignore"):  # a corner far sharper than h: qa = inf gives y = 0
        qa = rho / (2 * rs)
    qc = k * f - 1.0
    # (a negative discriminant only where the zone ends inside the facet, y unused there)
    with np.errstate(over="ignore"):
        y = -2 * qc / (k + np.sqrt(np.maximum(k * k - 4 * qa * qc, 0.0)))
    c_out = np.where(r > 0, f + y, f)  # a sharp corner pins the zone at c = f
    C = np.where(inside, c_flat, c_out)
    return C, -2 * s * rho * C


@dataclass(frozen=True)
class FacetPullOff(_PullOffBase):
    r"""Pull-off of a faceted wire under load control: the lowest load of its branch.

    Attributes
    ----------
    F_pulloff_over_Eh : ndarray or float
        The pull-off force over ``E h`` (negative).
    a_over_R_at_pulloff, c_over_R_at_pulloff : ndarray or float
        The half-widths at pull-off (``a = 0`` where it is the vanishing-width end).
    mechanism : ndarray of str or str
        ``"inside-facet"``: the contact lets go from inside the facet (``a < f``), its
        adhesive zone free; ``"corner-pinned"``: from inside the facet with the adhesive zone
        held at a sharp corner (``c = f``); ``"whole-facet"``: from a contact covering the
        facet (``a >= f``; the round wire's, ``f = 0``); ``"zero-width"``: at the
        vanishing-width end of the branch.
    F_zero_width_over_Eh : ndarray or float
        The load at the vanishing-width end (for the round wire Eq. 14).
    facet_half_width_over_R : ndarray or float
        The flat half-width ``f`` of the facet.
    F_strip_jkr_over_Eh, F_strength_over_Eh : ndarray or float
        The two limits of a flat facet of half-width ``f``: the strip's JKR pull-off
        :math:`-\sqrt{2\pi f E w}` and the strength cap :math:`-2 \sigma_0 f`, over ``E h``.
    beyond_corner_arc : ndarray or bool
        The adhesive zone at pull-off reaches past the corner's arc (``c - f > r_c
        sin(2 pi/n)``), where the parabolic corner stands for the next facet: the result is
        then doubtful (corners below about ``h``; a sharp corner, ``r_c = 0``, is exact).
    R_over_h, sigma0_over_E, sides, corner_radius_over_R : ndarray or float
        The parameters, broadcast.
    converged : ndarray or bool
        The bracket of the minimum closed to ``1e-10`` of its width.
    """

    inputs: ClassVar[tuple[str, ...]] = INPUTS

    facet_half_width_over_R: NDArray | float
    F_strip_jkr_over_Eh: NDArray | float
    F_strength_over_Eh: NDArray | float
    beyond_corner_arc: NDArray | bool
    R_over_h: NDArray | float
    sigma0_over_E: NDArray | float
    sides: NDArray | int
    corner_radius_over_R: NDArray | float
    converged: NDArray | bool


def _minimum(f, r, rho, s):
    """The lowest load of the branch per point: (F, a, c, converged); flat arrays."""
    P = f.size
    A2 = _grid(f, r)
    F2, U2 = _loads(A2, f, r, rho, s)
    i = np.argmin(F2, axis=1)
    rows = np.arange(P)
    K = A2.shape[1]
    lo = np.where(i > 0, A2[rows, np.maximum(i - 1, 0)], 0.5 * A2[rows, 0])
    hi = A2[rows, np.minimum(i + 1, K - 1)]
    hi = np.where(np.isfinite(hi) & (i + 1 < K), hi, A2[rows, i])
    t = np.linspace(0.0, 1.0, _ZOOM_POINTS)
    best_A = A2[rows, i]
    best_F = F2[rows, i]
    best_u = U2[rows, i]
    # a lowest point at the scan's widest width (a strong adhesion on a round corner: its
    # pull-off contact far wider than f + 4 r): the scan goes on, four decades at a time
    last = K - 1 - np.argmax(np.isfinite(A2[:, ::-1]), axis=1)
    at_end = (i == last) & (r > 0)
    ends = np.zeros(P, bool)
    for _ in range(_EXTENSIONS):
        if not at_end.any():
            break
        k = np.nonzero(at_end)[0]
        Ae = best_A[k, None] * _WIDER[None, :]
        Fe, Ue = _loads(Ae, f[k], r[k], rho[k], s[k], u0=best_u[k])
        j = np.argmin(Fe, axis=1)
        rk = np.arange(k.size)
        lower = Fe[rk, j] < best_F[k]
        kk = k[lower]
        jj, rr = j[lower], rk[lower]
        lo[kk] = Ae[rr, np.maximum(jj - 1, 0)]
        hi[kk] = Ae[rr, np.minimum(jj + 1, _WIDER.size - 1)]
        best_A[kk], best_F[kk], best_u[kk] = Ae[rr, jj], Fe[rr, jj], Ue[rr, jj]
        at_end[:] = False
        at_end[kk[jj == _WIDER.size - 1]] = True
    ends |= at_end  # still at the widest width searched: not converged
    for _ in range(_ZOOMS):
        Az = lo[:, None] + (hi - lo)[:, None] * t[None, :]
        Az = np.where(r[:, None] == 0, np.minimum(Az, f[:, None]), Az)
        Fz, Uz = _loads(Az, f, r, rho, s, u0=best_u)
        j = np.argmin(Fz, axis=1)
        best_u = np.where(Fz[rows, j] <= best_F, Uz[rows, j], best_u)
        better = Fz[rows, j] <= best_F
        best_F = np.where(better, Fz[rows, j], best_F)
        best_A = np.where(better, Az[rows, j], best_A)
        lo = Az[rows, np.maximum(j - 1, 0)]
        hi = Az[rows, np.minimum(j + 1, _ZOOM_POINTS - 1)]
    conv = (hi - lo) <= 1e-9 * np.maximum(best_A, 1e-300) + 1e-300
    _, C, F, _, ok, _ = branch(best_A, f, r, rho, s)
    return F, best_A, C, conv & ok & np.isfinite(F) & ~ends


def facet_pull_off(
    R_over_h: ArrayLike,
    sigma0_over_E: ArrayLike,
    *,
    sides: ArrayLike = 6,
    corner_radius_over_R: ArrayLike = 0.0,
) -> FacetPullOff:
    r"""Pull-off force of a faceted wire on its facet under load control.

    The lowest load of the whole branch (the scan of ``docs/faceted.md``, Sec. 4), or its
    vanishing-width end where that is lower.

    Parameters
    ----------
    R_over_h : array_like
        Circumradius over the range of the adhesive stress, ``[1e-3, 1e12]``.
    sigma0_over_E : array_like
        Adhesive (Dugdale) stress over the composite modulus, ``[0, 1e6]`` (0: no adhesion,
        a pull-off force of 0 at the vanishing-width end, as for the round wire).
    sides : array_like of int
        Number of sides, ``>= 3``.
    corner_radius_over_R : array_like
        Corner radius over the circumradius, ``[0, 1]`` (1: the round wire).

    Returns
    -------
    FacetPullOff

    Examples
    --------
    >>> import linecontact as lc
    >>> hexagon = lc.facet_pull_off(1e3, 0.01, sides=6, corner_radius_over_R=0.0)
    >>> hexagon.mechanism, round(hexagon.F_pulloff_over_Eh, 6)
    ('corner-pinned', -5.452786)
    """
    scalar, shape, rho, s, n, r = checked(R_over_h, sigma0_over_E, sides, corner_radius_over_R)
    f = _b.facet_half_width(n, r)
    F, A, C, conv = _minimum(f, r, rho, s)
    C0, F0 = _zero_width(f, r, rho, s)
    # the vanishing-width end where the branch's lowest point is it to rounding (the load is
    # flat to 1e-15 at widths below 1e-4 R: the scan's lowest point there is any of them)
    with np.errstate(invalid="ignore"):
        zero = F0 <= F + 1e-12 * np.abs(F)
    if np.any(~conv & ~zero):
        _, at = first_point(~conv & ~zero, R_over_h=rho, sigma0_over_E=s, sides=n)
        raise ConvergenceError(
            f"facet_pull_off did not converge at {point_text(at)}, corner_radius_over_R="
            f"{float(np.reshape(r, -1)[np.argmax(~conv & ~zero)])!r}: the load of the branch "
            "falls on beyond the widest contact searched (1e12 times the facet's half-width "
            "plus four corner radii)"
        )
    conv = conv | zero
    F = np.where(zero, F0, F)
    A = np.where(zero, 0.0, A)
    C = np.where(zero, C0, C)
    pinned = (r == 0) & (C >= f * (1 - 1e-12)) & (A < f)
    mech = np.where(
        pinned,
        "corner-pinned",
        np.where(zero, "zero-width", np.where(A < f, "inside-facet", "whole-facet")),
    )
    # the parabolic corner stands for the corner's arc out to x = f + r_c sin(2 pi/n): an
    # adhesive zone beyond it reaches where the next facet is (docs/faceted.md, Sec. 1)
    beyond = (r > 0) & (C - f > r * np.sin(2 * np.pi / n))
    jkr = _cf._strip_pull_off(f, rho, s)  # -sqrt(2 pi f E w) / (E h), w = sigma0 h
    return as_result(
        FacetPullOff,
        scalar,
        shape,
        F_pulloff_over_Eh=F,
        a_over_R_at_pulloff=A,
        c_over_R_at_pulloff=C,
        mechanism=mech,
        F_zero_width_over_Eh=F0,
        facet_half_width_over_R=f,
        F_strip_jkr_over_Eh=jkr,
        F_strength_over_Eh=-2 * s * rho * f,
        beyond_corner_arc=beyond,
        R_over_h=rho,
        sigma0_over_E=s,
        sides=n.astype(int),
        corner_radius_over_R=r,
        converged=conv,
    )


def facet_contact_for_load(
    F_over_Eh: ArrayLike,
    R_over_h: ArrayLike,
    sigma0_over_E: ArrayLike,
    *,
    sides: ArrayLike = 6,
    corner_radius_over_R: ArrayLike = 0.0,
    on_failure: FailurePolicy = "raise",
) -> FacetContact:
    r"""The stable contact of a faceted wire under a load (the widest state carrying it).

    Parameters
    ----------
    F_over_Eh : array_like
        Load per unit length over ``E h`` (compressive positive), ``[-1e12, 1e12]``.
    R_over_h, sigma0_over_E, sides, corner_radius_over_R : array_like
        As in :func:`facet_contact`.
    on_failure : {"raise", "report"}
        A load below the pull-off force raises :class:`~linecontact.errors.NoEquilibriumError`
        (``"raise"``) or gives NaN at that point (``"report"``).

    Returns
    -------
    FacetContact
        At a sharp corner a load of at least zero holds the contact at the facet's edges
        (``a = c = f``, region ``"corner-pinned"``: the pressure is singular at the corners).
    """
    Ft = _domain.check("F_over_Eh", F_over_Eh)
    policy = failure_policy(on_failure)
    scalar, shape, rho, s, n, r = checked(R_over_h, sigma0_over_E, sides, corner_radius_over_R)
    scalar = scalar and np.ndim(Ft) == 0
    # (broadcast in two steps: a message names the parameters' common shape against the load)
    Ft, rho, s, n, r = broadcast(
        F_over_Eh=Ft,
        R_over_h=rho.reshape(shape),
        sigma0_over_E=s.reshape(shape),
        sides=n.reshape(shape),
        corner_radius_over_R=r.reshape(shape),
    )
    shape = Ft.shape
    Ft, rho, s, n, r = _flat(Ft, rho, s, n, r)
    f = _b.facet_half_width(n, r)
    rows = np.arange(Ft.size)
    # the scan with its vanishing-width end first (a = 0, the load F0: a load between F0
    # and the narrowest width's is carried by a narrower contact still)
    grid = _grid(f, r)
    F_grid, _ = _loads(grid, f, r, rho, s)
    A2 = np.concatenate([np.zeros((Ft.size, 1)), grid], axis=1)
    F2 = np.concatenate([_zero_width(f, r, rho, s)[1][:, None], F_grid], axis=1)
    # a load beyond the widest width's (a round corner): the scan goes on, wider
    K = A2.shape[1]
    end = K - 1 - np.argmax(np.isfinite(A2[:, ::-1]), axis=1)
    wide = (r > 0) & (F2[rows, end] < Ft)
    ext = np.full((Ft.size, _WIDER.size - 1), np.nan)  # (NaN: not solved, _loads)
    if wide.any():  # up to the domain's widest contact, a/R = 10
        top = _domain.DOMAIN["facet_a_over_R"][2]
        a_end = A2[wide, end[wide]]
        steps = np.linspace(0.0, 1.0, _WIDER.size)[None, 1:]
        ext[wide] = a_end[:, None] * (np.maximum(top / a_end, 1.0)[:, None] ** steps)
    F_ext, _ = _loads(ext, f, r, rho, s)
    A2 = np.concatenate([A2, ext], axis=1)
    F2 = np.concatenate([F2, F_ext], axis=1)
    too_wide = wide & ~(np.nanmax(np.where(np.isfinite(F_ext), F_ext, -np.inf), axis=1) >= Ft)
    if np.any(too_wide):
        _, at = first_point(too_wide, F_over_Eh=Ft, R_over_h=rho, sigma0_over_E=s)
        raise ParameterError(
            "F_over_Eh",
            f"the load at {point_text(at)} needs a contact wider than a/R = 10, the end of the "
            "domain of the solvers",
        )
    # the widest crossing of F = Ft where F rises with a (the loaded, stable branch)
    d = F2 - Ft[:, None]
    up = (d[:, :-1] < 0) & (d[:, 1:] >= 0) & np.isfinite(F2[:, 1:])
    K = A2.shape[1]
    last = np.where(up.any(axis=1), K - 2 - np.argmax(up[:, ::-1], axis=1), -1)
    found = last >= 0
    li = np.maximum(last, 0)
    lo = A2[rows, li]
    hi = A2[rows, li + 1]
    sharp_loaded = (r == 0) & (Ft >= 0)
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        Fm, _ = _loads(mid[:, None], f, r, rho, s)
        below = Fm[:, 0] < Ft
        lo = np.where(below, mid, lo)
        hi = np.where(below, hi, mid)
    A = np.where(found, 0.5 * (lo + hi), np.nan)
    A = np.where(sharp_loaded, f, A)
    if policy == "raise" and not np.all(np.isfinite(A)):
        _, at = first_point(~np.isfinite(A), F_over_Eh=Ft, R_over_h=rho, sigma0_over_E=s)
        raise NoEquilibriumError(
            f"no contact carries the load at {point_text(at)}: it is below the pull-off force "
            "(facet_pull_off); the wire has pulled off"
        )
    ok = np.isfinite(A)
    Aok = np.where(ok, A, 1.0)
    u, C, F, res, conv, pinned = branch(Aok, f, r, rho, s)
    C = np.where(sharp_loaded, f, C)
    F = np.where(ok, Ft, F)  # the load asked for: the state carries it to the bisection's last bit
    pinned |= sharp_loaded
    region = np.where(ok, regions(pinned, Aok, f), "no-equilibrium")
    nan = np.where(ok, 1.0, np.nan)
    C, F, res = C * nan, F * nan, res * nan
    return contact_result(shape, scalar, A, C, F, region, res, conv & ok, ok, rho, s, n, r, f)
