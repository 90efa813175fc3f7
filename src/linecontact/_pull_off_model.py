r"""The pull-off force of a cylinder in SI units: the forward model and ``w`` from one pull-off.

Split from :mod:`linecontact.fits`, which re-exports every public name:
:func:`pull_off_force` (Maugis--Dugdale, the adhesion given as ``(w, z0)``), its JKR and rigid
(DMT) limits :func:`jkr_pull_off_force`, :func:`dmt_pull_off_force`, the work of adhesion they
alone would give (:func:`simple_model_work_of_adhesion`) and :func:`work_of_adhesion_from_pull_off`
(the model solved for ``w`` at a known radius, modulus and range).

Units: SI throughout (m, Pa, N/m, J/m^2); pull-off forces are negative (tensile).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any, Literal

import numpy as np
from numpy.typing import ArrayLike, NDArray

from . import closed_forms as _cf
from . import normal as _normal
from ._validation import (
    FailurePolicy,
    broadcast,
    check_array,
    failure_policy,
    first_point,
    point_text,
)
from .cylinder import _check_cylinder_si, _plausible
from .errors import ParameterError
from .facet import facet_pull_off
from .geometry import CrossSection
from .materials import MAUGIS_STRENGTH

__all__ = [
    "dmt_pull_off_force",
    "jkr_pull_off_force",
    "pull_off_force",
    "simple_model_work_of_adhesion",
    "work_of_adhesion_from_pull_off",
]

#: sigma0 = S w / z0 (Maugis: the strength of the Lennard-Jones law), h = z0 / S
S_LJ = MAUGIS_STRENGTH  # an alias of materials.MAUGIS_STRENGTH
#: the range of sigma0/E searched by the inversions (the solvers' domain is wider)
_S_MIN, _S_MAX = 1e-14, 0.999e6  # inside the solvers' domain of sigma0/E (to 1e6)
_BISECTIONS = 200


def _groups(radius, modulus, w, z0):
    """R/h and sigma0/E of a cylinder with adhesion (w, z0)."""
    h = z0 / S_LJ
    return radius / h, S_LJ * w / (z0 * modulus), h


def _shape(cross_section: CrossSection | None, R: NDArray) -> dict[str, Any] | None:
    """A polygon's groups at the radii ``R`` (None: the round wire), checked against them."""
    if cross_section is None:
        return None
    if not isinstance(cross_section, CrossSection):  # (a word such as "hexagon" too)
        raise ParameterError(
            "cross_section",
            f"cross_section must be linecontact.Round() or Polygon(...), got {cross_section!r}",
        )
    if cross_section.kind == "round":
        return None
    cross_section.checked(float(np.min(R)))  # a corner radius above a radius, named
    return cross_section.groups(R)  # its groups at each radius


def _pull_off_over_Eh(rho, s, shape: dict[str, Any] | None) -> NDArray:
    """The pull-off over E h of the round wire, or of a polygon on its facet (its groups)."""
    if shape is None:
        return np.asarray(_normal.pull_off(rho, s).F_pulloff_over_Eh)
    return np.asarray(facet_pull_off(rho, s, **shape).F_pulloff_over_Eh)


def pull_off_force(
    radius: ArrayLike,
    modulus: ArrayLike,
    work_of_adhesion: ArrayLike,
    equilibrium_spacing: ArrayLike,
    *,
    cross_section: CrossSection | None = None,
) -> NDArray:
    r"""Maugis--Dugdale pull-off force per unit length [N/m] (negative), vectorised.

    The forward model of the pull-off inversions: :func:`linecontact.pull_off` at
    :math:`R/h`, :math:`\sigma_0/E` of the adhesion ``(w, z0)``, times :math:`E h`; with
    ``cross_section=Polygon(sides, corner_radius)`` that of a faceted wire on its facet
    (:func:`linecontact.facet_pull_off`, ``radius`` its circumradius).

    Examples
    --------
    >>> round(float(pull_off_force(50e-9, 50e9, 0.1, 0.3e-9)), 6)
    -3.498523
    """
    R, E, w, z0 = broadcast(
        radius=check_array("radius", radius),
        modulus=check_array("modulus", modulus),
        work_of_adhesion=check_array("work_of_adhesion", work_of_adhesion),
        equilibrium_spacing=check_array("equilibrium_spacing", equilibrium_spacing),
    )
    _check_cylinder_si(R, E, {"work_of_adhesion": w, "equilibrium_spacing": z0}, stacklevel=4)
    rho, s, h = _groups(R, E, w, z0)
    return _pull_off_over_Eh(rho, s, _shape(cross_section, R)) * E * h


