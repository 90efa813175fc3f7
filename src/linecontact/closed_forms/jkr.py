r"""JKR line contact, and the rigid (DMT-like) pull-off of the Dugdale step.

:math:`F = \pi E a^2/(4R) - \sqrt{2\pi E w a}` with :math:`w = \sigma_0 h` (Chaudhury et al. 1996;
the :math:`m \to 1` limit of the Maugis--Dugdale solution), its pull-off and its half-width at a
load; :func:`_rigid_pull_off` is the other end of the family (small :math:`\kappa`). Hertz and JKR
have no range: the forms in SI units (:mod:`linecontact.inverse`, :math:`h = R`) and in the
Lennard-Jones law's units (:mod:`linecontact.adhesion_map`, :math:`h = z_0`, :math:`R/h = 1`,
:math:`\sigma_0/E = \mu`) scale these. Units as in :mod:`linecontact.closed_forms`.

References
----------
M. K. Chaudhury, T. Weaver, C. Y. Hui, E. J. Kramer, "Adhesive contact of cylindrical lens
and a flat sheet", J. Appl. Phys. 80 (1996) 30--37. doi:10.1063/1.362819
J. M. Baney, C.-Y. Hui, "A cohesive zone model for the adhesion of cylinders",
J. Adhesion Sci. Technol. 11 (1997) 393--406 (the rigid limit). doi:10.1163/156856197X00796
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import domain as _domain
from .._numerics import _representable
from .._validation import broadcast, out, scalar_or_array

__all__ = ["jkr_load"]


def jkr_load(a_over_R: ArrayLike, R_over_h: ArrayLike, sigma0_over_E: ArrayLike) -> NDArray | float:
    r"""JKR line contact with :math:`w = \sigma_0 h`.

    :math:`F = \pi E a^2/(4R) - \sqrt{2\pi E w a}`, i.e.
    :math:`F/(Eh) = (\pi/4)(a/R)^2(R/h) - \sqrt{2\pi(\sigma_0/E)(R/h)(a/R)}`.
    (Chaudhury et al. 1996; the :math:`m \to 1` limit of the Maugis--Dugdale solution.)
    """
    A = _domain.check("a_over_R", a_over_R)
    rho = _domain.check("R_over_h", R_over_h)
    s = _domain.check("sigma0_over_E", sigma0_over_E)
    A, rho, s = broadcast(a_over_R=A, R_over_h=rho, sigma0_over_E=s)
    with np.errstate(over="ignore", invalid="ignore"):
        val = _jkr(A, rho, s)
    val = _representable("the JKR load", val, a_over_R=A, R_over_h=rho, sigma0_over_E=s)
    return out(val, scalar_or_array(A, rho, s))


def _jkr(A, rho, s):
    r"""JKR line contact: :math:`F/(Eh) = (\pi/4) A^2 \rho - \sqrt{2\pi s \rho A}`."""
    return np.pi / 4 * A * A * rho + _strip_pull_off(A, rho, s)


def _strip_pull_off(A, rho, s):
    r"""The JKR pull-off of a flat strip of half-width ``A R``: :math:`-\sqrt{2\pi s\rho A}`.

    In SI units :math:`-\sqrt{2\pi a E w}` (Kendall's flat punch in plane strain; the
    adhesive term of the JKR line contact), over :math:`E h` with :math:`w = \sigma_0 h`.
    """
    return -np.sqrt(2 * np.pi * s * rho * A)


def _jkr_pull_off(rho, s):
    r"""JKR pull-off :math:`F/(Eh) = -\frac34 (4\pi s^2\rho)^{1/3}` and its half-width.

    :math:`A = (2s/(\pi\rho))^{1/3}`.
    """
    return -0.75 * np.cbrt(4 * np.pi * s * s * rho), np.cbrt(2 * s / (np.pi * rho))


def _jkr_half_width(F, rho, s):
    r"""The JKR half-width ``A`` on the stable branch at the load ``F/(Eh)`` (arrays broadcast).

    With :math:`u = \sqrt{A}` the load is :math:`a u^4 - b u` (:math:`a = \pi\rho/4`,
    :math:`b = \sqrt{2\pi s\rho}`), convex and increasing beyond the pull-off: Newton from above the
    root converges monotonically. NaN below the pull-off (no JKR contact).
    """
    F, rho, s = np.broadcast_arrays(*(np.asarray(v, float) for v in (F, rho, s)))
    a, b = np.pi * rho / 4, np.sqrt(2 * np.pi * s * rho)
    u_po = np.cbrt(b / (4.0 * a))  # the pull-off, where the load is least
    # a start where a u^4 - b u - F >= 0 and beyond the pull-off
    u = np.maximum(np.sqrt(np.sqrt(2.0 * np.maximum(F, 0.0) / a)), np.cbrt(2.0 * b / a))
    F_po, _ = _jkr_pull_off(rho, s)
    ok = F >= F_po * (1.0 + 1e-12)  # the pull-off itself, give or take round-off
    with np.errstate(divide="ignore", invalid="ignore"):  # no adhesion at zero load: nan
        for _ in range(200):  # quadratic convergence; linear (halving) at the pull-off
            step = np.where(ok, (a * u**4 - b * u - F) / (4.0 * a * u**3 - b), 0.0)
            u = np.maximum(u - step, u_po)
            if np.all(np.abs(step) <= 1e-15 * u):
                break
    return np.where(ok, u * u, np.nan)


def _rigid_pull_off(rho, s):
    r"""Pull-off of a rigid cylinder, Dugdale step: :math:`F/(Eh) = -2\sqrt2\, s \sqrt\rho`.

    The adhesive zone :math:`|x| < \sqrt{2 R h}` of a rigid cylinder touching at a point: the
    DMT-like (small :math:`\kappa`) limit.
    """
    return -2 * math.sqrt(2) * s * np.sqrt(rho)
