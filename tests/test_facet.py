"""The faceted wire on its facet (linecontact.facet): each result checked two independent ways.

- the round wire (corner radius = circumradius) is the Maugis--Dugdale line contact of
  linecontact.normal, to rounding, and the results converge to it as r_c -> R;
- a second solver written here, the paper's own machinery (Gauss--Chebyshev collocation of
  the bounded contact pressure with the facet's slope as the right-hand side, the separation
  at c by product integration: the library's sie core, not the closed form), agrees with
  the closed form to 1e-8 over the branch and to 1e-6 at the pull-off;
- the defining integrals of the load and of the profile's separation, by adaptive
  quadrature (scipy.integrate.quad), agree with their closed forms (hypothesis);
- the limits of a sharp facet: the strip's JKR pull-off at large Maugis parameter, the
  strength cap 2 sigma0 f at small;
- the pull-off is the lowest load of the branch (a dense scan finds none lower), and the
  contact for a load gives that load back.
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.integrate import quad
from scipy.optimize import brentq, minimize_scalar

import linecontact as lc
from linecontact.cli import main
from linecontact.facet import _branch
from linecontact.normal.contact import _I
from linecontact.sie import BoundedSolver, log_end_moments

HEX_RHO, HEX_S = 171.0, 0.00684  # R = 50 nm, E* = 50 GPa, w = 0.1 J/m^2, sigma0 = 342 MPa
SETTINGS = settings(derandomize=True, max_examples=30, deadline=None)


# --------------------------------------------------------------------------------------------
# a second solver: Gauss--Chebyshev collocation (the paper's Appendix A), written here


def _colloc_state(A, rho, s, sides, r, n=4096):
    """``(c/R, F/(Eh))`` at ``a/R = A`` by collocation of the bounded pressure (Eqs. 9, 11, 12).

    The facet enters only as the right-hand side (its slope ``g'``) and as the profile's
    separation ``g(c) - g(a)`` in the separation condition; the pressure's part of the
    separation is the product integration of :func:`linecontact.sie.log_end_moments`.
    """
    f = (1 - r) * math.sin(math.pi / sides)
    solver = BoundedSolver(n)
    x = solver.collocation_unit

    def g(t):
        return max(t - f, 0.0) ** 2 / (2 * r)

    def residual(u):
        m1 = 2 * math.sinh(u / 2) ** 2
        lg = np.log((m1 + 1 - x) / (m1 + 1 + x))
        slope = np.sign(x) * np.maximum(A * np.abs(x) - f, 0.0) / r
        sol = solver.solve((-0.5 * slope + (s / np.pi) * lg)[None, :], values=False)
        b = sol.coefficients
        mu, _ = log_end_moments(n, np.array([u]))
        J = float(np.einsum("...j,...j->...", b, mu)[0])
        Iv = float(_I(np.array([u]))[0][0])
        C = A * math.cosh(u)
        sep = 1 + rho * ((2 * A / np.pi) * J + (2 * s * A / np.pi) * Iv - (g(C) - g(A)))
        return sep, (np.pi / 2) * float(b[0, 0])

    u = brentq(lambda u: residual(u)[0], 1e-9, 60.0, xtol=1e-15, rtol=1e-15)
    _, resultant = residual(u)
    return A * math.cosh(u), rho * A * (resultant - 2 * math.cosh(u) * s)


@pytest.mark.parametrize("r", [0.3, 0.05, 1.0])
@pytest.mark.parametrize("A_over_f", [0.2, 0.95, 1.02, 1.4])
def test_collocation_agrees_with_the_closed_form(r, A_over_f):
    """To 1e-8 where the slope is smooth on the contact; to 1e-6 where the contact covers the
    facet's edge: the slope's kink there makes collocation converge algebraically, with an
    error that swings with where the kink falls between nodes (1e-6 to 1e-8 at n = 8192)."""
    f = (1 - r) * math.sin(math.pi / 6)
    A = A_over_f * f if f > 0 else 0.05 * A_over_f
    kink = 0 < f < A
    C, F = _colloc_state(A, HEX_RHO, HEX_S, 6, r, n=8192 if kink else 1024)
    got = lc.facet_contact(A, HEX_RHO, HEX_S, sides=6, corner_radius_over_R=r)
    rtol = 1e-6 if kink else 1e-10
    assert got.c_over_R == pytest.approx(C, rel=rtol), (r, A)
    assert got.F_over_Eh == pytest.approx(F, rel=rtol, abs=1e-12), (r, A)


@pytest.mark.parametrize(
    ("rho", "s", "sides", "r"),
    [(1e3, 0.02, 6, 0.3), (1e3, 0.02, 5, 0.1), (1e4, 0.01, 6, 0.05), (1e4, 0.01, 6, 1.0)],
)
def test_the_pull_off_by_collocation(rho, s, sides, r):
    p = lc.facet_pull_off(rho, s, sides=sides, corner_radius_over_R=r)
    A0 = p.a_over_R_at_pulloff
    assert A0 > 0  # a minimum inside the branch here (not its vanishing-width end)
    res = minimize_scalar(
        lambda A: _colloc_state(A, rho, s, sides, r, n=8192)[1],
        bracket=(0.9 * A0, A0, 1.1 * A0),
        tol=1e-10,
    )
    assert p.F_pulloff_over_Eh == pytest.approx(res.fun, rel=1e-6)


# --------------------------------------------------------------------------------------------
# the round wire and the approach to it


def test_the_round_wire_is_the_maugis_dugdale_line_contact():
    A = np.array([1e-6, 1e-3, 0.02, 0.1, 0.19])  # widths below the pull-off's: unstable
    for rho, s in [(100.0, 0.01), (1e4, 0.001), (5.0, 0.3)]:
        got = lc.facet_contact(A, rho, s, sides=6, corner_radius_over_R=1.0)
        want = lc.normal_contact(A, rho, s)
        np.testing.assert_allclose(got.F_over_Eh, want.F_over_Eh, rtol=1e-12, atol=1e-14)
        np.testing.assert_allclose(got.c_over_R, want.c_over_R, rtol=1e-12)
        np.testing.assert_array_equal(got.stable, want.stable)


@pytest.mark.parametrize(("rho", "s"), [(100, 0.01), (1e3, 0.01), (1e6, 0.01), (1e4, 1e-4)])
def test_the_round_wire_pull_off(rho, s):
    for sides in (3, 5, 6, 8):
        got = lc.facet_pull_off(rho, s, sides=sides, corner_radius_over_R=1.0)
        want = lc.pull_off(rho, s)
        assert got.F_pulloff_over_Eh == pytest.approx(want.F_pulloff_over_Eh, rel=1e-12)


def test_corner_radius_to_the_circumradius_converges_to_the_round_wire():
    """The difference falls linearly with R - r_c: at 1e-10 it is below 1e-8."""
    want = lc.normal_contact(0.05, 100.0, 0.01).F_over_Eh
    gaps = []
    for d in (1e-4, 1e-6, 1e-8, 1e-10):
        got = lc.facet_contact(0.05, 100.0, 0.01, sides=6, corner_radius_over_R=1 - d)
        gaps.append(abs(got.F_over_Eh - want) / abs(want))
    assert gaps[-1] < 1e-8
    ratios = [gaps[i] / gaps[i + 1] for i in range(len(gaps) - 1)]
    assert all(50 < q < 200 for q in ratios), ratios  # 100 per two decades: linear


# --------------------------------------------------------------------------------------------
# the defining integrals, by quadrature


# quad says so where its estimate meets rounding before 1e-10: the comparison is at 1e-9
@pytest.mark.filterwarnings("ignore::scipy.integrate.IntegrationWarning")
@SETTINGS
@given(
    r=st.floats(0.01, 1.0),
    sides=st.integers(3, 9),
    A_rel=st.floats(1.001, 3.0),
    u=st.floats(0.05, 3.0),
)
def test_the_closed_forms_are_the_defining_integrals(r, sides, A_rel, u):
    f = (1 - r) * math.sin(math.pi / sides)
    A = f * A_rel if f > 1e-3 else A_rel * 0.05
    C = A * math.cosh(u)

    def gp(t):
        return math.copysign(max(abs(t) - f, 0.0) / r, t)

    # the load of the bounded solution without adhesion: E int_0^a t g'(t)/sqrt(a^2 - t^2) dt
    tight = {"limit": 500, "epsabs": 1e-15, "epsrel": 1e-10}
    PH = quad(lambda th: A * math.sin(th) * gp(A * math.sin(th)), 0, math.pi / 2, **tight)[0]
    got = float(_branch.hertz_load(np.array(A), np.array(f), np.array(r))) / r
    assert got == pytest.approx(PH, rel=1e-9, abs=1e-14)

    # the profile's separation at c: int_a^c [g'(x) + sqrt(x^2-a^2)/pi int g'(t) dt
    # /(sqrt(a^2-t^2)(t-x))] dx, with t = a sin(phi)
    def slope(x):
        k = math.sqrt(x * x - A * A)
        ph = math.asin(min(f / A, 1.0))

        def inner(p):
            return gp(A * math.sin(p)) / (A * math.sin(p) - x)

        I1 = quad(inner, ph, math.pi / 2, **tight)[0]
        I2 = quad(inner, -math.pi / 2, -ph, **tight)[0]
        return gp(x) + k * (I1 + I2) / math.pi

    G = quad(lambda v: slope(A * math.cosh(v)) * A * math.sinh(v), 0, u, **tight)[0]
    got = float(
        _branch.profile_gap(
            np.array([A]), np.array([C]), np.array([u]), np.array([f]), np.array([r])
        )[0]
    )
    assert got / r == pytest.approx(G, rel=1e-9, abs=1e-14)


# --------------------------------------------------------------------------------------------
# the limits of a sharp facet


def test_a_sharp_facet_tends_to_the_strip_jkr_pull_off():
    errors = []
    for rho in (1e4, 1e6, 1e8, 1e10):
        p = lc.facet_pull_off(rho, 0.01, sides=6, corner_radius_over_R=0.0)
        assert p.mechanism == "corner-pinned"
        errors.append(abs(p.F_pulloff_over_Eh / p.F_strip_jkr_over_Eh - 1))
    # the Maugis parameter grows like rho^(1/2) and the error like its inverse square
    assert errors[-1] < 1e-8
    assert all(50 < errors[i] / errors[i + 1] < 200 for i in range(3)), errors


@pytest.mark.parametrize("sides", [3, 5, 6, 8])
def test_a_sharp_facet_is_capped_by_its_strength_at_small_maugis_parameter(sides):
    p = lc.facet_pull_off(np.array([0.01, 1.0, 10.0]), 0.01, sides=sides)
    np.testing.assert_allclose(p.F_pulloff_over_Eh, p.F_strength_over_Eh, rtol=1e-12)
    assert list(p.mechanism) == ["corner-pinned"] * 3


def test_the_issue_table_hexagon_and_pentagon():
    """Issue 33's table: E* = 50 GPa, w = 0.1, sigma0 = 342 MPa, R = 50 nm."""
    wire = lc.Cylinder.from_modulus(50e-9, 50e9, cohesive_stress=342e6, adhesion_range=0.1 / 342e6)
    Eh = wire.scale("Eh")
    for sides, width, jkr, cap in ((6, 50.0e-9, 28.0, 17.1), (5, 58.8e-9, 30.4, 20.1)):
        p = wire.shaped(lc.Polygon(sides, 0.0)).pull_off()
        nd = p.nondimensional
        assert 2 * nd.facet_half_width_over_R * 50e-9 == pytest.approx(width, abs=0.06e-9)
        assert -nd.F_strip_jkr_over_Eh * Eh == pytest.approx(jkr, abs=0.06)
        assert -nd.F_strength_over_Eh * Eh == pytest.approx(cap, abs=0.06)
        # below both limits, several times the round wire's (3.50 N/m)
        assert 3.5 < -p.pull_off_force <= -nd.F_strength_over_Eh * Eh * (1 + 1e-12)
    assert wire.pull_off().pull_off_force == pytest.approx(-3.50, abs=0.006)


# --------------------------------------------------------------------------------------------
# the pull-off is the branch's minimum; the contact for a load


@SETTINGS
@given(
    rho=st.floats(1.0, 1e5),
    s=st.floats(1e-4, 0.1),
    sides=st.integers(3, 8),
    r=st.sampled_from([0.0, 0.01, 0.1, 0.3, 0.6, 0.9, 1.0]),
)
def test_no_state_of_the_branch_is_below_the_pull_off(rho, s, sides, r):
    p = lc.facet_pull_off(rho, s, sides=sides, corner_radius_over_R=r)
    f = p.facet_half_width_over_R
    top = f if r == 0 else f + 2 * r
    A = np.geomspace(1e-6 * max(top, 1e-6), top, 400)
    c = lc.facet_contact(A, rho, s, sides=sides, corner_radius_over_R=r)
    assert np.all(c.converged)
    assert p.F_pulloff_over_Eh <= c.F_over_Eh.min() * (1 - 1e-12) + 1e-15
    assert p.F_strength_over_Eh * 1.000001 <= p.F_pulloff_over_Eh or r > 0
    assert p.F_pulloff_over_Eh <= p.F_zero_width_over_Eh


@pytest.mark.parametrize("r", [0.0, 0.05, 0.3, 1.0])
def test_the_contact_for_a_load_gives_the_load_back(r):
    p = lc.facet_pull_off(HEX_RHO, HEX_S, sides=6, corner_radius_over_R=r)
    F = np.array([0.9, 0.5, 0.0]) * p.F_pulloff_over_Eh
    F = np.concatenate([F, [0.5, 5.0]])
    c = lc.facet_contact_for_load(F, HEX_RHO, HEX_S, sides=6, corner_radius_over_R=r)
    assert np.all(c.stable)
    back = lc.facet_contact(c.a_over_R, HEX_RHO, HEX_S, sides=6, corner_radius_over_R=r)
    held = (r == 0) & (F >= 0)  # a compressive load holds a sharp facet at its edges
    np.testing.assert_allclose(back.F_over_Eh[~held], F[~held], rtol=1e-9, atol=1e-9)
    np.testing.assert_array_equal(c.a_over_R[held], c.facet_half_width_over_R[held])
    assert np.all(c.region[held] == "corner-pinned")
    with pytest.raises(lc.NoEquilibriumError, match="below the pull-off"):
        lc.facet_contact_for_load(
            1.01 * p.F_pulloff_over_Eh, HEX_RHO, HEX_S, sides=6, corner_radius_over_R=r
        )


def test_the_mechanism_is_one_name_for_one_state():
    """A rounded corner lets go at the vanishing width: one label, whatever the rounding."""
    r = np.linspace(0.02, 0.9, 30)
    p = lc.facet_pull_off(HEX_RHO, HEX_S, sides=6, corner_radius_over_R=r)
    assert set(p.mechanism) == {"zero-width"}
    np.testing.assert_array_equal(p.a_over_R_at_pulloff, 0.0)
    np.testing.assert_array_equal(p.F_pulloff_over_Eh, p.F_zero_width_over_Eh)
    sharp = lc.facet_pull_off(HEX_RHO, HEX_S, sides=6, corner_radius_over_R=0.0)
    assert sharp.mechanism == "corner-pinned" and not sharp.beyond_corner_arc


def test_a_zone_past_the_corners_arc_is_flagged():
    """Below about h the parabola stands for the next facet: said, not hidden."""
    rc = np.array([0.28e-9, 5e-9]) / 50e-9
    p = lc.facet_pull_off(HEX_RHO, HEX_S, sides=6, corner_radius_over_R=rc)
    assert list(p.beyond_corner_arc) == [True, False]
    f, c = p.facet_half_width_over_R, p.c_over_R_at_pulloff
    assert c[0] - f[0] > rc[0] * math.sin(math.pi / 3) >= 0


# --------------------------------------------------------------------------------------------
# bad input


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({"sides": 2}, "sides must be an integer >= 3"),
        ({"sides": 5.5}, "sides must be an integer >= 3"),
        ({"sides": "six"}, "sides must be an integer >= 3"),
        ({"corner_radius_over_R": -0.1}, "corner_radius_over_R"),
        ({"corner_radius_over_R": 1.5}, "corner_radius_over_R"),
    ],
)
def test_bad_geometry_is_refused_naming_it(kwargs, match):
    with pytest.raises(ValueError, match=match):
        lc.facet_pull_off(100.0, 0.01, **kwargs)


