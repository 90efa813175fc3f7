r"""The load curve of a faceted wire on its facet: :func:`facet_load_curve`.

The contact branch from its vanishing-width end (:math:`a = 0`, the load
:math:`F_0` of ``docs/faceted.md``, Sec. 3) to a largest width, the pull-off marked; units
as in :mod:`linecontact.facet`. The non-contact branch (the facet held off the substrate at
a central gap below ``h``) is not sampled for a polygon: the curve begins at touch-down.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import ClassVar

import numpy as np
from numpy.typing import NDArray

from .. import domain as _domain
from ..errors import NoEquilibriumError, ParameterError
from ..normal.curve import NUM_MAX, _LoadCurveBase
from .contact import INPUTS, check_geometry, facet_contact
from .pulloff import FacetPullOff, _zero_width, facet_contact_for_load, facet_pull_off


@dataclass(frozen=True)
class FacetLoadCurve(_LoadCurveBase):
    """The load curve of a faceted wire: its contact branch, the pull-off marked.

    Arrays are ordered from the vanishing-width end (``a = 0``) to the largest width; their
    fields are those of the round wire's :class:`~linecontact.normal.LoadCurve` (so that the
    SI layer writes both alike), with the contact's ``region``.

    Attributes
    ----------
    branch : ndarray of str
        ``"contact"`` (the curve begins at touch-down).
    central_gap_over_h : ndarray
        0 (in contact).
    a_over_R, c_over_R, F_over_Eh : ndarray
        The states (lengths over the circumradius).
    region : ndarray of str
        As in :class:`~linecontact.facet.FacetContact`.
    stable : ndarray of bool
        Stability under load control.
    turning_point : ndarray of bool
        Marks the pull-off: the lowest load of the branch (the first point where it is the
        vanishing-width end).
    pulloff : FacetPullOff
        The pull-off result.
    """

    inputs: ClassVar[tuple[str, ...]] = INPUTS

    region: NDArray
    stable: NDArray
    turning_point: NDArray
    R_over_h: float
    sigma0_over_E: float
    sides: int
    corner_radius_over_R: float
    pulloff: FacetPullOff = field(repr=False)


def _default_end(po: FacetPullOff, rho: float, s: float, n: int, r: float) -> float:
    """The largest width of the curve: the facet's edge, or the contact at 10 |F_pull-off|.

    For a sharp corner the facet's edge; else the contact at ten times the pull-off force
    in compression, at least 1.2 times the facet's half-width.
    """
    f = float(po.facet_half_width_over_R)
    if r == 0:
        return f
    load = 10 * max(abs(float(po.F_pulloff_over_Eh)), 1e-3)
    try:
        a = float(facet_contact_for_load(load, rho, s, sides=n, corner_radius_over_R=r).a_over_R)
    except NoEquilibriumError:  # beyond the widths the scan solves: its end
        a = f + 2 * r
    return max(a, 1.2 * f)


def facet_load_curve(
    R_over_h: float,
    sigma0_over_E: float,
    *,
    sides: int = 6,
    corner_radius_over_R: float = 0.0,
    a_max_over_R: float | None = None,
    num: int = 200,
) -> FacetLoadCurve:
    r"""Sample the load curve of a faceted wire (scalar parameters), the pull-off marked.

    Parameters
    ----------
    R_over_h, sigma0_over_E, sides, corner_radius_over_R : float or int
        As in :func:`~linecontact.facet.facet_pull_off` (scalars).
    a_max_over_R : float, optional
        The largest contact half-width. Default: the facet's half-width for a sharp corner
        (where a compressive load holds the contact, ``a = f``); else the width at ten times
        the pull-off force in compression, at least 1.2 times the facet's half-width.
    num : int
        Points of the branch, in ``[2, 10**7]`` (the pull-off's and the facet's edge added).

    Returns
    -------
    FacetLoadCurve

    Examples
    --------
    >>> c = facet_load_curve(171.0, 0.00684, sides=6, corner_radius_over_R=0.1, num=50)
    >>> bool(abs(c.F_over_Eh[c.turning_point][0] - c.pulloff.F_pulloff_over_Eh) < 1e-12)
    True
    """
    rho = _domain.scalar("R_over_h", R_over_h)
    s = _domain.scalar("sigma0_over_E", sigma0_over_E)
    n_, r_ = check_geometry(sides, corner_radius_over_R)
    if n_.ndim or r_.ndim:
        raise ParameterError("sides", "sides and corner_radius_over_R must be single numbers")
    n, r = int(n_), float(r_)
    if isinstance(num, bool) or not isinstance(num, int | np.integer) or not 2 <= num <= NUM_MAX:
        raise ParameterError("num", f"num must be an integer in [2, {NUM_MAX}], got {num!r}")
    po = facet_pull_off(rho, s, sides=n, corner_radius_over_R=r)
    f = float(po.facet_half_width_over_R)
    if a_max_over_R is None:
        a_max_over_R = _default_end(po, rho, s, n, r)
    amax = _domain.scalar("a_max_over_R", a_max_over_R, "facet_a_over_R")
    if r == 0 and amax > f:
        raise ParameterError(
            "a_max_over_R",
            f"a_max_over_R must be at most the facet's half-width {f!r} for a sharp corner "
            f"(corner_radius_over_R = 0), got {amax!r}",
        )
    lo = max(amax * 1e-4, _domain.DOMAIN["facet_a_over_R"][0])
    parts = [np.geomspace(lo, amax, num // 2), np.linspace(amax / num, amax, num - num // 2)]
    a_po = float(po.a_over_R_at_pulloff)
    extra = [x for x in (f, a_po) if 0 < x <= amax]  # the pull-off's own width, however small
    A = np.unique(np.concatenate([*parts, extra]))
    c = facet_contact(A, rho, s, sides=n, corner_radius_over_R=r)
    # the vanishing-width end first: a = 0, the zone's end and load of its quadratic
    C0, F0 = _zero_width(*(np.array([v], float) for v in (f, r, rho, s)))
    A = np.concatenate([[0.0], c.a_over_R])
    C = np.concatenate([C0, c.c_over_R])
    F = np.concatenate([F0, c.F_over_Eh])
    end = "corner-pinned" if r == 0 and C0[0] >= f else "inside-facet" if f > 0 else "whole-facet"
    region = np.concatenate([[end], c.region])
    stable_ = np.asarray(c.stable, bool)
    stable = np.concatenate([stable_[:1], stable_])  # the end as its nearest state
    turning = np.zeros(A.size, bool)
    turning[int(np.argmin(np.abs(A - a_po)))] = True
    return FacetLoadCurve(
        branch=np.full(A.size, "contact"),
        central_gap_over_h=np.zeros(A.size),
        a_over_R=A,
        c_over_R=C,
        F_over_Eh=F,
        region=region,
        stable=stable,
        turning_point=turning,
        R_over_h=rho,
        sigma0_over_E=s,
        sides=n,
        corner_radius_over_R=r,
        pulloff=po,
    )
