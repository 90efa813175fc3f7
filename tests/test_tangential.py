"""Tangential loading: initiation of sliding and steady rolling (constant tau0 and Coulomb).

Strict numerics: the closed forms are checked against the elasticity equations by
independent adaptive quadrature (not by the collocation they are compared with later), the
collocation solutions against the closed forms, the limits of every problem, the residuals,
the convergence in n, and the error messages word for word.
"""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from numpy.testing import assert_allclose
from scipy.integrate import quad

from linecontact import (
    ConvergenceError,
    Cylinder,
    NoEquilibriumError,
    contact_for_load,
    sliding_initiation,
    sliding_initiation_coulomb,
    steady_rolling,
    steady_rolling_coulomb,
)
from linecontact import tangential as tg

# --------------------------------------------------------------------------------------------
# independent checks of the closed forms: Eq 15 by adaptive quadrature
# (E = 1, tau0 = 1, a = 1; the slip gradient is d(u1 - u2)/dx = (2/(pi E)) int q/(x - s) ds
# with q the traction on the substrate)


def slip_gradient(q, breaks, x):
    """(2/pi) PV int q(s)/(x - s) ds over the pieces between ``breaks``."""
    total = 0.0
    for lo, hi in zip(breaks[:-1], breaks[1:], strict=True):
        if lo < x < hi:
            total -= quad(q, lo, hi, weight="cauchy", wvar=x, limit=400)[0]
        else:
            total += quad(lambda s: q(s) / (x - s), lo, hi, limit=400)[0]
    return 2 / np.pi * total


@pytest.mark.parametrize("d", [0.3, 0.8])
def test_initiation_closed_form_satisfies_the_stick_condition(d):
    r = sliding_initiation(1.0, d)

    def q(s):
        return float(r.traction(np.array([s]))[0])

    breaks = [-1.0, -d, d, 1.0]
    for x in (0.0, 0.4 * d, -0.9 * d):  # stick zone: zero slip gradient (Eq 16)
        assert abs(slip_gradient(q, breaks, x)) < 1e-9, x
    assert quad(q, -1, 1, points=[-d, d])[0] == pytest.approx(r.T_over_Ea, rel=1e-10)
    for x in (d + 0.3 * (1 - d), 0.99):  # slip zones: the gradient has the sign of the slip
        grad = slip_gradient(q, breaks, x)
        k = np.sqrt(1 - d * d)
        assert grad == pytest.approx(
            4 / np.pi * np.log((k + np.sqrt(x * x - d * d)) / np.sqrt(1 - x * x)), rel=1e-9
        )
        assert grad > 0 and slip_gradient(q, breaks, -x) == pytest.approx(-grad, rel=1e-9)
    # the slip is the integral of the (checked) gradient from the end of the stick zone
    for x in (0.5 * (1 + d), 1.0):
        s = quad(
            lambda y: 4 / np.pi * np.log((k + np.sqrt(y * y - d * d)) / np.sqrt(1 - y * y)),
            d,
            x,
            limit=200,
        )[0]
        assert float(r.slip(np.array([x]))[0]) == pytest.approx(s, rel=1e-10)


@pytest.mark.parametrize("d", [-0.7, 0.0, 0.6])
def test_rolling_closed_form_satisfies_stick_and_slip_conditions(d):
    r = steady_rolling(1.0, d)

    def q(s):  # on the substrate: minus the traction on the cylinder
        return -float(r.traction(np.array([s]))[0])

    breaks = [-1.0, d, 1.0]
    xi = r.creep_over_V
    for x in np.linspace(d, 1, 6)[1:-1]:  # stick: the slip gradient equals the creep (Eq 24)
        assert slip_gradient(q, breaks, x) == pytest.approx(xi, abs=1e-9), x
    assert -quad(q, -1, 1, points=[d])[0] == pytest.approx(r.T_over_Ea, rel=1e-10)
    # trailing slip zone: slip velocity s'/V = creep - gradient < 0, the direction of the
    # traction on the substrate (friction opposes the cylinder's slip): admissible
    for x in np.linspace(-1, d, 6)[1:-1]:
        assert xi - slip_gradient(q, breaks, x) < 0, x
    x = np.linspace(-1, 1, 201)
    tr = r.traction(x)
    assert np.all(tr <= 1 + 1e-15) and np.all(tr >= 0)


def test_coulomb_closed_forms_satisfy_their_stick_conditions():
    # Cattaneo-Mindlin, mu p0 = 1
    d = 0.6
    r = sliding_initiation_coulomb(1.0, 2.0, d)  # a/R = 2: p0/E = 1

    def q(s):
        return float(r.traction(np.array([s]))[0])

    for x in (0.0, 0.5 * d):
        assert abs(slip_gradient(q, [-1, -d, d, 1], x)) < 1e-9
    # Carter
    c = steady_rolling_coulomb(1.0, 2.0, 0.2)

    def qc(s):
        return -float(c.traction(np.array([s]))[0])

    for x in (0.4, 0.8):
        assert slip_gradient(qc, [-1, 0.2, 1], x) == pytest.approx(c.creep_over_V, abs=1e-9)
    for x in (-0.5, 0.1):
        assert c.creep_over_V - slip_gradient(qc, [-1, 0.2, 1], x) < 0


