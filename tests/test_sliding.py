"""Steady sliding (paper Eqs. 18-22): limits, symmetries, equilibrium, convergence, sweeps.

Two independent routes are compared throughout: the Gauss-Chebyshev collocation of the
printed equations (product integration of the log kernels) and the closed form derived in
docs/sliding.md; the separation conditions are also checked by direct quadrature of the gap
slope, which uses neither.
"""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy import integrate

import linecontact as lc
from linecontact import sliding as sl
from linecontact.errors import ConvergenceError, NoEquilibriumError
from linecontact.sie import BoundedSolver

METHODS = ("collocation", "closed-form")
A_GRID = np.array([1e-4, 1e-3, 0.005, 0.02, 0.05, 0.1, 0.2])


def _scale_F(r):
    """|Hertz| + |adhesive| terms of the load, the natural size of its error."""
    A, rho, s = np.asarray(r.a_over_R), np.asarray(r.R_over_h2), np.asarray(r.sigma0_over_E)
    z = (np.sqrt(r.c1_over_R**2 - A**2) + np.sqrt(r.c2_over_R**2 - A**2)) / A
    return np.pi / 4 * A * A * rho + s * rho * A * z


# --------------------------------------------------------------------------------------------
# the symmetric limit


@pytest.mark.parametrize("method", METHODS)
@pytest.mark.parametrize(("rho", "s"), [(100.0, 0.01), (100.0, 0.2), (1000.0, 0.05), (20.0, 0.001)])
def test_equal_ranges_reproduce_normal_contact(method, rho, s):
    r = sl.sliding_contact(A_GRID, rho, 1.0, s, method=method)
    n = lc.normal_contact(A_GRID, rho, s)
    msg = f"method={method}, R/h={rho}, sigma0/E={s}"
    np.testing.assert_allclose(r.c1_over_R, n.c_over_R, rtol=1e-12, err_msg=msg)
    np.testing.assert_allclose(r.c2_over_R, n.c_over_R, rtol=1e-12, err_msg=msg)
    np.testing.assert_allclose(
        r.F_over_Eh2, n.F_over_Eh, rtol=0, atol=1e-12 * np.max(_scale_F(r)), err_msg=msg
    )
    assert np.all(np.abs(r.e_over_R) <= 1e-15)
    assert np.all(np.abs(r.M_over_Eh2R) <= 1e-12 * np.max(_scale_F(r)))
    np.testing.assert_array_equal(r.stable, n.stable)
    x = A_GRID[:, None] * np.concatenate([np.linspace(-0.99, 0.99, 21), [-3.0, 1.5, 4.0]])
    np.testing.assert_allclose(r.pressure(x), n.pressure(x), rtol=0, atol=1e-13)


def test_equal_ranges_pull_off_and_inverse_match_normal():
    po = sl.sliding_pull_off(100.0, 1.0, [0.01, 0.2])
    ref = lc.pull_off(100.0, [0.01, 0.2])
    np.testing.assert_array_equal(po.mechanism, ref.mechanism)
    np.testing.assert_allclose(po.F_pulloff_over_Eh2, ref.F_pulloff_over_Eh, rtol=1e-11)
    np.testing.assert_allclose(po.a_over_R_at_pulloff, ref.a_over_R_at_pulloff, rtol=1e-6)
    np.testing.assert_allclose(
        po.F_zero_width_over_Eh2, lc.zero_width_load(100.0, [0.01, 0.2]), rtol=1e-13
    )
    F = [-0.2, 0.0, 1.5]
    r = sl.sliding_contact_for_load(F, 100.0, 1.0, 0.01, method="closed-form")
    n = lc.contact_for_load(F, 100.0, 0.01)
    np.testing.assert_allclose(r.a_over_R, n.a_over_R, rtol=1e-11)


# --------------------------------------------------------------------------------------------
# mirror symmetry, signs, and the moment about the axis


