""":class:`Cylinder`: radius, modulus, adhesion, Dundurs' beta, cross-section; normal contact."""

from __future__ import annotations

import math
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
)
from ..errors import NoEquilibriumError
from ..geometry import ROUND, CrossSection
from ..laws._values import Dugdale, Law, LennardJones
from ..units import Scales, to_si
from . import _facet, _lj_problems, _problems, _sliding
from ._body import Body
from ._checks import (
    _S_LJ,
    _ZERO_WIDTH,
    _as_given,
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
    pass


@dataclass(frozen=True)
class Cylinder(Body):
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

    cross_section: CrossSection = ROUND

    def _settle_shape(self) -> None:
        if not isinstance(self.cross_section, CrossSection):
            raise ValueError(
                "cross_section must be a cross-section (linecontact.geometry.Round or "
                f"Polygon), got {self.cross_section!r}"
            )
        self.cross_section.checked(self.radius)

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
            cross_section=self.cross_section,
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
        with _small_strain_in_si():
            c = self._dugdale_curve(
                _normal.load_curve, "max_half_width", max_half_width, num, num_noncontact
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
