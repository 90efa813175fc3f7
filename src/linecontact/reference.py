r"""Closed-form line-contact solutions: Hertz, JKR, Maugis--Dugdale, zero width (Eq. 14).

Units and scaling (stated once for the whole library): lengths in units of the cylinder
radius ``R`` (``a/R``, ``c/R``), the force per unit length in units of ``E h``
(``F/(E h)``), stresses in units of the composite modulus ``E`` (``sigma0/E``), with
``1/E = (1 - nu1**2)/E1 + (1 - nu2**2)/E2`` and ``h`` the range of the Dugdale stress
``sigma0`` (work of adhesion ``w = sigma0 h``). Compressive pressure and compressive load are
positive, so adhesive (pull-off) forces are negative.

Maugis--Dugdale line contact
----------------------------
With ``m = c/a = cosh(u)`` the bounded contact pressure is

.. math::

    p(x) = \frac{E}{2R}\sqrt{a^2 - x^2}
           - \frac{2\sigma_0}{\pi}\arctan\sqrt{\frac{c^2 - a^2}{a^2 - x^2}}, \quad |x| < a,

and :math:`p = -\sigma_0` for :math:`a < |x| < c`. Equilibrium and the separation
:math:`h` at :math:`x = c` give (Baney & Hui 1997, Eqs. 22--23; Johnson & Greenwood 2008)

.. math::

    F = \frac{\pi E a^2}{4R} - 2\sigma_0\sqrt{c^2 - a^2}, \qquad
    h = \frac{a^2}{2R}\,f_1(u) + \frac{4\sigma_0 a}{\pi E}\,f_2(u),

:math:`f_1 = \sinh u\cosh u - u`, :math:`f_2 = u\sinh u - \cosh u\ln\cosh u`.

The whole family depends on one group: with :math:`\bar a = (a/R)\sqrt{R/(2h)}` and
:math:`\kappa = (4/\pi)(\sigma_0/E)\sqrt{2R/h}` the separation condition reads
:math:`\bar a^2 f_1 + \kappa\bar a f_2 = 1` and :math:`F/(Eh) = (\pi/2)(\bar a^2 -
\kappa\bar a\sinh u)`. The load has exactly one stationary point along the contact branch,
at the ``u`` where :math:`\kappa = 2\sinh u/\sqrt{L^2 f_1 + 2L\sinh u\,f_2}`,
:math:`L = \ln\cosh u` (see ``docs/derivations.md``), a decreasing function of ``u`` from
infinity to zero; this makes the pull-off search a bracketed one-dimensional root.

All functions here are evaluated in forms scaled by :math:`e^{-u}` so that they neither
overflow for vanishing contact width (``u -> inf``) nor cancel near the JKR end
(``u -> 0``).

References
----------
J. M. Baney, C.-Y. Hui, "A cohesive zone model for the adhesion of cylinders",
J. Adhesion Sci. Technol. 11 (1997) 393--406. doi:10.1163/156856197X00796
K. L. Johnson, J. A. Greenwood, "A Maugis analysis of adhesive line contact",
J. Phys. D: Appl. Phys. 41 (2008) 155315. doi:10.1088/0022-3727/41/15/155315
M. K. Chaudhury, T. Weaver, C. Y. Hui, E. J. Kramer, "Adhesive contact of cylindrical lens
and a flat sheet", J. Appl. Phys. 80 (1996) 30--37 (JKR line contact). doi:10.1063/1.362819
K. L. Johnson, *Contact Mechanics*, Cambridge University Press (1985), Sec. 4.3 (Hertz line
contact). doi:10.1017/CBO9781139171731
"""

from __future__ import annotations

import warnings

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ._validation import broadcast, non_negative, out, positive, scalar_or_array
from .errors import ModelValidityWarning

__all__ = [
    "A_OVER_R_SMALL_STRAIN",
    "KAPPA_MAX",
    "hertz_load",
    "jkr_load",
    "kappa",
    "maugis_parameter",
    "zero_width_load",
]

