r"""The non-contact branch (:func:`non_contact`): the adhesive zone alone, no contact."""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import closed_forms as _cf
from .. import domain as _domain
from .._validation import (
    broadcast,
    check_array,
    scalar_or_array,
)
from ..results import Result, as_result


@dataclass(frozen=True)
class NonContact(Result):
    r"""Equilibrium without contact: the adhesive zone :math:`|x| < c`, central gap ``g0``.

    Attributes
    ----------
    central_gap_over_h : ndarray or float
        :math:`g_0/h` in :math:`[0, 1]`.
    c_over_R : ndarray or float
        Half-width of the adhesive zone.
    F_over_Eh : ndarray or float
        :math:`-2 \sigma_0 c / (E h)`; Eq. (14) at :math:`g_0 = 0`.
    stable : ndarray or bool
        Always False: unstable under load control (stable under displacement control).
    """

    inputs: ClassVar[tuple[str, ...]] = ("R_over_h", "sigma0_over_E")

    central_gap_over_h: NDArray | float
    c_over_R: NDArray | float
    F_over_Eh: NDArray | float
    R_over_h: NDArray | float
    sigma0_over_E: NDArray | float
    stable: NDArray | bool


def non_contact(
    central_gap_over_h: ArrayLike, R_over_h: ArrayLike, sigma0_over_E: ArrayLike
) -> NonContact:
    r"""The non-contact branch: attractive force vs the central gap :math:`g_0` in :math:`[0, h]`.

    With a uniform tensile stress on :math:`|x| < c` the gap rises from :math:`g_0` at the centre
    to :math:`h` at :math:`c`: :math:`h - g_0 = c^2/(2R) + 4\ln 2\,\sigma_0 c/(\pi E)`, and
    :math:`F = -2\sigma_0 c`. At :math:`g_0 = 0` this is Eq. (14).
    """
    g = check_array(
        "central_gap_over_h",
        central_gap_over_h,
        low=0.0,
        low_inclusive=True,
        high=1.0,
        high_inclusive=True,
    )
    rho = _domain.check("R_over_h", R_over_h)
    s = _domain.check("sigma0_over_E", sigma0_over_E)
    scalar = scalar_or_array(g, rho, s)
    g, rho, s = (
        np.asarray(v, float) for v in broadcast(central_gap_over_h=g, R_over_h=rho, sigma0_over_E=s)
    )
    k = 4 * _cf.LN2 * s / np.pi
    rhs = 2 * (1 - g) / rho
    # the root of C^2 + 2 k C = rhs without overflow of k^2; C = 0 at g0 = h (also 0/0 at s = 0)
    den = k + np.hypot(k, np.sqrt(rhs))
    C = rhs / np.where(rhs > 0, den, 1.0)
    F = -2 * s * rho * C
    return as_result(
        NonContact,
        scalar,
        central_gap_over_h=g,
        c_over_R=C,
        F_over_Eh=F,
        R_over_h=rho,
        sigma0_over_E=s,
        stable=np.zeros(g.shape, bool),
    )
