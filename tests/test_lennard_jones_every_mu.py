"""The Lennard-Jones law at every mu (issue 22): the JKR limit, the limit form, the S-curve.

Each result is checked a second, independent way: the self-consistent pull-off against the
closed-form JKR and Maugis-Dugdale pull-offs and against the limit form in their overlap; the
limit form's central gap against the JKR pressure at the centre; the fast pull-off search
against the whole curve; the error estimate against refinement.
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import linecontact as lc
from linecontact.cli import main
from linecontact.domain import DOMAIN
from linecontact.errors import ConvergenceError
from linecontact.lennard_jones import MAUGIS_MATCH_SIGMA0 as S
from linecontact.lennard_jones import _limit, lj_curve, lj_pull_off


def jkr(mu):
    return -0.75 * (4 * math.pi / mu) ** (1 / 3)


def md(mu, R_over_h=1e6):
    s = mu * S**1.5 / math.sqrt(R_over_h)
    po = lc.pull_off(R_over_h, s)
    return float(po.F_pulloff_over_Eh) / (s * math.sqrt(R_over_h / S))


def test_the_domain_of_the_curves_is_that_of_the_self_consistent_solver():
    assert DOMAIN["lj_mu"][2] == _limit.MU_SELF_CONSISTENT
    assert math.isinf(DOMAIN["lj_mu_pull_off"][2])


@settings(max_examples=6)
@given(st.floats(min_value=-2.0, max_value=math.log10(400.0)))
def test_pull_off_lies_between_the_rigid_cylinder_and_the_simpler_models(log_mu):
    # a cylinder pulls off at a load less tensile than under the Dugdale step with the same w
    # and peak tension, and than JKR; more than a rigid cylinder under the same law
    mu = 10.0**log_mu
    p = lj_pull_off(mu)
    F_rigid = lc.closed_forms.lennard_jones_rigid_pull_off()[0]
    assert F_rigid < p.F_pulloff < 0
    assert md(mu) < p.F_pulloff and jkr(mu) < p.F_pulloff
    assert p.method == "self-consistent" and p.converged
    assert 0 < p.error_estimate < 3e-5 * abs(p.F_pulloff)
    assert p.half_width_at_pulloff == 0.0  # the whole contact is tensile at pull-off


def test_pull_off_tends_to_jkr_with_the_edge_zone_rate():
    mus = (30.0, 100.0, 300.0)
    d = np.array([lj_pull_off(mu).F_pulloff / jkr(mu) - 1 for mu in mus])
    assert np.all(d < 0) and np.all(np.diff(np.abs(d)) < 0)
    rate = -np.diff(np.log(-d)) / np.diff(np.log(mus))
    # the edge zone (1/mu) over the contact (mu^(1/3)): towards 4/3 from below
    assert np.all((1.15 < rate) & (rate < 4 / 3))


def test_central_gap_at_pull_off_tends_to_the_jkr_pressure_at_the_centre():
    # at the JKR pull-off p(0) = -E a/(2R), a^3 = 2 mu/pi: the linearised law gives the gap
    for mu in (100.0, 400.0):
        p = lj_pull_off(mu)
        gap = 1 + (2 / math.pi) ** (1 / 3) / (32 * mu ** (2 / 3))
        assert p.central_gap_at_pulloff - 1 == pytest.approx(gap - 1, rel=0.01)


def test_limit_form_meets_the_self_consistent_solver_in_the_overlap():
    from linecontact.lennard_jones import _branch, _solver

    mu = _limit.MU_SELF_CONSISTENT
    sc = lj_pull_off(mu)
    F, err, gap = _limit.limit_pull_off(mu)
    assert abs(F - sc.F_pulloff) <= err
    assert gap == pytest.approx(sc.central_gap_at_pulloff, rel=1e-5)
    # beyond the public domain, the self-consistent solver forced there
    po, _ = _branch.pull_off_search(560.0, _solver._grid_for(560.0, None))
    F, err, _ = _limit.limit_pull_off(560.0)
    assert abs(F - po.F) <= err


@pytest.mark.parametrize("mu", [401.0, 1e4, 1e8])
def test_beyond_the_domain_the_pull_off_is_the_limit_form(mu):
    p = lj_pull_off(mu)
    assert p.method == "limit" and p.n == 0 and p.converged
    assert math.isnan(p.F_jump_in) and p.half_width_at_pulloff == 0.0
    assert 0 < p.error_estimate < abs(jkr(mu) - p.F_pulloff) * 1.0000001
    assert jkr(mu) < p.F_pulloff < 0
    assert p.F_pulloff == pytest.approx(jkr(mu), rel=1e-4)


def test_s_curve_appears_between_mu_3_and_10():
    assert math.isnan(lj_pull_off(3.0).F_jump_in)
    p = lj_pull_off(10.0)
    # jump-in: the last maximum of the load before the pull-off branch
    assert p.F_pulloff < p.F_jump_in < 0
    assert p.central_gap_at_jump_in > p.central_gap_at_pulloff
    assert p.F_jump_in == pytest.approx(-0.263665, abs=2e-6)


def test_fast_pull_off_is_the_minimum_of_the_whole_curve():
    mu = 30.0
    c = lj_curve(mu)
    p = lj_pull_off(mu)
    tol = p.error_estimate + c.pull_off.error_estimate
    assert abs(p.F_pulloff - c.pull_off.F_pulloff) <= tol
    assert abs(p.F_jump_in - c.pull_off.F_jump_in) <= 1e-6
    assert p.F_pulloff <= c.F.min() + tol
    # the curve passes its turning points in order: the jump-in before the pull-off
    assert c.F[-1] >= 7.5 and c.half_width[-1] > 0
    assert np.all(np.diff(c.central_gap_over_z0) < 0)


def test_error_estimate_bounds_the_change_under_refinement_at_large_mu():
    fine = lj_pull_off(30.0, m=640)
    for m in (160, 320):
        p = lj_pull_off(30.0, m=m)
        assert abs(p.F_pulloff - fine.F_pulloff) <= p.error_estimate


def test_unresolved_pull_off_raises(monkeypatch):
    from linecontact.lennard_jones import _branch

    monkeypatch.setattr(_branch, "_RESOLVED", 1e-12)
    with pytest.raises(ConvergenceError, match=r"not resolved at mu=3\.0"):
        lj_pull_off(3.0)


@pytest.mark.parametrize(
    ("modulus", "mu", "method"),
    [(5.7e8, 33.8, "self-consistent"), (2.0e6, 9.6e3, "limit")],
)
def test_cli_pull_off_of_a_polymer_and_an_elastomer_fibre(capsys, modulus, mu, method):
    argv = ["pulloff", "--law", "lennard-jones", "--radius", "1e-06", "--modulus"]
    argv += [repr(modulus), "--work-of-adhesion", "0.1", "--z0", "3e-10", "--json"]
    assert main(argv) == 0
    doc = json.loads(capsys.readouterr().out)
    r = doc["results"][0]
    assert r["mu"] == pytest.approx(mu, rel=0.01) and r["method"] == method
    F_jkr = -0.75 * (4 * math.pi * 1e-6 * 0.1**2 * modulus) ** (1 / 3)  # (E w^2 R)^(1/3)
    assert r["F_pulloff_N_per_m"] == pytest.approx(F_jkr, rel=0.01)
    assert 0 < r["error_estimate_over_Eh"] < 1e-4 * abs(r["F_pulloff_over_Eh"])


@pytest.mark.parametrize("bad", ["nan", "inf", "-1"])
def test_bad_mu_is_refused_naming_it(bad):
    with pytest.raises(ValueError, match="mu"):
        lj_pull_off(float(bad))


@pytest.mark.parametrize("y", [1.5, 11.0])
def test_compliant_contact_is_the_jkr_contact_s_compressed_part(y):
    # in the JKR limit the repulsive region is where the JKR pressure is compressive:
    # p(x) = E/(2R) sqrt(a^2 - x^2) + (F - F_hertz)/(pi sqrt(a^2 - x^2)) > 0 for
    # x^2 < a^2 + 2R (F - F_hertz)/(pi E); in these units xi_r^2 = a^2 - 2 sqrt(2 mu a/pi)
    from scipy.optimize import brentq

    from linecontact.lennard_jones import lj_contact_for_load

    mu = 100.0
    F_po = lj_pull_off(mu).F_pulloff
    F = F_po + y * abs(F_po)
    s = lj_contact_for_load(F, mu)

    def load(a):
        return math.pi * a * a / (4 * mu) - math.sqrt(2 * math.pi * a / mu) - F

    a = brentq(load, (2 * mu / math.pi) ** (1 / 3), 1e4, xtol=1e-14)
    xi_r = math.sqrt(a * a - 2 * math.sqrt(2 * mu * a / math.pi))
    assert s.half_width == pytest.approx(xi_r, rel=5e-4)  # measured 1.3e-4 and 3.6e-5
    assert s.half_width < a  # narrower than the JKR contact: its edge is in tension


def test_the_memory_of_a_continuation_changes_no_answer():
    from linecontact.lennard_jones import LJContinuation, lj_contact_for_load

    curve = LJContinuation(30.0)
    first = curve.contact_for_load(0.2)
    again = curve.contact_for_load(0.2)  # from the pull-off it found
    fresh = lj_contact_for_load(0.2, 30.0)
    for s in (again, fresh):
        assert s.half_width == pytest.approx(first.half_width, rel=1e-9)
        assert s.central_gap_over_z0 == pytest.approx(first.central_gap_over_z0, rel=1e-9)


@pytest.mark.parametrize("mu", [0.5, 3.0])
def test_a_call_does_not_depend_on_the_calls_before_it(mu, monkeypatch):
    """The warm start is the caller's object: the module keeps nothing between calls.

    Before, the last curve's states and the meshes' chord factorisations were the module's,
    and a state asked for after a curve at the same mu started from them (its load moved
    by about 2e-12 at mu = 0.5). Now each call's first Newton step finds no factorisation
    at its mu: nothing another call left. (The answers are compared too, at the solver's
    tolerance: bit for bit they may differ with the memory alignment of the arrays.)
    """
    from linecontact.lennard_jones import (
        _solver,
        lj_contact_for_load,
        lj_curve,
        lj_pull_off,
        lj_state,
    )

    iterate = _solver._iterate
    found: list[bool] = []  # at each Newton solve: a factorisation at its mu was there

    def spy(mu_, mesh, *args, **kwargs):
        found.append(mu_ in mesh.lu)
        return iterate(mu_, mesh, *args, **kwargs)

    monkeypatch.setattr(_solver, "_iterate", spy)

    def first_finds(call) -> tuple[bool, object]:
        found.clear()
        out = call()
        assert found  # the call solved
        return found[0], out

    def calls():
        got = [first_finds(lambda: lj_state(0.9 if mu < 1 else 1.2, mu))]
        got.append(first_finds(lambda: lj_contact_for_load(0.2, mu)))
        got.append(first_finds(lambda: lj_pull_off(mu)))
        assert not any(f for f, _ in got)  # each began with nothing carried over
        s, c, p = (out for _, out in got)
        return [s.F, s.half_width, c.half_width, c.central_gap_over_z0, p.F_pulloff]

    before = calls()
    lj_curve(mu)  # states and factorisations at this mu, then neighbours of those asked
    lj_contact_for_load(1.0, mu)
    lj_state(1.3, mu)
    after = calls()
    assert after == pytest.approx(before, rel=1e-9)
