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

import math
import warnings

import numpy as np
from numpy.typing import ArrayLike, NDArray

from . import domain as _domain
from ._validation import broadcast, first_point, out, point_text, scalar_or_array
from .errors import ModelValidityWarning

__all__ = [
    "A_OVER_R_SMALL_STRAIN",
    "KAPPA_MAX",
    "hertz_load",
    "jkr_load",
    "kappa",
    "lennard_jones_rigid_load",
    "lennard_jones_rigid_pull_off",
    "maugis_parameter",
    "zero_width_load",
]

LN2 = float(np.log(2.0))

#: Largest ``kappa`` the Maugis--Dugdale solvers accept. Their brackets in
#: ``u = arccosh(c/a)`` reach down to 1e-60 (the pull-off to 1e-10), and the load minimum sits
#: at ``u ~ 2.8 kappa**(-2/3)``: beyond ``kappa ~ 1e13`` the minimum and the contacts near it
#: fall outside, so pull-off forces and contacts for a given load would be wrong.
KAPPA_MAX = 1e12


#: Largest contact half-width over the radius of the small-strain, half-plane theory that
#: every solver uses (Hertz, Eq. 6): the surface strain is about ``p0/E = a/(2R)``, 10 % here.
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


def _representable(what: str, value: NDArray, **params: NDArray) -> NDArray:
    """``value`` if it is finite everywhere; otherwise say which inputs overflow it."""
    if not np.all(np.isfinite(value)):
        _, at = first_point(~np.isfinite(value), **params)
        raise ValueError(f"{what} is beyond the floating-point range at {point_text(at)}")
    return value


# --------------------------------------------------------------------------------------------
# groups


def _kappa(rho, s):
    """:func:`kappa` of validated inputs: arrays, NumPy scalars or Python floats.

    The one home of the formula: every solver forms ``kappa`` here. A Python float takes
    ``math.sqrt`` (fast, and correctly rounded as ``np.sqrt``: the same bits).
    """
    return (4 / np.pi) * s * (math.sqrt(2 * rho) if type(rho) is float else np.sqrt(2 * rho))


def _maugis_parameter(rho, s):
    """:func:`maugis_parameter` of validated inputs (arrays or NumPy scalars)."""
    return 4 / np.pi ** (2 / 3) * s ** (2 / 3) * rho ** (1 / 3)


def kappa(R_over_h: ArrayLike, sigma0_over_E: ArrayLike) -> NDArray | float:
    r"""The single group of the Maugis--Dugdale line contact.

    :math:`\kappa = (4/\pi)(\sigma_0/E)\sqrt{2R/h}`.

    Small :math:`\kappa` is the DMT-like (rigid, long-range) end, large :math:`\kappa` the
    JKR-like (compliant, short-range) end. :math:`\kappa = \lambda^{3/2}/\sqrt2`
    with :math:`\lambda` of :func:`maugis_parameter`.
    """
    rho = _domain.check("R_over_h", R_over_h)
    s = _domain.check("sigma0_over_E", sigma0_over_E)
    rho, s = broadcast(R_over_h=rho, sigma0_over_E=s)
    with np.errstate(over="ignore"):
        val = _kappa(rho, s)
    val = _representable("kappa", val, R_over_h=rho, sigma0_over_E=s)
    return out(val, scalar_or_array(rho, s))


def maugis_parameter(R_over_h: ArrayLike, sigma0_over_E: ArrayLike) -> NDArray | float:
    r"""Baney & Hui's Tabor-like parameter for line contact.

    :math:`\lambda = 4\sigma_0 (R/(\pi^2 E^2 w))^{1/3}`.

    With :math:`w = \sigma_0 h`: :math:`\lambda = (4/\pi^{2/3})(\sigma_0/E)^{2/3}(R/h)^{1/3}`.
    DMT-like for :math:`\lambda \lesssim 0.1`, JKR-like for :math:`\lambda \gtrsim 5`.
    """
    rho = _domain.check("R_over_h", R_over_h)
    s = _domain.check("sigma0_over_E", sigma0_over_E)
    rho, s = broadcast(R_over_h=rho, sigma0_over_E=s)
    with np.errstate(over="ignore"):
        val = _maugis_parameter(rho, s)
    val = _representable("the Maugis parameter", val, R_over_h=rho, sigma0_over_E=s)
    return out(val, scalar_or_array(rho, s))


