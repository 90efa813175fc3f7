r"""The dimensional (SI) layer: a cylinder on a substrate, and its problems in SI units.

:class:`Cylinder` holds the radius, the composite modulus, the adhesion ``(sigma0, h)`` and
Dundurs' ``beta``; its methods and the ``cylinder_*`` functions convert SI inputs to the
paper's groups, call the nondimensional solvers (:mod:`linecontact.normal`,
:mod:`linecontact.tangential`) and convert back. Units: lengths [m], stresses and moduli
[Pa], forces per unit length of cylinder [N/m], work of adhesion [J/m^2]. Materials and
adhesion conventions: :mod:`linecontact.materials`.
"""

from __future__ import annotations

import contextvars
import math
import warnings
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, Literal, overload

import numpy as np
from numpy.typing import ArrayLike, NDArray

from . import domain as _domain
from . import normal as _normal
from . import push as _push
from . import reference as _ref
from ._validation import (
    RAISE,
    FailurePolicy,
    broadcast,
    check_array,
    failure_policy,
    non_negative,
    positive,
    scalar,
)
from .errors import CouplingWarning, ModelValidityWarning, NoEquilibriumError
from .materials import (
    BETA_WARN,
    MAUGIS_STRENGTH,
    _adhesion,
    _moduli,
    composite_modulus,
    dundurs_beta,
)
from .tangential import (
    sliding_initiation,
    sliding_initiation_coulomb,
    steady_rolling,
    steady_rolling_coulomb,
)
from .tangential.initiation import _CATTANEO_MINDLIN, _INITIATION
from .tangential.rolling import _CARTER, _ROLLING

if TYPE_CHECKING:  # imported where used: the Lennard-Jones solver needs scipy
    from .lennard_jones_groups import LennardJonesContact
    from .presets import Material

__all__ = [
    "CylinderPush",
    "cylinder_push",
    "PLAUSIBLE",
    "Cylinder",
    "CylinderContact",
    "CylinderLennardJonesContact",
    "CylinderLennardJonesPullOff",
    "CylinderPullOff",
    "CylinderCyclicLoss",
    "CylinderTangential",
    "CylinderTangentialHistory",
    "cylinder_cyclic_loss",
    "cylinder_sliding_initiation",
    "cylinder_tangential_history",
    "cylinder_steady_rolling",
]


#: Plausible SI values: (low, high, unit, what a value outside suggests). A value outside
#: gives a :class:`~linecontact.errors.ModelValidityWarning` (it is still used): a radius
#: above 1 mm or below 0.1 nm, a modulus outside 1 kPa to 2 TPa, a work of adhesion above
#: 10 J/m^2, an adhesion range above 10 nm are most often a value in the wrong units.
PLAUSIBLE = {
    "radius": (1e-10, 1e-3, "m", "radius"),
    "modulus": (1e3, 2e12, "Pa", "modulus"),
    "work_of_adhesion": (0.0, 10.0, "J/m^2", "work of adhesion"),
    "adhesion_range": (0.0, 10e-9, "m", "adhesion range"),
}


#: A likely slip of units per input: (factor, unit) of the value as it was probably meant,
#: on the side of :data:`PLAUSIBLE` where that slip lands (nm given as m, GPa as Pa, ...).
_UNIT_SLIP = {
    "radius": ("above", 1e-9, "nm"),
    "modulus": ("below", 1e9, "GPa"),
    "work_of_adhesion": ("above", 1e-3, "mJ/m^2"),
    "adhesion_range": ("above", 1e-9, "nm"),
}

#: The narrowest contact half-width [m] that is a width at all (a femtometre, the size of a
#: nucleus): a result below it is round-off of zero width, or of inputs in the wrong units.
WIDTH_MIN = 1e-15

#: sigma0 = S w / z0 and h = z0 / S (the Maugis convention of :mod:`linecontact.materials`)
_S_LJ = MAUGIS_STRENGTH

#: Set while a factory of :class:`Cylinder` builds one: the factory has checked the SI
#: inputs under the names its caller used (``work_of_adhesion``, ``equilibrium_spacing``).
_CHECKED: contextvars.ContextVar[bool] = contextvars.ContextVar("_CHECKED", default=False)


def _implausible(name: str, value: ArrayLike, key: str | None = None) -> str | None:
    """The warning for the first value of ``name`` outside :data:`PLAUSIBLE` (None: none)."""
    key = key or name
    lo, hi, unit, what = PLAUSIBLE[key]
    if name != key and not name.startswith("-"):  # as the caller named it (equilibrium_spacing)
        what = name.replace("_", " ")
    v = np.asarray(value, float).reshape(-1)
    with np.errstate(invalid="ignore"):
        out = np.isfinite(v) & ~((v >= lo) & (v <= hi))
    if not np.any(out):
        return None
    x = float(v[np.flatnonzero(out)[0]])
    side = "above" if x > hi else "below"
    bound = hi if x > hi else lo
    hint = ""
    slip = _UNIT_SLIP.get(key)
    if slip is not None and slip[0] == side and lo <= x * slip[1] <= hi:
        hint = f"; {x:g} {slip[2]} is {x * slip[1]:g} {unit}"
    return (
        f"{name} = {x:g} {unit} is {side} {bound:g} {unit}: is the {what} in {unit}? "
        f"(linecontact takes SI units{hint})"
    )


def _plausible(name: str, value: ArrayLike, stacklevel: int = 3, key: str | None = None) -> None:
    """Warn (:class:`ModelValidityWarning`) for a value of ``name`` outside :data:`PLAUSIBLE`."""
    message = _implausible(name, value, key)
    if message is not None:
        warnings.warn(message, ModelValidityWarning, stacklevel=stacklevel)


def _first(bad: NDArray, *values: ArrayLike) -> list[float]:
    """The values at the first point where ``bad`` (broadcast together), as floats."""
    i = int(np.flatnonzero(np.reshape(bad, -1))[0])
    return [float(np.reshape(np.broadcast_to(v, np.shape(bad)), -1)[i]) for v in values]


def _which(default: str, *candidates: tuple[str, ArrayLike, str | None]) -> str:
    """The input that most likely has the wrong units: the first one outside PLAUSIBLE."""
    for name, value, key in candidates:
        if key is not None and _implausible(name, value, key) is not None:
            return name
    return default