@pytest.mark.parametrize("method", METHODS)
def test_swapping_the_ranges_mirrors_the_contact(method):
    # the mirror image has trailing range h2 and leading range h1: in its own groups
    # R/h2' = R/h1, h1'/h2' = h2/h1, F/(E h2') = F/(E h1), M/(E h2' R) = M/(E h1 R)
    rho, s = 100.0, 0.04
    for ratio in (1.5, 3.0, 0.4):
        a = sl.sliding_contact(A_GRID, rho, ratio, s, method=method)
        b = sl.sliding_contact(A_GRID, rho / ratio, 1 / ratio, s, method=method)
        msg = f"h1/h2={ratio}"
        np.testing.assert_allclose(b.c1_over_R, a.c2_over_R, rtol=1e-12, err_msg=msg)
        np.testing.assert_allclose(b.c2_over_R, a.c1_over_R, rtol=1e-12, err_msg=msg)
        np.testing.assert_allclose(b.e_over_R, -a.e_over_R, rtol=1e-9, err_msg=msg)
        np.testing.assert_allclose(b.M_over_Eh2R, -a.M_over_Eh2R / ratio, rtol=1e-9, err_msg=msg)
        np.testing.assert_allclose(
            b.F_over_Eh2, a.F_over_Eh2 / ratio, rtol=1e-10, atol=1e-12, err_msg=msg
        )


@pytest.mark.parametrize("method", METHODS)
def test_moment_about_the_axis_is_the_adhesion_hysteresis(method):
    # M - e F = (w1 - w2) R exactly (w_i = sigma0 h_i), at every width: the work of rolling
    # the cylinder on by R dtheta against the two edges
    r = np.array([0.3, 1.0, 1.5, 2.0, 3.0, 8.0])[:, None]
    res = sl.sliding_contact(A_GRID[None, :], 100.0, r, 0.04, method=method)
    expected = np.broadcast_to(0.04 * (r - 1), res.a_over_R.shape)
    np.testing.assert_allclose(res.M_axis_over_Eh2R, expected, rtol=1e-10, atol=1e-14)
    np.testing.assert_allclose(
        res.M_axis_over_Eh2R,
        res.M_over_Eh2R - res.e_over_R * res.F_over_Eh2,
        rtol=1e-14,
        atol=1e-17,
    )


def test_trailing_adhesion_shifts_the_contact_back_and_loads_it_clockwise():
    r = sl.sliding_contact(0.03, 100.0, 2.0, 0.04)
    assert r.c1_over_R > r.c2_over_R  # the trailing zone is the longer
    assert r.e_over_R > 0  # the apex lies ahead of the contact centre
    assert r.M_over_Eh2R > 0  # clockwise (x right = sliding direction, y up)


# --------------------------------------------------------------------------------------------
# Hertz and equilibrium


@pytest.mark.parametrize("method", METHODS)
def test_weak_adhesion_approaches_hertz(method):
    A, rho, ratio = np.array([0.01, 0.05, 0.1]), 100.0, 2.5
    hertz = lc.hertz_load(A, rho)
    errs = []
    for s in (1e-4, 1e-6, 1e-8):
        r = sl.sliding_contact(A, rho, ratio, s, method=method)
        errs.append(np.max(np.abs(r.F_over_Eh2 / hertz - 1)))
        assert np.max(np.abs(r.e_over_R)) < 10 * s and np.max(np.abs(r.M_over_Eh2R)) < 10 * s
    # the adhesive load is linear in sigma0 (c1, c2 tend to their Hertz values)
    assert 90 < errs[0] / errs[1] < 110 and 90 < errs[1] / errs[2] < 110, errs
    assert errs[-1] < 1e-4
    z = sl.sliding_contact(A, rho, ratio, 0.0, method=method)
    np.testing.assert_allclose(z.F_over_Eh2, hertz, rtol=1e-13)
    assert np.all(z.e_over_R == 0) or np.max(np.abs(z.e_over_R)) < 1e-16
    # without adhesion the zone ends are where the Hertz gap reaches h1 and h2
    gaps = z.gap(np.stack([-z.c1_over_R, z.c2_over_R], axis=-1))  # one pair per point
    np.testing.assert_allclose(gaps, np.broadcast_to([ratio, 1.0], (3, 2)), rtol=1e-12)