# --------------------------------------------------------------------------------------------
# Hertz, JKR, Eq. 14


def hertz_load(a_over_R: ArrayLike, R_over_h: ArrayLike) -> NDArray | float:
    r"""Hertz line contact, Eq. (13): :math:`F/(Eh) = (\pi/4)(a/R)^2 (R/h)`."""
    A = _domain.check("a_over_R", a_over_R)
    rho = _domain.check("R_over_h", R_over_h)
    A, rho = broadcast(a_over_R=A, R_over_h=rho)
    with np.errstate(over="ignore"):
        val = _hertz(A, rho)
    val = _representable("the Hertz load", val, a_over_R=A, R_over_h=rho)
    return out(val, scalar_or_array(A, rho))


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


# --------------------------------------------------------------------------------------------
# the closed forms of Hertz, JKR and the rigid (DMT-like) cylinder, once, in the paper's groups
#
# ``A = a/R``, ``rho = R/h``, ``s = sigma0/E``, loads over ``E h``. Hertz and JKR have no range:
# any length ``h`` and stress ``sigma0`` with ``w = sigma0 h`` give the same physics, so the
# forms in SI units (:mod:`linecontact.inverse`, ``h = R``) and in the Lennard-Jones law's
# units (:mod:`linecontact.adhesion_map`, ``h = z0``, ``rho = 1``, ``s = mu``) scale these.


def _hertz(A, rho):
    """Hertz line contact, Eq. (13): ``F/(Eh) = (pi/4) A^2 rho``."""
    return np.pi / 4 * A * A * rho


def _hertz_half_width(F, rho):
    """The inverse of :func:`_hertz`: ``A = sqrt(4 F/(pi rho))``, 0 for ``F <= 0``."""
    return np.sqrt(4.0 * np.maximum(F, 0.0) / (np.pi * rho))


def _jkr(A, rho, s):
    """JKR line contact: ``F/(Eh) = (pi/4) A^2 rho - sqrt(2 pi s rho A)``."""
    return np.pi / 4 * A * A * rho - np.sqrt(2 * np.pi * s * rho * A)


def _jkr_pull_off(rho, s):
    """JKR pull-off ``F/(Eh) = -(3/4)(4 pi s^2 rho)^(1/3)`` and its ``A = (2 s/(pi rho))^(1/3)``."""
    return -0.75 * np.cbrt(4 * np.pi * s * s * rho), np.cbrt(2 * s / (np.pi * rho))


