r"""An independent numerical check of the Maugis--Dugdale sphere: rings of uniform pressure.

Nothing here uses :mod:`linecontact.sphere._branch` or the library's closed forms; the
library is only called for the values compared against.

The elastic kernel
------------------
A uniform pressure ``p`` on a disc of radius ``b`` on an elastic half-space (composite
modulus ``E``, both bodies deforming) displaces the surface normally by

- ``(4 p b/(pi E)) E(r/b)`` for ``r <= b``,
- ``(4 p r/(pi E)) [E(b/r) - (1 - b^2/r^2) K(b/r)]`` for ``r > b``

(``K``, ``E`` the complete elliptic integrals of modulus ``k``; scipy takes ``m = k^2``).
For ``m <= 1/2`` the outer bracket, which cancels to ``m pi/4`` as ``m -> 0``, is computed
as ``m (K(m) - R_D(0, 1 - m, 1)/3)`` (Carlson's ``R_D``: ``K - E = (m/3) R_D``), for
``m > 1/2`` directly with ``(1 - m) K`` from ``ellipkm1``. The kernel is checked first
(:func:`test_disc_kernel_reproduces_hertz`, :func:`test_disc_kernel_known_values`): the
Hertz pressure ``p0 sqrt(1 - r^2/a^2)``, superposed from discs by quadrature, gives
Johnson's displacement (Contact Mechanics, Eqs 3.41a and 3.42b) inside and outside, and a
uniform disc gives ``2 p b/E`` at its centre, ``4 p b/(pi E)`` at its rim and Boussinesq's
``P/(pi E r)`` far away.

The formulation
---------------
The surface stress (tension negative) is written as a uniform ``-sigma0`` over the whole
disc ``r < c`` -- one disc, exact -- plus a pressure ``q(r)`` on the contact ``r < a``
only. Then the adhesive zone ``a < r < c`` carries exactly ``-sigma0`` (Dugdale) and the
contact carries ``q - sigma0``. ``q`` is piecewise constant on ``N`` rings with edges
``b_k = a sin(pi k/(2N))`` (a cosine map: in ``theta``, ``r = a sin(theta)``, the
square-root behaviour at the edge is smooth, and the last ring is ``~ a pi^2/(8 N^2)``
wide); a ring's displacement is that of its outer disc less its inner disc. Collocation is
at the ring mid-points in ``theta``, ``r_j = a sin(pi (j - 1/2)/(2N))``, where the surface
displacement equals ``delta - r_j^2/(2R)`` (the parabolic profile, as Maugis).

Regularity: for given ``(a, c, delta)`` the contact problem has one solution, which in
general carries the flat punch's ``1/sqrt(a^2 - r^2)`` singularity at the edge, its
strength linear in ``delta`` (the flat punch displaces the contact uniformly, as ``delta``
does). The Maugis--Dugdale solution is the one with bounded stress: the stress is then
continuous at ``r = a``, ``q(a) = 0`` with ``q ~ sqrt(a - r)``. It is imposed by setting
the edge ring's ``q_N = 0``. So, at a trial ``c``: unknowns ``q_1 .. q_{N-1}`` and
``delta``, ``N`` collocation equations -- a square linear system, whose matrix (lengths
over ``a``) depends on ``N`` alone and is factorised once; ``c`` enters only the
right-hand side, through the ``-sigma0`` disc. The remaining condition, the gap at ``c``,

    ``gap(c) = c^2/(2R) - delta + w(c) = h``  (``w`` from every load, the disc included),

is a scalar equation in ``c/a > 1``, solved by ``brentq`` (it rises from ``-h`` at
``c = a``). The load is ``F = 2 pi sum q_i r dr - sigma0 pi c^2``; in the groups
``F/(E h R) = rho pi alpha^2 (sum q_i/E (xi_i^2 - xi_{i-1}^2) - s (c/a)^2)``.

Refinement (measured, lengths over ``a``, max over ``F/(E h R)``, ``delta/h``, ``c/R`` of
the relative difference from :func:`linecontact.sphere.sphere_contact`; worst of the 18
curve points below, which is ``lambda = 1``, ``a = 1.2`` Maugis units)::

      N     raw        Richardson (N, 2N)   spread |R(N,2N) - R(2N,4N)|
     50   1.7e-02      1.0e-05              9.0e-06
    100   4.2e-03      1.3e-06              1.1e-06
    200   1.1e-03      1.6e-07              1.4e-07
    400   2.6e-04      1.9e-08              1.7e-08
    800   6.6e-05      2.4e-09              2.1e-09
   1600   1.6e-05      2.6e-10
   3200   4.1e-06

The error is ``C2/N^2 + C3/N^3`` (observed order 1.998 to 2.009 over N = 400, 800, 1600 at
every point; the Richardson values improve 8-fold per doubling), so ``R = (4 v_2N - v_N)/3``
is used, from the levels :data:`LEVELS` = (400, 800, 1600): ``R(800, 1600)``, with the
spread to ``R(400, 800)`` as its own error estimate (about 7 times its actual error). Over
all points the worst actual difference of ``R(800, 1600)`` from the library is 2.4e-9 and
the worst spread 1.7e-8; the tolerance :data:`TOL` = 1e-7 keeps a factor of 6 over the
solver's own estimate, and each comparison also asserts that the spread is below ``TOL/2``,
so that a point where the rings were not converged fails as such, not as a library error.

The pull-off is the minimum over ``a`` of the extrapolated ring load (load control) or
approach (displacement control), by ``minimize_scalar`` on ``log a``; its value agrees with
:func:`linecontact.sphere.sphere_pull_off` to 1e-10 or better (measured), its radius, which
a flat minimum fixes only to about the square root of the value's error, to 7e-6.
"""