def _check_cylinder_si(
    radius: ArrayLike,
    modulus: ArrayLike | None,
    adhesion: dict[str, ArrayLike | None],
    *,
    modulus_name: str = "modulus",
    stacklevel: int = 4,
) -> None:
    """Warn for implausible SI inputs, refuse those whose groups leave the solvers' domain.

    ``adhesion`` is ``{"work_of_adhesion": w, "equilibrium_spacing": z0}`` (``w`` may be
    None where it is unknown, as in an inversion), or ``{"cohesive_stress": sigma0,
    "adhesion_range": h}``, as the caller gave them: the messages name these, the radius
    and the modulus, and the ranges in SI units, never the nondimensional groups. Without
    the modulus (None) only the radius and the range are checked.
    """
    R = np.asarray(radius, float)
    E = np.asarray(np.nan if modulus is None else modulus, float)
    by_work = "equilibrium_spacing" in adhesion
    a_name, l_name = (
        ("work_of_adhesion", "equilibrium_spacing")
        if by_work
        else ("cohesive_stress", "adhesion_range")
    )
    a_val, l_val = adhesion[a_name], adhesion[l_name]
    length = np.asarray(l_val, float)
    conv = _S_LJ if by_work else 1.0  # R/h = conv R / length
    if a_val is None:
        stress = None
    elif by_work:
        stress = _S_LJ * np.asarray(a_val, float) / length  # sigma0 of (w, z0)
    else:
        stress = np.asarray(a_val, float)
    adhesive = stress is None or bool(np.any(stress > 0))
    # the warnings first: a value in the wrong units is said before what it breaks
    _plausible("radius", R, stacklevel)
    if modulus_name == "modulus":
        _plausible("modulus", E, stacklevel)
    if adhesive:  # without adhesion the range only sets a length scale
        _plausible(l_name, length, stacklevel, key="adhesion_range")
        if by_work and a_val is not None:
            _plausible("work_of_adhesion", a_val, stacklevel)
        elif stress is not None and _implausible(l_name, length, "adhesion_range") is None:
            # sigma0 h: said where the range is not already the suspect
            _plausible("work_of_adhesion", stress * length, stacklevel)
    unit = {"work_of_adhesion": "J/m^2", "cohesive_stress": "Pa"}[a_name]
    cands_l = ((l_name, length, "adhesion_range"), ("radius", R, "radius"))
    # the ratio of the radius to the range
    lo, _, hi, _ = _domain.DOMAIN["R_over_h"]
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        ratio = conv * R / length
    bad = ~((ratio >= lo) & (ratio <= hi))
    if np.any(bad):
        r, z = _first(bad, R, length)
        guess = _which(l_name, *cands_l)
        raise ValueError(
            f"radius / {l_name} must be in [{lo / conv:.3g}, {hi / conv:.3g}] (the domain of "
            f"the solvers), got radius={r!r} m, {l_name}={z!r} m; "
            f"{_units_question(guess, modulus_name, 'm')}"
        )
    if stress is None or modulus is None or a_val is None:
        return
    a_val = np.asarray(a_val, float)
    # the adhesive stress over the modulus
    s_hi = _domain.DOMAIN["sigma0_over_E"][2]
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        s = stress / E
    bad = ~(s <= s_hi)
    m_key = "modulus" if modulus_name == "modulus" else None
    cands_s = (
        (modulus_name, E, m_key),
        (a_name, a_val if by_work else stress, "work_of_adhesion" if by_work else None),
        (l_name, length, "adhesion_range"),
    )
    if np.any(bad):
        sv, ev, av, zv = _first(bad, stress, E, a_val, length)
        guess = _which(modulus_name, *cands_s)
        what = (
            f"the adhesive stress 16 w/(9 sqrt(3) z0) = {sv:.3g} Pa of {a_name}={av!r} "
            f"J/m^2 and {l_name}={zv!r} m"
            if by_work
            else f"{a_name}={av!r} Pa"
        )
        raise ValueError(
            f"{what} must be at most {s_hi:g} times the {modulus_name.replace('_', ' ')}, "
            f"{s_hi * ev:.3g} Pa here, got {modulus_name}={ev!r} Pa (the domain of the "
            f"solvers); {_units_question(guess, modulus_name, unit)}"
        )
    # kappa = (4/pi) (sigma0/E) sqrt(2 R/h), the single group of the Maugis-Dugdale contact
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        kap = _ref._kappa(ratio, s)
    bad = ~(kap <= _ref.KAPPA_MAX)
    if np.any(bad):
        k, r, ev, av, zv = _first(bad, kap, R, E, a_val, length)
        guess = _which(modulus_name, *cands_s, ("radius", R, "radius"))
        raise ValueError(
            f"the adhesion of this cylinder is beyond the range of the solvers: kappa = "
            f"(4/pi) sigma0 sqrt(2 R) / (E sqrt(h)) = {k:.3g} must be at most "
            f"{_ref.KAPPA_MAX:g}, got radius={r!r} m, {modulus_name}={ev!r} Pa, {a_name}="
            f"{av!r} {unit}, {l_name}={zv!r} m; {_units_question(guess, modulus_name, unit)}"
        )


def _units_question(guess: str, modulus_name: str, unit: str) -> str:
    """``is <input> in <unit>?`` for the input that most likely has the wrong units."""
    if guess == "composite modulus":
        return "are E1 and E2 in Pa?"
    the = "the " if "_" not in guess else ""  # a word (radius), or a parameter's name
    if guess == "radius" or guess.endswith(("range", "spacing")):
        return f"is {the}{guess} in metres?"
    return f"is {the}{guess} in {'Pa' if guess == modulus_name else unit}?"


#: Why a zero-width pull-off reports a width below :data:`WIDTH_MIN`.
_ZERO_WIDTH = (
    "the contact peels to zero width before it pulls off (mechanism 'zero-width'): read it as 0"
)


def _warn_widths(
    a: ArrayLike,
    radius: ArrayLike,
    what: str = "the contact half-width",
    why: str = "",
    stacklevel=3,
) -> None:
    """Warn for contact half-widths [m] that are no physical width: below WIDTH_MIN or above R."""
    v, Rv = (np.reshape(x, -1) for x in np.broadcast_arrays(np.asarray(a, float), radius))
    with np.errstate(invalid="ignore"):
        tiny = (v > 0) & (v < WIDTH_MIN)
        wide = v > Rv
    if np.any(tiny):
        x = float(v[np.flatnonzero(tiny)[0]])
        warnings.warn(
            f"{what} {x:.3g} m is below {WIDTH_MIN:g} m, the size of a nucleus: it is no "
            f"physical width ({why or 'round-off of a zero width'}, or an input in the wrong "
            "units: linecontact takes SI units)",
            ModelValidityWarning,
            stacklevel=stacklevel,
        )
    if np.any(wide):
        i = np.flatnonzero(wide)[0]
        x = float(v[i])
        warnings.warn(
            f"{what} {x:.3g} m is above the radius {float(Rv[i]):g} m: the contact is wider than "
            "the cylinder (an input in the wrong units? linecontact takes SI units)",
            ModelValidityWarning,
            stacklevel=stacklevel,
        )


