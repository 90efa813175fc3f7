r"""Pushed sideways, does a faceted wire slide or tip over its corner? :func:`facet_tipping`.

A sharp-cornered wire on its facet (half-width ``b = f R``) under a normal load ``F``
(compressive positive) and a push ``T`` at a height ``H`` above the substrate
(``docs/faceted.md``, Sec. 7). Units as in :mod:`linecontact.facet`: lengths over ``R``,
forces per unit length over ``E h``.

**Tipping, in the JKR limit.** The facet is a rigid flat punch; the push's moment about the
contact's centre, :math:`M = T H`, makes the pressure
:math:`p = (F + 2Mx/b^2)/(\pi\sqrt{b^2 - x^2})`, whose trailing edge opens, as a crack,
when :math:`K = (2M/b - F)/\sqrt{\pi b}` reaches :math:`\sqrt{2 E w}`: at
:math:`M_\text{peel} = (b/2)(F + |F_s|)`, :math:`F_s = -\sqrt{2\pi b E w}` the strip's
pull-off. As the contact recedes to :math:`[x_1, b]` (half-width :math:`b'`, pinned at the
leading corner) the moment it holds is
:math:`M(b') = (b'/2)(F + \sqrt{2\pi b' E w}) + F (b - b')`. Peeling is unstable where
:math:`dM/db' > 0` at :math:`b' = b`, that is where :math:`F < \tfrac32 |F_s|`; the moment
then falls and the wire tips at :math:`M_\text{peel}`, unless it rises again to the rigid
corner's :math:`F b` as :math:`b' \to 0`. Hence

.. math::

    M_\text{tip} = \frac{b}{2}\max(2F,\; F + |F_s|),

the rigid body's :math:`F b` without adhesion, 0 at the pull-off. **Sliding** needs the
facet's full slip, :math:`T = 2 b \tau_0`; it tips first where
:math:`T_\text{tip} = M_\text{tip}/H` is less, above the height
:math:`H^* = \max(2F, F + |F_s|)/(4\tau_0)`.

The JKR limit holds where the facet's Maugis--Dugdale pull-off is its strip's JKR value:
``jkr_error`` says how far it is, and a point beyond :data:`JKR_RTOL` is refused, naming
the Maugis parameter, never answered with the wrong limit.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import closed_forms as _cf
from .. import domain as _domain
from .._validation import broadcast, first_point, point_text, scalar_or_array
from ..errors import NoEquilibriumError, ParameterError
from ..results import Result, as_result
from . import _branch as _b
from .contact import check_geometry
from .pulloff import facet_pull_off

#: The JKR limit is taken where the facet's pull-off is within this fraction of the strip's
#: JKR pull-off (at a Maugis parameter of about 10 and above).
JKR_RTOL = 0.05


@dataclass(frozen=True)
class FacetTipping(Result):
    r"""Slide or tip: the pushes a sharp-cornered faceted wire takes, in the JKR limit.

    Attributes
    ----------
    T_tip_over_Eh, T_slide_over_Eh : ndarray or float
        The push that tips the wire over its leading corner (:math:`M_\text{tip}/H`) and the
        one that slides it (:math:`2 b \tau_0`), over ``E h``.
    first_motion : ndarray of str or str
        ``"tip"`` or ``"slide"`` (the smaller push; ``"slide"`` at a tie).
    H_star_over_R : ndarray or float
        The height above which it tips first.
    M_tip_over_EhR : ndarray or float
        :math:`M_\text{tip}/(E h R)`.
    tipping : ndarray of str or str
        ``"peel"``: the trailing edge's crack runs at once (:math:`F < |F_s|`);
        ``"corner"``: it arrests, and the wire tips at the rigid corner's :math:`F b`.
    jkr_error : ndarray or float
        The facet's Maugis--Dugdale pull-off over the strip's JKR one, minus 1.
    F_over_Eh, H_over_R, tau0_over_E, R_over_h, sigma0_over_E, sides : ndarray or float
        The parameters, broadcast.
    """

    inputs: ClassVar[tuple[str, ...]] = (
        "F_over_Eh",
        "H_over_R",
        "tau0_over_E",
        "R_over_h",
        "sigma0_over_E",
        "sides",
    )

    T_tip_over_Eh: NDArray | float
    T_slide_over_Eh: NDArray | float
    first_motion: NDArray | str
    H_star_over_R: NDArray | float
    M_tip_over_EhR: NDArray | float
    tipping: NDArray | str
    jkr_error: NDArray | float
    F_over_Eh: NDArray | float
    H_over_R: NDArray | float
    tau0_over_E: NDArray | float
    R_over_h: NDArray | float
    sigma0_over_E: NDArray | float
    sides: NDArray | int


def tipping_moment(F: NDArray, b: NDArray, Fs: NDArray) -> NDArray:
    r""":math:`M_\text{tip} = (b/2)\max(2F, F + |F_s|)` (any consistent units)."""
    return 0.5 * b * np.maximum(2 * F, F + np.abs(Fs))


def facet_tipping(
    F_over_Eh: ArrayLike,
    H_over_R: ArrayLike,
    tau0_over_E: ArrayLike,
    R_over_h: ArrayLike,
    sigma0_over_E: ArrayLike,
    *,
    sides: ArrayLike = 6,
) -> FacetTipping:
    r"""Whether a sharp-cornered faceted wire pushed at a height slides or tips first.

    Parameters
    ----------
    F_over_Eh : array_like
        Normal load over ``E h`` (compressive positive), above the facet's pull-off.
    H_over_R : array_like
        The push's height above the substrate over the circumradius, ``(0, 2]``.
    tau0_over_E : array_like
        The interface's friction stress over the composite modulus, ``(1e-12, 1]``.
    R_over_h, sigma0_over_E : array_like
        As in :func:`~linecontact.facet.facet_pull_off`; in the JKR limit (see the module).
    sides : array_like of int
        Number of sides, ``>= 3``; the corners sharp.

    Returns
    -------
    FacetTipping

    Examples
    --------
    >>> t = facet_tipping(0.0, 2.0, 0.01, 1e6, 0.01)  # a hexagon pushed at twice R
    >>> t.first_motion, t.tipping
    ('tip', 'peel')
    """
    F = _domain.check("F_over_Eh", F_over_Eh)
    H = _domain.check("H_over_R", H_over_R, "push_H_over_R")
    tau = _domain.check("tau0_over_E", tau0_over_E)
    rho = _domain.check("R_over_h", R_over_h)
    s = _domain.check("sigma0_over_E", sigma0_over_E)
    n, _ = check_geometry(sides, 0.0)
    scalar = scalar_or_array(F, H, tau, rho, s, n)
    F, H, tau, rho, s, n = broadcast(
        F_over_Eh=F, H_over_R=H, tau0_over_E=tau, R_over_h=rho, sigma0_over_E=s, sides=n
    )
    f = _b.facet_half_width(n.astype(float), np.zeros(n.shape))
    Fs = _cf._strip_pull_off(f, rho, s)
    po = facet_pull_off(rho, s, sides=n, corner_radius_over_R=0.0)
    err = np.asarray(po.F_pulloff_over_Eh) / Fs - 1
    far = ~(np.abs(err) <= JKR_RTOL)
    if np.any(far):
        _, at = first_point(far, R_over_h=rho, sigma0_over_E=s, sides=n)
        lam = float(np.reshape(_cf._maugis_parameter(rho, s) + 0 * err, -1)[np.argmax(far)])
        raise ParameterError(
            "sigma0_over_E",
            f"the tipping of a faceted wire is written in the JKR limit, where its pull-off is "
            f"the strip's JKR value to {JKR_RTOL:g}; at {point_text(at)} (Maugis parameter "
            f"{lam:.3g}) it is {float(np.reshape(err, -1)[np.argmax(far)]):+.3g} off: a "
            "larger Maugis parameter (a stiffer adhesion: larger R/h or sigma0/E) is needed",
        )
    below = F < Fs
    if np.any(below):
        _, at = first_point(below, F_over_Eh=F, R_over_h=rho, sigma0_over_E=s)
        raise NoEquilibriumError(
            f"no contact carries F_over_Eh at {point_text(at)}: it is below the facet's pull-off "
            "(the wire has pulled off; nothing to push)"
        )
    M = tipping_moment(F, f, Fs)  # over E h R
    T_tip = M / H
    T_slide = 2 * f * rho * tau
    return as_result(
        FacetTipping,
        scalar,
        T_tip_over_Eh=T_tip,
        T_slide_over_Eh=T_slide,
        first_motion=np.where(T_tip < T_slide, "tip", "slide"),
        H_star_over_R=M / T_slide,
        M_tip_over_EhR=M,
        tipping=np.where(F < np.abs(Fs), "peel", "corner"),
        jkr_error=err,
        F_over_Eh=F,
        H_over_R=H,
        tau0_over_E=tau,
        R_over_h=rho,
        sigma0_over_E=s,
        sides=n.astype(int),
    )
