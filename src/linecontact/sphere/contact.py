r"""The adhesive sphere at given contact radii: :func:`sphere_contact`.

The Maugis--Dugdale sphere (Maugis 1992) in the library's groups (``docs/sphere.md``; the
equations in :mod:`linecontact.sphere._branch`): given ``a/R``, the adhesive zone's radius,
the load over ``E h R`` and the approach over ``h``.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import ClassVar

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import domain as _domain
from .._validation import broadcast, first_point, point_text, scalar_or_array
from ..closed_forms.sphere import _sphere_maugis_parameter
from ..errors import ConvergenceError, ParameterError
from ..results import SI, Result, as_result
from . import _branch as _b

#: The inputs of the sphere's results (:attr:`linecontact.results.Result.inputs`).
INPUTS = ("R_over_h", "sigma0_over_E")

#: The residual of the gap condition (its logarithm) that counts as met.
RESIDUAL_TOL = 1e-12


@dataclass(frozen=True)
class SphereContact(Result):
    r"""The Maugis--Dugdale sphere at given contact radii.

    Attributes
    ----------
    a_over_R, c_over_R : ndarray or float
        Contact radius and the adhesive zone's outer radius over ``R``.
    F_over_EhR : ndarray or float
        Load over ``E h R`` (a force [N] over its scale; compressive positive).
    delta_over_h : ndarray or float
        Approach over ``h`` (the far points' displacement towards each other).
    R_over_h, sigma0_over_E : ndarray or float
        The parameters, broadcast.
    maugis_parameter : ndarray or float
        Maugis' :math:`\lambda` (0: Hertz, large: JKR).
    residual_separation : ndarray or float
        The logarithm of the gap at ``c`` over ``h`` (0 at the solution).
    converged : ndarray or bool
        The gap condition met to :data:`RESIDUAL_TOL`.
    stable : ndarray or bool
        :math:`dF/da > 0`: stable under load control.
    stable_displacement : ndarray or bool
        :math:`d\delta/da > 0`: stable under displacement control.
    """

    inputs: ClassVar[tuple[str, ...]] = INPUTS
    derived: ClassVar[tuple[str, ...]] = ("F_over_piwR",)

    a_over_R: NDArray | float = field(metadata=SI("contact_radius", "R", "m"))
    c_over_R: NDArray | float = field(metadata=SI("adhesive_zone_radius", "R", "m"))
    F_over_EhR: NDArray | float = field(metadata=SI("load", "EhR", "N"))
    delta_over_h: NDArray | float = field(metadata=SI("approach", "h", "m"))
    R_over_h: NDArray | float
    sigma0_over_E: NDArray | float
    maugis_parameter: NDArray | float
    residual_separation: NDArray | float
    converged: NDArray | bool
    stable: NDArray | bool
    stable_displacement: NDArray | bool

    @property
    def F_over_piwR(self):  # noqa: N802 - Maugis' unit of force
        r"""The load in Maugis' unit :math:`\pi w R` (NaN without adhesion)."""
        return over_piwR(self.F_over_EhR, self.sigma0_over_E)


def over_piwR(F_over_EhR, sigma0_over_E):  # noqa: N802 - Maugis' unit of force
    r"""A force over ``E h R`` in Maugis' unit :math:`\pi w R = \pi (\sigma_0/E)\, E h R`.

    NaN without adhesion (``sigma0 = 0``: no unit).
    """
    s = np.asarray(sigma0_over_E, float)
    with np.errstate(divide="ignore", invalid="ignore"):
        out = np.where(s > 0, np.asarray(F_over_EhR, float) / (np.pi * s), np.nan)
    return out.item() if out.ndim == 0 else out


#: The weakest adhesion a sphere is solved for (``sigma0/E``; below it, but 0, the unit of
#: force ``pi w R`` and the zone's scale are lost to rounding): give 0, Hertz.
SIGMA0_OVER_E_MIN = 1e-100


def check_adhesion(s: NDArray) -> None:
    """Refuse ``sigma0/E`` between 0 and :data:`SIGMA0_OVER_E_MIN` (ParameterError)."""
    weak = (s > 0) & (s < SIGMA0_OVER_E_MIN)
    if np.any(weak):
        bad = float(np.asarray(s)[weak].reshape(-1)[0])
        raise ParameterError(
            "sigma0_over_E",
            f"sigma0_over_E must be 0 (no adhesion: Hertz) or in [{SIGMA0_OVER_E_MIN:g}, 1e6] "
            f"for a sphere, got {bad!r} (the adhesion is lost to rounding below)",
        )


def checked(**values: ArrayLike) -> tuple[bool, list[NDArray]]:
    """The inputs checked against the domain and broadcast: ``(scalar, arrays)``."""
    arrays = [_domain.check(name, v) for name, v in values.items()]
    if "sigma0_over_E" in values:
        check_adhesion(arrays[list(values).index("sigma0_over_E")])
    scalar = scalar_or_array(*arrays)
    return scalar, [
        np.asarray(v, float) for v in broadcast(**dict(zip(values, arrays, strict=True)))
    ]


def states(alpha: NDArray, rho: NDArray, s: NDArray) -> dict[str, NDArray]:
    """The fields of :class:`SphereContact` at flat arrays (convergence checked)."""
    x, F, delta, q, res = _b.branch(alpha, rho, s)
    dF, dD = _b.slopes(alpha, rho, s, q)
    conv = np.abs(res) <= RESIDUAL_TOL
    if not np.all(conv):
        _, at = first_point(~conv, a_over_R=alpha, R_over_h=rho, sigma0_over_E=s)
        raise ConvergenceError(f"sphere_contact did not converge at {point_text(at)}")
    return dict(
        a_over_R=alpha,
        c_over_R=x,
        F_over_EhR=F,
        delta_over_h=delta,
        R_over_h=rho,
        sigma0_over_E=s,
        maugis_parameter=_sphere_maugis_parameter(rho, s),
        residual_separation=res,
        converged=conv,
        stable=dF > 0,
        stable_displacement=dD > 0,
    )


def sphere_contact(
    a_over_R: ArrayLike, R_over_h: ArrayLike, sigma0_over_E: ArrayLike
) -> SphereContact:
    r"""The Maugis--Dugdale sphere at contact radii ``a/R``.

    Parameters
    ----------
    a_over_R : array_like
        Contact radius over the sphere's radius, in ``[1e-150, 10]``.
    R_over_h : array_like
        Radius over the adhesion range ``h``, in ``[1e-3, 1e12]``.
    sigma0_over_E : array_like
        Adhesive stress over the composite modulus, in ``[0, 1e6]`` (0: Hertz).

    Returns
    -------
    SphereContact
        Broadcast over the three inputs (scalars in, scalars out).

    Notes
    -----
    The gap condition, the load and the approach of Maugis (1992, Eqs 6.17--6.19) in the
    groups (:mod:`linecontact.sphere._branch`); the zone is solved to rounding.

    Examples
    --------
    >>> r = sphere_contact(0.01, 1e4, 0.001)
    >>> print(f"{r.F_over_EhR:.10f} {r.maugis_parameter:.6f}")
    0.0036335378 0.242859
    """
    scalar, (alpha, rho, s) = checked(
        a_over_R=a_over_R, R_over_h=R_over_h, sigma0_over_E=sigma0_over_E
    )
    shape = alpha.shape
    vals = states(alpha.reshape(-1), rho.reshape(-1), s.reshape(-1))
    return as_result(SphereContact, scalar, shape, **vals)