LN2 = float(np.log(2.0))

#: Largest ``kappa`` the Maugis--Dugdale solvers accept. Their brackets in
#: ``u = arccosh(c/a)`` reach down to 1e-9 (the pull-off to 1e-10), and the load minimum sits
#: at ``u ~ 2.8 kappa**(-2/3)``: beyond ``kappa ~ 1e13`` the minimum and the contacts near it
#: fall outside, so pull-off forces and contacts for a given load would be wrong.
KAPPA_MAX = 1e12


#: Largest contact half-width over the radius of the small-strain, half-plane theory that
#: every solver uses (Hertz, Eq. 6): the surface strain is about ``p0/E = a/(2R)``, 10 % here.
#: Wider contacts are computed but give a :class:`~linecontact.errors.ModelValidityWarning`.
A_OVER_R_SMALL_STRAIN = 0.2


def _warn_wide(a_over_R: ArrayLike, stacklevel: int = 3) -> None:
    """Warn once per call when a contact is wider than :data:`A_OVER_R_SMALL_STRAIN`."""
    a = np.asarray(a_over_R, dtype=float)
    with np.errstate(invalid="ignore"):
        wide = a > A_OVER_R_SMALL_STRAIN
    if np.any(wide):
        warnings.warn(
            f"a_over_R = {float(np.max(a[wide])):.3g} is beyond the small-strain range of the "
            f"half-plane theory (a/R <= {A_OVER_R_SMALL_STRAIN:g}, strain a/(2R) <= "
            f"{A_OVER_R_SMALL_STRAIN / 2:g}): the results are those of linear elasticity",
            ModelValidityWarning,
            stacklevel=stacklevel,
        )


def _check_kappa(rho: NDArray, s: NDArray, rho_name: str = "R_over_h") -> None:
    """Refuse parameter points beyond :data:`KAPPA_MAX`, naming both parameters."""
    with np.errstate(over="ignore"):
        kap = (4 / np.pi) * s * np.sqrt(2 * rho)
    bad = ~(kap <= KAPPA_MAX)
    if np.any(bad):
        i = int(np.flatnonzero(np.reshape(bad, -1))[0])
        pick = [float(np.reshape(v, -1)[i if np.size(v) > 1 else 0]) for v in (kap, rho, s)]
        raise ValueError(
            f"kappa = (4/pi) sigma0_over_E sqrt(2 {rho_name}) must be <= {KAPPA_MAX:g} (the "
            f"range of the solvers), got kappa={pick[0]:.3g} at {rho_name}={pick[1]!r}, "
            f"sigma0_over_E={pick[2]!r}"
        )


def _representable(what: str, value: NDArray, **params: NDArray) -> NDArray:
    """``value`` if it is finite everywhere; otherwise say which inputs overflow it."""
    if not np.all(np.isfinite(value)):
        i = int(np.flatnonzero(~np.isfinite(np.reshape(value, -1)))[0])
        at = ", ".join(
            f"{k}={float(np.reshape(v, -1)[i if np.size(v) > 1 else 0])!r}"
            for k, v in params.items()
        )
        raise ValueError(f"{what} is beyond the floating-point range at {at}")
    return value


# --------------------------------------------------------------------------------------------
# groups


def kappa(R_over_h: ArrayLike, sigma0_over_E: ArrayLike) -> NDArray | float:
    r"""The single group of the Maugis--Dugdale line contact.

    :math:`\kappa = (4/\pi)(\sigma_0/E)\sqrt{2R/h}`.

    Small :math:`\kappa` is the DMT-like (rigid, long-range) end, large :math:`\kappa` the
    JKR-like (compliant, short-range) end. :math:`\kappa = \lambda^{3/2}/\sqrt2`
    with :math:`\lambda` of :func:`maugis_parameter`.
    """
    rho = positive("R_over_h", R_over_h)
    s = non_negative("sigma0_over_E", sigma0_over_E)
    rho, s = broadcast(R_over_h=rho, sigma0_over_E=s)
    with np.errstate(over="ignore"):
        val = (4 / np.pi) * s * np.sqrt(2 * rho)
    val = _representable("kappa", val, R_over_h=rho, sigma0_over_E=s)
    return out(val, scalar_or_array(rho, s))


