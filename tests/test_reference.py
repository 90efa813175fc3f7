"""Tests of the closed forms in `linecontact.closed_forms` (Hertz, JKR, Eq. 14, the groups).

Policy (STYLE habit 8): every closed form against a number that does not come from its own
formula: the integral it stands for (Hertz: the load as the quadrature of the Hertz pressure,
which is checked to solve Eq. 9), the problem it solves (the JKR pull-off as the numerical
minimum of the JKR load, against the minimum derived by hand; Eq. 14 as ``-2 sigma0 c`` of the
touching state, its separation condition solved by root finding), a second method (the
collocation solver of ``linecontact.normal``, which does not use these functions) and limits
(JKR as the Maugis--Dugdale state for a vanishing range at fixed work of adhesion), with values
worked out by hand where a definition is all there is (kappa, the Maugis parameter). Eq. (14) is
also checked literally as printed in the paper (in 40-digit decimal arithmetic so that the
reference is not limited by the cancellation in ``s - sqrt(s^2 + k)``).
"""

from __future__ import annotations

import decimal
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from numpy.testing import assert_allclose
from scipy.integrate import quad
from scipy.optimize import brentq, minimize_scalar

from linecontact.closed_forms import hertz_load, jkr_load, kappa, maugis_parameter, zero_width_load
from linecontact.normal import normal_contact, pull_off

SETTINGS = settings(derandomize=True, max_examples=60, deadline=None)


def log_uniform(lo, hi):
    return st.floats(math.log10(lo), math.log10(hi)).map(lambda e: 10.0**e)


def eq14_literal(R_over_h, sigma0_over_E):
    """Eq. (14) of the paper, term by term, in 40-digit decimal arithmetic.

    F/(Eh) = (8 ln2/pi) (R/h) (s0/E) (s0/E - sqrt((s0/E)^2 + (1/8)(pi/ln2)^2 (h/R)))
    """
    D = decimal.Decimal
    with decimal.localcontext() as ctx:
        ctx.prec = 40
        pi = D(math.pi)
        ln2 = D(2).ln()
        rho = D(R_over_h)
        s = D(sigma0_over_E)
        val = (8 * ln2 / pi) * rho * s * (s - (s * s + D(1) / 8 * (pi / ln2) ** 2 / rho).sqrt())
        return float(val)


# --------------------------------------------------------------------------------------------
# Hertz, Eq. (13)


@pytest.mark.parametrize(
    "E, R, h, a",  # [Pa], [m], [m], [m]
    [(70e9, 50e-9, 0.3e-9, 2e-9), (1e6, 1e-3, 1e-9, 1e-5), (200e9, 1e-6, 0.5e-9, 3e-8)],
)
def test_hertz_load_is_the_integral_of_the_hertz_pressure(E, R, h, a):
    """The Hertz pressure p = (E/(2R)) sqrt(a^2 - x^2) solves the contact condition of Eq. 9
    without adhesion, (1/(pi E)) PV int p(xi)/(xi - x) dxi = -x/(2R) (Cauchy principal value
    by QUADPACK), and the load is its integral (by quadrature, not by pi a^2 E/(4R))."""

    def p(t):  # the pressure at x = a t [Pa]
        return E / (2 * R) * a * math.sqrt(max(1 - t * t, 0.0))

    for t in (-0.7, -0.2, 0.35, 0.9):
        # PV int_{-a}^{a} p(xi)/(xi - x) dxi = PV int_{-1}^{1} p(a t')/(t' - t) dt', x = a t
        pv, _ = quad(p, -1, 1, weight="cauchy", wvar=t, epsabs=0, epsrel=1e-12, limit=200)
        assert pv / (math.pi * E) == pytest.approx(-a * t / (2 * R), rel=1e-10)
    F = a * quad(p, -1, 1, epsabs=0, epsrel=1e-13, limit=200)[0]  # [N/m]
    assert_allclose(hertz_load(a / R, R / h), F / (E * h), rtol=1e-12)


def test_hertz_load_hand_value():
    # a/R = 0.02, R/h = 100: (pi/4) (4e-4) (100) = 0.01 pi
    assert hertz_load(0.02, 100.0) == pytest.approx(0.031415926535897932, rel=1e-15)


