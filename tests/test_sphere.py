"""The Maugis-Dugdale sphere (linecontact.sphere): its limits, Maugis' own form, round trips.

Each result is checked a second way: Hertz at sigma0 = 0 to rounding; JKR and DMT, loads
and pull-offs, to 1e-10 deep in their limits of the Maugis parameter; Maugis' equations as
he wrote them (his units, his ``m = c/a``), solved here with mpmath at 40 digits; the
states depend on lambda alone in Maugis' units; the stable contact under a load gives that
load back; the pull-off is the lowest load of a dense scan of the branch; the slopes that
decide stability are the branch's finite differences. An independent ring solver is in
tests/test_sphere_rings.py.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from linecontact.closed_forms.sphere import (
    LAMBDA_OVER_TABOR,
    sphere_dmt_load,
    sphere_hertz_load,
    sphere_jkr_approach,
    sphere_jkr_load,
    sphere_maugis_parameter,
)
from linecontact.errors import NoEquilibriumError
from linecontact.sphere import _branch as _b
from linecontact.sphere import (
    sphere_contact,
    sphere_contact_for_load,
    sphere_load_curve,
    sphere_pull_off,
)

mp = pytest.importorskip("mpmath")


def _rho_s(lam: float, rho: float = 1e6) -> tuple[float, float]:
    """``(R/h, sigma0/E)`` of a Maugis parameter ``lam`` at ``R/h = rho``."""
    s = math.sqrt((lam / 2) ** 3 * 16 * math.pi / (9 * rho))
    return rho, s


def _unit(rho: float, s: float) -> float:
    """Maugis' unit of length over R."""
    return (3 * math.pi * s / (4 * rho)) ** (1 / 3)


# ------------------------------------------------------------------------------------------
# the limits


def test_sigma0_zero_is_hertz_to_rounding():
    a = np.geomspace(1e-6, 0.5, 40)
    r = sphere_contact(a, 1e4, 0.0)
    np.testing.assert_allclose(r.F_over_EhR, sphere_hertz_load(a, 1e4), rtol=4e-16)
    np.testing.assert_allclose(r.delta_over_h, 1e4 * a**2, rtol=4e-16)
    assert sphere_pull_off(1e4, 0.0).F_pulloff_over_EhR == 0.0
    assert sphere_pull_off(1e4, 0.0).mechanism == "no-adhesion"


def test_jkr_limit_of_the_load_and_the_approach():
    # lambda = 2.4e5: the Dugdale zone's width is ~1/lambda^2 of the contact's
    rho, s = 1e12, 100.0
    assert sphere_maugis_parameter(rho, s) > 2e5
    a = np.array([0.5, 1.0, 1.5, 3.0]) * _unit(rho, s)
    r = sphere_contact(a, rho, s)
    jkr = sphere_jkr_load(a, rho, s)
    scale = np.pi * s  # pi w R over E h R
    np.testing.assert_allclose(r.F_over_EhR / scale, jkr / scale, rtol=0, atol=1e-9)
    np.testing.assert_allclose(
        r.delta_over_h, sphere_jkr_approach(a, rho, s), rtol=1e-9, err_msg="approach"
    )


@pytest.mark.parametrize(("control", "jkr"), [("load", -1.5), ("displacement", -5 / 6)])
def test_jkr_pull_offs_in_their_limit(control, jkr):
    p = sphere_pull_off(1e12, 100.0, control=control)
    assert p.F_pulloff_over_piwR == pytest.approx(jkr, abs=1e-10), control
    assert p.mechanism == ("contact" if control == "load" else "jump-out")
    # JKR's radii at pull-off in Maugis' unit: (3/2)^(1/3) (load), (1/6)^(1/3)... measured
    A = p.a_over_R_at_pulloff / _unit(1e12, 100.0)
    want = 1.5 ** (1 / 3) if control == "load" else (1 / 6) ** (1 / 3)
    assert A == pytest.approx(want, rel=1e-6), control


