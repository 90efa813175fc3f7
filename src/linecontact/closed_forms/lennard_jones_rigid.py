r"""The Lennard-Jones law of Eq. (1) on a rigid cylinder: its load and its pull-off.

``F/(w sqrt(R/z0)) = -(8/3) sqrt(2 pi) (C3 zeta^(-5/2) - C9 zeta^(-17/2))``,
``C_n = Gamma(n - 1/2)/Gamma(n)``, ``zeta = g0/z0`` (docs/lennard-jones.md): the rigid limit
the elastic Lennard-Jones solver of :mod:`linecontact.lennard_jones` must meet. Loads in units
of ``w sqrt(R/z0)``, gaps in units of the equilibrium spacing ``z0``.

References
----------
K. L. Johnson, J. A. Greenwood, "A Maugis analysis of adhesive line contact",
J. Phys. D: Appl. Phys. 41 (2008) 155315 (the Maugis matching of the rigid pull-off).
doi:10.1088/0022-3727/41/15/155315
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import domain as _domain
from .._validation import out, scalar_or_array

__all__ = ["lennard_jones_rigid_load", "lennard_jones_rigid_pull_off"]

# the Lennard-Jones law of Eq. 1 on a rigid cylinder: F/(w sqrt(R/z0)) = -(8/3) sqrt(2 pi)
# (C3 zeta^(-5/2) - C9 zeta^(-17/2)), C_n = Gamma(n - 1/2)/Gamma(n) (docs/lennard-jones.md)
_LJ_C3 = float(np.sqrt(np.pi) * 0.75 / 2.0)  # Gamma(5/2)/Gamma(3) = (3 sqrt(pi)/4)/2
_LJ_C9 = float(np.exp(np.sum(np.log(np.arange(0.5, 8.0, 1.0)))) * np.sqrt(np.pi) / 40320.0)
_LJ_GAP_AT_PULL_OFF = float((17.0 * _LJ_C9 / (5.0 * _LJ_C3)) ** (1.0 / 6.0))


def _lj_rigid(zeta):
    k = (8.0 / 3.0) * np.sqrt(2.0 * np.pi)
    return -k * (_LJ_C3 * zeta**-2.5 - _LJ_C9 * zeta**-8.5)


def lennard_jones_rigid_load(central_gap_over_z0: ArrayLike) -> NDArray | float:
    r"""Load per unit length on a rigid cylinder under the Lennard-Jones law of Eq. (1).

    The surface traction is the law at the local gap ``z = g0 + x^2/(2R)``,
    :math:`p(z) = -\frac{8w}{3z_0}\left[(z_0/z)^3 - (z_0/z)^9\right]` (compressive
    positive: attraction beyond ``z0``), integrated over the whole line,
    :math:`\int (z_0/z)^n dx = \sqrt{2Rg_0}\,(z_0/g_0)^n\,\sqrt\pi\,\Gamma(n-\tfrac12)/
    \Gamma(n)`:

    .. math::

        \frac{F}{w\sqrt{R/z_0}} = -\frac{8}{3}\sqrt{2\pi}\left(C_3\,\zeta^{-5/2}
        - C_9\,\zeta^{-17/2}\right), \quad \zeta = g_0/z_0,\;
        C_n = \frac{\Gamma(n - 1/2)}{\Gamma(n)}.

    Parameters
    ----------
    central_gap_over_z0 : array_like
        The gap at the centre over the equilibrium spacing ``z0``, in ``[0.01, 1e6]``.

    Returns
    -------
    ndarray or float
        ``F / (w sqrt(R/z0))``, compressive positive.

    Examples
    --------
    >>> round(lennard_jones_rigid_load(1.0), 6)   # the surfaces at z0 at the centre
    -2.116227
    """
    g = _domain.check("central_gap_over_z0", central_gap_over_z0)
    return out(_lj_rigid(g), scalar_or_array(g))


def lennard_jones_rigid_pull_off() -> tuple[float, float]:
    r"""Pull-off force of a rigid cylinder under the Lennard-Jones law, and its central gap.

    The most tensile load of :func:`lennard_jones_rigid_load`, where its derivative
    vanishes: :math:`\zeta_*^6 = 17 C_9 / (5 C_3)`, :math:`\zeta_* = 1.100925`,
    :math:`F = -2.466056\, w\sqrt{R/z_0}`. The Maugis--Dugdale rigid pull-off with the
    Maugis matching (:math:`\sigma_0 = 16w/(9\sqrt3 z_0)`, :math:`h = w/\sigma_0`),
    :math:`2w\sqrt{2R/h} = 2.865520\,w\sqrt{R/z_0}`, is 16.2 % larger: for line contact the
    law matters even in the rigid limit (docs/lennard-jones.md).

    Returns
    -------
    (float, float)
        ``F_pulloff / (w sqrt(R/z0))`` (negative) and the central gap over ``z0`` there.

    Examples
    --------
    >>> F, g = lennard_jones_rigid_pull_off()
    >>> round(F, 6), round(g, 6)
    (-2.466056, 1.100925)
    """
    return float(_lj_rigid(_LJ_GAP_AT_PULL_OFF)), _LJ_GAP_AT_PULL_OFF
