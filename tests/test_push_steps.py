"""The steps of :func:`linecontact.push`, each alone against its contract.

``push`` checks its inputs once (``_checked``) and runs a pipeline of private steps on the
flat, checked arrays; each is tested here without the others (``docs/push.md`` for the
physics, ``tests/test_push.py`` for the whole).
"""

from __future__ import annotations

import ast
import importlib
import inspect

import numpy as np
import pytest

import linecontact as lc

# the module (``linecontact.push`` the attribute is the function)
P = importlib.import_module("linecontact.push")

RHO, R, S, TAU = 100.0, 2.0, 0.01, 1e-3


def _inputs(F=0.05, H=(0.25, 1.0, 1.6), Q=None, mu=None, rho=RHO, r=R, s=S, tau=TAU):
    return P._checked(rho, r, s, tau, F, np.asarray(H, float), Q, mu)


# --------------------------------------------------------------------------------------------
# the pipeline's shape


def _body_lines(fn) -> int:
    """Lines of a function without its docstring."""
    node = ast.parse(inspect.getsource(fn).lstrip()).body[0]
    assert isinstance(node, ast.FunctionDef)
    first = node.body[0]
    doc = isinstance(first, ast.Expr) and isinstance(first.value, ast.Constant)
    start = node.body[1].lineno if doc else first.lineno
    assert node.end_lineno is not None
    return (first.lineno - node.lineno) + (node.end_lineno - start + 1)  # signature + body


STEPS = [
    P.push,
    P._checked,
    P._slide_at,
    P._rest_at,
    P._steady_sliding_contact,
    P._tip_sliding_threshold,
    P._contact_at_rest,
    P._rolling_resistance,
    P._rolling_contact,
    P._lift_off,
    P._first_motion,
    P._creep,
    P._state_under_push,
    P._raise_unconverged,
    P._tip_forces,
]


@pytest.mark.parametrize("fn", STEPS, ids=lambda f: f.__name__)
def test_each_step_is_under_60_lines(fn):
    assert _body_lines(fn) < 60


def test_the_inputs_are_checked_once_then_flat():
    p = _inputs(H=[[0.5, 1.0]], mu=0.2)
    assert p.shape == (1, 2) and not p.scalar and p.tip
    assert all(v.shape == (2,) for v in (p.rho, p.r, p.s, p.tau, p.F, p.H, p.Q, p.mu))
    t = lc.tip_push([0.5, 1.0], 0.2)
    np.testing.assert_array_equal(p.arm, t.H_effective_over_R)
    np.testing.assert_array_equal(p.k, t.dF_per_P / t.Q_per_P)
    np.testing.assert_array_equal(p.dw, S * (R - 1.0))
    assert np.isnan(p.Q).all()
    q = P._checked(RHO, R, S, TAU, 0.0, 0.5, None, None)
    assert q.scalar and q.shape == () and not q.tip and q.k.tolist() == [0.0]
    assert q.arm.tolist() == [0.5]


def test_a_tip_is_checked_on_the_open_range_of_heights():
    with pytest.raises(ValueError, match=r"^H_over_R must be in \(0, 2\), got 0.0$"):
        P._checked(RHO, R, S, TAU, 0.0, 0.0, None, 0.1)
    with pytest.raises(ValueError, match=r"turns the tip's force backwards"):
        P._checked(RHO, R, S, TAU, 0.0, 1.9, None, 5.0)


# --------------------------------------------------------------------------------------------
# each step alone


@pytest.mark.parametrize("H", [1e-3, 0.25, 1.0, 1.6, 2.0])
@pytest.mark.parametrize("dw", [0.0, 1e-4, 0.01, 3.0])
def test_rolling_resistance_is_kendalls_energy_balance(H, dw):
    # rolling by d(phi) opens and closes R d(phi) of interface (costs dw R d(phi)) while the
    # push at height H moves H d(phi): Q H = R dw; and the forces: Q + S = dw
    Q, S_ = P._rolling_resistance(np.array([dw]), np.array([H]))
    assert Q[0] * H == pytest.approx(dw, rel=1e-15, abs=0)
    assert Q[0] + S_[0] == pytest.approx(dw, rel=1e-14, abs=4e-16 * Q[0])
    assert np.sign(S_[0]) == (np.sign(H - 1.0) if dw > 0 else 0.0)


def test_rolling_resistance_at_the_contact_line_is_infinite():
    Q, S_ = P._rolling_resistance(np.array([0.01, 0.0, 0.01]), np.array([0.0, 0.0, 1e-320]))
    assert Q.tolist() == [np.inf, np.inf, np.inf] and S_.tolist() == [-np.inf] * 3


