"""Fuzz the public API and the command line over the whole validated domain.

The promise (README, "Validated domain"): inside :data:`linecontact.domain.DOMAIN` every
function returns finite, self-consistent numbers or a documented error
(:class:`~linecontact.NoEquilibriumError`, :class:`~linecontact.ConvergenceError`, or a
``ValueError`` for a joint limit such as ``kappa <= 1e12`` or a contact wider than
``a/R = 10``); outside it, a ``ValueError`` names the parameter. Never another exception, a
``RuntimeWarning`` (pytest turns them into errors, ``pyproject.toml``) or NaN where a number
is due.

The draws are derandomized (the same examples on every machine and every run) and bounded;
``LINECONTACT_FUZZ_EXAMPLES=2000 pytest tests/test_fuzz.py`` runs a longer campaign.
"""

from __future__ import annotations

import io
import math
import os
import re
import warnings
from contextlib import redirect_stderr, redirect_stdout

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import linecontact as lc
from linecontact import ConvergenceError, NoEquilibriumError
from linecontact.cli import main
from linecontact.closed_forms import KAPPA_MAX
from linecontact.domain import DOMAIN

EXAMPLES = int(os.environ.get("LINECONTACT_FUZZ_EXAMPLES", "40"))
FUZZ = settings(
    derandomize=True,
    max_examples=EXAMPLES,
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much],
)
CHEAP = settings(FUZZ, max_examples=3 * EXAMPLES)  # the closed forms cost microseconds


# --------------------------------------------------------------------------------------------
# draws


def _log_uniform(lo: float, hi: float) -> st.SearchStrategy[float]:
    """Log-uniform on [lo, hi] (lo > 0), the ends included."""
    a, b = math.log10(lo), math.log10(hi)
    body = st.floats(a, b).map(lambda e: min(max(10.0**e, lo), hi))
    return st.one_of(st.sampled_from([lo, hi]), body, body, body)


def inside(key: str) -> st.SearchStrategy[float]:
    """Values inside the domain of ``key``: log-uniform over every decade, and its ends."""
    lo, lo_inc, hi, hi_inc = DOMAIN[key]
    lo_v = lo if lo_inc else math.nextafter(lo, math.inf)
    hi_v = hi if hi_inc else math.nextafter(hi, -math.inf)
    if lo > 0:
        return _log_uniform(lo_v, hi_v)
    tiny = 1e-300
    pos = _log_uniform(tiny, hi_v)
    if lo == 0:
        return st.one_of(st.just(0.0), pos) if lo_inc else pos
    neg = _log_uniform(tiny, -lo_v).map(lambda v: -v)
    return st.one_of(st.just(0.0), pos, neg)


def outside(key: str) -> st.SearchStrategy[float]:
    """Values outside the domain of ``key``: just beyond each end, far beyond, nan and inf."""
    lo, lo_inc, hi, hi_inc = DOMAIN[key]
    out = [math.nan, math.inf, -math.inf]
    below = math.nextafter(lo, -math.inf) if lo_inc else lo
    above = math.nextafter(hi, math.inf) if hi_inc else hi
    out += [below, above, hi * 10, -1e300, 1e300]
    if lo > 0:
        out += [lo / 10, 0.0, -lo]
    return st.sampled_from([v for v in out if not _in(key, v)])


def _in(key: str, v: float) -> bool:
    lo, lo_inc, hi, hi_inc = DOMAIN[key]
    return (v >= lo if lo_inc else v > lo) and (v <= hi if hi_inc else v < hi)


def _kappa_ok(rho: float, s: float) -> bool:
    return (4 / math.pi) * s * math.sqrt(2 * rho) <= KAPPA_MAX


def _finite(*values) -> bool:
    return all(np.all(np.isfinite(np.asarray(v, float))) for v in values)


