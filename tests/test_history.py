"""Tangential load histories and the loss per cycle (linecontact.tangential.history).

The Masing (closed-form) states are checked against the incremental collocation solver,
which knows no superposition or memory rule; the closed-form loss against the friction work
and the loop area by quadrature; the amplitude exponents and the full-slip limits; the
memory rules (erasure, return points) and the friction law at every step.
"""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.integrate import quad

from linecontact import (
    Cylinder,
    cyclic_loss,
    cyclic_loss_coulomb,
    sliding_initiation,
    sliding_initiation_coulomb,
    tangential_history,
    tangential_history_coulomb,
)
from linecontact.tangential.history import _LAWS, _graded

X = np.sin(np.linspace(-1.5, 1.5, 81)) * 1.0017  # off the zone ends (nice numbers), some outside
T0 = 0.01  # tau0/E
MU, A = 0.3, 0.01  # Coulomb: mu, a/R

# histories over the full-slip load: reversals, nested loops, closures, a slide and after
HISTORIES = [
    [0.8, -0.4, 0.8],  # a loop that closes exactly at its start
    [0.8, -0.4, 0.9, 0.2, 0.6, -0.95],  # closure, an inner loop, then past every extreme
    [0.5, 0.9, -0.3, 0.4, 0.1, 0.35, -0.6],  # nested memory
    [0.7, 1.2, 0.3, -0.5, 0.6],  # a slide, then stick-slip from full slip
    [-0.3, 0.3, -0.3, 0.3],  # cycles from the first loading
    # a small inner loop closed exactly at the old extreme: the force is flat between the
    # two stick zones there (the incremental solver once took a root inside that interval)
    [-0.852, -0.97, -0.8669, -0.97, -0.5],
]


def _both(law, loads):
    if law == "constant":
        f = lambda m: tangential_history(T0, np.multiply(loads, 2 * T0), method=m)  # noqa: E731
        scale = T0
    else:
        f = lambda m: tangential_history_coulomb(MU, A, loads, method=m)  # noqa: E731
        scale = MU * A / 2
    return f("closed-form"), f("incremental"), scale


# --------------------------------------------------------------------------------------------
# the two solvers


@pytest.mark.parametrize("law", ["constant", "coulomb"])
@pytest.mark.parametrize("loads", HISTORIES)
def test_masing_agrees_with_the_incremental_solver(law, loads):
    m, inc, scale = _both(law, loads)
    assert inc.converged.all()
    assert np.array_equal(m.state, inc.state)
    ok = m.state != "sliding"
    assert np.allclose(m.c_over_a[ok], inc.c_over_a[ok], rtol=0, atol=1e-12)
    assert np.max(np.abs(m.traction(X) - inc.traction(X))) < 1e-12 * scale
    ds = m.slip(X) - inc.slip(X)
    assert np.nanmax(np.abs(ds)) < 1e-12 * scale
    assert np.allclose(m.displacement_over_a[ok], inc.displacement_over_a[ok], atol=1e-12 * scale)
    w_m, w_i = m.dissipation_over_Ea2, inc.dissipation_over_Ea2
    assert np.array_equal(np.isnan(w_m), np.isnan(w_i))
    assert np.allclose(w_m[ok], w_i[ok], rtol=1e-10, atol=1e-14 * scale**2)


def test_the_incremental_solver_reports_its_diagnostics():
    h = tangential_history(T0, [0.016, -0.008, 0.004], method="incremental")
    assert h.method == "incremental"
    assert np.all(h.n_collocation >= 64)
    assert np.all(h.error_estimate < 1e-14)
    assert np.all(h.residual_stick < 1e-12)
    assert np.all(h.residual_admissible < 1e-12)
    assert np.all(h.memory == -1)  # it holds no turning points