from __future__ import annotations

import math
from functools import cache

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.linalg import lu_factor, lu_solve
from scipy.optimize import brentq, minimize_scalar
from scipy.special import ellipe, ellipk, ellipkm1, elliprd

from linecontact.sphere import sphere_contact, sphere_contact_for_load, sphere_pull_off

#: Ring counts of the three levels (Richardson on the last two pairs).
LEVELS = (400, 800, 1600)

#: Relative agreement with the library (see the module docstring for the measurement).
TOL = 1e-7

#: Maugis' lambda -> R/h; sigma0/E follows from lambda (the Maugis--Dugdale curve in Maugis'
#: units depends on lambda alone, so three different R/h also exercise the groups' scaling).
CASES = {0.1: 1e4, 1.0: 1e6, 5.0: 1e8}

#: Contact radii in Maugis' unit (pi w R^2/K)^(1/3) along the curve: on both sides of the
#: load-control pull-off, which is at 0.199, 0.904 and 1.126 for lambda = 0.1, 1, 5
#: (checked in test_pull_off_load_control); none where F or delta crosses zero.
ABAR = (0.05, 0.12, 0.3, 0.6, 1.2, 2.5)

CURVE = [(lam, abar) for lam in CASES for abar in ABAR]


def params(lam: float) -> tuple[float, float, float]:
    """``(R/h, sigma0/E, Maugis' unit of length over R)`` at Maugis' ``lambda``."""
    rho = CASES[lam]
    s = math.sqrt((lam / 2) ** 3 * 16 * math.pi / (9 * rho))  # lambda = 2 (9 s^2 rho/(16 pi))^(1/3)
    unit = (3 * math.pi * s / (4 * rho)) ** (1 / 3)  # (pi w R^2/K)^(1/3)/R, K = 4E/3, w = s h E
    return rho, s, unit


# --- the kernel ---------------------------------------------------------------------------