def test_a_sharp_facet_refuses_a_contact_wider_than_itself():
    with pytest.raises(ValueError, match="a contact wider than the facet needs a rounded corner"):
        lc.facet_contact(0.6, 100.0, 0.01, sides=6, corner_radius_over_R=0.0)


def test_the_fits_refuse_a_cross_section_that_is_no_value():
    with pytest.raises(ValueError, match="cross_section must be linecontact.Round"):
        lc.shear_strength_from_friction(0.2, 1.0, 50e-9, 50e9, 0.1, 3e-10, cross_section="hexagon")


def test_the_body_refuses_what_is_not_written_for_a_polygon():
    wire = lc.Cylinder.from_modulus(50e-9, 50e9, work_of_adhesion=0.1, equilibrium_spacing=3e-10)
    hexagon = wire.shaped(lc.Polygon(6, 5e-9))
    with pytest.raises(ValueError, match="push is not written for a hexagon wire"):
        hexagon.push(height=10e-9, normal_load=1.0, friction_stress=1e8)
    with pytest.raises(ValueError, match="cyclic_loss is not written for a hexagon wire"):
        hexagon.cyclic_loss(normal_load=1.0, friction_stress=1e8, amplitude=0.1)
    with pytest.raises(ValueError, match="pull_off is not written for a hexagon wire .* "):
        hexagon.under(lc.LennardJones).pull_off()
    with pytest.raises(ValueError, match="corner_radius must be at most the circumradius"):
        wire.shaped(lc.Polygon(6, 60e-9))
    with pytest.raises(ValueError, match="corner_radius must be a finite number >= 0"):
        lc.Polygon(6, -1e-9)