def test_a_small_reversal_needs_more_nodes_and_gets_them():
    # a reversal by 5% of full slip puts the new stick zone within 3e-4 of the edge
    h = tangential_history(T0, [0.016, 0.015], method="incremental")
    assert h.n_collocation[1] > h.n_collocation[0]
    m = tangential_history(T0, [0.016, 0.015])
    assert abs(h.c_over_a[1] - m.c_over_a[1]) < 1e-12
    assert h.converged.all()


# --------------------------------------------------------------------------------------------
# virgin loading is the initiation of sliding


def test_virgin_loading_is_the_initiation_of_sliding():
    h = tangential_history(T0, [0.004, 0.012, 0.018])
    s = sliding_initiation(T0, T_over_Ea=[0.004, 0.012, 0.018])
    assert np.allclose(h.c_over_a, s.d_over_a, rtol=0, atol=1e-15)
    assert np.allclose(h.traction(X), s.traction(X), rtol=0, atol=1e-17)
    xs = np.linspace(-0.99, 0.99, 41)
    assert np.allclose(h.slip(xs), s.slip(xs), rtol=0, atol=1e-16)


def test_virgin_coulomb_loading_is_cattaneo_mindlin():
    h = tangential_history_coulomb(MU, A, [0.2, 0.5, 0.9])
    s = sliding_initiation_coulomb(MU, A, T_over_muF=[0.2, 0.5, 0.9])
    assert np.allclose(h.c_over_a, s.d_over_a, rtol=0, atol=1e-15)
    assert np.allclose(h.traction(X), s.traction(X), rtol=0, atol=1e-17)


@pytest.mark.parametrize("law", ["constant", "coulomb"])
@pytest.mark.parametrize("r", [0.05, 0.5, 0.95])
def test_monotone_displacement_by_quadrature(law, r):
    """D = -(2/(pi E)) int q ln|xi/a| dxi, the datum at depth a (docs/load-histories.md)."""
    L = _LAWS[law]
    d = float(L.stick(r))
    # int_0^b f(x) ln x dx with the logarithm as the weight, piece by piece
    val = sum(
        quad(
            lambda x: float(L.traction(x, r)),
            lo,
            hi,
            weight="alg-loga",
            wvar=(0, 0),
            epsabs=1e-15,
            limit=200,
        )[0]
        if lo == 0
        else quad(lambda x: float(L.traction(x, r)) * math.log(x), lo, hi, epsabs=1e-15, limit=200)[
            0
        ]
        for lo, hi in ((0.0, d), (d, 1.0))
    )
    assert abs(-(2 / np.pi) * 2 * val - float(L.displacement(r))) < 1e-11


@pytest.mark.parametrize("law", ["constant", "coulomb"])
@pytest.mark.parametrize("r", [0.1, 0.6, 0.99])
def test_monotone_slip_integrates_the_slip_gradient(law, r):
    """s(x) = (2/(pi E)) int_0^x PV int q(xi)/(x' - xi) dxi dx' (Eq T1), by quadrature."""
    L = _LAWS[law]
    x = 0.995

    def el(y):  # (2/pi) int q(xi) ln|y - xi| dxi
        d = float(L.stick(r))
        pts = sorted({-d, d, y})
        v, _ = quad(
            lambda s: float(L.traction(s, r)) * math.log(abs(y - s)), -1, 1, points=pts, limit=400
        )
        return (2 / np.pi) * v

    assert abs((el(x) - el(0.0)) - float(L.slip(x, r))) < 1e-8


# --------------------------------------------------------------------------------------------
# the friction law and the stick condition along a history (the Masing states alone)