@dataclass(frozen=True)
class CylinderContact:
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
class CylinderPullOff:
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
class CylinderLennardJonesContact:
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
class CylinderLennardJonesPullOff:
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
class Cylinder:
    """A cylinder of radius ``R`` on a substrate, with Maugis--Dugdale adhesion.

    Build it with :meth:`from_materials` or :meth:`from_modulus`.

    Attributes
    ----------
    radius : float
        ``R`` [m] (the equivalent radius for two cylinders).
    modulus : float
        Composite plane-strain modulus ``E`` [Pa].
    cohesive_stress : float
        ``sigma0`` [Pa] (0: no adhesion).
    adhesion_range : float
        ``h`` [m].
    dundurs_beta : float
        Dundurs' ``beta = -B/A`` (0 when only the composite modulus was given).

    Examples
    --------
    >>> cyl = Cylinder.from_modulus(50e-9, 100e9, cohesive_stress=1e9, adhesion_range=0.5e-9)
    >>> round(cyl.R_over_h, 9), cyl.sigma0_over_E
    (100.0, 0.01)
    """

    radius: float
    modulus: float
    cohesive_stress: float
    adhesion_range: float
    dundurs_beta: float = 0.0

    def __post_init__(self) -> None:
        # the fields as Python floats, checked (also when the class is built directly)
        for name, limits in (
            ("radius", {}),
            ("modulus", {}),
            ("cohesive_stress", {"low_inclusive": True}),
            ("adhesion_range", {}),
            ("dundurs_beta", {"low": -np.inf, "low_inclusive": True}),
        ):
            object.__setattr__(self, name, scalar(name, getattr(self, name), **limits))
        # the units of the groups must be representable: R/h, sigma0/E and E h
        for what, v in (
            ("radius/adhesion_range (R/h)", self.radius / self.adhesion_range),
            ("cohesive_stress/modulus (sigma0/E)", self.cohesive_stress / self.modulus),
            (
                "modulus*adhesion_range (E h, the unit of force per length)",
                self.modulus * self.adhesion_range,
            ),
        ):
            if not (np.isfinite(v) and (v > 0 or (v == 0 and what.startswith("cohesive")))):
                raise ValueError(
                    f"{what} = {v!r} is not a finite positive number: radius="
                    f"{self.radius!r}, modulus={self.modulus!r}, cohesive_stress="
                    f"{self.cohesive_stress!r}, adhesion_range="
                    f"{self.adhesion_range!r} are too far apart in scale"
                )
        if not _CHECKED.get():  # a factory checked them under its caller's names
            _check_cylinder_si(
                self.radius,
                self.modulus,
                {"cohesive_stress": self.cohesive_stress, "adhesion_range": self.adhesion_range},
                stacklevel=5,
            )

    @classmethod
    def _build(
        cls,
        R: float,
        E: float,
        beta: float,
        adhesion: tuple[float | None, float | None, float | None, float | None],
        modulus_name: str = "modulus",
    ) -> Cylinder:
        """The cylinder of a factory, its SI inputs checked under the names the caller gave."""
        cohesive_stress, adhesion_range, work_of_adhesion, equilibrium_spacing = adhesion
        s0, h = _adhesion(cohesive_stress, adhesion_range, work_of_adhesion, equilibrium_spacing)
        given: dict[str, ArrayLike | None] = {"cohesive_stress": s0, "adhesion_range": h}
        if work_of_adhesion is not None and equilibrium_spacing is not None:
            given = {
                "work_of_adhesion": float(work_of_adhesion),
                "equilibrium_spacing": float(equilibrium_spacing),
            }
        _check_cylinder_si(R, E, given, modulus_name=modulus_name, stacklevel=5)
        token = _CHECKED.set(True)
        try:
            cyl = cls(R, E, s0, h, beta)
        finally:
            _CHECKED.reset(token)
        object.__setattr__(cyl, "_given", given)  # for the messages of the Lennard-Jones law
        return cyl

    @classmethod
    def from_modulus(
        cls,
        radius: float,
        modulus: float,
        *,
        cohesive_stress: float | None = None,
        adhesion_range: float | None = None,
        work_of_adhesion: float | None = None,
        equilibrium_spacing: float | None = None,
    ) -> Cylinder:
        """From the composite modulus ``E`` [Pa]; adhesion as ``(sigma0, h)`` or ``(w, z0)``."""
        R = scalar("radius", radius)
        E = scalar("modulus", modulus)
        adhesion = (cohesive_stress, adhesion_range, work_of_adhesion, equilibrium_spacing)
        return cls._build(R, E, 0.0, adhesion)

    @classmethod
    def from_materials(
        cls,
        radius: float,
        E1: float,
        nu1: float,
        E2: float,
        nu2: float,
        *,
        cohesive_stress: float | None = None,
        adhesion_range: float | None = None,
        work_of_adhesion: float | None = None,
        equilibrium_spacing: float | None = None,
    ) -> Cylinder:
        """From the moduli [Pa] and Poisson ratios of cylinder (1) and substrate (2)."""
        R = scalar("radius", radius)
        for name, v in zip(("E1", "nu1", "E2", "nu2"), _moduli(E1, nu1, E2, nu2), strict=True):
            if v.ndim != 0:
                raise ValueError(f"{name} must be a single number, got an array of shape {v.shape}")
        E = float(composite_modulus(E1, nu1, E2, nu2))
        beta = float(dundurs_beta(E1, nu1, E2, nu2))
        for name, mod in (("E1", E1), ("E2", E2)):
            e = float(np.asarray(mod))  # a single number (checked above)
            if np.isfinite(e) and not PLAUSIBLE["modulus"][0] <= e <= PLAUSIBLE["modulus"][1]:
                warnings.warn(
                    f"{name} = {e:g} Pa is outside 1 kPa to 2 TPa: is the modulus in Pa? "
                    "(linecontact takes SI units)",
                    ModelValidityWarning,
                    stacklevel=2,
                )
        if abs(beta) > BETA_WARN:
            warnings.warn(
                f"Dundurs beta = -B/A = {beta:.3g} is not small (|beta| > {BETA_WARN}): "
                "normal and tangential tractions are coupled, but linecontact "
                "solves the uncoupled case B = 0",
                CouplingWarning,
                stacklevel=2,
            )
        adhesion = (cohesive_stress, adhesion_range, work_of_adhesion, equilibrium_spacing)
        return cls._build(R, E, beta, adhesion, "composite modulus")

    @classmethod
    def from_presets(
        cls,
        radius: float,
        cylinder_material: str | Material,
        substrate_material: str | Material,
        *,
        cohesive_stress: float | None = None,
        adhesion_range: float | None = None,
        work_of_adhesion: float | None = None,
        equilibrium_spacing: float | None = None,
    ) -> Cylinder:
        """From material presets (:mod:`linecontact.presets`) of cylinder and substrate.

        Parameters
        ----------
        radius : float
            ``R`` [m].
        cylinder_material, substrate_material : str or Material
            A preset's name (case-insensitive: ``"ZnO"``, ``"SiO2"``, see
            :func:`~linecontact.presets.material_names`) or a
            :class:`~linecontact.presets.Material`.
        cohesive_stress, adhesion_range, work_of_adhesion, equilibrium_spacing : float, optional
            Adhesion as ``(sigma0, h)`` or ``(w, z0)``, as in :meth:`from_materials`.

        Returns
        -------
        Cylinder
            ``Cylinder.from_materials(radius, E1, nu1, E2, nu2, ...)`` with the presets'
            ``E`` and ``nu``.

        Examples
        --------
        >>> cyl = Cylinder.from_presets(
        ...     50e-9, "ZnO", "Si", work_of_adhesion=0.1, equilibrium_spacing=0.3e-9
        ... )
        >>> round(cyl.modulus / 1e9, 1)
        77.8
        """
        from .presets import Material

        def preset(name: str, m) -> Material:
            try:
                return m if isinstance(m, Material) else Material.from_name(m)
            except ValueError as exc:  # say which of the two
                raise ValueError(f"{name}: {exc}") from None

        m1 = preset("cylinder_material", cylinder_material)
        m2 = preset("substrate_material", substrate_material)
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            cyl = cls.from_materials(
                radius,
                m1.E,
                m1.nu,
                m2.E,
                m2.nu,
                cohesive_stress=cohesive_stress,
                adhesion_range=adhesion_range,
                work_of_adhesion=work_of_adhesion,
                equilibrium_spacing=equilibrium_spacing,
            )
        for w in caught:  # said where from_presets was called, not in here
            warnings.warn(w.message, stacklevel=2)
        return cyl

    # groups ------------------------------------------------------------------------------
    @property
    def R_over_h(self) -> float:
        """``R/h``."""
        return self.radius / self.adhesion_range

    @property
    def sigma0_over_E(self) -> float:
        """``sigma0/E``."""
        return self.cohesive_stress / self.modulus

    @property
    def work_of_adhesion(self) -> float:
        """``w = sigma0 h`` [J/m^2]."""
        return self.cohesive_stress * self.adhesion_range

    @property
    def maugis_parameter(self) -> float:
        """Baney & Hui's line-contact Tabor-like parameter (DMT-like small, JKR-like large)."""
        return float(_ref.maugis_parameter(self.R_over_h, self.sigma0_over_E))

    @property
    def kappa(self) -> float:
        """The single group of the Maugis--Dugdale line contact."""
        return float(_ref.kappa(self.R_over_h, self.sigma0_over_E))

    def _check_lennard_jones(self) -> None:
        """Refuse, in SI terms, a cylinder outside the domain of the Lennard-Jones solver.

        The solver's group is the Maugis (Tabor) parameter ``mu = w R^(1/2) / (E z0^(3/2))``
        with ``w = sigma0 h`` and ``z0 = 16 h/(9 sqrt 3)``; the message gives its value for
        this cylinder, the inputs as they were given, and what would bring it in.
        """
        hi = _domain.DOMAIN["lj_mu"][2]
        R, E = self.radius, self.modulus
        w, z0 = self.work_of_adhesion, _S_LJ * self.adhesion_range
        given = getattr(self, "_given", {})
        if self.cohesive_stress <= 0:
            raise ValueError(
                "the Lennard-Jones law needs adhesion: give the cylinder a work of adhesion "
                "(work_of_adhesion and equilibrium_spacing, or cohesive_stress > 0)"
            )
        mu = w * math.sqrt(R / z0) / (E * z0)
        if mu <= hi:
            return
        from .lennard_jones import maugis_parameter_of_mu

        lam = float(maugis_parameter_of_mu(hi))
        if "work_of_adhesion" in given:
            w, z0 = float(given["work_of_adhesion"]), float(given["equilibrium_spacing"])
            inputs = f"work_of_adhesion={w!r} J/m^2, equilibrium_spacing={z0!r} m"
            more = (
                f", a work of adhesion below {w * hi / mu:.3g} J/m^2 or an equilibrium spacing "
                f"z0 above {z0 * (mu / hi) ** (2 / 3):.3g} m"
            )
        else:
            inputs = (
                f"cohesive_stress={self.cohesive_stress!r} Pa, adhesion_range="
                f"{self.adhesion_range!r} m (w = {w:.3g} J/m^2, z0 = {z0:.3g} m)"
            )
            more = f" or a cohesive stress below {self.cohesive_stress * hi / mu:.3g} Pa"
        raise ValueError(
            f"under the Lennard-Jones law the Maugis parameter mu = w R^(1/2) / (E z0^(3/2)) "
            f"of this cylinder is {mu:.4g} (radius={R!r} m, modulus={E!r} Pa, {inputs}): the "
            f"Lennard-Jones solver takes mu in [0, {hi:g}] (Tabor-Maugis parameter up to "
            f"{lam:.3g}). Use the Dugdale law (law='dugdale', any mu), or a radius below "
            f"{R * (hi / mu) ** 2:.3g} m, a modulus above {E * mu / hi:.3g} Pa{more}"
        )

    # problems ----------------------------------------------------------------------------
    def _wrap(self, r: _normal.NormalContact) -> CylinderContact:
        R, Eh = self.radius, self.modulus * self.adhesion_range

        def si(v, unit):
            v = np.multiply(v, unit)
            return v.item() if np.ndim(v) == 0 else v

        a = si(r.a_over_R, R)
        _warn_widths(a, R, stacklevel=4)
        return CylinderContact(a, si(r.c_over_R, R), si(r.F_over_Eh, Eh), r.stable, r.state, r)

    @overload
    def contact(
        self,
        *,
        contact_half_width: ArrayLike | None = None,
        load: ArrayLike | None = None,
        method: str = "closed-form",
        branch: str = "stable",
        on_failure: FailurePolicy = RAISE,
        law: Literal["dugdale"] = "dugdale",
        **deprecated: Any,
    ) -> CylinderContact: ...

    @overload
    def contact(
        self,
        *,
        contact_half_width: ArrayLike | None = None,
        load: ArrayLike | None = None,
        method: str = "closed-form",
        branch: str = "stable",
        on_failure: FailurePolicy = RAISE,
        law: str,
        **deprecated: Any,
    ) -> CylinderContact | CylinderLennardJonesContact: ...

    def contact(
        self,
        *,
        contact_half_width: ArrayLike | None = None,
        load: ArrayLike | None = None,
        method: str = "closed-form",
        branch: str = "stable",
        on_failure: FailurePolicy = RAISE,
        law: str = "dugdale",
        **deprecated: Any,
    ) -> CylinderContact | CylinderLennardJonesContact:
        """The contact at given half-widths ``a`` [m] or loads ``F`` [N/m] (exactly one).

        For a load, ``branch`` selects the stable (default) or the unstable contact state;
        a load that no contact of the branch carries (below the pull-off force) raises
        :class:`~linecontact.errors.NoEquilibriumError`, or with ``on_failure="report"``
        gives ``state == "no-equilibrium"`` and NaN values; for a half-width, ``on_failure``
        is that of :func:`~linecontact.normal_contact` (a collocation point that misses its
        tolerance raises :class:`~linecontact.errors.ConvergenceError`, or is flagged in
        ``nondimensional.converged``). README, "Conventions"; ``on_no_equilibrium`` is the
        deprecated form of ``on_failure``.

        ``law="lennard-jones"`` is deprecated (a ``DeprecationWarning``): use
        :meth:`lennard_jones_contact`, which it calls. ``law="dugdale"`` (the default) is
        accepted silently.
        """
        _normal._check_law(law, "Cylinder.contact", "Cylinder.lennard_jones_contact(load=...)")
        if (contact_half_width is None) == (load is None):
            raise ValueError("give exactly one of contact_half_width or load")
        policy = failure_policy(
            on_failure, where="Cylinder.contact", accepts=("on_no_equilibrium",), **deprecated
        )
        if law == "lennard-jones":
            if load is None:
                raise ValueError(
                    "under the Lennard-Jones law the contact is found for a given load only: "
                    "give load [N/m], not contact_half_width"
                )
            if method != "closed-form" or branch != "stable":
                raise ValueError(
                    "method and branch apply to law='dugdale': under the Lennard-Jones law the "
                    "contact for a load is the stable state beyond the pull-off"
                )
            self._check_lennard_jones()
            return self._for_load_lj("load", load, policy)
        if method not in ("closed-form", "collocation"):
            raise ValueError(f"method must be 'closed-form' or 'collocation', got {method!r}")
        if branch not in ("stable", "unstable"):
            raise ValueError(f"branch must be 'stable' or 'unstable', got {branch!r}")
        if load is not None and method != "closed-form":
            raise ValueError(
                "the contact for a given load is found by the closed form: "
                "method='collocation' applies to contact_half_width only"
            )
        if contact_half_width is not None and branch != "stable":
            raise ValueError(
                "branch applies to a given load only: a contact half-width fixes the state"
            )
        if contact_half_width is not None:
            a = positive("contact_half_width", contact_half_width)
            _domain.check_si("contact_half_width", a, self.radius, "a_over_R", "m")
            r = _normal.normal_contact(
                a / self.radius, self.R_over_h, self.sigma0_over_E, method=method, on_failure=policy
            )
        else:
            return self._for_load("load", load, branch, policy)  # type: ignore[arg-type]
        return self._wrap(r)

    def _for_load(
        self, name: str, load: ArrayLike, branch: str = "stable", policy: FailurePolicy = "raise"
    ) -> CylinderContact:
        """The contact carrying ``load`` [N/m]; messages name the caller's parameter."""
        F = check_array(name, load, low=-np.inf, low_inclusive=True)
        Eh = self.modulus * self.adhesion_range
        _domain.check_si(name, F, Eh, "F_over_Eh", "N/m")
        if branch == "stable" and policy == "raise":
            # said in the units given ([N/m]), not only as F_over_Eh
            F_min = _normal.pull_off(self.R_over_h, self.sigma0_over_E).F_minimum_over_Eh * Eh
            if np.any(F < F_min):
                raise NoEquilibriumError(
                    f"no contact carries {name}={float(F[F < F_min].flat[0])!r} N/m: it is "
                    f"below the pull-off force, the minimum load on the contact branch "
                    f"{F_min!r} N/m; the cylinder has pulled off"
                )
        try:
            r = _normal.contact_for_load(
                F / Eh,
                self.R_over_h,
                self.sigma0_over_E,
                branch=branch,
                on_failure=policy,
            )
        except _domain.TooWideError as e:
            Fi = float(np.reshape(np.broadcast_to(F, np.shape(F)), -1)[e.index])
            raise ValueError(
                f"{name}={Fi!r} N/m needs a contact of half-width {e.a_over_R * self.radius:.6g}"
                f" m, {e.a_over_R:.6g} radii: {e.limit}"
            ) from None
        # the load asked for, not F/(Eh) times E h (which need not give back F exactly)
        c = self._wrap(r)
        load_given = F.item() if np.ndim(c.load) == 0 else np.broadcast_to(F, np.shape(c.load))
        return CylinderContact(
            c.contact_half_width,
            c.adhesive_zone_half_width,
            load_given,
            c.stable,
            c.state,
            r,
        )

    def _for_load_lj(
        self, name: str, load: ArrayLike, policy: FailurePolicy = "raise"
    ) -> CylinderLennardJonesContact:
        """The contact carrying ``load`` [N/m] under the Lennard-Jones law (SI messages)."""
        from . import lennard_jones_groups as _ljg
        from .laws import lennard_jones as _lj

        F = check_array(name, load, low=-np.inf, low_inclusive=True)
        Eh = self.modulus * self.adhesion_range
        _domain.check_si(name, F, Eh, "F_over_Eh", "N/m")
        F_max = float(_ljg.load_max_over_Eh(self.R_over_h, self.sigma0_over_E)) * Eh
        if np.any(F > F_max):
            raise ValueError(
                f"{name}={float(F[F > F_max].flat[0])!r} N/m is beyond the loads the "
                f"Lennard-Jones solver is asked for, up to {F_max:.6g} N/m here (ten times the "
                "rigid cylinder's pull-off); at such loads both laws approach Hertz, and the "
                "Dugdale law (the default) gives the contact"
            )
        try:
            r = _lj.contact_for_load(F / Eh, self.R_over_h, self.sigma0_over_E, on_failure=policy)
        except _ljg.BelowPullOffError as e:
            Fi = float(np.reshape(F, -1)[e.index])
            raise NoEquilibriumError(
                f"no contact carries {name}={Fi!r} N/m under the Lennard-Jones law: it is "
                f"below the pull-off force {e.F_pulloff_over_Eh * Eh!r} N/m (error estimate "
                f"{e.error_estimate_over_Eh * Eh:.2g} N/m); the cylinder has pulled off"
            ) from None

        def si(v, unit):
            v = np.multiply(v, unit)
            return v.item() if np.ndim(v) == 0 else v

        load_given = (
            F.item() if np.ndim(r.F_over_Eh) == 0 else np.broadcast_to(F, np.shape(r.F_over_Eh))
        )
        _warn_widths(si(r.a_over_R, self.radius), self.radius, stacklevel=4)
        return CylinderLennardJonesContact(
            si(r.a_over_R, self.radius),
            si(r.central_gap_over_h, self.adhesion_range),
            load_given,
            si(r.error_estimate_over_Eh, Eh),
            r.stable,
            r.state,
            r,
        )

    @overload
    def pull_off(self, *, law: Literal["dugdale"] = "dugdale") -> CylinderPullOff: ...

    @overload
    def pull_off(self, *, law: str) -> CylinderPullOff | CylinderLennardJonesPullOff: ...

    def pull_off(self, *, law: str = "dugdale") -> CylinderPullOff | CylinderLennardJonesPullOff:
        """Pull-off force under load control [N/m] (the Maugis--Dugdale law).

        ``law="lennard-jones"`` is deprecated (a ``DeprecationWarning``): use
        :meth:`lennard_jones_pull_off`, which it calls. ``law="dugdale"`` (the default) is
        accepted silently.
        """
        _normal._check_law(law, "Cylinder.pull_off", "Cylinder.lennard_jones_pull_off()")
        if law == "lennard-jones":
            return self._pull_off_lj()
        p = _normal.pull_off(self.R_over_h, self.sigma0_over_E)
        Eh = self.modulus * self.adhesion_range
        _warn_widths(
            p.a_over_R_at_pulloff * self.radius,
            self.radius,
            "the contact half-width at pull-off",
            _ZERO_WIDTH if p.mechanism == "zero-width" else "",
            stacklevel=3,
        )
        return CylinderPullOff(
            p.F_pulloff_over_Eh * Eh,
            p.a_over_R_at_pulloff * self.radius,
            p.mechanism,
            p.F_zero_width_over_Eh * Eh,
            p,
        )

    # the Lennard-Jones law (a law is a method here, as it is a module in linecontact.laws)
    def lennard_jones_contact(
        self, *, load: ArrayLike, on_failure: FailurePolicy = RAISE
    ) -> CylinderLennardJonesContact:
        """The contact carrying ``load`` [N/m] under the Lennard-Jones law of Eq. (1).

        Solved self-consistently (:func:`linecontact.laws.lennard_jones.contact_for_load`),
        the stable branch, with the cylinder's work of adhesion ``w = sigma0 h`` and
        ``z0 = 16 h/(9 sqrt 3)`` (for a cylinder built from ``(w, z0)`` these are the ``w``
        and ``z0`` given, as the Maugis conversion of :func:`~linecontact.adhesion_from_work`
        is undone). A load below the pull-off force raises
        :class:`~linecontact.errors.NoEquilibriumError`, or with ``on_failure="report"``
        gives ``state == "no-equilibrium"`` and NaN values.
        """
        policy = failure_policy(on_failure, where="Cylinder.lennard_jones_contact", accepts=())
        self._check_lennard_jones()
        return self._for_load_lj("load", load, policy)

    def lennard_jones_pull_off(self) -> CylinderLennardJonesPullOff:
        """Pull-off force [N/m] under the Lennard-Jones law of Eq. (1).

        With the cylinder's ``w`` and ``z0`` (as in :meth:`lennard_jones_contact`);
        :func:`linecontact.laws.lennard_jones.pull_off` in SI units.
        """
        return self._pull_off_lj()

    def _pull_off_lj(self) -> CylinderLennardJonesPullOff:
        """:meth:`lennard_jones_pull_off` (its warnings point at the caller of the caller)."""
        from .laws import lennard_jones as _lj

        self._check_lennard_jones()
        q = _lj.pull_off(self.R_over_h, self.sigma0_over_E)
        Eh = self.modulus * self.adhesion_range
        _warn_widths(
            q.a_over_R_at_pulloff * self.radius,
            self.radius,
            "the contact half-width at pull-off",
            "the repulsive region vanishes before the pull-off",
            stacklevel=4,
        )
        return CylinderLennardJonesPullOff(
            float(q.F_pulloff_over_Eh) * Eh,
            float(q.error_estimate_over_Eh) * Eh,
            float(q.a_over_R_at_pulloff) * self.radius,
            float(q.central_gap_over_h_at_pulloff) * self.adhesion_range,
            float(q.F_jump_in_over_Eh) * Eh,
            q,
        )