# --------------------------------------------------------------------------------------------
# one number from Python, the command line and a sweep (issue 33's Done-when)

ARGV = [
    "--radius",
    "50e-9",
    "--modulus",
    "50e9",
    "--work-of-adhesion",
    "0.1",
    "--z0",
    "0.3e-9",
]


def test_the_command_line_python_and_a_sweep_give_one_number(capsys):
    wire = lc.Cylinder.from_modulus(50e-9, 50e9, work_of_adhesion=0.1, equilibrium_spacing=3e-10)
    want = wire.shaped(lc.Polygon(6, 5e-9)).pull_off().pull_off_force
    capsys.readouterr()
    argv = ["pulloff", "--cross-section", "hexagon", "--corner-radius", "5e-9", *ARGV, "--json"]
    assert main(argv) == 0
    doc = json.loads(capsys.readouterr().out)
    (rec,) = doc["results"]
    assert rec["F_pulloff_N_per_m"] == pytest.approx(want, rel=1e-12)
    assert doc["parameters"]["cross_section"] == "hexagon"
    assert doc["parameters"]["corner_radius_m"] == 5e-9
    pytest.importorskip("xarray")
    ds = lc.sweep(
        "pulloff",
        cross_section="hexagon",
        corner_radius=[5e-9, 2e-8],
        radius=50e-9,
        modulus=50e9,
        work_of_adhesion=0.1,
        z0=0.3e-9,
    )
    # (a block of the sweep is one array call: its last bits may differ from a scalar's)
    assert float(ds.F_pulloff_N_per_m.values[0]) == pytest.approx(want, rel=1e-10)