def _jkr_half_width(F, rho, s):
    """The JKR half-width ``A`` on the stable branch at the load ``F/(Eh)`` (arrays broadcast).

    With ``u = sqrt(A)`` the load is ``a u^4 - b u`` (``a = pi rho/4``, ``b = sqrt(2 pi s
    rho)``), convex and increasing beyond the pull-off: Newton from above the root converges
    monotonically. NaN below the pull-off (no JKR contact).
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
    """Pull-off of a rigid cylinder under the Dugdale step: ``F/(Eh) = -2 sqrt(2) s sqrt(rho)``.

    The adhesive zone ``|x| < sqrt(2 R h)`` of a rigid cylinder touching at a point: the
    DMT-like (small ``kappa``) limit.
    """
    return -2 * math.sqrt(2) * s * np.sqrt(rho)


def _zero_width(rho: NDArray, s: NDArray) -> NDArray:
    k = (np.pi / LN2) ** 2 / (8 * rho)
    # s - sqrt(s^2 + k) written without cancellation, and without overflow of s^2 (hypot)
    # or of rho s k (rho k is a constant)
    return -(8 * LN2 / np.pi) * ((np.pi / LN2) ** 2 / 8) * s / (s + np.hypot(s, np.sqrt(k)))


# --------------------------------------------------------------------------------------------
# elementwise kernels and their per-point iteration
#
# The kernels below take either NumPy arrays (any shape) or NumPy scalars (``np.float64``):
# a scalar call of the public functions runs the very same code on scalars, where an
# arithmetic operation costs ~60 ns and an elementary function ~0.2 us instead of ~0.5 us on
# a 0-d array, and ``np.where`` (~2.5 us on 0-d arrays) is replaced by a plain conditional
# (:func:`_where`). A point gives the same answer alone and in a batch to rounding, not
# always to the bit: on some CPUs (AVX-512) NumPy's SIMD loops for ``exp``/``log`` on arrays
# round differently from its scalar code (README, "Same answers on every machine"). And
# ``x ** 2`` is pow() for a scalar but a product for an array: the kernels square by
# multiplying.


def _where(cond, a, b):
    """``np.where(cond, a, b)``; a plain conditional when ``cond`` is a scalar.

    Both ``a`` and ``b`` have been evaluated by the caller either way, so the two forms give
    the same values (and the same floating-point warnings).
    """
    if isinstance(cond, (bool, np.bool_)):
        return a if cond else b
    return np.where(cond, a, b)


def _minimum(a, b):
    """``np.minimum(a, b)`` (nan wins), as a NumPy scalar without a ufunc call for scalars."""
    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        return np.minimum(a, b)
    return np.float64(a if (a <= b or a != a) else b)


def _maximum(a, b):
    """``np.maximum(a, b)`` (nan wins), as a NumPy scalar without a ufunc call for scalars."""
    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        return np.maximum(a, b)
    return np.float64(a if (a >= b or a != a) else b)


def _is_scalar(*values) -> bool:
    """True when every value is a scalar (Python or NumPy, or a 0-d array)."""
    return all(np.ndim(v) == 0 for v in values)


def _scalars(*values):
    """0-d arrays (and Python numbers) as ``np.float64`` scalars, for the scalar fast path."""
    return tuple(np.float64(v) for v in values)


def _full(like, value: float):
    """``value`` with the shape of ``like``: a NumPy scalar for a scalar ``like``."""
    return np.full(like.shape, value) if isinstance(like, np.ndarray) else np.float64(value)


def _iterate(step, state: tuple, params: tuple, maxiter: int, done=None):
    """Iterate ``state, stop = step(*state, *params)`` per point until it stops.

    ``state`` and ``params`` are tuples of NumPy scalars, or of 1-D arrays of one length. A point
    whose ``stop`` is true leaves the loop at once: later iterations work only on the
    points still active (so one point that converges slowly, or never, costs the work of one
    point, not that of the whole batch), and a point that reaches ``maxiter`` keeps its last
    state; the caller checks its residual.

    ``done`` (optional) marks the points that need no iteration at all.

    Returns
    -------
    state : tuple
        The final state of every point (scalars, or new arrays).
    iterations : int or ndarray of int
        Iterations used per point.
    """
    if not isinstance(state[0], np.ndarray):
        if done:
            return state, 0
        for k in range(1, maxiter + 1):  # noqa: B007 (k is the count returned)
            state, stop = step(*state, *params)
            if stop:
                return state, k
        return state, maxiter
    out = [np.array(v, dtype=float) for v in state]
    its = np.full(out[0].shape, maxiter)
    idx = np.arange(out[0].size)
    cur, par = state, params
    if done is not None:
        its[done] = 0
        idx = idx[~done]
        if idx.size == 0:
            return tuple(out), its
        cur = tuple(v[idx] for v in cur)
        par = tuple(p[idx] for p in par)
    for k in range(1, maxiter + 1):
        cur, stop = step(*cur, *par)
        if k == maxiter or stop.all():
            for o, v in zip(out, cur, strict=True):
                o[idx] = v
            its[idx[stop]] = k
            break
        if stop.any():
            fin = idx[stop]
            for o, v in zip(out, cur, strict=True):
                o[fin] = v[stop]
            its[fin] = k
            keep = ~stop
            idx = idx[keep]
            cur = tuple(v[keep] for v in cur)
            par = tuple(p[keep] for p in par)
    return tuple(out), its


# --------------------------------------------------------------------------------------------
# scaled elementary functions of u = arccosh(c/a)

#: f1(u) = sinh u cosh u - u = u^3 sum_{k>=1} c_k (u^2)^(k-1), c_k = 4^k/(2k+1)!, used below
#: u = 1 (where the closed form cancels); twelve terms leave a truncation of ~1e-20 relative.
#: (int / int is correctly rounded in Python: each c_k is the double nearest to it.)
_F1_SERIES = tuple(4**k / math.factorial(2 * k + 1) for k in range(12, 0, -1))


def _f1_series(u):
    """The series of f1 = sinh u cosh u - u (Horner, highest power first); for |u| <= 1."""
    x = u * u
    acc = _F1_SERIES[0]
    for c in _F1_SERIES[1:]:
        acc = acc * x + c
    return acc * (x * u)


def _small_u(u, q):
    """``L = ln cosh u`` and ``F1`` below u = 1: by series, where 1 - q^2 - 4uq cancels."""
    sh = np.sinh(u / 2)
    return np.log1p(2 * sh * sh), 4 * q * _f1_series(u)


def _large_u(u, q):
    """``L`` and ``F1`` from u = 1 on (no overflow as u -> inf)."""
    return u + np.log1p(q) - LN2, 1 - q * q - 4 * u * q


def _scaled(u: NDArray) -> dict[str, NDArray]:
    """Overflow-free pieces: ``F1 = 4 e^{-2u} f1``, ``F2 = 2 e^{-u} f2``, ``St = 2e^{-u} sinh u``.

    Also ``Ct = 2 e^{-u} cosh u``, ``L = ln cosh u`` and the exponential ``q = e^{-2u}``.
    ``u`` is an array or a NumPy scalar (see :func:`_where`); a scalar evaluates only the
    branch (series or not) that it takes.
    """
    q = np.exp(-2 * u)
    St = -np.expm1(-2 * u)
    Ct = 1 + q
    small = u < 1.0
    if isinstance(small, np.ndarray):
        Ls, F1s = _small_u(np.where(small, u, 0.0), q)  # no overflow of the series at large u
        Ll, F1l = _large_u(u, q)
        L = np.where(small, Ls, Ll)
        F1 = np.where(small, F1s, F1l)
    else:
        L, F1 = _small_u(u, q) if small else _large_u(u, q)
    F2 = u * St - Ct * L
    return {"q": q, "St": St, "Ct": Ct, "L": L, "F1": F1, "F2": F2}


def _x_of_u(kap: NDArray, p: dict[str, NDArray]) -> NDArray:
    """X = abar e^u / 2 solving X^2 F1 + kappa X F2 = 1."""
    F1, F2 = p["F1"], p["F2"]
    kF2 = kap * F2
    return 2.0 / (kF2 + np.sqrt(kF2 * kF2 + 4 * F1))


def _abar_dln(u, kap, p):
    """X, e^{-u}, abar and d ln(abar)/du at u, from the pieces ``p`` of :func:`_scaled`."""
    X = _x_of_u(kap, p)
    e = np.exp(-u)
    St = p["St"]
    abar = 2 * X * e
    # d ln abar / du = -(X St^2 + kappa (u Ct - St L)/2) / (X F1 + kappa F2/2)
    dln = -(X * St * St + kap * (u * p["Ct"] - St * p["L"]) / 2) / (X * p["F1"] + kap * p["F2"] / 2)
    return X, e, abar, dln


def _branch_point(u: NDArray, kap: NDArray) -> dict[str, NDArray]:
    """Everything along the contact branch at parameter u, for group kappa (scaled units).

    Returns abar, Phi = (2/pi) F/(Eh), d ln(abar)/du and dPhi/du.
    """
    p = _scaled(u)
    X, e, abar, dln = _abar_dln(u, kap, p)
    St = p["St"]
    kX = kap * X
    phi = 4 * X * X * e * e - kX * St
    # dPhi/du = 2 abar^2 dln - kappa X (dln St + Ct); the load falls as u grows (a shrinks)
    # on the stable part of the branch, where dPhi/du < 0
    dphi = 2 * abar * abar * dln - kX * (dln * St + p["Ct"])
    return {"abar": abar, "phi": phi, "X": X, "dln": dln, "dphi": dphi, **p}


def _kappa_stationary(u: NDArray) -> NDArray:
    """Kappa at which the load is stationary at u: 2 St / sqrt(L^2 F1 + 2 L St F2)."""
    p = _scaled(np.asarray(u, dtype=float))
    L = p["L"]
    return 2 * p["St"] / np.sqrt(L * L * p["F1"] + 2 * L * p["St"] * p["F2"])


# --------------------------------------------------------------------------------------------
# the contact branch at a given width


_W_LO = float(np.log(1e-60))  # bracket of _u_of_abar in w = ln u (c - a ~ u^2 a / 2)
_W_HI = float(np.log(750.0))


def _abar_step(w, lo, hi, prev, target, kap):
    """One bracketed Newton step of ln abar(u) = target in w = ln u (errors ignored by caller).

    ``prev`` is the size of the previous Newton step (0 after any other step).
    """
    u = np.exp(w)
    _, _, abar, dln = _abar_dln(u, kap, _scaled(u))
    r = np.log(abar) - target  # decreasing in w
    lo = _where(r > 0, w, lo)
    hi = _where(r <= 0, w, hi)
    w_new = w - r / (dln * u)
    # (abs(x) < inf is isfinite(x), also for NumPy scalars, where np.isfinite costs ~0.7 us)
    bad = ~(abs(w_new) < np.inf) | (w_new < lo) | (w_new > hi)
    w_new = _where(bad, 0.5 * (lo + hi), w_new)
    done = abs(r) <= 2e-16
    w_new = _where(done, w, w_new)
    step = abs(w_new - w)
    wmax = _maximum(abs(w_new), 1.0)
    # Newton converges quadratically: with C = step/prev^2 observed over the last two Newton
    # steps, about C step^2 is left after this one; once that is below rounding another
    # evaluation has nothing to add (it saves one of the usual four)
    newton = ~(bad | done)
    quad = newton & (step < prev) & (step * step * step <= 1e-17 * prev * prev * wmax)
    stop = done | (step <= 1e-15 * wmax) | quad
    return (w_new, lo, hi, _where(newton, step, 0.0)), stop


def _u_guess(abar, kap):
    """Initial u for abar(u; kappa) = abar from the asymptotes of the two ends."""
    X_inf = 2.0 / (kap * LN2 + np.sqrt(kap * kap * LN2 * LN2 + 4))
    u_large = np.log(_maximum(2 * X_inf / abar, 1.0 + 1e-12))
    # small u: (2/3) abar^2 u^3 + kappa abar u^2 / 2 = 1  -> take the larger of the two roots
    u_small = _minimum(
        (1.5 / (abar * abar)) ** (1 / 3), np.sqrt(2.0 / _maximum(kap * abar, 1e-300))
    )
    return _minimum(_maximum(_where(u_large > 1.0, u_large, u_small), 1e-9), 700.0)


def _solve_abar(abar, kap, *, maxiter: int = 60):
    """u, separation residual, iterations and the branch point at u (flat arrays or scalars).

    The caller silences the floating-point warnings of the extreme widths (``np.errstate``
    over, divide and invalid; :func:`_u_of_abar` does), as ``normal_contact`` does once for
    all its work (an ``errstate`` costs ~1.5 us, a fair part of a scalar call).
    """
    target = np.log(abar)
    w0 = np.log(_u_guess(abar, kap))
    lo, hi = _full(w0, _W_LO), _full(w0, _W_HI)
    (w, _, _, _), it = _iterate(_abar_step, (w0, lo, hi, _full(w0, 0.0)), (target, kap), maxiter)
    u = np.exp(w)
    bp = _branch_point(u, kap)
    # separation residual (gap(c) - gap(a))/h - 1 = abar^2 f1 + kappa abar f2 - 1 at the
    # given abar, in the scaled form (Y = abar e^u / 2)
    Y = abar * np.exp(_minimum(u, 700.0)) / 2
    res = abs(Y * Y * bp["F1"] + kap * Y * bp["F2"] - 1)
    return u, res, it, bp


def _u_of_abar(
    abar: NDArray, kap: NDArray, *, maxiter: int = 60
) -> tuple[NDArray, NDArray, NDArray]:
    """Solve abar(u; kappa) = abar for u by bracketed Newton in w = ln u.

    Returns (u, separation residual (gap at c minus h, over h), iterations used). Arrays of
    any shape (broadcast together) or scalars; each point stops as soon as it has converged.
    """
    with np.errstate(over="ignore", divide="ignore", invalid="ignore"):
        if _is_scalar(abar, kap):
            u, res, it, _ = _solve_abar(*_scalars(abar, kap), maxiter=maxiter)
            return u, res, it
        abar, kap = np.broadcast_arrays(np.asarray(abar, float), np.asarray(kap, float))
        shape = abar.shape
        u, res, it, _ = _solve_abar(abar.reshape(-1), kap.reshape(-1), maxiter=maxiter)
    return u.reshape(shape), res.reshape(shape), it.reshape(shape)


# --------------------------------------------------------------------------------------------
# the load minimum


_WS_LO = float(np.log(1e-10))  # bracket of _u_stationary in w = ln u: kappa_s(lo) > kappa
_WS_HI = float(np.log(1e9))


def _stationary_step(w, lo, hi, lk):
    """One bracketed Newton step of ln kappa_s(u) = ln kappa in w = ln u.

    With D = L^2 F1 + 2 L St F2 and kappa_s = 2 St / sqrt(D), the derivatives of the scaled
    pieces are St' = 2q, L' = St/Ct, F1' = 2 St^2 - 2 F1 and F2' = 2q (u + L).
    """
    u = np.exp(w)
    p = _scaled(u)
    q, St, L, F1, F2 = p["q"], p["St"], p["L"], p["F1"], p["F2"]
    LSt = L * St
    D = L * L * F1 + 2 * LSt * F2
    g = np.log(2 * St / np.sqrt(D)) - lk  # decreasing in w
    dL = St / p["Ct"]
    dD = (
        2 * L * dL * F1
        + L * L * (2 * St * St - 2 * F1)
        + 2 * (dL * St + 2 * q * L) * F2
        + 4 * LSt * q * (u + L)
    )
    dg = u * (2 * q / St - dD / (2 * D))
    lo = _where(g > 0, w, lo)
    hi = _where(g > 0, hi, w)
    w_new = w - g / dg
    bad = ~np.isfinite(w_new) | (w_new < lo) | (w_new > hi)
    w_new = _where(bad, 0.5 * (lo + hi), w_new)
    done = g == 0
    w_new = _where(done, w, w_new)
    # converged: a step at rounding level, or a bracket shrunk to nothing (a root beyond the
    # bracket's end, for kappa < 2e-9, leaves u at that end, as the bisection did)
    tiny = 1e-15 * np.maximum(1.0, np.abs(w))
    stop = done | (np.abs(w_new - w) <= tiny) | (hi - lo <= tiny)
    return (w_new, lo, hi), stop


def _u_stationary(kap: NDArray | np.float64) -> NDArray | np.float64:
    """The u of the single load minimum for group kappa > 0.

    ``kappa_s(u)`` (:func:`_kappa_stationary`) decreases from infinity (as
    ``2 sqrt(2) u^(-3/2)``) to zero (as ``2/sqrt(u^2 - ln^2 2)``): a bracketed Newton
    iteration in ``w = ln u`` on ``ln kappa_s = ln kappa`` starts from these asymptotes and
    falls back on bisection whenever a step would leave the bracket. Arrays or scalars.
    """
    scalar = _is_scalar(kap)
    shape = np.shape(kap)
    kap = np.float64(kap) if scalar else np.asarray(kap, dtype=float).reshape(-1)
    with np.errstate(over="ignore", divide="ignore", invalid="ignore", under="ignore"):
        u_small = (2 * np.sqrt(2.0) / kap) ** (2 / 3)
        u_large = np.sqrt(4 / (kap * kap) + LN2 * LN2)
        u0 = _where(u_small < 1.0, u_small, u_large)
        w0 = np.minimum(np.maximum(np.log(u0), _WS_LO), _WS_HI)
        lo, hi = _full(w0, _WS_LO), _full(w0, _WS_HI)
        (w, _, _), _ = _iterate(_stationary_step, (w0, lo, hi), (np.log(kap),), 100)
        u = np.exp(w)
    return u if scalar else u.reshape(shape)