def disc(b, r):
    """Normal displacement at ``r`` of a unit pressure on the disc ``r < b`` (``E = 1``)."""
    b, r = np.broadcast_arrays(np.asarray(b, float), np.asarray(r, float))
    out = np.zeros(b.shape)
    inside = (r <= b) & (b > 0)
    out[inside] = (4 * b[inside] / np.pi) * ellipe((r[inside] / b[inside]) ** 2)
    outside = (r > b) & (b > 0)
    ro, bo = r[outside], b[outside]
    m = (bo / ro) ** 2
    p = (ro - bo) * (ro + bo) / ro**2  # 1 - m without cancellation
    near = m > 0.5
    val = np.empty(ro.shape)
    val[near] = (4 * ro[near] / np.pi) * (ellipe(m[near]) - p[near] * ellipkm1(p[near]))
    far = ~near  # E - (1 - m) K = m (K - R_D(0, 1 - m, 1)/3): no cancellation as m -> 0
    val[far] = (4 * bo[far] ** 2 / (np.pi * ro[far])) * (
        ellipk(m[far]) - elliprd(0.0, p[far], 1.0) / 3
    )
    out[outside] = val
    return out


def hertz_displacement(r: float) -> float:
    """Johnson (Eqs 3.41a, 3.42b): ``p0 = a = E = 1``."""
    if r <= 1:
        return np.pi * (2 - r * r) / 4
    return 0.5 * ((2 - r * r) * math.asin(1 / r) + math.sqrt(r * r - 1))


@pytest.mark.parametrize("r", [0.0, 0.3, 0.7, 0.99, 1.0, 1.5, 3.0, 10.0])
def test_disc_kernel_reproduces_hertz(r):
    # p(r) = sqrt(1 - r^2) is the superposition of discs of radius b = sin(t) with pressure
    # -p'(b) db = sin(t) dt
    def integrand(t):
        return math.sin(t) * float(disc(math.sin(t), r))

    brk = [math.asin(r)] if 0 < r < 1 else None
    got = quad(integrand, 0, np.pi / 2, points=brk, limit=200, epsabs=1e-14, epsrel=1e-13)[0]
    want = hertz_displacement(r)
    assert abs(got - want) <= 1e-10 * abs(want), (
        f"Hertz pressure at r/a = {r}: discs give {got!r}, Johnson {want!r}"
    )


def test_disc_kernel_known_values():
    b = 0.7
    assert abs(disc(b, 0.0) - 2 * b) <= 1e-15, "uniform disc at its centre: 2 p b/E"
    assert abs(disc(b, b) - 4 * b / np.pi) <= 1e-15, "uniform disc at its rim: 4 p b/(pi E)"
    for r in (1e2, 1e4, 1e8):  # Boussinesq P/(pi E r) (1 + m/8 + 3 m^2/64 + ...)
        m = (b / r) ** 2
        want = b * b / r * (1 + m / 8 + 3 * m * m / 64)
        assert abs(disc(b, r) - want) <= 1e-13 * want, f"uniform disc far away, r/b = {r / b}"
    # continuity across the rim, where the two formulas meet
    eps = 1e-9
    assert abs(disc(b, b * (1 + eps)) - disc(b, b * (1 - eps))) <= 1e-7, "disc rim jump"


# --- the ring solver ----------------------------------------------------------------------