# --------------------------------------------------------------------------------------------
# closed forms and limits


def test_initiation_closed_form_values():
    d = np.array([0.0, 0.6, 0.8])
    r = sliding_initiation(0.01, d, on_failure="report")  # d = 0: full slip, reported
    assert_allclose(r.T_over_Ea, 2 * 0.01 * np.sqrt(1 - d * d), rtol=1e-15)
    assert list(r.state) == ["sliding", "stick-slip", "stick-slip"]
    # traction: tau0 in the slip zones, (2 tau0/pi) arctan sqrt((a^2-d^2)/(d^2-x^2)) inside
    x = np.array([-0.7, 0.0, 0.5, 0.7])
    q = sliding_initiation(0.01, 0.6).traction(x)
    assert_allclose(
        q,
        [
            0.01,
            0.01 * 2 / np.pi * np.arctan(0.8 / 0.6),
            0.01 * 2 / np.pi * np.arctan(0.8 / np.sqrt(0.36 - 0.25)),
            0.01,
        ],
    )


def test_initiation_limits():
    # full stick: T -> 0 like sqrt(1 - d/a); T = 0 is "stick" with d = a
    r = sliding_initiation(0.01, 1 - 1e-12)
    assert r.T_over_Ea == pytest.approx(0.02 * np.sqrt(2e-12), rel=1e-6)
    z = sliding_initiation(0.01, T_over_Ea=0.0)
    assert (z.state, z.d_over_a, z.T_over_Ea) == ("stick", 1.0, 0.0)
    assert np.all(z.traction(np.linspace(-1, 1, 5)) == 0)
    # full slip: d = 0 at T = 2 a tau0, reported as sliding at and above it
    f = sliding_initiation(0.01, T_over_Ea=[0.02, 0.05], on_failure="report")
    assert list(f.state) == ["sliding", "sliding"]
    assert f.d_over_a[0] == 0 and np.isnan(f.d_over_a[1])
    assert_allclose(f.T_over_Ea, [0.02, 0.05])
    assert_allclose(f.traction(np.array([-0.5, 0.9, 1.5])), [[0.01, 0.01, 0]] * 2)
    assert np.all(np.isnan(f.slip(np.array([0.5]))))
    # the slip at the edge tends to (4 ln 2/pi) tau0 a/E as d -> 0
    s = sliding_initiation(0.01, [1e-9, 0.5]).slip(np.array([1.0]))
    assert s[0, 0] == pytest.approx(4 * np.log(2) / np.pi * 0.01, rel=1e-8)
    d = 0.5  # s(a) = (4/pi)(tau0/E)(k arccosh(a/d) + ln(d/a))
    k = np.sqrt(1 - d * d)
    assert s[1, 0] == pytest.approx(
        4 / np.pi * 0.01 * (k * np.arccosh(1 / d) + np.log(d)), rel=1e-13
    )


def test_initiation_slip_profile_is_monotone_and_symmetric():
    r = sliding_initiation(0.02, 0.4)
    x = np.linspace(-1, 1, 401)
    s = r.slip(x)
    assert np.all(s[np.abs(x) <= 0.4] == 0)
    right = s[x > 0.4]
    assert np.all(np.diff(right) > 0)
    assert_allclose(s, s[::-1], rtol=1e-12, atol=1e-17)
    assert np.all(np.isnan(r.slip(np.array([-1.01, 1.2]))))


def test_rolling_closed_form_values():
    d = np.array([-0.5, 0.0, 0.5])
    r = steady_rolling(0.01, d)
    assert_allclose(r.T_over_Ea, 0.01 * np.sqrt(2 * (1 + d)), rtol=1e-15)
    # creep = -(4/pi)(tau0/E) artanh(T/(2 a tau0)) = -(2/pi)(tau0/E) arccosh((3a+d)/(a-d))
    assert_allclose(
        r.creep_over_V, -4 / np.pi * 0.01 * np.arctanh(np.sqrt((1 + d) / 2)), rtol=1e-14
    )
    assert_allclose(r.creep_over_V, -2 / np.pi * 0.01 * np.arccosh((3 + d) / (1 - d)), rtol=1e-14)
    q = steady_rolling(0.01, 0.5).traction(np.array([-1.0, 0.0, 0.5, 0.75, 1.0, 1.2]))
    beta = 0.75
    assert_allclose(
        q, 0.01 * np.array([1, 1, 1, 2 / np.pi * np.arctan(np.sqrt(beta)), 0, 0]), atol=1e-17
    )


