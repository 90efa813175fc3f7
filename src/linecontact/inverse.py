r"""From measurements to properties: work of adhesion, range and shear strength, with uncertainty.

The inverse problems of the SI layer, each with the forward model it inverts:

* :func:`work_of_adhesion_from_pull_off`: the Maugis--Dugdale pull-off force of a cylinder
  (:func:`pull_off_force`, the closed form of :func:`linecontact.pull_off` in SI units, with the
  adhesion given as ``(w, z0)``: :math:`\sigma_0 = 16 w/(9 \sqrt{3} z_0)`, :math:`h = w/\sigma_0`),
  solved for ``w`` at a known radius, modulus and range;
* :func:`fit_pull_off`: ``(w, z0)`` jointly, or ``w`` alone at a fixed ``z0``, from pull-off
  forces at several radii, by weighted least squares (:func:`scipy.optimize.least_squares`)
  with the covariance, the correlation and a parametric-bootstrap interval;
* :func:`work_of_adhesion_from_width`: the contact half-width at a normal load
  (:func:`linecontact.contact_for_load`) solved for ``w``;
* :func:`shear_strength_from_friction`: :math:`\tau_0 = (f - \Delta w) / (2 a)` with ``a`` the
  Maugis--Dugdale contact at the normal load (or the steady-sliding contact when an adhesion
  hysteresis :math:`\Delta w = w_\text{receding} - w_\text{advancing}` is given), or JKR, DMT or
  Hertz when asked;
* :func:`shear_strength_from_bent_wire`: :math:`\tau_0 = f/(2a)` with ``f`` fitted to the
  profile of a bent wire (:func:`linecontact.bent_wire.fit_bent_wire`), its uncertainty and
  those of the wire and the interface propagated;
* :func:`sphere_work_of_adhesion_from_pull_off` and :func:`sphere_shear_strength_from_friction`:
  the same for a sphere (an AFM tip; forces in N), from the Maugis--Dugdale sphere
  (:mod:`linecontact.sphere`);
* :func:`propagate`: the standard uncertainty and the 95 % interval of any of these by Monte
  Carlo (seeded, vectorised through the solvers), with the linearised estimate beside it
  (:mod:`linecontact.uncertainty`, re-exported here).

The pull-off problems (the forward model, ``w`` from a pull-off, :func:`fit_pull_off` and its
:class:`AdhesionFit`) live in :mod:`linecontact.fits`; this module re-exports them.

Units: SI throughout (m, Pa, N/m, J/m^2). Pull-off forces are negative (tensile), as in
the rest of the library. ``docs/inverse.md`` derives the models and their limits.
"""

from __future__ import annotations

import warnings
from typing import TYPE_CHECKING, Literal

import numpy as np
from numpy.typing import ArrayLike, NDArray

from . import closed_forms as _cf
from . import normal as _normal
from ._pull_off_model import (
    _S_MAX,
    _S_MIN,
    S_LJ,
    _bisect_log,
    _groups,
    _shape,
    _work_in_domain,
    dmt_pull_off_force,
    jkr_pull_off_force,
    pull_off_force,
    simple_model_work_of_adhesion,
    work_of_adhesion_from_pull_off,
)
from ._validation import FailurePolicy, broadcast, check_array, failure_policy, first_point
from .cylinder import _check_cylinder_si, _plausible, _warn_widths
from .cylinder._checks import _small_strain_in_si, _warn_small_strain
from .errors import ModelValidityWarning, ParameterError
from .facet import facet_contact_for_load as _facet_contact_for_load
from .fits import AdhesionFit, ShearStrengthFit, fit_pull_off, fit_shear_strength
from .geometry import CrossSection
from .materials import MAUGIS_STRENGTH
from .sphere import sphere_contact_for_load as _sphere_contact_for_load
from .sphere import sphere_pull_off as _sphere_pull_off
from .uncertainty import Estimate, propagate

if TYPE_CHECKING:
    from .bent_wire import BentWireFit
    from .domain import TooWideError

__all__ = [
    "AdhesionFit",
    "ShearStrengthFit",
    "fit_shear_strength",
    "simple_model_work_of_adhesion",
    "Estimate",
    "dmt_pull_off_force",
    "fit_pull_off",
    "jkr_pull_off_force",
    "propagate",
    "pull_off_force",
    "shear_strength_from_bent_wire",
    "shear_strength_from_friction",
    "sphere_shear_strength_from_friction",
    "sphere_work_of_adhesion_from_pull_off",
    "work_of_adhesion_from_pull_off",
    "work_of_adhesion_from_width",
]


