r"""Tangential loading of the line contact: initiation of sliding and steady rolling.

Paper Eqs (15)--(17) (initiation of sliding, Mindlin-type) and Eqs (23)--(29) (steady
rolling, Carter-type), in the uncoupled case ``B = 0`` (Eq 7): the shear tractions do not
change the pressure, so the contact half-width ``a`` is that of the normal problem
(:mod:`linecontact.normal`) and enters here only as the unit of length.

Units and scaling
-----------------
Positions over the contact half-width (``x/a``, ``d/a``), the tangential force per unit
length over ``E a`` (``T/(E a)``), stresses over the composite modulus ``E``
(``tau0/E``, ``q/E``), the creep (rigid slip) velocity over the rolling speed ``V``
(``creep/V``). For Coulomb friction ``T/(mu F)`` is used as well, and ``a/R`` fixes the
Hertz pressure :math:`p_0 = E a/(2R)` (then :math:`T/(Ea) = (\pi/4)\,\mu\,(a/R)\,T/(\mu F)`).

Friction laws
-------------
``constant`` (the paper's nano-scale law, adhesion theory of friction): the shear traction
has the constant magnitude ``tau0`` wherever the surfaces slip; full slip carries
:math:`T = 2a\tau_0`. ``coulomb`` (the macro-scale counterpart, non-adhesive Hertz contact):
magnitude ``mu p(x)``; full slip carries :math:`T = \mu F`.

Sign conventions
----------------
Body 1 is the cylinder, body 2 the substrate, ``x`` along the surface, origin at the contact
centre. ``T >= 0`` is the tangential force per unit length transmitted through the
interface and ``traction(x)`` the shear traction carrying it (positive in the direction of
``T``, its integral over the contact is ``T``, magnitude ``tau0`` or ``mu p`` in the slip
zones). ``docs/tangential.md`` works with ``q``, the traction on the substrate, which is
the traction for the initiation and minus it for rolling.

* **Initiation of sliding**: a force ``T`` pulls the cylinder along ``+x``; the traction is
  the one the cylinder exerts on the substrate. Stick zone :math:`|x| < d`, slip zones
  :math:`d < |x| < a`. The slip :math:`s(x)` is the tangential displacement of the cylinder's
  surface relative to the substrate's surface in a slip zone, measured from the nearer end of
  the stick zone (where it vanishes): :math:`s(x) = \int_d^{|x|}
  \partial(u_x^{(1)} - u_x^{(2)})/\partial x\,dx` ``>= 0``, the cylinder slipping forward.
  (The rigid shift of remote points is not reported: plane strain fixes it only up to a
  logarithmic constant.)
* **Steady rolling**: the cylinder rolls towards ``+x`` at speed ``V`` (the contact moves
  along ``+x``, the leading edge is ``x = +a``) and is the **driving** body (a torque
  turns it, as a locomotive wheel); the substrate exerts the tractive force ``T`` on the
  cylinder along ``+x`` (the cylinder pushes the substrate backwards). Stick zone at the
  leading edge :math:`d < x < a`, slip zone at the trailing edge :math:`-a < x < d`.
  ``creep_over_V`` is :math:`\dot C/V = (V - \omega R)/V`, the velocity of the cylinder's
  rigid surface relative to the substrate in the rolling direction over ``V``: **negative**
  for a driving cylinder, whose circumference runs faster than it advances
  (:math:`\omega R > V`), as the paper says. A braking (driven) cylinder is the mirror image
  (all signs of ``T``, the traction and the creep reversed).

Solvers
-------
``method="closed-form"`` (default) evaluates the closed forms derived in
``docs/tangential.md``; ``method="collocation"`` solves the singular integral equations
(Eq 16 on the stick zone ``(-d, d)``; Eq 27 on ``(d, a)``, whose extra consistency equation
gives the creep) with :class:`linecontact.sie.BoundedSolver`, choosing the number of nodes
per point. The two agree to ~1e-14 (``benchmarks/tangential.py``).

Closed forms (constant ``tau0``; :math:`\delta = d/a`):

.. math::

    \text{initiation:}\quad \frac{T}{2a\tau_0} = \sqrt{1 - \delta^2},\qquad
    \mathrm{traction} = \frac{2\tau_0}{\pi}\arctan\sqrt{\frac{a^2 - d^2}{d^2 - x^2}}
    \ (|x| < d),

    \text{rolling:}\quad \frac{T}{2a\tau_0} = \sqrt{\frac{1 + \delta}{2}},\qquad
    \frac{\dot C}{V} = -\frac{4\tau_0}{\pi E}\,\operatorname{artanh}\frac{T}{2a\tau_0},\qquad
    \mathrm{traction} = \frac{2\tau_0}{\pi}\arctan\sqrt{\frac{(a + d)(a - x)}{2a(x - d)}}
    \ (d < x < a).

Coulomb: Cattaneo--Mindlin :math:`T/(\mu F) = 1 - \delta^2`; Carter
:math:`T/(\mu F) = 1 - ((1 - \delta)/2)^2`, :math:`\dot C/V = -(\mu a/R)(1 + \delta)/2`.

References
----------
F. W. Carter, "On the action of a locomotive driving wheel", Proc. R. Soc. Lond. A 112
(1926) 151--157. doi:10.1098/rspa.1926.0100
R. D. Mindlin, "Compliance of elastic bodies in contact", J. Appl. Mech. 16 (1949)
259--268. doi:10.1115/1.4009973
C. Cattaneo, "Sul contatto di due corpi elastici: distribuzione locale degli sforzi",
Rend. Accad. Naz. Lincei 27 (1938) 342--348, 434--436, 474--478.
K. L. Johnson, *Contact Mechanics*, Cambridge University Press (1985), Ch. 7
(Cattaneo--Mindlin) and Ch. 8 (Carter). doi:10.1017/CBO9781139171731
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from functools import lru_cache

import numpy as np
import scipy.special
from numpy.typing import ArrayLike, NDArray

from ._validation import (
    broadcast,
    check_array,
    check_solver_options,
    non_negative,
    positions,
    positive,
    scalar_or_array,
)
from .errors import ConvergenceError, NoEquilibriumError
from .normal import _as_output, _Result
from .sie import BoundedSolver, _log_moment_vector

__all__ = [
    "CoulombRolling",
    "CoulombSlidingInitiation",
    "CylinderTangential",
    "SlidingInitiation",
    "SteadyRolling",
    "cylinder_sliding_initiation",
    "cylinder_steady_rolling",
    "sliding_initiation",
    "sliding_initiation_coulomb",
    "steady_rolling",
    "steady_rolling_coulomb",
]

#: Collocation sizes tried by ``n="auto"`` (the largest bounds the work per point).
SIZES = (16, 24, 32, 48, 64, 96, 128, 192, 256, 384, 512, 768, 1024, 1536, 2048, 3072,
         4096, 6144, 8192)
#: Nodes used for the Coulomb problems (their right-hand sides are linear: exact for n >= 2).
N_COULOMB = 8
_N_CHECK = 16  # points of the stick zone where the stick condition is re-evaluated
_CHECK_THETA = np.pi * (np.arange(_N_CHECK) + 0.25) / _N_CHECK
_CHECK_Y = np.cos(_CHECK_THETA)
_FORCE_TOL = 1e-12  # Newton tolerance on T (relative to the full-slip load)

_STICK = "stick"
_STICK_SLIP = "stick-slip"
_SLIDING = "sliding"


# --------------------------------------------------------------------------------------------
# input checks


def _check_options(method, n, tol, raise_on_failure, on_sliding):
    if method not in ("closed-form", "collocation"):
        raise ValueError(f"method must be 'closed-form' or 'collocation', got {method!r}")
    check_solver_options(n, tol, raise_on_failure, n_max=SIZES[-1])
    if on_sliding not in ("report", "raise"):
        raise ValueError(f"on_sliding must be 'report' or 'raise', got {on_sliding!r}")


def _one_of(d_over_a, load, load_name: str) -> None:
    if (d_over_a is None) == (load is None):
        raise ValueError(f"give exactly one of d_over_a or {load_name}")


# --------------------------------------------------------------------------------------------
# collocation plumbing


@lru_cache(maxsize=32)
def _solver(n: int) -> BoundedSolver:
    return BoundedSolver(n)


@lru_cache(maxsize=32)
def _check_matrix(n: int) -> NDArray:
    """cos((j+1) theta_c): the Hilbert transform -sum_j b_j T_{j+1} at the check points."""
    m = np.cos(np.arange(1, n + 1)[:, None] * _CHECK_THETA[None, :])
    m.setflags(write=False)
    return m


def _tail(b: NDArray) -> NDArray:
    """Chebyshev tail: the largest of the last three coefficients over the largest one.

    The coefficients are in units of the friction stress (``tau0`` or ``mu p0``); a solution
    much smaller than that (a short stick zone) is measured against it instead, so that
    round-off in a tiny solution does not count as truncation error.
    """
    big = np.maximum(np.max(np.abs(b), axis=-1), 1.0)
    return np.max(np.abs(b[..., -3:]), axis=-1) / big


def _adaptive(kernel, delta: NDArray, rate: NDArray, n, tol: float) -> dict[str, NDArray]:
    """Run ``kernel(delta, n)`` per point with ``n`` chosen for ``tol``.

    The right-hand sides have logarithmic sources a distance ``cosh(rate)`` (in units of the
    interval's half-length) from the interval's centre, so the Chebyshev coefficients fall
    like ``exp(-rate j)``: start at the smallest size with ``exp(-rate n) <= tol`` and move
    points whose tail still exceeds ``tol`` one size up.
    """
    P = delta.size
    sizes = np.asarray(SIZES)
    if n == "auto":
        need = np.log(1.0 / tol) / np.maximum(rate, 1e-300)
        k = np.minimum(np.searchsorted(sizes, need), sizes.size - 1)
        nsel = sizes[k]
    else:
        nsel = np.full(P, int(n))
    out: dict[str, NDArray] = {}
    pending = np.ones(P, bool)
    while pending.any():
        for nn in np.unique(nsel[pending]):
            idx = np.flatnonzero(pending & (nsel == nn))
            r = kernel(delta[idx], int(nn))
            for key, v in r.items():
                if key not in out:
                    out[key] = np.zeros(P, dtype=np.asarray(v).dtype)
                out[key][idx] = v
        if n != "auto":
            break
        pending = pending & (out["tail"] > tol) & (nsel < sizes[-1])
        nsel = np.where(pending, sizes[np.minimum(np.searchsorted(sizes, nsel) + 1,
                                                  sizes.size - 1)], nsel)
    out["n"] = nsel
    return out


# --------------------------------------------------------------------------------------------
# initiation of sliding, constant tau0 (lengths over a, stresses over tau0)


def _init_T(delta):
    """T/(a tau0) of Eq 17 in closed form: 2 sqrt(1 - delta^2)."""
    return 2.0 * np.sqrt((1.0 - delta) * (1.0 + delta))


def _init_delta(r):
    """Stick-zone half-width d/a for T/(2 a tau0) = r in [0, 1]."""
    return np.sqrt((1.0 - r) * (1.0 + r))


def _init_rhs(delta, t):
    """Eq 16 over tau0 on the stick zone, at t = x/d: (1/pi) ln((a - x)/(a + x))."""
    return -(2.0 / np.pi) * np.arctanh(delta[..., None] * t)


def _init_kernel(delta: NDArray, n: int) -> dict[str, NDArray]:
    s = _solver(n)
    sol = s.solve(_init_rhs(delta, s.collocation_unit), values=False)
    b = sol.coefficients
    # Eq 17: T = 2 a tau0 - int tau; the bounded solution's resultant is d (pi/2) b_0
    T = 2.0 - delta * (np.pi / 2) * b[:, 0]
    res = np.max(np.abs(-b @ _check_matrix(n) - _init_rhs(delta, _CHECK_Y)), axis=-1)
    return dict(T=T, tail=_tail(b), stick=res, cons=np.abs(sol.consistency))


def _init_rate(delta):
    """Convergence rate: the log sources x = +-a sit at t = +-a/d."""
    # arccosh(1/delta) = ln((1 + sqrt(1 - delta^2))/delta), without overflow for tiny delta
    k = np.sqrt((1 - delta) * (1 + delta))
    safe = np.where(delta > 0, delta, 1.0)
    return np.where(delta > 0, np.log1p(k) - np.log(safe), np.inf)


def _init_coefficients(delta: NDArray, n: int) -> NDArray:
    s = _solver(n)
    return s.solve(_init_rhs(delta, s.collocation_unit), values=False).coefficients


def _G(x):
    """(1 + x) ln(1 + x) + (1 - x) ln(1 - x): the antiderivative of ln((1+x)/(1-x))."""
    return scipy.special.xlogy(1 + x, 1 + x) + scipy.special.xlogy(1 - x, 1 - x)


def _init_slip_closed(x, delta):
    r"""The slip s/a over (4 tau0/(pi E)) for delta <= x <= 1 (docs/tangential.md, Eq T6).

    S = k ln(x + r) - ln(x k + r) + (1 - k) ln(delta) + ((1 - x)/2) ln(1 - x^2) + x ln(k + r)
    with k = sqrt(1 - delta^2), r = sqrt(x^2 - delta^2); written so that delta -> 0 is
    stable (the first three terms then cancel exactly).
    """
    k = np.sqrt((1 - delta) * (1 + delta))
    r = np.sqrt(np.clip((x - delta) * (x + delta), 0.0, None))
    with np.errstate(divide="ignore", invalid="ignore"):
        head = k * np.log(x + r) - np.log(x * k + r) + scipy.special.xlogy(
            delta * delta / (1 + k), delta)
    head = np.where(delta > 0, head, 0.0)
    return head + scipy.special.xlogy((1 - x) / 2, (1 - x) * (1 + x)) + x * np.log(k + r)


# --------------------------------------------------------------------------------------------
# steady rolling, constant tau0 (lengths over a, stresses over tau0)


def _roll_sqrt_beta(delta):
    """T/(2 a tau0) = sqrt((1 + delta)/2)."""
    return np.sqrt((1.0 + delta) / 2.0)


def _roll_u0(delta):
    r"""u0 = arccosh((3a + d)/(a - d)) = 2 artanh(sqrt((1 + delta)/2)), stable at both ends."""
    sb = _roll_sqrt_beta(delta)
    with np.errstate(divide="ignore"):
        big = 2.0 * np.log((1.0 + sb) / np.sqrt((1.0 - delta) / 2.0))
    return np.where(sb < 0.7, 2.0 * np.arctanh(np.minimum(sb, 0.7)), big)


def _roll_creep_unit(delta):
    """creep/V over tau0/E: -(2/pi) u0 (docs/tangential.md)."""
    return -(2.0 / np.pi) * _roll_u0(delta)


def _roll_Y(delta):
    return (3.0 + delta) / (1.0 - delta)


def _roll_rhs(delta, t, split: str = "endpoint"):
    r"""Eq 27 over tau0 for tau-bar on the stick zone, at t in [-1, 1], without the creep term.

    ``"endpoint"``: q = -tau0 arccos(t)/pi + tau-bar (the split used by the library; the
    right-hand side -(1/pi) ln(2 (t + Y)) is smooth on the stick zone). ``"linear"``: the
    paper's Eq 25, q = -tau0 (1 - t)/2 + tau-bar, whose right-hand side (Eq 27, signs as in
    docs/tangential.md) has (1 -+ t) ln(1 -+ t) end-point terms: algebraic convergence.
    """
    Y = _roll_Y(delta)[..., None]
    if split == "endpoint":
        return -(1.0 / np.pi) * np.log(2.0 * (t + Y))
    return (1.0 / np.pi) * (scipy.special.xlogy((1 - t) / 2, 1 - t)
                            + scipy.special.xlogy((1 + t) / 2, 1 + t) - 1.0 - np.log(t + Y))


def _roll_solve(delta: NDArray, n: int, split: str = "endpoint"):
    s = _solver(n)
    f = _roll_rhs(delta, s.collocation_unit, split)
    return s.solve(f, extra=np.ones_like(f), values=False)


def _roll_kernel(delta: NDArray, n: int, split: str = "endpoint") -> dict[str, NDArray]:
    sol = _roll_solve(delta, n, split)
    b = sol.coefficients
    h = (1.0 - delta) / 2.0
    # Eq 29 (sign of the integral corrected): T = (3a + d) tau0/2 - int tau-bar
    T = (3.0 + delta) / 2.0 - h * (np.pi / 2) * b[:, 0]
    lam = sol.extra  # = -E creep/(2 tau0 V)
    res = np.max(np.abs(-b @ _check_matrix(n) - _roll_rhs(delta, _CHECK_Y, split)
                        - lam[:, None]), axis=-1)
    return dict(T=T, creep=-2.0 * lam, tail=_tail(b), stick=res, cons=np.abs(sol.consistency))


def _roll_rate(delta):
    """The log source x = -a sits at t = -(3a + d)/(a - d): rate u0."""
    return _roll_u0(delta)


# --------------------------------------------------------------------------------------------
# Coulomb counterparts (lengths over a, stresses over mu p0)


def _cm_kernel(delta: NDArray, n: int) -> dict[str, NDArray]:
    """Cattaneo--Mindlin: (1/pi) int tau/(s - x) = (mu/pi) int p/(s - x) = -x on |x| < d."""
    s = _solver(n)
    sol = s.solve(-delta[:, None] * s.collocation_unit[None, :], values=False)
    b = sol.coefficients
    # T/(mu F) = 1 - int tau / (mu p0 a pi/2)
    T = 1.0 - delta * b[:, 0]
    res = np.max(np.abs(-b @ _check_matrix(n) + delta[:, None] * _CHECK_Y), axis=-1)
    return dict(T=T, tail=_tail(b), stick=res, cons=np.abs(sol.consistency))


def _carter_kernel(delta: NDArray, n: int) -> dict[str, NDArray]:
    """Carter: (1/pi) int tau-bar/(s - x) = -x + lambda on d < x < a (q = -mu p + tau-bar)."""
    s = _solver(n)
    m = (1.0 + delta) / 2.0
    h = (1.0 - delta) / 2.0
    xs = m[:, None] + h[:, None] * s.collocation_unit[None, :]
    sol = s.solve(-xs, extra=np.ones_like(xs), values=False)
    b = sol.coefficients
    T = 1.0 - h * b[:, 0]
    lam = sol.extra  # = -E creep/(2 mu p0 V); creep/V = -lam mu a/R
    xc = m[:, None] + h[:, None] * _CHECK_Y[None, :]
    res = np.max(np.abs(-b @ _check_matrix(n) + xc - lam[:, None]), axis=-1)
    return dict(T=T, creep=-lam, tail=_tail(b), stick=res, cons=np.abs(sol.consistency))


# --------------------------------------------------------------------------------------------
# shared driver


def _solve_points(delta, active, method, n, tol, kernel, rate, T_closed, dT_closed,
                  T_target=None, T_full=2.0, lo=0.0, hi=1.0):
    """Closed form or collocation on the active points; Newton on delta for a given T.

    All in the units of the kernel (``T`` over ``a tau0`` or ``mu F``; ``T_full`` is the
    full-slip load in those units). Returns the arrays ``delta``, ``T`` (of the solution),
    ``creep``, ``n``, ``stick``, ``cons``, ``tail`` and ``force`` (``|T(d) - T|/T_full``).
    """
    P = delta.size
    out = dict(delta=delta.copy(), T=np.full(P, np.nan), n=np.zeros(P, int),
               stick=np.zeros(P), cons=np.zeros(P), tail=np.zeros(P), force=np.zeros(P),
               creep=np.full(P, np.nan))
    idx = np.flatnonzero(active)
    if idx.size == 0:
        return out
    d = delta[idx]
    if method == "closed-form":
        out["T"][idx] = T_closed(d)
    else:
        for _ in range(12):
            r = _adaptive(kernel, d, rate(d), n, tol)
            if T_target is None:
                break
            err = r["T"] - T_target[idx]
            with np.errstate(divide="ignore", invalid="ignore"):  # infinite slope at d = a
                slope = dT_closed(d)
            ok = np.abs(err) <= _FORCE_TOL * T_full
            if ok.all():
                break
            with np.errstate(divide="ignore", invalid="ignore"):
                step = np.where(ok | (np.abs(slope) < 1e-300), 0.0, err / slope)
            d = np.clip(d - step, lo, hi)
        out["delta"][idx] = d
        out["T"][idx] = r["T"]
        for key in ("n", "stick", "cons", "tail"):
            out[key][idx] = r[key]
        if "creep" in r:
            out["creep"][idx] = r["creep"]
    if T_target is not None:
        out["force"][idx] = np.abs(out["T"][idx] - T_target[idx]) / T_full
    return out


def _raise_unconverged(name, converged, labels: dict, out, n) -> None:
    conv = np.asarray(converged).reshape(-1)
    if conv.all():
        return
    i = int(np.flatnonzero(~conv)[0])
    where = ", ".join(f"{k}={float(np.reshape(v, -1)[i])!r}" for k, v in labels.items())
    raise ConvergenceError(
        f"{name} (collocation) did not converge at {where} (error estimate "
        f"{out['tail'][i]:.3g}, stick residual {out['stick'][i]:.3g}, force residual "
        f"{out['force'][i]:.3g}, n = {out['n'][i]}): " + (
            f"the stick zone is too close to its limit for n <= {SIZES[-1]}; use "
            f"method='closed-form'" if n == "auto" else
            f"n = {out['n'][i]} nodes are too few for tol; try n='auto'"))


def _raise_sliding(name, sliding, T_name, T, T_full) -> None:
    if not np.any(sliding):
        return
    i = int(np.flatnonzero(np.reshape(sliding, -1))[0])
    raise NoEquilibriumError(
        f"{name}: {T_name}={float(np.reshape(T, -1)[i])!r} is at or above the full-slip load "
        f"{float(np.reshape(T_full, -1)[i])!r}: the whole contact slips (sliding), there is no "
        f"stick zone")


def _states(sliding, stick, shape):
    st = np.full(shape, _STICK_SLIP, dtype=object)
    st[np.asarray(sliding, bool)] = _SLIDING
    st[np.asarray(stick, bool)] = _STICK
    return st.astype(str)


# --------------------------------------------------------------------------------------------
# results


@dataclass(frozen=True)
class _Tangential(_Result):
    """Fields shared by the four tangential results (see the subclasses)."""

    d_over_a: NDArray | float
    T_over_T_full_slip: NDArray | float
    state: NDArray | str
    method: str
    n_collocation: NDArray | int
    residual_stick: NDArray | float
    residual_force: NDArray | float
    residual_consistency: NDArray | float
    error_estimate: NDArray | float
    converged: NDArray | bool

    def _points(self, x_over_a):
        x = positions("x_over_a", x_over_a, np.shape(self.d_over_a))
        dlt = np.asarray(self.d_over_a, dtype=float)[..., None]
        st = np.asarray(self.state)[..., None]
        return x, dlt, st

    def _coefficients(self, kernel_solve) -> NDArray:
        """Re-solve the collocation system at the stored sizes: (points..., n_max)."""
        dlt = np.atleast_1d(np.asarray(self.d_over_a, dtype=float)).reshape(-1)
        nn = np.atleast_1d(np.asarray(self.n_collocation)).reshape(-1)
        nmax = max(int(nn.max()), 1)
        b = np.zeros((dlt.size, nmax))
        for n in np.unique(nn[nn > 0]):
            sel = nn == n
            b[sel, :n] = kernel_solve(dlt[sel], int(n))
        return b


def _cheb_u_series(b: NDArray, t: NDArray) -> NDArray:
    """sqrt(1 - t^2) sum_j b_j U_j(t) (zero outside [-1, 1]); b (P, n), t (P, m)."""
    inside = np.abs(t) <= 1.0
    tc = np.clip(t, -1.0, 1.0)
    bk1 = np.zeros(tc.shape)
    bk2 = np.zeros(tc.shape)
    for j in range(b.shape[-1] - 1, -1, -1):
        bk1, bk2 = b[:, j, None] + 2 * tc * bk1 - bk2, bk1
    return np.where(inside, np.sqrt(np.clip(1 - tc * tc, 0.0, None)) * bk1, 0.0)


@dataclass(frozen=True)
class SlidingInitiation(_Tangential):
    r"""Initiation of sliding with constant friction stress ``tau0`` (Eqs 15--17).

    Attributes
    ----------
    d_over_a : ndarray or float
        Half-width of the central stick zone over ``a`` (``nan`` when sliding under a given
        load above full slip; ``1`` at ``T = 0``).
    T_over_Ea : ndarray or float
        Tangential force per unit length over ``E a``.
    T_over_T_full_slip : ndarray or float
        ``T/(2 a tau0)``.
    tau0_over_E : ndarray or float
        Friction stress over the composite modulus.
    state : ndarray of str or str
        ``"stick"`` (``T = 0``), ``"stick-slip"`` or ``"sliding"`` (``T >= 2 a tau0``).
    method : str
        ``"closed-form"`` or ``"collocation"``.
    n_collocation : ndarray or int
        Nodes used per point (0: closed form, or nothing to solve).
    residual_stick : ndarray or float
        Largest residual of the stick condition (Eq 16) at 16 points of the stick zone other
        than the collocation points, over ``tau0`` (0 for the closed form).
    residual_force : ndarray or float
        ``|T(d) - T|/(2 a tau0)`` for a given ``T`` (Eq 17 solved for ``d``); 0 when ``d``
        is given.
    residual_consistency : ndarray or float
        Collocation consistency residual (zero by symmetry).
    error_estimate : ndarray or float
        Chebyshev tail of the solution over its largest coefficient (or over ``tau0`` when
        the solution is smaller), 0 for the closed form.
    converged : ndarray or bool
        Every tolerance met.
    """

    T_over_Ea: NDArray | float
    tau0_over_E: NDArray | float

    def traction(self, x_over_a: ArrayLike) -> NDArray:
        r"""Shear traction ``q/E`` at ``x/a`` (positive along ``T``; ``tau0/E`` when slipping).

        ``x_over_a`` has shape ``(m,)``; the result has shape ``points.shape + (m,)``: the
        stick-zone traction of the method used for ``|x| < d``, ``tau0/E`` for
        ``d <= |x| <= a`` (everywhere when sliding), zero outside the contact.
        """
        x, dlt, st = self._points(x_over_a)
        t0 = np.asarray(self.tau0_over_E, dtype=float)[..., None]
        ax = np.abs(x)
        if self.method == "closed-form":
            k = np.sqrt(np.clip((1 - dlt) * (1 + dlt), 0.0, None))
            inner = (2 / np.pi) * np.arctan2(k, np.sqrt(np.clip(dlt * dlt - x * x, 0.0, None)))
        else:
            b = self._coefficients(_init_coefficients)
            dd = np.atleast_1d(dlt[..., 0]).reshape(-1)
            xx = np.broadcast_to(x, dd.shape + x.shape[-1:])
            with np.errstate(divide="ignore", invalid="ignore"):
                tt = np.where(dd[:, None] > 0, xx / dd[:, None], 2.0)
            inner = 1.0 - _cheb_u_series(b, tt)
            inner = inner.reshape(np.shape(dlt[..., 0]) + x.shape[-1:])
        stick = (ax < dlt) & (st == _STICK_SLIP)
        q = np.where(ax <= 1.0, np.where(stick, inner, 1.0), 0.0)
        q = np.where(st == _STICK, 0.0, q)
        return t0 * q

    def slip(self, x_over_a: ArrayLike) -> NDArray:
        r"""Slip ``s/a`` at ``x/a`` (shape ``points.shape + (m,)``).

        The slip is the cylinder's tangential displacement relative to the substrate in the
        slip zones, measured from the nearer end of the stick zone: zero in the stick zone,
        positive (along ``T``) and growing towards the contact edges in the slip zones;
        ``nan`` outside the contact and for sliding points (the slip then grows without
        bound). Closed form (``docs/tangential.md``) or, for the collocation
        method, :math:`s = (2/(\pi E))[\tau_0 \int_d^x \ln\frac{a+x'}{a-x'}dx' -
        \int \tau(\xi)\ln|x-\xi|\,d\xi\,|_d^x]` with the logarithmic moments of the
        collocation solution (exact for its polynomial part).
        """
        x, dlt, st = self._points(x_over_a)
        t0 = np.asarray(self.tau0_over_E, dtype=float)[..., None]
        ax = np.abs(x)
        xs = np.clip(ax, dlt, 1.0)
        if self.method == "closed-form":
            val = (4 / np.pi) * _init_slip_closed(xs, np.where(np.isfinite(dlt), dlt, 0.0))
        else:
            val = self._slip_collocation(xs)
        sl = np.where(ax <= dlt, 0.0, val)
        sl = np.where(ax > 1.0, np.nan, sl)
        sl = np.where(st == _SLIDING, np.nan, sl)
        sl = np.where(st == _STICK, np.where(ax > 1.0, np.nan, 0.0), sl)
        return t0 * sl

    def _slip_collocation(self, xs: NDArray) -> NDArray:
        dshape = np.shape(self.d_over_a)
        dd = np.atleast_1d(np.asarray(self.d_over_a, dtype=float)).reshape(-1)
        nn = np.atleast_1d(np.asarray(self.n_collocation)).reshape(-1)
        X = np.broadcast_to(xs, dshape + xs.shape[-1:]).reshape(dd.size, -1)
        val = np.full(X.shape, np.nan)
        for n in np.unique(nn[nn > 0]):
            sel = nn == n
            d = dd[sel]
            b = _init_coefficients(d, int(n))

            def logmom(y, d=d, b=b, n=n):
                # int_{-d}^{d} tau(s) ln|y - s| ds over tau0, y of shape (p, m)
                mu = _log_moment_vector(y / d[:, None], int(n))
                return d[:, None] * (np.einsum("pj,pmj->pm", b, mu) +
                                     np.log(d)[:, None] * (np.pi / 2) * b[:, :1])

            Xs = X[sel]
            dm = np.broadcast_to(d[:, None], Xs.shape)
            lm = logmom(Xs) - logmom(dm)
            val[sel] = (2 / np.pi) * (_G(Xs) - _G(dm) - lm)
        return val.reshape(dshape + xs.shape[-1:])


@dataclass(frozen=True)
class SteadyRolling(_Tangential):
    r"""Steady rolling of a driving cylinder with constant friction stress (Eqs 23--29).

    Attributes
    ----------
    d_over_a : ndarray or float
        Start of the leading-edge stick zone ``d < x < a`` over ``a`` (``-1``: full stick
        at ``T = 0``; ``nan`` under a load above full slip).
    T_over_Ea : ndarray or float
        Tractive force per unit length over ``E a`` (on the cylinder, along the rolling
        direction).
    T_over_T_full_slip : ndarray or float
        ``T/(2 a tau0)``.
    creep_over_V : ndarray or float
        :math:`(V - \omega R)/V`, negative (``nan`` when sliding: at full slip the creep is
        not fixed by a stick zone; it diverges logarithmically as ``d -> a``).
    tau0_over_E : ndarray or float
    state, method, n_collocation, residual_stick, residual_force, residual_consistency, \