def _allowed(e: Exception) -> bool:
    """A documented refusal inside the box: a joint limit or a physical state that is not."""
    if isinstance(e, NoEquilibriumError | ConvergenceError):
        return True
    msg = str(e)
    documented = ("kappa", "needs a contact of half-width", "the tip does not push the fibre")
    return isinstance(e, ValueError) and any(d in msg for d in documented)


def _quiet(fn, *args, **kwargs):
    """Call ``fn``; a documented refusal returns None, anything else propagates."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", lc.ModelValidityWarning)
        try:
            return fn(*args, **kwargs)
        except Exception as e:
            if _allowed(e):
                return None
            raise


# --------------------------------------------------------------------------------------------
# the closed forms and the materials


@CHEAP
@given(inside("a_over_R"), inside("R_over_h"), inside("sigma0_over_E"))
def test_reference_closed_forms_are_finite_inside(a, rho, s):
    # closed forms: no joint limit (kappa bounds only the solvers' brackets)
    k, lam = lc.kappa(rho, s), lc.maugis_parameter(rho, s)
    assert _finite(k, lam) and k >= 0 and lam >= 0
    H = lc.hertz_load(a, rho)
    assert _finite(H) and H > 0
    J = _quiet(lc.jkr_load, a, rho, s)
    assert J is not None and _finite(J) and J <= H
    Z = lc.zero_width_load(rho, s)
    assert _finite(Z) and Z <= 0 and (Z < 0) == (s > 0 and k > 0)


@CHEAP
@given(
    inside("E1"),
    st.floats(-0.999, 0.5),
    inside("E2"),
    st.floats(-0.999, 0.5),
    st.booleans(),
)
def test_materials_are_finite_inside(E1, nu1, E2, nu2, rigid):
    if rigid:
        E1 = math.inf
    E = _quiet(lc.composite_modulus, E1, nu1, E2, nu2)
    if E is None:
        return
    A, B = lc.compliance_constants(E1, nu1, E2, nu2)
    beta = lc.dundurs_beta(E1, nu1, E2, nu2)
    assert _finite(E, A, B, beta) and E > 0 and A > 0
    # |beta| <= (1 - 2 nu)/(2 (1 - nu)) of the softer body's limit: 1/2 for nu >= 0, 3/4 at -1
    bound = max((1 - 2 * nu) / (2 * (1 - nu)) for nu in (nu1, nu2))
    assert abs(beta) <= bound * (1 + 1e-15)
    # 1/E = (1 - nu1^2)/E1 + (1 - nu2^2)/E2, the composite modulus it is
    inv = (1 - nu1 * nu1) / E1 + (1 - nu2 * nu2) / E2
    if np.isfinite(inv) and inv > 0 and np.isfinite(1 / inv):
        assert E == pytest.approx(1 / inv, rel=1e-12)


@CHEAP
@given(inside("work_of_adhesion"), inside("equilibrium_spacing"))
def test_adhesion_from_work_inside(w, z0):
    out = _quiet(lc.adhesion_from_work, w, z0)
    if out is None:
        return
    s0, h = out
    assert _finite(s0, h) and s0 > 0 and h > 0
    assert s0 * h == pytest.approx(w, rel=1e-12)


# --------------------------------------------------------------------------------------------
# the normal problem


@FUZZ
@given(inside("a_over_R"), inside("R_over_h"), inside("sigma0_over_E"))
def test_normal_contact_inside(a, rho, s):
    r = _quiet(lc.normal_contact, a, rho, s)
    if r is None:
        assert not _kappa_ok(rho, s)
        return
    assert _finite(r.a_over_R, r.c_over_R, r.F_over_Eh)
    assert r.c_over_R >= r.a_over_R
    assert r.F_over_Eh <= lc.hertz_load(a, rho) * (1 + 1e-12)


@FUZZ
@given(inside("a_over_R"), inside("R_over_h"), inside("sigma0_over_E"))
def test_normal_collocation_agrees_or_says_it_did_not_converge(a, rho, s):
    if not _kappa_ok(rho, s):
        return
    c = _quiet(lc.normal_contact, a, rho, s, method="collocation")
    if c is None:  # a ConvergenceError, documented
        return
    assert c.converged
    f = lc.normal_contact(a, rho, s)
    assert c.c_over_R == pytest.approx(f.c_over_R, rel=1e-8)


@FUZZ
@given(inside("F_over_Eh"), inside("R_over_h"), inside("sigma0_over_E"))
def test_contact_for_load_round_trips(F, rho, s):
    r = _quiet(lc.contact_for_load, F, rho, s)
    if r is None:
        if _kappa_ok(rho, s):
            po = lc.pull_off(rho, s)
            F10 = _quiet(lc.normal_contact, 10.0, rho, s).F_over_Eh
            # refused: below the pull-off force, or wider than a/R = 10
            below = F < po.F_minimum_over_Eh * (1 - 1e-12) or (s == 0 and F <= 0)
            assert below or F > F10 * (1 - 1e-12) or po.a_over_R_at_minimum > 10
        return
    assert r.F_over_Eh == F and _finite(r.a_over_R, r.c_over_R) and r.stable
    _assert_load_at_width(r.a_over_R, F, rho, s)


def _assert_load_at_width(a, F, rho, s):
    """The load at half-width ``a`` is F (to 1e-9 of the load's scale), by the forward map."""
    F0 = lc.zero_width_load(rho, s)
    a_min = DOMAIN["a_over_R"][0]
    if a < a_min:  # below the forward domain: within a Hertz load at a_min of zero width
        assert abs(F - F0) <= abs(F0) * 1e-9 + lc.hertz_load(a_min, rho)
        return
    scale = abs(F) + lc.hertz_load(a, rho) + abs(F0)
    back = lc.normal_contact(a, rho, s).F_over_Eh
    assert abs(back - F) <= 1e-9 * scale


@FUZZ
@given(inside("F_over_Eh"), inside("R_over_h"), inside("sigma0_over_E"))
def test_unstable_branch_reports_or_round_trips(F, rho, s):
    r = _quiet(lc.contact_for_load, F, rho, s, branch="unstable", on_failure="report")
    if r is None:
        return
    if r.state != "contact":
        assert r.state == "no-equilibrium" and np.isnan(r.a_over_R)
        return
    assert not r.stable and _finite(r.a_over_R, r.c_over_R)
    _assert_load_at_width(r.a_over_R, F, rho, s)


@FUZZ
@given(inside("R_over_h"), inside("sigma0_over_E"))
def test_pull_off_is_the_load_minimum(rho, s):
    p = _quiet(lc.pull_off, rho, s)
    if p is None:
        assert not _kappa_ok(rho, s)
        return
    assert _finite(p.F_pulloff_over_Eh, p.a_over_R_at_pulloff, p.F_zero_width_over_Eh)
    assert p.F_pulloff_over_Eh <= p.F_zero_width_over_Eh
    assert p.mechanism in ("snap-off", "zero-width")
    a0 = p.a_over_R_at_minimum
    if a0 > 0:
        near = np.clip(a0 * np.array([0.5, 0.9, 1.1, 2.0]), 1e-150, 10.0)
        F = lc.normal_contact(near, rho, s).F_over_Eh
        assert np.all(F >= p.F_minimum_over_Eh - 1e-12 * abs(p.F_minimum_over_Eh))


@FUZZ
@given(inside("F_over_Eh"), inside("R_over_h"), inside("sigma0_over_E"))
def test_equilibria_carry_the_load(F, rho, s):
    eqs = _quiet(lc.equilibria, F, rho, s)
    if eqs is None:
        return
    for e in eqs:
        assert e.F_over_Eh == pytest.approx(F, rel=1e-9, abs=1e-300)
        assert e.branch in ("contact", "non-contact")
        assert _finite(e.a_over_R, e.c_over_R, e.central_gap_over_h)
    if eqs and s == 0:
        assert len(eqs) == 1


@FUZZ
@given(inside("central_gap_over_h"), inside("R_over_h"), inside("sigma0_over_E"))
def test_non_contact_inside(g, rho, s):
    r = _quiet(lc.non_contact, g, rho, s)
    if r is None:
        return
    assert _finite(r.F_over_Eh, r.c_over_R)
    assert r.F_over_Eh <= 0


@settings(FUZZ, max_examples=max(EXAMPLES // 4, 5))
@given(inside("R_over_h"), inside("sigma0_over_E"), st.one_of(st.none(), inside("a_max_over_R")))
def test_load_curve_inside(rho, s, a_max):
    c = _quiet(lc.load_curve, rho, s, a_max_over_R=a_max, num=8, num_noncontact=4)
    if c is None:
        return
    assert _finite(c.a_over_R, c.F_over_Eh)


# --------------------------------------------------------------------------------------------
# steady sliding


def _sliding_inside():
    return (
        inside("sliding_a_over_R"),
        inside("R_over_h2"),
        inside("h1_over_h2"),
        inside("sigma0_over_E"),
    )


@FUZZ
@given(*_sliding_inside(), st.one_of(st.none(), inside("friction_tau0_over_E")))
def test_sliding_contact_closed_form_inside(a, rho, r, s, tau):
    c = _quiet(lc.sliding_contact, a, rho, r, s, tau0_over_E=tau, method="closed-form")
    if c is None:
        return
    assert _finite(c.c1_over_R, c.c2_over_R, c.e_over_R, c.F_over_Eh2, c.M_over_Eh2R)
    assert c.c1_over_R >= a * (1 - 1e-12) and c.c2_over_R >= a * (1 - 1e-12)


@settings(FUZZ, max_examples=max(EXAMPLES // 2, 5))
@given(*_sliding_inside())
def test_sliding_collocation_agrees_or_says_it_did_not_converge(a, rho, r, s):
    c = _quiet(lc.sliding_contact, a, rho, r, s)
    if c is None:
        return
    f = _quiet(lc.sliding_contact, a, rho, r, s, method="closed-form")
    if f is None:
        return
    assert c.converged and f.converged
    assert c.c1_over_R == pytest.approx(f.c1_over_R, rel=1e-7)
    assert c.c2_over_R == pytest.approx(f.c2_over_R, rel=1e-7)


@FUZZ
@given(inside("F_over_Eh2"), inside("R_over_h2"), inside("h1_over_h2"), inside("sigma0_over_E"))
def test_sliding_contact_for_load_round_trips(F, rho, r, s):
    c = _quiet(lc.sliding_contact_for_load, F, rho, r, s, method="closed-form")
    if c is None:
        return
    assert c.F_over_Eh2 == pytest.approx(F, rel=1e-9, abs=1e-300) or _finite(c.F_over_Eh2)
    back = lc.sliding_contact(c.a_over_R, rho, r, s, method="closed-form").F_over_Eh2
    scale = abs(F) + lc.hertz_load(c.a_over_R, rho)
    assert abs(back - F) <= 1e-8 * scale


@settings(FUZZ, max_examples=max(EXAMPLES // 2, 5))
@given(inside("R_over_h2"), inside("h1_over_h2"), inside("sigma0_over_E"))
def test_sliding_pull_off_inside(rho, r, s):
    p = _quiet(lc.sliding_pull_off, rho, r, s)
    if p is None:
        return
    assert _finite(p.F_pulloff_over_Eh2, p.a_over_R_at_pulloff)
    assert p.F_pulloff_over_Eh2 <= 0


# --------------------------------------------------------------------------------------------
# tangential loading


@FUZZ
@given(inside("tau0_over_E"), st.floats(0.0, 1.0, exclude_max=True), inside("T_over_Ea"))
def test_sliding_initiation_inside(t0, d, T):
    # full slip (d = 0, T >= 2 tau0) is reported here; by default it raises
    r = lc.sliding_initiation(t0, d, on_failure="report")
    assert _finite(r.T_over_Ea) and 0 <= r.T_over_Ea <= 2 * t0 * (1 + 1e-15)
    g = lc.sliding_initiation(t0, T_over_Ea=T, on_failure="report")
    if T >= 2 * t0:
        assert g.state == "sliding"
        with pytest.raises(NoEquilibriumError, match="full-slip load"):
            lc.sliding_initiation(t0, T_over_Ea=T)
    else:
        # T/(2 tau0) ~ sqrt(2 (1 - d)): d/a is 1.0 below T ~ 2e-8 of full slip, and the
        # forward map from the d/a returned is good to T ~ 2 tau0 sqrt(2 ulp(1))
        assert g.state == ("stick" if T == 0 else "stick-slip")
        assert _finite(g.d_over_a) and 0 <= g.d_over_a <= 1
        assert g.T_over_Ea == T
        back = lc.sliding_initiation(t0, min(g.d_over_a, np.nextafter(1.0, 0))).T_over_Ea
        assert back == pytest.approx(T, rel=1e-9, abs=2 * t0 * math.sqrt(4 * 2.3e-16))


@FUZZ
@given(
    inside("tau0_over_E"),
    st.floats(-1.0, 1.0, exclude_min=True, exclude_max=True),
    inside("T_over_Ea"),
)
def test_steady_rolling_inside(t0, d, T):
    r = lc.steady_rolling(t0, d)
    assert _finite(r.T_over_Ea, r.creep_over_V) and r.creep_over_V <= 0
    assert r.T_over_Ea <= 2 * t0 * (1 + 1e-15)
    g = lc.steady_rolling(t0, T_over_Ea=T, on_failure="report")
    if T >= 2 * t0:
        assert g.state == "sliding" and np.isnan(g.creep_over_V)
    else:
        assert _finite(g.creep_over_V) and g.creep_over_V <= 0 and g.T_over_Ea == T


@settings(FUZZ, max_examples=max(EXAMPLES // 2, 5))
@given(inside("tau0_over_E"), st.floats(-1.0, 1.0, exclude_min=True, exclude_max=True))
def test_rolling_collocation_agrees_or_says_it_did_not_converge(t0, d):
    c = _quiet(lc.steady_rolling, t0, d, method="collocation")
    if c is None:
        return
    f = lc.steady_rolling(t0, d)
    assert c.converged
    assert c.creep_over_V == pytest.approx(f.creep_over_V, rel=1e-10, abs=1e-300)


@FUZZ
@given(inside("mu"), inside("a_over_R"), inside("T_over_muF"), st.booleans())
def test_coulomb_problems_inside(mu, a, T, rolling):
    fn = lc.steady_rolling_coulomb if rolling else lc.sliding_initiation_coulomb
    r = _quiet(fn, mu, a, T_over_muF=T, on_failure="report")
    assert r is not None
    if T >= 1:
        assert r.state == "sliding"
        return
    assert r.T_over_muF == T and _finite(r.d_over_a, r.T_over_Ea)
    if rolling:
        assert _finite(r.creep_over_V) and r.creep_over_V <= 0


@FUZZ
@given(
    inside("R_over_h2"),
    inside("h1_over_h2").filter(lambda r: r >= 1),
    inside("sigma0_over_E"),
    inside("tau0_over_E"),
    inside("F_over_Eh2"),
    st.floats(0.0, 2.0),
)
def test_push_inside(rho, r, s, tau, F, H):
    p = _quiet(lc.push, rho, r, s, tau, F, H, 0.5 * tau)
    if p is None:
        return
    assert _finite(p.a_slide_over_R, p.Q_slide_over_Eh2, p.H_critical_over_R)
    assert p.converged and p.first_motion in ("roll", "slide", "roll+slide")
    assert p.state in ("rest", "roll", "slide", "roll+slide")
    dw = s * (r - 1)
    assert p.hysteresis_over_Eh2 == pytest.approx(dw, rel=1e-15, abs=0)
    if H > 0 and dw / H < 1e300:
        assert p.Q_roll_over_Eh2 * H == pytest.approx(dw, rel=1e-9, abs=1e-300)
    assert (p.first_motion == "slide") == (not p.Q_roll_over_Eh2 < p.Q_slide_over_Eh2)


@FUZZ
@given(
    inside("R_over_h2"),
    inside("h1_over_h2").filter(lambda r: r >= 1),
    inside("sigma0_over_E"),
    inside("tau0_over_E"),
    inside("F_over_Eh2"),
    st.floats(0.01, 1.99),
    st.floats(0.0, 1.0),
)
def test_push_with_a_tip_inside(rho, r, s, tau, F, H, mu):
    p = _quiet(lc.push, rho, r, s, tau, F, H, tip_friction=mu)
    if p is None:
        return
    assert p.converged
    assert p.first_motion in ("roll", "slide", "roll+slide", "lift-off")
    if p.first_motion != "lift-off":
        assert _finite(p.H_arm_over_R) and min(p.Q_roll_over_Eh2, p.Q_slide_over_Eh2) < np.inf


# --------------------------------------------------------------------------------------------
# the SI layer


@FUZZ
@given(
    _log_uniform(1e-10, 1e-3),
    _log_uniform(1e3, 2e12),
    _log_uniform(1e-3, 1e11),
    _log_uniform(1e-11, 1e-8),
    st.floats(-2.0, 3.0),
)
def test_si_cylinder_inside(R, E, s0, h, f):
    if not (_in("R_over_h", R / h) and _in("sigma0_over_E", s0 / E)):
        # said in SI terms, naming the SI inputs (not R_over_h or sigma0_over_E)
        with pytest.raises(ValueError, match="the domain of the solvers") as info:
            lc.Cylinder.from_modulus(R, E, cohesive_stress=s0, adhesion_range=h)
        assert "R_over_h" not in str(info.value) and "sigma0_over_E" not in str(info.value)
        return
    cyl = _quiet(lc.Cylinder.from_modulus, R, E, cohesive_stress=s0, adhesion_range=h)
    if cyl is None:
        assert not _kappa_ok(R / h, s0 / E)
        return
    p = cyl.pull_off()
    assert _finite(p.pull_off_force) and p.pull_off_force <= 0
    load = abs(p.pull_off_force) * f  # from beyond the pull-off force to three times it
    c = _quiet(cyl.contact, load=load)
    if c is None:
        return
    assert c.load == load and _finite(c.contact_half_width, c.adhesive_zone_half_width)


# --------------------------------------------------------------------------------------------
# outside the domain: a ValueError naming the parameter


def _inside_point():
    return dict(
        a_over_R=0.01,
        R_over_h=100.0,
        sigma0_over_E=0.01,
        F_over_Eh=1.0,
        central_gap_over_h=0.5,
        R_over_h2=100.0,
        h1_over_h2=2.0,
        sliding_a_over_R=0.01,
        F_over_Eh2=1.0,
        tau0_over_E=0.01,
        T_over_Ea=0.005,
        mu=0.3,
        T_over_muF=0.5,
        a_max_over_R=0.05,
        E1=1e11,
        E2=1e11,
        work_of_adhesion=0.1,
        equilibrium_spacing=3e-10,
        friction_tau0_over_E=0.001,
    )


def push_at_the_axis(*args):
    return lc.push(*args, 1.0)


# function, its arguments by domain key (positional), keyword arguments by domain key
CALLS = [
    (lc.hertz_load, ["a_over_R", "R_over_h"], {}),
    (lc.jkr_load, ["a_over_R", "R_over_h", "sigma0_over_E"], {}),
    (lc.zero_width_load, ["R_over_h", "sigma0_over_E"], {}),
    (lc.kappa, ["R_over_h", "sigma0_over_E"], {}),
    (lc.maugis_parameter, ["R_over_h", "sigma0_over_E"], {}),
    (lc.normal_contact, ["a_over_R", "R_over_h", "sigma0_over_E"], {}),
    (lc.contact_for_load, ["F_over_Eh", "R_over_h", "sigma0_over_E"], {}),
    (lc.equilibria, ["F_over_Eh", "R_over_h", "sigma0_over_E"], {}),
    (lc.non_contact, ["central_gap_over_h", "R_over_h", "sigma0_over_E"], {}),
    (lc.pull_off, ["R_over_h", "sigma0_over_E"], {}),
    (lc.load_curve, ["R_over_h", "sigma0_over_E"], {"a_max_over_R": "a_max_over_R"}),
    (
        lc.sliding_contact,
        ["sliding_a_over_R", "R_over_h2", "h1_over_h2", "sigma0_over_E"],
        {"tau0_over_E": "friction_tau0_over_E"},
    ),
    (
        lc.sliding_contact_for_load,
        ["F_over_Eh2", "R_over_h2", "h1_over_h2", "sigma0_over_E"],
        {},
    ),
    (lc.sliding_pull_off, ["R_over_h2", "h1_over_h2", "sigma0_over_E"], {}),
    (lc.sliding_initiation, ["tau0_over_E"], {"T_over_Ea": "T_over_Ea"}),
    (lc.steady_rolling, ["tau0_over_E"], {"T_over_Ea": "T_over_Ea"}),
    (lc.sliding_initiation_coulomb, ["mu", "a_over_R"], {"T_over_muF": "T_over_muF"}),
    (lc.steady_rolling_coulomb, ["mu", "a_over_R"], {"T_over_muF": "T_over_muF"}),
    (lc.adhesion_from_work, ["work_of_adhesion", "equilibrium_spacing"], {}),
    (
        push_at_the_axis,
        ["R_over_h2", "h1_over_h2", "sigma0_over_E", "tau0_over_E", "F_over_Eh2"],
        {},
    ),
]

#: the parameter's name where the function calls it something else than its domain key
NAMES = {
    "sliding_a_over_R": "a_over_R",
    "friction_tau0_over_E": "tau0_over_E",
}


@pytest.mark.parametrize(("fn", "pos", "kw"), CALLS, ids=[c[0].__name__ for c in CALLS])
@settings(FUZZ, max_examples=max(EXAMPLES // 2, 10))
@given(data=st.data())
def test_outside_the_domain_is_a_value_error_naming_the_parameter(fn, pos, kw, data):
    keys = pos + list(kw.values())
    key = data.draw(st.sampled_from(keys), label="parameter")
    bad = data.draw(outside(key), label="value")
    point = _inside_point()
    point[key] = bad
    args = [point[k] for k in pos]
    kwargs = {name: point[k] for name, k in kw.items()}
    name = NAMES.get(key, key)
    if fn is lc.load_curve:
        kwargs.update(num=5, num_noncontact=3)
    with pytest.raises(ValueError, match=rf"^{re.escape(name)} must be "):
        fn(*args, **kwargs)


# --------------------------------------------------------------------------------------------
# the command line: exit status 0, 1 or 2, never a traceback


FLAGS = {
    "normal": ["--R-over-h", "--sigma0-over-E", "--a-over-R", "--F-over-Eh", "--method"],
    "pulloff": ["--R-over-h", "--sigma0-over-E"],
    "curve": ["--R-over-h", "--sigma0-over-E", "--num", "--a-max-over-R"],
    "slide-init": ["--tau0-over-E", "--d-over-a", "--T-over-Ea", "--mu", "--friction"],
    "roll": ["--tau0-over-E", "--d-over-a", "--T-over-Ea", "--T-over-muF", "--a-over-R"],
    "slide": ["--R-over-h2", "--h1-over-h2", "--sigma0-over-E", "--a-over-R", "--F-over-Eh2"],
    "push": [
        "--R-over-h2",
        "--h1-over-h2",
        "--sigma0-over-E",
        "--tau0-over-E",
        "--H-over-R",
        "--F-over-Eh2",
        "--Q-over-Eh2",
    ],
}
SI_FLAGS = ["--radius", "--modulus", "--sigma0", "--h", "--load", "--a", "--tau0", "--h1"]
VALUES = st.one_of(
    st.sampled_from(["nan", "inf", "-inf", "0", "-1", "1e400", "abc", "", "0x10", "1_0"]),
    st.floats(allow_nan=False, allow_infinity=False).map(repr),
    st.floats(-12, 12).map(lambda e: f"{10**e:.6g}"),
)


@settings(FUZZ, max_examples=max(EXAMPLES * 2, 20))
@given(data=st.data())
def test_cli_random_argv_exits_0_1_or_2_without_traceback(data):
    cmd = data.draw(st.sampled_from(sorted(FLAGS)), label="command")
    flags = data.draw(
        st.lists(st.sampled_from(FLAGS[cmd] + SI_FLAGS), min_size=0, max_size=6),
        label="flags",
    )
    argv = [cmd]
    for f in flags:
        argv.append(f)
        argv += data.draw(st.lists(VALUES, min_size=0, max_size=2), label=f)
    if data.draw(st.booleans(), label="json"):
        argv.append("--json")
    out_buf, err_buf = io.StringIO(), io.StringIO()
    with warnings.catch_warnings(), redirect_stdout(out_buf), redirect_stderr(err_buf):
        warnings.simplefilter("ignore")
        try:
            code = main(argv)
        except SystemExit as e:  # argparse's own errors and --help
            code = e.code if isinstance(e.code, int) else 2
    err = err_buf.getvalue()
    assert code in (0, 1, 2), (argv, err)
    assert "Traceback" not in err and "internal error" not in err, (argv, err)
    if code == 2:
        lines = [ln for ln in err.splitlines() if ln.startswith("linecontact")]
        assert len(lines) == 1 and "error:" in lines[0], (argv, err)


# --------------------------------------------------------------------------------------------
# the Lennard-Jones law (each example solves a whole branch: a few examples per run)

LJ = settings(FUZZ, max_examples=max(EXAMPLES // 20, 2))


def _lj_mu() -> st.SearchStrategy[float]:
    return st.one_of(st.just(0.0), _log_uniform(1e-4, DOMAIN["lj_mu"][2]))


@LJ
@given(_lj_mu())
def test_lennard_jones_pull_off_inside(mu):
    from linecontact.closed_forms import lennard_jones_rigid_pull_off
    from linecontact.lennard_jones import MAUGIS_MATCH_SIGMA0, lj_pull_off

    p = lj_pull_off(mu)
    assert p.converged and _finite(p.F_pulloff, p.central_gap_at_pulloff, p.error_estimate)
    assert p.error_estimate < 1e-4 * abs(p.F_pulloff)
    # the rigid cylinder pulls hardest under the law; elasticity only lowers the pull-off
    assert lennard_jones_rigid_pull_off()[0] - 1e-9 <= p.F_pulloff < 0
    if mu > 0:  # the matched Dugdale step pulls harder (16 % in the rigid limit)
        R_over_h = 1e6
        s = mu * MAUGIS_MATCH_SIGMA0**1.5 / math.sqrt(R_over_h)
        md = lc.pull_off(R_over_h, s).F_pulloff_over_Eh / (
            s * math.sqrt(R_over_h / MAUGIS_MATCH_SIGMA0)
        )
        assert md < p.F_pulloff


@LJ
@given(_lj_mu(), st.floats(0.9, 8.0))
def test_lennard_jones_state_inside(mu, g0):
    from linecontact.lennard_jones import lj_state

    s = lj_state(g0, mu)
    assert s.converged and s.residual <= 1e-10
    assert _finite(s.F, s.error_estimate, s.half_width)
    assert s.error_estimate < 1e-4 * max(abs(s.F), 0.1)