@settings(max_examples=40, deadline=None)
@given(
    st.sampled_from(["constant", "coulomb"]),
    st.lists(st.floats(-1.3, 1.3, allow_nan=False), min_size=1, max_size=12),
)
def test_every_masing_state_obeys_the_friction_law(law, loads):
    if law == "constant":
        h = tangential_history(T0, np.multiply(loads, 2 * T0))
        B, scale = np.ones_like(X), T0
    else:
        h = tangential_history_coulomb(MU, A, loads)
        B, scale = np.sqrt(np.clip(1 - X * X, 0, None)), MU * A / 2
    q = h.traction(X) / scale
    assert np.all(np.abs(q) <= B + 1e-12)
    # force balance: the traction carries the load (Gauss-Legendre on pieces graded towards
    # the zone ends, where the traction has square-root ends and nearby log sources)
    T_full = 2 * T0 if law == "constant" else np.pi / 4 * MU * A
    xg, wg = np.polynomial.legendre.leggauss(16)
    for j, zones in enumerate(h.zones()):
        T = 0.0
        for lo, hi in _graded([z[0] for z in zones] + [1.0]):
            x = lo + (hi - lo) * (xg + 1) / 2
            q2 = h.traction(np.r_[x, -x], [j])[0]
            T += (hi - lo) / 2 * np.sum(np.r_[wg, wg] * q2)
        expected = np.sign(h.T_over_Ea[j]) * T_full if h.state[j] == "sliding" else h.T_over_Ea[j]
        assert T == pytest.approx(expected, abs=1e-10 * T_full)  # nearly singular ends
    s = h.slip(X)
    for j in range(1, h.step.size):
        if h.state[j] == "sliding" or h.state[j - 1] == "sliding":
            continue
        c = h.c_over_a[j]
        ds = s[j] - s[j - 1]
        stick = np.abs(X) < c - 1e-9
        slip_zone = (np.abs(X) > c + 1e-9) & (np.abs(X) <= 1)
        assert np.all(np.abs(ds[stick]) < 1e-13 * scale)  # stick: the slip does not change
        assert np.all(h.slip_direction[j] * ds[slip_zone] >= -1e-13 * scale)  # with the friction
        assert np.allclose(q[j][slip_zone], h.slip_direction[j] * B[slip_zone], atol=1e-12)
    w = h.dissipation_over_Ea2
    assert np.all(w[~np.isnan(w)] >= 0)


def test_a_closed_loop_is_erased():
    """Wiping-out: an inner loop leaves no trace once the load passes its start."""
    with_loop = tangential_history(T0, [0.012, 0.004, 0.008, 0.0, 0.010, -0.006, 0.014])
    plain = tangential_history(T0, [0.012, 0.004, 0.014])
    assert with_loop.memory[-1] == plain.memory[-1] == 0
    assert np.allclose(with_loop.traction(X, [-1]), plain.traction(X, [-1]), atol=1e-18)
    assert np.allclose(with_loop.slip(X, [-1]), plain.slip(X, [-1]), atol=1e-18, equal_nan=True)


def test_the_first_reversal_reaches_the_mirror_state():
    h = tangential_history(T0, [0.012, -0.012])
    mirror = tangential_history(T0, [-0.012])
    assert np.allclose(h.traction(X, [1]), mirror.traction(X), atol=1e-18)
    assert h.displacement_over_a[1] == pytest.approx(mirror.displacement_over_a[0], abs=1e-17)


def test_zones_after_two_reversals():
    h = tangential_history(T0, [0.016, -0.008, 0.0])
    z = h.zones()[2]
    kinds = [k for _, _, k in z]
    assert kinds == ["stick", "locked+", "locked-", "slip+"]
    ends = [b for _, b, _ in z]
    assert ends[0] == pytest.approx(0.6) and ends[1] == pytest.approx(0.8)
    assert ends[2] == pytest.approx(math.sqrt(1 - 0.2**2))
    assert [k for _, _, k in h.zones()[0]] == ["stick", "slip+"]


def test_sliding_is_reported_and_the_history_goes_on():
    h = tangential_history(T0, [0.01, 0.03, 0.01])
    assert h.state.tolist() == ["stick-slip", "sliding", "stick-slip"]
    assert np.isnan(h.c_over_a[1]) and np.isnan(h.dissipation_over_Ea2[1])
    assert np.isnan(h.displacement_over_a[1])
    # unloading from full slip: the branch from T = 2 a tau0
    assert h.c_over_a[2] == pytest.approx(math.sqrt(1 - (0.5 / 2) ** 2))
    assert h.zones()[1] == [(0.0, 1.0, "sliding")]
    assert [k for _, _, k in h.zones()[2]] == ["locked+", "slip-"]