class Rings:
    """``N`` rings on the contact ``0 < r < a`` (lengths over ``a``), the edge ring at zero."""

    def __init__(self, n: int):
        k = np.arange(n + 1)
        self.n = n
        self.b = np.sin(np.pi * k / (2 * n))
        self.b[-1] = 1.0
        self.r = np.sin(np.pi * (k[1:] - 0.5) / (2 * n))
        self.area = self.b[1:] ** 2 - self.b[:-1] ** 2  # ring areas over pi a^2
        ring = np.diff(disc(self.b[None, :], self.r[:, None]), axis=1)  # ring i at point j
        mat = np.empty((n, n))
        mat[:, : n - 1] = ring[:, : n - 1]  # q_N = 0: bounded stress at r = a
        mat[:, n - 1] = -1.0  # the unknown delta/a
        self.lu = lu_factor(mat)

    def solve(self, alpha: float, rho: float, s: float) -> np.ndarray:
        """``(F/(E h R), delta/h, c/R)`` at ``a/R = alpha``.

        Over ``a``: sum_i q_i G_i(xi_j) - delta/a = -alpha xi_j^2/2 + s disc(gamma, xi_j),
        with ``gamma = c/a``; the gap condition over ``h`` is
        rho alpha (alpha gamma^2/2 - delta/a + sum_i q_i G_i(gamma) - s 4 gamma/pi) = 1.
        """
        hertz = lu_solve(self.lu, -alpha * self.r**2 / 2)

        def state(gamma):
            y = hertz + s * lu_solve(self.lu, disc(gamma, self.r))
            q, t = y[:-1], y[-1]
            at_c = np.diff(disc(self.b, gamma))[:-1]
            w = q @ at_c - s * 4 * gamma / np.pi  # the -sigma0 disc at its own rim
            return rho * alpha * (alpha * gamma * gamma / 2 - t + w) - 1, q, t

        hi = 1.5
        while state(hi)[0] < 0:
            hi = 1 + 2 * (hi - 1)
        gamma = brentq(lambda g: state(g)[0], 1 + 1e-15, hi, xtol=1e-15, rtol=1e-15, maxiter=200)
        _, q, t = state(gamma)
        F = rho * np.pi * alpha**2 * (q @ self.area[:-1] - s * gamma * gamma)
        return np.array([F, rho * alpha * t, alpha * gamma])


@cache
def rings(n: int) -> Rings:
    return Rings(n)


def levels(alpha: float, rho: float, s: float) -> np.ndarray:
    """The three levels' ``(F, delta, c)``, one row each."""
    return np.array([rings(n).solve(alpha, rho, s) for n in LEVELS])