def test_rolling_limits():
    # full stick (d -> -a): T -> 0 and creep -> 0, both like sqrt(1 + d/a)
    eps = 1e-10
    r = steady_rolling(0.01, -1 + eps)
    assert r.T_over_Ea == pytest.approx(0.01 * np.sqrt(2 * eps), rel=1e-6)
    assert r.creep_over_V == pytest.approx(-4 / np.pi * 0.01 * np.sqrt(eps / 2), rel=1e-6)
    z = steady_rolling(0.01, T_over_Ea=0.0)
    assert (z.state, z.d_over_a, z.T_over_Ea, z.creep_over_V) == ("stick", -1.0, 0.0, 0.0)
    # full slip (d -> a): T -> 2 a tau0, the creep diverges like -(2/pi)(tau0/E) ln(8a/(a-d))
    d = 1 - eps
    eps = 1 - d  # exact: the distance that was actually represented
    r = steady_rolling(0.01, d)
    assert r.T_over_Ea == pytest.approx(0.02, rel=1e-9)
    assert r.creep_over_V == pytest.approx(-2 / np.pi * 0.01 * np.log(8 / eps), rel=1e-9)
    f = steady_rolling(0.01, T_over_Ea=[0.02, 0.03], on_failure="report")
    assert list(f.state) == ["sliding", "sliding"] and np.all(np.isnan(f.creep_over_V))
    assert_allclose(f.traction(np.array([0.0, 0.99])), [[0.01, 0.01]] * 2)


def test_creep_grows_with_the_load_and_the_friction_stress():
    d = np.linspace(-0.99, 0.99, 50)
    r = steady_rolling(0.01, d)
    assert np.all(np.diff(r.T_over_Ea) > 0) and np.all(np.diff(r.creep_over_V) < 0)
    assert_allclose(steady_rolling(0.03, d).creep_over_V, 3 * r.creep_over_V, rtol=1e-14)


def test_cattaneo_mindlin_closed_form():
    d = np.array([0.0, 0.3, 0.9])
    r = sliding_initiation_coulomb(0.3, 0.02, d, on_failure="report")
    assert_allclose(r.T_over_muF, 1 - d * d, rtol=1e-15)
    # Hertz F = pi E a^2/(4R): T/(E a) = T/(mu F) mu (pi/4) a/R
    assert_allclose(r.T_over_Ea, r.T_over_muF * 0.3 * np.pi / 4 * 0.02, rtol=1e-15)
    x = np.linspace(-1, 1, 41)
    p0 = 0.01  # E a/(2R) over E
    q = sliding_initiation_coulomb(0.3, 0.02, 0.3).traction(x)
    expect = 0.3 * p0 * (np.sqrt(1 - x * x) - 0.3 * np.sqrt(np.clip(1 - (x / 0.3) ** 2, 0, 1)))
    assert_allclose(q, expect, atol=1e-18)
    # limits: T -> 0 at full stick, T = mu F at d = 0 (sliding)
    assert sliding_initiation_coulomb(0.3, 0.02, 1 - 1e-12).T_over_muF == pytest.approx(
        2e-12, rel=1e-4
    )
    assert sliding_initiation_coulomb(0.3, 0.02, 0.0, on_failure="report").state == "sliding"
    inv = sliding_initiation_coulomb(
        0.3, 0.02, T_over_muF=[0.0, 0.75, 1.0, 2.0], on_failure="report"
    )
    assert_allclose(inv.d_over_a, [1.0, 0.5, 0.0, np.nan])
    assert list(inv.state) == ["stick", "stick-slip", "sliding", "sliding"]


def test_carter_closed_form():
    d = np.array([-0.6, 0.0, 0.6])
    r = steady_rolling_coulomb(0.2, 0.01, d)
    a1 = (1 - d) / 2  # a'/a
    assert_allclose(r.T_over_muF, 1 - a1**2, rtol=1e-15)
    # Carter: creep = -(mu a/R)(1 - a'/a) = -(mu a/R)(1 - sqrt(1 - T/(mu F)))
    assert_allclose(r.creep_over_V, -0.2 * 0.01 * (1 - a1), rtol=1e-15)
    assert_allclose(r.creep_over_V, -0.2 * 0.01 * (1 - np.sqrt(1 - r.T_over_muF)), rtol=1e-14)
    x = np.linspace(-1, 1, 81)
    q = steady_rolling_coulomb(0.2, 0.01, 0.2).traction(x)
    p0, a1, x0 = 0.005, 0.4, 0.6
    expect = 0.2 * p0 * (np.sqrt(1 - x * x) - a1 * np.sqrt(np.clip(1 - ((x - x0) / a1) ** 2, 0, 1)))
    assert_allclose(q, expect, atol=1e-18)
    # limits: full stick (d -> -a) T, creep -> 0; full slip (d -> a) T -> mu F, creep -> -mu a/R
    s = steady_rolling_coulomb(0.2, 0.01, [-1 + 1e-12, 1 - 1e-12])
    assert_allclose(s.T_over_muF, [1e-12, 1], atol=1e-11)
    assert_allclose(s.creep_over_V, [0, -0.2 * 0.01], atol=1e-14)


