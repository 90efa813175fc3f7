r"""The load curve (:func:`load_curve`): the contact and non-contact branches joined."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import ClassVar

import numpy as np
from numpy.typing import NDArray

from .. import closed_forms as _cf
from .. import domain as _domain
from ..results import SI, Result
from .contact import normal_contact
from .noncontact import non_contact
from .pulloff import PullOff, pull_off

#: The most points :func:`load_curve` samples on either branch.
NUM_MAX = 10**7


@dataclass(frozen=True)
class _LoadCurveBase(Result):
    """The fields that open a load curve: each state's branch, gap, widths and load.

    Those of :class:`LoadCurve` and of the faceted wire's
    :class:`~linecontact.facet.FacetLoadCurve` (the SI layer writes both alike).
    """

    branch: NDArray
    central_gap_over_h: NDArray = field(metadata=SI("central_gap", "h", "m"))
    a_over_R: NDArray = field(metadata=SI("contact_half_width", "R", "m"))
    c_over_R: NDArray = field(metadata=SI("adhesive_zone_half_width", "R", "m"))
    F_over_Eh: NDArray = field(metadata=SI("load", "Eh", "N/m"))


@dataclass(frozen=True)
class LoadCurve(_LoadCurveBase):
    """The whole load curve: non-contact branch then the contact branch.

    Arrays are ordered from the largest central gap (:math:`g_0 = h`, :math:`F = 0`) through
    touch-down (:math:`a = 0`, Eq. 14) to the largest contact width.

    Attributes
    ----------
    branch : ndarray of str
        ``"non-contact"`` or ``"contact"``.
    central_gap_over_h, a_over_R, c_over_R, F_over_Eh : ndarray
        The states (:math:`a = 0` off contact, :math:`g_0 = 0` in contact).
    stable : ndarray of bool
        Stability under load control.
    turning_point : ndarray of bool
        Marks the load minimum (the single turning point of the contact branch).
    pulloff : PullOff
        The pull-off result.
    """

    inputs: ClassVar[tuple[str, ...]] = ("R_over_h", "sigma0_over_E")

    stable: NDArray
    turning_point: NDArray
    R_over_h: float
    sigma0_over_E: float
    pulloff: PullOff = field(repr=False)


def load_curve(
    R_over_h: float,
    sigma0_over_E: float,
    *,
    a_max_over_R: float | None = None,
    num: int = 200,
    num_noncontact: int = 40,
) -> LoadCurve:
    r"""Sample the load curve (scalar parameters), pull-off and turning point included.

    Parameters
    ----------
    R_over_h, sigma0_over_E : float
        Parameters (scalars).
    a_max_over_R : float, optional
        Largest contact half-width; default: three times the width at pull-off, at least the Hertz
        width at :math:`F = 10\, |F_\text{pull-off}|` and at least ``0.02``, but at most the
        small-strain limit :data:`~linecontact.closed_forms.A_OVER_R_SMALL_STRAIN` (or 1.5 times the
        width at pull-off, if that is larger), and never beyond :math:`a/R = 10`, the end of the
        domain (where the pull-off is wider still, the curve stops short of it).
    num, num_noncontact : int
        Points on the contact and the non-contact branches, each in ``[2, NUM_MAX]``
        (``NUM_MAX = 10**7``: a few hundred MB of samples; more is refused up front rather
        than failing in NumPy's allocator).

    Returns
    -------
    LoadCurve
        (The Lennard-Jones law's: :func:`linecontact.laws.lennard_jones.load_curve`.)
    """
    rho = _domain.scalar("R_over_h", R_over_h)
    s = _domain.scalar("sigma0_over_E", sigma0_over_E)
    for name, v in (("num", num), ("num_noncontact", num_noncontact)):
        if isinstance(v, bool) or not isinstance(v, (int, np.integer)) or not 2 <= v <= NUM_MAX:
            raise ValueError(f"{name} must be an integer in [2, {NUM_MAX}], got {v!r}")
    po = pull_off(rho, s)
    if a_max_over_R is None:
        a_po = float(po.a_over_R_at_minimum)
        a_h = float(np.sqrt(4 * 10 * abs(float(po.F_pulloff_over_Eh)) / (np.pi * rho)))
        # within the small-strain range unless the pull-off itself is close to its end
        # and never beyond the domain of the solvers (a pull-off wider than that is cut off)
        cap = min(max(_cf.A_OVER_R_SMALL_STRAIN, 1.5 * a_po), _domain.DOMAIN["a_over_R"][2])
        a_max_over_R = min(max(3 * a_po, a_h, 0.02), cap)
    amax = _domain.scalar("a_max_over_R", a_max_over_R)
    A = np.unique(
        np.concatenate(
            [
                np.geomspace(amax * 1e-4, amax, num // 2),
                np.linspace(amax / num, amax, num - num // 2),
            ]
        )
    )
    # the minimum is a point of the curve (unless narrower than the domain: for small kappa
    # it sits at widths like 1e-152 R, its load within round-off of the zero-width load)
    at_min = _domain.DOMAIN["a_over_R"][0] <= po.a_over_R_at_minimum < amax
    if at_min:
        A = np.unique(np.append(A, po.a_over_R_at_minimum))
    nc = normal_contact(A, rho, s)
    parts_branch = []
    gaps = np.linspace(1.0, 0.0, num_noncontact) if s > 0 else np.array([])
    if gaps.size:
        ncb = non_contact(gaps, rho, s)
        parts_branch = ["non-contact"] * gaps.size
        g_nc, c_nc, F_nc = ncb.central_gap_over_h, ncb.c_over_R, ncb.F_over_Eh
    else:
        g_nc = c_nc = F_nc = np.array([])
    branch = np.array(parts_branch + ["contact"] * A.size)
    gap = np.concatenate([g_nc, np.zeros(A.size)])
    a = np.concatenate([np.zeros(gaps.size), A])
    c = np.concatenate([c_nc, nc.c_over_R])
    F = np.concatenate([F_nc, nc.F_over_Eh])
    stable = np.concatenate([np.zeros(gaps.size, bool), nc.stable])
    turning = np.zeros(a.size, bool)
    if at_min:
        turning[gaps.size + int(np.argmin(np.abs(A - po.a_over_R_at_minimum)))] = True
    return LoadCurve(branch, gap, a, c, F, stable, turning, rho, s, po)
