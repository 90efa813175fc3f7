"""Tests of the Gauss--Chebyshev singular-integral core, `linecontact.sie`.

Policy (STYLE habit 9): exactness by construction (Gauss rules, analytic Cauchy pairs), the
explicit Erdogan--Gupta--Cook matrix of the paper's Appendix A (Eqs. A3--A5), independent
quadrature (scipy) for the linear functionals, hypothesis with fixed seeds.
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from numpy.testing import assert_allclose, assert_array_equal
from scipy.integrate import quad
from scipy.special import beta, eval_chebyt, eval_chebyu, roots_chebyt, roots_chebyu, roots_jacobi

from linecontact.sie import (
    BoundedSolver,
    EndBoundedSolver,
    UnboundedSolver,
    bounded_rule,
    chebyshev_log_expansion,
)

SETTINGS = settings(derandomize=True, max_examples=40, deadline=None)


# --------------------------------------------------------------------------------------------
# helpers: analytic pairs and independent quadrature


def dugdale_f(x, m):
    """(1/pi) ln((m - x)/(m + x)): the right-hand side of the Dugdale pair, m > 1."""
    return np.log((m - x) / (m + x)) / np.pi


def dugdale_phi(t, m):
    """(2/pi) arctan(sqrt((1 - t^2)/(m^2 - 1))): bounded solution of the Dugdale pair."""
    return (2 / np.pi) * np.arctan(np.sqrt((1 - t * t) / (m * m - 1)))


def dugdale_resultant(m):
    return 2 * (m - np.sqrt(m * m - 1))


def weighted_moment(k):
    """Exact int_{-1}^{1} sqrt(1 - t^2) t^k dt."""
    if k % 2:
        return 0.0
    return beta((k + 1) / 2, 1.5)


def quad_log_inside(func, y, lo, hi):
    """int_lo^hi func(t) ln|y - t| dt by scipy quad, the log point given as a break point."""
    pts = [y] if lo < y < hi else None
    val, _ = quad(
        lambda t: func(t) * np.log(abs(y - t)),
        lo,
        hi,
        points=pts,
        limit=200,
        epsabs=1e-14,
        epsrel=1e-12,
    )
    return val


# --------------------------------------------------------------------------------------------
# bounded_rule


@pytest.mark.parametrize("n", [1, 2, 3, 7, 16, 51])
def test_bounded_rule_matches_scipy_roots_chebyu(n):
    nodes, weights, colloc = bounded_rule(n)
    ref_nodes, ref_weights = roots_chebyu(n)  # ascending, weight sqrt(1 - t^2)
    assert nodes.shape == weights.shape == (n,)
    assert colloc.shape == (n + 1,)
    assert np.all(np.diff(nodes) < 0), "nodes must be decreasing"
    assert_allclose(nodes[::-1], ref_nodes, rtol=0, atol=1e-15, err_msg=f"nodes, n={n}")
    assert_allclose(weights[::-1], ref_weights, rtol=1e-14, atol=1e-16, err_msg=f"weights, n={n}")
    # collocation points: zeros of T_{n+1}
    assert_allclose(
        np.sort(colloc), roots_chebyt(n + 1)[0], rtol=0, atol=1e-15, err_msg=f"x_k, n={n}"
    )
    assert len(np.unique(np.round(colloc, 14))) == n + 1


@pytest.mark.parametrize("n", [1, 2, 5, 10, 33, 200])
def test_bounded_rule_weights_sum_to_half_pi(n):
    _, weights, _ = bounded_rule(n)
    assert np.all(weights > 0)
    assert abs(weights.sum() - np.pi / 2) <= 4e-16 * n, f"n={n}"


@pytest.mark.parametrize("n", [1, 2, 3, 6, 11])
def test_bounded_rule_polynomial_exactness_and_sharpness(n):
    nodes, weights, _ = bounded_rule(n)
    for k in range(2 * n):  # exact up to degree 2n - 1
        approx = np.sum(weights * nodes**k)
        assert abs(approx - weighted_moment(k)) <= 1e-14, f"n={n}, degree k={k}"
    # ... and not beyond: degree 2n is not integrated exactly
    k = 2 * n
    assert abs(np.sum(weights * nodes**k) - weighted_moment(k)) > 1e-8, f"n={n}, k={k}"


# --------------------------------------------------------------------------------------------
# BoundedSolver: analytic pairs


@pytest.mark.parametrize("n", [1, 2, 5, 12])
def test_bounded_chebyshev_pairs_exact(n):
    """(1/pi) PV int sqrt(1-t^2) U_j(t)/(t-x) dt = -T_{j+1}(x), exact for j < n."""
    s = BoundedSolver(n)
    for j in range(n):
        sol = s.solve(-eval_chebyt(j + 1, s.collocation))
        assert_allclose(
            sol.values, eval_chebyu(j, s.nodes), rtol=0, atol=1e-13, err_msg=f"g = U_{j}, n={n}"
        )
        expected_coef = np.zeros(n)
        expected_coef[j] = 1.0
        assert_allclose(sol.coefficients, expected_coef, atol=1e-14, err_msg=f"j={j}, n={n}")
        assert abs(sol.consistency) <= 1e-15
        assert sol.extra is None


def test_bounded_hertz_pair_and_resultant():
    s = BoundedSolver(4)
    sol = s.solve(-s.collocation)
    assert_allclose(sol.values, 1.0, rtol=1e-14)
    assert_allclose(s.resultant(sol), np.pi / 2, rtol=1e-15)


@pytest.mark.parametrize("n", [6, 60])
def test_bounded_batch_dimensions(n):
    s = BoundedSolver(n)
    ms = np.array([[1.1, 1.5, 3.0], [1.2, 2.0, 10.0]])
    f = dugdale_f(s.collocation, ms[..., None])
    sol = s.solve(f)
    assert sol.coefficients.shape == (2, 3, n)
    assert sol.values.shape == (2, 3, n)
    assert sol.consistency.shape == (2, 3)
    assert s.resultant(sol).shape == (2, 3)
    for idx in np.ndindex(ms.shape):
        single = s.solve(f[idx])
        assert_allclose(sol.values[idx], single.values, rtol=1e-14, atol=1e-16)
    # values=False skips g at the nodes, the coefficients are unchanged
    lean = s.solve(f, values=False)
    assert lean.values is None
    assert_array_equal(lean.coefficients, sol.coefficients)
    assert_array_equal(lean.consistency, sol.consistency)


@pytest.mark.parametrize("m", [1.2, 1.5, 3.0])
def test_bounded_dugdale_pair_converges_geometrically(m):
    rate = m + np.sqrt(m * m - 1)  # Bernstein-ellipse parameter of the log singularity

    def error(n):
        s = BoundedSolver(n)
        sol = s.solve(dugdale_f(s.collocation, m))
        phi = np.sqrt(1 - s.nodes**2) * sol.values
        return max(
            np.max(np.abs(phi - dugdale_phi(s.nodes, m))),
            abs(s.resultant(sol) - dugdale_resultant(m)),
        )

    for k in (4, 8):
        ek, e2k = error(k), error(2 * k)
        assert ek > 1e-14, f"m={m}, n={k}: the coarse error must be visible"
        assert e2k < 0.1 * ek, f"m={m}: error at n={2 * k} ({e2k:.3g}) vs n={k} ({ek:.3g})"
        assert e2k <= max(ek * rate**-k, 1e-14), f"m={m}: slower than {rate:.3f}^-n"


def test_bounded_dugdale_pair_large_n_matches_to_1e12():
    m = 1.2
    s = BoundedSolver(128)
    sol = s.solve(dugdale_f(s.collocation, m))
    phi = np.sqrt(1 - s.nodes**2) * sol.values
    assert_allclose(phi, dugdale_phi(s.nodes, m), rtol=0, atol=1e-12, err_msg="m=1.2, n=128")
    assert abs(s.resultant(sol) - dugdale_resultant(m)) <= 1e-12
    assert abs(sol.consistency) <= 1e-15
    assert abs(s.first_moment(sol)) <= 1e-14  # even solution


@SETTINGS
@given(m=st.floats(1.2, 10.0))
def test_bounded_dugdale_pair_property(m):
    s = BoundedSolver(128)
    sol = s.solve(dugdale_f(s.collocation, m))
    assert_allclose(
        np.sqrt(1 - s.nodes**2) * sol.values, dugdale_phi(s.nodes, m), atol=1e-12, err_msg=f"m={m}"
    )
    assert_allclose(s.resultant(sol), dugdale_resultant(m), rtol=1e-12, err_msg=f"m={m}")


def test_bounded_evaluate_against_analytic_phi():
    m = 1.5
    s = BoundedSolver(96)
    sol = s.solve(dugdale_f(s.collocation, m))
    t = np.linspace(-1, 1, 41)
    assert_allclose(s.evaluate(sol, t), dugdale_phi(t, m), atol=1e-12, err_msg="m=1.5")
    # zero outside the interval, exactly
    assert_array_equal(s.evaluate(sol, np.array([-1.5, -1.0000001, 1.0000001, 7.0])), 0.0)
    # batch: solutions (3,) against points (m,)
    ms = np.array([1.2, 2.0, 5.0])
    solb = s.solve(dugdale_f(s.collocation, ms[:, None]))
    vals = s.evaluate(solb, t)
    assert vals.shape == (3, t.size)
    assert_allclose(vals, dugdale_phi(t, ms[:, None]), atol=1e-12)


# --------------------------------------------------------------------------------------------
# BoundedSolver against the explicit Erdogan-Gupta-Cook matrix (Appendix A)


def egc_matrix(n):
    """M[k, i] = W_i / (pi (t_i - x_k)), W_i = pi (1 - t_i^2)/(n + 1): Eq. (A3)."""
    i = np.arange(1, n + 1)
    t = np.cos(i * np.pi / (n + 1))  # Eq. (A4)
    k = np.arange(1, n + 2)
    x = np.cos(np.pi / 2 * (2 * k - 1) / (n + 1))  # Eq. (A5)
    W = np.pi * (1 - t * t) / (n + 1)
    return W[None, :] / (np.pi * (t[None, :] - x[:, None])), t, x


@pytest.mark.parametrize("n", [2, 4, 10, 30, 48, 64, 100])  # n >= 48: the DCT path
def test_bounded_equals_egc_dropped_middle_equation(n):
    """n even, odd f: drop the middle equation (x = 0) and solve the square system."""
    M, t, x = egc_matrix(n)
    s = BoundedSolver(n)
    assert_allclose(s.nodes, t, atol=1e-15)
    assert_allclose(s.collocation, x, atol=1e-15)
    mid = n // 2
    assert abs(x[mid]) < 1e-15
    keep = np.arange(n + 1) != mid
    for f in (-0.5 * x + 0.3 * dugdale_f(x, 1.3), x**3 - 2 * x, dugdale_f(x, 1.05)):
        g_egc = np.linalg.solve(M[keep], f[keep])
        sol = s.solve(f)
        assert_allclose(
            sol.values, g_egc, rtol=1e-11, atol=1e-11 * np.max(np.abs(g_egc)), err_msg=f"n={n}"
        )
        assert abs(sol.consistency) <= 1e-15


@SETTINGS
@given(
    n=st.integers(1, 80),
    coef=st.lists(st.floats(-2, 2), min_size=4, max_size=4),
    m=st.floats(1.01, 4.0),
)
def test_bounded_equals_egc_least_squares(n, coef, m):
    """Any f: the least-squares solution of the n+1 by n EGC system; residual = mean f."""
    M, _, x = egc_matrix(n)
    f = coef[0] + coef[1] * x + coef[2] * x * x + coef[3] * dugdale_f(x + 0.1, m + 0.1)
    g_ls, *_ = np.linalg.lstsq(M, f, rcond=None)
    s = BoundedSolver(n)
    sol = s.solve(f)
    scale = 1 + np.max(np.abs(g_ls))
    assert_allclose(sol.values, g_ls, atol=1e-10 * scale, err_msg=f"n={n}, coef={coef}, m={m}")
    # the unmatched component of f is its (discrete) mean: the consistency residual
    assert_allclose(
        f - M @ sol.values, f.mean(), atol=1e-10 * (1 + np.abs(f).max()), err_msg=f"n={n}"
    )
    assert_allclose(sol.consistency, f.mean(), atol=1e-15 * (1 + np.abs(f).max()) * n)


# --------------------------------------------------------------------------------------------
# consistency condition and the extra unknown (non-symmetric problems)


def test_bounded_consistency_residual():
    s = BoundedSolver(9)
    odd = s.solve(-s.collocation + dugdale_f(s.collocation, 1.4))
    assert abs(odd.consistency) <= 1e-15
    one = s.solve(np.ones(10))
    assert_allclose(one.consistency, 1.0, rtol=1e-15)
    # f = 1 has no bounded solution: nothing of it is matched
    assert_allclose(one.values, 0.0, atol=2e-14)


def test_bounded_extra_unknown_vanishes_for_odd_f():
    """f = -x + lambda * 1 is solvable only for lambda = 0."""
    s = BoundedSolver(8)
    sol = s.solve(-s.collocation, extra=np.ones(9))
    assert abs(sol.extra) <= 1e-16
    assert_allclose(sol.values, 1.0, rtol=1e-14)


@pytest.mark.parametrize("n", [2, 3, 8, 17])
def test_bounded_extra_unknown_even_f(n):
    """f0 = x^2, extra = 1: lambda = -mean(x_k^2) = -1/2, then x^2 - 1/2 = T_2/2, g = -U_1/2."""
    s = BoundedSolver(n)
    x = s.collocation
    sol = s.solve(x**2, extra=np.ones(n + 1))
    assert_allclose(sol.extra, -0.5, rtol=1e-14, err_msg=f"n={n}")
    assert_allclose(sol.extra, -np.mean(x**2), rtol=1e-14)
    assert_allclose(sol.values, -s.nodes, atol=1e-14, err_msg=f"n={n}")
    assert abs(sol.consistency) <= 1e-15


def test_bounded_extra_unknown_general_rhs():
    """phi = sqrt(1-t^2)(U_0 + 2 U_2): f = -T_1 - 2 T_3 = f0 + lambda f1 with known lambda."""
    s = BoundedSolver(10)
    x = s.collocation
    lam_true = 0.7
    f1 = 1 + x  # its mean is 1, so the consistency condition fixes lambda
    f_total = -eval_chebyt(1, x) - 2 * eval_chebyt(3, x)
    sol = s.solve(f_total - lam_true * f1, extra=f1)
    assert_allclose(sol.extra, lam_true, rtol=1e-14)
    assert_allclose(sol.values, 1 + 2 * eval_chebyu(2, s.nodes), atol=1e-13)
    # batch of right-hand sides with their own extra
    lams = np.array([0.1, -2.0, 3.5])
    solb = s.solve(f_total - lams[:, None] * f1, extra=np.broadcast_to(f1, (3, 11)))
    assert_allclose(solb.extra, lams, rtol=1e-13)


# --------------------------------------------------------------------------------------------
# mapped interval, first moment, log moment


@pytest.mark.parametrize("interval", [(-1.0, 1.0), (0.0, 1.0), (-3.0, 0.5), (2.0, 2.25)])
def test_bounded_mapped_interval(interval):
    lo, hi = interval
    half, mid = (hi - lo) / 2, (hi + lo) / 2
    m = 1.3
    unit = BoundedSolver(64)
    mapped = BoundedSolver(64, interval)
    assert_allclose(mapped.nodes, mid + half * unit.nodes_unit, rtol=1e-15)
    assert_allclose(mapped.collocation, mid + half * unit.collocation_unit, rtol=1e-15)
    assert_allclose(mapped.weights, half * unit.weights_unit, rtol=1e-15)
    tau = (2 * mapped.collocation - lo - hi) / (hi - lo)
    sol = mapped.solve(dugdale_f(tau, m))
    ref = unit.solve(dugdale_f(unit.collocation, m))
    assert_allclose(sol.values, ref.values, atol=1e-13, err_msg=f"interval={interval}")
    assert_allclose(
        mapped.resultant(sol),
        half * dugdale_resultant(m),
        rtol=1e-12,
        err_msg=f"interval={interval}",
    )
    t = np.linspace(lo, hi, 9)
    assert_allclose(mapped.evaluate(sol, t), dugdale_phi((t - mid) / half, m), atol=1e-12)


def _random_bounded_problem(seed, n, interval, degree=6):
    """phi = sqrt(1-tau^2) sum b_j U_j(tau) on the interval, with its exact right-hand side."""
    lo, hi = interval
    b = np.random.default_rng(seed).normal(size=degree)
    s = BoundedSolver(n, interval)

    def tau(t):
        return (2 * t - lo - hi) / (hi - lo)

    f = -sum(bj * eval_chebyt(j + 1, tau(s.collocation)) for j, bj in enumerate(b))

    def phi(t):
        tt = tau(t)
        return np.sqrt(max(0.0, 1 - tt * tt)) * sum(
            bj * eval_chebyu(j, tt) for j, bj in enumerate(b)
        )

    return s, s.solve(f), phi, b


@pytest.mark.parametrize("interval", [(-1.0, 1.0), (-0.3, 1.7), (5.0, 9.0)])
def test_bounded_resultant_and_first_moment_vs_quad(interval):
    lo, hi = interval
    s, sol, phi, b = _random_bounded_problem(1, 10, interval)
    assert_allclose(sol.coefficients[: b.size], b, atol=1e-13)
    assert_allclose(sol.coefficients[b.size :], 0.0, atol=1e-13)
    res, _ = quad(phi, lo, hi, epsabs=1e-14, epsrel=1e-13)
    mom, _ = quad(lambda t: t * phi(t), lo, hi, epsabs=1e-14, epsrel=1e-13)
    assert_allclose(s.resultant(sol), res, rtol=1e-12, atol=1e-13, err_msg=f"{interval}")
    assert_allclose(s.first_moment(sol), mom, rtol=1e-12, atol=1e-13, err_msg=f"{interval}")


def test_bounded_first_moment_n1():
    """n = 1 has no b_1: the first moment is mid * resultant."""
    s = BoundedSolver(1, (1.0, 3.0))
    sol = s.solve(-(s.collocation - 2.0))  # phi = sqrt(1 - tau^2), f = -tau
    assert_allclose(sol.values, 1.0, rtol=1e-15)
    assert_allclose(s.resultant(sol), np.pi / 2, rtol=1e-15)
    assert_allclose(s.first_moment(sol), 2.0 * np.pi / 2, rtol=1e-15)


@pytest.mark.parametrize("interval", [(-1.0, 1.0), (-0.3, 1.7), (0.25, 0.5)])
def test_bounded_log_moment_vs_quad(interval):
    lo, hi = interval
    half = (hi - lo) / 2
    s, sol, phi, _ = _random_bounded_problem(2, 12, interval)
    ys = [
        lo,
        hi,
        lo + 0.37 * (hi - lo),
        lo + 1e-3 * half,
        hi - 1e-6 * half,  # inside, ends
        lo - 2.0 * half,
        hi + 1e-6 * half,
        hi + 40.0 * half,
    ]  # outside
    got = s.log_moment(sol, np.array(ys))
    assert got.shape == (len(ys),)
    for y, g in zip(ys, got, strict=True):
        ref = quad_log_inside(phi, y, lo, hi)
        assert abs(g - ref) <= 1e-12 * max(1.0, abs(ref)), f"interval={interval}, y={y}"
        assert_allclose(s.log_moment(sol, y), g, rtol=1e-15)


def test_bounded_log_moment_batch_broadcast():
    s = BoundedSolver(16)
    ms = np.array([1.1, 2.0])
    sol = s.solve(dugdale_f(s.collocation, ms[:, None]))
    y = np.array([[0.0], [3.0], [1.0]])  # (3, 1) against batch (2,)
    val = s.log_moment(sol, y)
    assert val.shape == (3, 2)
    for i in range(3):
        for j in range(2):
            single = s.solve(dugdale_f(s.collocation, ms[j]))
            assert_allclose(val[i, j], s.log_moment(single, y[i, 0]), rtol=1e-14)


@pytest.mark.parametrize("interval", [(-1.0, 1.0), (0.0, 0.4)])
def test_bounded_log_moment_derivative_vs_finite_difference(interval):
    lo, hi = interval
    half, mid = (hi - lo) / 2, (hi + lo) / 2
    s, sol, _, _ = _random_bounded_problem(3, 10, interval)
    for v in (0.05, 0.7, 3.0):
        dv = 1e-5 * v

        def lm(vv):
            return s.log_moment(sol, mid + half * np.cosh(vv))

        fd = (lm(v + dv) - lm(v - dv)) / (2 * dv)
        got = s.log_moment_derivative(sol, mid + half * np.cosh(v))
        assert abs(got - fd) <= 1e-7 * max(1.0, abs(fd)), f"interval={interval}, v={v}"


def test_chebyshev_log_expansion_reconstructs_log():
    t = np.linspace(-0.95, 0.95, 13)
    kmax = 400
    for y in (1.5, -2.0, 1.05, -1.2):
        c0, e = chebyshev_log_expansion(y, kmax)
        k = np.arange(1, kmax + 1)
        series = c0 - 2 * np.sum(e[1:, None] / k[:, None] * eval_chebyt(k[:, None], t), axis=0)
        assert_allclose(series, np.log(np.abs(y - t)), atol=1e-12, err_msg=f"y={y}")
        assert e[0] == 1.0
    c0, e = chebyshev_log_expansion(np.array([0.3, -0.6]), 5)
    assert e.shape == (2, 6)
    assert_allclose(c0, -np.log(2.0), rtol=1e-15)
    assert_allclose(e[:, 3], eval_chebyt(3, np.array([0.3, -0.6])), rtol=1e-14)


# --------------------------------------------------------------------------------------------
# UnboundedSolver


@pytest.mark.parametrize("interval", [(-1.0, 1.0), (1.0, 4.0)])
def test_unbounded_basic_pairs(interval):
    half = (interval[1] - interval[0]) / 2
    s = UnboundedSolver(8, interval)
    # phi = 1/sqrt(1 - tau^2): f = 0, int phi = pi * half
    g = s.solve(np.zeros(7), np.pi * half)
    assert_allclose(g, 1.0, rtol=1e-14, err_msg=f"{interval}")
    assert_allclose(s.resultant(g), np.pi * half, rtol=1e-14)
    # phi = tau/sqrt(1 - tau^2): f = 1, int phi = 0
    g = s.solve(np.ones(7), 0.0)
    assert_allclose(g, s.nodes_unit, atol=1e-14, err_msg=f"{interval}")


@pytest.mark.parametrize("n", [2, 5, 12])
def test_unbounded_chebyshev_pairs(n):
    """(1/pi) PV int T_k(t)/(sqrt(1-t^2)(t-x)) dt = U_{k-1}(x), k >= 1, resultant 0."""
    s = UnboundedSolver(n)
    for k in range(1, n):
        g = s.solve(eval_chebyu(k - 1, s.collocation), 0.0)
        assert_allclose(g, eval_chebyt(k, s.nodes), atol=1e-12, err_msg=f"k={k}, n={n}")


def test_unbounded_batch():
    s = UnboundedSolver(6)
    C = np.array([0.0, 1.0, -2.5])
    g = s.solve(np.zeros((3, 5)), C)
    assert g.shape == (3, 6)
    assert_allclose(s.resultant(g), C, atol=1e-14)


@pytest.mark.parametrize("interval", [(-1.0, 1.0), (0.5, 2.5)])
def test_unbounded_log_moment_vs_quad(interval):
    lo, hi = interval
    half, mid = (hi - lo) / 2, (hi + lo) / 2
    s = UnboundedSolver(10, interval)
    t = s.nodes_unit
    g = 1 + 0.5 * t + 0.25 * eval_chebyt(3, t) - 0.1 * eval_chebyt(6, t)

    def g_of_theta(th):
        c = np.cos(th)
        return 1 + 0.5 * c + 0.25 * np.cos(3 * th) - 0.1 * np.cos(6 * th)

    for y in (lo, hi, mid + 0.3 * half, lo - 1.5 * half, hi + 1e-4 * half, hi + 20 * half):
        yu = (y - mid) / half
        # int phi ln|y - t| dt = half int_0^pi g(cos th) ln(half |yu - cos th|) dth
        if abs(yu) <= 1:
            th0 = np.arccos(np.clip(yu, -1, 1))

            def logdist(th, th0=th0):  # cos th0 - cos th without cancellation
                return np.log(2 * abs(np.sin((th + th0) / 2) * np.sin((th - th0) / 2)))

            pts = [th0] if 0 < th0 < np.pi else None
        else:

            def logdist(th, yu=yu):
                return np.log(abs(yu - np.cos(th)))

            pts = None
        ref, _ = quad(
            lambda th, ld=logdist: g_of_theta(th) * (ld(th) + np.log(half)),
            0,
            np.pi,
            points=pts,
            limit=200,
            epsabs=1e-15,
            epsrel=1e-13,
        )
        ref *= half
        assert abs(s.log_moment(g, y) - ref) <= 1e-12 * max(1, abs(ref)), f"{interval}, y={y}"


# --------------------------------------------------------------------------------------------
# EndBoundedSolver


@pytest.mark.parametrize("bounded_at, sign", [("right", -1.0), ("left", 1.0)])
def test_end_bounded_constant_pair(bounded_at, sign):
    """(1/pi) int sqrt((1-t)/(1+t))/(t-x) dt = -1 (right); the mirror gives +1 (left)."""
    s = EndBoundedSolver(7, bounded_at=bounded_at)
    g = s.solve(np.full(7, sign))
    assert_allclose(g, 1.0, rtol=1e-13, err_msg=bounded_at)
    assert_allclose(s.resultant(g), np.pi, rtol=1e-14)  # int sqrt((1-t)/(1+t)) dt = pi


@pytest.mark.parametrize("n", [1, 2, 7, 20])
@pytest.mark.parametrize("bounded_at", ["right", "left"])
def test_end_bounded_rule_is_gauss_jacobi(n, bounded_at):
    """Nodes and weights: Gauss-Jacobi for (1-t)^(1/2)(1+t)^(-1/2) (right) or its mirror."""
    alpha, beta_ = (0.5, -0.5) if bounded_at == "right" else (-0.5, 0.5)
    ref_nodes, ref_weights = roots_jacobi(n, alpha, beta_)
    s = EndBoundedSolver(n, bounded_at=bounded_at)
    order = np.argsort(s.nodes_unit)
    assert_allclose(s.nodes_unit[order], ref_nodes, atol=1e-15, err_msg=f"{bounded_at}, n={n}")
    assert_allclose(s.weights_unit[order], ref_weights, rtol=2e-12, err_msg=f"{bounded_at}, n={n}")
    assert abs(s.weights_unit.sum() - np.pi) <= 1e-14 * n  # int sqrt((1-t)/(1+t)) dt = pi
    assert s.collocation.shape == (n,)


def _end_bounded_exact_rhs(coef, x, bounded_at):
    """f(x) for phi = w(t) g(t), g = sum c_k t^k, exactly (quad moments + division).

    (1/pi) PV int w g/(t-x) = (1/pi) int w (g(t)-g(x))/(t-x) dt + g(x) (1/pi) PV int w/(t-x),
    the last factor being -1 (right) or +1 (left).
    """
    wvar = (-0.5, 0.5) if bounded_at == "right" else (0.5, -0.5)
    deg = len(coef) - 1
    mu = [
        quad(lambda t, j=j: t**j, -1, 1, weight="alg", wvar=wvar, epsabs=1e-15, epsrel=1e-14)[0]
        for j in range(deg)
    ]
    f = np.zeros_like(x)
    for k in range(1, deg + 1):
        for j in range(k):
            f += coef[k] * mu[j] * x ** (k - 1 - j) / np.pi
    g_x = np.polyval(coef[::-1], x)
    return f + (-1.0 if bounded_at == "right" else 1.0) * g_x


@pytest.mark.parametrize("bounded_at", ["right", "left"])
@pytest.mark.parametrize("interval", [(-1.0, 1.0), (2.0, 5.0)])
def test_end_bounded_polynomial_g(bounded_at, interval):
    lo, hi = interval
    half, mid = (hi - lo) / 2, (hi + lo) / 2
    coef = np.array([0.5, -1.0, 2.0, 0.3, -0.7])  # g(tau) = sum coef_k tau^k
    n = 9
    s = EndBoundedSolver(n, interval, bounded_at=bounded_at)
    x_unit = (s.collocation - mid) / half
    t_unit = (s.nodes - mid) / half
    f = _end_bounded_exact_rhs(coef, x_unit, bounded_at)
    # the quadrature sum of the rule reproduces the exact Cauchy integral at the x_k
    qsum = (
        s.weights_unit[None, :]
        * np.polyval(coef[::-1], t_unit)[None, :]
        / (np.pi * (t_unit[None, :] - x_unit[:, None]))
    ).sum(axis=1)
    assert_allclose(qsum, f, atol=1e-12, err_msg=f"{bounded_at}, {interval}")
    g = s.solve(f)
    assert_allclose(
        g, np.polyval(coef[::-1], t_unit), atol=1e-12, err_msg=f"{bounded_at}, {interval}"
    )
    wvar = (-0.5, 0.5) if bounded_at == "right" else (0.5, -0.5)
    res, _ = quad(lambda t: np.polyval(coef[::-1], t), -1, 1, weight="alg", wvar=wvar)
    assert_allclose(s.resultant(g), half * res, rtol=1e-12)
    # batch
    gb = s.solve(np.stack([f, 2 * f]))
    assert gb.shape == (2, n)
    assert_allclose(gb[1], 2 * g, rtol=1e-14)


# --------------------------------------------------------------------------------------------
# bad input (the message is part of the API)

BAD_SIE = [
    (lambda: bounded_rule(0), r"n must be an integer >= 1, got 0"),
    (lambda: bounded_rule(1.5), r"n must be an integer >= 1, got 1\.5"),
    (lambda: bounded_rule(True), r"n must be an integer >= 1, got True"),
    (lambda: BoundedSolver(0), r"n must be an integer >= 1, got 0"),
    (lambda: BoundedSolver(2.0), r"n must be an integer >= 1, got 2\.0"),
    (lambda: BoundedSolver(False), r"n must be an integer >= 1, got False"),
    (lambda: BoundedSolver(-3), r"n must be an integer >= 1, got -3"),
    (lambda: UnboundedSolver(1), r"n must be an integer >= 2, got 1"),
    (lambda: UnboundedSolver(1.5), r"n must be an integer >= 2, got 1\.5"),
    (lambda: EndBoundedSolver(0), r"n must be an integer >= 1, got 0"),
    (lambda: EndBoundedSolver(True), r"n must be an integer >= 1, got True"),
    (
        lambda: BoundedSolver(4, (1.0, 1.0)),
        r"interval must be finite with lo < hi, got \(1\.0, 1\.0\)",
    ),
    (lambda: BoundedSolver(4, (2.0, -1.0)), r"interval must be finite with lo < hi"),
    (lambda: BoundedSolver(4, (0.0, np.inf)), r"interval must be finite with lo < hi"),
    (lambda: BoundedSolver(4, (np.nan, 1.0)), r"interval must be finite with lo < hi"),
    (lambda: UnboundedSolver(4, (-np.inf, 0.0)), r"interval must be finite with lo < hi"),
    (lambda: EndBoundedSolver(4, (3.0, 0.0)), r"interval must be finite with lo < hi"),
    (
        lambda: EndBoundedSolver(4, bounded_at="middle"),
        r"bounded_at must be 'right' or 'left', got 'middle'",
    ),
    (
        lambda: BoundedSolver(4).solve(np.zeros(4)),
        r"f must have n \+ 1 = 5 values on its last axis, got 4",
    ),
    (
        lambda: BoundedSolver(4).solve(np.zeros((2, 6))),
        r"f must have n \+ 1 = 5 values on its last axis, got 6",
    ),
    (
        lambda: BoundedSolver(4).solve(np.zeros(5), extra=np.ones(3)),
        r"extra must have n \+ 1 = 5 values on its last axis, got 3",
    ),
    (
        lambda: UnboundedSolver(4).solve(np.zeros(4), 0.0),
        r"f must have n - 1 = 3 values on its last axis, got 4",
    ),
    (
        lambda: EndBoundedSolver(4).solve(np.zeros(5)),
        r"f must have n = 4 values on its last axis, got 5",
    ),
]


@pytest.mark.parametrize("call, message", BAD_SIE, ids=[m for _, m in BAD_SIE])
def test_bad_input(call, message):
    with pytest.raises(ValueError, match=message):
        call()


def test_numpy_integer_n_accepted():
    s = BoundedSolver(np.int64(5))
    assert s.n == 5 and type(s.n) is int
    assert UnboundedSolver(np.int32(3)).n == 3


def test_log_moment_derivative_matches_finite_difference():
    s = BoundedSolver(12, (0.5, 2.5))
    sol = s.solve(np.cos(s.collocation) * s.collocation, extra=np.ones(13))
    for v in (0.05, 0.7, 3.0):
        y = 1.5 + np.cosh(v)
        h = 1e-6
        up, down = (s.log_moment(sol, 1.5 + np.cosh(v + d)) for d in (h, -h))
        fd = (up - down) / (2 * h)
        assert abs(s.log_moment_derivative(sol, y) - fd) < 1e-7 * max(1.0, abs(fd)), v


@pytest.mark.parametrize("N", [1, 2, 3, 4, 7, 48, 49, 97, 256, 1025])
def test_dct2_is_scipys_type_2_dct(N):
    import scipy.fft

    from linecontact.sie import dct2

    x = np.random.default_rng(N).standard_normal((3, N))
    np.testing.assert_allclose(
        dct2(x), scipy.fft.dct(x, type=2, axis=-1), rtol=0, atol=1e-14 * np.abs(x).sum()
    )


def test_bounded_solve_needs_no_scipy():
    import subprocess
    import sys

    code = (
        "import sys, numpy as np; from linecontact.sie import BoundedSolver; "
        "s = BoundedSolver(200); s.solve(-s.collocation); "
        "assert 'scipy' not in sys.modules, sorted(m for m in sys.modules if 'scipy' in m)"
    )
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    assert p.returncode == 0, p.stderr