def extrapolated(v: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Richardson (order 2) on the finest pair, and its spread to the coarser pair's."""
    fine = (4 * v[2] - v[1]) / 3
    coarse = (4 * v[1] - v[0]) / 3
    return fine, np.abs(fine - coarse)


@cache
def curve_point(lam: float, abar: float) -> np.ndarray:
    rho, s, unit = params(lam)
    return levels(abar * unit, rho, s)


NAMES = ("F_over_EhR", "delta_over_h", "c_over_R")


@pytest.mark.parametrize(("lam", "abar"), CURVE, ids=[f"lam={la}-a={ab}" for la, ab in CURVE])
def test_ring_refinement_is_second_order(lam, abar):
    v = curve_point(lam, abar)
    order = np.log2(np.abs(v[0] - v[1]) / np.abs(v[1] - v[2]))
    for name, p in zip(NAMES, order, strict=True):
        assert 1.9 <= p <= 2.1, (
            f"{name}: observed order {p:.3f} over N = {LEVELS} at lambda = {lam}, "
            f"a = {abar} Maugis units"
        )


@pytest.mark.parametrize(("lam", "abar"), CURVE, ids=[f"lam={la}-a={ab}" for la, ab in CURVE])
def test_ring_curve_matches_sphere_contact(lam, abar):
    rho, s, unit = params(lam)
    alpha = abar * unit
    ring, spread = extrapolated(curve_point(lam, abar))
    lib = sphere_contact(alpha, rho, s)
    for i, name in enumerate(NAMES):
        want = float(getattr(lib, name))
        where = (
            f"{name} at a/R = {alpha!r} ({abar} Maugis units), R/h = {rho!r}, "
            f"sigma0/E = {s!r} (lambda = {lam})"
        )
        assert spread[i] <= TOL / 2 * abs(ring[i]), (
            f"rings not converged: spread {spread[i]!r} of {ring[i]!r}, {where}"
        )
        assert abs(ring[i] - want) <= TOL * abs(want), (
            f"rings {ring[i]!r} vs library {want!r} (rel {(ring[i] - want) / want:.2e}), {where}"
        )


def test_ring_solver_hertz_limit():
    # sigma0 = 0: Hertz, F = K a^3/R, delta = a^2/R in the groups
    rho, alpha = 1e6, 1e-3
    ring, spread = extrapolated(levels(alpha, rho, 0.0))
    for i, want in enumerate(((4 / 3) * rho * alpha**3, rho * alpha**2)):
        assert abs(ring[i] - want) <= TOL * want, (
            f"{NAMES[i]}: rings {ring[i]!r} vs Hertz {want!r} at a/R = {alpha}, R/h = {rho}"
        )
        assert spread[i] <= TOL / 2 * want, f"{NAMES[i]}: Hertz rings not converged"


# --- the pull-off ---------------------------------------------------------------------------


@cache
def ring_minimum(lam: float, of: int) -> tuple[float, float, float]:
    """The rings' minimum of the load (``of=0``) or the approach (``of=1``) over the
    contact radius: ``(abar, value, spread)``, ``abar`` in Maugis units.
    """
    rho, s, unit = params(lam)

    def value(log_abar):
        return extrapolated(levels(math.exp(log_abar) * unit, rho, s))[0][of]

    res = minimize_scalar(
        value, bounds=(math.log(0.01), math.log(5.0)), method="bounded", options={"xatol": 1e-8}
    )
    abar = math.exp(res.x)
    _, spread = extrapolated(levels(abar * unit, rho, s))
    return abar, float(res.fun), float(spread[of])


def check_pull_off(lam: float, control: str, of: int, stable_field: str) -> None:
    rho, s, unit = params(lam)
    abar, ring, spread = ring_minimum(lam, of)
    po = sphere_pull_off(rho, s, control=control)
    name = "F_pulloff_over_EhR" if of == 0 else "delta_over_h_at_pulloff"
    want = float(getattr(po, name))
    where = f"{control} control, R/h = {rho!r}, sigma0/E = {s!r} (lambda = {lam})"
    assert spread <= TOL / 2 * abs(ring), f"rings not converged at the minimum: {where}"
    assert abs(ring - want) <= TOL * abs(want), (
        f"{name}: rings' minimum {ring!r} vs library {want!r} "
        f"(rel {(ring - want) / want:.2e}), {where}"
    )
    # the minimum's radius: a flat minimum fixes it to about sqrt(its value's error);
    # measured 7e-6 at worst (lambda = 1, displacement control)
    a_lib = float(po.a_over_R_at_pulloff) / unit
    assert abs(abar - a_lib) <= 1e-4 * a_lib, (
        f"radius at pull-off: rings {abar!r}, library {a_lib!r} (Maugis units), {where}"
    )
    # the curve points lie on both sides of it, and the library's stability flags agree
    below = [a for a in ABAR if a < abar]
    assert below and len(below) < len(ABAR), f"curve points all on one side, {where}"
    flags = getattr(sphere_contact(np.array(ABAR) * unit, rho, s), stable_field)
    assert list(flags) == [a > abar for a in ABAR], (
        f"{stable_field} {list(flags)} at a = {ABAR} vs the rings' pull-off {abar:.6f}, {where}"
    )


@pytest.mark.parametrize("lam", [0.1, 1.0, 5.0])
def test_pull_off_load_control(lam):
    check_pull_off(lam, "load", 0, "stable")


@pytest.mark.parametrize("lam", [1.0, 5.0])  # at lambda = 0.1 it peels to a = 0 (no minimum)
def test_pull_off_displacement_control(lam):
    check_pull_off(lam, "displacement", 1, "stable_displacement")


@pytest.mark.parametrize("lam", [0.1, 1.0, 5.0])
def test_contact_for_load_inverts_ring_curve(lam):
    # on the stable side, sphere_contact_for_load at the rings' load gives back the radius
    rho, s, unit = params(lam)
    for abar in (a for a in ABAR if a > ring_minimum(lam, 0)[0]):
        ring, _ = extrapolated(curve_point(lam, abar))
        got = float(sphere_contact_for_load(ring[0], rho, s).a_over_R)
        want = abar * unit
        assert abs(got - want) <= TOL * want, (  # measured 4e-10 at worst
            f"a/R at the rings' load {ring[0]!r}: library {got!r}, rings {want!r} "
            f"({abar} Maugis units), R/h = {rho!r}, sigma0/E = {s!r} (lambda = {lam})"
        )