def maugis_parameter(R_over_h: ArrayLike, sigma0_over_E: ArrayLike) -> NDArray | float:
    r"""Baney & Hui's Tabor-like parameter for line contact.

    :math:`\lambda = 4\sigma_0 (R/(\pi^2 E^2 w))^{1/3}`.

    With :math:`w = \sigma_0 h`: :math:`\lambda = (4/\pi^{2/3})(\sigma_0/E)^{2/3}(R/h)^{1/3}`.
    DMT-like for :math:`\lambda \lesssim 0.1`, JKR-like for :math:`\lambda \gtrsim 5`.
    """
    rho = positive("R_over_h", R_over_h)
    s = non_negative("sigma0_over_E", sigma0_over_E)
    rho, s = broadcast(R_over_h=rho, sigma0_over_E=s)
    with np.errstate(over="ignore"):
        val = 4 / np.pi ** (2 / 3) * s ** (2 / 3) * rho ** (1 / 3)
    val = _representable("the Maugis parameter", val, R_over_h=rho, sigma0_over_E=s)
    return out(val, scalar_or_array(rho, s))


# --------------------------------------------------------------------------------------------
# Hertz, JKR, Eq. 14


def hertz_load(a_over_R: ArrayLike, R_over_h: ArrayLike) -> NDArray | float:
    r"""Hertz line contact, Eq. (13): :math:`F/(Eh) = (\pi/4)(a/R)^2 (R/h)`."""
    A = positive("a_over_R", a_over_R)
    rho = positive("R_over_h", R_over_h)
    A, rho = broadcast(a_over_R=A, R_over_h=rho)
    with np.errstate(over="ignore"):
        val = np.pi / 4 * A * A * rho
    val = _representable("the Hertz load", val, a_over_R=A, R_over_h=rho)
    return out(val, scalar_or_array(A, rho))


def jkr_load(a_over_R: ArrayLike, R_over_h: ArrayLike, sigma0_over_E: ArrayLike) -> NDArray | float:
    r"""JKR line contact with :math:`w = \sigma_0 h`.

    :math:`F = \pi E a^2/(4R) - \sqrt{2\pi E w a}`, i.e.
    :math:`F/(Eh) = (\pi/4)(a/R)^2(R/h) - \sqrt{2\pi(\sigma_0/E)(R/h)(a/R)}`.
    (Chaudhury et al. 1996; the :math:`m \to 1` limit of the Maugis--Dugdale solution.)
    """
    A = positive("a_over_R", a_over_R)
    rho = positive("R_over_h", R_over_h)
    s = non_negative("sigma0_over_E", sigma0_over_E)
    A, rho, s = broadcast(a_over_R=A, R_over_h=rho, sigma0_over_E=s)
    with np.errstate(over="ignore", invalid="ignore"):
        val = np.pi / 4 * A * A * rho - np.sqrt(2 * np.pi * s * rho * A)
    val = _representable("the JKR load", val, a_over_R=A, R_over_h=rho, sigma0_over_E=s)
    return out(val, scalar_or_array(A, rho, s))