# --------------------------------------------------------------------------------------------
# tangential problems in SI units


@dataclass(frozen=True)
class CylinderTangential:
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


def _cylinder_tangential(
    problem,
    cylinder,
    normal_load,
    friction_stress,
    friction_coefficient,
    d_over_a,
    tangential_load,
    method,
    policy,
) -> CylinderTangential:
    if not isinstance(cylinder, Cylinder):
        raise ValueError(
            f"cylinder must be a linecontact.Cylinder (Cylinder.from_modulus or "
            f"Cylinder.from_materials), got {cylinder!r}"
        )
    if (friction_stress is None) == (friction_coefficient is None):
        raise ValueError(
            "give exactly one of friction_stress (constant tau0 [Pa]) or "
            "friction_coefficient (Coulomb mu)"
        )
    if (d_over_a is None) == (tangential_load is None):
        raise ValueError("give exactly one of d_over_a or tangential_load [N/m]")
    E = cylinder.modulus
    rolling = problem == "steady rolling"
    coulomb = friction_coefficient is not None
    pb = (
        (_CARTER if coulomb else _ROLLING)
        if rolling
        else (_CATTANEO_MINDLIN if coulomb else _INITIATION)
    )
    # every input checked, and the shapes against each other, before any solve
    if coulomb:
        F = check_array("normal_load", normal_load)
        fr_name, fr = (
            "friction_coefficient",
            _domain.check("friction_coefficient", friction_coefficient, "mu"),
        )
    else:
        F = check_array("normal_load", normal_load, low=-np.inf)
        fr_name, fr = "friction_stress", positive("friction_stress", friction_stress)
        _domain.check_si("friction_stress", fr, E, "tau0_over_E", "Pa")
    if d_over_a is not None:
        st_name = "d_over_a"
        st = check_array(
            "d_over_a", d_over_a, low=pb.d_low, low_inclusive=pb.d_low_inclusive, high=1.0
        )
    else:
        st_name, st = "tangential_load", non_negative("tangential_load", tangential_load)
    broadcast(normal_load=F, **{fr_name: fr, st_name: st})
    d = st if d_over_a is not None else None
    if coulomb:
        if cylinder.cohesive_stress != 0:
            raise ValueError(
                "Coulomb friction is the macro-scale counterpart for the "
                "non-adhesive Hertz contact: use a Cylinder without adhesion "
                "(cohesive_stress = 0), or give friction_stress"
            )
        contact = cylinder._for_load("normal_load", F)
        A = np.asarray(contact.contact_half_width) / cylinder.radius
        mu = fr
        if d is None:
            _domain.check_si("tangential_load", st, mu * F, "T_over_muF", "N/m")
        T = None if d is not None else st / (mu * F)
        coulomb_fn = steady_rolling_coulomb if rolling else sliding_initiation_coulomb
        full = mu * F
        try:
            r: Any = coulomb_fn(mu, A, d, T_over_muF=T, method=method, on_failure=policy)
        except NoEquilibriumError:
            raise _full_slip(st, full, "mu F", st_name) from None
        friction = "coulomb"
    else:
        contact = cylinder._for_load("normal_load", F)
        a = np.asarray(contact.contact_half_width)
        t0 = fr
        if d is None:
            _domain.check_si("tangential_load", st, E * a, "T_over_Ea", "N/m")
        T = None if d is not None else st / (E * a)
        fn = steady_rolling if rolling else sliding_initiation
        # broadcast with a so that every field has the shape of the points
        full = 2 * a * t0
        try:
            r = fn(t0 / E + 0 * a, d, T_over_Ea=T, method=method, on_failure=policy)
        except NoEquilibriumError:
            raise _full_slip(st, full, "2 a tau0", st_name) from None
        friction = "constant"
    a = np.asarray(contact.contact_half_width)
    Tn = np.multiply(r.T_over_Ea, E * a)
    creep = r.creep_over_V if rolling else None
    return CylinderTangential(
        problem,
        friction,
        _scalar(F + 0 * a),
        _scalar(a),
        _scalar(np.multiply(r.d_over_a, a)),
        _scalar(Tn),
        _scalar(full),
        creep,
        r.state,
        r,
        contact,
    )