def jkr_pull_off_force(radius: ArrayLike, modulus: ArrayLike, work_of_adhesion: ArrayLike):
    r"""JKR pull-off of a line contact, :math:`-\tfrac34 (4 \pi w^2 E R)^{1/3}` [N/m] (no range)."""
    R = check_array("radius", radius)
    E = check_array("modulus", modulus)
    w = check_array("work_of_adhesion", work_of_adhesion)
    for name, v in (("radius", R), ("modulus", E), ("work_of_adhesion", w)):
        _plausible(name, v)
    with np.errstate(over="ignore", under="ignore", invalid="ignore"):
        F = _jkr_pull_off_si(R, E, w)
    return _finite_force(F, radius=R, modulus=E, work_of_adhesion=w)


def _finite_force(F: Any, **inputs: NDArray) -> Any:
    """``F`` [N/m], refused where inputs far out of scale left the floating-point range.

    The message names the inputs at the first such point (the likely slip of units).
    """
    bad = ~np.isfinite(F)
    if np.any(bad):
        _, at = first_point(bad, **inputs)
        raise ValueError(
            f"the pull-off force of {point_text(at)} is beyond the floating-point range: is an "
            "input in the wrong units (m, Pa, J/m^2)?"
        )
    return F


def _jkr_pull_off_si(R, E, w):
    """:func:`linecontact.closed_forms._jkr_pull_off` in SI units (``h = R``: no range in JKR)."""
    return E * R * _cf._jkr_pull_off(1.0, w / (E * R))[0]


def _dmt_pull_off_si(R, w, z0):
    """:func:`linecontact.closed_forms._rigid_pull_off` in SI units: ``E h`` times it (any E)."""
    h = z0 / S_LJ
    return h * _cf._rigid_pull_off(R / h, w / h)


def dmt_pull_off_force(
    radius: ArrayLike, work_of_adhesion: ArrayLike, equilibrium_spacing: ArrayLike
):
    r"""Rigid-cylinder (DMT-like) pull-off, Dugdale law: :math:`-2\sqrt{2}\, w \sqrt{R/h}` [N/m].

    The small-Maugis-parameter limit: the adhesive zone :math:`|x| < \sqrt{2 R h}` around a rigid
    cylinder touching at a point, :math:`h = 9 \sqrt{3} z_0/16`.
    """
    R = check_array("radius", radius)
    w = check_array("work_of_adhesion", work_of_adhesion)
    z0 = check_array("equilibrium_spacing", equilibrium_spacing)
    for name, v in (("radius", R), ("work_of_adhesion", w)):
        _plausible(name, v)
    _plausible("equilibrium_spacing", z0, key="adhesion_range")
    with np.errstate(over="ignore", under="ignore", invalid="ignore", divide="ignore"):
        F = _dmt_pull_off_si(R, w, z0)
    return _finite_force(F, radius=R, work_of_adhesion=w, equilibrium_spacing=z0)


