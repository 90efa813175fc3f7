"""The pushed fibre (``docs/push.md``): each result checked against a second, independent way.

- rolling resistance: the moment identity of the sliding solution (at every width, both
  solvers) against Kendall's energy balance ``Q H = R dw``;
- the contacts against the inverse solvers run with the other method (collocation);
- no hysteresis: no rolling resistance and the plain normal contact;
- the static peak: the transition family from rest to steady sliding rises monotonically;
- the tip reduction against the cross product of the free body;
- the states against the thresholds, the creep against the rolling collocation.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

import linecontact as lc
from linecontact import NoEquilibriumError

SEEDED = settings(derandomize=True, deadline=None, max_examples=30)
BASE = dict(R_over_h2=100.0, h1_over_h2=2.0, sigma0_over_E=0.01, tau0_over_E=1e-3, F_over_Eh2=0.0)


def _push(**kw):
    args = {**BASE, **kw}
    return lc.push(
        args["R_over_h2"],
        args["h1_over_h2"],
        args["sigma0_over_E"],
        args["tau0_over_E"],
        args["F_over_Eh2"],
        args.get("H_over_R", 1.0),
        args.get("Q_over_Eh2"),
    )


points = st.fixed_dictionaries(
    {
        "R_over_h2": st.floats(10.0, 1e4),
        "h1_over_h2": st.floats(1.0, 10.0),
        "sigma0_over_E": st.floats(1e-3, 0.1),
        "tau0_over_E": st.floats(1e-5, 1e-2),
        "load": st.floats(0.0, 3.0),  # from the sliding pull-off to well into compression
        "H_over_R": st.floats(0.0, 2.0),
    }
)


def _load(p):
    po = lc.sliding_pull_off(p["R_over_h2"], p["h1_over_h2"], p["sigma0_over_E"])
    F0 = po.F_pulloff_over_Eh2
    return F0 * (1 - p["load"]) + p["load"] * abs(F0)


# --------------------------------------------------------------------------------------------
# rolling: moment (the solver) against energy (Kendall)


@pytest.mark.parametrize("method", ["closed-form", "collocation"])
def test_the_sliding_contact_has_the_moment_R_dw_at_every_width(method):
    a = np.geomspace(1e-3, 0.3, 25)
    for r, s in ((2.0, 0.01), (5.0, 0.05), (1.2, 0.002)):
        c = lc.sliding_contact(a, 100.0, r, s, method=method)
        np.testing.assert_allclose(c.M_axis_over_Eh2R, s * (r - 1), rtol=1e-10)


@SEEDED
@given(points)
def test_rolling_resistance_is_kendalls_energy_balance(p):
    F = _load(p)
    r = lc.push(
        p["R_over_h2"], p["h1_over_h2"], p["sigma0_over_E"], p["tau0_over_E"], F, p["H_over_R"]
    )
    dw = p["sigma0_over_E"] * (p["h1_over_h2"] - 1)  # Q H = R dw: the push's work per turn
    if p["H_over_R"] == 0 or dw / p["H_over_R"] > 1e300:  # at the contact line: no moment
        assert r.Q_roll_over_Eh2 > 1e300
        return
    assert r.Q_roll_over_Eh2 * p["H_over_R"] == pytest.approx(dw, rel=1e-10, abs=1e-300)
    # and the force balance: the contact's shear plus the push carry the hysteresis force
    # (to the rounding of the two, which are huge at the contact line)
    Q, S = r.Q_roll_over_Eh2, r.S_roll_over_Eh2
    assert Q + S == pytest.approx(dw, rel=1e-10, abs=4e-16 * Q)


# --------------------------------------------------------------------------------------------
# the contacts, the resistances, the first motion


@SEEDED
@given(points)
def test_contacts_agree_with_the_other_method(p):
    F = _load(p)
    args = (p["R_over_h2"], p["h1_over_h2"], p["sigma0_over_E"], p["tau0_over_E"], F)
    r = lc.push(*args, p["H_over_R"])
    assert r.converged and r.residual_load < 1e-10
    s = lc.sliding_contact_for_load(F, *args[:3], method="collocation")
    assert r.a_slide_over_R == pytest.approx(s.a_over_R, rel=1e-9)
    rest = lc.contact_for_load(F, p["R_over_h2"], p["sigma0_over_E"], on_failure="report")
    if rest.state != "contact":  # no contact at rest carries a load between the pull-offs
        assert math.isnan(r.a_rest_over_R) and math.isnan(r.Q_onset_over_Eh2)
    elif r.a_rest_over_R >= 1e-20:  # (narrower: zero width to round-off)
        c = lc.normal_contact(
            r.a_rest_over_R, p["R_over_h2"], p["sigma0_over_E"], method="collocation"
        )
        assert c.F_over_Eh == pytest.approx(F, rel=1e-9, abs=1e-9 * abs(c.F_over_Eh) + 1e-12)
    # sliding resistance: friction on the steady contact and the hysteresis
    dw = p["sigma0_over_E"] * (p["h1_over_h2"] - 1)
    friction = 2 * s.a_over_R * p["R_over_h2"] * p["tau0_over_E"]
    assert r.Q_slide_over_Eh2 == pytest.approx(friction + dw, rel=1e-9)
    # the first motion is the lower resistance: rolling iff H > H*
    if r.first_motion == "slide":
        assert p["H_over_R"] <= r.H_critical_over_R * (1 + 1e-12)
    else:
        assert p["H_over_R"] >= r.H_critical_over_R * (1 - 1e-12)
    # below the axis rolling first means the contact holds the shear (the same inequality)
    if p["H_over_R"] < 1:
        assert r.first_motion != "roll+slide"


def test_without_hysteresis_any_push_rolls_it():
    r = _push(h1_over_h2=1.0, H_over_R=np.array([0.0, 0.01, 1.0, 2.0]))
    np.testing.assert_array_equal(r.Q_roll_over_Eh2, [np.inf, 0.0, 0.0, 0.0])
    np.testing.assert_array_equal(r.first_motion, ["slide", "roll", "roll", "roll"])
    assert np.all(r.hysteresis_over_Eh2 == 0) and np.all(r.H_critical_over_R == 0)
    # the steady contact is the plain normal contact
    n = lc.contact_for_load(0.0, 100.0, 0.01)
    np.testing.assert_allclose(r.a_slide_over_R, n.a_over_R, rtol=1e-10)
    np.testing.assert_allclose(r.a_rest_over_R, n.a_over_R, rtol=1e-10)


def test_paper_like_case_by_hand():
    r = _push(H_over_R=np.array([0.25, 1.0, 2.0]))
    # dw = 0.01 (2 - 1) = 0.01; Q_roll = 0.01 / H
    np.testing.assert_allclose(r.Q_roll_over_Eh2, [0.04, 0.01, 0.005], rtol=1e-12)
    np.testing.assert_allclose(r.S_roll_over_Eh2, [-0.03, 0.0, 0.005], rtol=1e-12, atol=1e-15)
    np.testing.assert_array_equal(r.first_motion, ["slide", "roll", "roll"])
    # the creep: braked below the axis (positive), none at it, driven above (negative)
    assert r.creep_over_V[0] > 0 or math.isnan(r.creep_over_V[0])
    assert r.creep_over_V[1] == 0 and r.creep_over_V[2] < 0


def test_creep_is_the_rolling_solution_at_the_contact_shear():
    r = _push(H_over_R=np.array([0.7, 1.3, 1.9]))
    for i in range(3):
        T = abs(r.S_roll_over_Eh2[i]) / (100.0 * r.a_slide_over_R[i])
        ref = lc.steady_rolling(1e-3, T_over_Ea=T, method="collocation")
        assert abs(r.creep_over_V[i]) == pytest.approx(abs(ref.creep_over_V), rel=1e-10)


def test_roll_and_slide_when_the_contact_cannot_hold_the_rolling_shear():
    # above the axis with a tiny friction stress: rolling needs a driving shear beyond 2 a tau0
    r = _push(tau0_over_E=1e-9, H_over_R=1.9)
    assert r.first_motion == "roll+slide" and math.isnan(r.creep_over_V)
    assert abs(r.S_roll_over_Eh2) >= r.friction_over_Eh2


# --------------------------------------------------------------------------------------------
# from rest to steady sliding: the static peak


@SEEDED
@given(points)
def test_the_resistance_rises_from_onset_to_steady_sliding(p):
    # the trailing edge stretches from h2 to h1: each state a steady sliding contact with the
    # trailing range h' in [h2, h1]; Q(h') = 2 a(h') tau0 + sigma0 (h' - h2) increases. The
    # fibre starts at rest: loads from 1% above the pull-off force of the contact at rest
    # (below it no rest state exists; at it the width is ill-conditioned)
    rho, s, tau = p["R_over_h2"], p["sigma0_over_E"], p["tau0_over_E"]
    F0 = lc.pull_off(rho, s).F_pulloff_over_Eh
    load = 0.01 + p["load"]
    F = F0 * (1 - load) + load * abs(F0) if F0 < 0 else 1e-3 + p["load"]
    ratios = np.geomspace(1.0, p["h1_over_h2"], 12)
    a = lc.sliding_contact_for_load(F, rho, ratios, s, method="closed-form").a_over_R
    Q = 2 * a * rho * tau + s * (ratios - 1)
    assert np.all(np.diff(Q) >= -1e-12 * Q[-1])
    r = lc.push(rho, p["h1_over_h2"], s, tau, F, p["H_over_R"])
    assert Q[-1] == pytest.approx(r.Q_slide_over_Eh2, rel=1e-9)
    assert Q[0] == pytest.approx(r.Q_onset_over_Eh2, rel=1e-9)
    assert r.Q_onset_over_Eh2 <= r.Q_slide_over_Eh2 * (1 + 1e-12)


# --------------------------------------------------------------------------------------------
# a push given: the state


def test_states_under_a_given_push():
    base = _push(H_over_R=0.5)  # Q_roll = 0.02, Q_slide = 0.0235
    Qr, Qs, Qo = base.Q_roll_over_Eh2, base.Q_slide_over_Eh2, base.Q_onset_over_Eh2
    Q = np.array([0.0, 0.5 * Qo, Qo * 1.01, Qr * 1.001, Qs * 1.001])
    r = _push(H_over_R=0.5, Q_over_Eh2=Q)
    np.testing.assert_array_equal(r.state, ["rest", "rest", "rest", "roll", "roll+slide"])
    init = lc.sliding_initiation(1e-3, T_over_Ea=0.5 * Qo / (100.0 * r.a_rest_over_R[1]))
    assert r.d_over_a_rest[0] == 1.0 and r.d_over_a_rest[1] == pytest.approx(init.d_over_a)
    assert r.d_over_a_rest[2] == 0.0  # slipped at the onset, held by the stretched edge
    assert np.all(np.isnan(r.d_over_a_rest[3:]))
    assert _push(H_over_R=0.1, Q_over_Eh2=Qs * 1.001).state == "slide"
    assert _push(H_over_R=0.5).state == ""


def test_scalar_and_vector_calls_agree():
    H = np.array([0.2, 0.9, 1.7])
    v = _push(H_over_R=H, Q_over_Eh2=0.015)
    for i, h in enumerate(H):
        one = _push(H_over_R=float(h), Q_over_Eh2=0.015)
        for k, val in one.to_dict().items():
            got = np.asarray(getattr(v, k))[i]
            if isinstance(val, str):
                assert got == val, k
            else:
                np.testing.assert_allclose(got, val, rtol=1e-15, err_msg=k)


# --------------------------------------------------------------------------------------------
# the tip


@SEEDED
@given(st.floats(0.01, 1.99), st.floats(0.0, 0.5))
def test_tip_reduction_is_the_free_body(H, mu):
    sin = H - 1.0
    cos = math.sqrt(H * (2.0 - H))
    point = np.array([-cos, sin])  # the tip's contact on the fibre's rear, axis at the origin
    normal_in = -point  # along the normal, through the axis
    velocity = np.array([sin, cos])  # of that surface point in forward rolling
    force = normal_in - mu * velocity  # P = 1; friction opposes the surface's motion
    # high on the fibre a rough tip's force points backwards or down (cos <= mu sin, e.g.
    # H = 1.9375, mu = 0.5): outside the domain, refused as documented
    assume(abs(force[0]) > 1e-9)  # not at the boundary itself, where round-off decides
    if force[0] < 0:
        with pytest.raises(ValueError, match=r"turns the tip's force backwards or vertical"):
            lc.tip_push(H, mu)
        return
    t = lc.tip_push(H, mu)
    assert t.Q_per_P == pytest.approx(force[0], abs=1e-14)
    assert t.dF_per_P == pytest.approx(-force[1], abs=1e-14)  # compressive positive
    # moment about the contact point (0, -1): the same as a push Q at height H_eff
    arm = point - np.array([0.0, -1.0])
    moment = arm[0] * force[1] - arm[1] * force[0]  # z-component; forward rolling negative
    assert -moment == pytest.approx(t.Q_per_P * t.H_effective_over_R, abs=1e-13)


def test_a_frictionless_tip_acts_at_the_axis():
    t = lc.tip_push(np.array([0.3, 1.0, 1.7]))
    np.testing.assert_allclose(t.H_effective_over_R, 1.0, rtol=1e-15)
    assert t.dF_per_P[0] < 0 < t.dF_per_P[2]  # below the axis it lifts, above it presses


# --------------------------------------------------------------------------------------------
# bad input


@pytest.mark.parametrize(
    ("kw", "message"),
    [
        ({"h1_over_h2": 0.5}, r"^h1_over_h2 must be in \[1, 1000\], got 0.5$"),
        ({"H_over_R": 2.5}, r"^H_over_R must be in \[0, 2\], got 2.5$"),
        ({"H_over_R": -0.1}, r"^H_over_R must be in \[0, 2\], got -0.1$"),
        ({"tau0_over_E": 0.0}, r"^tau0_over_E must be in \[1e-12, 1\], got 0.0$"),
        ({"sigma0_over_E": np.nan}, r"^sigma0_over_E must be a finite number"),
        ({"R_over_h2": -1.0}, r"^R_over_h2 must be in \[0.001, 1e\+12\], got -1.0$"),
        ({"Q_over_Eh2": -1.0}, r"^Q_over_Eh2 must be in \[0, 1e\+12\], got -1.0$"),
    ],
)
def test_bad_input_names_the_parameter(kw, message):
    with pytest.raises(ValueError, match=message):
        _push(**kw)


def test_a_load_below_the_sliding_pull_off_says_so():
    po = lc.sliding_pull_off(100.0, 2.0, 0.01).F_pulloff_over_Eh2
    with pytest.raises(NoEquilibriumError, match=r"pull-off force .* the cylinder has pulled off"):
        _push(F_over_Eh2=po * 1.01)


@pytest.mark.parametrize(
    ("args", "message"),
    [
        ((0.0,), r"^H_over_R must be in \(0, 2\), got 0.0$"),
        ((2.0,), r"^H_over_R must be in \(0, 2\), got 2.0$"),
        ((1.0, -0.1), r"^tip_friction must be in \[0, 10\], got -0.1$"),
        ((1.9, 5.0), r"turns the tip's force backwards"),
    ],
)
def test_tip_bad_input(args, message):
    with pytest.raises(ValueError, match=message):
        lc.tip_push(*args)


# --------------------------------------------------------------------------------------------
# a push from a tip


def test_a_frictionless_tip_rolls_the_fibre_at_the_axis_resistance_from_any_height():
    H = np.array([0.3, 1.0, 1.7])
    p = lc.push(100.0, 2.0, 0.01, 1e-3, 0.0, H, tip_friction=0.0)
    np.testing.assert_allclose(p.H_arm_over_R, 1.0, rtol=1e-15)
    np.testing.assert_allclose(p.Q_roll_over_Eh2, 0.01, rtol=1e-12)  # R dw / R
    # at the axis the tip adds no load: the horizontal push's numbers
    h = _push(H_over_R=1.0)
    assert p.Q_slide_over_Eh2[1] == pytest.approx(h.Q_slide_over_Eh2, rel=1e-14)


@pytest.mark.parametrize(("H", "mu"), [(0.4, 0.0), (1.6, 0.0), (1.6, 0.3), (0.5, 0.2)])
def test_the_tips_sliding_threshold_carries_the_load_the_tip_adds(H, mu):
    # independent: the steady contact at F + dF(Q_slide) resists exactly Q_slide
    F, rho, r, s, tau = 0.05, 100.0, 2.0, 0.01, 1e-3
    p = lc.push(rho, r, s, tau, F, H, tip_friction=mu)
    t = lc.tip_push(H, mu)
    load = F + t.dF_per_P / t.Q_per_P * p.Q_slide_over_Eh2
    a = lc.sliding_contact_for_load(load, rho, r, s, method="collocation").a_over_R
    assert p.Q_slide_over_Eh2 == pytest.approx(2 * a * rho * tau + s * (r - 1), rel=1e-12)
    assert p.a_slide_over_R == pytest.approx(a, rel=1e-12)
    assert p.Q_roll_over_Eh2 * t.H_effective_over_R == pytest.approx(s * (r - 1), rel=1e-12)


def test_a_tip_low_on_the_fibre_lifts_it_off_first():
    # frictionless at H = 0.05 R the tip pulls up 3 times as hard as it pushes: the load
    # reaches the pull-off force of the contact at rest at Q = (F - F_po)/3.04 = 0.0873,
    # below Q_roll = R dw / R = 0.09
    p = lc.push(100.0, 10.0, 0.01, 1e-3, 0.0, 0.05, [0.05, 0.088], tip_friction=0.0)
    F_po = lc.pull_off(100.0, 0.01).F_pulloff_over_Eh
    t = lc.tip_push(0.05)
    Q_lift = -F_po / (-t.dF_per_P / t.Q_per_P)
    assert 0.05 < Q_lift < 0.088 and Q_lift < p.Q_roll_over_Eh2[0]
    assert list(p.first_motion) == ["lift-off", "lift-off"]
    assert list(p.state) == ["rest", "lift-off"]


def test_loads_above_the_zero_width_load_skip_the_pull_off_search_and_agree():
    # push asks the sliding branch's pull-off search only where its load could lie below
    # the pull-off force (at or below the zero-width load, which bounds it; or with a tip);
    # elsewhere the bracket starts at zero width. The widths must be those of
    # sliding_contact_for_load, which searches every point, for interior minima (whose
    # lower end then differs) as for minima at zero width, and for loads on both sides.
    from linecontact.closed_forms import _kappa
    from linecontact.sliding.pulloff import _zero_width

    rng = np.random.default_rng(36)
    n = 3000
    rho = 10 ** rng.uniform(1, 4, n)
    r = 10 ** rng.uniform(0, 1, n)
    s = 10 ** rng.uniform(-3, -1, n)
    po = lc.sliding_pull_off(rho, r, s)
    X1, X2, _ = _zero_width(_kappa(rho, s), r)
    F_zero = -(np.pi / 4) * _kappa(rho, s) * (X1 + X2)
    np.testing.assert_allclose(F_zero, po.F_zero_width_over_Eh2, rtol=1e-14)
    depth = rng.uniform(0.0, 1.0, n)  # between the pull-off and the zero-width load ...
    F = np.where(
        rng.random(n) < 0.5,
        po.F_pulloff_over_Eh2 + depth * (F_zero - po.F_pulloff_over_Eh2) * 0.999 + 1e-12,
        F_zero + rng.uniform(1e-6, 3.0, n) * np.abs(F_zero),  # ... or above the latter
    )
    interior = po.mechanism == "snap-off"
    skipped = F > F_zero * (1 - 1e-9)
    assert (interior & skipped).sum() > 100 and (interior & ~skipped).sum() > 100
    p = lc.push(rho, r, s, 1e-3, F, 1.0)
    c = lc.sliding_contact_for_load(F, rho, r, s, method="closed-form")
    np.testing.assert_allclose(p.a_slide_over_R, c.a_over_R, rtol=1e-13)


def test_the_onset_under_a_lifting_tip_close_to_the_pull_off_at_rest_settles():
    # F lies 0.7 % above the pull-off force at rest and the tip lifts (dF/P < 0): the width
    # at rest is ill-conditioned in the load there, and the plain iteration of the onset
    # cycled at 3.8e-14 of it, so push raised ConvergenceError for a state it had found.
    # Independent: the onset carries the contact at rest at the load the tip leaves,
    # F + dF(Q_onset), by the normal solver in its own groups (range h2).
    rho, r, s = 11.761964175819415, 1.3267231952126142, 0.025804769969068223
    tau = 0.0039845549435044095
    F, H, mu = -0.23530981465212072, 0.8289336282929719, 0.058125025364371696
    p = lc.push(rho, r, s, tau, F, H, tip_friction=mu)
    t = lc.tip_push(H, mu)
    assert t.dF_per_P < 0 and F < 0.99 * float(lc.pull_off(rho, s).F_pulloff_over_Eh)
    load = F + t.dF_per_P / t.Q_per_P * p.Q_onset_over_Eh2
    a = lc.contact_for_load(load, rho, s).a_over_R
    assert p.a_rest_over_R == pytest.approx(a, rel=1e-12)
    assert p.Q_onset_over_Eh2 == pytest.approx(2 * a * rho * tau, rel=1e-12)