error_estimate, converged
        As in :class:`SlidingInitiation`; ``residual_stick`` refers to Eq 27 (the slip
        gradient in the stick zone equal to the creep ratio), ``residual_consistency`` to
        the extra collocation equation that fixes the creep.
    """

    T_over_Ea: NDArray | float
    creep_over_V: NDArray | float
    tau0_over_E: NDArray | float

    def traction(self, x_over_a: ArrayLike) -> NDArray:
        r"""Shear traction ``q/E`` on the cylinder at ``x/a``.

        Positive along the rolling direction: ``tau0/E`` in the trailing slip zone, falling
        to 0 at the leading edge. ``x_over_a`` has shape ``(m,)``; the result has shape
        ``points.shape + (m,)``.
        """
        x, dlt, st = self._points(x_over_a)
        t0 = np.asarray(self.tau0_over_E, dtype=float)[..., None]
        if self.method == "closed-form":
            beta = (1 + dlt) / 2
            inner = (2 / np.pi) * np.arctan2(np.sqrt(np.clip(beta * (1 - x), 0.0, None)),
                                             np.sqrt(np.clip(x - dlt, 0.0, None)))
        else:
            b = self._coefficients(lambda d, n: _roll_solve(d, n).coefficients)
            dd = np.atleast_1d(dlt[..., 0]).reshape(-1)
            xx = np.broadcast_to(x, dd.shape + x.shape[-1:])
            tt = (2 * xx - 1 - dd[:, None]) / (1 - dd[:, None])  # exact at x = d and x = a
            # q on the cylinder = -(q on the substrate) = tau0 arccos(t)/pi - tau-bar
            inner = np.arccos(np.clip(tt, -1, 1)) / np.pi - _cheb_u_series(b, tt)
            inner = inner.reshape(np.shape(dlt[..., 0]) + x.shape[-1:])
        stick = (x > dlt) & (st == _STICK_SLIP)
        q = np.where(np.abs(x) <= 1.0, np.where(stick, inner, 1.0), 0.0)
        q = np.where(st == _STICK, 0.0, q)
        return t0 * q


@dataclass(frozen=True)
class CoulombSlidingInitiation(_Tangential):
    r"""Cattaneo--Mindlin line contact: Hertz pressure, Coulomb friction ``mu``.

    Attributes
    ----------
    d_over_a : ndarray or float
        Half-width of the central stick zone over ``a``.
    T_over_muF : ndarray or float
        ``T/(mu F) = 1 - (d/a)^2`` (also in ``T_over_T_full_slip``).
    T_over_Ea : ndarray or float
        ``(pi/4) mu (a/R) T/(mu F)``.
    mu, a_over_R : ndarray or float
        Friction coefficient and Hertz half-width over the radius.
    state, method, n_collocation, residual_stick, residual_force, residual_consistency, \