# --------------------------------------------------------------------------------------------
# collocation against the closed forms, residuals, convergence


@pytest.mark.parametrize("d", [0.05, 0.3, 0.7, 0.95, 0.995])
def test_initiation_collocation_matches_closed_form(d):
    c = sliding_initiation(0.01, d, method="collocation")
    f = sliding_initiation(0.01, d)
    msg = f"tau0_over_E=0.01, d_over_a={d}, n={c.n_collocation}"
    assert c.converged and c.n_collocation >= 16, msg
    assert_allclose(c.T_over_Ea, f.T_over_Ea, rtol=1e-13, err_msg=msg)
    assert c.residual_stick < 1e-12 and c.residual_consistency < 1e-14, msg
    x = np.concatenate([np.linspace(-1, 1, 201), [-d * 0.999, d * 0.999]])
    assert_allclose(c.traction(x), f.traction(x), atol=1e-12 * 0.01, err_msg=msg)
    assert_allclose(c.slip(x), f.slip(x), atol=1e-12 * 0.01, err_msg=msg)


@pytest.mark.parametrize("d", [-0.995, -0.9, -0.3, 0.0, 0.5, 0.9, 0.999])
def test_rolling_collocation_matches_closed_form(d):
    c = steady_rolling(0.02, d, method="collocation")
    f = steady_rolling(0.02, d)
    msg = f"tau0_over_E=0.02, d_over_a={d}, n={c.n_collocation}"
    assert c.converged, msg
    assert_allclose(c.T_over_Ea, f.T_over_Ea, rtol=1e-13, err_msg=msg)
    assert_allclose(c.creep_over_V, f.creep_over_V, rtol=1e-12, err_msg=msg)
    # the stick condition (slip gradient = creep) holds off the collocation points, and the
    # extra (consistency) equation that fixed the creep is satisfied
    assert c.residual_stick < 1e-12 and c.residual_consistency < 1e-13, msg
    x = np.linspace(-1, 1, 201)
    assert_allclose(c.traction(x), f.traction(x), atol=1e-12 * 0.02, err_msg=msg)


@pytest.mark.parametrize("fn", [sliding_initiation_coulomb, steady_rolling_coulomb])
def test_coulomb_collocation_matches_closed_form(fn):
    d = (
        np.array([0.1, 0.5, 0.9])
        if fn is sliding_initiation_coulomb
        else np.array([-0.9, 0.0, 0.9])
    )
    c = fn(0.25, 0.01, d, method="collocation")
    f = fn(0.25, 0.01, d)
    assert np.all(c.converged) and np.all(c.n_collocation == tg.N_COULOMB)
    assert_allclose(c.T_over_muF, f.T_over_muF, rtol=1e-14)
    if fn is steady_rolling_coulomb:
        assert_allclose(c.creep_over_V, f.creep_over_V, rtol=1e-13)
    assert np.all(c.residual_stick < 1e-13)
    x = np.linspace(-1, 1, 101)
    assert_allclose(c.traction(x), f.traction(x), atol=1e-16)


def test_given_load_force_balance_and_round_trip():
    T = np.array([0.001, 0.01, 0.019])
    for fn in (sliding_initiation, steady_rolling):
        c = fn(0.01, T_over_Ea=T, method="collocation")
        f = fn(0.01, T_over_Ea=T)
        assert_allclose(c.T_over_Ea, T)  # reported as given; d solved from Eq 17 / 29
        assert np.all(c.residual_force < 1e-13), fn.__name__
        assert_allclose(c.d_over_a, f.d_over_a, rtol=1e-12, atol=1e-13)
        back = fn(0.01, f.d_over_a)  # round trip d -> T
        assert_allclose(back.T_over_Ea, T, rtol=1e-13)
    for fn in (sliding_initiation_coulomb, steady_rolling_coulomb):
        c = fn(0.3, 0.01, T_over_muF=[0.2, 0.9], method="collocation")
        assert np.all(c.residual_force < 1e-13)
        assert_allclose(fn(0.3, 0.01, c.d_over_a).T_over_muF, [0.2, 0.9], rtol=1e-13)


def test_initiation_convergence_with_n():
    d = 0.95
    exact = sliding_initiation(1.0, d).T_over_Ea
    errs = [
        abs(
            sliding_initiation(1.0, d, method="collocation", n=n, on_failure="report").T_over_Ea
            - exact
        )
        for n in (4, 8, 16, 32)
    ]
    # geometric: error ~ exp(-2 n arccosh(a/d)), arccosh(1/0.95) = 0.32
    assert errs[0] > errs[1] > errs[2] > 1e3 * errs[3], errs
    # at least the rate of the log source's Chebyshev coefficients, exp(-2 n arccosh(a/d))
    v = np.arccosh(1 / d)
    assert errs[0] / errs[1] > 0.5 * np.exp(2 * 4 * v) and errs[1] / errs[2] > 0.5 * np.exp(
        2 * 8 * v
    ), errs