def test_the_steady_contact_is_the_sliding_inverse_at_the_load():
    p = _inputs(F=[0.05, 1.0, 0.05])
    c = P._steady_sliding_contact(p)
    ref = lc.sliding_contact_for_load(p.F, RHO, R, S)
    _close(c.a, ref.a_over_R)
    np.testing.assert_allclose(c.F, p.F, rtol=1e-12)
    np.testing.assert_array_equal(c.Q, 2 * c.a * RHO * TAU + S * (R - 1))
    assert c.converged.all()


@pytest.mark.parametrize(("H", "mu"), [(0.4, 0.0), (1.6, 0.0), (1.6, 0.3), (0.5, 0.2)])
def test_the_tips_sliding_threshold_is_a_fixed_point(H, mu):
    p = _inputs(H=[H], mu=mu)
    c = P._steady_sliding_contact(p)
    load = p.F + p.k * c.Q
    a = lc.sliding_contact_for_load(load, RHO, R, S).a_over_R
    np.testing.assert_allclose(c.a, a, rtol=1e-14)
    np.testing.assert_allclose(c.Q, 2 * a * RHO * TAU + p.dw, rtol=1e-14)
    np.testing.assert_allclose(c.F, p.F, rtol=1e-12, atol=1e-12)  # the load given
    assert c.converged.all()


def test_a_tip_that_lifts_the_fibre_leaves_the_fixed_point_as_nan():
    # the tip low on the fibre lifts it before it slides; the other point slides. This
    # vector raised "F_over_Eh2 must be a finite number ..., got nan" before the steps
    # (the lifted point's NaN threshold was fed back as a load)
    p = _inputs(F=-2.0, H=[0.09, 1.5], mu=0.1, rho=75.0, r=8.0, s=0.05)
    c = P._steady_sliding_contact(p)
    assert np.isnan(c.a[0]) and np.isnan(c.Q[0]) and c.converged.all()
    assert np.isfinite(c.a[1]) and c.F[0] == -2.0
    r = lc.push(75.0, 8.0, 0.05, 1e-3, -2.0, [0.09, 1.5], tip_friction=0.1)
    assert list(r.first_motion) == ["lift-off", "slide"]


def test_the_contact_at_rest_carries_the_load_and_the_onset_push():
    p = _inputs(F=[0.05, 1.0], H=[0.5, 0.5], mu=0.2)
    c = P._contact_at_rest(p)
    ref = lc.contact_for_load(p.F + p.k * c.Q, RHO, S).a_over_R
    np.testing.assert_allclose(c.a, ref, rtol=1e-14)
    np.testing.assert_array_equal(c.Q, 2 * c.a * RHO * TAU)
    assert c.converged.all() and np.isnan(c.F).all()
    h = P._contact_at_rest(_inputs(F=[0.05, 1.0], H=[0.5, 0.5]))  # horizontal: at F
    _close(h.a, lc.contact_for_load([0.05, 1.0], RHO, S).a_over_R)


def test_the_rolling_contact_is_the_steady_one_without_a_tip():
    p = _inputs()
    a = np.array([0.1, 0.2, 0.3])
    np.testing.assert_array_equal(P._rolling_contact(p, a, np.ones(3)), a)
    t = _inputs(H=[0.5], mu=0.1)
    Q = np.array([0.02])
    ref = lc.sliding_contact_for_load(t.F + t.k * Q, RHO, R, S).a_over_R
    _close(P._rolling_contact(t, np.array([0.1]), Q), ref)


def test_lift_off_where_the_tip_pulls_the_load_to_the_pull_off_at_rest():
    p = _inputs(F=0.0, H=[0.05, 1.5], mu=0.0)
    Q = P._lift_off(p)
    F_po = lc.pull_off(RHO, S).F_pulloff_over_Eh
    assert Q[0] == pytest.approx((0.0 - F_po) / -p.k[0], rel=1e-15) and Q[1] == np.inf
    assert P._lift_off(_inputs()).tolist() == [np.inf] * 3


def test_the_first_motion_is_the_lower_resistance():
    p = _inputs(H=[1.0] * 5)
    inf = np.inf
    Q_slide = np.array([1.0, 1.0, 1.0, np.nan, 1.0])
    Q_roll = np.array([0.5, 2.0, 0.5, 0.5, 0.5])
    S_roll = np.array([0.0, 0.0, 1.0, 0.0, 0.0])  # 2 a tau0 rho = 0.02 holds 0, not 1
    a_roll = np.full(5, 0.1)
    Q_lift = np.array([inf, inf, inf, inf, 0.1])
    first, holds, Qr, Qs = P._first_motion(p, Q_slide, Q_roll, S_roll, a_roll, Q_lift)
    assert list(first) == ["roll", "slide", "roll+slide", "roll", "lift-off"]
    assert holds.tolist() == [True, True, False, True, True]
    assert Qs[3] == inf and Qr.tolist() == Q_roll.tolist()
    lifted = P._first_motion(p, Q_slide, Q_roll, S_roll, np.full(5, np.nan), Q_lift)
    assert lifted[2].tolist() == [inf] * 5  # a contact lifted while rolling: never rolls