def _quad(f, lo, hi, points):
    val, _ = integrate.quad(f, lo, hi, points=points, limit=400, epsabs=1e-15, epsrel=1e-13)
    return val


@pytest.mark.parametrize(
    ("A", "rho", "ratio", "s"),
    [(0.03, 100.0, 2.5, 0.04), (0.08, 100.0, 3.0, 0.02), (0.01, 500.0, 0.5, 0.1)],
)
def test_load_and_moment_are_the_integrals_of_the_pressure(A, rho, ratio, s):
    for method in METHODS:
        r = sl.sliding_contact(A, rho, ratio, s, method=method)
        c1, c2 = r.c1_over_R, r.c2_over_R

        def p(x, r=r):
            return float(r.pressure(np.array([x]))[0])

        # the pressure is -sigma0 on the zones: integrate the contact numerically, the
        # zones exactly, so that the check is not limited by the jumps at +-a
        F = _quad(p, -A, A, None) - s * (c1 - A) - s * (c2 - A)
        M = _quad(lambda x: x * p(x), -A, A, None) - s * (c2**2 - c1**2) / 2
        msg = f"{method}: a/R={A}, R/h2={rho}, h1/h2={ratio}, sigma0/E={s}"
        assert math.isclose(F * rho, r.F_over_Eh2, rel_tol=1e-10, abs_tol=1e-12), msg
        assert math.isclose(M * rho, r.M_over_Eh2R, rel_tol=1e-9, abs_tol=1e-13), msg


@pytest.mark.parametrize(
    ("A", "rho", "ratio", "s"), [(0.03, 100.0, 2.5, 0.04), (0.01, 500.0, 0.5, 0.1)]
)
def test_separation_conditions_by_quadrature_of_the_gap_slope(A, rho, ratio, s):
    """Eqs. 21-22 without their log kernels.

    Outside the contact the gap slope is g'(x) = (x - e)/R + (2/(pi E)) PV int p/(xi - x);
    integrated from the contact edges by adaptive quadrature it must reach h2 at c2 and h1
    at -c1. The pressure is the collocation state's, evaluated as pbar/sqrt(a^2 - xi^2)
    (smooth) against the algebraic end-point weight.
    """
    r = sl.sliding_contact(A, rho, ratio, s, method="collocation")
    c1, c2, e = r.c1_over_R, r.c2_over_R, r.e_over_R
    q1, q2 = math.exp(-math.acosh(c1 / A)), math.exp(-math.acosh(c2 / A))

    def smooth(xi):  # pbar / (E sqrt(a^2 - xi^2)), from the closed form of Eq. 20's solution
        ct = xi / A
        sn = math.sqrt(max(1 - ct * ct, 0.0))
        if sn == 0.0:
            return 0.5 + (2 * s / math.pi) * (q2 / (1 - q2 * ct) + q1 / (1 + q1 * ct)) / A
        return 0.5 + (2 * s / math.pi) * (
            math.atan2(q2 * sn, 1 - q2 * ct) + math.atan2(q1 * sn, 1 + q1 * ct)
        ) / (A * sn)

    def slope(x):
        inner, _ = integrate.quad(
            lambda xi: smooth(xi) / (xi - x),
            -A,
            A,
            weight="alg",
            wvar=(0.5, 0.5),
            epsabs=1e-15,
            epsrel=1e-13,
            limit=200,
        )
        return (x - e) + (2 / math.pi) * (inner - s * math.log(abs((c2 - x) / (c1 + x))))

    g_lead = _quad(slope, A, c2, None) * rho
    g_trail = -_quad(slope, -c1, -A, None) * rho
    assert math.isclose(g_lead, 1.0, rel_tol=1e-12)
    assert math.isclose(g_trail, ratio, rel_tol=1e-12)
    # the pressure used is the collocation solution's
    t = np.linspace(-0.95, 0.95, 9)
    np.testing.assert_allclose(
        [smooth(v) * A * math.sqrt(1 - (v / A) ** 2) - s for v in A * t],
        r.pressure(A * t),
        atol=1e-14,
    )
    np.testing.assert_allclose(
        r.gap(np.array([-c1, -A, 0.0, A, c2])), [ratio, 0.0, 0.0, 0.0, 1.0], atol=1e-11
    )