@pytest.mark.parametrize(
    ("argv", "flag"),
    [
        (["--corner-radius", "5e-9", *ARGV], "--corner-radius"),
        (["--cross-section", "hexagon", "--corner-radius", "6e-8", *ARGV], "--corner-radius"),
        (["--cross-section", "hexagon", "--corner-radius-over-R", "0.1", *ARGV], "--corner-radius"),
        (
            ["--cross-section", "hexagon", "--corner-radius", "1e-9", "--R-over-h", "100"]
            + ["--sigma0-over-E", "0.01"],
            "--corner-radius",
        ),
        (
            ["--cross-section", "hexagon", "--R-over-h", "100", "--sigma0-over-E", "0.01"]
            + ["--corner-radius-over-R", "2"],
            "--corner-radius-over-R",
        ),
        (["--cross-section", "hexagon", "--law", "lennard-jones", *ARGV], "--law"),
        (["--cross-section", "decagon", *ARGV], "--cross-section"),
    ],
)
def test_the_command_line_refuses_bad_shapes_naming_the_flag(capsys, argv, flag):
    capsys.readouterr()
    try:
        status = main(["pulloff", *argv])
    except SystemExit as e:  # argparse's own refusals (a word not among the choices)
        status = e.code
    assert status == 2
    err = capsys.readouterr().err
    assert err.startswith("error:") or "error:" in err
    assert flag in err
    assert "Traceback" not in err


