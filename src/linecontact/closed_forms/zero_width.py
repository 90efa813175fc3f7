r"""The load at vanishing contact width, Eq. (14) of the paper.

The Maugis--Dugdale line contact (Baney & Hui 1997; Johnson & Greenwood 2008) as the contact
width goes to zero: also the most tensile force on the non-contact branch (central gap zero).
Written without cancellation and without overflow. Units as in
:mod:`linecontact.closed_forms`.

References
----------
J. M. Baney, C.-Y. Hui, "A cohesive zone model for the adhesion of cylinders",
J. Adhesion Sci. Technol. 11 (1997) 393--406. doi:10.1163/156856197X00796
K. L. Johnson, J. A. Greenwood, "A Maugis analysis of adhesive line contact",
J. Phys. D: Appl. Phys. 41 (2008) 155315. doi:10.1088/0022-3727/41/15/155315
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import domain as _domain
from .._validation import broadcast, out, scalar_or_array
from .maugis_dugdale import LN2

__all__ = ["zero_width_load"]


def zero_width_load(R_over_h: ArrayLike, sigma0_over_E: ArrayLike) -> NDArray | float:
    r"""The load at vanishing contact width, Eq. (14) of the paper.

    .. math::

        \frac{F}{Eh} = \frac{8\ln 2}{\pi}\frac{R}{h}\frac{\sigma_0}{E}\left(\frac{\sigma_0}{E}
        - \sqrt{\left(\frac{\sigma_0}{E}\right)^2 + \frac{1}{8}\left(\frac{\pi}{\ln 2}\right)^2
        \frac{h}{R}}\right)

    It is also the most tensile force on the non-contact branch (central gap zero).
    """
    rho = _domain.check("R_over_h", R_over_h)
    s = _domain.check("sigma0_over_E", sigma0_over_E)
    rho, s = broadcast(R_over_h=rho, sigma0_over_E=s)
    return out(_zero_width(rho, s), scalar_or_array(rho, s))


def _zero_width(rho: NDArray, s: NDArray) -> NDArray:
    k = (np.pi / LN2) ** 2 / (8 * rho)
    # s - sqrt(s^2 + k) written without cancellation, and without overflow of s^2 (hypot)
    # or of rho s k (rho k is a constant)
    return -(8 * LN2 / np.pi) * ((np.pi / LN2) ** 2 / 8) * s / (s + np.hypot(s, np.sqrt(k)))