def test_collocation_pressure_is_the_closed_form():
    r = sl.sliding_contact(0.04, 100.0, 2.0, 0.04, method="closed-form")
    u1 = np.atleast_1d(np.arccosh(r.c1_over_a))
    u2 = np.atleast_1d(np.arccosh(r.c2_over_a))
    solver = BoundedSolver(64)
    f = sl._colloc_rhs(solver.collocation_unit, np.array([0.04]), np.array([0.04]), u1, u2)
    sol = solver.solve(f[:, 0], extra=np.full(65, 0.5))
    t = np.linspace(-0.99, 0.99, 23)
    phi = solver.evaluate(sol, t[None, :])[0] - 0.04
    np.testing.assert_allclose(phi, r.pressure(0.04 * t), atol=1e-14)
    # and the eccentricity fixed by the consistency condition is the closed form's
    assert math.isclose(sol.extra[0], r.e_over_R, rel_tol=1e-13)


# --------------------------------------------------------------------------------------------
# convergence and the solver's diagnostics


def test_convergence_with_the_number_of_nodes():
    A, rho, ratio, s = 0.15, 2000.0, 2.0, 0.2  # thin zones: c/a - 1 of order 1e-2
    ref = sl.sliding_contact(A, rho, ratio, s, method="closed-form")
    assert ref.c2_over_a - 1 < 0.05
    errs, ests = [], []
    for n in (16, 32, 64, 128, 256):
        r = sl.sliding_contact(A, rho, ratio, s, method="collocation", n=n, on_failure="report")
        errs.append(abs(r.F_over_Eh2 / ref.F_over_Eh2 - 1) + abs(r.c2_over_R / ref.c2_over_R - 1))
        ests.append(r.error_estimate)
    assert all(b < a / 4 for a, b in zip(errs[:3], errs[1:4], strict=True)), errs
    assert errs[-1] < 1e-11 and ests[-1] < ests[0] / 1e6
    auto = sl.sliding_contact(A, rho, ratio, s, method="collocation")
    assert auto.n_collocation >= 64 and auto.converged
    assert abs(auto.F_over_Eh2 / ref.F_over_Eh2 - 1) < 1e-11


def test_too_few_nodes_is_reported():
    kw = dict(
        a_over_R=0.15,
        R_over_h2=2000.0,
        h1_over_h2=2.0,
        sigma0_over_E=0.2,
        method="collocation",
        n=8,
    )
    with pytest.raises(ConvergenceError, match=r"did not converge at a_over_R=.*h1_over_h2"):
        sl.sliding_contact(**kw)
    r = sl.sliding_contact(**kw, on_failure="report")
    assert r.converged is False and r.error_estimate > 1e-12


def test_closed_form_jacobian_and_stability_by_finite_differences():
    ab, kap, ratio = np.array([0.7]), np.array([1.3]), np.array([2.2])
    u1, u2 = np.array([1.1]), np.array([0.6])
    E1, E2, *J = sl._cf_eval(ab, kap, ratio, u1, u2)
    h = 1e-6
    for k, (d1, d2) in enumerate(((h, 0), (0, h))):
        p = sl._cf_eval(ab, kap, ratio, u1 + d1, u2 + d2)
        m = sl._cf_eval(ab, kap, ratio, u1 - d1, u2 - d2)
        np.testing.assert_allclose(
            [J[k], J[2 + k]], [(p[0] - m[0]) / (2 * h), (p[1] - m[1]) / (2 * h)], rtol=1e-7
        )
    # dF/da sign is the stability flag: compare with finite differences of F(a)
    A = np.geomspace(0.004, 0.1, 25)
    r = sl.sliding_contact(A, 100.0, 2.0, 0.04, method="closed-form")
    F_p = sl.sliding_contact(A * (1 + 1e-6), 100.0, 2.0, 0.04, method="closed-form").F_over_Eh2
    F_m = sl.sliding_contact(A * (1 - 1e-6), 100.0, 2.0, 0.04, method="closed-form").F_over_Eh2
    np.testing.assert_array_equal(r.stable, F_p > F_m)
    assert not r.stable[0] and r.stable[-1]