def test_the_creep_is_steady_rollings_with_the_sign_of_the_shear():
    p = _inputs(H=[0.5, 1.0, 1.5])
    S_roll = np.array([-0.01, 0.0, 0.01])
    a = np.full(3, 0.2)
    creep = P._creep(p, S_roll, a, np.array([True, True, True]))
    ref = lc.steady_rolling(TAU, T_over_Ea=0.01 / (RHO * 0.2)).creep_over_V
    _close(creep, [-ref, 0.0, ref])
    assert np.isnan(P._creep(p, S_roll, a, np.zeros(3, bool))).all()


def test_the_state_under_a_push_and_the_stick_zone_at_rest():
    p = _inputs(H=[1.0] * 5, Q=[0.0, 0.01, 1.5, 2.5, 1.5])
    Q_roll, Q_slide = np.array([1.0, 1.0, 1.0, 1.0, 1.0]), np.full(5, 2.0)
    holds, a_rest = np.array([True] * 4 + [False]), np.full(5, 0.1)
    Q_lift = np.full(5, np.inf)
    state, d = P._state_under_push(p, Q_roll, Q_slide, Q_lift, holds, a_rest)
    assert list(state) == ["rest", "rest", "roll", "roll+slide", "roll+slide"]
    init = lc.sliding_initiation(TAU, T_over_Ea=0.01 / (RHO * 0.1))
    assert d[0] == 1.0 and d[1] == pytest.approx(init.d_over_a, rel=1e-15)
    assert np.isnan(d[2:]).all()
    Q_lift[1] = 0.01
    assert P._state_under_push(p, Q_roll, Q_slide, Q_lift, holds, a_rest)[0][1] == "lift-off"
    none = P._state_under_push(
        _inputs(), Q_roll[:3], Q_slide[:3], Q_lift[:3], holds[:3], a_rest[:3]
    )
    assert list(none[0]) == [""] * 3 and np.isnan(none[1]).all()  # without a push


def test_an_unconverged_point_is_named():
    p = _inputs(H=[0.25, 1.0, 1.6])
    P._raise_unconverged(p, np.ones(3, bool), False)
    with pytest.raises(lc.ConvergenceError, match=r"push did not converge at .*H_over_R=1.0"):
        P._raise_unconverged(p, np.array([True, False, True]), False)


# --------------------------------------------------------------------------------------------
# public functions check, private kernels compute (issue 21): the pull-off searches run once


def test_the_pulloff_searches_run_once_per_call(monkeypatch):
    SI = importlib.import_module("linecontact.sliding.inverse")
    NI = importlib.import_module("linecontact.normal.inverse")
    calls = []
    search = SI._pulloff_flat
    monkeypatch.setattr(SI, "_pulloff_flat", lambda *a: calls.append(1) or search(*a))
    rest = NI._pulloff_arrays
    monkeypatch.setattr(NI, "_pulloff_arrays", lambda *a: calls.append(2) or rest(*a))
    H = [0.3, 0.6, 1.2, 1.7]
    p = lc.push(RHO, R, S, TAU, 0.05, H, 2e-3, tip_friction=0.2)  # fixed points iterate
    assert calls == [1]  # the sliding search, at _branch_ends; the normal one outside NI
    assert np.all(p.converged)
    calls.clear()
    lc.push(RHO, R, S, TAU, 0.05, 0.6, 2e-3, tip_friction=0.2)  # the scalar path
    assert calls == [1]


def _close(got, want):
    """To rounding, not bit for bit: the kernel and the public function may take the scalar
    and the array paths (README, "Same answers on every machine")."""
    np.testing.assert_allclose(got, np.reshape(want, -1), rtol=1e-14, atol=0)


@pytest.mark.parametrize("scalar", [False, True])
def test_the_kernels_give_the_public_answers(scalar):
    F = 0.05 if scalar else [-0.005, 0.05, 1.0]
    p = _inputs(F=F, H=1.2 if scalar else [1.2, 1.2, 1.2], mu=0.2)
    load = p.F + 0.01
    a, F, conv = P._slide_at(p, slice(None), load)
    args = (float(load[0]), RHO, R, S) if scalar else (load, RHO, R, S)
    ref = lc.sliding_contact_for_load(*args)
    _close(a, ref.a_over_R)
    _close(F, ref.F_over_Eh2)
    assert conv.all()
    a, conv = P._rest_at(p, slice(None), load)
    ref = lc.contact_for_load(args[0], RHO, S, on_failure="report")
    _close(a, ref.a_over_R)