@pytest.mark.parametrize("A", [1e-3, 0.01, 0.05, 0.1])
@pytest.mark.parametrize("rho", [10.0, 100.0, 1e4])
def test_hertz_load_is_the_collocation_without_adhesion(A, rho):
    """The second solver: Gauss-Chebyshev collocation of Eq. 9 with sigma0 = 0."""
    col = normal_contact(A, rho, 0.0, method="collocation")
    assert_allclose(hertz_load(A, rho), col.F_over_Eh, rtol=1e-13, err_msg=f"{A=}, {rho=}")


@SETTINGS
@given(A=log_uniform(1e-8, 0.5), rho=log_uniform(1.0, 1e8), k=st.floats(0.5, 2.0))
def test_hertz_load_scales_with_a_squared_and_R_over_h(A, rho, k):
    # F = pi E a^2/(4R): F/(Eh) is quadratic in a/R and linear in R/h
    msg = f"a_over_R={A}, R_over_h={rho}, k={k}"
    assert_allclose(hertz_load(k * A, rho), k * k * hertz_load(A, rho), rtol=1e-14, err_msg=msg)
    assert_allclose(hertz_load(A, k * rho), k * hertz_load(A, rho), rtol=1e-14, err_msg=msg)


# --------------------------------------------------------------------------------------------
# JKR line contact (Chaudhury et al. 1996)


@pytest.mark.parametrize(
    "E, R, h, sigma0",  # [Pa], [m], [m], [Pa]
    [(70e9, 50e-9, 0.3e-9, 2e9), (1e6, 1e-3, 1e-9, 1e5), (200e9, 1e-6, 0.5e-9, 5e9)],
)
def test_jkr_pull_off_is_the_minimum_of_the_jkr_load(E, R, h, sigma0):
    """The minimum of F(a) = pi E a^2/(4R) - sqrt(2 pi E w a), found numerically from
    ``jkr_load``, against the minimum derived by hand: dF/da = pi E a/(2R) -
    sqrt(2 pi E w)/(2 sqrt a) = 0 at a^3 = 2 w R^2/(pi E); there sqrt(2 pi E w a) = pi E a^2/R,
    so F = -(3/4) pi E a^2/R = -(3/4) (4 pi E w^2 R)^(1/3)."""
    w = sigma0 * h  # [J/m^2]
    rho, s = R / h, sigma0 / E
    res = minimize_scalar(
        lambda t: jkr_load(math.exp(t), rho, s),
        bracket=(math.log(1e-6), math.log(1e-3), math.log(0.5)),
        tol=1e-10,
    )
    assert res.fun < jkr_load(1e-3, rho, s)
    a_min = 2 * w * R * R / (math.pi * E)  # a^3 [m^3]
    F_min = -0.75 * (4 * math.pi * E * w * w * R) ** (1 / 3)  # [N/m]
    assert math.exp(res.x) * R == pytest.approx(a_min ** (1 / 3), rel=1e-6)
    assert res.fun * E * h == pytest.approx(F_min, rel=1e-12)


@pytest.mark.parametrize("A", [0.005, 0.01, 0.05])
def test_jkr_is_the_maugis_dugdale_limit_of_a_short_range(A):
    """At fixed work of adhesion w = sigma0 h and contact width, the Maugis-Dugdale load
    (the closed form of linecontact.normal) tends to the JKR load as the range h -> 0; the
    difference falls like h^2 (measured: a factor 100 per decade)."""
    w_over_ER = 1e-5  # w/(E R)
    err = []
    for h_over_R in (1e-6, 1e-7, 1e-8):
        rho, s = 1 / h_over_R, w_over_ER / h_over_R
        md = normal_contact(A, rho, s).F_over_Eh
        err.append(abs(md / jkr_load(A, rho, s) - 1))
    assert err[-1] < 1e-7, err
    assert 50 < err[0] / err[1] < 200 and 50 < err[1] / err[2] < 200, err


