"""The SI result classes of the cylinder's problems (frozen dataclasses, each a ``Result``).

Their SI fields are built by :func:`linecontact.units.to_si` from the scales that their
nondimensional results declare.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, ClassVar

from numpy.typing import NDArray

from .. import normal as _normal
from ..results import Result

if TYPE_CHECKING:  # imported where used: the Lennard-Jones solver needs scipy
    from ..lennard_jones_groups import LennardJonesContact


@dataclass(frozen=True)
class CylinderContact(Result):
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
    """

    contact_half_width: NDArray | float
    adhesive_zone_half_width: NDArray | float
    load: NDArray | float
    stable: NDArray | bool
    state: NDArray | str
    nondimensional: _normal.NormalContact = field(repr=False)


@dataclass(frozen=True)
class CylinderPullOff(Result):
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

    pull_off_force: NDArray | float
    contact_half_width_at_pull_off: NDArray | float
    mechanism: NDArray | str
    zero_width_force: NDArray | float
    nondimensional: _normal.PullOff = field(repr=False)


@dataclass(frozen=True)
class CylinderLennardJonesContact(Result):
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
    """

    contact_half_width: NDArray | float
    central_gap: NDArray | float
    load: NDArray | float
    error_estimate: NDArray | float
    stable: NDArray | bool
    state: NDArray | str
    nondimensional: LennardJonesContact = field(repr=False)


@dataclass(frozen=True)
class CylinderLennardJonesPullOff(Result):
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
    nondimensional : LennardJonesPullOff
    """

    pull_off_force: float
    error_estimate: float
    contact_half_width_at_pull_off: float
    central_gap_at_pull_off: float
    jump_in_force: float
    nondimensional: Any = field(repr=False)


@dataclass(frozen=True)
class CylinderTangential(Result):
    """A tangential state of a :class:`~linecontact.cylinder.Cylinder`, in SI units.

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
        ``d`` [m]: the half-width of the central stick zone ``|x| < d`` (initiation), or the
        start of the leading-edge stick zone ``d < x < a`` (rolling).
    tangential_load : ndarray or float
        ``T`` [N/m].
    full_slip_load : ndarray or float
        ``2 a tau0`` or ``mu F`` [N/m].
    creep_ratio : ndarray or float or None
        ``(V - omega R)/V`` for rolling (negative: driving cylinder); None for initiation.
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
class CylinderPush(Result):
    """A pushed :class:`~linecontact.cylinder.Cylinder` (``docs/push.md``), in SI units.

    Attributes
    ----------
    height : ndarray or float
        ``H`` [m] of the push (or of the tip's contact).
    moment_arm : ndarray or float
        ``H``, or the tip's ``H_eff`` [m].
    rest_half_width, slide_half_width : ndarray or float
        ``a_rest`` and ``a_slide`` [m].
    rolling_resistance, sliding_resistance, slip_onset : ndarray or float
        ``Q_roll = R dw / H``, ``Q_slide = 2 a_slide tau0 + dw`` and ``2 a_rest tau0``
        [N/m] (horizontal pushes).
    critical_height : ndarray or float
        ``H* = R dw / Q_slide`` [m].
    first_motion : ndarray of str or str
        ``"roll"``, ``"slide"``, ``"roll+slide"`` or ``"lift-off"``.
    creep_ratio : ndarray or float
        ``(V - omega R)/V`` while rolling.
    state : ndarray of str or str
        Under the push given (``""`` without one).
    length : float or None
        The fibre's length [m] for the totals ``*_total`` [N] (None: per unit length).
    nondimensional : Push
        The underlying result with its diagnostics.
    """

    inputs: ClassVar[tuple[str, ...]] = ("length",)

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
class CylinderTangentialHistory(Result):
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
    tangential_load: NDArray
    stick_zone_half_width: NDArray
    displacement: NDArray
    dissipation: NDArray
    state: NDArray
    nondimensional: Any = field(repr=False)


@dataclass(frozen=True)
class CylinderCyclicLoss(Result):
    """Cyclic tangential loading of a :class:`~linecontact.cylinder.Cylinder`, in SI units.

    Attributes
    ----------
    friction : str
    normal_load, contact_half_width, full_slip_load : float
        ``F`` [N/m], ``a`` [m], ``2 a tau0`` or ``mu F`` [N/m].
    amplitude : ndarray or float
        ``T*`` [N/m].
    energy_per_cycle : ndarray or float
        Energy dissipated per cycle per unit length [J/m] (``nan`` when sliding).
    stick_zone_half_width : ndarray or float
        ``c`` [m] at the peaks (``nan`` when sliding).
    state : ndarray of str or str
    nondimensional : CyclicLoss or CoulombCyclicLoss
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
    amplitude: NDArray | float
    energy_per_cycle: NDArray | float
    stick_zone_half_width: NDArray | float
    state: NDArray | str
    nondimensional: Any = field(repr=False)
