"""The problems of :class:`~linecontact.cylinder.Cylinder` in SI units, one short method each.

Each method wraps its implementation in ``_problems.py`` (or ``_sliding.py``), which takes
the cylinder as its first argument and does not import :class:`Cylinder`: so
``_cylinder.py`` imports this module, and no import closes a circle.
"""

from __future__ import annotations

from typing import Literal

from numpy.typing import ArrayLike

from .._validation import FailurePolicy
from ._problems import (
    _cyclic_loss,
    _pushed_fibre,
    _sliding_initiation,
    _steady_rolling,
    _tangential_history,
)
from ._results import (
    CylinderCyclicLoss,
    CylinderPush,
    CylinderSliding,
    CylinderTangential,
    CylinderTangentialHistory,
)
from ._sliding import _sliding


class _Problems:
    """The SI problems of a cylinder (the base of :class:`Cylinder`)."""

    def sliding_initiation(
        self,
        normal_load: ArrayLike,
        *,
        friction_stress: ArrayLike | None = None,
        friction_coefficient: ArrayLike | None = None,
        d_over_a: ArrayLike | None = None,
        tangential_load: ArrayLike | None = None,
        method: str = "closed-form",
        on_failure: FailurePolicy = "raise",
    ) -> CylinderTangential:
        """Initiation of sliding under ``normal_load`` [N/m] (Eqs 15-17, SI units).

        Exactly one of ``friction_stress`` ``tau0`` [Pa] and ``friction_coefficient`` ``mu``
        (Coulomb, no adhesion); exactly one of ``d_over_a`` (the stick zone over ``a``) and
        ``tangential_load`` [N/m]. A load at or above full slip raises
        :class:`~linecontact.errors.NoEquilibriumError` (``on_failure="raise"``) or gives
        ``state == "sliding"`` (``"report"``).

        Examples
        --------
        >>> from linecontact import Cylinder
        >>> cyl = Cylinder.from_modulus(50e-9, 100e9, cohesive_stress=1e9, adhesion_range=0.5e-9)
        >>> cyl.sliding_initiation(1.0, friction_stress=1e9, tangential_load=1.0).state
        'stick-slip'
        """
        return _sliding_initiation(
            self,
            normal_load,
            friction_stress=friction_stress,
            friction_coefficient=friction_coefficient,
            d_over_a=d_over_a,
            tangential_load=tangential_load,
            method=method,
            on_failure=on_failure,
        )

    def steady_rolling(
        self,
        normal_load: ArrayLike,
        *,
        friction_stress: ArrayLike | None = None,
        friction_coefficient: ArrayLike | None = None,
        d_over_a: ArrayLike | None = None,
        tangential_load: ArrayLike | None = None,
        method: str = "closed-form",
        on_failure: FailurePolicy = "raise",
    ) -> CylinderTangential:
        r"""Steady rolling of a driving cylinder under ``normal_load`` [N/m] (Eqs 23-29).

        The arguments of :meth:`sliding_initiation`, with ``d_over_a`` in ``(-1, 1)`` the start
        of the leading-edge stick zone and ``tangential_load`` the tractive force [N/m]; the
        result's ``creep_ratio`` is :math:`(V - \omega R)/V` (negative).
        """
        return _steady_rolling(
            self,
            normal_load,
            friction_stress=friction_stress,
            friction_coefficient=friction_coefficient,
            d_over_a=d_over_a,
            tangential_load=tangential_load,
            method=method,
            on_failure=on_failure,
        )

    def push(
        self,
        *,
        friction_stress: float,
        height: ArrayLike,
        receding_range: float | None = None,
        receding_work_of_adhesion: float | None = None,
        normal_load: ArrayLike = 0.0,
        push: ArrayLike | None = None,
        tip_friction: ArrayLike | None = None,
        length: float | None = None,
    ) -> CylinderPush:
        r"""Will the cylinder, pushed at ``height`` [m], stay, roll or slide (``docs/push.md``).

        The cylinder's adhesion is the advancing one (range ``h2``); the receding edge's range
        :math:`h_1 \ge h_2` is ``receding_range`` [m] or ``receding_work_of_adhesion`` [J/m^2]
        (exactly one); ``friction_stress`` ``tau0`` [Pa], ``normal_load`` [N/m], a ``push``
        [N/m] whose state is wanted, a tip's ``tip_friction``, the fibre's ``length`` [m].

        Examples
        --------
        >>> from linecontact import Cylinder, adhesion_from_work
        >>> s0, h1 = adhesion_from_work(0.05, 0.3e-9)  # receding work of adhesion
        >>> h2 = 0.025 / s0  # the advancing range, of the advancing work of adhesion
        >>> cyl = Cylinder.from_modulus(50e-9, 48.4e9, cohesive_stress=s0, adhesion_range=h2)
        >>> p = cyl.push(friction_stress=1e6, height=[25e-9, 50e-9], receding_range=h1)
        >>> [str(m) for m in p.first_motion]
        ['slide', 'roll']
        """
        return _pushed_fibre(
            self,
            friction_stress=friction_stress,
            height=height,
            receding_range=receding_range,
            receding_work_of_adhesion=receding_work_of_adhesion,
            normal_load=normal_load,
            push=push,
            tip_friction=tip_friction,
            length=length,
        )

    def tangential_history(
        self,
        normal_load: float,
        tangential_load: ArrayLike,
        *,
        friction_stress: float | None = None,
        friction_coefficient: float | None = None,
        method: str = "closed-form",
    ) -> CylinderTangentialHistory:
        """The states along a history of ``tangential_load`` [N/m] at a fixed ``normal_load``.

        Exactly one of ``friction_stress`` ``tau0`` [Pa] and ``friction_coefficient`` ``mu``;
        ``method`` as in :func:`linecontact.tangential_history` (``docs/load-histories.md``).
        """
        return _tangential_history(
            self,
            normal_load,
            tangential_load,
            friction_stress=friction_stress,
            friction_coefficient=friction_coefficient,
            method=method,
        )

    def cyclic_loss(
        self,
        normal_load: float,
        amplitude: ArrayLike,
        *,
        friction_stress: float | None = None,
        friction_coefficient: float | None = None,
        method: str = "closed-form",
    ) -> CylinderCyclicLoss:
        """The energy dissipated per cycle between ``-amplitude`` and ``+amplitude`` [N/m].

        At a fixed ``normal_load`` [N/m]; exactly one of ``friction_stress`` ``tau0`` [Pa] and
        ``friction_coefficient`` ``mu``; ``method`` as in :func:`linecontact.cyclic_loss`.
        """
        return _cyclic_loss(
            self,
            normal_load,
            amplitude,
            friction_stress=friction_stress,
            friction_coefficient=friction_coefficient,
            method=method,
        )

    def sliding(
        self,
        *,
        receding_range: float | None = None,
        h1_over_h2: float | None = None,
        contact_half_width: ArrayLike | None = None,
        load: ArrayLike | None = None,
        friction_stress: float | None = None,
        method: Literal["closed-form", "collocation"] = "collocation",
        on_failure: FailurePolicy = "raise",
    ) -> CylinderSliding:
        """Steady sliding in SI units (Eqs 18-22; :func:`~linecontact.sliding.sliding_contact`).

        The cylinder's range is the leading edge's ``h2``; the trailing edge's ``h1`` [m] is
        ``receding_range`` (or give ``h1_over_h2``); ``contact_half_width`` [m] or ``load``
        [N/m]; ``friction_stress`` ``tau0`` [Pa] adds the friction force. Returns the SI
        :class:`CylinderSliding` (its ``nondimensional`` the
        :class:`~linecontact.sliding.SlidingContact`, in :math:`h = h_2`).
        """
        return _sliding(
            self,
            receding_range=receding_range,
            h1_over_h2=h1_over_h2,
            contact_half_width=contact_half_width,
            load=load,
            friction_stress=friction_stress,
            method=method,
            on_failure=on_failure,
        )
