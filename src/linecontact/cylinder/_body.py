"""The body on its substrate: its radius, modulus, adhesion law and Dundurs' beta (SI).

:class:`Body` holds what every body shares, and builds it: from a composite modulus, from
the two materials' moduli and Poisson ratios, or from presets, with the adhesion as a law
value or by its parameters; the groups ``R/h`` and ``sigma0/E`` and their SI scales. A body
is a geometry with its problems: :class:`~linecontact.Cylinder` (a wire, force per unit
length) and :class:`~linecontact.Sphere` (an AFM tip or a colloidal probe, force in N).
"""

from __future__ import annotations

import warnings
from collections.abc import Callable
from dataclasses import dataclass, fields
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import ArrayLike

from .. import domain as _domain
from .._validation import scalar
from ..errors import CouplingWarning, UnitsWarning
from ..laws._values import Dugdale, Law
from ..materials import BETA_WARN, _moduli, composite_modulus, dundurs_beta
from ._checks import PLAUSIBLE, _check_cylinder_si

if TYPE_CHECKING:  # imported where used
    from typing_extensions import Self

    from ..presets import Material

__all__ = ["Body"]


@dataclass(frozen=True)
class Body:
    r"""A body of radius ``R`` on a substrate, with its adhesion law (SI units).

    Attributes
    ----------
    radius : float
        ``R`` [m] (the equivalent radius of two bodies).
    modulus : float
        Composite modulus ``E`` [Pa], :math:`1/E = (1-\nu_1^2)/E_1 + (1-\nu_2^2)/E_2`.
    adhesion : Law
        The adhesion law and its SI parameters.
    dundurs_beta : float
        Dundurs' :math:`\beta = -B/A` (0 when only the composite modulus was given).
    cohesive_stress, adhesion_range : float
        ``sigma0`` [Pa] (0: no adhesion) and ``h`` [m] of the law's Dugdale step.
    """

    radius: float
    modulus: float
    adhesion: Law
    dundurs_beta: float = 0.0

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
    def _made(cls, radius: float, modulus: float, adhesion: Law, beta: float, **shape: Any) -> Self:
        """The body of a factory that has checked its SI inputs under its caller's names.

        The fields are settled as the constructor settles them, without the constructor's
        check under the fields' names (the factory said it as ``work_of_adhesion``,
        ``equilibrium_spacing``, ...): an argument of the build, not a state around it.
        ``shape``: the fields of the geometry (a wire's ``cross_section``), else defaults.
        """
        self = object.__new__(cls)
        values = {"radius": radius, "modulus": modulus, "adhesion": adhesion, "dundurs_beta": beta}
        for f in fields(cls):
            value = values.get(f.name, shape.get(f.name, f.default))
            object.__setattr__(self, f.name, value)
        self._settle()
        return self

    def _settle_shape(self) -> None:
        """Check the geometry's own fields (a wire's cross-section): none here."""

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
        self._settle_shape()
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
    ) -> Self:
        """The body of a factory, its SI inputs checked under the names the caller gave."""
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
    ) -> Self:
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
    ) -> Self:
        """From the moduli [Pa] and Poisson ratios of the body (1) and the substrate (2).

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
    ) -> Self:
        """From material presets (:mod:`linecontact.presets`) of the body and the substrate.

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
        Cylinder or Sphere
            ``from_materials(radius, E1, nu1, E2, nu2, ...)`` with the presets' ``E`` and
            ``nu``.

        Examples
        --------
        >>> from linecontact import Cylinder
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

    # groups ---
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

    # the SI form of the groups ---
    def scale(self, name: str) -> float:
        """The SI unit of a group: ``"R"``, ``"h"`` [m], ``"E"`` [Pa], ``"Eh"`` [N/m], ``"EhR"``.

        ``"EhR"`` [N] is the unit of a wire's moment per unit length and of a sphere's force.

        >>> from linecontact import Cylinder
        >>> cyl = Cylinder.from_modulus(50e-9, 100e9, cohesive_stress=1e9, adhesion_range=0.5e-9)
        >>> cyl.scale("Eh")
        50.0
        """
        R, E, h = self.radius, self.modulus, self.adhesion_range
        units = {"R": R, "h": h, "E": E, "Eh": E * h, "EhR": E * h * R}
        if name not in units:
            raise ValueError(f"scale must be one of {', '.join(units)}, got {name!r}")
        return units[name]

    # the problems every body shares ---
    def _dugdale_curve(
        self,
        curve: Callable[..., Any],
        max_width_name: str,
        max_width: float | None,
        num: int,
        num_noncontact: int,
    ) -> Any:
        """The nondimensional Dugdale load curve ``curve`` of this body, up to ``max_width`` [m].

        ``curve`` is the geometry's function of ``(R/h, sigma0/E)`` (a wire's or a
        sphere's); ``max_width`` (a half-width or a radius, None: the function's default) is
        checked under the caller's name ``max_width_name``, then given over ``R``.
        """
        a_max = None
        if max_width is not None:
            _domain.check_si(max_width_name, max_width, self.radius, "a_max_over_R", "m")
            a_max = self.over(max_width, "R")
        return curve(
            self.R_over_h,
            self.sigma0_over_E,
            a_max_over_R=a_max,
            num=num,
            num_noncontact=num_noncontact,
        )

    def in_si(self, value: ArrayLike, scale: str) -> Any:
        """``value`` given over the group ``scale`` (:meth:`scale`) in SI units."""
        return np.multiply(value, self.scale(scale))

    def over(self, value: ArrayLike, scale: str) -> Any:
        """``value`` in SI units over the group ``scale`` (:meth:`scale`); :meth:`in_si` undone."""
        return np.divide(value, self.scale(scale))