# --------------------------------------------------------------------------------------------
# sweeps over the domain


@settings(max_examples=12, deadline=None, derandomize=True)
@given(seed=st.integers(0, 2**32 - 1))
def test_sweep_methods_agree_and_signs_follow_the_ranges(seed):
    rng = np.random.default_rng(seed)
    n = 40
    A = 10 ** rng.uniform(-4, np.log10(0.2), n)
    rho = 10 ** rng.uniform(1, 4, n)
    ratio = 10 ** rng.uniform(-1, 1, n)
    s = 10 ** rng.uniform(-4, np.log10(0.3), n)
    co = sl.sliding_contact(A, rho, ratio, s, method="collocation")
    cf = sl.sliding_contact(A, rho, ratio, s, method="closed-form")
    assert np.all(co.converged) and np.all(cf.converged)
    assert np.all(co.c1_over_R >= A) and np.all(co.c2_over_R >= A)
    np.testing.assert_allclose(co.c1_over_R, cf.c1_over_R, rtol=1e-12)
    np.testing.assert_allclose(co.c2_over_R, cf.c2_over_R, rtol=1e-12)
    scale = _scale_F(cf)
    assert np.all(np.abs(co.F_over_Eh2 - cf.F_over_Eh2) <= 1e-12 * scale)
    e_scale = 2 * s / np.pi * (np.arccosh(cf.c1_over_a) + np.arccosh(cf.c2_over_a))
    assert np.all(np.abs(co.e_over_R - cf.e_over_R) <= 1e-11 * e_scale)
    np.testing.assert_allclose(co.M_axis_over_Eh2R, s * (ratio - 1), rtol=1e-9, atol=1e-15)
    assert np.all(np.maximum(co.residual_leading, co.residual_trailing) <= 1e-10)
    # the longer trailing range gives the longer trailing zone, e > 0 and M > 0
    sign = np.sign(ratio - 1)
    np.testing.assert_array_equal(np.sign(co.c1_over_R - co.c2_over_R), sign)
    np.testing.assert_array_equal(np.sign(co.e_over_R), sign)
    np.testing.assert_array_equal(np.sign(co.M_over_Eh2R), sign)


@settings(max_examples=8, deadline=None, derandomize=True)
@given(
    rho=st.floats(10, 1e4),
    ratio=st.floats(0.2, 5),
    s=st.floats(1e-3, 0.3),
    load=st.floats(0.0, 3.0),
)
def test_sweep_inverse_round_trip(rho, ratio, s, load):
    po = sl.sliding_pull_off(rho, ratio, s)
    assert po.F_pulloff_over_Eh2 <= po.F_zero_width_over_Eh2 < 0
    # loads from just above pull-off to well into compression
    F = po.F_pulloff_over_Eh2 * (1 - load) + load * abs(po.F_pulloff_over_Eh2)
    r = sl.sliding_contact_for_load(F, rho, ratio, s, method="closed-form", tau0_over_E=0.01)
    assert r.stable
    assert math.isclose(r.F_over_Eh2, F, rel_tol=1e-10, abs_tol=1e-12 * abs(F) + 1e-13)
    assert r.a_over_R >= po.a_over_R_at_pulloff
    assert math.isclose(r.T_over_Eh2, 2 * r.a_over_R * rho * 0.01, rel_tol=1e-15)


