r"""The Lennard-Jones law of Eq. (1) in the paper's groups: pull-off, contact, load curve.

The functions of :mod:`linecontact.laws.dugdale` (:mod:`linecontact.normal`) for the Lennard-Jones
law, with the same names and argument order: :math:`R/h`, :math:`\sigma_0/E` in, loads over
:math:`E h`, widths over :math:`R`, gaps over :math:`h` out. The law keeps the Dugdale step's work
of adhesion :math:`w = \sigma_0 h` and its peak tension :math:`\sigma_0 = S w/z_0` (the Maugis
matching, :math:`S` = :data:`~linecontact.materials.MAUGIS_STRENGTH`), so :math:`z_0 = S h`; its one
group is :math:`\mu = w \sqrt{R/z_0}/(E z_0) = (\sigma_0/E) \sqrt{R/h}\, S^{-3/2}`, solved
self-consistently for :math:`\mu` within ``domain.DOMAIN["lj_mu"]`` (to 400, Maugis parameter 104;
``sigma0_over_E > 0``); the pull-off at every ``mu``, beyond that by the JKR limit with a fitted
correction.

The solver (:mod:`linecontact.lennard_jones`, in the law's own units: gaps over :math:`z_0`,
loads over :math:`w \sqrt{R/z_0}`) follows the load curve by the central gap far away and by the
edge of the contact nearer: a pull-off costs a few tenths of a second, a whole curve about a
second (``benchmarks/lennard_jones.py``).

This module is not :mod:`linecontact.lennard_jones`: that one is the solver in its own
units (``lj_pull_off(mu)``, ``lj_curve(mu)``, ...), and :mod:`linecontact.lennard_jones_groups`
(which holds the conversions used here) imports it, so the functions below cannot live there
without an import circle.
"""

from __future__ import annotations

from numpy.typing import ArrayLike

from .. import domain as _domain
from .._validation import FailurePolicy, broadcast, failure_policy, scalar_or_array
from ..lennard_jones import LennardJonesPullOff, pull_off_in_dugdale_groups
from ..lennard_jones_groups import (
    LJ_LOAD_MAX,
    BelowPullOffError,
    LennardJonesContact,
    LennardJonesLoadCurve,
    contact_for_load_in_dugdale_groups,
    load_curve_in_dugdale_groups,
)

__all__ = [
    "LJ_LOAD_MAX",
    "BelowPullOffError",
    "LennardJonesContact",
    "LennardJonesLoadCurve",
    "LennardJonesPullOff",
    "contact_for_load",
    "load_curve",
    "pull_off",
]


def pull_off(R_over_h: ArrayLike, sigma0_over_E: ArrayLike) -> LennardJonesPullOff:
    """Pull-off force under the Lennard-Jones law, vectorised over parameter points.

    The most tensile load of the law's curve (jump-out under load control), refined
    between the states of the continuation, with its discretisation error.

    Parameters
    ----------
    R_over_h : array_like
        ``> 0``.
    sigma0_over_E : array_like
        ``> 0`` (it sets the work of adhesion); every ``mu`` (beyond
        ``domain.DOMAIN["lj_mu"]`` the limit form, ``method == "limit"``).

    Returns
    -------
    LennardJonesPullOff
        Scalars for scalar inputs, arrays of the broadcast shape otherwise.

    See Also
    --------
    linecontact.pull_off : the same under the Maugis--Dugdale law.
    """
    rho = _domain.check("R_over_h", R_over_h)
    s = _domain.check("sigma0_over_E", sigma0_over_E)
    scalar = scalar_or_array(rho, s)
    rho, s = broadcast(R_over_h=rho, sigma0_over_E=s)
    return pull_off_in_dugdale_groups(
        rho.reshape(()) if scalar else rho, s.reshape(()) if scalar else s
    )


def contact_for_load(
    F_over_Eh: ArrayLike,
    R_over_h: ArrayLike,
    sigma0_over_E: ArrayLike,
    *,
    on_failure: FailurePolicy = "raise",
) -> LennardJonesContact:
    r"""The contact carrying a given load under the Lennard-Jones law (the stable branch).

    Parameters
    ----------
    F_over_Eh : array_like
        Load over ``E h`` (compressive positive), up to :data:`LJ_LOAD_MAX` :math:`w \sqrt{R/z_0}`.
    R_over_h, sigma0_over_E : array_like
        As in :func:`pull_off`.
    on_failure : {"raise", "report"}
        For a load below the pull-off force: raise :class:`BelowPullOffError` (a
        :class:`~linecontact.errors.NoEquilibriumError`; default), or report the point with
        ``state == "no-equilibrium"`` and NaN values.

    Returns
    -------
    LennardJonesContact
        ``a_over_R`` is the half-width of the repulsive region (the gap below ``z0``).

    Raises
    ------
    NoEquilibriumError
        For a load below the pull-off force, naming it.
    ConvergenceError
        If the solver's search fails.

    See Also
    --------
    linecontact.contact_for_load : the same under the Maugis--Dugdale law.
    """
    F = _domain.check("F_over_Eh", F_over_Eh)
    rho = _domain.check("R_over_h", R_over_h)
    s = _domain.check("sigma0_over_E", sigma0_over_E)
    policy = failure_policy(on_failure)
    scalar = scalar_or_array(F, rho, s)
    F, rho, s = broadcast(F_over_Eh=F, R_over_h=rho, sigma0_over_E=s)
    return contact_for_load_in_dugdale_groups(F, rho, s, scalar=scalar, on_failure=policy)


def load_curve(
    R_over_h: float, sigma0_over_E: float, *, F_max_over_Eh: float | None = None
) -> LennardJonesLoadCurve:
    r"""The load curve under the Lennard-Jones law (scalar parameters), pull-off included.

    The states of the solver's continuation in the central gap, from far away through the
    pull-off (and, where the curve is S-shaped, the jump-in) to ``F_max_over_Eh``.

    Parameters
    ----------
    R_over_h, sigma0_over_E : float
        As in :func:`pull_off` (scalars).
    F_max_over_Eh : float, optional
        The compressive load where the curve ends (default: :math:`7.5\, w \sqrt{R/z_0}`,
        three times the rigid cylinder's pull-off; at most :data:`LJ_LOAD_MAX`
        :math:`w \sqrt{R/z_0}`).

    Returns
    -------
    LennardJonesLoadCurve

    See Also
    --------
    linecontact.load_curve : the same under the Maugis--Dugdale law.
    """
    rho = _domain.scalar("R_over_h", R_over_h)
    s = _domain.scalar("sigma0_over_E", sigma0_over_E)
    return load_curve_in_dugdale_groups(rho, s, F_max_over_Eh)