def zero_width_load(R_over_h: ArrayLike, sigma0_over_E: ArrayLike) -> NDArray | float:
    r"""The load at vanishing contact width, Eq. (14) of the paper.

    .. math::

        \frac{F}{Eh} = \frac{8\ln 2}{\pi}\frac{R}{h}\frac{\sigma_0}{E}\left(\frac{\sigma_0}{E}
        - \sqrt{\left(\frac{\sigma_0}{E}\right)^2 + \frac{1}{8}\left(\frac{\pi}{\ln 2}\right)^2
        \frac{h}{R}}\right)

    It is also the most tensile force on the non-contact branch (central gap zero).
    """
    rho = positive("R_over_h", R_over_h)
    s = non_negative("sigma0_over_E", sigma0_over_E)
    rho, s = broadcast(R_over_h=rho, sigma0_over_E=s)
    return out(_zero_width(rho, s), scalar_or_array(rho, s))


def _zero_width(rho: NDArray, s: NDArray) -> NDArray:
    k = (np.pi / LN2) ** 2 / (8 * rho)
    # s - sqrt(s^2 + k) written without cancellation, and without overflow of s^2 (hypot)
    # or of rho s k (rho k is a constant)
    return -(8 * LN2 / np.pi) * ((np.pi / LN2) ** 2 / 8) * s / (s + np.hypot(s, np.sqrt(k)))


# --------------------------------------------------------------------------------------------
# scaled elementary functions of u = arccosh(c/a)


def _scaled(u: NDArray) -> dict[str, NDArray]:
    """Overflow-free pieces: ``F1 = 4 e^{-2u} f1``, ``F2 = 2 e^{-u} f2``, ``St = 2e^{-u} sinh u``.

    Also ``Ct = 2 e^{-u} cosh u``, ``L = ln cosh u`` and the exponential ``q = e^{-2u}``.
    """
    u = np.asarray(u, dtype=float)
    q = np.exp(-2 * u)
    St = -np.expm1(-2 * u)
    Ct = 1 + q
    small = u < 1.0
    us = np.where(small, u, 0.0)
    # L = ln cosh u
    L = np.where(small, np.log1p(2 * np.sinh(us / 2) ** 2), u + np.log1p(q) - LN2)
    # f1 = sinh u cosh u - u = sum_{k>=1} 4^k u^(2k+1)/(2k+1)!  (series below u = 1)
    term = us**3 * (4.0 / 6.0)
    f1s = term.copy()
    for k in range(2, 30):
        term = term * 4 * us * us / ((2 * k) * (2 * k + 1))
        f1s = f1s + term
    F1 = np.where(small, 4 * q * f1s, 1 - q * q - 4 * u * q)
    F2 = u * St - Ct * L
    return {"q": q, "St": St, "Ct": Ct, "L": L, "F1": F1, "F2": F2}


def _x_of_u(kap: NDArray, p: dict[str, NDArray]) -> NDArray:
    """X = abar e^u / 2 solving X^2 F1 + kappa X F2 = 1."""
    F1, F2 = p["F1"], p["F2"]
    return 2.0 / (kap * F2 + np.sqrt(kap * kap * F2 * F2 + 4 * F1))


def _branch_point(u: NDArray, kap: NDArray) -> dict[str, NDArray]:
    """Everything along the contact branch at parameter u, for group kappa (scaled units).

    Returns abar, Phi = (2/pi) F/(Eh), d ln(abar)/du and dPhi/du.
    """
    p = _scaled(u)
    X = _x_of_u(kap, p)
    e = np.exp(-np.asarray(u, dtype=float))
    abar = 2 * X * e
    phi = 4 * X * X * e * e - kap * X * p["St"]
    # d ln abar / du = -(X St^2 + kappa (u Ct - St L)/2) / (X F1 + kappa F2/2)
    dln = -(X * p["St"] ** 2 + kap * (u * p["Ct"] - p["St"] * p["L"]) / 2) / (
        X * p["F1"] + kap * p["F2"] / 2
    )
    # dPhi/du = 2 abar^2 dln - kappa X (dln St + Ct); the load falls as u grows (a shrinks)
    # on the stable part of the branch, where dPhi/du < 0
    dphi = 2 * abar * abar * dln - kap * X * (dln * p["St"] + p["Ct"])
    return {"abar": abar, "phi": phi, "X": X, "dln": dln, "dphi": dphi, **p}