def _full_slip(
    T: NDArray, full: ArrayLike, what: str, given: str = "tangential_load"
) -> NoEquilibriumError:
    """The error for a tangential load [N/m] at or above full slip, said in N/m.

    With ``given == "d_over_a"``, ``T`` is the stick zone given: full slip is ``d_over_a = 0``.
    """
    if given == "d_over_a":
        d, full = np.broadcast_arrays(np.asarray(T, float), np.asarray(full, float))
        di, fi = _first(d == 0, d, full) if np.any(d == 0) else (0.0, float(full.flat[0]))
        return NoEquilibriumError(
            f"d_over_a={di!r} is full slip (the tangential load is the full-slip load "
            f"{fi:.6g} N/m, {what}): the whole contact slips (sliding), there is no stick zone"
        )
    T, full = np.broadcast_arrays(np.asarray(T, float), np.asarray(full, float))
    Ti, fi = (
        _first(T >= full, T, full) if np.any(T >= full) else (float(T.flat[0]), float(full.flat[0]))
    )
    return NoEquilibriumError(
        f"tangential_load={Ti!r} N/m is at or above the full-slip load {fi:.6g} N/m ({what}): "
        "the whole contact slips (sliding), there is no stick zone"
    )


def _scalar(v):
    v = np.asarray(v)
    return v.item() if v.ndim == 0 else v