# --------------------------------------------------------------------------------------------
# the initiation of sliding at the facet's width (a constant friction stress)


def test_sliding_starts_at_two_a_tau0_of_the_facets_contact(capsys):
    """The constant-stress friction law makes the tangential problem at a given width the
    round wire's (uncoupled, B = 0): full slip at 2 a tau0 with the facet's a."""
    wire = lc.Cylinder.from_modulus(50e-9, 50e9, work_of_adhesion=0.1, equilibrium_spacing=3e-10)
    hexagon = wire.shaped(lc.Polygon(6, 5e-9))
    a = hexagon.contact(load=1.0).contact_half_width
    r = hexagon.sliding_initiation(normal_load=1.0, friction_stress=1e8, tangential_load=[0.5, 2.0])
    assert r.contact_half_width == pytest.approx(a, rel=1e-12)
    assert r.full_slip_load == pytest.approx(2 * a * 1e8, rel=1e-12)
    want = lc.sliding_initiation(1e8 / 50e9, T_over_Ea=np.array([0.5, 2.0]) / (50e9 * a))
    np.testing.assert_allclose(r.stick_zone_end, want.d_over_a * a, rtol=1e-12)
    # the command line, with SI inputs and with the groups, gives the same stick zones
    capsys.readouterr()
    argv = ["slide-init", "--cross-section", "hexagon", "--corner-radius", "5e-9", *ARGV]
    assert (
        main([*argv, "--load", "1", "--tau0", "1e8", "--tangential-load", "0.5", "2", "--json"])
        == 0
    )
    doc = json.loads(capsys.readouterr().out)
    np.testing.assert_allclose([x["d_m"] for x in doc["results"]], r.stick_zone_end, rtol=1e-12)
    with pytest.raises(lc.NoEquilibriumError, match="2 a tau0"):
        hexagon.sliding_initiation(normal_load=1.0, friction_stress=1e8, tangential_load=10.0)
    with pytest.raises(ValueError, match="not written for a hexagon wire"):
        hexagon.steady_rolling(normal_load=1.0, friction_stress=1e8, tangential_load=0.5)


