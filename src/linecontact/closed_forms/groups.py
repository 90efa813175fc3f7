r"""The groups of the Maugis--Dugdale line contact: ``kappa`` and the Maugis parameter.

:math:`\kappa = (4/\pi)(\sigma_0/E) \sqrt{2R/h}` (Johnson & Greenwood 2008) is the one group on
which the whole Maugis--Dugdale family depends; every solver forms it with :func:`_kappa` and
refuses points beyond :data:`KAPPA_MAX` (:func:`_check_kappa`). The Maugis parameter is Baney &
Hui's Tabor-like parameter for line contact, :math:`\kappa = \lambda^{3/2}/\sqrt2`. Units as in
:mod:`linecontact.closed_forms`.

References
----------
J. M. Baney, C.-Y. Hui, "A cohesive zone model for the adhesion of cylinders",
J. Adhesion Sci. Technol. 11 (1997) 393--406. doi:10.1163/156856197X00796
K. L. Johnson, J. A. Greenwood, "A Maugis analysis of adhesive line contact",
J. Phys. D: Appl. Phys. 41 (2008) 155315. doi:10.1088/0022-3727/41/15/155315
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import domain as _domain
from .._numerics import _representable
from .._validation import broadcast, first_point, out, scalar_or_array

__all__ = ["KAPPA_MAX", "kappa", "maugis_parameter"]

#: Largest ``kappa`` the Maugis--Dugdale solvers accept. Their brackets in
#: :math:`u = \operatorname{arccosh}(c/a)` reach down to 1e-60 (the pull-off to 1e-10), and the
#: load minimum sits at :math:`u \approx 2.8\, \kappa^{-2/3}`: beyond
#: :math:`\kappa \approx 10^{13}` the minimum and the contacts near it fall outside, so
#: pull-off forces and contacts for a given load would be wrong.
KAPPA_MAX = 1e12


def _check_kappa(rho: NDArray, s: NDArray, rho_name: str = "R_over_h") -> None:
    """Refuse parameter points beyond :data:`KAPPA_MAX`, naming both parameters."""
    if np.ndim(rho) == 0 and np.ndim(s) == 0:
        # the same operations on Python floats (sqrt is correctly rounded in both)
        if _kappa(float(rho), float(s)) <= KAPPA_MAX:
            return
    with np.errstate(over="ignore"):
        kap = _kappa(rho, s)
    bad = ~(kap <= KAPPA_MAX)
    if np.any(bad):
        pick = list(first_point(bad, kap=kap, rho=rho, s=s)[1].values())
        raise ValueError(
            f"kappa = (4/pi) sigma0_over_E sqrt(2 {rho_name}) must be <= {KAPPA_MAX:g} (the "
            f"range of the solvers), got kappa={pick[0]:.3g} at {rho_name}={pick[1]!r}, "
            f"sigma0_over_E={pick[2]!r}"
        )


def _kappa(rho, s):
    """:func:`kappa` of validated inputs: arrays, NumPy scalars or Python floats.

    The one home of the formula: every solver forms ``kappa`` here. A Python float takes
    ``math.sqrt`` (fast, and correctly rounded as ``np.sqrt``: the same bits).
    """
    return (4 / np.pi) * s * (math.sqrt(2 * rho) if type(rho) is float else np.sqrt(2 * rho))


def _maugis_parameter(rho, s):
    """:func:`maugis_parameter` of validated inputs (arrays or NumPy scalars)."""
    return 4 / np.pi ** (2 / 3) * s ** (2 / 3) * rho ** (1 / 3)


def _closed_form(what: str, kernel: Callable[..., NDArray], **groups: ArrayLike) -> NDArray | float:
    """``kernel`` of the checked, broadcast ``groups`` (in order), refused where it overflows.

    The public closed forms in one place: each group checked against its domain, the groups
    broadcast together, ``what`` named in the overflow message.
    """
    checked = {name: _domain.check(name, value) for name, value in groups.items()}
    arrays = broadcast(**checked)
    with np.errstate(over="ignore"):
        val = kernel(*arrays)
    val = _representable(what, val, **dict(zip(checked, arrays, strict=True)))
    return out(val, scalar_or_array(*arrays))


def kappa(R_over_h: ArrayLike, sigma0_over_E: ArrayLike) -> NDArray | float:
    r"""The single group of the Maugis--Dugdale line contact.

    :math:`\kappa = (4/\pi)(\sigma_0/E)\sqrt{2R/h}`.

    Small :math:`\kappa` is the DMT-like (rigid, long-range) end, large :math:`\kappa` the
    JKR-like (compliant, short-range) end. :math:`\kappa = \lambda^{3/2}/\sqrt2`
    with :math:`\lambda` of :func:`maugis_parameter`.
    """
    return _closed_form("kappa", _kappa, R_over_h=R_over_h, sigma0_over_E=sigma0_over_E)


def maugis_parameter(R_over_h: ArrayLike, sigma0_over_E: ArrayLike) -> NDArray | float:
    r"""Baney & Hui's Tabor-like parameter for line contact.

    :math:`\lambda = 4\sigma_0 (R/(\pi^2 E^2 w))^{1/3}`.

    With :math:`w = \sigma_0 h`: :math:`\lambda = (4/\pi^{2/3})(\sigma_0/E)^{2/3}(R/h)^{1/3}`.
    DMT-like for :math:`\lambda \lesssim 0.1`, JKR-like for :math:`\lambda \gtrsim 5`.
    """
    return _closed_form(
        "the Maugis parameter", _maugis_parameter, R_over_h=R_over_h, sigma0_over_E=sigma0_over_E
    )