def cylinder_sliding_initiation(
    cylinder,
    normal_load: ArrayLike,
    *,
    friction_stress: ArrayLike | None = None,
    friction_coefficient: ArrayLike | None = None,
    d_over_a: ArrayLike | None = None,
    tangential_load: ArrayLike | None = None,
    method: str = "closed-form",
    on_failure: FailurePolicy = RAISE,
    **deprecated: Any,
) -> CylinderTangential:
    """Initiation of sliding of a :class:`~linecontact.cylinder.Cylinder` (SI units).

    Parameters
    ----------
    cylinder : Cylinder
        Geometry, materials and adhesion.
    normal_load : array_like
        ``F`` [N/m]; the contact half-width ``a`` is that of the stable normal contact
        (:meth:`Cylinder.contact`). A load below the pull-off force raises
        :class:`~linecontact.errors.NoEquilibriumError`.
    friction_stress : array_like, optional
        ``tau0`` [Pa], ``> 0``: the nano-scale law (:func:`sliding_initiation`).
    friction_coefficient : array_like, optional
        ``mu``, ``> 0``: Coulomb friction on the Hertz contact
        (:func:`sliding_initiation_coulomb`); the cylinder must have no adhesion and
        ``F > 0``. Give exactly one of ``friction_stress`` and ``friction_coefficient``.
    d_over_a : array_like, optional
        Stick-zone half-width over ``a`` in ``[0, 1)``.
    tangential_load : array_like, optional
        ``T`` [N/m], ``>= 0`` (exactly one of ``d_over_a`` and ``tangential_load``).
    method : {"closed-form", "collocation"}
        As in :func:`sliding_initiation`.
    on_failure : {"raise", "report"}
        As in :func:`sliding_initiation`: a tangential load at or above full slip raises
        :class:`~linecontact.errors.NoEquilibriumError` (``"raise"``, default), or gives
        ``state == "sliding"`` (``"report"``); README, "Conventions". **Changed** after
        0.2.0: the deprecated ``on_sliding`` defaulted to ``"report"``. A normal load below
        the pull-off force raises either way.

    Returns
    -------
    CylinderTangential

    Examples
    --------
    >>> from linecontact import Cylinder
    >>> cyl = Cylinder.from_modulus(50e-9, 100e9, cohesive_stress=1e9, adhesion_range=0.5e-9)
    >>> s = cylinder_sliding_initiation(cyl, 1.0, friction_stress=1e9, tangential_load=1.0)
    >>> s.state, s.stick_zone_end < s.contact_half_width
    ('stick-slip', True)
    """
    policy = failure_policy(
        on_failure, where="cylinder_sliding_initiation", accepts=("on_sliding",), **deprecated
    )
    return _cylinder_tangential(
        "sliding initiation",
        cylinder,
        normal_load,
        friction_stress,
        friction_coefficient,
        d_over_a,
        tangential_load,
        method,
        policy,
    )