# --------------------------------------------------------------------------------------------
# the loss per cycle


def _loop_area_by_quadrature(law, r):
    """W = int (D_down - D_up) dT over the loop, D from the monotone closed form (Masing)."""
    g = _LAWS[law].displacement
    Tf = _LAWS[law].T_full
    f = lambda t: float(2 * g(r) - 2 * g((r - t) / 2) - 2 * g((t + r) / 2))  # noqa: E731
    v, _ = quad(f, -r, r, epsabs=0, epsrel=1e-11, limit=200)
    return Tf * v


@pytest.mark.parametrize("r", [0.01, 0.2, 0.7, 0.999])
def test_loss_is_the_loop_area(r):
    w = cyclic_loss(T0, 2 * T0 * r)
    assert w.W_over_Ea2 == pytest.approx(T0**2 * _loop_area_by_quadrature("constant", r), rel=1e-9)
    wc = cyclic_loss_coulomb(MU, A, r)
    assert wc.W_over_Ea2 == pytest.approx(
        (MU * A / 2) ** 2 * _loop_area_by_quadrature("coulomb", r), rel=1e-9
    )


def test_the_datum_drops_out_of_the_loop_area():
    w = cyclic_loss(T0, 0.012)
    loop = w.loop(4001)
    T, D = loop["T_over_Ea"], loop["displacement_over_a"]
    for kappa in (0.0, 3.0, -50.0):
        Dk = D + kappa * T
        area = np.trapezoid(T, Dk)  # the work of T around the loop
        assert area == pytest.approx(w.W_over_Ea2, rel=1e-5)


@pytest.mark.parametrize("r", [0.05, 0.3, 0.8, 0.97])
def test_loss_is_the_friction_work_of_the_incremental_solver(r):
    a = cyclic_loss(T0, 2 * T0 * r)
    b = cyclic_loss(T0, 2 * T0 * r, method="incremental")
    assert b.W_over_Ea2 == pytest.approx(a.W_over_Ea2, rel=1e-10)
    ac = cyclic_loss_coulomb(MU, A, r)
    bc = cyclic_loss_coulomb(MU, A, r, method="incremental")
    assert bc.W_over_Ea2 == pytest.approx(ac.W_over_Ea2, rel=1e-10)


def test_the_history_of_a_cycle_dissipates_the_cyclic_loss():
    h = tangential_history(T0, [0.014, -0.014, 0.014, -0.014, 0.014])
    w = cyclic_loss(T0, 0.014)
    assert h.dissipation_over_Ea2[1] + h.dissipation_over_Ea2[2] == pytest.approx(
        w.W_over_Ea2, rel=1e-13
    )
    # the loop is steady from the first cycle (Masing)
    assert h.dissipation_over_Ea2[3] == pytest.approx(h.dissipation_over_Ea2[1], rel=1e-13)
    # splitting the steps does not change the energy
    fine = tangential_history(
        T0, np.r_[np.linspace(0, 0.014, 30)[1:], np.linspace(0.014, -0.014, 50)[1:]]
    )
    assert np.sum(fine.dissipation_over_Ea2[29:]) == pytest.approx(
        h.dissipation_over_Ea2[1], rel=1e-12
    )


