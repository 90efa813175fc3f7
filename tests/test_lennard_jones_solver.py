"""The self-consistent Lennard-Jones solver: limits, refinement, the curve and bad input.

Checked here: the rigid limit against the closed form (state and pull-off), the error
estimate against the change under mesh refinement, the discrete gap equation solved, the
load curve's pull-off as its minimum and the contact for a load on it, the sign of the
elastic correction (compliance lifts the surface under the centre, so at a given central
gap the attraction is weaker), the trend towards JKR and the comparison with
Maugis-Dugdale, and refusal of bad input.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from linecontact import ConvergenceError, NoEquilibriumError, maugis_parameter, pull_off
from linecontact.closed_forms import lennard_jones_rigid_load, lennard_jones_rigid_pull_off
from linecontact.lennard_jones import (
    MAUGIS_MATCH_SIGMA0,
    lj_contact_for_load,
    lj_curve,
    lj_pull_off,
    lj_state,
    maugis_parameter_of_mu,
    mu_of_dugdale,
)


@pytest.mark.parametrize("zeta0", [0.95, 1.1, 2.0, 8.0])
def test_rigid_limit_state_is_the_closed_form(zeta0):
    s = lj_state(zeta0, 0.0)
    exact = lennard_jones_rigid_load(zeta0)
    assert abs(s.F / exact - 1) < 1e-7
    assert abs(s.F - exact) <= s.error_estimate + 1e-12 * abs(exact)
    assert s.converged and s.residual < 1e-10


def test_rigid_limit_pull_off_is_the_closed_form():
    F, z = lennard_jones_rigid_pull_off()
    po = lj_pull_off(0.0)
    assert po.F_pulloff == pytest.approx(F, rel=1e-9)
    assert po.central_gap_at_pulloff == pytest.approx(z, rel=1e-6)
    assert math.isnan(po.F_jump_in) and po.half_width_at_pulloff == 0.0


def test_small_mu_approaches_the_rigid_pull_off_linearly():
    F0 = lennard_jones_rigid_pull_off()[0]
    d = [lj_pull_off(mu).F_pulloff - F0 for mu in (0.01, 0.02)]
    assert d[0] > 0 and d[1] / d[0] == pytest.approx(2.0, rel=0.05)


def test_error_estimate_bounds_the_change_under_refinement():
    fine = lj_state(1.05, 1.0, m=640)
    for m in (160, 320):
        s = lj_state(1.05, 1.0, m=m)
        assert abs(s.F - fine.F) <= s.error_estimate
        assert s.residual < 1e-10
    assert fine.error_estimate < 1e-6 * abs(fine.F)


def test_compliance_weakens_the_attraction_at_a_given_central_gap():
    # the attraction lifts the surface most under the centre: around it the gap is wider
    F = [lj_state(1.05, mu, m=160).F for mu in (0.0, 0.1, 0.3, 1.0)]
    assert np.all(np.diff(F) > 0)


def test_gap_field_solves_the_gap_equation_and_has_its_datum_at_the_centre():
    s = lj_state(1.0, 1.0, m=160)
    assert s.gap_over_z0[0] == 1.0 and np.all(s.gap_over_z0 > 0)
    # far away the gap is the parabola plus the log of the net load, wider for a tension
    far = s.xi > 100
    assert np.all(s.gap_over_z0[far] > 0.5 * s.xi[far] ** 2)
    assert s.F == pytest.approx(2 * np.trapezoid(s.pressure, s.xi), rel=1e-3)


@pytest.fixture(scope="module")
def curve_1():
    return lj_curve(1.0)


def test_curve_pull_off_is_its_minimum_and_is_stable_beyond_it(curve_1):
    c, po = curve_1, curve_1.pull_off
    assert np.all(np.diff(c.central_gap_over_z0) < 0)  # one pass, no fold at mu = 1
    assert po.F_pulloff <= c.F.min() + 1e-12
    assert c.F[-1] >= 7.5 and c.half_width[-1] > 0
    beyond = c.central_gap_over_z0 < po.central_gap_at_pulloff
    assert np.all(c.stable[beyond][1:-1])
    assert not np.any(c.stable[~beyond][1:-1])
    assert np.count_nonzero(c.turning) == 1
    assert po.error_estimate < 1e-3 * abs(po.F_pulloff)


def test_contact_for_load_round_trip(curve_1):
    for F in (-1.0, 0.0, 2.0):
        s = lj_contact_for_load(F, 1.0)
        assert s.F == pytest.approx(F, abs=1e-10)
        assert s.central_gap_over_z0 < curve_1.pull_off.central_gap_at_pulloff
        again = lj_state(s.central_gap_over_z0, 1.0)
        assert again.F == pytest.approx(F, abs=10 * s.error_estimate + 1e-9)
    with pytest.raises(NoEquilibriumError, match="below the pull-off"):
        lj_contact_for_load(-2.0, 1.0)


def _jkr(mu: float) -> float:
    # JKR line contact F = pi E a^2/(4R) - sqrt(2 pi E w a): its minimum over a is
    # -(3/4) pi^(1/3) (E R)^(1/3) (2w)^(2/3) = -(3/4)(4 pi/mu)^(1/3) w sqrt(R/z0)
    return -0.75 * (4 * math.pi / mu) ** (1 / 3)


def _md(mu: float, R_over_h: float = 1e4) -> float:
    """The matched Maugis-Dugdale pull-off over w sqrt(R/z0) (the Dugdale solver)."""
    s = mu * MAUGIS_MATCH_SIGMA0**1.5 / math.sqrt(R_over_h)
    m, R_over_z0 = mu_of_dugdale(R_over_h, s)
    assert m == pytest.approx(mu, rel=1e-12)
    return float(pull_off(R_over_h, s).F_pulloff_over_Eh / (s * math.sqrt(R_over_z0)))


def test_mu_of_dugdale_from_the_matching():
    # w = sigma0 h and sigma0 = S w/z0 (the law's peak tension): z0 = S h, and
    # mu = w sqrt(R/z0)/(E z0) = (sigma0/E) sqrt(R/h) S^(-3/2), written out here
    S = 16 / (9 * math.sqrt(3))
    for R_over_h, s in ((1e4, 0.003), (10.0, 0.2), (1e6, 1e-5)):
        w_over_Eh, z0_over_h = s, S
        mu = w_over_Eh / z0_over_h * math.sqrt(R_over_h / z0_over_h)
        m, R_over_z0 = mu_of_dugdale(R_over_h, s)
        assert m == pytest.approx(mu, rel=1e-13)
        assert R_over_z0 == pytest.approx(R_over_h / z0_over_h, rel=1e-13)


def test_matched_dugdale_reaches_jkr():
    # independent of the Lennard-Jones solver: the Dugdale solver, mapped to the native
    # groups by the matching, tends to the JKR pull-off at large mu (a check of the map)
    errs = [abs(_md(mu, 1e6) / _jkr(mu) - 1) for mu in (1.0, 10.0, 100.0)]
    assert errs[0] > errs[1] > errs[2] and errs[2] < 1e-6


def test_pull_off_between_jkr_and_dugdale():
    # for mu <= 1 (Maugis parameter <= 1.96) JKR pulls hardest, the matched Dugdale step
    # next, the full law least (16 % below Dugdale in the rigid limit)
    for mu in (0.1, 0.3, 1.0):
        po = lj_pull_off(mu)
        assert _jkr(mu) < _md(mu) < po.F_pulloff < 0


@pytest.mark.slow
def test_jkr_limit():
    # the full law tends to JKR as mu grows (the edge zone ~1/mu shrinks against the contact
    # ~mu^(1/3)): the relative difference falls by more than 3 for each factor 3 in mu
    # (0.19, 0.060, 0.017 at mu = 0.3, 1, 3; 0.0041 at mu = 10, docs/lennard-jones.md)
    errs = []
    for mu in (0.3, 1.0, 3.0):
        po = lj_pull_off(mu)
        errs.append(abs(po.F_pulloff / _jkr(mu) - 1))
        assert po.error_estimate < 1e-5 * abs(po.F_pulloff)
    assert errs[0] > 3 * errs[1] > 9 * errs[2]
    assert errs[2] < 0.02


def test_maugis_parameter_of_mu():
    # the library's Maugis parameter of the matched Dugdale groups depends on mu alone
    for R_over_h, s in ((1e4, 0.003), (10.0, 0.2)):
        mu, _ = mu_of_dugdale(R_over_h, s)
        lam = maugis_parameter(R_over_h, s)
        assert maugis_parameter_of_mu(mu) == pytest.approx(lam, rel=1e-12)


@pytest.mark.parametrize(
    ("call", "match"),
    [
        (lambda: lj_state(0.0, 1.0), "central_gap_over_z0"),
        (lambda: lj_state(float("nan"), 1.0), "central_gap_over_z0"),
        (lambda: lj_state(1.0, -1.0), "mu"),
        (lambda: lj_state(1.0, 401.0), "mu"),
        (lambda: lj_pull_off(float("inf")), "mu"),
        (lambda: lj_curve(1.0, F_max=-1.0), "F_max"),
        (lambda: lj_curve(1.0, m=30), "m must be"),
        (lambda: lj_contact_for_load(float("nan"), 1.0), "F must be finite"),
    ],
)
def test_bad_input(call, match):
    with pytest.raises(ValueError, match=match):
        call()


def test_convergence_error_names_the_point(monkeypatch):
    import linecontact.lennard_jones._solver as lj

    monkeypatch.setattr(lj, "_iterate", lambda mu, mesh, z, z0, e, tol: (z, z0, 1.0, False))
    with pytest.raises(ConvergenceError, match=r"mu=0\.5"):
        lj_pull_off(0.5)
    with pytest.raises(ConvergenceError, match=r"mu=30\.0"):
        lj_curve(30.0)


def test_pull_off_law_lennard_jones_in_dugdale_groups():
    from linecontact.laws.lennard_jones import pull_off as lj_groups_pull_off
    from linecontact.lennard_jones import LennardJonesPullOff

    R_over_h, s = 100.0, 0.05
    p = lj_groups_pull_off(R_over_h, s)
    assert isinstance(p, LennardJonesPullOff) and p.law == "lennard-jones"
    mu, R_over_z0 = mu_of_dugdale(R_over_h, s)
    native = lj_pull_off(float(mu))
    assert p.F_pulloff_over_Eh == pytest.approx(native.F_pulloff * s * math.sqrt(R_over_z0))
    assert p.central_gap_over_h_at_pulloff == pytest.approx(
        native.central_gap_at_pulloff * MAUGIS_MATCH_SIGMA0
    )
    # Dugdale with the same w and peak tension pulls harder
    assert pull_off(R_over_h, s).F_pulloff_over_Eh < p.F_pulloff_over_Eh < 0
    arr = lj_groups_pull_off([R_over_h, 1000.0], s / 3)
    assert arr.F_pulloff_over_Eh.shape == (2,)
    # beyond the self-consistent domain the pull-off is the corrected JKR limit
    far = lj_groups_pull_off(1e4, 10.0)
    assert far.method == "limit" and far.error_estimate_over_Eh > 0
    assert p.method == "self-consistent"
    with pytest.raises(ValueError, match="sigma0_over_E"):
        lj_groups_pull_off(100.0, math.inf)
    with pytest.raises(ValueError, match="sigma0_over_E must be > 0"):
        lj_groups_pull_off(100.0, 0.0)
    with pytest.raises(TypeError, match="law"):
        pull_off(100.0, 0.01, law="lennard-jones")  # a law is a module (laws.lennard_jones)


def test_contact_for_a_load_the_curve_passed_through():
    # a load equal to a state of the march: the bracket's end, solved again, may land on
    # the other side of the load by round-off (brentq refused the bracket before)
    mu = 0.0961667
    F = float(lj_curve(mu).F[-1])
    s = lj_contact_for_load(F, mu)
    assert s.F == pytest.approx(F, abs=10 * s.error_estimate)
