"""Tests of the adhesive normal contact, `linecontact.normal` (paper Eqs. 5--14).

Policy (STYLE habit 8): the collocation solver (the paper's route, Eqs. 9, 11, 12) against the
closed form with ``err_msg`` naming the parameters; every limit (Hertz, JKR, Eq. 14); an
independent check of the separation condition and of equilibrium by direct quadrature of the
returned pressure; round trips ``F(a)`` then ``a(F)``; the pull-off minimum against brute force.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from numpy.testing import assert_allclose, assert_array_equal
from scipy.integrate import quad
from scipy.special import roots_legendre

from linecontact import closed_forms
from linecontact.errors import ConvergenceError, NoEquilibriumError
from linecontact.normal import (
    SNAP_OFF_MIN_WIDTH_OVER_H,
    ZERO_WIDTH_LOAD_RTOL,
    LoadCurve,
    NonContact,
    NormalContact,
    PullOff,
    contact_for_load,
    equilibria,
    load_curve,
    non_contact,
    normal_contact,
    pull_off,
)

SETTINGS = settings(derandomize=True, max_examples=40, deadline=None)

# a snap-off case (kappa = 3.6) and a zero-width case (kappa = 0.18), R/h = 100 as in Fig. 2
SNAP = (100.0, 0.2)
ZERO = (100.0, 0.01)


def log_uniform(lo, hi):
    return st.floats(math.log10(lo), math.log10(hi)).map(lambda e: 10.0**e)


def load_scale(A, C, rho, s):
    """Size of the two parts of the load, pi/4 A^2 rho + 2 s rho sqrt(C^2 - A^2), for F ~ 0."""
    return np.pi / 4 * A * A * rho + 2 * s * rho * np.sqrt(np.maximum(C * C - A * A, 0.0))


# --------------------------------------------------------------------------------------------
# closed form against collocation


@SETTINGS
@given(s=log_uniform(1e-4, 0.3), rho=log_uniform(10.0, 1e4), A=log_uniform(1.0001e-4, 0.2))
def test_collocation_matches_closed_form(s, rho, A):
    msg = f"a_over_R={A}, R_over_h={rho}, sigma0_over_E={s}"
    cf = normal_contact(A, rho, s)
    co = normal_contact(A, rho, s, method="collocation")
    assert co.converged and cf.converged, msg
    assert co.method == "collocation" and cf.method == "closed-form"
    scale = load_scale(A, cf.c_over_R, rho, s)
    assert abs(co.F_over_Eh - cf.F_over_Eh) <= 1e-8 * scale, msg
    assert abs(co.c_over_R - cf.c_over_R) <= 1e-8 * cf.c_over_R, msg
    assert (
        co.stable == cf.stable
        or abs(cf.F_over_Eh - pull_off(rho, s).F_minimum_over_Eh) <= 1e-6 * scale
    ), msg


@pytest.mark.parametrize(
    "A, rho, s", [(0.2, 1e4, 0.3), (0.1, 1e4, 0.3), (0.05, 1e4, 0.3), (0.15, 2000.0, 0.27)]
)
def test_collocation_matches_closed_form_jkr_like(A, rho, s):
    """Thin adhesive zones, c/a - 1 < 1e-2: the hard end for the collocation."""
    msg = f"a_over_R={A}, R_over_h={rho}, sigma0_over_E={s}"
    cf = normal_contact(A, rho, s)
    assert cf.c_over_a - 1 < 1e-2, msg
    co = normal_contact(A, rho, s, method="collocation")
    scale = load_scale(A, cf.c_over_R, rho, s)
    assert abs(co.F_over_Eh - cf.F_over_Eh) <= 1e-8 * scale, msg
    assert abs(co.c_over_R - cf.c_over_R) <= 1e-8 * cf.c_over_R, msg
    assert co.n_collocation > 16, msg  # the adaptive size grew


def test_collocation_matches_closed_form_vectorised():
    A = np.geomspace(1e-4, 0.2, 9)[:, None]
    rho = np.array([10.0, 300.0, 1e4])
    s = np.array([[[1e-4]], [[0.03]], [[0.3]]])
    cf = normal_contact(A, rho, s)
    co = normal_contact(A, rho, s, method="collocation")
    assert co.F_over_Eh.shape == (3, 9, 3)
    scale = load_scale(cf.a_over_R, cf.c_over_R, cf.R_over_h, cf.sigma0_over_E)
    assert_allclose(co.F_over_Eh / scale, cf.F_over_Eh / scale, rtol=0, atol=1e-8)
    assert_allclose(co.c_over_R, cf.c_over_R, rtol=1e-8)


# --------------------------------------------------------------------------------------------
# limits: Hertz, JKR, Eq. 14


@pytest.mark.parametrize("method", ["closed-form", "collocation"])
def test_hertz_limit_exact(method):
    A = np.array([1e-4, 1e-3, 0.01, 0.1, 0.2])
    rho = np.array([[10.0], [1e4]])
    r = normal_contact(A, rho, 0.0, method=method)
    assert_allclose(r.F_over_Eh, np.pi / 4 * A * A * rho, rtol=1e-14, err_msg=method)
    assert_allclose(r.F_over_Eh, closed_forms.hertz_load(A, rho), rtol=1e-14)
    assert np.all(r.stable)
    # the pressure is Hertz's: (1/2) sqrt(a^2 - x^2) / R in units of E
    r1 = normal_contact(0.05, 100.0, 0.0, method=method)
    x = np.linspace(-0.049, 0.049, 11)
    assert_allclose(r1.pressure(x), 0.5 * np.sqrt(0.05**2 - x * x), rtol=1e-12, atol=1e-16)


def test_hertz_limit_approached_as_sigma0_vanishes():
    A = np.array([1e-3, 0.01, 0.1])
    rho = 100.0
    errs = [
        np.max(np.abs(normal_contact(A, rho, s).F_over_Eh / closed_forms.hertz_load(A, rho) - 1))
        for s in (1e-4, 1e-6, 1e-8, 1e-10)
    ]
    for e_big, e_small in zip(errs, errs[1:], strict=False):
        assert e_small < e_big / 50, f"relative Hertz errors {errs}"
    assert errs[-1] < 1e-4


def test_jkr_limit():
    """At fixed w/(E R) = s/rho, rho -> infinity (h -> 0): Maugis-Dugdale -> JKR."""
    W = 1e-4
    A = np.array([0.01, 0.03, 0.1])
    errs, gaps = [], []
    for rho in (1e3, 1e4, 1e5, 1e6, 1e7):
        s = W * rho
        r = normal_contact(A, rho, s)
        errs.append(np.abs(r.F_over_Eh - closed_forms.jkr_load(A, rho, s)) / rho)  # in E R units
        gaps.append(r.c_over_a - 1)
    errs, gaps = np.array(errs), np.array(gaps)
    assert np.all(errs[1:] < errs[:-1] / 50), f"|F - F_JKR|/(E R): {errs}"
    assert np.all(gaps[1:] < gaps[:-1]), f"c/a - 1: {gaps}"
    assert np.all(errs[-1] < 1e-11)
    assert np.all(gaps[-1] < 1e-7)
    # the load itself is a finite number of E R: the comparison is not of two tiny numbers
    assert np.all(np.abs(closed_forms.jkr_load(A, 1e7, W * 1e7)) / 1e7 > 1e-5)


@pytest.mark.parametrize("rho, s", [(100.0, 0.01), (1e4, 0.3), (10.0, 1e-4), (100.0, 0.2)])
def test_eq14_limit_zero_width(rho, s):
    F0 = closed_forms.zero_width_load(rho, s)
    A = np.array([1e-3, 1e-5, 1e-7, 1e-9, 1e-12])
    r = normal_contact(A, rho, s)
    err = np.abs(r.F_over_Eh / F0 - 1)
    msg = f"R_over_h={rho}, sigma0_over_E={s}: {err}"
    assert np.all(np.maximum(err[1:], 1e-14) <= np.maximum(err[:-1], 1e-14)), msg
    assert err[3] < 1e-9, msg
    assert err[4] < 1e-13, msg
    # the adhesive zone tends to that of the non-contact state with zero central gap
    assert_allclose(r.c_over_R[-1], non_contact(0.0, rho, s).c_over_R, rtol=1e-12)


@pytest.mark.parametrize("rho, s", [(100.0, 0.01), (10.0, 1e-4), (1e4, 0.3)])
def test_eq14_limit_collocation_moderate(rho, s):
    A = np.array([1e-6, 1e-7])
    co = normal_contact(A, rho, s, method="collocation")
    cf = normal_contact(A, rho, s)
    assert_allclose(
        co.F_over_Eh, cf.F_over_Eh, rtol=1e-12, err_msg=f"R_over_h={rho}, sigma0_over_E={s}"
    )


@pytest.mark.parametrize("A, rho, s", [(1e-10, 100.0, 0.01), (1e-9, 100.0, 0.2), (1e-12, 1e4, 0.3)])
def test_eq14_limit_collocation_tiny_width(A, rho, s):
    co = normal_contact(A, rho, s, method="collocation")
    assert_allclose(co.F_over_Eh, normal_contact(A, rho, s).F_over_Eh, rtol=1e-12)
    assert co.n_collocation <= 64


# --------------------------------------------------------------------------------------------
# independent checks: separation condition (Eq. 10) and equilibrium (Eq. 12) from the pressure

_XG, _WG = roots_legendre(800)
_TH = 0.5 * np.pi * (_XG + 1)  # x = a cos(theta) on the contact: smooth integrands
_WTH = 0.5 * np.pi * _WG


def gap_rise_over_h(r):
    """(gap(c) - gap(a))/h by quadrature of gap'(x) = x/R + (2/(pi E)) PV int p(s)/(s-x) ds.

    In units of R and E. With p = pbar - sigma0 on |x| < c the Cauchy integral of the constant
    is ln((c-x)/(c+x)); pbar is taken from ``r.pressure`` (Gauss-Legendre in theta, x = a cos);
    the outer integral over a < x < c is scipy's quad (log singularity at x = c).
    """
    A, C, s, rho = r.a_over_R, r.c_over_R, r.sigma0_over_E, r.R_over_h
    S = A * np.cos(_TH)
    pbar_ds = (r.pressure(S) + s) * A * np.sin(_TH) * _WTH

    def dgap(X):
        return X + (2 / np.pi) * (np.sum(pbar_ds / (S - X)) - s * np.log((C - X) / (C + X)))

    val, _ = quad(dgap, A, C, limit=200, epsabs=1e-13, epsrel=1e-12)
    return rho * val


def load_from_pressure(r):
    """rho * int_{-c}^{c} p/E d(x/R), every piece from ``r.pressure``."""
    A, C, rho = r.a_over_R, r.c_over_R, r.R_over_h
    inner = np.sum(r.pressure(A * np.cos(_TH)) * A * np.sin(_TH) * _WTH)
    xz = 0.5 * (C - A) * (_XG + 1) + A  # the adhesive zones
    zones = 0.5 * (C - A) * np.sum(_WG * (r.pressure(xz) + r.pressure(-xz)))
    return rho * (inner + zones)


SEPARATION_POINTS = [
    (0.05, 100.0, 0.01),
    (0.02, 1000.0, 0.1),
    (0.1, 100.0, 0.2),
    (0.001, 100.0, 0.01),
    (0.13, 1000.0, 0.1),
    (0.05, 100.0, 0.0),
]


@pytest.mark.parametrize("method", ["closed-form", "collocation"])
@pytest.mark.parametrize("A, rho, s", SEPARATION_POINTS)
def test_separation_condition_by_quadrature(A, rho, s, method):
    r = normal_contact(A, rho, s, method=method)
    msg = f"{method}: a_over_R={A}, R_over_h={rho}, sigma0_over_E={s}"
    assert abs(gap_rise_over_h(r) - 1) <= 1e-6, msg
    # a wrong c must fail the check
    wrong = NormalContact(**{**r.to_dict(), "c_over_R": r.c_over_R * (1 + 1e-3)})
    assert abs(gap_rise_over_h(wrong) - 1) > 1e-6, msg


@pytest.mark.parametrize("method", ["closed-form", "collocation"])
@pytest.mark.parametrize("A, rho, s", SEPARATION_POINTS)
def test_equilibrium_by_quadrature(A, rho, s, method):
    r = normal_contact(A, rho, s, method=method)
    scale = load_scale(A, r.c_over_R, rho, s)
    assert abs(load_from_pressure(r) - r.F_over_Eh) <= 1e-10 * scale, (
        f"{method}: a_over_R={A}, R_over_h={rho}, sigma0_over_E={s}"
    )


def test_pressure_shape_and_regions():
    r = normal_contact(np.array([0.02, 0.05]), 100.0, 0.05)
    x = np.array([0.0, 0.019, 0.03, 0.049, 0.2])
    p = r.pressure(x)
    assert p.shape == (2, 5)
    C = r.c_over_R
    zone = outside = 0
    for i in range(2):
        for j, xv in enumerate(x):
            if r.a_over_R[i] <= abs(xv) <= C[i]:
                assert p[i, j] == -0.05
                zone += 1
            elif abs(xv) > C[i]:
                assert p[i, j] == 0.0
                outside += 1
    assert zone >= 2 and outside >= 2  # both regions are sampled
    # continuous at the contact edge (bounded solution, Eq. 9): p(a-) = -sigma0
    a = r.a_over_R[0]
    assert_allclose(r.pressure(np.array([a * (1 - 1e-12)]))[0], -0.05, atol=1e-6)
    # the centre: p(0)/E = a/(2R) - (2 s0/(pi E)) arctan(sqrt(c^2 - a^2)/a)
    A = r.a_over_R
    assert_allclose(
        p[:, 0], A / 2 - (2 * 0.05 / np.pi) * np.arctan(np.sqrt(C * C - A * A) / A), rtol=1e-13
    )


# --------------------------------------------------------------------------------------------
# convergence and diagnostics of the collocation solver

CONV_POINT = (0.13, 1000.0, 0.1)  # c/a = 1.05


def test_collocation_converges_geometrically():
    A, rho, s = CONV_POINT
    cf = normal_contact(A, rho, s)
    m = cf.c_over_a
    assert abs(m - 1.05) < 1e-3
    rate = m + np.sqrt(m * m - 1)  # Bernstein ellipse of the log source at x = c
    ns = [16, 32, 64, 128]
    runs = [normal_contact(A, rho, s, method="collocation", n=n, on_failure="report") for n in ns]
    errF = np.array([abs(r.F_over_Eh - cf.F_over_Eh) / abs(cf.F_over_Eh) for r in runs])
    errC = np.array([abs(r.c_over_R / cf.c_over_R - 1) for r in runs])
    for i in range(len(ns) - 1):
        dn = ns[i + 1] - ns[i]
        for name, e in (("F", errF), ("c", errC)):
            assert e[i + 1] <= max(10 * rate**-dn * e[i], 1e-14), f"{name} errors {e} at n={ns}"
    assert errF[0] > 1e-6  # the coarse error is real
    assert errF[-1] < 1e-13 and errC[-1] < 1e-13
    for r, n, eF, eC in zip(runs, ns, errF, errC, strict=True):
        assert r.n_collocation == n
        assert r.residual_separation <= 1e-12, f"n={n}"
        assert r.residual_consistency <= 1e-15, f"n={n}"
        assert max(eF, eC) <= max(r.error_estimate, 1e-14), f"n={n}: estimate below error"
        assert r.converged == (r.error_estimate <= 1e-11), f"n={n}"
    assert not runs[0].converged and runs[-1].converged
    ests = [r.error_estimate for r in runs]
    assert all(b < a for a, b in zip(ests[:2], ests[1:3], strict=True))


def test_diagnostics_shapes_and_types():
    A = np.array([[0.01], [0.13]])
    s = np.array([1e-3, 0.05, 0.1])
    co = normal_contact(A, 1000.0, s, method="collocation")
    cf = normal_contact(A, 1000.0, s)
    for r in (co, cf):
        for name in (
            "a_over_R",
            "c_over_R",
            "F_over_Eh",
            "R_over_h",
            "sigma0_over_E",
            "n_collocation",
            "residual_separation",
            "residual_consistency",
            "error_estimate",
            "converged",
            "stable",
        ):
            assert np.shape(getattr(r, name)) == (2, 3), f"{r.method}: {name}"
        assert r.converged.dtype == bool and r.stable.dtype == bool
        assert np.issubdtype(r.n_collocation.dtype, np.integer)
        assert np.all(r.converged)
        assert np.all(r.residual_separation <= 1e-12)
    assert_array_equal(cf.n_collocation, 0)
    assert_array_equal(cf.residual_consistency, 0.0)
    assert_array_equal(cf.error_estimate, 0.0)
    assert np.all(co.n_collocation >= 16)
    assert np.all(co.error_estimate <= 1e-11)
    assert np.all(co.residual_consistency <= 1e-15)
    assert np.all(co.c_over_a >= 1)


def test_convergence_error_names_the_point():
    with pytest.raises(
        ConvergenceError, match=r"a_over_R=.*0\.1.*R_over_h=.*10000\.0.*sigma0_over_E=.*0\.3"
    ):
        normal_contact(0.1, 1e4, 0.3, method="collocation", n=16)
    assert issubclass(ConvergenceError, RuntimeError)
    r = normal_contact(0.1, 1e4, 0.3, method="collocation", n=16, on_failure="report")
    assert r.converged is False and r.n_collocation == 16 and r.error_estimate > 1e-11
    # the first failing point of an array is the one named
    with pytest.raises(ConvergenceError, match=r"a_over_R=.*0\.2"):
        normal_contact(np.array([1e-7, 0.2, 0.1]), 1e4, 0.3, method="collocation", n=16)


def test_error_messages_show_plain_numbers():
    with pytest.raises(ConvergenceError) as info:
        normal_contact(0.1, 1e4, 0.3, method="collocation", n=16)
    assert "a_over_R=0.1," in str(info.value), str(info.value)
    with pytest.raises(NoEquilibriumError) as info:
        contact_for_load(-100.0, *SNAP)
    assert "F_over_Eh=-100.0" in str(info.value), str(info.value)


# --------------------------------------------------------------------------------------------
# arrays in, arrays out; scalars in, scalars out


@pytest.mark.parametrize("method", ["closed-form", "collocation"])
def test_broadcasting(method):
    A = np.array([[0.01], [0.03], [0.06]])
    rho = np.array([50.0, 100.0, 200.0, 400.0])
    r = normal_contact(A, rho, 0.02, method=method)
    assert r.F_over_Eh.shape == (3, 4)
    assert r.R_over_h.shape == (3, 4) and r.sigma0_over_E.shape == (3, 4)
    assert_array_equal(r.a_over_R, np.broadcast_to(A, (3, 4)))
    single = normal_contact(0.03, 200.0, 0.02, method=method)
    assert_allclose(r.F_over_Eh[1, 2], single.F_over_Eh, rtol=1e-13)
    assert_allclose(r.c_over_R[1, 2], single.c_over_R, rtol=1e-13)
    assert normal_contact([0.01], 100.0, 0.02, method=method).F_over_Eh.shape == (1,)


@pytest.mark.parametrize("method", ["closed-form", "collocation"])
def test_scalars_give_python_scalars(method):
    r = normal_contact(0.05, 100.0, 0.02, method=method)
    for name in (
        "a_over_R",
        "c_over_R",
        "F_over_Eh",
        "R_over_h",
        "sigma0_over_E",
        "residual_separation",
        "residual_consistency",
        "error_estimate",
    ):
        assert type(getattr(r, name)) is float, name
    assert type(r.n_collocation) is int
    assert type(r.converged) is bool and type(r.stable) is bool
    d = r.to_dict()
    assert d["method"] == method and type(d["F_over_Eh"]) is float


def test_stable_flag_is_sign_of_dF_da():
    rho, s = SNAP
    A = np.geomspace(1e-3, 0.5, 40)
    r = normal_contact(A, rho, s)
    h = 1e-6
    dF = (
        normal_contact(A * (1 + h), rho, s).F_over_Eh
        - normal_contact(A * (1 - h), rho, s).F_over_Eh
    )
    assert_array_equal(r.stable, dF > 0)
    assert not r.stable[0] and r.stable[-1]


# --------------------------------------------------------------------------------------------
# pull-off


def test_kappa_stationary_strictly_decreasing():
    u = np.geomspace(1e-6, 1e6, 200_001)
    k = closed_forms._kappa_stationary(u)
    assert np.all(np.isfinite(k))
    assert np.all(np.diff(k) < 0)
    # the ends: infinity at u -> 0 (as 2 sqrt(2) u^(-3/2)) and 0 at u -> infinity
    assert_allclose(k[0], 2 * np.sqrt(2) * 1e-6**-1.5, rtol=1e-5)
    assert k[-1] < 1e-5


@pytest.mark.slow
def test_pull_off_is_the_minimum_over_a_dense_grid():
    """Brute force: no point of a dense a/R grid (1e-12 .. 1) lies below F_minimum_over_Eh."""
    A = np.geomspace(1e-12, 1.0, 100_000)
    cases = [
        (100.0, 1e-3),
        (100.0, 0.01),
        (100.0, 0.05),
        (100.0, 0.1),
        (100.0, 0.2),
        (100.0, 0.5),
        (10.0, 1e-4),
        (1e4, 0.3),
        (1000.0, 0.1),
    ]
    for rho, s in cases:
        po = pull_off(rho, s)
        F = normal_contact(A, rho, s).F_over_Eh
        Fmin = po.F_minimum_over_Eh
        msg = f"R_over_h={rho}, sigma0_over_E={s}, kappa={po.kappa:.4g}"
        assert F.min() >= Fmin - 1e-12 * abs(Fmin), msg
        assert F.min() - Fmin <= 1e-7 * abs(Fmin), msg
        assert po.F_pulloff_over_Eh >= Fmin
        if po.mechanism == "snap-off":
            assert_allclose(A[np.argmin(F)], po.a_over_R_at_minimum, rtol=2e-3, err_msg=msg)


@pytest.mark.parametrize("rho, s", [(100.0, 1e-3), ZERO, (10.0, 1e-4), (1e3, 1e-3)])
def test_pull_off_zero_width_mechanism(rho, s):
    po = pull_off(rho, s)
    msg = f"R_over_h={rho}, sigma0_over_E={s}"
    assert po.mechanism == "zero-width", msg
    # the minimum is at a width below the adhesion range h, and at the load of Eq. 14
    assert po.a_over_R_at_pulloff < SNAP_OFF_MIN_WIDTH_OVER_H / rho
    assert po.a_over_R_at_pulloff == po.a_over_R_at_minimum
    assert po.F_pulloff_over_Eh == po.F_minimum_over_Eh <= po.F_zero_width_over_Eh
    assert_allclose(po.F_pulloff_over_Eh, closed_forms.zero_width_load(rho, s), rtol=1e-8)
    assert_allclose(po.c_over_R_at_pulloff, non_contact(0.0, rho, s).c_over_R, rtol=1e-8)
    assert_allclose(po.kappa, closed_forms.kappa(rho, s), rtol=1e-15)
    assert_allclose(po.maugis_parameter, closed_forms.maugis_parameter(rho, s), rtol=1e-15)


@pytest.mark.parametrize("rho", [10.0, 100.0, 1e3, 1e4])
def test_the_mechanism_changes_where_the_width_at_pull_off_reaches_h(rho):
    s = np.geomspace(1e-4, 1.0, 400)
    po = pull_off(rho, s)
    snap = po.mechanism == "snap-off"
    assert snap.any() and not snap.all()
    # one switch, from peeling (weak adhesion) to snap-off (strong adhesion), at a = h or
    # where the force leaves Eq. 14 by 1 % (at R/h = 10 first: a is still 0.63 h there)
    k = int(np.argmax(snap))
    assert not snap[:k].any() and snap[k:].all()
    rel = po.F_pulloff_over_Eh / po.F_zero_width_over_Eh - 1
    A = po.a_over_R_at_pulloff
    assert A[k - 1] < 1 / rho and rel[k - 1] <= ZERO_WIDTH_LOAD_RTOL
    assert A[k] >= 1 / rho or rel[k] > ZERO_WIDTH_LOAD_RTOL
    assert (rel[k] > ZERO_WIDTH_LOAD_RTOL) == (rho == 10.0)
    # the pull-off force is the minimum of the load whatever the label
    assert_array_equal(po.F_pulloff_over_Eh, po.F_minimum_over_Eh)
    # where the label says zero width the load is close to Eq. 14 (docs/derivations.md)
    bound = {10.0: 1e-2, 100.0: 2.2e-3, 1e3: 1.9e-4, 1e4: 1.8e-5}[rho]
    assert np.all(rel[~snap] <= bound) and np.all(rel[~snap] >= 0)


@pytest.mark.parametrize("rho, s", [SNAP, (100.0, 0.5), (1000.0, 0.1), (1e4, 0.3)])
def test_pull_off_snap_off_mechanism(rho, s):
    po = pull_off(rho, s)
    msg = f"R_over_h={rho}, sigma0_over_E={s}"
    assert po.mechanism == "snap-off", msg
    assert po.a_over_R_at_pulloff > 0, msg
    assert po.a_over_R_at_pulloff == po.a_over_R_at_minimum
    assert po.F_pulloff_over_Eh == po.F_minimum_over_Eh
    assert po.F_pulloff_over_Eh < closed_forms.zero_width_load(rho, s) * (1 + 1e-6), msg
    r = normal_contact(po.a_over_R_at_pulloff, rho, s)
    assert_allclose(r.F_over_Eh, po.F_pulloff_over_Eh, rtol=1e-12, err_msg=msg)
    assert_allclose(r.c_over_R, po.c_over_R_at_pulloff, rtol=1e-12, err_msg=msg)


def test_pull_off_hertz():
    po = pull_off(100.0, 0.0)
    assert po.F_pulloff_over_Eh == 0.0 and po.mechanism == "zero-width"
    assert po.kappa == 0.0


@pytest.mark.parametrize("rho, s", [SNAP, (100.0, 0.05), (1000.0, 0.1), (100.0, 0.5), (1e4, 0.3)])
def test_load_is_stationary_at_the_minimum(rho, s):
    po = pull_off(rho, s)
    a = po.a_over_R_at_minimum

    def a_dF_da(aa, h=1e-4):
        return (
            normal_contact(aa * (1 + h), rho, s).F_over_Eh
            - normal_contact(aa * (1 - h), rho, s).F_over_Eh
        ) / (2 * h)

    left, mid, right = a_dF_da(0.8 * a), a_dF_da(a), a_dF_da(1.2 * a)
    msg = f"R_over_h={rho}, sigma0_over_E={s}: {left}, {mid}, {right}"
    assert left < 0 < right, msg
    assert abs(mid) <= 1e-4 * min(abs(left), abs(right)), msg


def test_pull_off_vectorised_1000_points():
    rng = np.random.default_rng(20240501)
    rho = 10 ** rng.uniform(0, 5, 1000)
    s = 10 ** rng.uniform(-5, 0, 1000)
    po = pull_off(rho, s)
    assert po.F_pulloff_over_Eh.shape == (1000,)
    for name in (
        "F_pulloff_over_Eh",
        "a_over_R_at_pulloff",
        "c_over_R_at_pulloff",
        "F_minimum_over_Eh",
        "a_over_R_at_minimum",
        "kappa",
    ):
        assert np.all(np.isfinite(getattr(po, name))), name
    F0 = closed_forms.zero_width_load(rho, s)
    assert np.all(po.F_pulloff_over_Eh <= F0)
    assert np.all(po.F_pulloff_over_Eh < 0)
    assert set(np.unique(po.mechanism)) == {"snap-off", "zero-width"}
    zw = po.mechanism == "zero-width"
    assert_array_equal(po.F_pulloff_over_Eh, po.F_minimum_over_Eh)
    # the label: a snap-off lets go from a width of at least h or more than 1 % below Eq. 14,
    # a zero width below h and within 1 % of it
    gap = po.F_pulloff_over_Eh / F0 - 1
    assert np.all((po.a_over_R_at_pulloff[~zw] >= 1 / rho[~zw]) | (gap[~zw] > 1e-2))
    assert np.all((po.a_over_R_at_pulloff[zw] < 1 / rho[zw]) & (gap[zw] <= 1e-2))
    # pull_off broadcasts like the others
    assert pull_off(np.array([[10.0], [100.0]]), np.array([0.01, 0.1, 0.3])).kappa.shape == (2, 3)


def test_pull_off_scalar_output():
    po = pull_off(*SNAP)
    assert isinstance(po, PullOff)
    assert type(po.F_pulloff_over_Eh) is float and type(po.mechanism) is str
    assert isinstance(po.maugis_parameter, float)


# --------------------------------------------------------------------------------------------
# contact_for_load: round trips and pull-off


@pytest.mark.parametrize("rho, s", [SNAP, (1000.0, 0.1), (1e4, 0.3)])
def test_contact_for_load_round_trip(rho, s):
    po = pull_off(rho, s)
    am = po.a_over_R_at_minimum
    msg = f"R_over_h={rho}, sigma0_over_E={s}"
    A_st = am * np.array([1.02, 1.2, 1.5, 3.0, 10.0])
    nc = normal_contact(A_st, rho, s)
    r = contact_for_load(nc.F_over_Eh, rho, s)
    assert_allclose(r.a_over_R, A_st, rtol=1e-10, err_msg=f"stable, {msg}")
    assert_allclose(r.c_over_R, nc.c_over_R, rtol=1e-10, err_msg=f"stable, {msg}")
    assert_allclose(r.F_over_Eh, nc.F_over_Eh, rtol=1e-12)
    assert np.all(r.stable)
    A_un = am * np.array([1e-3, 0.01, 0.3, 0.8, 0.98])
    nc = normal_contact(A_un, rho, s)
    assert np.all(nc.F_over_Eh < po.F_zero_width_over_Eh)
    r = contact_for_load(nc.F_over_Eh, rho, s, branch="unstable")
    assert_allclose(r.a_over_R, A_un, rtol=1e-8, err_msg=f"unstable, {msg}")
    assert not np.any(r.stable)


def test_contact_for_load_round_trip_zero_width_and_hertz():
    A = np.array([1e-3, 0.01, 0.05, 0.2])
    for rho, s in (ZERO, (100.0, 0.0)):
        nc = normal_contact(A, rho, s)
        r = contact_for_load(nc.F_over_Eh, rho, s)
        assert_allclose(r.a_over_R, A, rtol=1e-10, err_msg=f"R_over_h={rho}, sigma0_over_E={s}")
    # scalars in, scalars out
    r = contact_for_load(1.0, *SNAP)
    assert type(r.a_over_R) is float and type(r.stable) is bool
    assert_allclose(normal_contact(r.a_over_R, *SNAP).F_over_Eh, 1.0, rtol=1e-12)


def test_contact_for_load_below_pull_off():
    po = pull_off(*SNAP)
    assert issubclass(NoEquilibriumError, ValueError)
    with pytest.raises(NoEquilibriumError, match="pull-off"):
        contact_for_load(po.F_pulloff_over_Eh * 1.001, *SNAP)
    with pytest.raises(NoEquilibriumError, match="pull-off"):
        contact_for_load(np.array([1.0, -100.0]), *SNAP)
    with pytest.raises(NoEquilibriumError, match="pull-off"):
        contact_for_load(-1e-3, 100.0, 0.0)  # no adhesion, no tensile load
    # just above the pull-off force a stable and an unstable state straddle the minimum
    F = po.F_pulloff_over_Eh * (1 - 1e-6)
    r_st = contact_for_load(F, *SNAP)
    r_un = contact_for_load(F, *SNAP, branch="unstable")
    assert r_un.a_over_R < po.a_over_R_at_pulloff < r_st.a_over_R
    for r in (r_st, r_un):
        assert_allclose(r.a_over_R, po.a_over_R_at_pulloff, rtol=1e-2)
        assert_allclose(r.F_over_Eh, F, rtol=1e-12)
        assert_allclose(normal_contact(r.a_over_R, *SNAP).F_over_Eh, F, rtol=1e-12)
    # the unstable branch exists only between the minimum and Eq. 14
    with pytest.raises(NoEquilibriumError, match="F_zero_width_over_Eh"):
        contact_for_load(0.5 * po.F_zero_width_over_Eh, *SNAP, branch="unstable")


# --------------------------------------------------------------------------------------------
# equilibria


def test_equilibria_between_minimum_and_eq14():
    po = pull_off(*SNAP)
    F = 0.5 * (po.F_minimum_over_Eh + po.F_zero_width_over_Eh)
    states = equilibria(F, *SNAP)
    assert len(states) == 2
    assert all(st_.branch == "contact" for st_ in states)
    assert sorted(st_.stable for st_ in states) == [False, True]
    stable = next(st_ for st_ in states if st_.stable)
    unstable = next(st_ for st_ in states if not st_.stable)
    assert stable.a_over_R > po.a_over_R_at_minimum > unstable.a_over_R > 0
    for st_ in states:
        r = normal_contact(st_.a_over_R, *SNAP)
        assert_allclose(r.F_over_Eh, F, rtol=1e-10)
        assert_allclose(r.c_over_R, st_.c_over_R, rtol=1e-10)


@pytest.mark.parametrize("frac", [1.0, 0.7, 0.2])
def test_equilibria_above_eq14_has_a_non_contact_state(frac):
    po = pull_off(*SNAP)
    F = frac * po.F_zero_width_over_Eh  # F >= Eq. 14 (tensile)
    states = equilibria(F, *SNAP)
    branches = [st_.branch for st_ in states]
    assert branches.count("contact") == 1 and branches.count("non-contact") == 1
    for st_ in states:
        assert st_.F_over_Eh == F
        if st_.branch == "contact":
            assert st_.stable
            assert_allclose(normal_contact(st_.a_over_R, *SNAP).F_over_Eh, F, rtol=1e-10)
        else:
            assert not st_.stable and st_.a_over_R == 0.0
            nc = non_contact(st_.central_gap_over_h, *SNAP)
            assert_allclose(nc.F_over_Eh, F, rtol=1e-10)
            assert_allclose(nc.c_over_R, st_.c_over_R, rtol=1e-10)


def test_equilibria_compressive_and_below_pull_off():
    states = equilibria(2.0, *SNAP)
    assert len(states) == 1 and states[0].stable and states[0].branch == "contact"
    assert equilibria(1.01 * pull_off(*SNAP).F_pulloff_over_Eh, *SNAP) == ()


# --------------------------------------------------------------------------------------------
# non_contact


def test_non_contact_end_points_and_monotonicity():
    for rho, s in (SNAP, ZERO, (1e4, 0.3)):
        r0 = non_contact(0.0, rho, s)
        assert_allclose(r0.F_over_Eh, closed_forms.zero_width_load(rho, s), rtol=1e-14)
        r1 = non_contact(1.0, rho, s)
        assert r1.F_over_Eh == 0.0 and r1.c_over_R == 0.0
        g = np.linspace(0, 1, 101)
        r = non_contact(g, rho, s)
        assert isinstance(r, NonContact)
        assert np.all(np.diff(r.F_over_Eh) > 0)  # less attraction as the gap opens
        assert np.all(np.diff(r.c_over_R) < 0)
        assert not np.any(r.stable)
        assert_allclose(r.F_over_Eh, -2 * s * rho * r.c_over_R, rtol=1e-15)


@pytest.mark.parametrize("g0", [0.0, 0.3, 0.9])
def test_non_contact_gap_by_quadrature(g0):
    """Uniform tension -sigma0 on |x| < c: the gap rises by h - g0 from x = 0 to x = c."""
    rho, s = SNAP
    r = non_contact(g0, rho, s)
    C = r.c_over_R

    def dgap(X):  # x/R + (2/(pi E)) PV int_{-c}^{c} (-sigma0)/(s - x) ds
        return X - (2 * s / np.pi) * np.log((C - X) / (C + X))

    val, _ = quad(dgap, 0, C, epsabs=1e-14, epsrel=1e-13)
    assert_allclose(rho * val, 1 - g0, rtol=1e-10, err_msg=f"g0={g0}")


def test_non_contact_without_adhesion():
    r = non_contact(np.array([0.0, 0.5]), 100.0, 0.0)
    assert_array_equal(r.F_over_Eh, 0.0)
    assert_allclose(r.c_over_R, np.sqrt(2 * (1 - np.array([0.0, 0.5])) / 100.0), rtol=1e-15)


# --------------------------------------------------------------------------------------------
# load_curve


def test_load_curve_snap_off():
    rho, s = SNAP
    lc = load_curve(rho, s)
    assert isinstance(lc, LoadCurve)
    assert set(lc.branch.tolist()) == {"contact", "non-contact"}
    nc = lc.branch == "non-contact"
    ct = ~nc
    assert np.all(nc[: nc.sum()]), "non-contact states come first"
    assert lc.turning_point.sum() == 1
    i = int(np.flatnonzero(lc.turning_point)[0])
    po = lc.pulloff
    assert isinstance(po, PullOff) and po.mechanism == "snap-off"
    assert po == pull_off(rho, s)
    assert lc.branch[i] == "contact"
    assert_allclose(lc.a_over_R[i], po.a_over_R_at_minimum, rtol=1e-14)
    assert_allclose(lc.F_over_Eh[i], po.F_pulloff_over_Eh, rtol=1e-12)
    assert lc.F_over_Eh.min() >= po.F_pulloff_over_Eh - 1e-12 * abs(po.F_pulloff_over_Eh)
    # both branches of the contact curve are present
    assert np.any(lc.stable[ct]) and np.any(~lc.stable[ct])
    assert np.all(lc.a_over_R[ct][lc.stable[ct]] >= po.a_over_R_at_minimum * (1 - 1e-12))
    # ordering: from g0 = h (F = 0) to touch-down, then a increasing
    assert lc.central_gap_over_h[0] == 1.0 and lc.F_over_Eh[0] == 0.0
    assert np.all(np.diff(lc.central_gap_over_h[nc]) < 0)
    assert np.all(np.diff(lc.a_over_R[ct]) > 0)
    assert_allclose(lc.F_over_Eh[nc][-1], closed_forms.zero_width_load(rho, s), rtol=1e-14)
    assert_array_equal(lc.a_over_R[nc], 0.0)
    assert_array_equal(lc.central_gap_over_h[ct], 0.0)
    assert_allclose(lc.F_over_Eh[ct], normal_contact(lc.a_over_R[ct], rho, s).F_over_Eh, rtol=1e-13)
    assert lc.a_over_R.size == lc.F_over_Eh.size == lc.c_over_R.size == lc.stable.size


def test_load_curve_sizes_and_hertz():
    lc = load_curve(100.0, 0.0, num=20, num_noncontact=5, a_max_over_R=0.1)
    assert set(lc.branch.tolist()) == {"contact"}  # no adhesion: no non-contact branch
    assert lc.a_over_R.max() == 0.1
    assert not lc.turning_point.any()
    assert_allclose(lc.F_over_Eh, closed_forms.hertz_load(lc.a_over_R, 100.0), rtol=1e-14)
    lc = load_curve(*SNAP, num=20, num_noncontact=5)
    assert (lc.branch == "non-contact").sum() == 5


# --------------------------------------------------------------------------------------------
# bad input: ValueError naming the parameter (the message is part of the API)

BAD_NORMAL = [
    (normal_contact, (0.0, 100.0, 0.01), {}, r"a_over_R must be in \[1e-150, 10\], got 0\.0"),
    (normal_contact, (-0.1, 100.0, 0.01), {}, r"a_over_R must be in \[1e-150, 10\], got -0\.1"),
    (normal_contact, (np.nan, 100.0, 0.01), {}, r"a_over_R must be a finite number"),
    (normal_contact, (np.inf, 100.0, 0.01), {}, r"a_over_R must be a finite number"),
    (normal_contact, (0.1, 0.0, 0.01), {}, r"R_over_h must be in \[0.001, 1e\+12\], got 0\.0"),
    (normal_contact, (0.1, -100.0, 0.01), {}, r"R_over_h must be in \[0.001, 1e\+12\]"),
    (normal_contact, (0.1, np.inf, 0.01), {}, r"R_over_h must be a finite number"),
    (normal_contact, (0.1, 100.0, -0.01), {}, r"sigma0_over_E must be in \[0, 1e\+06\]"),
    (normal_contact, (0.1, 100.0, np.nan), {}, r"sigma0_over_E must be a finite number"),
    (normal_contact, ([0.1, -0.2], 100.0, 0.01), {}, r"a_over_R must be in .* got -0\.2"),
    (
        normal_contact,
        (0.1, 100.0, 0.01),
        {"method": "foo"},
        r"method must be 'closed-form' or 'collocation', got 'foo'",
    ),
    (
        normal_contact,
        (0.1, 100.0, 0.01),
        {"method": "collocation", "n": 1},
        r"n must be 'auto' or an integer in \[2, 8192\], got 1",
    ),
    (normal_contact, (0.1, 100.0, 0.01), {"n": 1.5}, r"n must be 'auto' or an integer"),
    (normal_contact, (0.1, 100.0, 0.01), {"n": True}, r"n must be 'auto' or an integer"),
    (normal_contact, (0.1, 100.0, 0.01), {"n": 10_000}, r"n must be 'auto' or an integer"),
    (normal_contact, (0.1, 100.0, 0.01), {"n": "fast"}, r"n must be 'auto' or an integer"),
    (normal_contact, (0.1, 100.0, 0.01), {"tol": 0}, r"tol must be in \[1e-15, 1e-2\), got 0"),
    (normal_contact, (0.1, 100.0, 0.01), {"tol": 0.1}, r"tol must be in \[1e-15, 1e-2\)"),
    (normal_contact, (0.1, 100.0, 0.01), {"tol": np.nan}, r"tol must be in \[1e-15, 1e-2\)"),
    (pull_off, (0.0, 0.1), {}, r"R_over_h must be in \[0.001, 1e\+12\], got 0\.0"),
    (pull_off, (np.nan, 0.1), {}, r"R_over_h must be a finite number"),
    (pull_off, (100.0, -0.1), {}, r"sigma0_over_E must be in \[0, 1e\+06\], got -0\.1"),
    (pull_off, (100.0, np.inf), {}, r"sigma0_over_E must be a finite number"),
    (contact_for_load, (np.nan, 100.0, 0.1), {}, r"F_over_Eh must be a finite number"),
    (contact_for_load, (np.inf, 100.0, 0.1), {}, r"F_over_Eh must be a finite number"),
    (contact_for_load, (1.0, -1.0, 0.1), {}, r"R_over_h must be in \[0.001, 1e\+12\]"),
    (contact_for_load, (1.0, 100.0, -0.1), {}, r"sigma0_over_E must be in \[0, 1e\+06\]"),
    (
        contact_for_load,
        (1.0, 100.0, 0.1),
        {"branch": "both"},
        r"branch must be 'stable' or 'unstable', got 'both'",
    ),
    (non_contact, (-0.1, 100.0, 0.1), {}, r"central_gap_over_h must be in \[0, 1\], got -0\.1"),
    (non_contact, (1.5, 100.0, 0.1), {}, r"central_gap_over_h must be in \[0, 1\], got 1\.5"),
    (non_contact, (np.nan, 100.0, 0.1), {}, r"central_gap_over_h must be a finite number"),
    (non_contact, (0.5, 0.0, 0.1), {}, r"R_over_h must be in \[0.001, 1e\+12\]"),
    (non_contact, (0.5, 100.0, -1.0), {}, r"sigma0_over_E must be in \[0, 1e\+06\]"),
    (equilibria, (np.nan, 100.0, 0.1), {}, r"F_over_Eh must be a finite number"),
    (equilibria, (1.0, 0.0, 0.1), {}, r"R_over_h must be in \[0.001, 1e\+12\]"),
    (load_curve, (100.0, 0.1), {"num": 1}, r"num must be an integer in \[2, 10000000\], got 1"),
    # issue 20: 10**10 points failed in NumPy's allocator (MemoryError); refused up front
    (load_curve, (100.0, 0.01), {"num": 10**10}, r"^num must be an integer in \[2, 10000000\]"),
    (load_curve, (100.0, 0.1), {"num": True}, r"num must be an integer in \[2, 10000000\]"),
    (load_curve, (100.0, 0.1), {"num_noncontact": 1.5}, r"num_noncontact must be an integer"),
    (load_curve, (100.0, 0.1), {"a_max_over_R": -1.0}, r"a_max_over_R must be in \[1e-100, 10\]"),
]


@pytest.mark.parametrize(
    "func, args, kwargs, message",
    BAD_NORMAL,
    ids=[f"{f.__name__}-{m}" for f, _, _, m in BAD_NORMAL],
)
def test_bad_input(func, args, kwargs, message):
    with pytest.raises(ValueError, match=message):
        func(*args, **kwargs)