@pytest.mark.parametrize("control", ["load", "displacement"])
def test_dmt_pull_off_in_its_limit(control):
    rho, s = _rho_s(1e-9)
    p = sphere_pull_off(rho, s, control=control)
    assert p.F_pulloff_over_piwR == pytest.approx(-2.0, abs=1e-10), control


def test_dmt_load_in_its_limit():
    # its departure from DMT at a fixed radius is about 4 pi lambda (1.26e-8 at 1e-9)
    rho, s = _rho_s(1e-12)
    a = np.array([0.5, 1.0, 2.0]) * _unit(rho, s)
    r = sphere_contact(a, rho, s)
    scale = np.pi * s
    np.testing.assert_allclose(
        r.F_over_EhR / scale, sphere_dmt_load(a, rho, s) / scale, rtol=0, atol=1e-10
    )


def test_the_pull_off_moves_from_dmt_to_jkr_monotonically():
    lam = np.geomspace(1e-3, 1e3, 61)
    rho = np.full(lam.shape, 1e8)
    s = np.sqrt((lam / 2) ** 3 * 16 * np.pi / (9 * rho))
    P = sphere_pull_off(rho, s).F_pulloff_over_piwR
    assert np.all(np.diff(P) > 0) and P[0] > -2 and P[-1] < -1.5
    D = sphere_pull_off(rho, s, control="displacement").F_pulloff_over_piwR
    assert np.all(D >= P - 1e-12) and D[-1] < -5 / 6 + 1e-3


def test_the_maugis_parameter_and_tabors():
    assert sphere_maugis_parameter(100.0, 0.01) == pytest.approx(
        2 * (9 * 1e-4 * 100 / (16 * math.pi)) ** (1 / 3), rel=1e-15
    )
    # lambda = 2 sigma0 (R/(pi w K^2))^(1/3) with sigma0 = 16 w/(9 sqrt 3 z0): 1.1570 mu
    R, E, w, z0 = 1e-6, 50e9, 0.1, 0.3e-9
    sigma0 = 16 * w / (9 * math.sqrt(3) * z0)
    lam = 2 * sigma0 * (R / (math.pi * w * (4 * E / 3) ** 2)) ** (1 / 3)
    mu = (R * w * w / (E * E * z0**3)) ** (1 / 3)
    assert lam / mu == pytest.approx(LAMBDA_OVER_TABOR, rel=1e-14)
    assert LAMBDA_OVER_TABOR == pytest.approx(1.1570, abs=5e-5)


# ------------------------------------------------------------------------------------------
# Maugis' own equations, in his units, to 40 digits


def _maugis(A: float, lam: float) -> tuple[float, float, float]:
    """``(m, P, Delta)`` of Maugis (1992), Eqs 6.17-6.19, his units (mpmath, 40 digits)."""
    with mp.workdps(40):
        A, lam = mp.mpf(A), mp.mpf(lam)

        def gap(m):
            r = mp.sqrt(m * m - 1)
            t = mp.atan(r)
            return lam * A**2 / 2 * (r + (m * m - 2) * t) + 4 * lam**2 * A / 3 * (r * t - m + 1) - 1

        m = mp.findroot(gap, (mp.mpf(1) + mp.mpf("1e-30"), mp.mpf(10) ** 8), solver="anderson")
        r = mp.sqrt(m * m - 1)
        P = A**3 - lam * A**2 * (r + m * m * mp.atan(r))
        D = A**2 - mp.mpf(4) / 3 * A * lam * r
        return float(m), float(P), float(D)


@pytest.mark.parametrize("lam", [0.01, 0.3, 1.0, 3.0, 30.0])
@pytest.mark.parametrize("A", [1e-3, 0.1, 0.6, 1.2, 4.0])
def test_maugis_own_equations_at_40_digits(lam, A):
    rho, s = _rho_s(lam, rho=1e5)
    a = A * _unit(rho, s)
    r = sphere_contact(a, rho, s)
    m, P, D = _maugis(A, lam)
    delta_unit = (9 * math.pi**2 * s * s * rho / 16) ** (1 / 3)
    assert r.c_over_R / a == pytest.approx(m, rel=2e-14), (lam, A)
    assert r.F_over_piwR == pytest.approx(P, rel=1e-13, abs=1e-13), (lam, A)
    assert r.delta_over_h / delta_unit == pytest.approx(D, rel=1e-13, abs=1e-13), (lam, A)


