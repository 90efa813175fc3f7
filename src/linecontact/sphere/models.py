r"""Which model holds for a sphere, and the Carpick--Ogletree--Salmeron :math:`\alpha`.

- :func:`sphere_models`: for a sphere and a load, the Maugis parameter, the regime
  (Johnson & Greenwood 1997: DMT below :math:`\lambda = 0.1`, JKR above 5, the transition
  between) and the error of Hertz, DMT and JKR against the Maugis--Dugdale sphere, in the
  pull-off force and in the contact radius at the load: the answer to "which model?".
- :func:`cos_alpha`, :func:`maugis_parameter_of_cos_alpha`: the transition parameter
  :math:`\alpha` of Carpick, Ogletree & Salmeron (1999),
  :math:`a = a_0 [(\alpha + \sqrt{1 - F/F_c})/(1 + \alpha)]^{2/3}` (``F_c`` the pull-off,
  ``a_0`` the radius at zero load), fitted here to the library's own Maugis--Dugdale curve
  by least squares in ``a`` over the stable branch from the pull-off to ``COS_LOADS`` times
  its size in compression (``docs/sphere.md``), not taken from a published fit.

References
----------
K. L. Johnson, J. A. Greenwood, "An adhesion map for the contact of elastic spheres",
J. Colloid Interface Sci. 192 (1997) 326--333. doi:10.1006/jcis.1997.4984
R. W. Carpick, D. F. Ogletree, M. Salmeron, "A general equation for fitting contact area
and friction vs load measurements", J. Colloid Interface Sci. 211 (1999) 395--400.
doi:10.1006/jcis.1998.6027
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._validation import check_array
from ..closed_forms.sphere import (
    DMT_PULL_OFF,
    JKR_LOAD_CONTROL,
    _sphere_maugis_parameter,
)
from ..errors import ParameterError
from ..results import Result, as_result
from .contact import INPUTS, checked
from .pulloff import sphere_contact_for_load, sphere_pull_off

#: Johnson & Greenwood's bounds of the transition in the Maugis parameter.
DMT_BELOW, JKR_ABOVE = 0.1, 5.0

#: The loads of the COS fit: from the pull-off to this many times its size in compression.
COS_LOADS = 5.0

#: Points of the Maugis--Dugdale curve the COS fit is made to.
_COS_POINTS = 200

#: The Maugis parameters between which :func:`maugis_parameter_of_cos_alpha` looks.
_LAMBDA_RANGE = (1e-4, 1e4)


@dataclass(frozen=True)
class SphereModels(Result):
    r"""Which model holds for a sphere under a load: the regime, each model's errors.

    Attributes
    ----------
    maugis_parameter : ndarray or float
    regime : ndarray of str or str
        ``"DMT"`` (:math:`\lambda < 0.1`), ``"JKR"`` (:math:`\lambda > 5`) or
        ``"transition"``.
    pull_off_error_hertz, pull_off_error_dmt, pull_off_error_jkr : ndarray or float
        Each model's load-control pull-off less the Maugis--Dugdale one, over its size
        (Hertz: -1, none).
    radius_error_hertz, radius_error_dmt, radius_error_jkr : ndarray or float
        Each model's contact radius at the load less the Maugis--Dugdale one, over it (NaN
        where the model has no contact at that load).
    best : ndarray of str or str
        The model with the smallest error in the radius at the load.
    F_over_EhR, R_over_h, sigma0_over_E : ndarray or float
        The load and the parameters.
    """

    inputs: ClassVar[tuple[str, ...]] = INPUTS

    maugis_parameter: NDArray | float
    regime: NDArray | str
    pull_off_error_hertz: NDArray | float
    pull_off_error_dmt: NDArray | float
    pull_off_error_jkr: NDArray | float
    radius_error_hertz: NDArray | float
    radius_error_dmt: NDArray | float
    radius_error_jkr: NDArray | float
    best: NDArray | str
    F_over_EhR: NDArray | float
    R_over_h: NDArray | float
    sigma0_over_E: NDArray | float


def _radii(F: NDArray, rho: NDArray, s: NDArray) -> dict[str, NDArray]:
    """Each simple model's contact radius ``a/R`` under the load ``F/(E h R)``."""
    with np.errstate(invalid="ignore"):
        hertz = np.where(F >= 0, np.cbrt(3 * F / (4 * rho)), np.nan)
        dmt_load = F - DMT_PULL_OFF * np.pi * s
        dmt = np.where(dmt_load >= 0, np.cbrt(3 * dmt_load / (4 * rho)), np.nan)
        # JKR: (4/3) rho y^2 - sqrt(8 pi s rho) y - F = 0, y = (a/R)^(3/2), its larger root
        b = np.sqrt(8 * np.pi * s * rho)
        disc = b * b + (16 / 3) * rho * F
        y = (b + np.sqrt(disc)) / ((8 / 3) * rho)
        jkr = np.where(disc >= 0, y ** (2 / 3), np.nan)
    return {"hertz": hertz, "dmt": dmt, "jkr": jkr}


