"""Slide or tip (linecontact.facet.tipping): the JKR-limit criterion checked a second way.

The closed form rests on the pressure of a rigid flat punch under a load and a moment, on
the crack criterion at its trailing edge, and on the receding contact's moment. The check
here takes none of them from the module: a Gauss--Chebyshev collocation of the tilted punch
(``sie.UnboundedSolver``, exact for its linear right-hand side) gives the pressure and the
trailing edge's stress intensity; the rotation that brings it to the Griffith value is
solved for at each receding width ``b'``, and the moment the wire then holds is maximised
over ``b'`` numerically. Its maximum is the tipping moment.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import linecontact as lc
from linecontact.facet.tipping import JKR_RTOL, tipping_moment
from linecontact.sie import UnboundedSolver

N = 64  # the punch's pressure is g / sqrt(1 - t^2) with g linear: any n >= 2 is exact


def _punch(b: float, P: float, theta: float):
    """Node values ``g`` and the solver of a flat punch on [-b, b] turned by ``theta``.

    (1/pi) PV int p(t)/(t - x) dt = (E/2) theta with E = 1 (the surface follows the rotated
    face), and the resultant P.
    """
    solver = UnboundedSolver(N, (-b, b))
    g = solver.solve(np.full(N - 1, 0.5 * theta), P)
    return solver, g


def _moment_and_K(b: float, P: float, theta: float) -> tuple[float, float]:
    """The first moment of the pressure about the centre and K (tension) at x = -b."""
    solver, g = _punch(b, P, theta)
    M = float(g @ (solver.weights * solver.nodes))
    # g at the trailing end t = -1 from its Chebyshev interpolant (g is linear: exact)
    t = solver.nodes_unit
    slope, intercept = np.polyfit(t, g, 1)
    K = -(intercept - slope) * math.sqrt(math.pi * b)
    return M, K


@pytest.mark.parametrize(("b", "P", "theta"), [(1.0, 2.0, 0.3), (0.5, -1.0, -0.7), (2.0, 0.0, 1.0)])
def test_the_punchs_pressure_and_its_stress_intensity(b, P, theta):
    solver, g = _punch(b, P, theta)
    M = float(g @ (solver.weights * solver.nodes))
    want = (P + 2 * M * solver.nodes / b**2) / (math.pi * b)  # g of the closed form
    np.testing.assert_allclose(g, want, rtol=1e-12, atol=1e-13)
    _, K = _moment_and_K(b, P, theta)
    assert K == pytest.approx((2 * M / b - P) / math.sqrt(math.pi * b), rel=1e-11, abs=1e-12)


def _tipping_by_collocation(P: float, b: float, Kc: float) -> float:
    """max over b' of the moment held with the trailing crack at K = Kc (the numerical way)."""
    best = -math.inf
    for bp in b * np.concatenate([np.geomspace(1e-6, 1.0, 400), [1.0]]):
        M0, K0 = _moment_and_K(bp, P, 0.0)
        M1, K1 = _moment_and_K(bp, P, 1.0)
        theta = (Kc - K0) / (K1 - K0)  # K is linear in the rotation
        Mp = M0 + theta * (M1 - M0)  # about the contact's centre
        best = max(best, Mp + P * (b - bp))  # about the wire's: the centre at b - b'
    return best


@pytest.mark.parametrize("P_over_Fs", [-0.9, -0.5, 0.0, 0.5, 1.0, 1.2, 1.5, 2.0, 5.0])
def test_the_tipping_moment_is_the_receding_contacts_largest(P_over_Fs):
    b, E, w = 0.5, 1.0, 1e-3
    Fs = math.sqrt(2 * math.pi * b * E * w)  # the strip's pull-off, |F_s|
    P = P_over_Fs * Fs
    Kc = math.sqrt(2 * E * w)
    numeric = _tipping_by_collocation(P, b, Kc)
    closed = float(tipping_moment(np.array(P), np.array(b), np.array(-Fs)))
    # the grid of b' reaches 1e-6 b: the rigid limit F b to 1e-6 relative
    assert numeric == pytest.approx(closed, rel=2e-6, abs=1e-12)


def test_the_limits():
    b, Fs = 0.5, -0.3
    # no adhesion: the rigid body's F b; at the pull-off: nothing holds it
    assert tipping_moment(np.array(2.0), np.array(b), np.array(0.0)) == pytest.approx(2.0 * b)
    assert tipping_moment(np.array(Fs), np.array(b), np.array(Fs)) == pytest.approx(0.0)
    # continuous where the peel turns into the corner's tipping (F = |F_s|)
    at = tipping_moment(np.array([abs(Fs) - 1e-9, abs(Fs) + 1e-9]), np.array(b), np.array(Fs))
    assert abs(at[1] - at[0]) < 1e-8


def test_slide_or_tip_and_the_critical_height():
    t = lc.facet_tipping([0.0, 0.0], [0.1, 1.9], 1e-4, 1e6, 0.01)
    assert list(t.first_motion) == ["slide", "tip"]
    H = t.H_star_over_R[0]
    below = lc.facet_tipping(0.0, 0.999 * H, 1e-4, 1e6, 0.01)
    above = lc.facet_tipping(0.0, 1.001 * H, 1e-4, 1e6, 0.01)
    assert below.first_motion == "slide" and above.first_motion == "tip"
    assert abs(t.jkr_error[0]) < JKR_RTOL
    # the facet's sliding push is the initiation of sliding's full slip, 2 b tau0
    f = math.sin(math.pi / 6)
    assert t.T_slide_over_Eh[0] == pytest.approx(2 * f * 1e6 * 1e-4)


def test_outside_the_jkr_limit_or_the_pull_off_it_says_so():
    with pytest.raises(ValueError, match="written in the JKR limit"):
        lc.facet_tipping(0.0, 1.0, 0.01, 171.0, 0.00684)
    with pytest.raises(lc.NoEquilibriumError, match="below the facet's pull-off"):
        lc.facet_tipping(-1e6, 1.0, 0.01, 1e6, 0.01)
    with pytest.raises(ValueError, match="H_over_R"):
        lc.facet_tipping(0.0, 3.0, 0.01, 1e6, 0.01)