def work_of_adhesion_from_width(
    half_width: ArrayLike,
    normal_load: ArrayLike,
    radius: ArrayLike,
    modulus: ArrayLike,
    equilibrium_spacing: ArrayLike,
    *,
    on_failure: FailurePolicy = "raise",
) -> NDArray:
    """The work of adhesion [J/m^2] whose stable contact at the load has the half-width measured.

    Forward model: the stable Maugis--Dugdale contact carrying ``normal_load``
    (:func:`linecontact.contact_for_load`); a wider contact needs more adhesion. A contact
    narrower than Hertz's at that load needs none: it cannot be produced (``ValueError``;
    NaN at its point with ``on_failure="report"``, as for
    :func:`work_of_adhesion_from_pull_off`).

    Examples
    --------
    >>> import linecontact as lc
    >>> cyl = lc.Cylinder.from_modulus(50e-9, 50e9, work_of_adhesion=0.1,
    ...                                equilibrium_spacing=0.3e-9)
    >>> a = cyl.contact(load=0.5).contact_half_width
    >>> round(float(work_of_adhesion_from_width(a, 0.5, 50e-9, 50e9, 0.3e-9)), 10)
    0.1
    """
    return _work_from_width(
        half_width,
        normal_load,
        radius,
        modulus,
        equilibrium_spacing,
        unreachable="nan" if failure_policy(on_failure) == "report" else "raise",
        stacklevel=5,
    )


def _work_from_width(
    half_width: ArrayLike,
    normal_load: ArrayLike,
    radius: ArrayLike,
    modulus: ArrayLike,
    equilibrium_spacing: ArrayLike,
    *,
    unreachable: Literal["raise", "nan"] = "raise",
    stacklevel: int = 4,
) -> NDArray:
    """:func:`work_of_adhesion_from_width` with the options of :func:`_work_from_pull_off`."""
    a = check_array("half_width", half_width)
    F = check_array("normal_load", normal_load, low=-np.inf)
    R = check_array("radius", radius)
    E = check_array("modulus", modulus)
    z0 = check_array("equilibrium_spacing", equilibrium_spacing)
    a, F, R, E, z0 = broadcast(
        half_width=a, normal_load=F, radius=R, modulus=E, equilibrium_spacing=z0
    )
    _check_cylinder_si(
        R, E, {"work_of_adhesion": None, "equilibrium_spacing": z0}, stacklevel=stacklevel
    )
    _check_load("normal_load", F, E, z0)
    _warn_widths(a, R, "the half_width measured", stacklevel=stacklevel - 1)

    def width(w):
        # pulled off: 0 (more adhesion is needed); wider than the solvers' domain: inf
        with warnings.catch_warnings():  # the contacts searched may be beyond small strain
            warnings.simplefilter("ignore", ModelValidityWarning)
            return _stable_width(F, R, E, w, z0, too_wide=np.inf, pulled_off=0.0)

    w_lo = _S_MIN * E * z0 / S_LJ
    w_hi = _S_MAX * E * z0 / S_LJ
    a_lo, a_hi = width(w_lo), width(w_hi)
    bad = ~((a > a_lo) & (a < a_hi))
    nan_mode = unreachable == "nan"
    if np.any(bad) and nan_mode:  # for propagate: nan where no w reaches
        a = np.where(bad, np.where(np.isfinite(a_hi), 0.5 * (a_lo + a_hi), 2 * a_lo + 1e-300), a)
    if np.any(bad) and not nan_mode:
        _, at = first_point(bad, a=a, F=F, lo=a_lo, hi=a_hi)
        raise ParameterError(
            "half_width",
            f"half_width={at['a']!r} m at normal_load="
            f"{at['F']!r} N/m cannot be produced by any work of adhesion: the "
            f"reachable half-widths are ({at['lo']:.6g}, "
            f"{at['hi']:.6g}) m (about Hertz's, without adhesion, at the "
            "low end)",
        )
    w = _bisect_log(lambda w: width(w) - a, w_lo, w_hi)
    # under a tension the width jumps from none (pulled off) to that at pull-off: a width
    # inside the jump is reached by no w
    got = width(w)
    off = ~(np.abs(got - a) <= 1e-6 * a)
    if nan_mode:
        return _work_in_domain(np.where(bad | off, np.nan, w), "nan", E, "m", half_width=a)
    if np.any(off):
        _, at = first_point(off, a=a, F=F, got=got)
        raise ParameterError(
            "half_width",
            f"half_width={at['a']!r} m at normal_load="
            f"{at['F']!r} N/m cannot be produced by any work of adhesion: the "
            f"narrowest stable contact carrying this load is {at['got']:.6g} m "
            "wide (at its pull-off)",
        )
    return _work_in_domain(w, "raise", E, "m", half_width=a)


