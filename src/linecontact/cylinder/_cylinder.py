""":class:`Cylinder`: radius, modulus, adhesion, Dundurs' beta, cross-section; normal contact."""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, ClassVar, Literal

import numpy as np
from numpy.typing import ArrayLike

from .. import _moved
from .. import closed_forms as _cf
from .. import domain as _domain
from .. import normal as _normal
from .._validation import (
    FailurePolicy,
    failure_policy,
    positive,
    scalar,
)
from ..errors import CouplingWarning, NoEquilibriumError, UnitsWarning
from ..geometry import ROUND, CrossSection
from ..laws._values import Dugdale, Law, LennardJones
from ..materials import (
    BETA_WARN,
    _moduli,
    composite_modulus,
    dundurs_beta,
)
from ..units import Scales, to_si
from . import _facet, _lj_problems, _problems, _sliding
from ._checks import (
    _S_LJ,
    _ZERO_WIDTH,
    PLAUSIBLE,
    _as_given,
    _check_cylinder_si,
    _normal_load,
    _small_strain_in_si,
    _too_wide,
    _warn_small_strain,
    _warn_widths,
)
from ._results import (
    CylinderContact,
    CylinderLennardJonesLoadCurve,
    CylinderLennardJonesPullOff,
    CylinderLoadCurve,
    CylinderPullOff,
)

if TYPE_CHECKING:  # imported where used: the Lennard-Jones solver needs scipy
    from ..presets import Material