def test_rolling_convergence_with_n_and_the_papers_linear_split():
    d = -0.9
    exact = steady_rolling(1.0, d).creep_over_V
    errs = [
        abs(
            steady_rolling(1.0, d, method="collocation", n=n, on_failure="report").creep_over_V
            - exact
        )
        for n in (4, 8, 16, 32)
    ]
    assert errs[0] > errs[1] > errs[2] > errs[3] and errs[3] < 1e-12, errs
    # the paper's Eq 25 split (linear, signs as derived in docs/tangential.md) converges to
    # the same creep, but only algebraically (~n^-3): the end-point terms (x-d) ln(x-d) of
    # Eq 27 are not smooth
    lin = [
        abs(-2 * tg.rolling._roll_solve(np.array([d]), n, "linear").extra[0] - exact)
        for n in (64, 256, 1024)
    ]
    assert lin[0] > lin[1] > lin[2] and lin[2] < 1e-8, lin
    assert 20 < lin[0] / lin[1] < 200 and 20 < lin[1] / lin[2] < 200, lin


def test_adaptive_size_follows_the_distance_to_the_limit():
    n = sliding_initiation(0.01, [0.1, 0.9, 0.99, 0.999], method="collocation").n_collocation
    assert np.all(np.diff(n) > 0) and n[0] == 16
    m = steady_rolling(0.01, [0.9, 0.0, -0.9, -0.99], method="collocation").n_collocation
    assert np.all(np.diff(m) >= 0) and m[0] == 16 and m[-1] >= 8 * m[1]


def test_convergence_failure_is_named():
    with pytest.raises(
        ConvergenceError,
        match=r"sliding_initiation \(collocation\) did not "
        r"converge at tau0_over_E=0\.01, "
        r"d_over_a=0\.9999999",
    ):
        sliding_initiation(0.01, 0.9999999, method="collocation")
    r = steady_rolling(0.01, [-0.9999999, 0.0], method="collocation", on_failure="report")
    assert list(r.converged) == [False, True]
    assert r.n_collocation[0] == tg.SIZES[-1]


def test_on_failure_raise_is_the_default_beyond_full_slip():
    with pytest.raises(NoEquilibriumError, match=r"T_over_Ea=0\.03 is at or above"):
        sliding_initiation(0.01, T_over_Ea=[0.01, 0.03])
    with pytest.raises(NoEquilibriumError, match=r"T_over_muF=1\.0 is at or above"):
        steady_rolling_coulomb(0.3, 0.01, T_over_muF=[0.5, 1.0])
    with pytest.raises(NoEquilibriumError, match=r"d_over_a=0\.0 is full slip"):
        sliding_initiation(0.01, [0.5, 0.0])
    r = sliding_initiation(0.01, T_over_Ea=[0.01, 0.03], on_failure="report")
    assert list(r.state) == ["stick-slip", "sliding"]


def test_on_failure_raise():
    with pytest.raises(
        NoEquilibriumError,
        match=r"steady_rolling: T_over_Ea=0\.03 is at or "
        r"above the full-slip load 0\.02",
    ):
        steady_rolling(0.01, T_over_Ea=[0.01, 0.03], on_failure="raise")
    with pytest.raises(NoEquilibriumError, match=r"T_over_muF=1\.0 is at or above"):
        sliding_initiation_coulomb(0.3, 0.01, T_over_muF=1.0, on_failure="raise")
    assert sliding_initiation(0.01, T_over_Ea=0.01, on_failure="raise").state == "stick-slip"


# --------------------------------------------------------------------------------------------
# vectorisation


def test_scalars_in_scalars_out_and_broadcasting():
    r = steady_rolling(0.01, 0.2, method="collocation")
    for name in (
        "d_over_a",
        "T_over_Ea",
        "creep_over_V",
        "residual_stick",
        "converged",
        "state",
        "n_collocation",
    ):
        assert np.ndim(getattr(r, name)) == 0 and not isinstance(getattr(r, name), np.ndarray)
    a = steady_rolling([[0.01], [0.02]], [-0.5, 0.0, 0.5])
    assert a.T_over_Ea.shape == a.creep_over_V.shape == a.state.shape == (2, 3)
    assert a.traction(np.linspace(-1, 1, 7)).shape == (2, 3, 7)
    assert r.traction(np.linspace(-1, 1, 7)).shape == (7,)
    s = sliding_initiation(0.01, [0.2, 0.4], method="collocation")
    assert s.slip(np.linspace(-1, 1, 5)).shape == (2, 5)
    recs = a.to_records()
    assert len(recs) == 6 and recs[0]["state"] == "stick-slip"