def test_the_states_depend_on_lambda_alone_in_maugis_units():
    lam = 0.7
    out = []
    for rho in (10.0, 1e4, 1e9):
        rho, s = _rho_s(lam, rho)
        a = np.array([0.05, 0.5, 2.0]) * _unit(rho, s)
        r = sphere_contact(a, rho, s)
        out.append((r.F_over_piwR, sphere_pull_off(rho, s).F_pulloff_over_piwR))
    for F, P in out[1:]:
        np.testing.assert_allclose(F, out[0][0], rtol=1e-13)
        assert P == pytest.approx(out[0][1], rel=1e-13)


# ------------------------------------------------------------------------------------------
# round trips, the pull-off against a scan, the slopes


@pytest.mark.parametrize("lam", [0.05, 0.5, 2.0, 20.0])
def test_the_contact_under_a_load_gives_the_load_back(lam):
    rho, s = _rho_s(lam)
    po = sphere_pull_off(rho, s)
    loads = po.F_pulloff_over_EhR * np.array([1 - 1e-9, 0.5, 0.0, -1.0, -10.0, -1e3])
    r = sphere_contact_for_load(loads, rho, s)
    assert np.all(r.stable) and np.all(r.a_over_R >= po.a_over_R_at_pulloff)
    back = sphere_contact(r.a_over_R, rho, s).F_over_EhR
    # a load of 0 is a difference of terms of the pull-off's size: rounding of that size
    np.testing.assert_allclose(back, loads, rtol=1e-12, atol=1e-13 * abs(po.F_pulloff_over_EhR))


def test_a_load_below_the_pull_off_has_no_contact():
    rho, s = _rho_s(1.0)
    F = 1.01 * sphere_pull_off(rho, s).F_pulloff_over_EhR
    with pytest.raises(NoEquilibriumError, match="below the pull-off force.*has come off"):
        sphere_contact_for_load(F, rho, s)
    r = sphere_contact_for_load([F, 0.0], rho, s, on_failure="report")
    assert np.isnan(r.a_over_R[0]) and r.a_over_R[1] > 0


@pytest.mark.parametrize("lam", [0.02, 0.2, 1.0, 5.0, 50.0])
@pytest.mark.parametrize("control", ["load", "displacement"])
def test_the_pull_off_is_the_lowest_point_of_a_dense_scan(lam, control):
    rho, s = _rho_s(lam)
    p = sphere_pull_off(rho, s, control=control)
    a = np.geomspace(1e-7, 20, 20001) * _unit(rho, s)
    x, F, delta, q, res = _b.branch(a, rho, s)
    values = F if control == "load" else delta
    got = p.F_pulloff_over_EhR if control == "load" else p.delta_over_h_at_pulloff
    end = _b.separated(0.0, rho, s)[1 if control == "load" else 2]
    lowest = min(values.min(), float(end))
    scale = abs(lowest)
    assert got <= lowest + 1e-13 * scale, (lam, control)
    assert got >= lowest - 1e-6 * scale, (lam, control)  # the scan's own spacing


@pytest.mark.parametrize("lam", [0.05, 1.0, 10.0])
def test_the_slopes_are_the_branchs_finite_differences(lam):
    rho, s = _rho_s(lam)
    a = np.array([0.1, 0.7, 1.3, 3.0]) * _unit(rho, s)
    q = _b.zone(a, rho, s)[0]
    dF, dD = _b.slopes(a, rho, s, q)
    h = 1e-6 * a
    Fp, Fm = _b.branch(a + h, rho, s)[1], _b.branch(a - h, rho, s)[1]
    Dp, Dm = _b.branch(a + h, rho, s)[2], _b.branch(a - h, rho, s)[2]
    # the differences lose the loads' rounding over h: compared at the slopes' own scale
    fd_F, fd_D = (Fp - Fm) / (2 * h), (Dp - Dm) / (2 * h)
    np.testing.assert_allclose(dF, fd_F, rtol=1e-6, atol=1e-6 * np.abs(fd_F).max())
    np.testing.assert_allclose(dD, fd_D, rtol=1e-6, atol=1e-6 * np.abs(fd_D).max())