def test_amplitude_exponents():
    """W ~ T*^4 for constant tau0, T*^3 for Coulomb at small amplitude."""
    r = np.array([1e-3, 2e-3])
    w = cyclic_loss(T0, 2 * T0 * r).W_over_Ea2
    assert np.log(w[1] / w[0]) / np.log(2) == pytest.approx(4.0, abs=1e-5)
    # the leading term: (8 / (3 pi)) (tau0/E)^2 r^4
    assert w[0] == pytest.approx(8 / (3 * np.pi) * T0**2 * r[0] ** 4, rel=1e-6)
    wc = cyclic_loss_coulomb(MU, A, r).W_over_Ea2
    assert np.log(wc[1] / wc[0]) / np.log(2) == pytest.approx(3.0, abs=1e-3)
    assert wc[0] == pytest.approx(np.pi / 24 * MU**2 * A**2 * r[0] ** 3, rel=1e-3)
    # the series and the closed form meet without a jump
    rr = np.array([0.3 - 1e-12, 0.3 + 1e-12])
    w2 = cyclic_loss(T0, 2 * T0 * rr).W_over_Ea2
    assert w2[1] / w2[0] == pytest.approx(1.0, abs=1e-10)
    rc = np.array([0.25 - 1e-12, 0.25 + 1e-12])
    w3 = cyclic_loss_coulomb(MU, A, rc).W_over_Ea2
    assert w3[1] / w3[0] == pytest.approx(1.0, abs=1e-10)


def test_tiny_amplitudes_have_no_cancellation():
    r = 1e-6
    w = cyclic_loss(T0, 2 * T0 * r).W_over_Ea2
    assert w == pytest.approx(8 / (3 * np.pi) * T0**2 * r**4, rel=1e-9)
    wc = cyclic_loss_coulomb(MU, A, r).W_over_Ea2
    assert wc == pytest.approx(np.pi / 24 * MU**2 * A**2 * r**3, rel=1e-5)


def test_full_slip_limits():
    w = cyclic_loss(T0, 2 * T0 * (1 - 1e-12)).W_over_Ea2
    assert w == pytest.approx(32 / np.pi * (math.log(2) - 0.5) * T0**2, rel=1e-10)
    wc = cyclic_loss_coulomb(MU, A, 1 - 1e-12).W_over_Ea2
    assert wc == pytest.approx(np.pi / 8 * MU**2 * A**2, rel=1e-10)
    s = cyclic_loss(T0, [2 * T0, 3 * T0])
    assert s.state.tolist() == ["sliding", "sliding"]
    assert np.all(np.isnan(s.W_over_Ea2)) and np.all(np.isnan(s.c_over_a))


def test_cyclic_loss_broadcasts_and_returns_scalars_for_scalars():
    w = cyclic_loss([[0.01], [0.02]], [0.001, 0.002, 0.003])
    assert w.W_over_Ea2.shape == (2, 3)
    assert isinstance(cyclic_loss(0.01, 0.001).W_over_Ea2, float)
    assert cyclic_loss(0.01, 0.001).c_over_a == pytest.approx(math.sqrt(1 - 0.05**2))
    assert w.loop(11)["T_over_Ea"].shape == (2, 3, 21)


# --------------------------------------------------------------------------------------------
# SI layer and bad input


def test_si_layer_converts_units():
    cyl = Cylinder.from_modulus(50e-9, 100e9, cohesive_stress=1e9, adhesion_range=0.5e-9)
    w = cyl.cyclic_loss(1.0, [0.5, 1.0, 100.0], friction_stress=1e9)
    a, E = w.contact_half_width, 100e9
    nd = cyclic_loss(1e9 / E, np.array([0.5, 1.0]) / (E * a))
    assert np.allclose(w.energy_per_cycle[:2], nd.W_over_Ea2 * E * a * a, rtol=1e-14)
    assert w.state[2] == "sliding" and np.isnan(w.energy_per_cycle[2])
    h = cyl.tangential_history(1.0, [1.0, -1.0, 1.0], friction_stress=1e9)
    assert np.sum(h.dissipation[1:]) == pytest.approx(w.energy_per_cycle[1], rel=1e-13)
    hertz = Cylinder.from_modulus(50e-9, 100e9, cohesive_stress=0.0, adhesion_range=0.5e-9)
    wc = hertz.cyclic_loss(1.0, 0.1, friction_coefficient=0.3)
    assert wc.full_slip_load == pytest.approx(0.3)
    assert wc.energy_per_cycle > 0