def _too_wide_error(e: TooWideError, F: NDArray, R: NDArray, what: str) -> ValueError:
    """The error for a load ``F`` [N/m] that needs ``what`` wider than the solvers' domain."""
    i = e.index
    Ri = float(np.reshape(R, -1)[i])
    return ValueError(
        f"normal_load={float(np.reshape(F, -1)[i])!r} N/m needs {what} of "
        f"half-width {e.a_over_R * Ri:.6g} m, {e.a_over_R:.6g} radii at radius="
        f"{Ri!r} m: {e.limit}"
    )


def _stable_width(F, R, E, w, z0, *, too_wide=None, pulled_off=np.nan):
    """Half-width [m] of the stable Maugis--Dugdale contact at the load F (arrays of one shape).

    A load below the pull-off gives ``pulled_off``. A contact wider than the solvers'
    domain gives ``too_wide``, or (``None``) a ValueError naming ``normal_load``.
    """
    from .domain import TooWideError

    h = z0 / S_LJ
    rho, s = R / h, S_LJ * w / (z0 * E)

    def one(F_, rho_, s_, E_, h_):
        with _small_strain_in_si():  # said of the width in metres by the caller
            c = _normal.contact_for_load(F_ / (E_ * h_), rho_, s_, on_failure="report")
        return np.asarray(c.a_over_R, float)

    _check_load("normal_load", F, E, z0)
    try:
        A = one(F, rho, s, E, h)
    except TooWideError as e:
        if too_wide is None:
            raise _too_wide_error(e, F, R, "a contact") from None
        A = np.empty(np.shape(F))
        for i in np.ndindex(np.shape(F)):
            try:
                A[i] = one(F[i], rho[i], s[i], E[i], h[i])
            except TooWideError:
                A[i] = np.inf
    aw = A * R
    return np.where(np.isnan(aw), pulled_off, np.where(np.isinf(A), too_wide or 0.0, aw))


def _check_load(name: str, F: NDArray, E: NDArray, z0: NDArray, key: str = "F_over_Eh") -> None:
    r"""Refuse normal loads [N/m] beyond the solvers' domain, said in N/m (not as a group).

    The unit of the loads is the modulus times the adhesion range :math:`h = z_0/S` of the Maugis
    convention (:math:`0.974\, z_0`).
    """
    from .domain import check_si

    with np.errstate(over="ignore", under="ignore"):
        unit = E * (z0 / S_LJ)
    check_si(
        name,
        F,
        unit,
        key,
        "N/m",
        "times the modulus times the adhesion range (0.974 times the equilibrium spacing)",
    )


def _hertz_width(F, R, E):
    """Hertz half-width [m] at the load F [N/m]: the closed form of closed_forms, ``h = R``."""
    return R * _cf._hertz_half_width(F / (E * R), 1.0)