def cylinder_steady_rolling(
    cylinder,
    normal_load: ArrayLike,
    *,
    friction_stress: ArrayLike | None = None,
    friction_coefficient: ArrayLike | None = None,
    d_over_a: ArrayLike | None = None,
    tangential_load: ArrayLike | None = None,
    method: str = "closed-form",
    on_failure: FailurePolicy = RAISE,
    **deprecated: Any,
) -> CylinderTangential:
    """Steady rolling of a driving :class:`~linecontact.cylinder.Cylinder` (SI units).

    Parameters as in :func:`cylinder_sliding_initiation`, with ``d_over_a`` in ``(-1, 1)``
    the start of the leading-edge stick zone; ``tangential_load`` is the tractive force
    [N/m]. The result's ``creep_ratio`` is ``(V - omega R)/V`` (negative).

    Examples
    --------
    >>> from linecontact import Cylinder
    >>> cyl = Cylinder.from_modulus(50e-9, 100e9, cohesive_stress=1e9, adhesion_range=0.5e-9)
    >>> r = cylinder_steady_rolling(cyl, 1.0, friction_stress=1e9, d_over_a=0.0)
    >>> r.creep_ratio < 0
    True
    """
    policy = failure_policy(
        on_failure, where="cylinder_steady_rolling", accepts=("on_sliding",), **deprecated
    )
    return _cylinder_tangential(
        "steady rolling",
        cylinder,
        normal_load,
        friction_stress,
        friction_coefficient,
        d_over_a,
        tangential_load,
        method,
        policy,
    )


# --------------------------------------------------------------------------------------------
# the pushed fibre in SI units


@dataclass(frozen=True)
class CylinderPush:
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
            raise ValueError("give length= to cylinder_push for totals in N")
        return v * self.length


