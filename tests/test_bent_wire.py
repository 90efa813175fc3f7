"""The shape of a wire dragged at its midpoint (:mod:`linecontact.bent_wire`), checked two ways.

- **Small loads**: the cantilever under a uniform load, the end lag f l^4/(8 EI) and the
  midpoint curvature f l^2/(2 EI), to 1e-8 at Lambda = 1e-6, the departure second order.
- **Two independent solvers written here**: SciPy's ``solve_bvp`` (collocation with its own
  mesh) and shooting with ``solve_ivp`` (an adaptive Runge--Kutta method) on the same
  boundary-value problem, to 1e-7 at large deflection.
- **Equilibrium**: the moment at the midpoint is the friction's moment about it,
  :math:`\\theta'(0) = -\\Lambda\\int_0^1 x\\,du`, from the returned shape.
- **Convergence** in the collocation points (spectral).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from numpy.polynomial import chebyshev as C

from linecontact.bent_wire import dragged_wire
from linecontact.bent_wire.elastica import LAMBDA_MAX
from linecontact.errors import ParameterError


def _bvp(lam: float):
    """The problem by SciPy's solve_bvp: (end lag, end angle, midpoint curvature)."""
    from scipy.integrate import solve_bvp

    def f(u, y):  # y = theta, theta', x, y
        return np.vstack([y[1], lam * (1 - u) * np.cos(y[0]), np.cos(y[0]), np.sin(y[0])])

    def bc(a, b):
        return np.array([a[0], b[1], a[2], a[3]])

    u = np.linspace(0, 1, 201)
    guess = np.zeros((4, u.size))
    guess[2] = u
    sol = solve_bvp(f, bc, u, guess, tol=1e-11, max_nodes=200000)
    assert sol.success, sol.message
    end = sol.sol(1.0)
    return -end[3], end[0], sol.sol(0.0)[1]


def _shooting(lam: float, k0: float):
    """The problem by shooting with solve_ivp on the midpoint curvature (brentq)."""
    from scipy.integrate import solve_ivp
    from scipy.optimize import brentq

    def end(k: float):
        f = lambda u, y: [y[1], lam * (1 - u) * math.cos(y[0]), math.cos(y[0]), math.sin(y[0])]  # noqa: E731
        return solve_ivp(f, (0, 1), [0, k, 0, 0], rtol=1e-12, atol=1e-13).y[:, -1]

    k = brentq(lambda k: end(k)[1], 1.5 * k0 - 0.5, 0.5 * k0 + 0.5, xtol=1e-14)
    e = end(k)
    return -e[3], e[0], k


def test_small_loads_are_the_cantilever_under_a_uniform_load():
    lam = np.array([1e-6, 2e-6])
    w = dragged_wire(lam)
    lag = np.asarray(w.end_lag_over_l) / (lam / 8)
    curv = np.asarray(w.midpoint_curvature) / (-lam / 2)
    assert np.all(np.abs(lag - 1) < 1e-8) and np.all(np.abs(curv - 1) < 1e-8)
    # the departure is second order in the load (the slopes' cosines)
    big = dragged_wire([1e-2, 2e-2])
    d = np.asarray(big.end_lag_over_l) / (np.array([1e-2, 2e-2]) / 8) - 1
    assert d[0] < 0 and 3.9 < d[1] / d[0] < 4.1


@pytest.mark.parametrize("lam", [1.0, 10.0, 40.0, LAMBDA_MAX])
def test_against_two_independent_solvers(lam):
    w = dragged_wire(lam)
    for lag, angle, curv in (_bvp(lam), _shooting(lam, w.midpoint_curvature)):
        assert w.end_lag_over_l == pytest.approx(lag, abs=1e-7)
        assert w.end_angle == pytest.approx(angle, abs=1e-7)
        assert w.midpoint_curvature == pytest.approx(curv, rel=1e-7)


@pytest.mark.parametrize("lam", [0.5, 20.0, 60.0])
def test_the_midpoint_moment_is_the_frictions_moment(lam):
    w = dragged_wire(lam)
    t = 2 * w.u - 1
    c = C.chebint(C.chebfit(t, w.x_over_l, w.nodes), lbnd=-1) / 2
    moment = -lam * C.chebval(1.0, c)
    assert w.midpoint_curvature == pytest.approx(moment, rel=1e-10)
    # and the wire keeps its length: |r'| = 1 along the shape
    assert abs(w.x_over_l[0]) < 1e-15 and abs(w.y_over_l[0]) < 1e-15
    assert 0 < w.end_shortening_over_l < 1 and w.end_angle < 0


def test_spectral_convergence_in_the_nodes():
    lam = [1.0, 30.0, 60.0]
    coarse, fine, finer = (dragged_wire(lam, nodes=n) for n in (24, 48, 96))
    d1 = np.max(np.abs(np.asarray(coarse.end_lag_over_l) - finer.end_lag_over_l))
    d2 = np.max(np.abs(np.asarray(fine.end_lag_over_l) - finer.end_lag_over_l))
    assert d2 < 1e-11 and d2 < d1
    assert np.all(fine.converged) and np.all(np.asarray(fine.residual) < 1e-8)


def test_arrays_in_arrays_out_and_zero_is_straight():
    w = dragged_wire(np.zeros((2, 3)))
    assert np.shape(w.end_lag_over_l) == (2, 3) and w.theta.shape == (2, 3, 49)
    assert np.all(np.asarray(w.end_lag_over_l) == 0.0)
    assert np.all(np.abs(w.x_over_l[..., -1] - 1.0) < 1e-14)
    one = dragged_wire(1.0)
    assert isinstance(one.end_lag_over_l, float)


@pytest.mark.parametrize(
    ("kw", "name", "match"),
    [
        ({"friction_group": -1.0}, "friction_group", r"\[0, 60\]"),
        ({"friction_group": 61.0}, "friction_group", r"\[0, 60\]"),
        ({"friction_group": math.nan}, "friction_group", "friction_group"),
        ({"friction_group": 1.0, "nodes": 4}, "nodes", r"nodes must be an integer in \[8, 512\]"),
        ({"friction_group": 1.0, "nodes": 8.5}, "nodes", "nodes must be an integer"),
        ({"friction_group": 1.0, "nodes": True}, "nodes", "nodes must be an integer"),
    ],
)
def test_bad_input_is_refused_naming_it(kw, name, match):
    with pytest.raises(ParameterError, match=match) as err:
        dragged_wire(**kw)
    assert err.value.parameter == name