def shear_strength_from_friction(
    friction_force: ArrayLike,
    normal_load: ArrayLike,
    radius: ArrayLike,
    modulus: ArrayLike,
    work_of_adhesion: ArrayLike,
    equilibrium_spacing: ArrayLike,
    *,
    contact: str = "maugis-dugdale",
    receding_work_of_adhesion: ArrayLike | None = None,
    cross_section: CrossSection | None = None,
) -> NDArray:
    r"""Interfacial shear strength ``tau0`` [Pa] from a sliding friction force per length.

    :math:`\tau_0 = (f - \Delta w) / (2 a)`: the friction stress times the contact width carries
    the sliding force, less the adhesion hysteresis
    :math:`\Delta w = w_\text{receding} - w_\text{advancing}` (the work of opening the trailing
    edge, ``docs/push.md``). ``a`` comes from the contact at the normal load:

    * ``"maugis-dugdale"`` (default): the stable Maugis--Dugdale contact
      (:func:`linecontact.contact_for_load`), or with ``receding_work_of_adhesion`` the
      steady-sliding contact with the receding range :math:`h_1 = w_\text{receding}/\sigma_0`
      (:func:`linecontact.sliding_contact_for_load`, ``work_of_adhesion`` the advancing one);
    * ``"jkr"``, ``"dmt"``, ``"hertz"``: the simple models, only when asked (JKR's line
      contact; Hertz at the load plus the rigid-cylinder adhesive force for DMT; Hertz).

    With ``cross_section=Polygon(sides, corner_radius)`` the wire is faceted and lies on a
    facet (``radius`` its circumradius): ``a`` is its stable Maugis--Dugdale contact
    (:func:`linecontact.facet_contact_for_load`), several times the round wire's, and
    ``tau0`` is smaller by as much (``docs/faceted.md``).

    Examples
    --------
    >>> tau = shear_strength_from_friction(0.2, 0.5, 50e-9, 50e9, 0.1, 0.3e-9)
    >>> bool(1e7 < tau < 1e8)
    True
    """
    f = check_array("friction_force", friction_force, low=0.0, low_inclusive=False)
    F = check_array("normal_load", normal_load, low=-np.inf)
    R = check_array("radius", radius)
    E = check_array("modulus", modulus)
    w = check_array("work_of_adhesion", work_of_adhesion)
    z0 = check_array("equilibrium_spacing", equilibrium_spacing)
    if contact not in ("maugis-dugdale", "jkr", "dmt", "hertz"):
        raise ValueError(
            f"contact must be 'maugis-dugdale', 'jkr', 'dmt' or 'hertz', got {contact!r}"
        )
    # the receding work of adhesion broadcasts with the others (it may set the points' shape)
    receding = (
        {}
        if receding_work_of_adhesion is None
        else {
            "receding_work_of_adhesion": check_array(
                "receding_work_of_adhesion", receding_work_of_adhesion
            )
        }
    )
    f, F, R, E, w, z0, *w1_given = broadcast(
        friction_force=f,
        normal_load=F,
        radius=R,
        modulus=E,
        work_of_adhesion=w,
        equilibrium_spacing=z0,
        **receding,
    )
    _check_cylinder_si(R, E, {"work_of_adhesion": w, "equilibrium_spacing": z0}, stacklevel=4)
    rho, s, h = _groups(R, E, w, z0)
    dw = np.zeros_like(f)
    shape = _shape(cross_section, R)
    if shape is not None and (contact != "maugis-dugdale" or receding_work_of_adhesion is not None):
        raise ParameterError(
            "cross_section",
            f"a {cross_section!r} wire's contact is its Maugis-Dugdale contact on the facet: "
            "give contact='maugis-dugdale' and no receding_work_of_adhesion with it",
        )
    if shape is not None:
        _check_load("normal_load", F, E, z0, "F_over_Eh")
        facet = _facet_contact_for_load(F / (E * h), rho, s, on_failure="report", **shape)
        a = np.asarray(facet.a_over_R) * R
    elif receding_work_of_adhesion is not None:
        if contact != "maugis-dugdale":
            raise ValueError("receding_work_of_adhesion needs contact='maugis-dugdale'")
        w1 = w1_given[0]
        _plausible("receding_work_of_adhesion", w1, key="work_of_adhesion")
        if np.any((w1 < w) | (w1 > 1e3 * w)):
            _, at = first_point((w1 < w) | (w1 > 1e3 * w), w1=w1, w=w)
            raise ValueError(
                "receding_work_of_adhesion must be from work_of_adhesion (the advancing one: "
                "the hysteresis is not negative) to 1000 times it (the domain of steady "
                f"sliding), got {at['w1']!r} for {at['w']!r}"
            )
        from .domain import TooWideError
        from .sliding import sliding_contact_for_load

        _check_load("normal_load", F, E, z0, "F_over_Eh2")
        try:
            with _small_strain_in_si():  # said of the width in metres below
                c = sliding_contact_for_load(F / (E * h), rho, w1 / w, s, method="closed-form")
        except TooWideError as e:
            raise _too_wide_error(e, F, R, "a sliding contact") from None
        a = np.asarray(c.a_over_R) * R
        dw = w1 - w
    elif contact == "maugis-dugdale":
        a = _stable_width(F, R, E, w, z0)
    elif contact == "hertz":
        a = _hertz_width(F, R, E)
    elif contact == "dmt":
        a = _hertz_width(F - dmt_pull_off_force(R, w, z0), R, E)
    else:  # JKR: the stable (wider) root of F = pi E a^2/(4R) - sqrt(2 pi w E a)
        a = _jkr_width(F, R, E, w)
    if shape is None:  # a contact on the facet strains nothing for its a/R
        _warn_small_strain(a, R, stacklevel=3)
    bad = ~(np.isfinite(a) & (a > 0))
    if np.any(bad):
        _, at = first_point(bad, F=F)
        raise ValueError(
            f"normal_load={at['F']!r} N/m has no contact ({contact}): it is "
            "below the pull-off force, so there is no contact width to divide by"
        )
    with np.errstate(over="ignore"):  # an overflow is refused just below
        tau = (f - dw) / (2 * a)
    if not np.all(np.isfinite(tau)):
        _, at = first_point(~np.isfinite(tau), f=f, a=a)
        raise ValueError(
            f"friction_force={at['f']!r} N/m over a contact of half-width "
            f"{at['a']:.6g} m gives no finite shear strength"
        )
    if np.any(tau <= 0):
        _, at = first_point(tau <= 0, f=f, dw=dw)
        raise ValueError(
            f"friction_force={at['f']!r} N/m does not exceed the adhesion "
            f"hysteresis {at['dw']:.6g} J/m^2: no positive shear strength"
        )
    return tau