@pytest.mark.parametrize(
    ("argv", "flag"),
    [
        (["--a-over-R", "0.1", "--tau0-over-E", "0.002", "--T-over-Ea", "0.1"], "--cross-section"),
        (["--friction", "coulomb", "--mu", "0.3", "--a-over-R", "0.1"], "--friction"),
    ],
)
def test_slide_init_refuses_a_shape_it_cannot_use(capsys, argv, flag):
    capsys.readouterr()
    assert main(["slide-init", "--cross-section", "hexagon", *argv]) == 2
    assert flag in capsys.readouterr().err


def test_normal_gives_the_facets_contact_for_widths_and_loads(capsys):
    wire = lc.Cylinder.from_modulus(50e-9, 50e9, work_of_adhesion=0.1, equilibrium_spacing=3e-10)
    hexagon = wire.shaped(lc.Polygon(6, 5e-9))
    capsys.readouterr()
    argv = ["normal", "--cross-section", "hexagon", "--corner-radius", "5e-9", *ARGV]
    assert main([*argv, "--load", "-20", "0", "1", "--json"]) == 0
    cap = capsys.readouterr()
    assert "small-strain" not in cap.err  # a contact on the facet: a/R is no strain
    rows = json.loads(cap.out)["results"]
    assert rows[0]["state"] == "no-equilibrium" and "pulled off" in rows[0]["reason"]
    want = hexagon.contact(load=[0.0, 1.0])
    np.testing.assert_allclose([r["a_m"] for r in rows[1:]], want.contact_half_width, rtol=1e-12)
    assert [r["F_N_per_m"] for r in rows[1:]] == [0.0, 1.0]
    assert (
        main(
            ["normal", "--cross-section", "pentagon", "--corner-radius-over-R", "0.1"]
            + ["--R-over-h", "171", "--sigma0-over-E", "0.00684", "--a-over-R", "0.1", "--json"]
        )
        == 0
    )
    (row,) = json.loads(capsys.readouterr().out)["results"]
    got = lc.facet_contact(0.1, 171.0, 0.00684, sides=5, corner_radius_over_R=0.1)
    assert row["F_over_Eh"] == pytest.approx(got.F_over_Eh, rel=1e-12)
    assert row["region"] == "inside-facet"
    assert main([*argv, "--load", "0", "--method", "collocation"]) == 2
    assert "--method" in capsys.readouterr().err