def test_jkr_zero_adhesion_is_hertz_and_adhesion_scales_as_sqrt_w():
    assert jkr_load(0.03, 200.0, 0.0) == hertz_load(0.03, 200.0)
    # the adhesive term sqrt(2 pi E w a) is proportional to sqrt(w): four times w, twice it
    A, rho, s = 0.03, 200.0, 0.01
    adh = hertz_load(A, rho) - jkr_load(A, rho, s)
    assert adh > 0
    assert_allclose(hertz_load(A, rho) - jkr_load(A, rho, 4 * s), 2 * adh, rtol=1e-13)
    # and to sqrt(a)
    assert_allclose(hertz_load(4 * A, rho) - jkr_load(4 * A, rho, s), 2 * adh, rtol=1e-13)


# --------------------------------------------------------------------------------------------
# Eq. (14)


@pytest.mark.parametrize(
    "rho, s", [(100.0, 0.01), (200.0, 0.05), (10.0, 1e-4), (1e4, 0.3), (1.0, 1.0), (1e6, 1e-6)]
)
def test_zero_width_load_eq14_literal(rho, s):
    assert_allclose(
        zero_width_load(rho, s),
        eq14_literal(rho, s),
        rtol=1e-14,
        err_msg=f"R_over_h={rho}, sigma0_over_E={s}",
    )


@SETTINGS
@given(rho=log_uniform(1.0, 1e8), s=log_uniform(1e-8, 10.0))
def test_zero_width_load_eq14_literal_property(rho, s):
    assert_allclose(
        zero_width_load(rho, s),
        eq14_literal(rho, s),
        rtol=1e-14,
        err_msg=f"R_over_h={rho}, sigma0_over_E={s}",
    )


@pytest.mark.parametrize(
    "rho, s", [(100.0, 0.01), (200.0, 0.05), (10.0, 1e-4), (1e4, 0.3), (1.0, 1.0), (1e6, 1e-6)]
)
def test_zero_width_load_is_the_touching_non_contact_state(rho, s):
    """Eq. 14 from the non-contact branch at zero central gap (docs/derivations.md Sec. 5):
    the adhesive zone c solves h = c^2/(2R) + 4 ln2 sigma0 c/(pi E), found here by root
    finding, and the load is the adhesive stress over it, F = -2 sigma0 c."""

    def gap_at_c(C):  # (h - g0 - c^2/(2R) - 4 ln2 sigma0 c/(pi E)) / R with g0 = 0, C = c/R
        return 1 / rho - C * C / 2 - 4 * math.log(2) / math.pi * s * C

    C = brentq(gap_at_c, 0.0, math.sqrt(2 / rho), xtol=1e-300, rtol=1e-15)
    assert_allclose(zero_width_load(rho, s), -2 * s * C * rho, rtol=1e-13)


@pytest.mark.parametrize("rho, s", [(100.0, 0.01), (200.0, 0.05), (1e4, 0.3)])
def test_zero_width_load_is_the_collocation_at_vanishing_width(rho, s):
    """The second solver: the collocation of Eqs. 9-12 at a very narrow contact (the load
    approaches Eq. 14 about like (a/R)^2: 6e-9 at a/R = 1e-8 for kappa = 54, 7e-13 at 1e-10)."""
    col = normal_contact(1e-12, rho, s, method="collocation")
    assert_allclose(col.F_over_Eh, zero_width_load(rho, s), rtol=1e-12)


def test_zero_width_load_limits():
    # sigma0 = 0: no force, exactly
    assert zero_width_load(100.0, 0.0) == 0.0
    # it is negative (tensile) for any adhesion
    s = np.geomspace(1e-8, 10, 50)
    F = zero_width_load(100.0, s)
    assert np.all(F < 0)
    # and more tensile for stronger adhesion
    assert np.all(np.diff(F) < 0)
    # small s0/E (rigid limit): F/(Eh) -> -(8 ln2/pi) rho s sqrt(k) = -2 s sqrt(2 rho)
    rho = 100.0
    s_small = 1e-9
    assert_allclose(zero_width_load(rho, s_small), -2 * s_small * np.sqrt(2 * rho), rtol=1e-7)
    # large s0/E: s - sqrt(s^2 + k) ~ -k/(2 s), k = (pi/ln2)^2/(8 rho): F/(Eh) -> -pi/(2 ln2)
    assert_allclose(zero_width_load(rho, 1e6), -np.pi / (2 * np.log(2)), rtol=1e-9)


# --------------------------------------------------------------------------------------------
# groups: kappa and the Maugis parameter lambda