# --------------------------------------------------------------------------------------------
# inverse, pull-off, limits


def test_inverse_with_friction_and_collocation():
    r = sl.sliding_contact_for_load(
        [-0.5, 0.0, 1.0], 100.0, 2.0, 0.04, tau0_over_E=0.02, method="collocation"
    )
    assert r.method == "collocation" and np.all(r.stable) and np.all(r.converged)
    np.testing.assert_allclose(r.F_over_Eh2, [-0.5, 0.0, 1.0], rtol=1e-11, atol=1e-12)
    np.testing.assert_allclose(r.T_over_Eh2, 2 * r.a_over_R * 100 * 0.02, rtol=1e-15)
    np.testing.assert_allclose(r.T_over_Eh2, r.friction_force(0.02), rtol=1e-15)
    direct = sl.sliding_contact(r.a_over_R, 100.0, 2.0, 0.04, method="collocation")
    np.testing.assert_allclose(direct.F_over_Eh2, r.F_over_Eh2, rtol=1e-13, atol=1e-14)
    assert np.all(np.isnan(direct.T_over_Eh2))


def test_below_pull_off_says_so():
    po = sl.sliding_pull_off(100.0, 2.0, 0.04)
    with pytest.raises(
        NoEquilibriumError,
        match=r"below the pull-off force "
        r"F_pulloff_over_Eh2=-1\.11",
    ):
        sl.sliding_contact_for_load(po.F_pulloff_over_Eh2 - 0.01, 100.0, 2.0, 0.04)
    with pytest.raises(NoEquilibriumError, match="without adhesion"):
        sl.sliding_contact_for_load(-0.1, 100.0, 2.0, 0.0)


def test_zero_width_limit_of_the_branch():
    po = sl.sliding_pull_off(100.0, [1.5, 3.0], 0.01)
    r = sl.sliding_contact(1e-9, 100.0, np.array([1.5, 3.0]), 0.01, method="closed-form")
    np.testing.assert_allclose(r.F_over_Eh2, po.F_zero_width_over_Eh2, rtol=1e-7)
    np.testing.assert_allclose(r.c1_over_R, po.c1_over_R_zero_width, rtol=1e-7)
    np.testing.assert_allclose(r.c2_over_R, po.c2_over_R_zero_width, rtol=1e-7)
    # F = -sigma0 (c1 + c2) at zero width
    np.testing.assert_allclose(
        po.F_zero_width_over_Eh2,
        -0.01 * 100 * (po.c1_over_R_zero_width + po.c2_over_R_zero_width),
        rtol=1e-14,
    )


@pytest.mark.parametrize("s, mechanism", [(0.04, "zero-width"), (0.1, "snap-off")])
def test_pull_off_is_the_load_minimum(s, mechanism):
    po = sl.sliding_pull_off(100.0, 2.0, s)
    # the label: the width at the minimum against the shorter range h2 (h2/R = 0.01)
    assert po.mechanism == mechanism
    assert (po.a_over_R_at_pulloff >= 0.01) == (mechanism == "snap-off")
    a = po.a_over_R_at_pulloff * np.array([0.9, 0.97, 1.0, 1.03, 1.1])
    F = sl.sliding_contact(a, 100.0, 2.0, s, method="closed-form").F_over_Eh2
    assert np.argmin(F) == 2 and math.isclose(F[2], po.F_pulloff_over_Eh2, rel_tol=1e-12)
    assert po.F_pulloff_over_Eh2 < po.F_zero_width_over_Eh2


# --------------------------------------------------------------------------------------------
# interface