# --------------------------------------------------------------------------------------------
# the fits: tau0 from a friction force at the facet's width, w from a faceted pull-off


def test_tau0_from_a_friction_force_at_the_facets_width():
    hexagon = lc.Polygon(6, 5e-9)
    wire = lc.Cylinder.from_modulus(50e-9, 50e9, work_of_adhesion=0.1, equilibrium_spacing=3e-10)
    loads = np.array([0.0, 1.0, 5.0])
    a = wire.shaped(hexagon).contact(load=loads).contact_half_width
    # the friction force of a full slip at tau0 = 30 MPa (Cylinder.sliding_initiation's)
    f = 2 * a * 3e7
    tau = lc.shear_strength_from_friction(f, loads, 50e-9, 50e9, 0.1, 0.3e-9, cross_section=hexagon)
    np.testing.assert_allclose(tau, 3e7, rtol=1e-12)
    # read as a round wire, the same forces give a shear strength several times larger
    tau_round = lc.shear_strength_from_friction(f, loads, 50e-9, 50e9, 0.1, 0.3e-9)
    assert np.all(tau_round > 5 * tau)
    with pytest.raises(ValueError, match="contact='maugis-dugdale'"):
        lc.shear_strength_from_friction(
            f, loads, 50e-9, 50e9, 0.1, 0.3e-9, cross_section=hexagon, contact="jkr"
        )


