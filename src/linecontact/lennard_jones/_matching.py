r"""The Maugis matching of the Lennard-Jones law to the Dugdale step: constants, ``mu``.

Same work of adhesion :math:`w = \sigma_0 h` and same peak tension :math:`\sigma_0 = S w/z_0`:
the group ``mu`` of a Dugdale step and the Maugis parameter of a ``mu``.
"""

from __future__ import annotations

import numpy as np

from ..materials import MAUGIS_H_OVER_Z0, MAUGIS_STRENGTH

#: Peak tension of the law over :math:`w/z_0`: the Maugis matching of the Dugdale stress (an alias
#: of :data:`linecontact.materials.MAUGIS_STRENGTH`).
MAUGIS_MATCH_SIGMA0 = MAUGIS_STRENGTH
#: :math:`h/z_0 = w/(\sigma_0 z_0)` of the matched Dugdale step (0.974; an alias of
#: :data:`linecontact.materials.MAUGIS_H_OVER_Z0`).
MAUGIS_MATCH_H_OVER_Z0 = MAUGIS_H_OVER_Z0


def mu_of_dugdale(R_over_h, sigma0_over_E):
    r"""The group ``mu`` of the Lennard-Jones law matched to a Dugdale step :math:`(\sigma_0, h)`.

    Same work of adhesion :math:`w = \sigma_0 h` and same peak tension :math:`\sigma_0 = S w/z_0`
    (:math:`S` = :data:`MAUGIS_MATCH_SIGMA0`), so :math:`z_0 = S h` and
    :math:`w/(E z_0) = (\sigma_0/E)/S`: :math:`\mu = (\sigma_0/E) \sqrt{R/h}\, S^{-3/2}`. Returns
    ``(mu, R_over_z0)``.
    """
    R_over_z0 = np.asarray(R_over_h, float) / MAUGIS_MATCH_SIGMA0
    w_over_Ez0 = np.asarray(sigma0_over_E, float) / MAUGIS_MATCH_SIGMA0  # sigma0 h/(E z0)
    return w_over_Ez0 * np.sqrt(R_over_z0), R_over_z0


def maugis_parameter_of_mu(mu):
    r"""The Maugis parameter of the matched Dugdale step, as :func:`linecontact.maugis_parameter`.

    That parameter is :math:`(4/\pi^{2/3}) (\sigma_0/E)^{2/3} (R/h)^{1/3}`; with the matching
    (:func:`mu_of_dugdale`), :math:`(\sigma_0/E)^{2/3} (R/h)^{1/3} = S \mu^{2/3}`.
    """
    mu = np.asarray(mu, float)
    return 4.0 / np.pi ** (2.0 / 3.0) * MAUGIS_MATCH_SIGMA0 * mu ** (2.0 / 3.0)
