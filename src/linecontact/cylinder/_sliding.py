"""Steady sliding of a cylinder in SI units (Eqs 18-22).

The function ``sliding`` is the method :meth:`Cylinder.sliding <linecontact.Cylinder.sliding>`
(the class binds it); ``self`` is the cylinder.
"""

from __future__ import annotations

from typing import Any, Literal

import numpy as np
from numpy.typing import ArrayLike

from .. import domain as _domain
from .._validation import FailurePolicy, check_array, failure_policy, positive, scalar
from ..units import Scales, to_si
from ._checks import _small_strain_in_si, _too_wide, _warn_small_strain
from ._results import CylinderSliding


def sliding(
    self: Any,
    *,
    receding_range: float | None = None,
    h1_over_h2: float | None = None,
    contact_half_width: ArrayLike | None = None,
    load: ArrayLike | None = None,
    friction_stress: float | None = None,
    method: Literal["closed-form", "collocation"] = "collocation",
    on_failure: FailurePolicy = "raise",
) -> CylinderSliding:
    r"""Steady sliding in SI units (Eqs 18-22; :func:`~linecontact.sliding.sliding_contact`).

    The cylinder's adhesion is the leading (advancing) edge's: ``sigma0`` and the range
    ``h2``; the trailing (receding) edge has the same ``sigma0`` and the range ``h1``.

    Parameters
    ----------
    receding_range : float, optional
        ``h1`` [m]; or give ``h1_over_h2`` (exactly one).
    contact_half_width : array_like, optional
        ``a`` [m]; or give ``load`` [N/m], compressive positive (exactly one): the stable
        sliding contact that carries it (:func:`~linecontact.sliding.sliding_contact_for_load`).
    friction_stress : float, optional
        ``tau0`` [Pa], ``>= 0``: adds the friction force :math:`2 a \tau_0`.
    method, on_failure
        As in :func:`~linecontact.sliding.sliding_contact`.

    Returns
    -------
    CylinderSliding
        The SI result (:func:`linecontact.units.to_si` of the nondimensional
        :class:`~linecontact.sliding.SlidingContact`, in :math:`h = h_2`, its ``nondimensional``);
        ``receding_range`` is the trailing range used, ``total(length)`` the totals over a
        fibre.
    """
    from ..sliding import sliding_contact, sliding_contact_for_load

    self._written("sliding")
    policy = failure_policy(on_failure)
    if (receding_range is None) == (h1_over_h2 is None):
        raise ValueError("give exactly one of receding_range [m] or h1_over_h2")
    if (contact_half_width is None) == (load is None):
        raise ValueError("give exactly one of contact_half_width [m] or load [N/m]")
    if receding_range is not None:
        h1 = positive("receding_range", receding_range)
        _domain.check_si("receding_range", h1, self.adhesion_range, "h1_over_h2", "m")
        h1_over_h2 = self.over(h1, "h")
    tau = None
    if friction_stress is not None:
        t = scalar("friction_stress", friction_stress, low=0.0, low_inclusive=True)
        _domain.check_si("friction_stress", t, self.modulus, "friction_tau0_over_E", "Pa")
        tau = self.over(t, "E")
    groups: tuple[Any, Any, Any] = (self.R_over_h, h1_over_h2, self.sigma0_over_E)
    if contact_half_width is not None:
        a = positive("contact_half_width", contact_half_width)
        _domain.check_si("contact_half_width", a, self.radius, "sliding_a_over_R", "m")
        with _small_strain_in_si():  # said in metres below
            res = sliding_contact(
                self.over(a, "R"), *groups, tau0_over_E=tau, method=method, on_failure=policy
            )
    else:
        F = check_array("load", load, low=-np.inf, low_inclusive=True)  # type: ignore[arg-type]
        _domain.check_si("load", F, self.scale("Eh"), "F_over_Eh2", "N/m")
        try:
            with _small_strain_in_si():
                res = sliding_contact_for_load(
                    self.over(F, "Eh"),
                    *groups,
                    tau0_over_E=tau,
                    method=method,
                    on_failure=policy,
                )
        except _domain.TooWideError as e:
            raise _too_wide("load", float(np.reshape(F, -1)[e.index]), e, self.radius) from None
    out = _si(self, res)
    _warn_small_strain(out.contact_half_width, self.radius, stacklevel=4)  # the caller's
    return out


def _si(cylinder: Any, res: Any) -> CylinderSliding:
    """The SI form of the nondimensional sliding result ``res`` (in :math:`h = h_2`)."""
    scales = Scales.of(cylinder)
    h1 = float(np.reshape(res.h1_over_h2, -1)[0]) * scales["h"]  # one h1 for all the points
    return CylinderSliding(
        **to_si(res, scales),
        receding_range=h1,
        converged=res.converged,
        stable=res.stable,
        state=res.state,
        nondimensional=res,
        scales=scales,
    )


def sliding_pull_off_force(cylinder: Any, h1_over_h2: float) -> float:
    """The pull-off force of steady sliding [N/m] (``nan`` without adhesion)."""
    from ..sliding import sliding_pull_off

    if cylinder.cohesive_stress == 0:
        return float("nan")
    po = sliding_pull_off(cylinder.R_over_h, h1_over_h2, cylinder.sigma0_over_E)
    return float(cylinder.in_si(po.F_pulloff_over_Eh2, "Eh"))


def hysteresis_adhesion(
    receding_work_of_adhesion: float, advancing_work_of_adhesion: float, equilibrium_spacing: float
) -> tuple[float, float, float]:
    r"""``(sigma0 [Pa], h2 [m], h1 [m])`` of a receding and an advancing work of adhesion.

    One ``sigma0``, that of the receding ``w1`` with ``z0`` (the Maugis convention of
    :func:`~linecontact.adhesion_from_work`, which gives ``h1``); the advancing range
    :math:`h_2 = w_2 / \sigma_0`. A cylinder with ``(sigma0, h2)`` and the receding range ``h1`` is
    the pushed or sliding fibre of :meth:`Cylinder.push <linecontact.Cylinder.push>`.
    """
    from ..materials import adhesion_from_work

    s0, h1 = adhesion_from_work(receding_work_of_adhesion, equilibrium_spacing)
    return float(s0), float(advancing_work_of_adhesion / s0), float(h1)