# --------------------------------------------------------------------------------------------
# hypothesis sweeps: derandomized (the examples follow from the test alone, the same on every
# machine, and no example database is replayed), bounded, no deadline

tau0s = st.floats(1e-4, 0.1)


@settings(derandomize=True, max_examples=40, deadline=None)
@given(tau0s, st.floats(0.0, 0.98))
def test_sweep_initiation(t0, d):
    # d = 0 is full slip: reported
    c = sliding_initiation(t0, d, method="collocation", on_failure="report")
    f = sliding_initiation(t0, d, on_failure="report")
    assert c.T_over_Ea == pytest.approx(f.T_over_Ea, rel=1e-12)
    # round trip through the load, and the bound |q| <= tau0
    back = sliding_initiation(t0, T_over_Ea=f.T_over_Ea, on_failure="report")
    if d > 0:
        assert back.d_over_a == pytest.approx(d, abs=1e-9)
    q = f.traction(np.linspace(-1, 1, 51))
    assert np.all(q <= t0 * (1 + 1e-14)) and np.all(q >= 0)


@settings(derandomize=True, max_examples=40, deadline=None)
@given(tau0s, st.floats(-0.98, 0.98))
def test_sweep_rolling(t0, d):
    c = steady_rolling(t0, d, method="collocation")
    f = steady_rolling(t0, d)
    assert c.T_over_Ea == pytest.approx(f.T_over_Ea, rel=1e-12)
    assert c.creep_over_V == pytest.approx(f.creep_over_V, rel=1e-11)
    assert f.creep_over_V < 0 < f.T_over_Ea < 2 * t0
    back = steady_rolling(t0, T_over_Ea=f.T_over_Ea)
    assert back.d_over_a == pytest.approx(d, abs=1e-12)
    assert back.creep_over_V == pytest.approx(f.creep_over_V, rel=1e-10)


@settings(derandomize=True, max_examples=30, deadline=None)
@given(st.floats(0.01, 1.0), st.floats(1e-4, 0.1), st.floats(-0.99, 0.99))
def test_sweep_coulomb(mu, A, d):
    r = steady_rolling_coulomb(mu, A, d, method="collocation")
    assert r.T_over_muF == pytest.approx(1 - ((1 - d) / 2) ** 2, rel=1e-13)
    assert r.creep_over_V == pytest.approx(-mu * A * (1 + d) / 2, rel=1e-12)
    if d >= 0:
        s = sliding_initiation_coulomb(mu, A, d, method="collocation", on_failure="report")
        assert s.T_over_muF == pytest.approx(1 - d * d, rel=1e-12, abs=1e-15)


# --------------------------------------------------------------------------------------------
# SI layer


def test_si_layer_matches_nondimensional():
    cyl = Cylinder.from_modulus(50e-9, 100e9, cohesive_stress=1e9, adhesion_range=0.5e-9)
    F = np.array([0.5, 2.0])
    r = cyl.steady_rolling(F, friction_stress=2e8, tangential_load=0.5)
    a = contact_for_load(F / (100e9 * 0.5e-9), 100.0, 0.01).a_over_R * 50e-9
    assert_allclose(r.contact_half_width, a, rtol=1e-14)
    nd = steady_rolling(2e8 / 100e9, T_over_Ea=0.5 / (100e9 * a))
    assert_allclose(r.stick_zone_end, nd.d_over_a * a, rtol=1e-14)
    assert_allclose(r.creep_ratio, nd.creep_over_V, rtol=1e-14)
    assert_allclose(r.full_slip_load, 2 * a * 2e8, rtol=1e-14)
    assert_allclose(r.tangential_load, 0.5, rtol=1e-14)
    assert r.problem == "steady rolling" and r.friction == "constant"
    s = cyl.sliding_initiation(1.0, friction_stress=2e8, d_over_a=[0.0, 0.5], on_failure="report")
    assert list(s.state) == ["sliding", "stick-slip"] and s.creep_ratio is None


def test_si_layer_coulomb_uses_hertz():
    cyl = Cylinder.from_modulus(1e-3, 100e9, adhesion_range=1e-9)  # no adhesion
    F = 1e4
    r = cyl.sliding_initiation(F, friction_coefficient=0.3, tangential_load=1500.0)
    a = np.sqrt(4 * F * 1e-3 / (np.pi * 100e9))
    assert r.contact_half_width == pytest.approx(a, rel=1e-12)
    assert r.full_slip_load == pytest.approx(0.3 * F)
    assert r.stick_zone_end == pytest.approx(a * np.sqrt(1 - 1500 / 3000), rel=1e-12)
    assert r.friction == "coulomb"


