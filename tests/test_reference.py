"""Tests of the closed forms in `linecontact.reference` (Hertz, JKR, Eq. 14, the groups).

Policy (STYLE habit 8): every closed form against its formula written out independently,
dimensional where the literature states it dimensionally, Eq. (14) literally as printed in the
paper (evaluated in 40-digit decimal arithmetic so that the reference is not limited by the
cancellation in ``s - sqrt(s^2 + k)``).
"""

from __future__ import annotations

import decimal
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from numpy.testing import assert_allclose

from linecontact.reference import hertz_load, jkr_load, kappa, maugis_parameter, zero_width_load

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


@SETTINGS
@given(A=log_uniform(1e-8, 1.0), rho=log_uniform(1.0, 1e8))
def test_hertz_load_formula(A, rho):
    assert_allclose(
        hertz_load(A, rho),
        np.pi / 4 * A * A * rho,
        rtol=1e-15,
        err_msg=f"a_over_R={A}, R_over_h={rho}",
    )


def test_hertz_load_dimensional():
    """F = pi a^2 E / (4 R) (Eq. 13) in SI units, then divided by E h."""
    E, R, h, a = 70e9, 50e-9, 0.3e-9, 2e-9  # [Pa], [m], [m], [m]
    F = math.pi * a * a * E / (4 * R)  # [N/m]
    assert_allclose(hertz_load(a / R, R / h), F / (E * h), rtol=1e-14)


# --------------------------------------------------------------------------------------------
# JKR line contact (Chaudhury et al. 1996)


@pytest.mark.parametrize(
    "E, R, h, sigma0, a",
    [
        (70e9, 50e-9, 0.3e-9, 2e9, 2e-9),
        (1e6, 1e-3, 1e-9, 1e5, 1e-5),
        (200e9, 1e-6, 0.5e-9, 5e9, 3e-8),
    ],
)
def test_jkr_load_dimensional(E, R, h, sigma0, a):
    """F = pi E a^2/(4R) - sqrt(2 pi E w a), w = sigma0 h, in SI units."""
    w = sigma0 * h  # [J/m^2]
    F = math.pi * E * a * a / (4 * R) - math.sqrt(2 * math.pi * E * w * a)  # [N/m]
    assert_allclose(
        jkr_load(a / R, R / h, sigma0 / E),
        F / (E * h),
        rtol=1e-13,
        err_msg=f"E={E}, R={R}, h={h}, sigma0={sigma0}, a={a}",
    )


@SETTINGS
@given(A=log_uniform(1e-6, 1.0), rho=log_uniform(1.0, 1e6), s=log_uniform(1e-6, 1.0))
def test_jkr_load_formula(A, rho, s):
    expected = np.pi / 4 * A * A * rho - np.sqrt(2 * np.pi * s * rho * A)
    scale = np.pi / 4 * A * A * rho + np.sqrt(2 * np.pi * s * rho * A)
    assert abs(jkr_load(A, rho, s) - expected) <= 1e-15 * scale, (
        f"a_over_R={A}, R_over_h={rho}, sigma0_over_E={s}"
    )


def test_jkr_minimum_and_zero_adhesion():
    # no adhesion: Hertz
    assert jkr_load(0.03, 200.0, 0.0) == hertz_load(0.03, 200.0)
    # the JKR load is minimal at a^3 = 2 w R^2/(pi E): in units A^3 = 2 s / (pi rho)
    rho, s = 300.0, 0.05
    A_star = (2 * s / (np.pi * rho)) ** (1 / 3)
    A = A_star * np.array([1 - 1e-4, 1.0, 1 + 1e-4])
    F = jkr_load(A, rho, s)
    assert F[1] < F[0] and F[1] < F[2]
    # the JKR line-contact pull-off force: F = -(3/4) (4 pi E w^2 R)^(1/3), here over E h
    assert_allclose(F[1], -0.75 * (4 * np.pi * s * s * rho) ** (1 / 3), rtol=1e-14)


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


@SETTINGS
@given(rho=log_uniform(1.0, 1e8), s=log_uniform(1e-8, 10.0))
def test_kappa_and_maugis_parameter_formulas(rho, s):
    msg = f"R_over_h={rho}, sigma0_over_E={s}"
    assert_allclose(kappa(rho, s), (4 / np.pi) * s * np.sqrt(2 * rho), rtol=1e-15, err_msg=msg)
    # Baney & Hui: lambda = 4 sigma0 (R/(pi^2 E^2 w))^(1/3), w = sigma0 h
    assert_allclose(
        maugis_parameter(rho, s), 4 * s * (rho / (np.pi**2 * s)) ** (1 / 3), rtol=1e-14, err_msg=msg
    )
    # the relation between the two groups implied by these two definitions (and documented
    # in kappa's docstring)
    assert_allclose(
        kappa(rho, s), maugis_parameter(rho, s) ** 1.5 / np.sqrt(2), rtol=1e-13, err_msg=msg
    )


def test_maugis_parameter_dimensional():
    E, R, sigma0, h = 70e9, 50e-9, 2e9, 0.3e-9
    w = sigma0 * h
    lam = 4 * sigma0 * (R / (math.pi**2 * E**2 * w)) ** (1 / 3)
    assert_allclose(maugis_parameter(R / h, sigma0 / E), lam, rtol=1e-14)
    kap = (4 / math.pi) * (sigma0 / E) * math.sqrt(2 * R / h)
    assert_allclose(kappa(R / h, sigma0 / E), kap, rtol=1e-15)


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
    assert_allclose(hertz_load(A, rho)[2, 1], hertz_load(0.05, 100.0), rtol=0)


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
