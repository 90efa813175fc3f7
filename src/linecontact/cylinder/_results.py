"""The SI result classes of the cylinder's problems (frozen dataclasses, each a ``Result``).

Their SI fields are built by :func:`linecontact.units.to_si` from the scales that their
nondimensional results declare.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, ClassVar

import numpy as np
from numpy.typing import NDArray

from .. import normal as _normal
from .._validation import positive
from ..results import Result
from ..units import Scales

if TYPE_CHECKING:  # imported where used: the Lennard-Jones solver needs scipy
    from ..lennard_jones_groups import LennardJonesContact, LennardJonesLoadCurve
    from ..sliding import SlidingContact


class _PerLength:
    """The totals over a fibre of the per-unit-length SI fields listed in ``per_length``."""

    #: The SI fields per unit length (N/m, N m/m) that :meth:`total` multiplies by a length.
    per_length: ClassVar[tuple[str, ...]] = ()
    nondimensional: Any  # a field of the result (the mixin declares no field)

    def total(self, length: float) -> dict[str, Any]:
        """Each field of ``per_length`` over a fibre of ``length`` [m]: the field times it.

        ``{"load": F * L, ...}`` ([N/m] times [m]: [N]; a moment [N m/m] gives [N m]). A
        result that keeps its ``scales`` forms it from its nondimensional group, as the
        group times the scale's total over the fibre (``F_over_Eh * (E h L)``).
        """
        L = positive("length", length)
        scales = getattr(self, "scales", None)
        if scales is None:
            return {k: np.multiply(getattr(self, k), L) for k in self.per_length}
        nd = self.nondimensional
        groups = {name: (f, scale) for f, (name, scale, _) in type(nd).si.items()}
        out = {}
        for k in self.per_length:
            f, scale = groups[k]
            out[k] = np.multiply(getattr(nd, f), scales[scale] * L)
        return out


@dataclass(frozen=True)
class CylinderContact(_PerLength, Result):
    """A normal contact state in SI units, with its nondimensional result.

    Attributes
    ----------
    contact_half_width : ndarray or float
        ``a`` [m].
    adhesive_zone_half_width : ndarray or float
        ``c`` [m].
    load : ndarray or float
        ``F`` [N/m], compressive positive.
    stable : ndarray or bool
        Stable under load control.
    state : ndarray of str or str
        ``"contact"``, or ``"no-equilibrium"`` for a load no contact carries (reported with
        ``on_failure="report"``; its values are NaN).
    nondimensional : NormalContact
        The underlying result with diagnostics.
    scales : Scales or None
        The cylinder's scales, for :meth:`total` (None: the SI value times the length).
    """

    per_length: ClassVar[tuple[str, ...]] = ("load",)

    contact_half_width: NDArray | float
    adhesive_zone_half_width: NDArray | float
    load: NDArray | float
    stable: NDArray | bool
    state: NDArray | str
    nondimensional: _normal.NormalContact = field(repr=False)
    scales: Scales | None = field(default=None, repr=False)


@dataclass(frozen=True)
class CylinderPullOff(_PerLength, Result):
    """Pull-off in SI units.

    Attributes
    ----------
    pull_off_force : float
        [N/m], negative.
    contact_half_width_at_pull_off : float
        [m], 0 at zero width.
    mechanism : str
        ``"snap-off"`` or ``"zero-width"``.
    zero_width_force : float
        Eq. (14) [N/m].
    nondimensional : PullOff
    """

    per_length: ClassVar[tuple[str, ...]] = ("pull_off_force",)

    pull_off_force: NDArray | float
    contact_half_width_at_pull_off: NDArray | float
    mechanism: NDArray | str
    zero_width_force: NDArray | float
    nondimensional: _normal.PullOff = field(repr=False)


@dataclass(frozen=True)
class CylinderLennardJonesContact(_PerLength, Result):
    """A contact state under the Lennard-Jones law in SI units, with its nondimensional result.

    Attributes
    ----------
    contact_half_width : ndarray or float
        Half-width of the repulsive region (the gap below ``z0``) [m]; 0 where there is none.
    central_gap : ndarray or float
        The gap at the centre [m].
    load : ndarray or float
        ``F`` [N/m], compressive positive: the load asked for.
    error_estimate : ndarray or float
        Estimated discretisation error of the state's load [N/m].
    stable : ndarray or bool
        Stable under load control (the branch beyond the pull-off).
    state : ndarray of str or str
        ``"contact"``, or ``"no-equilibrium"`` for a load below the pull-off force (reported
        with ``on_failure="report"``; its values are NaN).
    nondimensional : LennardJonesContact
        The underlying result (Dugdale groups) with its diagnostics.
    scales : Scales or None
        The cylinder's scales, for :meth:`total` (None: the SI value times the length).
    """

    per_length: ClassVar[tuple[str, ...]] = ("load",)

    contact_half_width: NDArray | float
    central_gap: NDArray | float
    load: NDArray | float
    error_estimate: NDArray | float
    stable: NDArray | bool
    state: NDArray | str
    nondimensional: LennardJonesContact = field(repr=False)
    scales: Scales | None = field(default=None, repr=False)


@dataclass(frozen=True)
class CylinderLennardJonesPullOff(_PerLength, Result):
    """Pull-off under the Lennard-Jones law in SI units.

    Attributes
    ----------
    pull_off_force : float
        [N/m], negative: the most tensile load of the curve.
    error_estimate : float
        Its estimated discretisation error [N/m].
    contact_half_width_at_pull_off : float
        Half-width of the repulsive region there [m] (0: the pull-off precedes it).
    central_gap_at_pull_off : float
        [m].
    jump_in_force : float
        The jump-in load where the curve is S-shaped [N/m], else ``nan``.
    method : str
        ``"self-consistent"`` or ``"limit"`` (the corrected JKR limit beyond the
        self-consistent solver's domain; its error estimate the whole correction).
    nondimensional : LennardJonesPullOff
    """

    per_length: ClassVar[tuple[str, ...]] = ("pull_off_force",)

    pull_off_force: float
    error_estimate: float
    contact_half_width_at_pull_off: float
    central_gap_at_pull_off: float
    jump_in_force: float
    method: str
    nondimensional: Any = field(repr=False)


@dataclass(frozen=True)
class CylinderLoadCurve(_PerLength, Result):
    """The load curve of a :class:`~linecontact.cylinder.Cylinder` in SI units.

    Attributes
    ----------
    branch : ndarray of str
        ``"non-contact"`` or ``"contact"``.
    central_gap : ndarray
        ``g0`` [m] (0 in contact).
    contact_half_width, adhesive_zone_half_width : ndarray
        ``a`` and ``c`` [m] (``a = 0`` off contact).
    load : ndarray
        ``F`` [N/m], compressive positive.
    stable : ndarray of bool
        Stable under load control.
    turning_point : ndarray of bool
        Marks the load minimum.
    nondimensional : LoadCurve
        The underlying result (with its ``pulloff``).
    """

    per_length: ClassVar[tuple[str, ...]] = ("load",)

    branch: NDArray
    central_gap: NDArray
    contact_half_width: NDArray
    adhesive_zone_half_width: NDArray
    load: NDArray
    stable: NDArray
    turning_point: NDArray
    nondimensional: _normal.LoadCurve = field(repr=False)


@dataclass(frozen=True)
class CylinderLennardJonesLoadCurve(_PerLength, Result):
    """The load curve under the Lennard-Jones law in SI units.

    Attributes
    ----------
    central_gap : ndarray
        [m], decreasing along the curve.
    contact_half_width : ndarray
        Half-width of the repulsive region [m]; 0 where there is none.
    load : ndarray
        ``F`` [N/m], compressive positive.
    error_estimate : ndarray
        Estimated discretisation error of the load [N/m].
    stable : ndarray of bool
    turning_point : ndarray of bool
    nondimensional : LennardJonesLoadCurve
        The underlying result (Dugdale groups, with its ``pulloff``).
    """

    per_length: ClassVar[tuple[str, ...]] = ("load",)

    central_gap: NDArray
    contact_half_width: NDArray
    load: NDArray
    error_estimate: NDArray
    stable: NDArray
    turning_point: NDArray
    nondimensional: LennardJonesLoadCurve = field(repr=False)


@dataclass(frozen=True)
class CylinderSliding(_PerLength, Result):
    r"""Steady sliding of a :class:`~linecontact.cylinder.Cylinder` in SI units (Eqs 18-22).

    Attributes
    ----------
    contact_half_width : ndarray or float
        ``a`` [m].
    trailing_zone_end, leading_zone_end : ndarray or float
        ``c1`` and ``c2`` [m]: the ends of the trailing (:math:`-c_1 < x < -a`) and leading
        (:math:`a < x < c_2`) adhesive zones from the contact centre.
    eccentricity : ndarray or float
        ``e`` [m]: the cylinder's axis relative to the contact centre.
    load : ndarray or float
        ``F`` [N/m], compressive positive.
    moment, moment_about_axis : ndarray or float
        ``M`` [N m/m] about the contact centre (clockwise positive), and about the axis.
    friction_force : ndarray or float
        :math:`T = 2 a \tau_0` [N/m] (nan without a friction stress).
    receding_range : float
        ``h1`` [m], the trailing edge's range.
    converged, stable : ndarray or bool
    state : ndarray of str or str
        ``"contact"``, or ``"no-equilibrium"`` (reported with ``on_failure="report"``).
    nondimensional : SlidingContact
        The underlying result (in :math:`h = h_2`) with its diagnostics.
    scales : Scales
        The cylinder's scales (:math:`h = h_2`), for :meth:`total`.
    """

    inputs: ClassVar[tuple[str, ...]] = ("receding_range",)
    per_length: ClassVar[tuple[str, ...]] = ("load", "moment", "friction_force")

    contact_half_width: NDArray | float
    trailing_zone_end: NDArray | float
    leading_zone_end: NDArray | float
    eccentricity: NDArray | float
    load: NDArray | float
    moment: NDArray | float
    moment_about_axis: NDArray | float
    friction_force: NDArray | float
    receding_range: float
    converged: NDArray | bool
    stable: NDArray | bool
    state: NDArray | str
    nondimensional: SlidingContact = field(repr=False)
    scales: Scales | None = field(default=None, repr=False)


@dataclass(frozen=True)
class CylinderTangential(Result):
    r"""A tangential state of a :class:`~linecontact.cylinder.Cylinder`, in SI units.

    Attributes
    ----------
    problem : str
        ``"sliding initiation"`` or ``"steady rolling"``.
    friction : str
        ``"constant"`` (friction stress ``tau0``) or ``"coulomb"`` (coefficient ``mu``).
    normal_load : ndarray or float
        ``F`` [N/m], compressive positive.
    contact_half_width : ndarray or float
        ``a`` [m], from the normal problem (Maugis--Dugdale; Hertz for Coulomb friction).
    stick_zone_end : ndarray or float
        ``d`` [m]: the half-width of the central stick zone :math:`|x| < d` (initiation), or the
        start of the leading-edge stick zone :math:`d < x < a` (rolling).
    tangential_load : ndarray or float
        ``T`` [N/m].
    full_slip_load : ndarray or float
        :math:`2 a \tau_0` or :math:`\mu F` [N/m].
    creep_ratio : ndarray or float or None
        :math:`(V - \omega R)/V` for rolling (negative: driving cylinder); None for initiation.
    state : ndarray of str or str
        ``"stick"``, ``"stick-slip"`` or ``"sliding"``.
    nondimensional : result
        The underlying nondimensional result with its diagnostics.
    normal : CylinderContact
        The normal contact.
    """

    inputs: ClassVar[tuple[str, ...]] = ("problem", "friction")

    problem: str
    friction: str
    normal_load: NDArray | float
    contact_half_width: NDArray | float
    stick_zone_end: NDArray | float
    tangential_load: NDArray | float
    full_slip_load: NDArray | float
    creep_ratio: NDArray | float | None
    state: NDArray | str
    nondimensional: object = field(repr=False)
    normal: object = field(repr=False)


@dataclass(frozen=True)
class CylinderPush(_PerLength, Result):
    r"""A pushed :class:`~linecontact.cylinder.Cylinder` (``docs/push.md``), in SI units.

    Attributes
    ----------
    height : ndarray or float
        ``H`` [m] of the push (or of the tip's contact).
    moment_arm : ndarray or float
        ``H``, or the tip's ``H_eff`` [m].
    rest_half_width, slide_half_width : ndarray or float
        ``a_rest`` and ``a_slide`` [m].
    rolling_resistance, sliding_resistance, slip_onset : ndarray or float
        :math:`Q_\text{roll} = R\,\Delta w / H`,
        :math:`Q_\text{slide} = 2 a_\text{slide} \tau_0 + \Delta w` and
        :math:`2 a_\text{rest} \tau_0` [N/m] (horizontal pushes).
    critical_height : ndarray or float
        :math:`H^* = R\,\Delta w / Q_\text{slide}` [m].
    first_motion : ndarray of str or str
        ``"roll"``, ``"slide"``, ``"roll+slide"`` or ``"lift-off"``.
    creep_ratio : ndarray or float
        :math:`(V - \omega R)/V` while rolling.
    state : ndarray of str or str
        Under the push given (``""`` without one).
    length : float or None
        The fibre's length [m] for the totals ``*_total`` [N] (None: per unit length).
    nondimensional : Push
        The underlying result with its diagnostics.
    scales : Scales or None
        The cylinder's scales, for :meth:`total` (None: the SI value times the length).
    """

    inputs: ClassVar[tuple[str, ...]] = ("length",)
    per_length: ClassVar[tuple[str, ...]] = ("rolling_resistance", "sliding_resistance")

    height: NDArray | float
    moment_arm: NDArray | float
    rest_half_width: NDArray | float
    slide_half_width: NDArray | float
    rolling_resistance: NDArray | float
    sliding_resistance: NDArray | float
    slip_onset: NDArray | float
    critical_height: NDArray | float
    first_motion: NDArray | str
    creep_ratio: NDArray | float
    state: NDArray | str
    length: float | None
    nondimensional: object = field(repr=False)
    scales: Scales | None = field(default=None, repr=False)

    @property
    def rolling_resistance_total(self) -> NDArray | float:
        """``Q_roll L`` [N] (needs ``length``)."""
        return self._total(self.rolling_resistance)

    @property
    def sliding_resistance_total(self) -> NDArray | float:
        """``Q_slide L`` [N] (needs ``length``)."""
        return self._total(self.sliding_resistance)

    def _total(self, v):
        if self.length is None:
            raise ValueError("give length= to Cylinder.push for totals in N")
        return v * self.length


@dataclass(frozen=True)
class _HistoryResult(Result):
    """The fields that both SI load-history results begin with: the fixed normal contact.

    The friction law (``"constant"`` or ``"coulomb"``), the normal load ``F`` [N/m], the
    contact half-width ``a`` [m] and the full-slip load [N/m]: the inputs of every point of
    :class:`CylinderTangentialHistory` and :class:`CylinderCyclicLoss`, which document them.
    """

    inputs: ClassVar[tuple[str, ...]] = (
        "friction",
        "normal_load",
        "contact_half_width",
        "full_slip_load",
    )

    friction: str
    normal_load: float
    contact_half_width: float
    full_slip_load: float


@dataclass(frozen=True)
class CylinderTangentialHistory(_HistoryResult):
    """A tangential load history of a :class:`~linecontact.cylinder.Cylinder`, in SI units.

    Attributes
    ----------
    friction : str
        ``"constant"`` or ``"coulomb"``.
    normal_load : float
        ``F`` [N/m].
    contact_half_width : float
        ``a`` [m] (fixed along the history).
    full_slip_load : float
        ``2 a tau0`` or ``mu F`` [N/m].
    tangential_load : ndarray
        ``T`` [N/m] at the end of each step.
    stick_zone_half_width : ndarray
        ``c`` [m] (``nan`` when sliding).
    displacement : ndarray
        ``D`` [m], datum at depth ``a`` (see :mod:`linecontact.tangential.history`).
    dissipation : ndarray
        Energy dissipated in each step per unit length [J/m] (``nan`` for a sliding step).
    state : ndarray of str
    nondimensional : TangentialHistory or CoulombTangentialHistory
        With the diagnostics, and ``traction``, ``slip`` and ``zones``.
    """

    tangential_load: NDArray
    stick_zone_half_width: NDArray
    displacement: NDArray
    dissipation: NDArray
    state: NDArray
    nondimensional: Any = field(repr=False)


@dataclass(frozen=True)
class CylinderCyclicLoss(_HistoryResult):
    r"""Cyclic tangential loading of a :class:`~linecontact.cylinder.Cylinder`, in SI units.

    Attributes
    ----------
    friction : str
    normal_load, contact_half_width, full_slip_load : float
        ``F`` [N/m], ``a`` [m], :math:`2 a \tau_0` or :math:`\mu F` [N/m].
    amplitude : ndarray or float
        ``T*`` [N/m].
    energy_per_cycle : ndarray or float
        Energy dissipated per cycle per unit length [J/m] (``nan`` when sliding).
    stick_zone_half_width : ndarray or float
        ``c`` [m] at the peaks (``nan`` when sliding).
    state : ndarray of str or str
    nondimensional : CyclicLoss or CoulombCyclicLoss
    """

    amplitude: NDArray | float
    energy_per_cycle: NDArray | float
    stick_zone_half_width: NDArray | float
    state: NDArray | str
    nondimensional: Any = field(repr=False)