BAD = [
    (sliding_initiation, (0.0, 0.5), {}, r"tau0_over_E must be in \[1e-12, 1\], got 0\.0"),
    (steady_rolling, (-0.01, 0.5), {}, r"tau0_over_E must be in \[1e-12, 1\], got -0\.01"),
    (
        sliding_initiation,
        (np.nan, 0.5),
        {},
        r"tau0_over_E must be a finite number in \[1e-12, 1\], "
        r"got nan",
    ),
    (sliding_initiation, (0.01, 1.0), {}, r"d_over_a must be in \[0, 1\), got 1\.0"),
    (sliding_initiation, (0.01, -0.2), {}, r"d_over_a must be in \[0, 1\), got -0\.2"),
    (steady_rolling, (0.01, 1.5), {}, r"d_over_a must be in \(-1, 1\), got 1\.5"),
    (steady_rolling, (0.01, -1.0), {}, r"d_over_a must be in \(-1, 1\), got -1\.0"),
    (
        steady_rolling,
        (0.01, np.inf),
        {},
        r"d_over_a must be a finite number in \(-1, 1\), "
        r"got inf",
    ),
    (sliding_initiation, (0.01,), {}, r"give exactly one of d_over_a or T_over_Ea"),
    (
        steady_rolling,
        (0.01, 0.5),
        {"T_over_Ea": 0.01},
        r"give exactly one of d_over_a or T_over_Ea",
    ),
    (
        steady_rolling,
        (0.01,),
        {"T_over_Ea": -0.01},
        r"T_over_Ea must be in \[0, 1e\+12\], "
        r"got -0\.01",
    ),
    (sliding_initiation, (0.01,), {"T_over_Ea": np.inf}, r"T_over_Ea must be a finite number"),
    (sliding_initiation_coulomb, (0.0, 0.01, 0.5), {}, r"mu must be in \[1e-06, 100\], got 0\.0"),
    (steady_rolling_coulomb, (0.3, 0.0, 0.5), {}, r"a_over_R must be in \[1e-150, 10\], got 0\.0"),
    (steady_rolling_coulomb, (0.3, 0.01), {}, r"give exactly one of d_over_a or T_over_muF"),
    (
        sliding_initiation_coulomb,
        (0.3, 0.01),
        {"T_over_muF": -1.0},
        r"T_over_muF must be in \[0, 1e\+12\], got -1\.0",
    ),
    (
        steady_rolling,
        (0.01, 0.5),
        {"method": "exact"},
        r"method must be 'closed-form' or 'collocation', got 'exact'",
    ),
    (
        steady_rolling,
        (0.01, 0.5),
        {"method": "collocation", "n": 1},
        r"n must be 'auto' or an integer in \[2, 8192\], got 1",
    ),
    (sliding_initiation, (0.01, 0.5), {"tol": 0.0}, r"tol must be in \[1e-15, 1e-2\), got 0\.0"),
    (
        sliding_initiation,
        (0.01, 0.5),
        {"on_failure": "ignore"},
        r"on_failure must be 'raise' or 'report', got 'ignore'",
    ),
]


@pytest.mark.parametrize(("fn", "args", "kwargs", "message"), BAD)
def test_bad_input(fn, args, kwargs, message):
    with pytest.raises(ValueError, match=message):
        fn(*args, **kwargs)


def _cyl(**adh):
    return Cylinder.from_modulus(50e-9, 100e9, adhesion_range=0.5e-9, **adh)


BAD_SI = [
    (
        dict(),
        r"give exactly one of friction_stress \(constant tau0 \[Pa\]\) or "
        r"friction_coefficient \(Coulomb mu\)",
    ),
    (dict(friction_stress=1e8, friction_coefficient=0.3), r"give exactly one of friction_stress"),
    (dict(friction_stress=0.0), r"friction_stress must be in \(0, inf\), got 0\.0"),
    (dict(friction_coefficient=-0.3), r"friction_coefficient must be in \[1e-06, 100\], got -0\.3"),
    (
        dict(friction_stress=1e8, tangential_load=1.0, d_over_a=0.5),
        r"give exactly one of d_over_a or tangential_load \[N/m\]",
    ),
    # the validated domain, said in SI units (E = 1e11 Pa, so tau0/E in [1e-12, 1] is
    # tau0 in [0.1, 1e11] Pa)
    (
        dict(friction_stress=1e12),
        r"friction_stress must be in \[0\.1, 1e\+11\] Pa \(1e-12 to 1 times the modulus, the "
        r"domain of the solvers\), "
        r"got 1000000000000\.0",
    ),
    (dict(friction_stress=1e-3), r"friction_stress must be in \[0\.1, 1e\+11\] Pa"),
    (dict(friction_coefficient=1e3), r"friction_coefficient must be in \[1e-06, 100\], got 1000"),
    (
        dict(friction_stress=1e8, tangential_load=1e30),
        r"tangential_load must be in \[0, [0-9.e+]+\] N/m \(0 to 1e\+12 times the modulus times "
        r"the contact half-width, the domain of the solvers\), "
        r"got 1e\+30",
    ),
]