@dataclass(frozen=True)
class Cylinder:
    r"""A cylinder of radius ``R`` on a substrate, with its adhesion law: a body.

    Build it with :meth:`from_materials`, :meth:`from_modulus` or :meth:`from_presets`; the
    adhesion is a law value (:class:`~linecontact.laws.Dugdale`, the default, or
    :class:`~linecontact.laws.LennardJones`), given as ``adhesion=`` or by its parameters
    (a Dugdale law). Each problem is a method: :meth:`contact`, :meth:`pull_off`,
    :meth:`load_curve` (both laws), :meth:`sliding`, :meth:`sliding_initiation`,
    :meth:`steady_rolling`, :meth:`push`, :meth:`tangential_history` and
    :meth:`cyclic_loss` (the Dugdale law); a problem not written for the law is refused,
    naming both.

    Attributes
    ----------
    radius : float
        ``R`` [m] (the equivalent radius for two cylinders).
    modulus : float
        Composite plane-strain modulus ``E`` [Pa].
    adhesion : Law
        The adhesion law and its SI parameters.
    dundurs_beta : float
        Dundurs' :math:`\beta = -B/A` (0 when only the composite modulus was given).
    cross_section : CrossSection
        :class:`~linecontact.geometry.Round` (the default) or a
        :class:`~linecontact.geometry.Polygon` on its facet (``radius`` its circumradius):
        :meth:`shaped` gives the same wire with another; the problems written for a polygon
        are :meth:`contact`, :meth:`pull_off`, :meth:`load_curve` and
        :meth:`sliding_initiation` (its constant friction stress) under the Dugdale law
        (``WRITTEN``).
    cohesive_stress, adhesion_range : float
        ``sigma0`` [Pa] (0: no adhesion) and ``h`` [m] of the law's Dugdale step.

    Examples
    --------
    >>> cyl = Cylinder.from_modulus(50e-9, 100e9, cohesive_stress=1e9, adhesion_range=0.5e-9)
    >>> round(cyl.R_over_h, 9), cyl.sigma0_over_E
    (100.0, 0.01)
    >>> from linecontact.laws import LennardJones
    >>> lj = Cylinder.from_modulus(50e-9, 100e9, adhesion=LennardJones(0.1, 0.3e-9))
    >>> round(lj.pull_off().pull_off_force, 3)
    -3.107
    """

    radius: float
    modulus: float
    adhesion: Law
    dundurs_beta: float = 0.0
    cross_section: CrossSection = ROUND

    @property
    def cohesive_stress(self) -> float:
        r""":math:`\sigma_0` [Pa] of the law's Dugdale step (0: no adhesion)."""
        return self.adhesion.cohesive_stress

    @property
    def adhesion_range(self) -> float:
        """``h`` [m] of the law's Dugdale step."""
        return self.adhesion.adhesion_range

    def __post_init__(self) -> None:
        self._settle()
        _check_cylinder_si(
            self.radius,
            self.modulus,
            {"cohesive_stress": self.cohesive_stress, "adhesion_range": self.adhesion_range},
            stacklevel=5,
        )

    @classmethod
    def _made(
        cls,
        radius: float,
        modulus: float,
        adhesion: Law,
        beta: float,
        shape: CrossSection = ROUND,
    ) -> Cylinder:
        """The cylinder of a factory that has checked its SI inputs under its caller's names.

        The fields are settled as the constructor settles them, without the constructor's
        check under the fields' names (the factory said it as ``work_of_adhesion``,
        ``equilibrium_spacing``, ...): an argument of the build, not a state around it.
        """
        self = object.__new__(cls)
        fields = {"radius": radius, "modulus": modulus, "adhesion": adhesion, "dundurs_beta": beta}
        fields["cross_section"] = shape
        for name, value in fields.items():
            object.__setattr__(self, name, value)
        self._settle()
        return self

    def _settle(self) -> None:
        """Check the fields and keep them as Python floats (also when built directly)."""
        if not isinstance(self.adhesion, Law):
            raise ValueError(
                f"adhesion must be a law (linecontact.laws.Dugdale or LennardJones), got "
                f"{self.adhesion!r}"
            )
        for name, limits in (
            ("radius", {}),
            ("modulus", {}),
            # |beta| < 3/4 for any pair of materials (a rigid body on nu = -1: 3/4)
            (
                "dundurs_beta",
                {"low": -0.75, "low_inclusive": True, "high": 0.75, "high_inclusive": True},
            ),
        ):
            object.__setattr__(self, name, scalar(name, getattr(self, name), **limits))
        if not isinstance(self.cross_section, CrossSection):
            raise ValueError(
                "cross_section must be a cross-section (linecontact.geometry.Round or "
                f"Polygon), got {self.cross_section!r}"
            )
        self.cross_section.checked(self.radius)
        # the units of the groups must be representable: R/h, sigma0/E and E h (said in the
        # caller's names: the groups are the library's)
        for what, v in (
            ("radius/adhesion_range", self.radius / self.adhesion_range),
            ("cohesive_stress/modulus", self.cohesive_stress / self.modulus),
            (
                "modulus*adhesion_range (the unit of force per length)",
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

    @classmethod
    def _build(
        cls,
        R: float,
        E: float,
        beta: float,
        adhesion: tuple[float | None, float | None, float | None, float | None],
        modulus_name: str = "modulus",
        law: Law | None = None,
    ) -> Cylinder:
        """The cylinder of a factory, its SI inputs checked under the names the caller gave."""
        cohesive_stress, adhesion_range, work_of_adhesion, equilibrium_spacing = adhesion
        if law is None:
            law = Dugdale(
                work_of_adhesion=work_of_adhesion,
                equilibrium_spacing=equilibrium_spacing,
                cohesive_stress=cohesive_stress,
                adhesion_range=adhesion_range,
            )
        elif any(v is not None for v in adhesion):
            raise ValueError(
                "give adhesion either as a law (adhesion=Dugdale(...) or LennardJones(...)) "
                "or by its parameters (cohesive_stress, adhesion_range or work_of_adhesion, "
                "equilibrium_spacing), not both"
            )
        elif not isinstance(law, Law):
            raise ValueError(
                f"adhesion must be a law (linecontact.laws.Dugdale or LennardJones), got {law!r}"
            )
        _check_cylinder_si(R, E, dict(law.given), modulus_name=modulus_name, stacklevel=5)
        return cls._made(R, E, law, beta)

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
        adhesion: Law | None = None,
    ) -> Cylinder:
        """From the composite modulus ``E`` [Pa].

        The adhesion as a law value (``adhesion=LennardJones(w, z0)``), or a Dugdale law by
        its parameters ``(sigma0, h)`` or ``(w, z0)``.
        """
        R = scalar("radius", radius)
        E = scalar("modulus", modulus)
        given = (cohesive_stress, adhesion_range, work_of_adhesion, equilibrium_spacing)
        return cls._build(R, E, 0.0, given, law=adhesion)

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
        adhesion: Law | None = None,
    ) -> Cylinder:
        """From the moduli [Pa] and Poisson ratios of cylinder (1) and substrate (2).

        The adhesion as in :meth:`from_modulus`.
        """
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
                    UnitsWarning,
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
        given = (cohesive_stress, adhesion_range, work_of_adhesion, equilibrium_spacing)
        return cls._build(R, E, beta, given, "composite modulus", law=adhesion)

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
        adhesion: Law | None = None,
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
        adhesion : Law, optional
            The adhesion as a law value, instead.

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
        from ..presets import Material

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
                adhesion=adhesion,
            )
        for w in caught:  # said where from_presets was called, not in here
            warnings.warn(w.message, stacklevel=2)
        return cyl

    # groups ------------------------------------------------------------------------------
    @property
    def R_over_h(self) -> float:
        """:math:`R/h`."""
        return self.radius / self.adhesion_range

    @property
    def sigma0_over_E(self) -> float:
        r""":math:`\sigma_0/E`."""
        return self.cohesive_stress / self.modulus

    @property
    def work_of_adhesion(self) -> float:
        r""":math:`w = \sigma_0 h` [J/m^2] of the law."""
        return self.adhesion.work_of_adhesion

    @property
    def maugis_parameter(self) -> float:
        """Baney & Hui's line-contact Tabor-like parameter (DMT-like small, JKR-like large)."""
        return float(_cf.maugis_parameter(self.R_over_h, self.sigma0_over_E))

    @property
    def kappa(self) -> float:
        """The single group of the Maugis--Dugdale line contact."""
        return float(_cf.kappa(self.R_over_h, self.sigma0_over_E))

    def _check_lennard_jones(self, pull_off: bool = False) -> None:
        r"""Refuse, in SI terms, a cylinder outside the domain of the Lennard-Jones solver.

        The solver's group is the Maugis (Tabor) parameter :math:`\mu = w R^{1/2} / (E z_0^{3/2})`
        with :math:`w = \sigma_0 h` and :math:`z_0 = 16 h/(9 \sqrt 3)`; the message gives its value
        for this cylinder, the inputs as they were given, and what would bring it in.
        """
        hi = _domain.DOMAIN["lj_mu"][2]
        R, E = self.radius, self.modulus
        w, z0 = self.work_of_adhesion, _S_LJ * self.adhesion_range
        given = self.adhesion.given
        if self.cohesive_stress <= 0:
            raise ValueError(
                "the Lennard-Jones law needs adhesion: give the cylinder a work of adhesion "
                "(work_of_adhesion and equilibrium_spacing, or cohesive_stress > 0)"
            )
        mu = w * math.sqrt(R / z0) / (E * z0)
        if mu <= hi or pull_off:  # the pull-off has a limit form beyond
            return
        from ..lennard_jones import maugis_parameter_of_mu

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
            f"under the Lennard-Jones law w R^(1/2) / (E z0^(3/2)) of this cylinder is "
            f"{mu:.4g} (radius={R!r} m, modulus={E!r} Pa, {inputs}): the Lennard-Jones "
            f"solver takes it up to {hi:g} for contacts and load curves (a Tabor-Maugis "
            f"parameter up to {lam:.3g}; the pull-off at any value). Use the Dugdale law "
            f"(law='dugdale', any value), or a radius below {R * (hi / mu) ** 2:.3g} m, a "
            f"modulus above {E * mu / hi:.3g} Pa{more}"
        )

    # problems ----------------------------------------------------------------------------
    def _wrap(self, r: _normal.NormalContact) -> CylinderContact:
        si = to_si(r, Scales.of(self))
        _warn_widths(si["contact_half_width"], self.radius, stacklevel=4)
        return CylinderContact(
            **si, stable=r.stable, state=r.state, nondimensional=r, scales=Scales.of(self)
        )

    def contact(
        self,
        *,
        contact_half_width: ArrayLike | None = None,
        load: ArrayLike | None = None,
        method: str = "closed-form",
        branch: str = "stable",
        on_failure: FailurePolicy = "raise",
    ) -> CylinderContact:
        """The contact at given half-widths ``a`` [m] or loads ``F`` [N/m] (exactly one).

        For a load, ``branch`` selects the stable (default) or the unstable contact state;
        a load that no contact of the branch carries (below the pull-off force) raises
        :class:`~linecontact.errors.NoEquilibriumError`, or with ``on_failure="report"``
        gives ``state == "no-equilibrium"`` and NaN values; for a half-width, ``on_failure``
        is that of :func:`~linecontact.normal_contact` (a collocation point that misses its
        tolerance raises :class:`~linecontact.errors.ConvergenceError`, or is flagged in
        ``nondimensional.converged``). README, "Conventions".

        Under the Lennard-Jones law: the stable contact carrying ``load``, solved
        self-consistently (:func:`linecontact.laws.lennard_jones.contact_for_load`), with the
        law's :math:`w` and :math:`z_0` (a load below the pull-off force as above); a given
        half-width, ``method`` and ``branch`` are the Dugdale law's.
        """
        if (contact_half_width is None) == (load is None):
            raise ValueError("give exactly one of contact_half_width or load")
        policy = failure_policy(on_failure)
        if self.cross_section.kind != "round":
            self._written("contact")
            return _facet.contact(self, contact_half_width, load, method, branch, policy)
        if isinstance(self.adhesion, LennardJones):
            self._dugdale_only(
                "the contact",
                contact_half_width=contact_half_width is not None,
                method=method != "closed-form",
                branch=branch != "stable",
            )
            self._check_lennard_jones()
            return self._for_load_lj("load", load, policy)  # type: ignore[arg-type,return-value]
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
            with _small_strain_in_si():  # said in metres by _wrap
                r = _normal.normal_contact(
                    a / self.radius,
                    self.R_over_h,
                    self.sigma0_over_E,
                    method=method,
                    on_failure=policy,
                )
        else:
            return self._for_load("load", load, branch, policy)  # type: ignore[arg-type]
        return self._wrap(r)

    def _for_load(
        self, name: str, load: ArrayLike, branch: str = "stable", policy: FailurePolicy = "raise"
    ) -> CylinderContact:
        """The contact carrying ``load`` [N/m]; messages name the caller's parameter."""
        if self.cross_section.kind != "round":
            return _facet.for_load(self, name, load, policy)
        F, Eh = _normal_load(self, name, load)
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
            with _small_strain_in_si():  # said in metres by _wrap
                r = _normal.contact_for_load(
                    F / Eh,
                    self.R_over_h,
                    self.sigma0_over_E,
                    branch=branch,
                    on_failure=policy,
                )
        except _domain.TooWideError as e:
            Fi = float(np.reshape(np.broadcast_to(F, np.shape(F)), -1)[e.index])
            raise _too_wide(name, Fi, e, self.radius) from None
        # the load asked for, not F/(Eh) times E h (which need not give back F exactly)
        c = self._wrap(r)
        return CylinderContact(
            c.contact_half_width,
            c.adhesive_zone_half_width,
            _as_given(F, c.load),
            c.stable,
            c.state,
            r,
            scales=Scales.of(self),
        )

    def pull_off(self) -> CylinderPullOff | CylinderLennardJonesPullOff:
        """Pull-off force under load control [N/m], under the cylinder's law.

        The Lennard-Jones law's (:func:`linecontact.laws.lennard_jones.pull_off`) is a
        :class:`CylinderLennardJonesPullOff`, with the law's ``w`` and ``z0``.
        """
        if self.cross_section.kind != "round":
            self._written("pull_off")
            return _facet.pull_off(self)
        if isinstance(self.adhesion, LennardJones):
            return self._pull_off_lj()
        p = _normal.pull_off(self.R_over_h, self.sigma0_over_E)
        si = to_si(p, Scales.of(self))
        _warn_widths(
            si["contact_half_width_at_pull_off"],
            self.radius,
            "the contact half-width at pull-off",
            _ZERO_WIDTH if p.mechanism == "zero-width" else "",
            stacklevel=3,
        )
        return CylinderPullOff(**si, mechanism=p.mechanism, nondimensional=p)

    def under(self, law: type[Law]) -> Cylinder:
        """The same cylinder, with the same adhesion (the same Dugdale step) under ``law``.

        >>> from linecontact.laws import LennardJones
        >>> cyl = Cylinder.from_modulus(
        ...     50e-9, 100e9, work_of_adhesion=0.1, equilibrium_spacing=0.3e-9
        ... )
        >>> round(cyl.under(LennardJones).pull_off().pull_off_force, 3)
        -3.107
        """
        if not (isinstance(law, type) and issubclass(law, Law)):
            raise ValueError(f"law must be a law's class (Dugdale or LennardJones), got {law!r}")
        # checked when it was built
        return self._made(
            self.radius,
            self.modulus,
            self.adhesion.same_adhesion(law),
            self.dundurs_beta,
            self.cross_section,
        )

    #: The problems written for each cross-section's kind and law (the others are refused,
    #: naming both: one place).
    WRITTEN: ClassVar[dict[str, dict[str, tuple[type[Law], ...]]]] = {
        "contact": {"round": (Dugdale, LennardJones), "polygon": (Dugdale,)},
        "pull_off": {"round": (Dugdale, LennardJones), "polygon": (Dugdale,)},
        "load_curve": {"round": (Dugdale, LennardJones), "polygon": (Dugdale,)},
        "sliding_initiation": {"round": (Dugdale,), "polygon": (Dugdale,)},
        "steady_rolling": {"round": (Dugdale,)},
        "push": {"round": (Dugdale,)},
        "tangential_history": {"round": (Dugdale,)},
        "cyclic_loss": {"round": (Dugdale,)},
        "sliding": {"round": (Dugdale,)},
    }

    def _written(self, problem: str) -> None:
        """Refuse ``problem`` where it is not written for this wire's cross-section and law."""
        laws = self.WRITTEN[problem].get(self.cross_section.kind, ())
        if not isinstance(self.adhesion, laws):
            self._not_written(problem)

    def _dugdale_only(self, problem: str, **given: bool) -> None:
        """Refuse ``problem`` with the Dugdale law's keywords ``given`` (True: given)."""
        named = [k for k, v in given.items() if v]
        if named:
            self._not_written(f"{problem} with {', '.join(named)}")

    def _not_written(self, problem: str) -> None:
        """Refuse ``problem``: it is not written for this geometry under this law."""
        shape = self.cross_section
        if shape.kind != "round":
            raise ValueError(
                f"{problem} is not written for a {shape.name} wire (cross_section="
                f"{shape!r}) under the {self.adhesion.name} law: for a polygon, the contact, "
                "the pull-off, the load curve and the initiation of sliding (a constant "
                "friction stress) under the Dugdale law are; the round wire "
                "(cross_section=Round()) has every problem"
            )
        raise ValueError(
            f"{problem} is not written for a cylinder under the {self.adhesion.name} law "
            f"(adhesion={self.adhesion!r}): give the cylinder a Dugdale law "
            "(adhesion=Dugdale(...) or its parameters) for it"
        )

    # the SI form of the groups ---
    def scale(self, name: str) -> float:
        """The SI unit of a group: ``"R"``, ``"h"`` [m], ``"E"`` [Pa], ``"Eh"`` [N/m], ``"EhR"``.

        ``"EhR"`` [N] is the unit of a moment per unit length.

        >>> cyl = Cylinder.from_modulus(50e-9, 100e9, cohesive_stress=1e9, adhesion_range=0.5e-9)
        >>> cyl.scale("Eh")
        50.0
        """
        R, E, h = self.radius, self.modulus, self.adhesion_range
        units = {"R": R, "h": h, "E": E, "Eh": E * h, "EhR": E * h * R}
        if name not in units:
            raise ValueError(f"scale must be one of {', '.join(units)}, got {name!r}")
        return units[name]

    def in_si(self, value: ArrayLike, scale: str) -> Any:
        """``value`` given over the group ``scale`` (:meth:`scale`) in SI units."""
        return np.multiply(value, self.scale(scale))

    def over(self, value: ArrayLike, scale: str) -> Any:
        """``value`` in SI units over the group ``scale`` (:meth:`scale`); :meth:`in_si` undone."""
        return np.divide(value, self.scale(scale))

    @staticmethod
    def total(value: Any, length: float | None) -> Any:
        """A value per unit length (N/m, J/m, N m/m) over a fibre of ``length`` [m].

        None without a length; otherwise ``value * length`` ([N], [J], [N m]).
        """
        if length is None:
            return None
        return np.multiply(value, positive("length", length))

    def tangential_load(
        self,
        normal_load: float,
        value: ArrayLike,
        *,
        over: Literal["Ea", "muF"] = "Ea",
        friction_coefficient: float | None = None,
    ) -> Any:
        """A tangential load [N/m] given over ``E a`` or over ``mu F`` (Coulomb).

        ``a`` is the half-width of the stable contact under ``normal_load`` ``F`` [N/m]
        (:meth:`contact`), ``mu`` the ``friction_coefficient``: ``value * (E a)`` or
        ``value * mu * F``.
        """
        if over == "muF":
            if friction_coefficient is None:
                raise ValueError(
                    "a load over the Coulomb limit (over='muF') needs friction_coefficient"
                )
            return np.multiply(np.multiply(value, friction_coefficient), normal_load)
        if over != "Ea":
            raise ValueError(f"over must be 'Ea' or 'muF', got {over!r}")
        a = self.contact(load=normal_load).contact_half_width
        return np.multiply(value, self.modulus * a)

    # the tangential problems, the pushed fibre, the load histories and steady sliding: the
    # functions of _problems.py and _sliding.py are these methods (self is the cylinder) --
    sliding_initiation = _problems.sliding_initiation
    steady_rolling = _problems.steady_rolling
    push = _problems.push
    tangential_history = _problems.tangential_history
    cyclic_loss = _problems.cyclic_loss
    sliding = _sliding.sliding
    shaped = _facet.shaped
    # the Lennard-Jones law's contact, pull-off and load curve (self is the cylinder)
    _for_load_lj = _lj_problems.for_load
    _pull_off_lj = _lj_problems.pull_off
    _load_curve_lj = _lj_problems.load_curve

    # the normal problems -------------------------------------------------------------------
    def load_curve(
        self,
        *,
        max_half_width: float | None = None,
        num: int = 200,
        num_noncontact: int = 40,
        max_load: float | None = None,
    ) -> CylinderLoadCurve | CylinderLennardJonesLoadCurve:
        """The load curve (:func:`linecontact.load_curve`) up to ``max_half_width`` [m].

        Returns the SI :class:`CylinderLoadCurve` (its ``nondimensional`` the
        :class:`~linecontact.normal.LoadCurve`, with the pull-off). Under the Lennard-Jones
        law: the curve up to the compressive ``max_load`` [N/m]
        (:func:`linecontact.laws.lennard_jones.load_curve`), a
        :class:`CylinderLennardJonesLoadCurve`; ``max_half_width``, ``num`` and
        ``num_noncontact`` are the Dugdale law's, ``max_load`` the Lennard-Jones law's.
        """
        self._written("load_curve")
        if self.cross_section.kind != "round":
            return _facet.load_curve(self, max_half_width, num, num_noncontact)
        if isinstance(self.adhesion, LennardJones):
            self._dugdale_only(
                "the load curve",
                max_half_width=max_half_width is not None,
                num=num != 200,
                num_noncontact=num_noncontact != 40,
            )
            return self._load_curve_lj(max_load)
        if max_load is not None:
            raise ValueError(
                "max_load ends the load curve of the Lennard-Jones law: the Dugdale law's "
                "ends at max_half_width"
            )
        a_max = None
        if max_half_width is not None:
            _domain.check_si("max_half_width", max_half_width, self.radius, "a_max_over_R", "m")
            a_max = self.over(max_half_width, "R")
        with _small_strain_in_si():
            c = _normal.load_curve(
                self.R_over_h,
                self.sigma0_over_E,
                a_max_over_R=a_max,
                num=num,
                num_noncontact=num_noncontact,
            )
        curve = _si_load_curve(self, c)
        _warn_small_strain(curve.contact_half_width, self.radius, stacklevel=3)
        return curve

    def __getattr__(self, name: str) -> Any:
        # a method deleted before 1.0 (linecontact._moved): its error names the replacement
        return _moved.resolve("linecontact.Cylinder", name)


def _si_load_curve(cylinder: Cylinder, c: Any) -> CylinderLoadCurve:
    """The SI form of the nondimensional load curve ``c`` of ``cylinder`` (its groups)."""
    return CylinderLoadCurve(
        branch=c.branch,
        **to_si(c, Scales.of(cylinder)),
        stable=c.stable,
        turning_point=c.turning_point,
        nondimensional=c,
    )