@pytest.mark.parametrize(
    ("call", "name"),
    [
        (lambda: tangential_history(T0, [0.01, np.nan]), "T_over_Ea"),
        (lambda: tangential_history(T0, []), "T_over_Ea"),
        (lambda: tangential_history(T0, [[0.01]]), "T_over_Ea"),
        (lambda: tangential_history(0.0, [0.01]), "tau0_over_E"),
        (lambda: tangential_history(T0, [0.01], method="masing"), "method"),
        (lambda: tangential_history(T0, [0.01], method="incremental", n=2), "n"),
        (lambda: tangential_history_coulomb(-1, A, [0.1]), "mu"),
        (lambda: cyclic_loss(T0, 0.0), "T_amplitude_over_Ea"),
        (lambda: cyclic_loss(T0, -1.0), "T_amplitude_over_Ea"),
        (lambda: cyclic_loss(T0, np.inf), "T_amplitude_over_Ea"),
        (lambda: cyclic_loss_coulomb(MU, A, 0.0), "T_amplitude_over_muF"),
        (lambda: cyclic_loss_coulomb(MU, 0.0, 0.1), "a_over_R"),
        (lambda: cyclic_loss(T0, 0.01).loop(1), "num"),
        (lambda: tangential_history(T0, [0.01]).traction(X, [5]), "steps"),
    ],
)
def test_bad_input_names_the_parameter(call, name):
    with pytest.raises(ValueError, match=name):
        call()


# --------------------------------------------------------------------------------------------
# found by fuzzing (each failed on the first version)


def test_returning_to_full_slip_slides():
    """A loop closed at a full-slip turning point slides again, as the incremental solver says."""
    for loads in ([0.02, 0.0, 0.02], [0.02, -0.02]):
        for method in ("closed-form", "incremental"):
            h = tangential_history(T0, loads, method=method)
            assert h.state[-1] == "sliding", (loads, method)
            assert np.isnan(h.c_over_a[-1]) and np.isnan(h.dissipation_over_Ea2[-1])
    # and no jump between just below and exactly at the old extreme
    h = tangential_history(T0, [0.019999999, 0.0, 0.02])
    assert h.state[-1] == "sliding"


def test_a_load_held_at_full_slip_keeps_sliding_with_an_undetermined_loss():
    for method in ("closed-form", "incremental"):
        h = tangential_history(T0, [0.02, 0.02], method=method)
        assert h.state.tolist() == ["sliding", "sliding"]
        assert np.all(np.isnan(h.dissipation_over_Ea2))


def test_zones_stay_ordered_under_round_off():
    h = tangential_history(0.5, [3, 0.9999999999999997, 0.9999999999999999])
    for zs in h.zones():
        ends = [(lo, hi) for lo, hi, _ in zs]
        assert ends[0][0] == 0.0 and ends[-1][1] == 1.0
        assert all(b[0] == a[1] for a, b in zip(ends, ends[1:], strict=False))
        assert all(hi > lo for lo, hi in ends)


def test_round_off_gives_no_negative_energy_and_slip_outside_is_nan():
    h = tangential_history(0.5, [-0.4673388790854809, -0.46733887908548094])
    assert np.all(h.dissipation_over_Ea2 >= 0)
    assert np.isnan(tangential_history(T0, [0.0]).slip([2.0])[0, 0])
    with np.errstate(all="raise"):  # far points: no overflow warning
        assert tangential_history(T0, [0.01]).traction([1e300])[0, 0] == 0.0


def test_the_domain_ends_are_inclusive_and_tol_is_checked():
    assert tangential_history(T0, [1e12]).state[0] == "sliding"
    assert cyclic_loss(1e-12, 1e12).state == "sliding"
    for tol in ("x", float("nan"), -1.0):
        with pytest.raises(ValueError, match="tol"):
            tangential_history(T0, [0.01], method="incremental", tol=tol)
        with pytest.raises(ValueError, match="tol"):
            cyclic_loss(T0, 0.01, method="incremental", tol=tol)