def simple_model_work_of_adhesion(
    radius: ArrayLike,
    pull_off_force: ArrayLike,
    modulus: float,
    equilibrium_spacing: float,
    sd: ArrayLike | None = None,
) -> dict[str, float]:
    r"""The work of adhesion JKR and DMT alone would give, by weighted least squares.

    :math:`F = -c_i w^{2/3}` (JKR, :math:`c_i = \tfrac34 (4 \pi E R_i)^{1/3}`) and
    :math:`F = -d_i w` (the rigid/DMT limit, :math:`d_i = 2 \sqrt{2} \sqrt{R_i/h}` at the range
    given) are linear in :math:`w^{2/3}` and :math:`w`: closed-form weighted least squares. Returns
    ``{"jkr": w_JKR, "dmt": w_DMT}`` [J/m^2] — what the simple models would have reported.

    Examples
    --------
    >>> R = np.array([1e-4, 2e-4])
    >>> F = jkr_pull_off_force(R, 50e9, 0.2)
    >>> round(simple_model_work_of_adhesion(R, F, 50e9, 0.3e-9)["jkr"], 12)
    0.2
    """
    R = check_array("radius", radius).reshape(-1)
    F = check_array("pull_off_force", pull_off_force, low=-np.inf, high=0.0).reshape(-1)
    E = float(check_array("modulus", modulus))
    z0 = float(check_array("equilibrium_spacing", equilibrium_spacing))
    wt = np.ones_like(F) if sd is None else 1.0 / check_array("sd", sd).reshape(-1) ** 2
    _check_cylinder_si(R, E, {"work_of_adhesion": None, "equilibrium_spacing": z0}, stacklevel=4)
    c = -_jkr_pull_off_si(R, E, 1.0)  # the JKR pull-off is -c w^(2/3)
    u = float(np.sum(wt * c * -F) / np.sum(wt * c * c))
    d = -_dmt_pull_off_si(R, 1.0, z0)  # the rigid pull-off is -d w
    w_dmt = float(np.sum(wt * d * -F) / np.sum(wt * d * d))
    return {"jkr": u**1.5, "dmt": w_dmt}


def _bisect_log(
    fun: Callable[[NDArray], NDArray], lo: NDArray, hi: NDArray, rtol: float = 1e-15
) -> NDArray:
    """Root of an increasing ``fun`` between ``lo`` and ``hi`` (> 0), bisected in log.

    To ``rtol`` relative in the root (round-off at the default).
    """
    a, b = np.log(lo), np.log(hi)
    for _ in range(_BISECTIONS):
        m = 0.5 * (a + b)
        up = fun(np.exp(m)) > 0
        a, b = np.where(up, a, m), np.where(up, m, b)
        if np.all(b - a <= np.maximum(rtol, 4e-16 * np.abs(m))):
            break
    return np.exp(0.5 * (a + b))


def work_of_adhesion_from_pull_off(
    pull_off_force: ArrayLike,
    radius: ArrayLike,
    modulus: ArrayLike,
    equilibrium_spacing: ArrayLike,
    *,
    on_failure: FailurePolicy = "raise",
    cross_section: CrossSection | None = None,
) -> NDArray:
    """The work of adhesion [J/m^2] whose Maugis--Dugdale pull-off is the one measured.

    Parameters
    ----------
    pull_off_force : array_like
        Measured pull-off force per unit length [N/m], negative (tensile).
    radius, modulus, equilibrium_spacing : array_like
        ``R`` [m], the composite plane-strain modulus ``E`` [Pa], the range ``z0`` [m].
    on_failure : {"raise", "report"}
        A force that no ``w`` produces raises (``"raise"``, default) or gives NaN at its
        point (``"report"``: what :func:`~linecontact.inverse.propagate` wants, so that a
        batch of draws is not split around the unreachable ones).
    cross_section : Polygon, optional
        A faceted wire on its facet (``radius`` its circumradius): the pull-off of
        :func:`pull_off_force` with it. Default: the round wire.

    Returns
    -------
    ndarray
        ``w`` [J/m^2]; arrays broadcast together.

    Raises
    ------
    ValueError
        For a force no ``w`` can produce (not negative, or beyond the reachable range,
        which the message states in N/m), with ``on_failure="raise"``.

    Examples
    --------
    >>> F = pull_off_force(50e-9, 50e9, 0.1, 0.3e-9)
    >>> round(float(work_of_adhesion_from_pull_off(F, 50e-9, 50e9, 0.3e-9)), 12)
    0.1
    """
    return _work_from_pull_off(
        pull_off_force,
        radius,
        modulus,
        equilibrium_spacing,
        unreachable="nan" if failure_policy(on_failure) == "report" else "raise",
        stacklevel=5,
        cross_section=cross_section,
    )