def _jkr_width(F, R, E, w):
    """Stable JKR line-contact half-width at the load F (nan below the pull-off)."""
    return R * _cf._jkr_half_width(F / (E * R), 1.0, w / (E * R))


# ------------------------------------------------------------------------------------------
# the sphere (an AFM tip, a colloidal probe): forces in N


def _sphere_groups(w, R, E, z0):
    """``(R/h, sigma0/E)`` of a sphere whose Dugdale step is matched to ``(w, z0)``."""
    sigma0 = MAUGIS_STRENGTH * w / z0
    return R * sigma0 / w, sigma0 / E


def sphere_work_of_adhesion_from_pull_off(
    pull_off_force: ArrayLike,
    radius: ArrayLike,
    modulus: ArrayLike,
    equilibrium_spacing: ArrayLike,
) -> NDArray | float:
    r"""The work of adhesion [J/m^2] whose Maugis--Dugdale sphere pulls off at the force given.

    The pull-off of a sphere under load control lies between DMT's :math:`-2\pi w R` and
    JKR's :math:`-\tfrac32\pi w R`, and its size grows with ``w`` (the Maugis parameter
    grows as :math:`w^{2/3}`), so ``w`` lies in :math:`[|F|/(2\pi R), |F|/(1.5\pi R)]`:
    the Illinois method on its logarithm in that bracket, to rounding.

    Parameters
    ----------
    pull_off_force : array_like
        The measured pull-off force [N], negative (tensile).
    radius, modulus, equilibrium_spacing : array_like
        ``R`` [m], the composite modulus ``E`` [Pa], the range ``z0`` [m] (the Dugdale step
        matched to the Lennard-Jones law's peak: ``sigma0 = 16 w/(9 sqrt 3 z0)``).

    Returns
    -------
    ndarray or float
        ``w`` [J/m^2]; arrays broadcast together.

    Examples
    --------
    >>> from linecontact import Sphere
    >>> F = Sphere.from_modulus(1e-6, 50e9, work_of_adhesion=0.05, equilibrium_spacing=3e-10)
    >>> w = sphere_work_of_adhesion_from_pull_off(F.pull_off().pull_off_force, 1e-6, 50e9, 3e-10)
    >>> print(f"{w:.12f}")
    0.050000000000
    """
    F = check_array("pull_off_force", pull_off_force, low=-np.inf, high=0.0, high_inclusive=False)
    R = check_array("radius", radius, low=0.0)
    E = check_array("modulus", modulus, low=0.0)
    z0 = check_array("equilibrium_spacing", equilibrium_spacing, low=0.0)
    scalar = all(np.ndim(v) == 0 for v in (pull_off_force, radius, modulus, equilibrium_spacing))
    F, R, E, z0 = (
        np.asarray(v, float).reshape(-1)
        for v in broadcast(pull_off_force=F, radius=R, modulus=E, equilibrium_spacing=z0)
    )

    def excess(v: NDArray) -> NDArray:  # the pull-off at w = e^v less the one measured, over it
        rho, s = _sphere_groups(np.exp(v), R, E, z0)
        got = np.asarray(_sphere_pull_off(rho, s).F_pulloff_over_EhR) * (E * (R / rho) * R)
        return got / F - 1  # > 0: more tensile than measured (too much adhesion)

    lo = np.log(-F / (2 * np.pi * R) * (1 - 1e-12))
    hi = np.log(-F / (1.5 * np.pi * R) * (1 + 1e-12))
    g_lo, g_hi = excess(lo), excess(hi)
    # the Illinois method (false position, the stale end's value halved) inside the bracket
    side = np.zeros(F.shape, int)
    for _ in range(100):
        with np.errstate(divide="ignore", invalid="ignore"):
            v = (lo * g_hi - hi * g_lo) / (g_hi - g_lo)
        v = np.where(np.isfinite(v) & (v > lo) & (v < hi), v, 0.5 * (lo + hi))
        g = excess(v)
        low = g < 0
        g_lo = np.where(low, g, np.where(side == 1, 0.5 * g_lo, g_lo))
        g_hi = np.where(~low, g, np.where(side == -1, 0.5 * g_hi, g_hi))
        side = np.where(low, -1, 1)
        lo, hi = np.where(low, v, lo), np.where(low, hi, v)
        if np.all((np.abs(g) <= 4e-16) | (hi - lo <= 2e-16 * np.abs(v))):
            break
    w = np.exp(v)
    return w.item() if scalar else w


