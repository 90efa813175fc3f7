r"""The faceted wire on its facet against an independent boundary-element solver.

Policy: :func:`linecontact.facet_contact` is a closed form
(``docs/faceted.md``, the Muskhelishvili inversion of the bounded solution); here the same
Maugis--Dugdale problem is discretised directly, with none of the library's formulas, and the
two are compared at several states, together with the solver's own convergence.

The solver
----------
Lengths over the circumradius :math:`R`, stresses over the composite modulus :math:`E`. The
profile is :math:`g(x) = (|x| - f)_+^2/(2r)`, :math:`f = (1 - r)\sin(\pi/n)`. A uniform
pressure :math:`p` on :math:`[x_1, x_2]` displaces the surface of the half-plane (plane
strain) by :math:`-(2p/\pi)[\phi(x - x_1) - \phi(x - x_2)]` plus a constant,
:math:`\phi(y) = y\ln|y|`: the exact influence of a strip, whose slope is
:math:`(2p/\pi)\ln|(x_2 - x)/(x_1 - x)|`, as :math:`dv/dx = (2/\pi)\,\mathrm{PV}\!\int
q(t)/(t - x)\,dt` requires. The contact :math:`[0, a]` is cut into :math:`N` elements of
constant pressure :math:`p_j` (each with its mirror image on :math:`[-a, 0]`), graded toward
the contact edge (:math:`x = a[1 - (1 - \xi)^2]`, uniform :math:`\xi`), and, when the contact
reaches onto the rounded corner (:math:`a > f`), with a node at the corner :math:`x = f`,
where the profile's curvature jumps: half the elements on :math:`[0, f]`, graded toward
:math:`f`, half on :math:`[f, a]`, graded toward both ends. The Dugdale tension
:math:`\sigma_0` on :math:`a < |x| < c` is two more strips, exact. The gap is
:math:`g(x) - \delta + v(x)`.

For a given :math:`a` the unknowns are the :math:`p_j`, the approach :math:`\delta` and
:math:`c`; the equations are

* the gap vanishes at the :math:`N` element midpoints;
* the pressure of the element at the edge equals the Dugdale stress,
  :math:`p_N = -\sigma_0`;
* the gap at :math:`c` is :math:`h` (:math:`1/\rho` over :math:`R`).

For a fixed :math:`c` the first two are linear in :math:`(p_j, \delta)`, with a matrix that
does not depend on :math:`c` (factorised once); :math:`c` is then the root of the third, a
scalar equation (Brent). The load is :math:`F = 2\sum_j p_j (x_{j+1} - x_j) - 2\sigma_0
(c - a)`.

Why that edge condition. The midpoint conditions alone leave one free mode, the flat-punch
pressure :math:`\propto (a^2 - x^2)^{-1/2}` together with a rigid shift of :math:`\delta`,
which keeps the gap zero on the contact. The Maugis--Dugdale solution is the member without
the square-root singularity: near the edge its pressure is :math:`-\sigma_0 + A\sqrt{a - x}
+ O((a - x)^{3/2})`, continuous with the Dugdale tension. In the discrete problem a jump
:math:`p_N + \sigma_0` between the last element and the Dugdale zone puts a term
:math:`(2/\pi)(p_N + \sigma_0)\ln|x - a|` in the gap's slope at the edge, the discrete image
of the singular mode; :math:`p_N = -\sigma_0` removes it. Against the exact solution, whose
average over the last element (width :math:`h_N`) is :math:`-\sigma_0 + \tfrac23 A
\sqrt{h_N}`, the condition leaves a singular amplitude of order :math:`A h_N`, and the
grading makes :math:`h_N = O(N^{-2})`: no worse than the collocation elsewhere. The
alternatives were set aside: a stationarity (energy) condition in :math:`a` vanishes
quadratically in the singular amplitude (the energy release rate is its square), no sign
change for a root finder; an extrapolation of several edge elements to the edge amplifies
their own discretisation error.

Convergence and the tolerance reached
-------------------------------------
A piecewise-constant pressure approximates :math:`p` to :math:`O(h)` pointwise, but the
midpoint collocation makes the first-order error odd on each element, so the integrated
quantities, :math:`F` and the gap at :math:`c` (hence :math:`c`), converge as :math:`N^{-2}`
(the ratio of successive errors measured is 4.00 to 4.02 at every state below). That order
is the limit of constant elements: the pressure's slope on each element is not represented,
an error of :math:`O(h^2)` in every integral of it, which the grading can spread evenly but
not remove (and the edge condition above carries the same order). The error is a clean
:math:`C N^{-2} + D N^{-3}`, so one Richardson step, :math:`(4 X_{2N} - X_N)/3`, leaves
:math:`O(N^{-3})`. Measured against the closed form (relative, :math:`c` and :math:`F`):
the raw solution with :math:`N = 1600` is within :math:`2.7\times10^{-6}` (worst: the
contact over the corner, where :math:`p` is least smooth) and :math:`8\times10^{-7}`
elsewhere; the extrapolation from :math:`N = 800, 1600` within :math:`1.8\times10^{-9}`
(over the corner) and :math:`1.5\times10^{-10}` elsewhere. Asserted: the raw errors
decrease with :math:`N` at the second order (each ratio in :math:`[3.9, 4.1]`), the raw
:math:`N = 1600` within :math:`10^{-5}` and the extrapolated within :math:`10^{-8}`. A
closed form wrong by :math:`2\times10^{-8}` fails the last, one wrong by :math:`10^{-7}`
also the ratios. A sharp corner that pins the zone (:math:`c = f`) is solved at that fixed
:math:`c`, without the gap condition, whose gap at :math:`f` must stay below :math:`h`. The
file runs in 5 to 8 s on two cores (the :math:`N = 1600` factorisations).
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.linalg import lu_factor, lu_solve
from scipy.optimize import brentq

import linecontact as lc

#: Element counts of the convergence study (each the double of the one before).
COUNTS = (100, 200, 400, 800, 1600)
#: Relative agreement asserted: the raw finest solution and the Richardson extrapolation.
RAW_RTOL = 1e-5
EXTRAPOLATED_RTOL = 1e-8


# --------------------------------------------------------------------------------------------
# the boundary-element solver


def _phi(y):
    """``y ln|y|`` (0 at ``y = 0``)."""
    y = np.asarray(y, dtype=float)
    ay = np.where(y == 0, 1.0, np.abs(y))
    return np.where(y == 0, 0.0, y * np.log(ay))


def _strips(x, x1, x2):
    """Surface displacement at ``x`` of a unit pressure on ``[x1, x2]`` and ``[-x2, -x1]``."""
    return -(2 / np.pi) * (_phi(x - x1) - _phi(x - x2) + _phi(x + x2) - _phi(x + x1))


def _profile(x, f, r):
    """The profile ``(|x| - f)_+^2 / (2 r)``; 0 on the facet of a sharp corner (``r = 0``)."""
    d = np.maximum(np.abs(x) - f, 0.0)
    return 0.0 * d if r == 0 else d * d / (2 * r)


def _graded(lo, hi, n, both):
    """``n + 1`` nodes on ``[lo, hi]``, quadratically graded toward ``hi`` (and ``lo``)."""
    xi = np.linspace(0.0, 1.0, n + 1)
    if both:
        t = np.where(xi < 0.5, 0.5 * (2 * xi) ** 2, 1 - 0.5 * (2 * (1 - xi)) ** 2)
    else:
        t = 1 - (1 - xi) ** 2
    return lo + (hi - lo) * t


def _mesh(a, f, N):
    """The element nodes on ``[0, a]``: graded toward ``a``, with a node at the corner ``f``."""
    if 0 < f < a:
        flat = _graded(0.0, f, N // 2, both=False)
        corner = _graded(f, a, N - N // 2, both=True)
        return np.concatenate([flat, corner[1:]])
    return _graded(0.0, a, N, both=False)


def bem_contact(a, rho, s, n, r, N, c=None):
    """``(c/R, F/(E h), gap at c over h)`` of the element solution with ``N`` elements.

    ``c``: a fixed end of the Dugdale zone (the gap condition at ``c`` then not imposed).
    """
    f = (1 - r) * np.sin(np.pi / n)
    nodes = _mesh(a, f, N)
    x1, x2 = nodes[:-1], nodes[1:]
    xm = 0.5 * (x1 + x2)
    # rows: the gap at each midpoint, then p_N = -s; columns: p_1..p_N, delta
    M = np.zeros((N + 1, N + 1))
    M[:N, :N] = _strips(xm[:, None], x1[None, :], x2[None, :])
    M[:N, N] = -1.0
    M[N, N - 1] = 1.0
    lu = lu_factor(M)

    def unknowns(c):
        rhs = np.empty(N + 1)
        rhs[:N] = -_profile(xm, f, r) + s * _strips(xm, a, c)
        rhs[N] = -s
        return lu_solve(lu, rhs)

    def gap_at(c):
        z = unknowns(c)
        v = _strips(c, x1, x2) @ z[:N] - s * _strips(c, a, c)
        return _profile(c, f, r) - z[N] + v

    if c is None:
        # the gap at c grows from 0 (c = a) with c; a sharp corner bounds the zone by f
        top = f if r == 0 else np.inf
        hi = min(2 * a, top)
        while gap_at(hi) < 1 / rho:
            assert hi < top, "the zone reaches the sharp corner: pinned"
            hi = min(a + 2 * (hi - a), top)
        c = brentq(lambda c: gap_at(c) - 1 / rho, a * (1 + 1e-12), hi, xtol=1e-15, rtol=1e-15)
    p = unknowns(c)[:N]
    F = rho * (2 * np.sum(p * (x2 - x1)) - 2 * s * (c - a))
    return c, F, rho * gap_at(c)


def convergence(a, rho, s, n, r):
    """``c`` and ``F`` per element count of :data:`COUNTS` and extrapolated from the last two."""
    runs = np.array([bem_contact(a, rho, s, n, r, N)[:2] for N in COUNTS])
    extrapolated = (4 * runs[-1] - runs[-2]) / 3
    return runs, extrapolated


# --------------------------------------------------------------------------------------------
# against the closed form

# (a/R, R/h, sigma0/E, sides, corner radius/R)
STATES = {
    "hexagon, contact on the facet": (0.2, 300.0, 0.01, 6, 0.3),
    "hexagon, contact over the corner": (0.45, 300.0, 0.01, 6, 0.3),
    "hexagon, over the corner, weak": (0.42, 1000.0, 0.005, 6, 0.3),
    "pentagon, sharp corner": (0.1, 1000.0, 0.02, 5, 0.0),
    "round wire": (0.05, 100.0, 0.01, 3, 1.0),
    "round wire, stiff adhesion": (0.1, 1000.0, 0.02, 6, 1.0),
}


@pytest.mark.parametrize("state", STATES.values(), ids=STATES.keys())
def test_elements_converge_to_the_closed_form(state):
    a, rho, s, n, r = state
    ref = lc.facet_contact(a, rho, s, sides=n, corner_radius_over_R=r)
    exact = np.array([ref.c_over_R, ref.F_over_Eh])
    runs, extrapolated = convergence(a, rho, s, n, r)
    err = np.abs(runs / exact - 1)  # rows: N; columns: c, F
    msg = f"a/R={a}, R/h={rho}, s={s}, n={n}, r={r}: relative errors {err.tolist()}"
    # second-order convergence toward the closed form, each doubling dividing the error by 4
    ratio = err[:-1] / err[1:]
    assert np.all((ratio > 3.9) & (ratio < 4.1)), f"{msg}, ratios {ratio.tolist()}"
    assert np.all(err[-1] < RAW_RTOL), msg
    np.testing.assert_allclose(extrapolated, exact, rtol=EXTRAPOLATED_RTOL, atol=0, err_msg=msg)
    if r == 1:  # the round wire (any number of sides): the normal contact's closed form too
        round_wire = lc.normal_contact(a, rho, s)
        np.testing.assert_allclose(
            extrapolated,
            [round_wire.c_over_R, round_wire.F_over_Eh],
            rtol=EXTRAPOLATED_RTOL,
            atol=0,
            err_msg=msg,
        )


def test_sharp_corner_pins_the_zone():
    # the free zone would pass the corner: the gap at c = f is still below h, and with the
    # zone stopped there the load is the library's corner-pinned one
    a, rho, s, n = 0.05, 100.0, 0.01, 5
    ref = lc.facet_contact(a, rho, s, sides=n, corner_radius_over_R=0.0)
    assert ref.region == "corner-pinned"
    f = ref.facet_half_width_over_R
    runs = np.array([bem_contact(a, rho, s, n, 0.0, N, c=f) for N in COUNTS])
    assert np.all(runs[:, 2] < 1), runs[:, 2]  # gap(f) / h
    err = np.abs(runs[:, 1] / ref.F_over_Eh - 1)
    ratio = err[:-1] / err[1:]
    assert np.all((ratio > 3.9) & (ratio < 4.1)), err
    extrapolated = (4 * runs[-1, 1] - runs[-2, 1]) / 3
    np.testing.assert_allclose(extrapolated, ref.F_over_Eh, rtol=EXTRAPOLATED_RTOL, atol=0)


@pytest.mark.parametrize(("rho", "s", "n", "r"), [(1e3, 0.02, 6, 0.3), (1e3, 0.02, 5, 0.1)])
def test_elements_at_the_pull_off(rho, s, n, r):
    """At the pull-off's width (a minimum inside the branch) the elements' load is the
    pull-off force, and the elements' own loads a little to either side are above it."""
    p = lc.facet_pull_off(rho, s, sides=n, corner_radius_over_R=r)
    a0 = p.a_over_R_at_pulloff
    assert p.mechanism == "inside-facet" and a0 > 0
    _, extrapolated = convergence(a0, rho, s, n, r)
    np.testing.assert_allclose(extrapolated[1], p.F_pulloff_over_Eh, rtol=EXTRAPOLATED_RTOL)
    for side in (0.97, 1.03):
        _, beside = convergence(a0 * side, rho, s, n, r)
        assert beside[1] > extrapolated[1]