def _work_from_pull_off(
    pull_off_force: ArrayLike,
    radius: ArrayLike,
    modulus: ArrayLike,
    equilibrium_spacing: ArrayLike,
    *,
    rtol: float = 1e-15,
    unreachable: Literal["raise", "nan"] = "raise",
    stacklevel: int = 4,
    cross_section: CrossSection | None = None,
) -> NDArray:
    """:func:`work_of_adhesion_from_pull_off` with the options of the module's own callers.

    ``rtol``: of the bisection in ``w`` (a fit's starting point needs 1e-4 only);
    ``unreachable="nan"``: nan where no ``w`` produces the force, instead of the
    ``ValueError`` (for :func:`propagate`); ``stacklevel``: of the units warnings, for the
    caller of the public function.
    """
    F = check_array("pull_off_force", pull_off_force, low=-np.inf)
    R = check_array("radius", radius)
    E = check_array("modulus", modulus)
    z0 = check_array("equilibrium_spacing", equilibrium_spacing)
    F, R, E, z0 = broadcast(pull_off_force=F, radius=R, modulus=E, equilibrium_spacing=z0)
    _check_cylinder_si(
        R, E, {"work_of_adhesion": None, "equilibrium_spacing": z0}, stacklevel=stacklevel
    )
    shape = _shape(cross_section, R)
    # a polygon's search: sigma0/E up to 1 (its scan of the branch is not for stiffer glue)
    w_lo = _S_MIN * E * z0 / S_LJ
    s_max = _S_MAX if shape is None else 1.0
    w_hi = s_max * E * z0 / S_LJ

    def force_at(R, E, w, z0):
        rho, s, h = _groups(R, E, w, z0)
        return _pull_off_over_Eh(rho, s, shape) * E * h

    F_lo = force_at(R, E, w_hi, z0)  # the strongest adhesion searched
    F_hi = force_at(R, E, w_lo, z0)  # the weakest
    bad = ~((F < F_hi) & (F > F_lo))
    if np.any(bad) and unreachable == "nan":  # for propagate: nan where no w reaches
        Fm = np.where(bad, 0.5 * (F_lo + F_hi), F)
        w = _bisect_log(lambda w: Fm - force_at(R, E, w, z0), w_lo, w_hi, rtol)
        return _work_in_domain(np.where(bad, np.nan, w), "nan", E, "N/m", pull_off_force=F)
    if np.any(bad):
        _, at = first_point(bad, F=F, R=R, E=E, z0=z0, lo=F_lo, hi=F_hi)
        raise ParameterError(
            "pull_off_force",
            f"pull_off_force={at['F']!r} N/m cannot be produced by any work of "
            f"adhesion at radius={at['R']!r} m, modulus="
            f"{at['E']!r} Pa, equilibrium_spacing={at['z0']!r}"
            f" m: the reachable pull-off forces are ({at['lo']:.6g}, "
            f"{at['hi']:.6g}) N/m (an adhesive stress from {_S_MIN:g} to {s_max:g} times the "
            "modulus)",
        )
    # the pull-off force falls (grows in magnitude) with w
    w = _bisect_log(lambda w: F - force_at(R, E, w, z0), w_lo, w_hi, rtol)
    return _work_in_domain(w, unreachable, E, "N/m", pull_off_force=F)


def _work_in_domain(
    w: NDArray, unreachable: Literal["raise", "nan"], E: NDArray, unit: str, **given: NDArray
) -> NDArray:
    """``w`` [J/m^2] inside the domain of the work of adhesion (nan, or a ValueError, beyond).

    A modulus far out of scale (1e300 Pa) moves every reachable ``w`` with it: the work of
    adhesion found is then refused in J/m^2, with the measurement that needs it and the
    modulus (the likely slip of units), not left to overflow later.
    """
    from .domain import DOMAIN

    hi = DOMAIN["work_of_adhesion"][2]
    bad = ~(w <= hi)
    if not np.any(bad):
        return w
    if unreachable == "nan":
        return np.where(bad, np.nan, w)
    name = next(iter(given))
    _, at = first_point(bad, w=w, v=given[name], E=E)
    raise ParameterError(
        name,
        f"{name}={at['v']!r} {unit} needs a work of adhesion of {at['w']:.3g} J/m^2 at modulus="
        f"{at['E']!r} Pa, beyond the domain of the solvers (at most {hi:g} J/m^2): is the "
        "modulus in Pa?",
    )


def pull_off_force_at(R, E, w, z0):
    """:func:`pull_off_force` without the broadcasting (arrays of one shape)."""
    rho, s, h = _groups(R, E, w, z0)
    return np.asarray(_normal.pull_off(rho, s).F_pulloff_over_Eh) * E * h
