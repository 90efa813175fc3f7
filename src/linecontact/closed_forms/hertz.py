r"""Hertz line contact, Eq. (13) of the paper, and the small-strain limit of the theory.

:math:`F/(E h) = (\pi/4)(a/R)^2 (R/h)` (Johnson 1985, Sec. 4.3); :func:`_hertz` is its one home
in the paper's groups and :func:`_hertz_half_width` its inverse. :data:`A_OVER_R_SMALL_STRAIN`
bounds the contact width of the half-plane theory every solver uses (:func:`_warn_wide`).
Units as in :mod:`linecontact.closed_forms`.

References
----------
K. L. Johnson, *Contact Mechanics*, Cambridge University Press (1985), Sec. 4.3 (Hertz line
contact). doi:10.1017/CBO9781139171731
"""

from __future__ import annotations

import warnings

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..errors import ModelValidityWarning
from .groups import _closed_form

__all__ = ["A_OVER_R_SMALL_STRAIN", "hertz_load"]

#: Largest contact half-width over the radius of the small-strain, half-plane theory that
#: every solver uses (Hertz, Eq. 6): the surface strain is about :math:`p_0/E = a/(2R)`, 10 % here.
#: Wider contacts are computed but give a :class:`~linecontact.errors.ModelValidityWarning`.
A_OVER_R_SMALL_STRAIN = 0.2


def _warn_wide(a_over_R: ArrayLike, stacklevel: int = 3) -> None:
    """Warn once per call when a contact is wider than :data:`A_OVER_R_SMALL_STRAIN`.

    NaN (a point without a state) never warns; a scalar costs one comparison.
    """
    if isinstance(a_over_R, np.ndarray) and a_over_R.ndim:
        wide = a_over_R > A_OVER_R_SMALL_STRAIN  # NaN compares False, silently
        if not wide.any():
            return
        worst = float(np.max(a_over_R[wide]))
    else:
        worst = float(a_over_R)  # type: ignore[arg-type]
        if not worst > A_OVER_R_SMALL_STRAIN:
            return
    warnings.warn(
        f"a_over_R = {worst:.3g} is beyond the small-strain range of the half-plane theory "
        f"(a/R <= {A_OVER_R_SMALL_STRAIN:g}, strain a/(2R) <= {A_OVER_R_SMALL_STRAIN / 2:g}): "
        "the results are those of linear elasticity",
        ModelValidityWarning,
        stacklevel=stacklevel,
    )


def hertz_load(a_over_R: ArrayLike, R_over_h: ArrayLike) -> NDArray | float:
    r"""Hertz line contact, Eq. (13): :math:`F/(Eh) = (\pi/4)(a/R)^2 (R/h)`."""
    return _closed_form("the Hertz load", _hertz, a_over_R=a_over_R, R_over_h=R_over_h)


# --------------------------------------------------------------------------------------------
# the closed forms of Hertz, JKR and the rigid (DMT-like) cylinder, once, in the paper's groups
#
# ``A = a/R``, ``rho = R/h``, ``s = sigma0/E``, loads over ``E h``. Hertz and JKR have no range:
# any length ``h`` and stress ``sigma0`` with ``w = sigma0 h`` give the same physics, so the
# forms in SI units (:mod:`linecontact.inverse`, ``h = R``) and in the Lennard-Jones law's
# units (:mod:`linecontact.adhesion_map`, ``h = z0``, ``rho = 1``, ``s = mu``) scale these.


def _hertz(A, rho):
    r"""Hertz line contact, Eq. (13): :math:`F/(Eh) = (\pi/4) A^2 \rho`."""
    return np.pi / 4 * A * A * rho


def _hertz_half_width(F, rho):
    r"""The inverse of :func:`_hertz`: :math:`A = \sqrt{4 F/(\pi \rho)}`, 0 for :math:`F \le 0`."""
    return np.sqrt(4.0 * np.maximum(F, 0.0) / (np.pi * rho))
