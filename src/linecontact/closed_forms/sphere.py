r"""The adhesive sphere's closed forms: Hertz, JKR, DMT and the Maugis parameter.

A sphere of radius ``R`` on a flat (or two spheres of equivalent radius ``R``), composite
modulus ``E`` as everywhere (``1/E = (1 - nu1**2)/E1 + (1 - nu2**2)/E2``), ``K = 4E/3``,
adhesion ``(sigma0, h)`` with ``w = sigma0 h``. The groups are the wire's inputs, ``R/h``
and ``sigma0/E``; lengths over ``R`` (the contact radius ``a/R``), the approach (the
distance the far points move together) over ``h``, and the force, in N, over ``E h R``:

- Hertz: :math:`F = K a^3/R`, :math:`\delta = a^2/R`, so
  :math:`F/(E h R) = (4/3)(R/h)(a/R)^3`, :math:`\delta/h = (R/h)(a/R)^2`;
- JKR (Johnson, Kendall & Roberts 1971): :math:`F = K a^3/R - \sqrt{8\pi w E a^3}`,
  :math:`\delta = a^2/R - \sqrt{2\pi w a/E}`; its pull-off is :math:`-(3/2)\pi w R` under
  load control and :math:`-(5/6)\pi w R` under displacement control;
- DMT (Derjaguin, Muller & Toporov 1975): :math:`F = K a^3/R - 2\pi w R`,
  :math:`\delta = a^2/R`; its pull-off :math:`-2\pi w R`.

The Maugis parameter :math:`\lambda = 2\sigma_0 (R/(\pi w K^2))^{1/3}` (Maugis 1992), in
the groups :math:`\lambda = 2 (9 (\sigma_0/E)^2 (R/h)/(16\pi))^{1/3}`. Where the Dugdale
step matches the Lennard-Jones law's peak tension (``sigma0 = 16 w/(9 sqrt(3) z0)``, the
library's :class:`~linecontact.laws.Dugdale` from ``(w, z0)``), it is Tabor's parameter
:math:`\mu = (R w^2/(E^2 z_0^3))^{1/3}` times :data:`LAMBDA_OVER_TABOR` (1.1570...).

References
----------
K. L. Johnson, K. Kendall, A. D. Roberts, "Surface energy and the contact of elastic
solids", Proc. R. Soc. Lond. A 324 (1971) 301--313. doi:10.1098/rspa.1971.0141
B. V. Derjaguin, V. M. Muller, Yu. P. Toporov, "Effect of contact deformations on the
adhesion of particles", J. Colloid Interface Sci. 53 (1975) 314--326.
doi:10.1016/0021-9797(75)90018-1
D. Maugis, "Adhesion of spheres: the JKR-DMT transition using a Dugdale model",
J. Colloid Interface Sci. 150 (1992) 243--269. doi:10.1016/0021-9797(92)90285-T
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike

from ..materials import MAUGIS_STRENGTH

__all__ = [
    "LAMBDA_OVER_TABOR",
    "sphere_dmt_load",
    "sphere_hertz_load",
    "sphere_jkr_approach",
    "sphere_jkr_load",
    "sphere_maugis_parameter",
    "sphere_tabor_parameter",
]

#: lambda over Tabor's mu for the Dugdale step matched to the Lennard-Jones peak tension
#: (``MAUGIS_STRENGTH = 16/(9 sqrt 3)``): 2 MAUGIS_STRENGTH (9/(16 pi))^(1/3).
LAMBDA_OVER_TABOR = 2 * MAUGIS_STRENGTH * (9 / (16 * math.pi)) ** (1 / 3)

#: The pull-offs over pi w R: JKR under load and displacement control, DMT.
JKR_LOAD_CONTROL = -1.5
JKR_DISPLACEMENT_CONTROL = -5 / 6
DMT_PULL_OFF = -2.0


def sphere_maugis_parameter(R_over_h: ArrayLike, sigma0_over_E: ArrayLike):
    r"""Maugis' :math:`\lambda = 2\sigma_0 (R/(\pi w K^2))^{1/3}` of a sphere.

    >>> print(f"{sphere_maugis_parameter(100.0, 0.01):.6f}")
    0.242859
    """
    return _sphere_maugis_parameter(np.asarray(R_over_h, float), np.asarray(sigma0_over_E, float))


def _sphere_maugis_parameter(rho, s):
    return 2 * np.cbrt(9 * s * s * rho / (16 * np.pi))


def sphere_tabor_parameter(R_over_h: ArrayLike, sigma0_over_E: ArrayLike):
    r"""Tabor's :math:`\mu = (R w^2/(E^2 z_0^3))^{1/3}` of the law matched to the Dugdale step.

    With :math:`w = \sigma_0 h` and :math:`z_0 = S h` (``S = MAUGIS_STRENGTH``):
    :math:`\mu = ((R/h)(\sigma_0/E)^2/S^3)^{1/3}`; the Maugis parameter is
    :data:`LAMBDA_OVER_TABOR` times it.

    >>> print(f"{sphere_maugis_parameter(100.0, 0.01) / sphere_tabor_parameter(100.0, 0.01):.4f}")
    1.1570
    """
    rho, s = np.asarray(R_over_h, float), np.asarray(sigma0_over_E, float)
    return np.cbrt(rho * s * s / MAUGIS_STRENGTH**3)


def sphere_hertz_load(a_over_R: ArrayLike, R_over_h: ArrayLike):
    """Hertz: the load over ``E h R`` of a contact radius ``a/R``.

    >>> print(f"{sphere_hertz_load(0.1, 100.0):.6f}")
    0.133333
    """
    return _hertz(np.asarray(a_over_R, float), np.asarray(R_over_h, float))


def _hertz(alpha, rho):
    return (4 / 3) * rho * alpha**3


def sphere_jkr_load(a_over_R: ArrayLike, R_over_h: ArrayLike, sigma0_over_E: ArrayLike):
    """JKR: the load over ``E h R`` of a contact radius ``a/R`` (``w/(E h) = sigma0/E``).

    >>> print(f"{sphere_jkr_load(0.1, 100.0, 0.01):.9f}")
    -0.025199759
    """
    alpha, rho, s = (np.asarray(v, float) for v in (a_over_R, R_over_h, sigma0_over_E))
    return _jkr(alpha, rho, s)


def _jkr(alpha, rho, s):
    return _hertz(alpha, rho) - _jkr_adhesive(alpha, rho, s)


def _jkr_adhesive(alpha, rho, s):
    r"""JKR's adhesive load :math:`\sqrt{8\pi w E a^3}` over ``E h R``.

    Its approach's term, :math:`\sqrt{2\pi w a/E}`, is it over ``2 E a``.
    """
    return np.sqrt(8 * np.pi * s * rho * alpha**3)


def sphere_jkr_approach(a_over_R: ArrayLike, R_over_h: ArrayLike, sigma0_over_E: ArrayLike):
    """JKR: the approach over ``h`` of a contact radius ``a/R``."""
    alpha, rho, s = (np.asarray(v, float) for v in (a_over_R, R_over_h, sigma0_over_E))
    return rho * alpha**2 - _jkr_adhesive(alpha, rho, s) / (2 * alpha)


def sphere_dmt_load(a_over_R: ArrayLike, R_over_h: ArrayLike, sigma0_over_E: ArrayLike):
    """DMT: the load over ``E h R`` of a contact radius ``a/R``: Hertz less ``2 pi w R``.

    >>> print(f"{sphere_dmt_load(0.1, 100.0, 0.01):.9f}")
    0.070501480
    """
    alpha, rho, s = (np.asarray(v, float) for v in (a_over_R, R_over_h, sigma0_over_E))
    return _hertz(alpha, rho) + DMT_PULL_OFF * np.pi * s