def cylinder_push(
    cylinder,
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
    """Will a pushed :class:`~linecontact.cylinder.Cylinder` stay, roll or slide (SI units).

    The cylinder's adhesion is the advancing one (its ``cohesive_stress`` and
    ``adhesion_range`` ``h2``, e.g. from the advancing work of adhesion); the receding edge
    has the same ``sigma0`` and the range ``h1``, given as ``receding_range`` [m] or as
    ``receding_work_of_adhesion`` [J/m^2] (``h1 = w1 / sigma0``), ``h1 >= h2``.

    Parameters
    ----------
    cylinder : Cylinder
        Geometry, materials, advancing adhesion.
    friction_stress : float
        ``tau0`` [Pa].
    height : array_like
        ``H`` [m] of the push, in ``[0, 2R]`` (of the tip's contact, in ``(0, 2R)``).
    receding_range, receding_work_of_adhesion : float
        Exactly one.
    normal_load : array_like
        ``F`` [N/m] (default 0).
    push : array_like, optional
        A horizontal push [N/m] whose state is wanted.
    tip_friction : array_like, optional
        A tip at ``height`` with this friction coefficient (:func:`linecontact.push`).
    length : float, optional
        The fibre's length [m], for the totals.

    Returns
    -------
    CylinderPush

    Examples
    --------
    >>> from linecontact import Cylinder, adhesion_from_work
    >>> s0, h1 = adhesion_from_work(0.05, 0.3e-9)        # receding work of adhesion
    >>> cyl = Cylinder.from_modulus(50e-9, 48.4e9, cohesive_stress=s0, adhesion_range=0.025 / s0)
    >>> p = cylinder_push(cyl, friction_stress=1e6, height=[25e-9, 50e-9], receding_range=h1)
    >>> [str(m) for m in p.first_motion]
    ['slide', 'roll']
    """
    if (receding_range is None) == (receding_work_of_adhesion is None):
        raise ValueError("give exactly one of receding_range [m] or receding_work_of_adhesion")
    s0, h2, R, E = (
        cylinder.cohesive_stress,
        cylinder.adhesion_range,
        cylinder.radius,
        cylinder.modulus,
    )
    if receding_range is not None:
        # h1 >= h2 (the hysteresis is not negative), as push's h1/h2 in [1, 1000]
        h1 = scalar(
            "receding_range",
            receding_range,
            low=h2,
            low_inclusive=True,
            high=1e3 * h2,
            high_inclusive=True,
        )
    elif receding_work_of_adhesion is not None:
        w1 = scalar("receding_work_of_adhesion", receding_work_of_adhesion)
        if not (np.isfinite(w1) and w1 > 0 and s0 > 0):
            raise ValueError(
                "receding_work_of_adhesion must be a finite number > 0, with a cylinder that "
                f"has adhesion (cohesive_stress > 0), got {w1!r}"
            )
        scalar(
            "receding_work_of_adhesion",
            w1,
            low=s0 * h2,
            low_inclusive=True,
            high=1e3 * s0 * h2,
            high_inclusive=True,
        )
        h1 = w1 / s0
        _plausible("receding_work_of_adhesion", w1, key="work_of_adhesion")
    if receding_range is not None:
        _plausible("receding_range", h1, key="adhesion_range")
    tau = scalar("friction_stress", friction_stress)
    _domain.check_si("friction_stress", tau, E, "tau0_over_E", "Pa")
    H = check_array("height", height, low=0.0, low_inclusive=True, high=2 * R, high_inclusive=True)
    Eh = E * h2
    # the SI inputs are checked (and named) here, not as the groups they form
    load = check_array("normal_load", normal_load, low=-np.inf, high=np.inf)
    _domain.check_si("normal_load", load, Eh, "F_over_Eh2", "N/m")
    F = load / Eh
    Q = None
    if push is not None:
        Q = check_array("push", push, low=0.0, low_inclusive=True) / Eh
    if length is not None:
        positive("length", length)
    try:
        p = _push.push(
            R / h2,
            h1 / h2,
            cylinder.sigma0_over_E,
            tau / E,
            F,
            np.asarray(H, float) / R,
            Q,
            tip_friction=tip_friction,
        )
    except NoEquilibriumError:
        # below the pull-off force of steady sliding: said in N/m, for this cylinder
        from .sliding import sliding_pull_off

        F_po = float(sliding_pull_off(R / h2, h1 / h2, cylinder.sigma0_over_E).F_pulloff_over_Eh2)
        F_po *= Eh
        below = np.asarray(load < F_po)
        Fi = float(load[below].flat[0]) if np.any(below) else float(np.min(load))
        raise NoEquilibriumError(
            f"normal_load={Fi!r} N/m is below the sliding pull-off force {F_po:.6g} N/m of "
            f"this cylinder (receding range {h1:.6g} m): it has pulled off"
        ) from None
    except _domain.TooWideError as e:
        # e.index counts the points of push, over the shape all its inputs broadcast to
        points = np.broadcast_shapes(
            *(np.shape(v) for v in (F, H, Q, tip_friction) if v is not None)
        )
        Fi = float(np.broadcast_to(load, points).reshape(-1)[e.index])
        raise ValueError(
            f"normal_load={Fi!r} N/m needs a contact of half-width {e.a_over_R * R:.6g} m, "
            f"{e.a_over_R:.6g} radii: {e.limit}"
        ) from None

    def si(v, unit):
        out = np.multiply(v, unit)
        return out.item() if np.ndim(out) == 0 else out

    _warn_widths(si(p.a_rest_over_R, R), R, "the contact half-width at rest")
    _warn_widths(si(p.a_slide_over_R, R), R, "the contact half-width while sliding")
    return CylinderPush(
        height=si(p.H_over_R, R),
        moment_arm=si(p.H_arm_over_R, R),
        rest_half_width=si(p.a_rest_over_R, R),
        slide_half_width=si(p.a_slide_over_R, R),
        rolling_resistance=si(p.Q_roll_over_Eh2, Eh),
        sliding_resistance=si(p.Q_slide_over_Eh2, Eh),
        slip_onset=si(p.Q_onset_over_Eh2, Eh),
        critical_height=si(p.H_critical_over_R, R),
        first_motion=p.first_motion,
        creep_ratio=p.creep_over_V,
        state=p.state,
        length=length,
        nondimensional=p,
    )


# --------------------------------------------------------------------------------------------
# tangential load histories and cyclic loading in SI units


def _history_contact(cylinder, normal_load, friction_stress, friction_coefficient):
    """(F, a [m], friction scale, coulomb?) for the SI history functions, every input checked."""
    if not isinstance(cylinder, Cylinder):
        raise ValueError(
            f"cylinder must be a linecontact.Cylinder (Cylinder.from_modulus or "
            f"Cylinder.from_materials), got {cylinder!r}"
        )
    if (friction_stress is None) == (friction_coefficient is None):
        raise ValueError(
            "give exactly one of friction_stress (constant tau0 [Pa]) or "
            "friction_coefficient (Coulomb mu)"
        )
    coulomb = friction_coefficient is not None
    if coulomb:
        F = scalar("normal_load", normal_load)
        fr = _domain.scalar("friction_coefficient", friction_coefficient, "mu")
        if cylinder.cohesive_stress != 0:
            raise ValueError(
                "Coulomb friction is the macro-scale counterpart for the non-adhesive Hertz "
                "contact: use a Cylinder without adhesion (cohesive_stress = 0), or give "
                "friction_stress"
            )
    else:
        F = scalar("normal_load", normal_load, low=-np.inf)
        fr = scalar("friction_stress", friction_stress)
        _domain.check_si("friction_stress", fr, cylinder.modulus, "tau0_over_E", "Pa")
    contact = cylinder._for_load("normal_load", F)
    a = float(contact.contact_half_width)
    return F, a, fr, coulomb, contact


def _history_solve(cylinder, normal_load, stress, coefficient, loads, constant, coulomb, method):
    """``(F, a, full-slip load, result, law)``: ``loads`` [N/m] through the nondimensional call.

    ``constant(tau0/E, loads/(E a))`` or ``coulomb(mu, a/R, loads/(mu F))``; ``law`` is
    ``"constant"`` or ``"coulomb"``.
    """
    F, a, fr, is_coulomb, _ = _history_contact(cylinder, normal_load, stress, coefficient)
    if is_coulomb:
        r = coulomb(fr, a / cylinder.radius, loads / (fr * F), method=method)
        full = fr * F
    else:
        E = cylinder.modulus
        r = constant(fr / E, loads / (E * a), method=method)
        full = 2 * a * fr
    return F, a, full, r, "coulomb" if is_coulomb else "constant"


@dataclass(frozen=True)
class CylinderTangentialHistory:
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


def cylinder_tangential_history(
    cylinder,
    normal_load: float,
    tangential_load: ArrayLike,
    *,
    friction_stress: float | None = None,
    friction_coefficient: float | None = None,
    method: str = "closed-form",
) -> CylinderTangentialHistory:
    """The states of a :class:`~linecontact.cylinder.Cylinder` along a tangential history.

    Parameters
    ----------
    cylinder : Cylinder
    normal_load : float
        ``F`` [N/m], fixed; ``a`` is that of the stable normal contact.
    tangential_load : array_like, 1-D
        ``T`` [N/m] at the end of each step, either sign, starting from 0.
    friction_stress, friction_coefficient : float
        Exactly one: ``tau0`` [Pa] (constant friction stress) or ``mu`` (Coulomb, Hertz).
    method : {"closed-form", "incremental"}
        As in :func:`linecontact.tangential_history`.

    Returns
    -------
    CylinderTangentialHistory

    Examples
    --------
    >>> from linecontact import Cylinder
    >>> cyl = Cylinder.from_modulus(50e-9, 100e9, cohesive_stress=1e9, adhesion_range=0.5e-9)
    >>> h = cylinder_tangential_history(cyl, 1.0, [1.0, -1.0, 1.0], friction_stress=1e9)
    >>> h.state.tolist()
    ['stick-slip', 'stick-slip', 'stick-slip']
    >>> bool(h.dissipation[1] > 0)
    True
    """
    from .tangential.history import tangential_history, tangential_history_coulomb

    T = check_array("tangential_load", tangential_load, low=-np.inf)
    F, a, full, h, law = _history_solve(
        cylinder,
        normal_load,
        friction_stress,
        friction_coefficient,
        T,
        tangential_history,
        tangential_history_coulomb,
        method,
    )
    E = cylinder.modulus
    return CylinderTangentialHistory(
        law,
        F,
        a,
        full,
        T.reshape(-1),  # as given (not back from T/(E a))
        np.asarray(h.c_over_a) * a,
        np.asarray(h.displacement_over_a) * a,
        np.asarray(h.dissipation_over_Ea2) * E * a * a,
        h.state,
        h,
    )


@dataclass(frozen=True)
class CylinderCyclicLoss:
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

    friction: str
    normal_load: float
    contact_half_width: float
    full_slip_load: float
    amplitude: NDArray | float
    energy_per_cycle: NDArray | float
    stick_zone_half_width: NDArray | float
    state: NDArray | str
    nondimensional: Any = field(repr=False)


def cylinder_cyclic_loss(
    cylinder,
    normal_load: float,
    amplitude: ArrayLike,
    *,
    friction_stress: float | None = None,
    friction_coefficient: float | None = None,
    method: str = "closed-form",
) -> CylinderCyclicLoss:
    """Energy dissipated per cycle between ``-T*`` and ``+T*`` (SI units).

    Parameters
    ----------
    cylinder : Cylinder
    normal_load : float
        ``F`` [N/m], fixed.
    amplitude : array_like
        ``T*`` [N/m], ``> 0``; at or above full slip the state is ``"sliding"``.
    friction_stress, friction_coefficient : float
        Exactly one: ``tau0`` [Pa] or Coulomb ``mu``.
    method : {"closed-form", "incremental"}
        As in :func:`linecontact.cyclic_loss`.

    Returns
    -------
    CylinderCyclicLoss

    Examples
    --------
    >>> from linecontact import Cylinder
    >>> cyl = Cylinder.from_modulus(50e-9, 100e9, cohesive_stress=1e9, adhesion_range=0.5e-9)
    >>> w = cylinder_cyclic_loss(cyl, 1.0, [0.5, 1.0], friction_stress=1e9)
    >>> bool(w.energy_per_cycle[1] > w.energy_per_cycle[0] > 0)
    True
    """
    from .tangential.history import cyclic_loss, cyclic_loss_coulomb

    A = check_array("amplitude", amplitude, low=0.0, low_inclusive=False)
    F, a, full, w, law = _history_solve(
        cylinder,
        normal_load,
        friction_stress,
        friction_coefficient,
        A,
        cyclic_loss,
        cyclic_loss_coulomb,
        method,
    )
    E = cylinder.modulus
    return CylinderCyclicLoss(
        law,
        F,
        a,
        full,
        _scalar(A + 0 * np.asarray(w.W_over_Ea2)),  # as given, in the result's shape
        _scalar(np.multiply(w.W_over_Ea2, E * a * a)),
        _scalar(np.multiply(w.c_over_a, a)),
        w.state,
        w,
    )