def sphere_shear_strength_from_friction(
    friction_force: ArrayLike,
    normal_load: ArrayLike,
    radius: ArrayLike,
    modulus: ArrayLike,
    work_of_adhesion: ArrayLike,
    equilibrium_spacing: ArrayLike,
) -> NDArray | float:
    r"""The interfacial shear strength [Pa] of a sphere sliding at a friction force.

    :math:`\tau_0 = f/(\pi a^2)`, the friction over the contact area of the Maugis--Dugdale
    sphere under the normal load (the area a friction force measured by an AFM acts on).

    Parameters
    ----------
    friction_force : array_like
        ``f`` [N], positive.
    normal_load : array_like
        ``F`` [N], compressive positive, above the pull-off.
    radius, modulus, work_of_adhesion, equilibrium_spacing : array_like
        ``R`` [m], ``E`` [Pa], ``w`` [J/m^2], ``z0`` [m].

    Returns
    -------
    ndarray or float
        ``tau0`` [Pa].

    Examples
    --------
    >>> tau = sphere_shear_strength_from_friction(1e-9, 5e-9, 20e-9, 50e9, 0.1, 3e-10)
    >>> print(f"{tau / 1e6:.1f} MPa")
    89.9 MPa
    """
    f = check_array("friction_force", friction_force, low=0.0)
    scalar = all(
        np.ndim(v) == 0
        for v in (
            friction_force,
            normal_load,
            radius,
            modulus,
            work_of_adhesion,
            equilibrium_spacing,
        )
    )
    F = check_array("normal_load", normal_load, low=-np.inf)
    R = check_array("radius", radius, low=0.0)
    E = check_array("modulus", modulus, low=0.0)
    w = check_array("work_of_adhesion", work_of_adhesion, low=0.0)
    z0 = check_array("equilibrium_spacing", equilibrium_spacing, low=0.0)
    f, F, R, E, w, z0 = (np.asarray(v, float) for v in broadcast(
        friction_force=f, normal_load=F, radius=R, modulus=E, work_of_adhesion=w,
        equilibrium_spacing=z0,
    ))  # fmt: skip
    rho, s = _sphere_groups(w, R, E, z0)
    unit = E * (R / rho) * R  # E h R [N]
    a = np.asarray(_sphere_contact_for_load(F / unit, rho, s).a_over_R) * R
    tau = f / (np.pi * a * a)
    return tau.item() if scalar else tau