def _kappa_stationary(u: NDArray) -> NDArray:
    """Kappa at which the load is stationary at u: 2 St / sqrt(L^2 F1 + 2 L St F2)."""
    p = _scaled(u)
    L = p["L"]
    return 2 * p["St"] / np.sqrt(L * L * p["F1"] + 2 * L * p["St"] * p["F2"])


def _u_of_abar(
    abar: NDArray, kap: NDArray, *, maxiter: int = 60
) -> tuple[NDArray, NDArray, NDArray]:
    """Solve abar(u; kappa) = abar for u by bracketed Newton in w = ln u.

    Returns (u, separation residual (gap at c minus h, over h), iterations used).
    """
    abar, kap = np.broadcast_arrays(np.asarray(abar, float), np.asarray(kap, float))
    target = np.log(abar)
    w_lo = np.full(abar.shape, np.log(1e-9))
    w_hi = np.full(abar.shape, np.log(750.0))
    # initial guess from the two asymptotes
    X_inf = 2.0 / (kap * LN2 + np.sqrt(kap * kap * LN2 * LN2 + 4))
    u_large = np.log(np.maximum(2 * X_inf / abar, 1.0 + 1e-12))
    # small u: (2/3) abar^2 u^3 + kappa abar u^2 / 2 = 1  -> take the larger of the two roots
    with np.errstate(over="ignore", divide="ignore"):  # abar**2 under/overflows at the ends
        u_small = np.minimum(
            (1.5 / abar**2) ** (1 / 3), np.sqrt(2.0 / np.maximum(kap * abar, 1e-300))
        )
    u0 = np.clip(np.where(u_large > 1.0, u_large, u_small), 1e-9, 700.0)
    w = np.log(u0)
    it = np.zeros(abar.shape, dtype=int)
    active = np.ones(abar.shape, dtype=bool)
    for k in range(maxiter):
        u = np.exp(w)
        bp = _branch_point(u, kap)
        r = np.log(bp["abar"]) - target  # decreasing in w
        w_lo = np.where(r > 0, w, w_lo)
        w_hi = np.where(r <= 0, w, w_hi)
        dr = bp["dln"] * u
        with np.errstate(divide="ignore", invalid="ignore"):
            w_new = w - r / dr
        bad = ~np.isfinite(w_new) | (w_new < w_lo) | (w_new > w_hi)
        w_new = np.where(bad, 0.5 * (w_lo + w_hi), w_new)
        done = np.abs(r) <= 2e-16
        w_new = np.where(done, w, w_new)
        step = np.abs(w_new - w)
        it = np.where(active, k + 1, it)
        w = np.where(active, w_new, w)
        active = active & ~done & (step > 1e-15 * np.maximum(1.0, np.abs(w)))
        if not active.any():
            break
    u = np.exp(w)
    # separation residual (gap(c) - gap(a))/h - 1 = abar^2 f1 + kappa abar f2 - 1 at the
    # given abar, in the scaled form (Y = abar e^u / 2)
    p = _scaled(u)
    Y = abar * np.exp(np.minimum(u, 700.0)) / 2
    res = np.abs(Y * Y * p["F1"] + kap * Y * p["F2"] - 1)
    return u, res, it


def _u_stationary(kap: NDArray) -> NDArray:
    """The u of the single load minimum for group kappa > 0 (bisection in ln u, monotone)."""
    kap = np.asarray(kap, dtype=float)
    lo = np.full(kap.shape, np.log(1e-10))  # kappa_s(lo) > kappa
    hi = np.full(kap.shape, np.log(1e9))
    for _ in range(90):
        mid = 0.5 * (lo + hi)
        above = _kappa_stationary(np.exp(mid)) > kap
        lo = np.where(above, mid, lo)
        hi = np.where(above, hi, mid)
    return np.exp(0.5 * (lo + hi))
