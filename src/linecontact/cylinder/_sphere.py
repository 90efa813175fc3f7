r""":class:`Sphere`: an AFM tip or a colloidal probe on a substrate, in SI units.

The same body as a wire's (:class:`~linecontact.cylinder._body.Body`: radius, composite
modulus, adhesion law, built from a modulus, the materials or presets), with the sphere's
problems: its contact, pull-off (load or displacement control) and load curve under the
Dugdale law (:mod:`linecontact.sphere`, the Maugis--Dugdale sphere), and its pull-off and
load curve under the Lennard-Jones law (:mod:`linecontact.sphere.lennard_jones`). Forces are
in N (the scale ``E h R``), not per unit length. A problem that is a wire's only (sliding,
rolling, the push, the load histories) is refused, naming the pair.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, ClassVar, Literal

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import domain as _domain
from .. import sphere as _sphere
from ..closed_forms.sphere import sphere_maugis_parameter, sphere_tabor_parameter
from ..errors import NoEquilibriumError, ParameterError
from ..laws._values import Dugdale, Law, LennardJones
from ..results import Result
from ..units import Scales, to_si
from ._body import Body
from ._checks import _S_LJ

__all__ = ["Sphere", "SphereContactSI", "SphereLJCurveSI", "SphereLoadCurveSI", "SpherePullOffSI"]


@dataclass(frozen=True)
class SphereContactSI(Result):
    """A sphere's contact state in SI units, with its nondimensional result.

    Attributes
    ----------
    contact_radius, adhesive_zone_radius : ndarray or float
        ``a`` and ``c`` [m].
    load : ndarray or float
        ``F`` [N], compressive positive.
    approach : ndarray or float
        ``delta`` [m], the far points' displacement towards each other.
    stable, stable_displacement : ndarray or bool
        Stable under load and under displacement control.
    nondimensional : SphereContact
    """

    contact_radius: NDArray | float
    adhesive_zone_radius: NDArray | float
    load: NDArray | float
    approach: NDArray | float
    stable: NDArray | bool
    stable_displacement: NDArray | bool
    nondimensional: _sphere.SphereContact = field(repr=False)


@dataclass(frozen=True)
class SpherePullOffSI(Result):
    """A sphere's pull-off in SI units.

    Attributes
    ----------
    pull_off_force : float
        [N], negative (0 without adhesion).
    contact_radius_at_pull_off, adhesive_zone_radius_at_pull_off : float
        [m] (``a = 0``: it lets go at zero radius). Under the Lennard-Jones law: where the
        gap crosses ``z0`` and ``1.5 z0``.
    approach_at_pull_off : float
        [m].
    mechanism : str
        As in :class:`~linecontact.sphere.SpherePullOff`; ``"lennard-jones"`` under that law.
    control : str
        ``"load"`` or ``"displacement"``.
    nondimensional : SpherePullOff or SphereLJPullOff
    """

    pull_off_force: NDArray | float
    contact_radius_at_pull_off: NDArray | float
    adhesive_zone_radius_at_pull_off: NDArray | float
    approach_at_pull_off: NDArray | float
    mechanism: NDArray | str
    control: str
    nondimensional: Any = field(repr=False)  # SpherePullOff, or SphereLJPullOff


@dataclass(frozen=True)
class SphereLoadCurveSI(Result):
    """A sphere's load curve in SI units (both branches, the pull-offs marked).

    Attributes
    ----------
    branch : ndarray of str
    contact_radius, adhesive_zone_radius, load, approach : ndarray
        As in :class:`SphereContactSI`.
    stable, stable_displacement, pull_off_load, pull_off_displacement : ndarray of bool
    nondimensional : SphereLoadCurve
    """

    branch: NDArray
    contact_radius: NDArray
    adhesive_zone_radius: NDArray
    load: NDArray
    approach: NDArray
    stable: NDArray
    stable_displacement: NDArray
    pull_off_load: NDArray
    pull_off_displacement: NDArray
    nondimensional: _sphere.SphereLoadCurve = field(repr=False)


@dataclass(frozen=True)
class SphereLJCurveSI(Result):
    """The Lennard-Jones sphere's load curve in SI units, through its S-shape.

    Attributes
    ----------
    load : ndarray
        [N], compressive positive.
    load_error : ndarray
        Each load's estimated error [N] (``error_estimate`` of :class:`SphereLJCurve`).
    approach : ndarray
        The approach of the far points [m].
    central_gap : ndarray
        The gap at the centre [m].
    contact_radius : ndarray
        Where the gap crosses ``z0`` [m] (0: none).
    stable, stable_displacement : ndarray of bool
        Stable under load control, under displacement control.
    pull_off_force, jump_in_force : float
        The load-control pull-off and jump-in [N] (the jump-in NaN where the curve is not
        S-shaped).
    nondimensional : SphereLJCurve
    """

    whole: ClassVar[tuple[str, ...]] = ("pull_off_force", "jump_in_force")

    load: NDArray
    load_error: NDArray
    approach: NDArray
    central_gap: NDArray
    contact_radius: NDArray
    stable: NDArray
    stable_displacement: NDArray
    pull_off_force: float
    jump_in_force: float
    nondimensional: Any = field(repr=False)


@dataclass(frozen=True)
class Sphere(Body):
    r"""A sphere of radius ``R`` on a substrate, with its adhesion law: a body.

    Build it as a wire is built: :meth:`from_modulus`, :meth:`from_materials` or
    :meth:`from_presets`, the adhesion as ``(sigma0, h)``, ``(w, z0)`` or a law value. Its
    problems are :meth:`contact`, :meth:`pull_off` and :meth:`load_curve` under the Dugdale
    law, :meth:`pull_off` and :meth:`load_curve` under the Lennard-Jones law; forces in N.

    Examples
    --------
    >>> tip = Sphere.from_modulus(20e-9, 50e9, work_of_adhesion=0.1, equilibrium_spacing=0.3e-9)
    >>> p = tip.pull_off()
    >>> print(f"{p.pull_off_force * 1e9:.3f} nN, {p.mechanism}, lambda {tip.maugis_parameter:.3f}")
    -11.965 nN, contact, lambda 0.166
    """

    #: The problems of a sphere (and the laws they are written for).
    WRITTEN: ClassVar[dict[str, tuple[type, ...]]] = {
        "contact": (Dugdale,),
        "pull_off": (Dugdale, LennardJones),
        "load_curve": (Dugdale, LennardJones),
    }

    def __getattr__(self, name: str) -> Any:
        from ._cylinder import Cylinder

        if name in Cylinder.WRITTEN:
            raise AttributeError(
                f"{name} is not written for a sphere: its problems are "
                f"{', '.join(self.WRITTEN)} (the Lennard-Jones law's: pull_off, load_curve); "
                f"{name} is a wire's "
                "(Cylinder)"
            )
        raise AttributeError(f"'Sphere' object has no attribute {name!r}")

    def _written(self, problem: str) -> None:
        if not isinstance(self.adhesion, self.WRITTEN[problem]):
            under = [p for p, laws in self.WRITTEN.items() if isinstance(self.adhesion, laws)]
            raise ValueError(
                f"{problem} is not written for a sphere under the {self.adhesion.name} law "
                f"(adhesion={self.adhesion!r}): under it a sphere's problems are "
                f"{', '.join(under)}; {problem} is the Dugdale law's"
            )

    # groups ---
    @property
    def maugis_parameter(self) -> float:
        r"""Maugis' :math:`\lambda = 2\sigma_0 (R/(\pi w K^2))^{1/3}` (0: Hertz; large: JKR)."""
        return float(sphere_maugis_parameter(self.R_over_h, self.sigma0_over_E))

    @property
    def tabor_parameter(self) -> float:
        r"""Tabor's :math:`\mu = (R w^2/(E^2 z_0^3))^{1/3}`, ``z0 = 16h/(9\sqrt3)`` the law's."""
        return float(sphere_tabor_parameter(self.R_over_h, self.sigma0_over_E))

    def _scales(self) -> Scales:
        return Scales.of(self)

    # problems ---
    def contact(
        self,
        *,
        load: ArrayLike | None = None,
        contact_radius: ArrayLike | None = None,
        on_failure: str = "raise",
    ) -> SphereContactSI:
        """The contact under a ``load`` [N] (the stable state) or at a ``contact_radius`` [m].

        Give exactly one. ``on_failure="report"``: a load below the pull-off gives NaN.
        """
        self._written("contact")
        if (load is None) == (contact_radius is None):
            raise ValueError("give exactly one of load [N] or contact_radius [m]")
        rho, s = self.R_over_h, self.sigma0_over_E
        if load is not None:
            _domain.check_si("load", load, self.scale("EhR"), "F_over_EhR", "N")
            F = np.divide(np.asarray(load, float), self.scale("EhR"))
            try:
                r = _sphere.sphere_contact_for_load(F, rho, s, on_failure=on_failure)
            except ParameterError as e:  # wider than the domain's radii: said in N and m
                if e.parameter != "F_over_EhR":
                    raise
                raise ParameterError(
                    "load",
                    f"load = {float(np.max(load))!r} N needs a contact radius beyond "
                    f"{10 * self.radius:.6g} m (10 radii, the domain of the solvers)",
                ) from None
            except NoEquilibriumError:  # said in N
                po = self.pull_off().pull_off_force
                low = float(np.asarray(load, float)[np.asarray(load, float) < po].flat[0])
                raise NoEquilibriumError(
                    f"load = {low!r} N is below the pull-off force {po!r} N of this sphere: "
                    "no contact carries it (it has come off)"
                ) from None
        else:
            radii = np.asarray(contact_radius, float)
            _domain.check_si("contact_radius", radii, self.radius, "a_over_R", "m")
            a_over_R = radii / self.radius
            r = _sphere.sphere_contact(a_over_R, rho, s)
        return SphereContactSI(
            **to_si(r, self._scales()),
            stable=r.stable,
            stable_displacement=r.stable_displacement,
            nondimensional=r,
        )

    def under(self, law: type[Law]) -> Sphere:
        """The same sphere with the same adhesion (the same ``w``, the same peak) under ``law``."""
        if not (isinstance(law, type) and issubclass(law, Law)):
            raise ValueError(f"law must be a law's class (Dugdale or LennardJones), got {law!r}")
        return self._made(
            self.radius, self.modulus, self.adhesion.same_adhesion(law), self.dundurs_beta
        )

    def pull_off(self, control: Literal["load", "displacement"] = "load") -> SpherePullOffSI:
        """The pull-off [N] under load or displacement control.

        Under the Lennard-Jones law, the Lennard-Jones sphere
        (:func:`linecontact.sphere.lennard_jones.sphere_lj_pull_off`) under load control:
        self-consistent up to Tabor's parameter ``MU_SELF_CONSISTENT``, beyond it the JKR limit
        with its fitted correction (``nondimensional.method``).
        """
        self._written("pull_off")
        if isinstance(self.adhesion, LennardJones):
            return self._pull_off_lj(control)
        p = _sphere.sphere_pull_off(self.R_over_h, self.sigma0_over_E, control=control)
        return SpherePullOffSI(
            **to_si(p, self._scales()),
            mechanism=p.mechanism,
            control=control,
            nondimensional=p,
        )

    def _pull_off_lj(self, control: str) -> SpherePullOffSI:
        from ..sphere import lennard_jones as _lj

        if control != "load":
            raise ValueError(
                f"the pull-off under {control} control is not written for a sphere under the "
                "lennard-jones law: under load control it is"
            )
        r = _lj.sphere_lj_pull_off(self.tabor_parameter)
        z0 = _S_LJ * self.adhesion_range
        root = (self.radius * z0) ** 0.5
        return SpherePullOffSI(
            pull_off_force=r.F_pulloff_over_piwR * np.pi * self.work_of_adhesion * self.radius,
            contact_radius_at_pull_off=r.contact_radius * root,
            adhesive_zone_radius_at_pull_off=r.edge_radius * root,
            approach_at_pull_off=r.approach_over_z0 * z0,
            mechanism="lennard-jones",
            control="load",
            nondimensional=r,
        )

    def load_curve(
        self,
        *,
        max_radius: float | None = None,
        num: int = 200,
        num_noncontact: int = 40,
        max_load: float | None = None,
    ) -> SphereLoadCurveSI | SphereLJCurveSI:
        """The load curve, both branches, the pull-offs marked.

        Under the Dugdale law up to the contact radius ``max_radius`` [m] (default: where the
        load is ten times the pull-off in compression), ``num`` points on the contact branch
        and ``num_noncontact`` on the other. Under the Lennard-Jones law the self-consistent
        curve (:func:`linecontact.sphere.lennard_jones.sphere_lj_curve`, Tabor's parameter up
        to ``MU_SELF_CONSISTENT``) from a central gap of ``6 z0`` to the compressive load
        ``max_load`` [N] (default: ``pi w R``, at most ten times that), its points where its
        states fall.
        """
        self._written("load_curve")
        if isinstance(self.adhesion, LennardJones):
            return self._load_curve_lj(max_radius, num, num_noncontact, max_load)
        if max_load is not None:
            raise ValueError(
                "max_load is the Lennard-Jones curve's end: under the Dugdale law the curve "
                "ends at max_radius [m]"
            )
        c = self._dugdale_curve(
            _sphere.sphere_load_curve, "max_radius", max_radius, num, num_noncontact
        )
        return SphereLoadCurveSI(
            branch=c.branch,
            **to_si(c, self._scales()),
            stable=c.stable,
            stable_displacement=c.stable_displacement,
            pull_off_load=c.pull_off_load,
            pull_off_displacement=c.pull_off_displacement,
            nondimensional=c,
        )

    def _load_curve_lj(
        self, max_radius: float | None, num: int, num_noncontact: int, max_load: float | None
    ) -> SphereLJCurveSI:
        from ..sphere import lennard_jones as _lj

        if max_radius is not None or (num, num_noncontact) != (200, 40):
            raise ValueError(
                "max_radius, num and num_noncontact are the Dugdale curve's: the Lennard-Jones "
                "sphere's curve ends at max_load [N], its points where its states fall"
            )
        mu = self.tabor_parameter
        if mu > _lj.MU_SELF_CONSISTENT:
            q = _lj.MU_SELF_CONSISTENT / mu  # Tabor's parameter goes as R^(1/3)
            raise ValueError(
                f"Tabor's parameter (R w^2/(E^2 z0^3))^(1/3) of this sphere is {mu:.4g} "
                f"(radius={self.radius!r} m, modulus={self.modulus!r} Pa, "
                f"adhesion={self.adhesion!r}), over {_lj.MU_SELF_CONSISTENT:g}, the largest the "
                "Lennard-Jones sphere's curve is solved for (its pull-off is given at every "
                f"value): use the Dugdale law, or a radius below {self.radius * q**3:.3g} m"
            )
        unit = np.pi * self.work_of_adhesion * self.radius  # the force unit pi w R [N]
        F_max = 1.0
        if max_load is not None:
            if np.ndim(max_load) != 0:
                raise ParameterError(
                    "max_load", f"max_load must be one number [N], got {max_load!r}"
                )
            _domain.check_si("max_load", max_load, unit, "F_max_over_piwR", "N")
            F_max = float(max_load) / unit
        c = _lj.sphere_lj_curve(mu, F_max=F_max)
        z0 = _S_LJ * self.adhesion_range
        return SphereLJCurveSI(
            load=c.F_over_piwR * unit,
            load_error=c.error_estimate * unit,
            approach=c.approach_over_z0 * z0,
            central_gap=c.central_gap_over_z0 * z0,
            contact_radius=c.contact_radius * (self.radius * z0) ** 0.5,
            stable=c.stable,
            stable_displacement=c.stable_displacement,
            pull_off_force=c.F_pulloff_over_piwR * unit,
            jump_in_force=c.F_jump_in_over_piwR * unit,
            nondimensional=c,
        )