def sphere_models(
    F_over_EhR: ArrayLike, R_over_h: ArrayLike, sigma0_over_E: ArrayLike
) -> SphereModels:
    r"""Which model holds for an adhesive sphere under a load: its regime, each one's error.

    Parameters
    ----------
    F_over_EhR : array_like
        The load over ``E h R`` (compressive positive), at or above the pull-off.
    R_over_h, sigma0_over_E : array_like
        As in :func:`~linecontact.sphere.sphere_contact`; ``sigma0/E > 0``.

    Returns
    -------
    SphereModels

    Examples
    --------
    >>> m = sphere_models(0.0, 1e8, 0.01)  # lambda = 24: JKR-like
    >>> print(m.regime, m.best, f"{m.pull_off_error_jkr:+.4f}")
    JKR jkr +0.0002
    """
    scalar, (F, rho, s) = checked(
        F_over_EhR=F_over_EhR, R_over_h=R_over_h, sigma0_over_E=sigma0_over_E
    )
    if np.any(s <= 0):
        raise ParameterError(
            "sigma0_over_E", "sigma0_over_E must be > 0: without adhesion every model is Hertz"
        )
    shape = F.shape
    F, rho, s = F.reshape(-1), rho.reshape(-1), s.reshape(-1)
    lam = _sphere_maugis_parameter(rho, s)
    md = np.asarray(sphere_contact_for_load(F, rho, s).a_over_R, float).reshape(-1)
    po = np.asarray(sphere_pull_off(rho, s).F_pulloff_over_EhR, float).reshape(-1)
    models = _radii(F, rho, s)
    pulls = {
        "hertz": 0.0 * po,
        "dmt": DMT_PULL_OFF * np.pi * s,
        "jkr": JKR_LOAD_CONTROL * np.pi * s,
    }
    radius_error = {k: (a - md) / md for k, a in models.items()}
    errors = np.stack([np.abs(e) for e in radius_error.values()])
    best = np.array(list(models))[np.argmin(np.where(np.isfinite(errors), errors, np.inf), axis=0)]
    regime = np.where(lam < DMT_BELOW, "DMT", np.where(lam > JKR_ABOVE, "JKR", "transition"))
    return as_result(
        SphereModels,
        scalar,
        shape,
        maugis_parameter=lam,
        regime=regime,
        **{f"pull_off_error_{k}": (v - po) / np.abs(po) for k, v in pulls.items()},
        **{f"radius_error_{k}": v for k, v in radius_error.items()},
        best=best,
        F_over_EhR=F,
        R_over_h=rho,
        sigma0_over_E=s,
    )


def _cos_radius(alpha: float, load: NDArray, a0: float, Fc: float) -> NDArray:
    r"""COS: :math:`a_0 [(\alpha + \sqrt{1 - F/F_c})/(1 + \alpha)]^{2/3}` (``Fc < 0``)."""
    return a0 * ((alpha + np.sqrt(np.maximum(1 - load / Fc, 0.0))) / (1 + alpha)) ** (2 / 3)


def _cos_fit(lam: float) -> float:
    from scipy.optimize import minimize_scalar  # imported where used: a slow import

    rho = 1e6
    s = float(np.sqrt((lam / 2) ** 3 * 16 * np.pi / (9 * rho)))
    Fc = float(sphere_pull_off(rho, s).F_pulloff_over_EhR)
    loads = np.linspace(Fc, -COS_LOADS * Fc, _COS_POINTS)
    a = np.asarray(sphere_contact_for_load(loads, rho, s).a_over_R, float)
    a0 = float(sphere_contact_for_load(0.0, rho, s).a_over_R)

    def misfit(alpha: float) -> float:
        return float(np.sum((_cos_radius(alpha, loads, a0, Fc) / a - 1) ** 2))

    fit = minimize_scalar(misfit, bounds=(0.0, 1.5), method="bounded", options={"xatol": 1e-12})
    return float(fit.x)


def cos_alpha(maugis_parameter: ArrayLike) -> NDArray | float:
    r"""The COS transition parameter :math:`\alpha` that fits the Maugis--Dugdale sphere.

    Fitted by least squares in the contact radius over the stable branch from the
    load-control pull-off to :data:`COS_LOADS` times its size; 0 is DMT, 1 JKR.

    Parameters
    ----------
    maugis_parameter : array_like
        :math:`\lambda`, in ``[1e-4, 1e4]``.

    Examples
    --------
    >>> print(f"{cos_alpha(1.0):.3f}")
    0.685
    """
    lo, hi = _LAMBDA_RANGE
    lam = check_array(
        "maugis_parameter", maugis_parameter, low=lo, low_inclusive=True, high=hi,
        high_inclusive=True,
    )  # fmt: skip
    out = np.array([_cos_fit(float(x)) for x in lam.reshape(-1)]).reshape(lam.shape)
    return out.item() if out.ndim == 0 else out


def maugis_parameter_of_cos_alpha(alpha: float) -> float:
    r"""The Maugis parameter whose sphere the COS :math:`\alpha` fits (:func:`cos_alpha` undone).

    Examples
    --------
    >>> print(f"{maugis_parameter_of_cos_alpha(0.685):.3f}")
    1.000
    """
    lo, hi = (cos_alpha(x) for x in _LAMBDA_RANGE)
    a = float(alpha)
    if not lo <= a <= hi:
        raise ParameterError(
            "alpha",
            f"alpha must be in [{lo:.4g}, {hi:.4g}] (the fits at lambda {_LAMBDA_RANGE[0]:g} "
            f"and {_LAMBDA_RANGE[1]:g}), got {alpha!r}",
        )
    from scipy.optimize import brentq  # imported where used: a slow import

    ends = np.log(_LAMBDA_RANGE)
    t = brentq(lambda v: cos_alpha(np.clip(np.exp(v), *_LAMBDA_RANGE)) - a, *ends, xtol=1e-10)
    return float(np.exp(t))
