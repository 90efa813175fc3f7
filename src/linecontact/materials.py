r"""Dimensional (SI) layer: materials, adhesion and a cylinder on a substrate.

Everything here converts SI inputs to the paper's groups, calls the nondimensional solvers of
:mod:`linecontact.normal` and converts back. Units: lengths [m], stresses and moduli [Pa],
forces per unit length of cylinder [N/m], work of adhesion [J/m^2].

Materials (Eq. 7 of the paper): body 1 is the cylinder, body 2 the substrate,

.. math::

    \frac{1}{E} = \frac{1-\nu_1^2}{E_1} + \frac{1-\nu_2^2}{E_2},\quad
    A = \frac{4(1-\nu_1)}{G_1} + \frac{4(1-\nu_2)}{G_2} = \frac{8}{E},\quad
    B = \frac{2-4\nu_1}{G_1} - \frac{2-4\nu_2}{G_2}.

The solvers assume the uncoupled case ``B = 0``; :func:`dundurs_beta` gives Dundurs' second
parameter ``beta = -B/A`` and a :class:`~linecontact.errors.CouplingWarning` is issued when
``|beta| > BETA_WARN``.

Adhesion is given either as the Dugdale stress and range ``(sigma0, h)`` or as the work of
adhesion and equilibrium spacing ``(w, z0)`` of a Lennard-Jones surface potential (Eq. 1).
The Maugis convention takes ``sigma0`` as the theoretical strength of that potential,
:math:`\sigma_0 = 16 w/(9\sqrt{3} z_0)`, and ``h = w/sigma0``
:math:`= 9\sqrt{3} z_0/16 \approx 0.974 z_0` (the paper's "0.97 z0").

References
----------
D. Maugis, "Adhesion of spheres: the JKR-DMT transition using a Dugdale model",
J. Colloid Interface Sci. 150 (1992) 243--269. doi:10.1016/0021-9797(92)90285-T
J. Dundurs, discussion, J. Appl. Mech. 36 (1969) 650--652. doi:10.1115/1.3564739
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import ArrayLike, NDArray

from . import normal as _normal
from . import reference as _ref
from ._validation import broadcast, check_array, positive, scalar
from .errors import CouplingWarning, NoEquilibriumError

__all__ = [
    "BETA_WARN",
    "Cylinder",
    "CylinderContact",
    "CylinderPullOff",
    "adhesion_from_work",
    "composite_modulus",
    "compliance_constants",
    "dundurs_beta",
]

#: |beta| = |B/A| above which a CouplingWarning is issued.
BETA_WARN = 0.05


def _moduli(E1, nu1, E2, nu2):
    E1 = check_array("E1", E1, allow_inf=True)
    E2 = check_array("E2", E2, allow_inf=True)
    nu1 = check_array("nu1", nu1, low=-1.0, high=0.5, high_inclusive=True)
    nu2 = check_array("nu2", nu2, low=-1.0, high=0.5, high_inclusive=True)
    E1, nu1, E2, nu2 = broadcast(E1=E1, nu1=nu1, E2=E2, nu2=nu2)
    if np.any(np.isinf(E1) & np.isinf(E2)):
        raise ValueError("E1 and E2 cannot both be infinite (two rigid bodies)")
    return E1, nu1, E2, nu2


def composite_modulus(E1: ArrayLike, nu1: ArrayLike, E2: ArrayLike, nu2: ArrayLike):
    """Plane-strain composite modulus ``E`` [Pa], Eq. (7); ``E2 = inf`` for a rigid substrate.

    Examples
    --------
    >>> round(composite_modulus(70e9, 0.17, 70e9, 0.17) / 1e9, 6)  # E1/(2(1 - nu^2))
    36.041602
    """
    E1, nu1, E2, nu2 = _moduli(E1, nu1, E2, nu2)
    val = 1.0 / ((1 - nu1 ** 2) / E1 + (1 - nu2 ** 2) / E2)
    return val.item() if val.ndim == 0 else val


def compliance_constants(E1: ArrayLike, nu1: ArrayLike, E2: ArrayLike, nu2: ArrayLike):
    """The constants ``A`` and ``B`` of Eq. (7) [1/Pa]."""
    E1, nu1, E2, nu2 = _moduli(E1, nu1, E2, nu2)
    G1 = E1 / (2 * (1 + nu1))
    G2 = E2 / (2 * (1 + nu2))
    A = 4 * (1 - nu1) / G1 + 4 * (1 - nu2) / G2
    B = (2 - 4 * nu1) / G1 - (2 - 4 * nu2) / G2
    return (A.item(), B.item()) if A.ndim == 0 else (A, B)


def dundurs_beta(E1: ArrayLike, nu1: ArrayLike, E2: ArrayLike, nu2: ArrayLike):
    r"""Dundurs' second parameter :math:`\beta = -B/A` (Eq. 7; 0 for identical materials).

    With the cylinder as body 1: :math:`\beta = [G_1(1-2\nu_2) - G_2(1-2\nu_1)] /
    [2(G_1(1-\nu_2) + G_2(1-\nu_1))]`, the standard sign convention.
    """
    A, B = compliance_constants(E1, nu1, E2, nu2)
    return -B / A


def adhesion_from_work(work_of_adhesion: ArrayLike, equilibrium_spacing: ArrayLike):
    r"""Dugdale stress and range ``(sigma0 [Pa], h [m])`` from ``(w [J/m^2], z0 [m])``.

    Maugis convention: :math:`\sigma_0 = 16w/(9\sqrt3 z_0)` (the strength of the
    Lennard-Jones law, Eq. 1) and :math:`h = w/\sigma_0`.

    Examples
    --------
    >>> s0, h = adhesion_from_work(0.1, 0.3e-9)
    >>> round(h / 0.3e-9, 4)
    0.9743
    """
    w = positive("work_of_adhesion", work_of_adhesion)
    z0 = positive("equilibrium_spacing", equilibrium_spacing)
    w, z0 = broadcast(work_of_adhesion=w, equilibrium_spacing=z0)
    with np.errstate(over="ignore", under="ignore"):
        s0 = 16 * w / (9 * np.sqrt(3) * z0)
    bad = ~(np.isfinite(s0) & (s0 > 0))
    if np.any(bad):
        i = int(np.flatnonzero(bad.reshape(-1))[0])
        raise ValueError(f"work_of_adhesion={float(w.reshape(-1)[i])!r} and equilibrium_spacing="
                         f"{float(z0.reshape(-1)[i])!r} give sigma0 = 16 w/(9 sqrt(3) z0) = "
                         f"{float(s0.reshape(-1)[i])!r} [Pa], not a finite positive number")
    h = w / s0
    return (s0.item(), h.item()) if s0.ndim == 0 else (s0, h)


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
    nondimensional : NormalContact
        The underlying result with diagnostics.
    """

    contact_half_width: NDArray | float
    adhesive_zone_half_width: NDArray | float
    load: NDArray | float
    stable: NDArray | bool
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
        for name, limits in (("radius", {}), ("modulus", {}),
                             ("cohesive_stress", {"low_inclusive": True}),
                             ("adhesion_range", {}),
                             ("dundurs_beta", {"low": -np.inf, "low_inclusive": True})):
            object.__setattr__(self, name, scalar(name, getattr(self, name), **limits))
        # the units of the groups must be representable: R/h, sigma0/E and E h
        for what, v in (("radius/adhesion_range (R/h)", self.radius / self.adhesion_range),
                        ("cohesive_stress/modulus (sigma0/E)",
                         self.cohesive_stress / self.modulus),
                        ("modulus*adhesion_range (E h, the unit of force per length)",
                         self.modulus * self.adhesion_range)):
            if not (np.isfinite(v) and (v > 0 or (v == 0 and what.startswith("cohesive")))):
                raise ValueError(f"{what} = {v!r} is not a finite positive number: radius="
                                 f"{self.radius!r}, modulus={self.modulus!r}, cohesive_stress="
                                 f"{self.cohesive_stress!r}, adhesion_range="
                                 f"{self.adhesion_range!r} are too far apart in scale")

    @classmethod
    def from_modulus(cls, radius: float, modulus: float, *, cohesive_stress: float | None = None,
                     adhesion_range: float | None = None, work_of_adhesion: float | None = None,
                     equilibrium_spacing: float | None = None) -> Cylinder:
        """From the composite modulus ``E`` [Pa]; adhesion as ``(sigma0, h)`` or ``(w, z0)``."""
        R = scalar("radius", radius)
        E = scalar("modulus", modulus)
        s0, h = _adhesion(cohesive_stress, adhesion_range, work_of_adhesion, equilibrium_spacing)
        return cls(R, E, s0, h, 0.0)

    @classmethod
    def from_materials(cls, radius: float, E1: float, nu1: float, E2: float, nu2: float, *,
                       cohesive_stress: float | None = None, adhesion_range: float | None = None,
                       work_of_adhesion: float | None = None,
                       equilibrium_spacing: float | None = None) -> Cylinder:
        """From the moduli [Pa] and Poisson ratios of cylinder (1) and substrate (2)."""
        R = scalar("radius", radius)
        for name, v in zip(("E1", "nu1", "E2", "nu2"), _moduli(E1, nu1, E2, nu2), strict=True):
            if v.ndim != 0:
                raise ValueError(f"{name} must be a single number, got an array of shape "
                                 f"{v.shape}")
        E = float(composite_modulus(E1, nu1, E2, nu2))
        beta = float(dundurs_beta(E1, nu1, E2, nu2))
        if abs(beta) > BETA_WARN:
            warnings.warn(f"Dundurs beta = -B/A = {beta:.3g} is not small (|beta| > {BETA_WARN}): "
                          "normal and tangential tractions are coupled, but linecontact "
                          "solves the uncoupled case B = 0", CouplingWarning, stacklevel=2)
        s0, h = _adhesion(cohesive_stress, adhesion_range, work_of_adhesion, equilibrium_spacing)
        return cls(R, E, s0, h, beta)

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

    # problems ----------------------------------------------------------------------------
    def _wrap(self, r: _normal.NormalContact) -> CylinderContact:
        R, Eh = self.radius, self.modulus * self.adhesion_range

        def si(v, unit):
            v = np.multiply(v, unit)
            return v.item() if np.ndim(v) == 0 else v

        return CylinderContact(si(r.a_over_R, R), si(r.c_over_R, R), si(r.F_over_Eh, Eh),
                               r.stable, r)

    def contact(self, *, contact_half_width: ArrayLike | None = None,
                load: ArrayLike | None = None, method: str = "closed-form",
                branch: str = "stable") -> CylinderContact:
        """The contact at given half-widths ``a`` [m] or loads ``F`` [N/m] (exactly one).

        For a load, ``branch`` selects the stable (default) or the unstable contact state;
        a load below the pull-off force raises
        :class:`~linecontact.errors.NoEquilibriumError`.
        """
        if (contact_half_width is None) == (load is None):
            raise ValueError("give exactly one of contact_half_width or load")
        if method not in ("closed-form", "collocation"):
            raise ValueError(f"method must be 'closed-form' or 'collocation', got {method!r}")
        if branch not in ("stable", "unstable"):
            raise ValueError(f"branch must be 'stable' or 'unstable', got {branch!r}")
        if load is not None and method != "closed-form":
            raise ValueError("the contact for a given load is found by the closed form: "
                             "method='collocation' applies to contact_half_width only")
        if contact_half_width is not None and branch != "stable":
            raise ValueError("branch applies to a given load only: a contact half-width "
                             "fixes the state")
        if contact_half_width is not None:
            a = positive("contact_half_width", contact_half_width)
            r = _normal.normal_contact(a / self.radius, self.R_over_h, self.sigma0_over_E,
                                       method=method)
        else:
            F = check_array("load", load, low=-np.inf, low_inclusive=True)
            Eh = self.modulus * self.adhesion_range
            if branch == "stable":
                # said in the units given ([N/m]), not only as F_over_Eh
                F_min = _normal.pull_off(self.R_over_h, self.sigma0_over_E).F_minimum_over_Eh * Eh
                if np.any(F < F_min):
                    raise NoEquilibriumError(
                        f"no contact carries load={float(F[F < F_min].flat[0])!r} N/m: it is "
                        f"below the pull-off force, the minimum load on the contact branch "
                        f"{F_min!r} N/m; the cylinder has pulled off")
            r = _normal.contact_for_load(F / Eh, self.R_over_h, self.sigma0_over_E,
                                         branch=branch)
        return self._wrap(r)

    def pull_off(self) -> CylinderPullOff:
        """Pull-off force under load control [N/m]."""
        p = _normal.pull_off(self.R_over_h, self.sigma0_over_E)
        Eh = self.modulus * self.adhesion_range
        return CylinderPullOff(p.F_pulloff_over_Eh * Eh, p.a_over_R_at_pulloff * self.radius,
                               p.mechanism, p.F_zero_width_over_Eh * Eh, p)


def _adhesion(s0, h, w, z0) -> tuple[float, float]:
    by_stress = s0 is not None or h is not None
    by_work = w is not None or z0 is not None
    if by_stress and by_work:
        raise ValueError("give adhesion either as (cohesive_stress, adhesion_range) or as "
                         "(work_of_adhesion, equilibrium_spacing), not both")
    if by_work:
        if w is None or z0 is None:
            raise ValueError("give both work_of_adhesion and equilibrium_spacing")
        s, hh = adhesion_from_work(scalar("work_of_adhesion", w),
                                   scalar("equilibrium_spacing", z0))
        return float(s), float(hh)
    if h is None:
        raise ValueError("give adhesion_range h (> 0): it sets the length scale R/h even "
                         "without adhesion")
    hh = scalar("adhesion_range", h)
    s = 0.0 if s0 is None else scalar("cohesive_stress", s0, low_inclusive=True)
    return s, hh