def test_scalars_in_scalars_out_and_broadcasting():
    r = sl.sliding_contact(0.02, 100.0, 2.0, 0.01)
    for name in ("c1_over_R", "c2_over_R", "e_over_R", "F_over_Eh2", "M_over_Eh2R"):
        assert isinstance(getattr(r, name), float), name
    assert isinstance(r.converged, bool) and isinstance(r.n_collocation, int)
    b = sl.sliding_contact(
        np.array([[0.01], [0.02]]), 100.0, [1.0, 2.0, 3.0], 0.01, method="collocation"
    )
    assert b.c1_over_R.shape == (2, 3) and b.pressure(np.zeros(5)).shape == (2, 3, 5)
    recs = b.to_records()
    assert len(recs) == 6 and recs[0]["method"] == "collocation"
    assert {"a_over_R", "c1_over_R", "c2_over_R", "e_over_R", "F_over_Eh2", "M_over_Eh2R"} <= set(
        recs[0]
    )


BAD = [
    (dict(a_over_R=0.0), "a_over_R must be in \\[1e-20, 10\\], got 0.0"),
    (dict(a_over_R=np.nan), "a_over_R must be a finite number in \\[1e-20, 10\\], got nan"),
    (dict(R_over_h2=-1.0), "R_over_h2 must be in \\[0.001, 1e\\+12\\], got -1.0"),
    (dict(h1_over_h2=-1.0), "h1_over_h2 must be in \\[0.001, 1000\\], got -1.0"),
    (dict(h1_over_h2=np.inf), "h1_over_h2 must be a finite number in \\[0.001, 1000\\], got inf"),
    (dict(sigma0_over_E=-0.1), "sigma0_over_E must be in \\[0, 1e\\+06\\], got -0.1"),
    (dict(tau0_over_E=-1.0), "tau0_over_E must be in \\[0, 1\\], got -1.0"),
    (dict(method="spline"), "method must be 'closed-form' or 'collocation'"),
    (dict(n=1), "n must be 'auto' or an integer in \\[2, 8192\\]"),
    (dict(tol=0.5), "tol must be in \\[1e-15, 1e-2\\)"),
]


@pytest.mark.parametrize(("kwargs", "message"), BAD)
def test_bad_input(kwargs, message):
    args = dict(a_over_R=0.02, R_over_h2=100.0, h1_over_h2=2.0, sigma0_over_E=0.01)
    args.update(kwargs)
    with pytest.raises(ValueError, match=message):
        sl.sliding_contact(**args)


BAD_INVERSE = [
    (dict(F_over_Eh2=np.nan), "F_over_Eh2 must be a finite number"),
    (dict(R_over_h2=0.0), "R_over_h2 must be in \\[0.001, 1e\\+12\\], got 0.0"),
    (dict(h1_over_h2=0.0), "h1_over_h2 must be in \\[0.001, 1000\\], got 0.0"),
]


@pytest.mark.parametrize(("kwargs", "message"), BAD_INVERSE)
def test_bad_input_inverse(kwargs, message):
    args = dict(F_over_Eh2=0.1, R_over_h2=100.0, h1_over_h2=2.0, sigma0_over_E=0.01)
    args.update(kwargs)
    with pytest.raises(ValueError, match=message):
        sl.sliding_contact_for_load(**args)


def test_pull_off_without_adhesion_is_zero_at_zero_width():
    # as pull_off: no adhesion, no tensile load; the zones are the touching gaps' h1 and h2
    po = sl.sliding_pull_off(100.0, 2.0, 0.0)
    assert po.F_pulloff_over_Eh2 == 0 and po.a_over_R_at_pulloff == 0
    assert po.c1_over_R_zero_width == pytest.approx(math.sqrt(2 * 2.0 / 100.0), rel=1e-15)
    assert po.c2_over_R_zero_width == pytest.approx(math.sqrt(2 / 100.0), rel=1e-15)


def test_bad_input_pull_off():
    with pytest.raises(ValueError, match="sigma0_over_E must be in \\[0, 1e\\+06\\], got -0.1"):
        sl.sliding_pull_off(100.0, 2.0, -0.1)
    with pytest.raises(ValueError, match="h1_over_h2 must be in \\[0.001, 1000\\], got -2.0"):
        sl.sliding_pull_off(100.0, -2.0, 0.1)