def test_out_of_contact_meets_the_contact_branch_at_touching():
    rho, s = _rho_s(0.4)
    x, F, delta = _b.separated(0.0, rho, s)
    c = sphere_contact(1e-12 * _unit(rho, s), rho, s)
    assert c.c_over_R == pytest.approx(float(x), rel=1e-10)
    assert c.F_over_EhR == pytest.approx(float(F), rel=1e-10)
    assert c.delta_over_h == pytest.approx(float(delta), rel=1e-10)


def test_the_load_curve_passes_through_both_pull_offs():
    rho, s = _rho_s(5.0)
    c = sphere_load_curve(rho, s, num=300, num_noncontact=20)
    assert list(c.branch[:20]) == ["non-contact"] * 20 and c.branch[-1] == "contact"
    # the curve's states are one array, the pull-offs' their own calls: SIMD paths may round
    # apart in the last bits (README), so within a few ulp
    same = dict(rel=1e-14, abs=0.0)
    assert c.F_over_EhR[c.pull_off_load][0] == pytest.approx(c.pulloff.F_pulloff_over_EhR, **same)
    pd = c.pulloff_displacement.F_pulloff_over_EhR
    assert c.F_over_EhR[c.pull_off_displacement][0] == pytest.approx(pd, **same)
    assert c.F_over_EhR.min() == pytest.approx(c.pulloff.F_pulloff_over_EhR, **same)
    contact = c.branch == "contact"
    # the load grows with the radius beyond the pull-off, and the approach with it
    after = contact & (c.a_over_R > c.pulloff.a_over_R_at_pulloff)
    assert np.all(np.diff(c.F_over_EhR[after]) > 0) and np.all(c.stable[after])
    # out of contact the gap closes from h to 0, the zone growing, the tension with it
    off = ~contact
    assert c.central_gap_over_h[0] == 1.0 and np.all(np.diff(c.c_over_R[off]) > 0)


# ------------------------------------------------------------------------------------------
# the whole domain


@given(
    rho=st.floats(1e-3, 1e12),
    s=st.floats(1e-9, 1e3),
)
@settings(max_examples=150, deadline=None)
def test_every_pull_off_lies_between_jkr_and_dmt(rho, s):
    p = sphere_pull_off(rho, s)
    d = sphere_pull_off(rho, s, control="displacement")
    assert p.converged and d.converged and abs(p.residual_separation) < 1e-12, (rho, s)
    assert -2 - 1e-12 <= p.F_pulloff_over_piwR <= -1.5 + 1e-12, (rho, s)
    assert p.F_pulloff_over_piwR <= d.F_pulloff_over_piwR + 1e-12, (rho, s)
    assert -2 - 1e-12 <= d.F_pulloff_over_piwR <= -5 / 6 + 1e-12, (rho, s)
    try:
        r = sphere_contact_for_load(0.0, rho, s)
    except ValueError as e:  # the far corner: a contact wider than the domain's 10 R
        assert "beyond 10" in str(e) and p.a_over_R_at_pulloff > 1, (rho, s, e)
        return
    assert r.converged and r.stable and r.a_over_R > 0, (rho, s)


@pytest.mark.parametrize(
    ("call", "message"),
    [
        (lambda: sphere_contact(-0.1, 100, 0.01), "a_over_R"),
        (lambda: sphere_contact(0.1, 0, 0.01), "R_over_h"),
        (lambda: sphere_contact(0.1, 100, -1), "sigma0_over_E"),
        (lambda: sphere_pull_off(100, 0.01, control="force"), "control must be 'load'"),
        (lambda: sphere_contact_for_load(2e12, 100, 0.01), "F_over_EhR"),
        (lambda: sphere_load_curve(100, 0.01, num=1), "num must be an integer"),
    ],
)
def test_bad_input_names_the_parameter(call, message):
    with pytest.raises(ValueError, match=message):
        call()