def f1(u):
    return math.sinh(u) * math.cosh(u) - u


def f2(u):
    return u * math.sinh(u) - math.cosh(u) * math.log(math.cosh(u))


@pytest.mark.parametrize(
    "A, rho, s", [(0.02, 100.0, 0.01), (0.05, 200.0, 0.05), (0.01, 1e4, 0.002), (0.1, 10.0, 0.2)]
)
def test_kappa_from_the_separation_condition_of_the_collocation(A, rho, s):
    """The separation condition h = (a^2/(2R)) f1(u) + (4 sigma0 a/(pi E)) f2(u), c = a cosh u
    (Baney & Hui 1997; docs/derivations.md Sec. 3), divided by h is abar^2 f1 + kappa abar f2 = 1
    with abar = (a/R) sqrt(R/(2h)). The state comes from the collocation solver, which solves
    Eqs. 9-12 without kappa; the kappa it implies must be the function's."""
    col = normal_contact(A, rho, s, method="collocation")
    u = math.acosh(col.c_over_R / A)
    abar = A * math.sqrt(rho / 2)
    implied = (1 - abar * abar * f1(u)) / (abar * f2(u))
    assert_allclose(kappa(rho, s), implied, rtol=1e-9, err_msg=f"{A=}, {rho=}, {s=}")


def test_groups_hand_values():
    # kappa = (4/pi) (sigma0/E) sqrt(2R/h): (4/pi)(0.01)(sqrt 200 = 14.14213562373095049)
    assert kappa(100.0, 0.01) == pytest.approx(0.18006326323142121, rel=1e-15)
    # Baney & Hui's lambda = 4 sigma0 (R/(pi^2 E^2 w))^(1/3), w = sigma0 h:
    # 4 ((0.01)^2 (100)/pi^2)^(1/3) = 4 (1.0132118364233778e-3)^(1/3) = 0.40175387674099486
    assert maugis_parameter(100.0, 0.01) == pytest.approx(0.40175387674099486, rel=1e-15)
    # in SI: E = 70 GPa, R = 50 nm, sigma0 = 2 GPa, h = 0.3 nm, so w = 0.6 J/m^2 and
    # R/(pi^2 E^2 w) = 1.7231493816724111e-30 m^3/N^2... lambda = 0.95910089553792656,
    # kappa = (4/pi)(2/70) sqrt(1000/3) = 0.66417335215148254
    E, R, sigma0, h = 70e9, 50e-9, 2e9, 0.3e-9
    assert maugis_parameter(R / h, sigma0 / E) == pytest.approx(0.95910089553792656, rel=1e-14)
    assert kappa(R / h, sigma0 / E) == pytest.approx(0.66417335215148254, rel=1e-14)


@pytest.mark.parametrize("rho1, s1, rho2", [(100.0, 0.05, 800.0), (1e3, 0.01, 10.0)])
def test_the_load_curve_depends_on_the_maugis_parameter_alone(rho1, s1, rho2):
    """Two cylinders with the same Maugis parameter (found by root finding on the function)
    have the same pull-off force over E h and the same width at pull-off over sqrt(h R): the
    exponents of sigma0/E and R/h in the parameter are those of the problem's one group, and
    kappa = lambda^(3/2)/sqrt(2) holds for them too."""
    lam = maugis_parameter(rho1, s1)
    s2 = brentq(lambda s: maugis_parameter(rho2, s) - lam, 1e-6, 10.0, xtol=1e-300, rtol=1e-15)
    assert s2 != pytest.approx(s1, rel=1e-3)  # a different cylinder
    po1, po2 = pull_off(rho1, s1), pull_off(rho2, s2)
    assert_allclose(po2.F_pulloff_over_Eh, po1.F_pulloff_over_Eh, rtol=1e-9)
    assert_allclose(
        po2.a_over_R_at_pulloff * math.sqrt(rho2),
        po1.a_over_R_at_pulloff * math.sqrt(rho1),
        rtol=1e-8,
    )
    assert_allclose(kappa(rho2, s2), kappa(rho1, s1), rtol=1e-13)
    assert_allclose(kappa(rho1, s1), lam**1.5 / math.sqrt(2), rtol=1e-13)


