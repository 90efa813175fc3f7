r"""A sphere's shear strength from friction against load, with its interval.

:func:`sphere_fit_shear_strength`: one ``tau0`` from friction forces against loads,
:math:`f = \tau_0 \pi a^2` with ``a`` the Maugis--Dugdale sphere's contact radius under each
load (:func:`~linecontact.sphere.sphere_contact_for_load`, the Dugdale step matched to the
Lennard-Jones law as in :mod:`linecontact.sphere.fits`): linear least squares, its
covariance in closed form, the shared inputs' uncertainties by Monte Carlo
(:class:`SphereShearStrengthFit`). Units SI (m, Pa, N, J/m^2).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import ClassVar

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._validation import check_array
from ..errors import ParameterError
from ..results import Result
from .fits import _count, _groups, _number, _standard_deviations, _vector
from .pulloff import sphere_contact_for_load

__all__ = ["SphereShearStrengthFit", "sphere_fit_shear_strength"]


@dataclass(frozen=True)
class SphereShearStrengthFit(Result):
    r"""One shear strength ``tau0`` fitted to a sphere's friction forces against its loads.

    Attributes
    ----------
    shear_strength, shear_strength_sd : float
        ``tau0`` [Pa] and its standard uncertainty from the data (closed form).
    shear_strength_ci95 : (float, float)
        Its 95 % interval from the data [Pa] (normal with sds, Student's t without).
    shear_strength_sd_inputs : float
        The standard uncertainty the inputs' uncertainties add, by Monte Carlo (0 without
        them); ``shear_strength_sd_total`` combines both in quadrature.
    contact_radius : ndarray
        The Maugis--Dugdale sphere's contact radius at each load [m].
    model, residuals : ndarray
        ``tau0 pi a^2`` [N] and it less the measured friction [N].
    chi2, dof, birge_ratio : float, int, float
        The squared weighted residuals' sum, the degrees of freedom, and ``chi2/dof`` (nan
        without sds or with one point); a Birge ratio above 1 widens the interval by its
        square root.
    note : str
    """

    whole: ClassVar[tuple[str, ...]] = ("shear_strength_ci95",)
    derived: ClassVar[tuple[str, ...]] = ("shear_strength_sd_total",)

    shear_strength: float
    shear_strength_sd: float
    shear_strength_ci95: tuple[float, float]
    shear_strength_sd_inputs: float
    contact_radius: NDArray
    model: NDArray
    residuals: NDArray
    chi2: float
    dof: int
    birge_ratio: float
    note: str

    @property
    def shear_strength_sd_total(self) -> float:
        """The standard uncertainty of ``tau0`` from the data and the inputs [Pa]."""
        return math.hypot(self.shear_strength_sd, self.shear_strength_sd_inputs)


def _areas(load: NDArray, R: float, E: ArrayLike, w: ArrayLike, z0: ArrayLike) -> NDArray:
    r"""The contact areas :math:`\pi a^2` [m^2] at the loads (nan below the pull-off).

    ``E``, ``w``, ``z0`` broadcast against ``load`` (a column of draws gives a row each).
    """
    rho, s, h = _groups(R, E, w, z0)
    a_over_R = sphere_contact_for_load(load / (E * h * R), rho, s, on_failure="report").a_over_R
    return np.pi * (np.asarray(a_over_R, float) * R) ** 2


def _through_origin(f: NDArray, A: NDArray, wt: NDArray) -> NDArray:
    """Weighted least squares of ``f = tau0 A`` along the last axis: ``tau0`` per row."""
    return np.sum(wt * f * A, axis=-1) / np.sum(wt * A * A, axis=-1)


def sphere_fit_shear_strength(
    friction_force: ArrayLike,
    normal_load: ArrayLike,
    radius: float,
    modulus: float,
    work_of_adhesion: float,
    equilibrium_spacing: float,
    *,
    sd: ArrayLike | None = None,
    modulus_sd: float = 0.0,
    work_of_adhesion_sd: float = 0.0,
    equilibrium_spacing_sd: float = 0.0,
    samples: int = 200,
    seed: int = 0,
) -> SphereShearStrengthFit:
    r"""Fit one interfacial shear strength to a sphere's friction forces against its loads.

    :math:`f_i = \tau_0 \pi a_i^2`, ``a_i`` the Maugis--Dugdale sphere's contact radius
    under the load ``F_i`` (:func:`~linecontact.sphere.sphere_contact_for_load`): linear in
    :math:`\tau_0`, so weighted least squares in closed form,
    :math:`\tau_0 = \sum w_i f_i A_i / \sum w_i A_i^2` with :math:`A_i = \pi a_i^2`,
    :math:`w_i = 1/s_i^2`, and the variance :math:`1/\sum w_i A_i^2` (with sds; times the
    Birge ratio where it is above 1), or the residuals' variance over :math:`\sum A_i^2`
    without them (a Student's t interval). A bootstrap of a linear fit would give this
    interval again; the inputs' uncertainties (shared by every point) are propagated by
    ``samples`` refits with ``E``, ``w`` and ``z0`` drawn.

    Parameters
    ----------
    friction_force : array_like, 1-D
        Friction forces ``f`` [N], positive.
    normal_load : array_like, 1-D
        Normal loads ``F`` [N], compressive positive, above the pull-off; one per force.
    radius, modulus, work_of_adhesion, equilibrium_spacing : float
        ``R`` [m], the composite modulus ``E`` [Pa], ``w`` [J/m^2], ``z0`` [m].
    sd : array_like, optional
        Standard deviations of the friction forces [N].
    modulus_sd, work_of_adhesion_sd, equilibrium_spacing_sd : float
        Standard uncertainties of the inputs [Pa], [J/m^2], [m] (draws at or below zero,
        or whose sphere comes off at a load, are skipped).
    samples : int
        The Monte Carlo refits for the inputs' uncertainties (only with one of them).
    seed : int
        Of the draws.

    Returns
    -------
    SphereShearStrengthFit

    Examples
    --------
    Friction at 100 MPa over the contact areas of the SI body, then the fit:

    >>> from linecontact import Sphere
    >>> F = np.array([0.0, 5e-9, 20e-9])
    >>> tip = Sphere.from_modulus(20e-9, 50e9, work_of_adhesion=0.1, equilibrium_spacing=3e-10)
    >>> a = tip.contact(load=F).contact_radius
    >>> fit = sphere_fit_shear_strength(1e8 * np.pi * a**2, F, 20e-9, 50e9, 0.1, 3e-10)
    >>> print(f"{fit.shear_strength / 1e6:.6f} MPa", fit.dof)
    100.000000 MPa 2
    """
    f = _vector("friction_force", friction_force, None)
    F = _vector("normal_load", normal_load, f.size, low=-np.inf)
    R = _number("radius", radius, "m")
    E = _number("modulus", modulus, "Pa")
    w = _number("work_of_adhesion", work_of_adhesion, "J/m^2")
    z0 = _number("equilibrium_spacing", equilibrium_spacing, "m")
    sig = _standard_deviations(sd, f, "N")
    shared = {"modulus": modulus_sd, "work_of_adhesion": work_of_adhesion_sd}
    shared["equilibrium_spacing"] = equilibrium_spacing_sd
    spreads = [
        float(check_array(f"{k}_sd", v, low=0.0, low_inclusive=True)) for k, v in shared.items()
    ]
    samples = _count("samples", samples, 2)
    seed = _count("seed", seed, 0)
    try:
        A = _areas(F, R, E, w, z0)
    except ParameterError as err:  # a load too large for the sphere's domain: as the caller's
        if err.parameter != "F_over_EhR":
            raise
        raise ParameterError(
            "normal_load",
            f"normal_load: a load is beyond the contacts the sphere is solved for: {err}",
        ) from err
    if np.any(np.isnan(A)):
        i = int(np.flatnonzero(np.isnan(A))[0])
        raise ParameterError(
            "normal_load",
            f"normal_load {float(F[i])!r} N (point {i + 1}) is below the pull-off of this "
            "sphere: no contact to slide on (check its sign: compressive positive)",
        )
    wt = np.ones_like(f) if sig is None else (np.min(sig) / sig) ** 2
    tau = float(_through_origin(f, A, wt))
    model = tau * A
    resid = model - f
    dof = f.size - 1
    notes = []
    birge = math.nan
    if sig is not None:
        chi2 = float(np.sum((resid / sig) ** 2))
        var = 1.0 / float(np.sum(A * A / sig**2))
        if dof > 0:
            birge = chi2 / dof
            var *= max(1.0, birge)
        z = 1.959963984540054
    else:
        chi2 = float(np.sum(resid**2))
        var = chi2 / dof / float(np.sum(A * A)) if dof > 0 else math.nan
        z = _student(dof) if dof > 0 else math.nan
        if dof == 0:
            notes.append("one point and no sd: no uncertainty can be estimated")
    tau_sd = math.sqrt(var) if math.isfinite(var) else math.nan
    ci = (tau - z * tau_sd, tau + z * tau_sd)
    sd_inputs = 0.0
    if any(spreads):
        sd_inputs = _shared_spread(f, F, R, (E, w, z0), spreads, wt, samples, seed)
        if not math.isfinite(sd_inputs):
            notes.append("fewer than 2 draws of the inputs kept a contact at every load")
    return SphereShearStrengthFit(
        shear_strength=tau,
        shear_strength_sd=tau_sd,
        shear_strength_ci95=ci,
        shear_strength_sd_inputs=sd_inputs,
        contact_radius=np.sqrt(A / np.pi),
        model=model,
        residuals=resid,
        chi2=chi2,
        dof=dof,
        birge_ratio=birge,
        note="; ".join(notes),
    )


def _student(dof: int) -> float:
    """Student's t at 97.5 % for ``dof`` degrees of freedom (scipy imported here: slow)."""
    from scipy.stats import t

    return float(t.ppf(1.0 - 0.05 / 2.0, dof))  # the two-sided 95 % quantile


def _shared_spread(
    f: NDArray,
    F: NDArray,
    R: float,
    values: tuple[float, float, float],
    spreads: list[float],
    wt: NDArray,
    samples: int,
    seed: int,
) -> float:
    """The sd of ``tau0`` over ``samples`` refits with ``(E, w, z0)`` drawn (a row each).

    A draw at or below zero, or one whose sphere comes off at a load, is skipped; nan where
    fewer than two are kept.
    """
    rng = np.random.default_rng(seed)
    noise = rng.standard_normal((samples, 3)) * spreads
    draws = [v + noise[:, i : i + 1] for i, v in enumerate(values)]
    keep = np.all(np.concatenate(draws, axis=1) > 0, axis=1)
    E, w, z0 = (d[keep] for d in draws)
    A = _areas(F[None, :], R, E, w, z0)
    taus = _through_origin(f, A, wt)
    taus = taus[np.isfinite(taus)]
    return float(np.std(taus, ddof=1)) if taus.size >= 2 else math.nan