error_estimate, converged
        As in :class:`SlidingInitiation` (stresses over ``mu p0``).
    """

    T_over_muF: NDArray | float
    T_over_Ea: NDArray | float
    mu: NDArray | float
    a_over_R: NDArray | float

    def traction(self, x_over_a: ArrayLike) -> NDArray:
        r"""Shear traction ``q/E`` at ``x/a`` (shape ``points.shape + (m,)``).

        ``mu p`` in the slip zones,
        :math:`\mu p_0[\sqrt{1-x^2/a^2} - (d/a)\sqrt{1-x^2/d^2}]` in the stick zone.
        """
        x, dlt, st = self._points(x_over_a)
        p0 = np.asarray(self.a_over_R, dtype=float)[..., None] / 2
        mu = np.asarray(self.mu, dtype=float)[..., None]
        xq = np.clip(x, -2.0, 2.0)  # the terms vanish beyond |x| = a; no overflow of x*x
        hertz = np.sqrt(np.clip(1 - xq * xq, 0.0, None))
        if self.method == "closed-form":
            corr = np.sqrt(np.clip(dlt * dlt - xq * xq, 0.0, None))
        else:
            b = self._coefficients(lambda d, n: _solver(n).solve(
                -d[:, None] * _solver(n).collocation_unit, values=False).coefficients)
            dd = np.atleast_1d(dlt[..., 0]).reshape(-1)
            xx = np.broadcast_to(x, dd.shape + x.shape[-1:])
            with np.errstate(divide="ignore", invalid="ignore"):
                tt = np.where(dd[:, None] > 0, xx / dd[:, None], 2.0)
            corr = _cheb_u_series(b, tt).reshape(np.shape(dlt[..., 0]) + x.shape[-1:])
        stick = (np.abs(x) < dlt) & (st == _STICK_SLIP)
        q = hertz - np.where(stick, corr, 0.0)
        q = np.where(st == _STICK, 0.0, q)
        return mu * p0 * q


@dataclass(frozen=True)
class CoulombRolling(_Tangential):
    r"""Carter's steady rolling: Hertz pressure, Coulomb friction, driving cylinder.

    Attributes
    ----------
    d_over_a : ndarray or float
        Start of the leading-edge stick zone over ``a``; its half-width is
        ``a' = (a - d)/2``.
    T_over_muF : ndarray or float
        ``1 - (a'/a)^2``.
    T_over_Ea : ndarray or float
        ``(pi/4) mu (a/R) T/(mu F)``.
    creep_over_V : ndarray or float
        ``(V - omega R)/V = -(mu a/R)(1 - a'/a)`` (Carter), negative.
    mu, a_over_R : ndarray or float
    state, method, n_collocation, residual_stick, residual_force, residual_consistency, \
error_estimate, converged
        As in :class:`SteadyRolling` (stresses over ``mu p0``).
    """

    T_over_muF: NDArray | float
    T_over_Ea: NDArray | float
    creep_over_V: NDArray | float
    mu: NDArray | float
    a_over_R: NDArray | float

    def traction(self, x_over_a: ArrayLike) -> NDArray:
        r"""Shear traction ``q/E`` on the cylinder at ``x/a`` (along the rolling direction).

        :math:`\mu p_0[\sqrt{1-x^2/a^2} - (a'/a)\sqrt{1-(x-x_0)^2/a'^2}]` in the stick
        zone, ``x0 = a - a'``; ``mu p`` in the slip zone. Shape ``points.shape + (m,)``.
        """
        x, dlt, st = self._points(x_over_a)
        p0 = np.asarray(self.a_over_R, dtype=float)[..., None] / 2
        mu = np.asarray(self.mu, dtype=float)[..., None]
        xq = np.clip(x, -2.0, 2.0)  # the terms vanish beyond |x| = a; no overflow of x*x
        hertz = np.sqrt(np.clip(1 - xq * xq, 0.0, None))
        m = (1 + dlt) / 2
        h = (1 - dlt) / 2
        if self.method == "closed-form":
            corr = np.sqrt(np.clip(h * h - (xq - m) ** 2, 0.0, None))
        else:
            def coef(d, n):
                mm, hh = (1 + d) / 2, (1 - d) / 2
                xs = mm[:, None] + hh[:, None] * _solver(n).collocation_unit
                return _solver(n).solve(-xs, extra=np.ones_like(xs), values=False).coefficients

            b = self._coefficients(coef)
            dd = np.atleast_1d(dlt[..., 0]).reshape(-1)
            xx = np.broadcast_to(x, dd.shape + x.shape[-1:])
            tt = (2 * xx - 1 - dd[:, None]) / (1 - dd[:, None])
            corr = _cheb_u_series(b, tt).reshape(np.shape(dlt[..., 0]) + x.shape[-1:])
        stick = (x > dlt) & (st == _STICK_SLIP)
        q = hertz - np.where(stick, corr, 0.0)
        q = np.where(st == _STICK, 0.0, q)
        return mu * p0 * q


# --------------------------------------------------------------------------------------------
# public functions (nondimensional)


@dataclass(frozen=True)
class _Problem:
    """What distinguishes the four problems (units: T over a tau0, or over mu F)."""

    name: str
    kernel: Callable[[NDArray, int], dict[str, NDArray]]
    rate: Callable[[NDArray], NDArray]
    T_closed: Callable[[NDArray], NDArray]  # T(delta)
    dT_closed: Callable[[NDArray], NDArray]  # dT/d delta
    delta_closed: Callable[[NDArray], NDArray]  # delta(T/T_full), for 0 <= T/T_full <= 1
    T_full: float
    d_low: float
    d_low_inclusive: bool
    d_stick: float  # delta at T = 0
    constant: bool = True  # constant tau0 (load T_over_Ea) or Coulomb (load T_over_muF)
    creep_closed: Callable[[NDArray], NDArray] | None = None  # rolling only
    n_auto: int | None = None  # fixed n for n="auto" (Coulomb: linear right-hand sides)


def _run(pb: _Problem, d_over_a, load, load_name, method, n, tol, raise_on_failure,
         on_sliding, params: dict):
    """Validate the state variable, solve, return (fields, diagnostics, scalar-flag parts)."""
    _one_of(d_over_a, load, load_name)
    _check_options(method, n, tol, raise_on_failure, on_sliding)
    names = list(params)
    arrays = list(params.values())
    if d_over_a is not None:
        dl = check_array("d_over_a", d_over_a, low=pb.d_low, low_inclusive=pb.d_low_inclusive,
                         high=1.0)
        given = ("d_over_a", dl)
    else:
        dl = None
        given = (load_name, non_negative(load_name, load))
    scalar = scalar_or_array(*arrays, given[1])
    *arrays, g = (np.asarray(v, float) for v in broadcast(**dict(zip(names, arrays,
                                                                   strict=True)),
                                                          **{given[0]: given[1]}))
    shape = g.shape
    if dl is not None:
        dl = g
        r = pb.T_closed(dl) / pb.T_full  # T over the full-slip load
        T_target = None
        # the state follows from d (T rounds to the full-slip load long before d reaches 0)
        sliding = dl == 0 if pb.d_low_inclusive else np.zeros(shape, bool)
        stick = np.zeros(shape, bool)
    else:
        r = g / (2 * arrays[0]) if pb.constant else g.copy()
        dl = np.where(r <= 1, pb.delta_closed(np.minimum(r, 1.0)), np.nan)
        T_target = pb.T_full * np.minimum(r, 1.0)
        sliding = r >= 1
        stick = r == 0
    active = ~(sliding | stick)
    nn = pb.n_auto if (pb.n_auto is not None and n == "auto") else n
    out = _solve_points(np.where(np.isfinite(dl), dl, 0.0).reshape(-1), active.reshape(-1),
                        method, nn, tol, pb.kernel, pb.rate, pb.T_closed, pb.dT_closed,
                        None if T_target is None else T_target.reshape(-1), pb.T_full,
                        lo=pb.d_low + (0.0 if pb.d_low_inclusive else 1e-16), hi=1.0 - 1e-16)
    act = active.reshape(-1)
    if T_target is None:
        T_unit = np.where(act, out["T"], pb.T_full * r.reshape(-1)).reshape(shape)
    else:
        T_unit = pb.T_full * r
        dl = np.where(active, out["delta"].reshape(shape), np.where(stick, pb.d_stick, dl))
    if pb.creep_closed is not None:
        creep = out["creep"] if method == "collocation" else pb.creep_closed(out["delta"])
        creep = np.where(act, creep, np.nan).reshape(shape)
        creep = np.where(stick, 0.0, creep)
    else:
        creep = None
    if on_sliding == "raise":
        _raise_sliding(pb.name, sliding, given[0], given[1] if d_over_a is None else T_unit,
                       2 * arrays[0] if pb.constant else np.ones(shape))
    converged = np.ones(shape, bool)
    if method == "collocation":
        converged = (((out["tail"] <= 10 * tol) & (out["force"] <= 1e-10)
                      & np.isfinite(out["T"])) | ~act).reshape(shape)
        if raise_on_failure:
            labels = dict(zip(names, arrays, strict=True))
            labels[given[0]] = g
            _raise_unconverged(pb.name, converged, labels, out, n)
    diag = dict(n_collocation=out["n"].reshape(shape), residual_stick=out["stick"].reshape(shape),
                residual_force=out["force"].reshape(shape),
                residual_consistency=out["cons"].reshape(shape),
                error_estimate=out["tail"].reshape(shape), converged=converged,
                state=_states(sliding, stick, shape), d_over_a=dl,
                T_over_T_full_slip=T_unit / pb.T_full)
    return arrays, T_unit, creep, diag, scalar


def _build(cls, method, scalar, **vals):
    return cls(method=method, **{k: _as_output(np.asarray(v), scalar) for k, v in vals.items()})


_INITIATION = _Problem(
    "sliding_initiation", _init_kernel, _init_rate, _init_T,
    lambda d: -2 * d / np.sqrt((1 - d) * (1 + d)), _init_delta, 2.0, 0.0,
    True, 1.0)
_ROLLING = _Problem(
    "steady_rolling", _roll_kernel, _roll_rate, lambda d: 2 * _roll_sqrt_beta(d),
    lambda d: 1 / (2 * _roll_sqrt_beta(d)), lambda r: 2 * r * r - 1, 2.0, -1.0, False, -1.0,
    creep_closed=_roll_creep_unit)
_CATTANEO_MINDLIN = _Problem(
    "sliding_initiation_coulomb", _cm_kernel, lambda d: np.full(d.shape, np.inf),
    lambda d: 1 - d * d, lambda d: -2 * d, lambda r: np.sqrt(1 - r), 1.0, 0.0, True, 1.0,
    constant=False, n_auto=N_COULOMB)
_CARTER = _Problem(
    "steady_rolling_coulomb", _carter_kernel, lambda d: np.full(d.shape, np.inf),
    lambda d: 1 - ((1 - d) / 2) ** 2, lambda d: (1 - d) / 2, lambda r: 1 - 2 * np.sqrt(1 - r),
    1.0, -1.0, False, -1.0, constant=False, creep_closed=lambda d: -(1 + d) / 2,
    n_auto=N_COULOMB)


def sliding_initiation(tau0_over_E: ArrayLike, d_over_a: ArrayLike | None = None, *,
                       T_over_Ea: ArrayLike | None = None, method: str = "closed-form",
                       n: int | str = "auto", tol: float = 1e-12,
                       raise_on_failure: bool = True,
                       on_sliding: str = "report") -> SlidingInitiation:
    r"""Initiation of sliding with constant friction stress ``tau0`` (paper Eqs 15--17).

    A tangential force ``T`` grows on a contact of half-width ``a`` (from the normal
    problem, unchanged by ``T`` since ``B = 0``); the central zone ``|x| < d`` sticks, the
    edges ``d < |x| < a`` slip under the shear stress ``tau0``.

    Parameters
    ----------
    tau0_over_E : array_like
        Friction stress over the composite modulus, ``> 0``.
    d_over_a : array_like, optional
        Stick-zone half-width over ``a``, in ``[0, 1)`` (``0``: onset of full sliding).
    T_over_Ea : array_like, optional
        Tangential force per unit length over ``E a``, ``>= 0``; give exactly one of
        ``d_over_a`` and ``T_over_Ea``. At or above ``2 tau0/E`` the cylinder slides.
    method : {"closed-form", "collocation"}
        Closed form, or Gauss--Chebyshev collocation of Eq 16 (for a given ``T``, Eq 17 is
        then solved for ``d`` by Newton's method on the collocation solution).
    n : int or "auto"
        Collocation nodes (``"auto"``: chosen per point for ``tol``).
    tol : float
        Target discretisation error of the collocation solution.
    raise_on_failure : bool
        Raise :class:`~linecontact.errors.ConvergenceError` when a collocation point misses
        its tolerance (otherwise it is flagged in ``converged``).
    on_sliding : {"report", "raise"}
        For a given ``T`` at or above full slip: report ``state == "sliding"`` (default) or
        raise :class:`~linecontact.errors.NoEquilibriumError`.

    Returns
    -------
    SlidingInitiation
        Inputs broadcast together; scalars in, scalars out.

    Notes
    -----
    With :math:`p_x = \tau_0 - \tau(x)` and zero relative slip gradient in the stick zone,
    Eq 15 gives Eq 16, :math:`\frac{1}{\pi}\int_{-d}^{d}\frac{\tau(\xi)\,d\xi}{\xi - x}
    = \frac{\tau_0}{\pi}\ln\frac{a-x}{a+x}`, bounded at :math:`\pm d`: the Dugdale pair of
    the normal problem, :math:`\tau = (2\tau_0/\pi)\arctan\sqrt{(d^2-x^2)/(a^2-d^2)}`, and
    Eq 17 gives :math:`T = 2\tau_0\sqrt{a^2 - d^2}`.

    Examples
    --------
    >>> r = sliding_initiation(0.01, 0.6)
    >>> round(r.T_over_Ea, 12)          # 2 (tau0/E) sqrt(1 - 0.36)
    0.016
    >>> c = sliding_initiation(0.01, 0.6, method="collocation")
    >>> abs(c.T_over_Ea - r.T_over_Ea) < 1e-14
    True
    >>> sliding_initiation(0.01, T_over_Ea=0.03).state
    'sliding'
    """
    arrays, T_unit, _, diag, scalar = _run(
        _INITIATION, d_over_a, T_over_Ea, "T_over_Ea", method, n, tol, raise_on_failure,
        on_sliding, {"tau0_over_E": positive("tau0_over_E", tau0_over_E)})
    (t0,) = arrays
    return _build(SlidingInitiation, method, scalar, T_over_Ea=t0 * T_unit, tau0_over_E=t0,
                  **diag)


def steady_rolling(tau0_over_E: ArrayLike, d_over_a: ArrayLike | None = None, *,
                   T_over_Ea: ArrayLike | None = None, method: str = "closed-form",
                   n: int | str = "auto", tol: float = 1e-12, raise_on_failure: bool = True,
                   on_sliding: str = "report") -> SteadyRolling:
    r"""Steady rolling of a driving cylinder with constant friction stress (Eqs 23--29).

    Conventions (module docstring): rolling along ``+x`` (leading edge ``x = a``), the
    cylinder drives, ``T`` is the tractive force on it; stick zone ``d < x < a`` at the
    leading edge, slip zone ``-a < x < d`` at the trailing edge with shear ``tau0``.

    Parameters
    ----------
    tau0_over_E : array_like
        Friction stress over the composite modulus, ``> 0``.
    d_over_a : array_like, optional
        Start of the stick zone over ``a``, in ``(-1, 1)`` (``-1``: full stick, ``1``: full
        slip).
    T_over_Ea : array_like, optional
        Tractive force per unit length over ``E a``, ``>= 0`` (exactly one of the two); at
        or above ``2 tau0/E`` the contact slips entirely (``state == "sliding"``).
    method, n, tol, raise_on_failure, on_sliding
        As in :func:`sliding_initiation`; the collocation solves Eq 27 on ``(d, a)`` with
        the creep as the extra unknown of the consistency equation.

    Returns
    -------
    SteadyRolling

    Notes
    -----
    The stick condition (Eq 24) makes the slip gradient
    :math:`\partial(u_x^{(1)} - u_x^{(2)})/\partial x` equal to the creep ratio
    :math:`\dot C/V` in the stick zone. Writing the stick-zone traction on the substrate as
    :math:`q = -\tau_0 L(x) + \bar\tau(x)` with :math:`L(d) = 1`, :math:`L(a) = 0`
    (:math:`\bar\tau` bounded, zero at both ends), Eq 15 gives a singular integral equation
    for :math:`\bar\tau` whose consistency condition fixes :math:`\dot C/V`. Closed form:
    :math:`T = \tau_0\sqrt{2a(a + d)}`,
    :math:`\dot C/V = -(2\tau_0/(\pi E))\operatorname{arccosh}((3a + d)/(a - d))`.

    Examples
    --------
    >>> r = steady_rolling(0.01, 0.0)
    >>> round(r.T_over_Ea / 0.01, 12)      # sqrt(2 (1 + d/a))
    1.414213562373
    >>> r.creep_over_V < 0                 # the driving cylinder turns faster than it rolls
    True
    >>> abs(steady_rolling(0.01, 0.0, method="collocation").creep_over_V - r.creep_over_V) < 1e-14
    True
    """
    arrays, T_unit, creep, diag, scalar = _run(
        _ROLLING, d_over_a, T_over_Ea, "T_over_Ea", method, n, tol, raise_on_failure,
        on_sliding, {"tau0_over_E": positive("tau0_over_E", tau0_over_E)})
    (t0,) = arrays
    return _build(SteadyRolling, method, scalar, T_over_Ea=t0 * T_unit,
                  creep_over_V=t0 * creep, tau0_over_E=t0, **diag)


def sliding_initiation_coulomb(mu: ArrayLike, a_over_R: ArrayLike,
                               d_over_a: ArrayLike | None = None, *,
                               T_over_muF: ArrayLike | None = None, method: str = "closed-form",
                               n: int | str = "auto", tol: float = 1e-12,
                               raise_on_failure: bool = True,
                               on_sliding: str = "report") -> CoulombSlidingInitiation:
    r"""Cattaneo--Mindlin initiation of sliding of a Hertz line contact (Coulomb friction).

    The macro-scale counterpart of :func:`sliding_initiation`: Hertz pressure
    :math:`p = p_0\sqrt{1 - x^2/a^2}`, :math:`p_0 = E a/(2R)`, shear ``mu p`` in the slip
    zones ``d < |x| < a``.

    Parameters
    ----------
    mu : array_like
        Coefficient of friction, ``> 0``.
    a_over_R : array_like
        Hertz contact half-width over the radius, ``> 0`` (it sets ``p0`` and ``F``).
    d_over_a : array_like, optional
        Stick-zone half-width over ``a``, in ``[0, 1)``.
    T_over_muF : array_like, optional
        Tangential force over ``mu F``, ``>= 0`` (exactly one of the two); ``>= 1`` slides.
    method, n, tol, raise_on_failure, on_sliding
        As in :func:`sliding_initiation`; the collocation solves
        :math:`\frac1\pi\int_{-d}^{d}\frac{\tau\,d\xi}{\xi-x} = \frac{\mu}{\pi}
        \int_{-a}^{a}\frac{p\,d\xi}{\xi-x} = -\mu p_0 x/a` for the correction ``tau`` with
        ``q = mu p - tau`` in the stick zone (``n`` defaults to :data:`N_COULOMB`).

    Returns
    -------
    CoulombSlidingInitiation

    Examples
    --------
    >>> r = sliding_initiation_coulomb(0.3, 0.01, 0.5)
    >>> round(r.T_over_muF, 12)
    0.75
    """
    arrays, T_unit, _, diag, scalar = _run(
        _CATTANEO_MINDLIN, d_over_a, T_over_muF, "T_over_muF", method, n, tol,
        raise_on_failure, on_sliding,
        {"mu": positive("mu", mu), "a_over_R": positive("a_over_R", a_over_R)})
    m, A = arrays
    return _build(CoulombSlidingInitiation, method, scalar, T_over_muF=T_unit,
                  T_over_Ea=(np.pi / 4) * m * A * T_unit, mu=m, a_over_R=A, **diag)


def steady_rolling_coulomb(mu: ArrayLike, a_over_R: ArrayLike, d_over_a: ArrayLike | None = None,
                           *, T_over_muF: ArrayLike | None = None, method: str = "closed-form",
                           n: int | str = "auto", tol: float = 1e-12,
                           raise_on_failure: bool = True,
                           on_sliding: str = "report") -> CoulombRolling:
    r"""Carter's steady rolling of a driving cylinder (Hertz pressure, Coulomb friction).

    Conventions as in :func:`steady_rolling`. Stick zone ``d < x < a`` of half-width
    ``a' = (a - d)/2`` centred at ``x0 = a - a'``.

    Parameters
    ----------
    mu, a_over_R : array_like
        As in :func:`sliding_initiation_coulomb`.
    d_over_a : array_like, optional
        Start of the stick zone over ``a``, in ``(-1, 1)``.
    T_over_muF : array_like, optional
        Tractive force over ``mu F``, ``>= 0`` (exactly one of the two); ``>= 1`` slides.
    method, n, tol, raise_on_failure, on_sliding
        As in :func:`steady_rolling`; with ``q = -mu p + tau-bar`` on the stick zone the
        equation for ``tau-bar`` is
        :math:`\frac1\pi\int_d^a\frac{\bar\tau\,d\xi}{\xi - x} = -\mu p_0 x/a
        - E\dot C/(2V)`, its consistency condition giving the creep.

    Returns
    -------
    CoulombRolling

    Examples
    --------
    >>> r = steady_rolling_coulomb(0.3, 0.01, 0.0)   # a' = a/2
    >>> round(r.T_over_muF, 12), round(r.creep_over_V / (0.3 * 0.01), 12)
    (0.75, -0.5)
    """
    arrays, T_unit, creep, diag, scalar = _run(
        _CARTER, d_over_a, T_over_muF, "T_over_muF", method, n, tol, raise_on_failure,
        on_sliding, {"mu": positive("mu", mu), "a_over_R": positive("a_over_R", a_over_R)})
    m, A = arrays
    return _build(CoulombRolling, method, scalar, T_over_muF=T_unit,
                  T_over_Ea=(np.pi / 4) * m * A * T_unit, creep_over_V=m * A * creep, mu=m,
                  a_over_R=A, **diag)


# --------------------------------------------------------------------------------------------
# SI layer


@dataclass(frozen=True)
class CylinderTangential:
    """A tangential state of a :class:`~linecontact.materials.Cylinder`, in SI units.

    Attributes
    ----------
    problem : str
        ``"sliding initiation"`` or ``"steady rolling"``.
    friction : str
        ``"constant"`` (friction stress ``tau0``) or ``"coulomb"`` (coefficient ``mu``).
    normal_load : ndarray or float
        ``F`` [N/m], compressive positive.
    contact_half_width : ndarray or float
        ``a`` [m], from the normal problem (Maugis--Dugdale; Hertz for Coulomb friction).
    stick_zone_end : ndarray or float
        ``d`` [m]: the half-width of the central stick zone ``|x| < d`` (initiation), or the
        start of the leading-edge stick zone ``d < x < a`` (rolling).
    tangential_load : ndarray or float
        ``T`` [N/m].
    full_slip_load : ndarray or float
        ``2 a tau0`` or ``mu F`` [N/m].
    creep_ratio : ndarray or float or None
        ``(V - omega R)/V`` for rolling (negative: driving cylinder); None for initiation.
    state : ndarray of str or str
        ``"stick"``, ``"stick-slip"`` or ``"sliding"``.
    nondimensional : result
        The underlying nondimensional result with its diagnostics.
    normal : CylinderContact
        The normal contact.
    """

    problem: str
    friction: str
    normal_load: NDArray | float
    contact_half_width: NDArray | float
    stick_zone_end: NDArray | float
    tangential_load: NDArray | float
    full_slip_load: NDArray | float
    creep_ratio: NDArray | float | None
    state: NDArray | str
    nondimensional: object = field(repr=False)
    normal: object = field(repr=False)


def _cylinder_tangential(problem, cylinder, normal_load, friction_stress, friction_coefficient,
                         d_over_a, tangential_load, method, on_sliding) -> CylinderTangential:
    from .materials import Cylinder

    if not isinstance(cylinder, Cylinder):
        raise ValueError(f"cylinder must be a linecontact.Cylinder (Cylinder.from_modulus or "
                         f"Cylinder.from_materials), got {cylinder!r}")
    if (friction_stress is None) == (friction_coefficient is None):
        raise ValueError("give exactly one of friction_stress (constant tau0 [Pa]) or "
                         "friction_coefficient (Coulomb mu)")
    if (d_over_a is None) == (tangential_load is None):
        raise ValueError("give exactly one of d_over_a or tangential_load [N/m]")
    E = cylinder.modulus
    rolling = problem == "steady rolling"
    coulomb = friction_coefficient is not None
    pb = (_CARTER if coulomb else _ROLLING) if rolling else \
        (_CATTANEO_MINDLIN if coulomb else _INITIATION)
    # every input checked, and the shapes against each other, before any solve
    if coulomb:
        F = check_array("normal_load", normal_load)
        fr_name, fr = "friction_coefficient", positive("friction_coefficient",
                                                       friction_coefficient)
    else:
        F = check_array("normal_load", normal_load, low=-np.inf)
        fr_name, fr = "friction_stress", positive("friction_stress", friction_stress)
    if d_over_a is not None:
        st_name = "d_over_a"
        st = check_array("d_over_a", d_over_a, low=pb.d_low, low_inclusive=pb.d_low_inclusive,
                         high=1.0)
    else:
        st_name, st = "tangential_load", non_negative("tangential_load", tangential_load)
    broadcast(normal_load=F, **{fr_name: fr, st_name: st})
    d = st if d_over_a is not None else None
    if coulomb:
        if cylinder.cohesive_stress != 0:
            raise ValueError("Coulomb friction is the macro-scale counterpart for the "
                             "non-adhesive Hertz contact: use a Cylinder without adhesion "
                             "(cohesive_stress = 0), or give friction_stress")
        contact = cylinder.contact(load=F)
        A = np.asarray(contact.contact_half_width) / cylinder.radius
        mu = fr
        T = None if d is not None else st / (mu * F)
        fn = steady_rolling_coulomb if rolling else sliding_initiation_coulomb
        r = fn(mu, A, d, T_over_muF=T, method=method, on_sliding=on_sliding)
        full = mu * F
        friction = "coulomb"
    else:
        contact = cylinder.contact(load=F)
        a = np.asarray(contact.contact_half_width)
        t0 = fr
        T = None if d is not None else st / (E * a)
        fn = steady_rolling if rolling else sliding_initiation
        # broadcast with a so that every field has the shape of the points
        r = fn(t0 / E + 0 * a, d, T_over_Ea=T, method=method, on_sliding=on_sliding)
        full = 2 * a * t0
        friction = "constant"
    a = np.asarray(contact.contact_half_width)
    Tn = np.multiply(r.T_over_Ea, E * a)
    creep = r.creep_over_V if rolling else None
    return CylinderTangential(problem, friction, _scalar(F + 0 * a), _scalar(a),
                              _scalar(np.multiply(r.d_over_a, a)), _scalar(Tn), _scalar(full),
                              creep, r.state, r, contact)


def _scalar(v):
    v = np.asarray(v)
    return v.item() if v.ndim == 0 else v


def cylinder_sliding_initiation(cylinder, normal_load: ArrayLike, *,
                                friction_stress: ArrayLike | None = None,
                                friction_coefficient: ArrayLike | None = None,
                                d_over_a: ArrayLike | None = None,
                                tangential_load: ArrayLike | None = None,
                                method: str = "closed-form",
                                on_sliding: str = "report") -> CylinderTangential:
    """Initiation of sliding of a :class:`~linecontact.materials.Cylinder` (SI units).

    Parameters
    ----------
    cylinder : Cylinder
        Geometry, materials and adhesion.
    normal_load : array_like
        ``F`` [N/m]; the contact half-width ``a`` is that of the stable normal contact
        (:meth:`Cylinder.contact`). A load below the pull-off force raises
        :class:`~linecontact.errors.NoEquilibriumError`.
    friction_stress : array_like, optional
        ``tau0`` [Pa], ``> 0``: the nano-scale law (:func:`sliding_initiation`).
    friction_coefficient : array_like, optional
        ``mu``, ``> 0``: Coulomb friction on the Hertz contact
        (:func:`sliding_initiation_coulomb`); the cylinder must have no adhesion and
        ``F > 0``. Give exactly one of ``friction_stress`` and ``friction_coefficient``.
    d_over_a : array_like, optional
        Stick-zone half-width over ``a`` in ``[0, 1)``.
    tangential_load : array_like, optional
        ``T`` [N/m], ``>= 0`` (exactly one of ``d_over_a`` and ``tangential_load``).
    method, on_sliding : str
        As in :func:`sliding_initiation`.

    Returns
    -------
    CylinderTangential

    Examples
    --------
    >>> from linecontact import Cylinder
    >>> cyl = Cylinder.from_modulus(50e-9, 100e9, cohesive_stress=1e9, adhesion_range=0.5e-9)
    >>> s = cylinder_sliding_initiation(cyl, 1.0, friction_stress=1e9, tangential_load=1.0)
    >>> s.state, s.stick_zone_end < s.contact_half_width
    ('stick-slip', True)
    """
    return _cylinder_tangential("sliding initiation", cylinder, normal_load, friction_stress,
                                friction_coefficient, d_over_a, tangential_load, method,
                                on_sliding)


def cylinder_steady_rolling(cylinder, normal_load: ArrayLike, *,
                            friction_stress: ArrayLike | None = None,
                            friction_coefficient: ArrayLike | None = None,
                            d_over_a: ArrayLike | None = None,
                            tangential_load: ArrayLike | None = None,
                            method: str = "closed-form",
                            on_sliding: str = "report") -> CylinderTangential:
    """Steady rolling of a driving :class:`~linecontact.materials.Cylinder` (SI units).

    Parameters as in :func:`cylinder_sliding_initiation`, with ``d_over_a`` in ``(-1, 1)``
    the start of the leading-edge stick zone; ``tangential_load`` is the tractive force
    [N/m]. The result's ``creep_ratio`` is ``(V - omega R)/V`` (negative).

    Examples
    --------
    >>> from linecontact import Cylinder
    >>> cyl = Cylinder.from_modulus(50e-9, 100e9, cohesive_stress=1e9, adhesion_range=0.5e-9)
    >>> r = cylinder_steady_rolling(cyl, 1.0, friction_stress=1e9, d_over_a=0.0)
    >>> r.creep_ratio < 0
    True
    """
    return _cylinder_tangential("steady rolling", cylinder, normal_load, friction_stress,
                                friction_coefficient, d_over_a, tangential_load, method,
                                on_sliding)