def test_w_from_pull_offs_of_faceted_wires_round_trips():
    from linecontact.fits import pull_off_force, work_of_adhesion_from_pull_off

    pentagon = lc.Polygon(5, 2e-9)
    w = np.array([0.05, 0.1, 0.3])
    F = pull_off_force(50e-9, 50e9, w, 0.3e-9, cross_section=pentagon)
    wire = lc.Cylinder.from_modulus(50e-9, 50e9, work_of_adhesion=0.1, equilibrium_spacing=3e-10)
    assert F[1] == pytest.approx(wire.shaped(pentagon).pull_off().pull_off_force, rel=1e-12)
    back = work_of_adhesion_from_pull_off(F, 50e-9, 50e9, 0.3e-9, cross_section=pentagon)
    np.testing.assert_allclose(back, w, rtol=1e-10)
    # the round wire's reading of a faceted wire's pull-off: a work of adhesion far too large
    round_w = work_of_adhesion_from_pull_off(F, 50e-9, 50e9, 0.3e-9)
    assert np.all(round_w > 3 * w)


# --------------------------------------------------------------------------------------------
# the load curve


@pytest.mark.parametrize("r", [0.0, 0.1, 1.0])
def test_the_load_curve_marks_the_pull_off_and_is_the_branch(r):
    c = lc.facet_load_curve(HEX_RHO, HEX_S, sides=6, corner_radius_over_R=r, num=60)
    (i,) = np.flatnonzero(c.turning_point)
    assert c.F_over_Eh[i] == pytest.approx(c.pulloff.F_pulloff_over_Eh, rel=1e-12)
    assert c.F_over_Eh.min() >= c.pulloff.F_pulloff_over_Eh * (1 + 1e-12)
    assert c.a_over_R[0] == 0 and c.F_over_Eh[0] == c.pulloff.F_zero_width_over_Eh
    again = lc.facet_contact(c.a_over_R[1:], HEX_RHO, HEX_S, sides=6, corner_radius_over_R=r)
    np.testing.assert_array_equal(again.F_over_Eh, c.F_over_Eh[1:])
    if r == 1.0:  # the round wire's curve has the same contact branch
        want = lc.normal_contact(c.a_over_R[1:], HEX_RHO, HEX_S)
        np.testing.assert_allclose(c.F_over_Eh[1:], want.F_over_Eh, rtol=1e-11, atol=1e-14)
    if r == 0.0:  # a sharp facet's curve ends at its edge
        assert c.a_over_R[-1] == pytest.approx(c.pulloff.facet_half_width_over_R)


def test_the_load_curve_in_si_and_on_the_command_line(capsys):
    wire = lc.Cylinder.from_modulus(50e-9, 50e9, work_of_adhesion=0.1, equilibrium_spacing=3e-10)
    curve = wire.shaped(lc.Polygon(6, 5e-9)).load_curve(num=20)
    capsys.readouterr()
    argv = ["curve", "--cross-section", "hexagon", "--corner-radius", "5e-9", *ARGV]
    assert main([*argv, "--num", "20", "--json"]) == 0
    rows = json.loads(capsys.readouterr().out)["results"]
    np.testing.assert_allclose([x["F_N_per_m"] for x in rows], curve.load, rtol=1e-12)
    assert [x["pulloff"] for x in rows] == list(curve.turning_point)
    assert main([*argv, "--num-noncontact", "5"]) == 2
    assert "--num-noncontact" in capsys.readouterr().err


def test_the_collocation_converges_to_the_closed_form_with_its_size():
    """The paper's machinery on a contact over the facet's kink: algebraic convergence (its
    error swings with where the kink falls between nodes, falling overall)."""
    f = 0.7 * math.sin(math.pi / 6)
    A = 1.4 * f
    want = lc.facet_contact(A, HEX_RHO, HEX_S, sides=6, corner_radius_over_R=0.3).F_over_Eh
    err = {
        n: abs(_colloc_state(A, HEX_RHO, HEX_S, 6, 0.3, n=n)[1] / want - 1)
        for n in (64, 256, 1024, 8192)
    }
    assert err[64] > err[256] > err[1024] > err[8192]
    assert err[8192] < 1e-6 < err[64]