def shear_strength_from_bent_wire(
    fit: BentWireFit,
    radius: float,
    modulus: float,
    contact_modulus: float,
    work_of_adhesion: float,
    equilibrium_spacing: float,
    *,
    normal_load: float = 0.0,
    cross_section: CrossSection | None = None,
    inner_radius: float = 0.0,
    radius_sd: float = 0.0,
    modulus_sd: float = 0.0,
    contact_modulus_sd: float = 0.0,
    work_of_adhesion_sd: float = 0.0,
    equilibrium_spacing_sd: float = 0.0,
    n_samples: int = 4000,
    seed: int = 0,
) -> Estimate:
    r"""The interfacial shear strength [Pa] of a wire from the friction its bent shape shows.

    :math:`\tau_0 = f/(2a)`: ``f`` the friction per unit length fitted to the wire's
    profile, with the bending stiffness :math:`EI` of its cross-section
    (:func:`linecontact.bent_wire.bending_stiffness`); ``a`` the half-width of its contact
    under the normal load, from adhesion (:func:`shear_strength_from_friction`: the stable
    Maugis--Dugdale contact, on a facet for a faceted wire). The uncertainties propagate by
    Monte Carlo (:func:`propagate`): the shape's (the fit's covariance), and those of the
    radius (in both :math:`EI` and ``a``), the moduli and the adhesion, each independent.

    Parameters
    ----------
    fit : BentWireFit
        The fitted profile.
    radius : float
        The wire's radius [m] (a polygon's circumradius; a tube's outer radius).
    modulus : float
        The wire's Young's modulus along it [Pa], for :math:`EI`.
    contact_modulus : float
        The composite plane-strain modulus of the wire on its substrate [Pa]
        (:func:`linecontact.composite_modulus`).
    work_of_adhesion, equilibrium_spacing : float
        ``w`` [J/m^2], ``z0`` [m].
    normal_load : float, optional
        The load pressing the wire on the substrate besides adhesion (its weight) [N/m].
    cross_section : CrossSection, optional
        ``Polygon(sides, corner_radius)`` for a faceted wire lying on a facet; round by
        default.
    inner_radius : float, optional
        A tube's inner radius [m] (round only; its contact taken as the round wire's).
    radius_sd, modulus_sd, contact_modulus_sd, work_of_adhesion_sd, equilibrium_spacing_sd : float
        Standard uncertainties, in the units of their values.
    n_samples, seed : int, optional
        The Monte Carlo's draws and seed.

    Returns
    -------
    Estimate
        ``tau0`` [Pa] with its standard uncertainty and 95 % interval.
    """
    from .bent_wire import bending_stiffness

    EI = fit.bending_stiffness
    rel = fit.friction_per_length_sd_shape / fit.friction_per_length
    if not (np.isfinite(rel) and fit.friction_per_length > 0):
        raise ParameterError(
            "fit",
            "the fit does not determine the friction (zero, or no finite uncertainty): no "
            "shear strength follows from it",
        )
    shape = dict(cross_section=cross_section) if cross_section is not None else {}

    def tau(shape_factor, radius, modulus, contact_modulus, work_of_adhesion, equilibrium_spacing):
        ei = bending_stiffness(modulus, radius, inner_radius=inner_radius, **shape)
        f = fit.friction_per_length * shape_factor * np.asarray(ei) / EI
        return shear_strength_from_friction(
            f,
            normal_load,
            radius,
            contact_modulus,
            work_of_adhesion,
            equilibrium_spacing,
            **({"cross_section": cross_section} if cross_section is not None else {}),
        )

    values = dict(
        shape_factor=1.0,
        radius=radius,
        modulus=modulus,
        contact_modulus=contact_modulus,
        work_of_adhesion=work_of_adhesion,
        equilibrium_spacing=equilibrium_spacing,
    )
    sds = dict(
        shape_factor=rel,
        radius=radius_sd,
        modulus=modulus_sd,
        contact_modulus=contact_modulus_sd,
        work_of_adhesion=work_of_adhesion_sd,
        equilibrium_spacing=equilibrium_spacing_sd,
    )
    return propagate(tau, values, sds, n_samples=n_samples, seed=seed)