# --------------------------------------------------------------------------------------------
# arrays in, arrays out; scalars in, scalars out


def test_broadcasting_and_scalar_output():
    A = np.array([[0.01], [0.02], [0.05]])
    rho = np.array([10.0, 100.0])
    assert np.shape(hertz_load(A, rho)) == (3, 2)
    assert np.shape(jkr_load(A, rho, 0.01)) == (3, 2)
    assert np.shape(zero_width_load(rho, [[0.01], [0.1]])) == (2, 2)
    assert np.shape(kappa(rho, 0.1)) == (2,)
    assert np.shape(maugis_parameter([1.0], 0.1)) == (1,)
    for val in (
        hertz_load(0.01, 100.0),
        jkr_load(0.01, 100.0, 0.01),
        zero_width_load(100.0, 0.01),
        kappa(100.0, 0.01),
        maugis_parameter(100.0, 0.01),
    ):
        assert isinstance(val, float) and np.ndim(val) == 0
    # an element of the array call is the scalar call, to rounding (not bit for bit: NumPy's
    # SIMD loops on arrays may round differently from its scalar code)
    assert_allclose(hertz_load(A, rho)[2, 1], hertz_load(0.05, 100.0), rtol=1e-15)


# --------------------------------------------------------------------------------------------
# bad input: ValueError naming the parameter (the message is part of the API)

BAD_REFERENCE = [
    (hertz_load, (0.0, 100.0), r"a_over_R must be in \[1e-150, 10\], got 0\.0"),
    (hertz_load, (-0.1, 100.0), r"a_over_R must be in \[1e-150, 10\], got -0\.1"),
    (hertz_load, (np.nan, 100.0), r"a_over_R must be a finite number in \[1e-150, 10\], got nan"),
    (hertz_load, (np.inf, 100.0), r"a_over_R must be a finite number in \[1e-150, 10\], got inf"),
    (hertz_load, (0.1, 0.0), r"R_over_h must be in \[0.001, 1e\+12\], got 0\.0"),
    (hertz_load, (0.1, [100.0, -1.0]), r"R_over_h must be in \[0.001, 1e\+12\], got -1\.0"),
    (hertz_load, ("abc", 100.0), r"a_over_R must be a real number or an array of them"),
    (hertz_load, ([], 100.0), r"a_over_R must not be empty"),
    (jkr_load, (0.1, 100.0, -0.01), r"sigma0_over_E must be in \[0, 1e\+06\], got -0\.01"),
    (jkr_load, (0.1, 100.0, np.inf), r"sigma0_over_E must be a finite number in \[0, 1e\+06\]"),
    (
        jkr_load,
        (0.1, np.nan, 0.01),
        r"R_over_h must be a finite number in \[0.001, 1e\+12\], got nan",
    ),
    (jkr_load, (-1.0, 100.0, 0.01), r"a_over_R must be in \[1e-150, 10\], got -1\.0"),
    (zero_width_load, (0.0, 0.01), r"R_over_h must be in \[0.001, 1e\+12\], got 0\.0"),
    (zero_width_load, (-np.inf, 0.01), r"R_over_h must be a finite number in \[0.001, 1e\+12\]"),
    (zero_width_load, (100.0, -1e-9), r"sigma0_over_E must be in \[0, 1e\+06\], got -1e-09"),
    (zero_width_load, (100.0, np.nan), r"sigma0_over_E must be a finite number in \[0, 1e\+06\]"),
    (kappa, (-5.0, 0.1), r"R_over_h must be in \[0.001, 1e\+12\], got -5\.0"),
    (kappa, (100.0, -0.1), r"sigma0_over_E must be in \[0, 1e\+06\], got -0\.1"),
    (maugis_parameter, (0.0, 0.1), r"R_over_h must be in \[0.001, 1e\+12\], got 0\.0"),
    (maugis_parameter, (100.0, np.inf), r"sigma0_over_E must be a finite number in \[0, 1e\+06\]"),
]


@pytest.mark.parametrize(
    "func, args, message", BAD_REFERENCE, ids=[f"{f.__name__}-{m}" for f, _, m in BAD_REFERENCE]
)
def test_bad_input(func, args, message):
    with pytest.raises(ValueError, match=message):
        func(*args)