@pytest.mark.parametrize(("kwargs", "message"), BAD_SI)
def test_bad_si_input(kwargs, message):
    kw = {"d_over_a": 0.5, **kwargs} if "tangential_load" not in kwargs else kwargs
    with pytest.raises(ValueError, match=message):
        _cyl().steady_rolling(1.0, **kw)


def test_si_errors_from_the_normal_problem_and_coulomb_adhesion():
    with pytest.raises(
        ValueError,
        match=r"Coulomb friction is the macro-scale counterpart for "
        r"the non-adhesive Hertz contact",
    ):
        _cyl(cohesive_stress=1e9).sliding_initiation(1.0, friction_coefficient=0.3, d_over_a=0.5)
    with pytest.raises(ValueError, match=r"normal_load must be in \(0, inf\), got 0\.0"):
        _cyl().sliding_initiation(0.0, friction_coefficient=0.3, d_over_a=0.5)
    with pytest.raises(NoEquilibriumError, match=r"below the pull-off force"):
        _cyl(cohesive_stress=1e9).sliding_initiation(-100.0, friction_stress=1e8, d_over_a=0.5)


# --------------------------------------------------------------------------------------------
# precision near full stick (T -> 0) and honest error estimates


@pytest.mark.parametrize("r", [1e-3, 1e-8, 1e-14, 1e-300])
def test_small_tangential_loads_keep_their_relative_precision(r):
    # Closed forms evaluated without cancellation: T -> 0 gives the creep -> 0 in proportion,
    # to full relative precision (hand limits, not the code's formulas): rolling, creep =
    # -(4/pi) (tau0/E) artanh(T/(2 a tau0)); Carter, creep/V = -(mu a/R) (1 - sqrt(1 - r))
    # with r = T/(mu F), a Taylor series here; Cattaneo-Mindlin, c/a = sqrt(1 - r).
    close = dict(rel=1e-14, abs=0.0)
    one_minus_sqrt = r / 2 + r**2 / 8 + r**3 / 16 + 5 * r**4 / 128  # 1 - sqrt(1 - r)
    ro = steady_rolling(0.01, T_over_Ea=2 * 0.01 * r)
    assert ro.state == "stick-slip"
    assert ro.creep_over_V == pytest.approx(-(4 / np.pi) * 0.01 * np.arctanh(r), **close)
    ca = steady_rolling_coulomb(0.3, 0.01, T_over_muF=r)
    assert ca.creep_over_V == pytest.approx(-0.3 * 0.01 * one_minus_sqrt, rel=1e-13, abs=0.0)
    cm = sliding_initiation_coulomb(0.3, 0.01, T_over_muF=r)
    assert cm.T_over_muF == r and ca.T_over_muF == r
    # d/a = 1 - 2 sqrt(1 - r) and c/a = sqrt(1 - r), to the spacing of floats near -1 and 1
    assert 1 + ca.d_over_a == pytest.approx(2 * one_minus_sqrt, rel=1e-14, abs=2.3e-16)
    assert 1 - cm.d_over_a == pytest.approx(one_minus_sqrt, rel=1e-14, abs=1.2e-16)
    if r >= 1e-14:
        # and back: the load from the state, to the precision d carries
        back = steady_rolling_coulomb(0.3, 0.01, ca.d_over_a).T_over_muF
        assert back == pytest.approx(r, rel=max(1e-13, 3e-16 / r), abs=0.0)


@pytest.mark.parametrize(
    ("fn", "args", "ds"),
    [
        (steady_rolling, (0.01,), -1 + np.geomspace(1e-9, 0.5, 25)),
        (steady_rolling_coulomb, (0.3, 0.01), -1 + np.geomspace(1e-12, 0.5, 25)),
        (sliding_initiation, (0.01,), 1 - np.geomspace(1e-9, 0.5, 25)),
    ],
)
def test_converged_means_accurate_near_full_stick(fn, args, ds):
    # A point the collocation reports converged agrees with the closed form to 10 tol; the
    # others say so (converged False) rather than return a wrong creep
    c = fn(*args, ds, method="collocation", on_failure="report")
    f = fn(*args, ds)
    T = "T_over_muF" if fn is steady_rolling_coulomb else "T_over_Ea"
    errs = [np.abs(getattr(c, T) / getattr(f, T) - 1)]
    if fn is not sliding_initiation:
        errs.append(np.abs(c.creep_over_V / f.creep_over_V - 1))
    err = np.max(errs, axis=0)
    assert c.converged.any() and not c.converged.all()
    assert np.all(err[c.converged] <= 1e-11)
    assert np.all(err[c.converged] <= 10 * np.maximum(c.error_estimate[c.converged], 1e-13))
