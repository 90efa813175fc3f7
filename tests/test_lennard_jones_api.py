"""The Lennard-Jones law: linecontact.laws.lennard_jones, Cylinder's methods and the CLI.

The conversion to the Dugdale groups is checked against the native solver
(:mod:`linecontact.lennard_jones`) with the groups derived here from the matching alone
(``w = sigma0 h``, ``sigma0 = S w/z0``, ``S = 16/(9 sqrt 3)``), not with the library's
``mu_of_dugdale``; the contact for a load read off the curve against the curve; the Dugdale
default; bad input; the CLI's JSON and exit codes; the ``law=`` keyword gone (a law is a
module: ``law="lennard-jones"`` was deprecated and is deleted before 1.0).
Parameters are chosen for ``mu`` about 0.1 (a solve about a second).
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

import linecontact as lc
from linecontact import Cylinder, NoEquilibriumError, NormalContact
from linecontact.cli import main
from linecontact.closed_forms import lennard_jones_rigid_pull_off
from linecontact.cylinder import (
    CylinderContact,
    CylinderLennardJonesContact,
    CylinderLennardJonesPullOff,
    CylinderPullOff,
)
from linecontact.domain import DOMAIN
from linecontact.laws import LennardJones
from linecontact.laws import lennard_jones as lj_law
from linecontact.lennard_jones import lj_contact_for_load, lj_curve, lj_pull_off, lj_state
from linecontact.lennard_jones_groups import (
    LJ_LOAD_MAX,
    LennardJonesContact,
    LennardJonesLoadCurve,
)
from linecontact.normal import LoadCurve

LJ = "lennard-jones"
S = 16 / (9 * math.sqrt(3))  # the peak tension of the law over w/z0
RHO, SIG = 100.0, 0.01  # mu = 0.096
#: sigma0/E that puts mu at 1.5 times the end of its domain (at R/h = RHO)
MU_BAD = 1.5 * DOMAIN["lj_mu"][2]
SIG_BAD = MU_BAD * S**1.5 / math.sqrt(RHO)


def native_groups(R_over_h, sigma0_over_E):
    """``(mu, sqrt(R/z0), w sqrt(R/z0)/(E h))`` from the matching: z0 = S h, w = sigma0 h."""
    R_over_z0 = R_over_h / S
    w_over_Ez0 = sigma0_over_E / S  # sigma0 h/(E S h)
    return (
        w_over_Ez0 * math.sqrt(R_over_z0),
        math.sqrt(R_over_z0),
        sigma0_over_E * math.sqrt(R_over_z0),
    )


def run(capsys, *argv):
    try:
        code = main(list(argv))
    except SystemExit as e:  # argparse's own errors (an unknown choice)
        code = e.code
    out, err = capsys.readouterr()
    return code, out, err


def document(text):
    doc = json.loads(text)
    assert set(doc) == {"linecontact", "command", "parameters", "units", "results"}
    return doc


@pytest.fixture(scope="module")
def curve():
    return lj_law.load_curve(RHO, SIG)


# --------------------------------------------------------------------------------------------
# the groups against the native solver


def test_contact_for_load_is_the_native_solver_in_dugdale_groups():
    mu, root, scale = native_groups(RHO, SIG)
    F = 0.05
    r = lj_law.contact_for_load(F, RHO, SIG)
    st = lj_contact_for_load(F / scale, mu)
    assert isinstance(r, LennardJonesContact) and r.law == LJ
    assert r.mu == pytest.approx(mu, rel=1e-14)
    assert r.maugis_parameter == pytest.approx(lc.maugis_parameter(RHO, SIG), rel=1e-12)
    assert r.F_over_Eh == F  # the load asked for
    assert r.a_over_R == pytest.approx(st.half_width / root, rel=1e-9)
    assert r.central_gap_over_h == pytest.approx(st.central_gap_over_z0 * S, rel=1e-9)
    assert r.error_estimate_over_Eh == pytest.approx(st.error_estimate * scale, rel=1e-6)
    assert r.n == st.n and r.residual < 1e-10
    # a compressive load: a repulsive region, the central gap below z0 = S h
    assert 0 < r.a_over_R < 0.2 and r.central_gap_over_h < S
    # scalars in, Python scalars out
    assert type(r.a_over_R) is float and type(r.n) is int
    assert r.converged is True and r.stable is True and r.state == "contact"


def test_curve_is_the_native_curve_in_dugdale_groups(curve):
    mu, root, scale = native_groups(RHO, SIG)
    nat = lj_curve(mu)
    assert isinstance(curve, LennardJonesLoadCurve)
    # two solves agree to the Newton tolerance (1e-11 of the gaps), not to the bit: the chord
    # iteration reuses the last Jacobian factorised
    noise = 1e-9 * scale
    np.testing.assert_allclose(curve.F_over_Eh, nat.F * scale, rtol=1e-9, atol=noise)
    np.testing.assert_allclose(curve.a_over_R, nat.half_width / root, rtol=1e-9)
    np.testing.assert_allclose(curve.central_gap_over_h, nat.central_gap_over_z0 * S, rtol=1e-9)
    np.testing.assert_allclose(
        curve.error_estimate_over_Eh, nat.error_estimate * scale, rtol=1e-6, atol=noise
    )
    np.testing.assert_array_equal(curve.stable, nat.stable)
    np.testing.assert_array_equal(curve.turning_point, nat.turning)
    po = curve.pulloff
    assert po.law == LJ and po.R_over_h == RHO and po.sigma0_over_E == SIG
    assert po.F_pulloff_over_Eh == pytest.approx(nat.pull_off.F_pulloff * scale, rel=1e-9)
    assert po.central_gap_over_h_at_pulloff == pytest.approx(
        nat.pull_off.central_gap_at_pulloff * S, rel=1e-9
    )
    # the pull-off is the most tensile load; the curve runs from far away to its end
    assert po.F_pulloff_over_Eh <= curve.F_over_Eh.min() + 1e-12
    assert np.all(np.diff(curve.central_gap_over_h) < 0)
    assert curve.F_over_Eh[-1] >= 7.5 * scale and curve.a_over_R[-1] > 0
    # and it is the pull-off of the law's module, to the error estimates
    ref = lj_law.pull_off(RHO, SIG)
    assert abs(ref.F_pulloff_over_Eh - po.F_pulloff_over_Eh) <= 10 * (
        ref.error_estimate_over_Eh + po.error_estimate_over_Eh
    )
    assert curve.mu == pytest.approx(mu, rel=1e-14) and curve.law == LJ


def test_contact_for_loads_read_off_the_curve_give_them_back(curve):
    mu, _, scale = native_groups(RHO, SIG)
    beyond = curve.central_gap_over_h < curve.pulloff.central_gap_over_h_at_pulloff
    pick = np.flatnonzero(beyond & curve.stable & (curve.F_over_Eh <= 2 * scale))
    assert pick.size >= 3
    idx = pick[[0, -1]]  # just beyond the pull-off (tensile) and a compressive load
    F = curve.F_over_Eh[idx]
    assert F[0] < 0 < F[1]
    r = lj_law.contact_for_load(F, RHO, SIG)  # arrays in, arrays out
    assert r.a_over_R.shape == (2,) and list(r.state) == ["contact", "contact"]
    np.testing.assert_array_equal(r.F_over_Eh, F)
    np.testing.assert_allclose(r.central_gap_over_h, curve.central_gap_over_h[idx], rtol=1e-8)
    np.testing.assert_allclose(r.a_over_R, curve.a_over_R[idx], rtol=1e-6, atol=1e-12)
    for k, i in enumerate(idx):
        # the state at the central gap found carries the load, to the error estimates
        back = lj_state(r.central_gap_over_h[k] / S, mu).F * scale
        tol = 10 * (r.error_estimate_over_Eh[k] + curve.error_estimate_over_Eh[i])
        assert abs(back - F[k]) <= tol


def test_contact_for_load_broadcasts_and_solves_a_repeated_point_once():
    F = np.array([[0.0], [0.05]])
    r = lj_law.contact_for_load(F, [RHO, RHO], SIG)
    assert r.a_over_R.shape == (2, 2) and r.n.shape == (2, 2)
    np.testing.assert_array_equal(r.a_over_R[:, 0], r.a_over_R[:, 1])
    assert np.all(r.a_over_R[1] > r.a_over_R[0])  # wider under the larger load
    assert np.all(r.mu == r.mu.flat[0]) and r.law == LJ


# --------------------------------------------------------------------------------------------
# below the pull-off


def test_a_load_below_the_pull_off_raises_naming_the_first_such_point():
    po = lj_law.pull_off(RHO, SIG).F_pulloff_over_Eh
    with pytest.raises(NoEquilibriumError, match=r"F_over_Eh=-1\.0 .*pulled off"):
        lj_law.contact_for_load([0.05, -1.0, -2.0], RHO, SIG)
    # the Dugdale law refuses a load below its own pull-off the same way
    assert -1.0 < lc.pull_off(RHO, SIG).F_pulloff_over_Eh and -1.0 < po
    with pytest.raises(NoEquilibriumError, match="pulled off"):
        lc.contact_for_load([0.05, -1.0], RHO, SIG)


def test_a_load_below_the_pull_off_is_reported_on_request():
    r = lj_law.contact_for_load([-1.0, 0.05], RHO, SIG, on_failure="report")
    assert list(r.state) == ["no-equilibrium", "contact"]
    assert math.isnan(r.a_over_R[0]) and r.a_over_R[1] > 0
    assert list(r.converged) == [False, True] and list(r.stable) == [False, True]
    np.testing.assert_array_equal(r.F_over_Eh, [-1.0, 0.05])


# --------------------------------------------------------------------------------------------
# the SI Cylinder


@pytest.fixture(scope="module")
def fibre():
    # built from (w, z0): the law gets these back
    R, E, w, z0 = 50e-9, 20e9, 0.05, 0.3e-9
    mu = w * math.sqrt(R / z0) / (E * z0)  # 0.108
    return Cylinder.from_modulus(R, E, work_of_adhesion=w, equilibrium_spacing=z0), (
        R,
        w,
        z0,
        mu,
    )


def test_cylinder_contact_for_a_load_in_si(fibre):
    cyl, (R, w, z0, mu) = fibre
    unit = w * math.sqrt(R / z0)  # N/m
    c = cyl.under(LennardJones).contact(load=0.2)
    st = lj_contact_for_load(0.2 / unit, mu)
    assert isinstance(c, CylinderLennardJonesContact)
    assert c.load == 0.2 and c.state == "contact" and c.stable is True
    assert c.contact_half_width == pytest.approx(st.half_width * math.sqrt(R * z0), rel=1e-8)
    assert c.central_gap == pytest.approx(st.central_gap_over_z0 * z0, rel=1e-8)
    assert c.error_estimate == pytest.approx(st.error_estimate * unit, rel=1e-5)
    assert c.nondimensional.mu == pytest.approx(mu, rel=1e-12)


def test_cylinder_pull_off_in_si(fibre):
    cyl, (R, w, z0, mu) = fibre
    unit = w * math.sqrt(R / z0)
    p = cyl.under(LennardJones).pull_off()
    ref = lj_pull_off(mu)
    assert isinstance(p, CylinderLennardJonesPullOff)
    assert p.pull_off_force == pytest.approx(ref.F_pulloff * unit, rel=1e-8)
    assert p.error_estimate == pytest.approx(ref.error_estimate * unit, rel=1e-5)
    assert p.central_gap_at_pull_off == pytest.approx(ref.central_gap_at_pulloff * z0, rel=1e-8)
    # below it no contact: said in N/m
    with pytest.raises(NoEquilibriumError, match=r"load=-5\.0 N/m .*pull-off force -\d.* N/m"):
        cyl.under(LennardJones).contact(load=-5.0)


def test_cylinder_refuses_what_the_law_does_not_do(fibre):
    cyl, _ = fibre
    with pytest.raises(TypeError, match="law"):
        cyl.contact(load=0.1, law="lennard-jones")
    with pytest.raises(TypeError, match="law"):
        cyl.pull_off(law="lennard-jones")
    with pytest.raises(ValueError, match=r"beyond the loads .* N/m"):
        cyl.under(LennardJones).contact(load=1e3)
    hertz = Cylinder.from_modulus(50e-9, 20e9, adhesion_range=0.3e-9)
    with pytest.raises(ValueError, match="the Lennard-Jones law needs adhesion"):
        hertz.under(LennardJones).contact(load=0.1)


# --------------------------------------------------------------------------------------------
# the Dugdale default and bad input


def test_the_dugdale_default_is_unchanged():
    F = np.array([-0.1, 0.0, 0.3])
    r = lc.contact_for_load(F, RHO, 0.05)
    assert isinstance(r, NormalContact)
    assert r.to_dict() == lj_free_contact(F, 0.05).to_dict()
    c = lc.load_curve(RHO, 0.05, num=20, num_noncontact=5)
    assert isinstance(c, LoadCurve)
    assert c.to_dict() == lc.laws.dugdale.load_curve(RHO, 0.05, num=20, num_noncontact=5).to_dict()
    cyl = Cylinder.from_modulus(50e-9, 100e9, cohesive_stress=1e9, adhesion_range=0.5e-9)
    k = cyl.contact(load=[0.0, 1.0])
    assert isinstance(k, CylinderContact)
    assert isinstance(cyl.pull_off(), CylinderPullOff)


def lj_free_contact(F, s):
    """The Dugdale law's module: the same function as linecontact.contact_for_load."""
    return lc.laws.dugdale.contact_for_load(F, RHO, s)


@pytest.mark.parametrize(
    ("call", "match"),
    [
        (lambda: lj_law.contact_for_load(0.0, RHO, SIG_BAD), f"mu={MU_BAD:.6g}"),
        (lambda: lj_law.load_curve(RHO, SIG_BAD), f"mu={MU_BAD:.6g}"),
        (lambda: lj_law.contact_for_load(0.0, RHO, 0.0), "sigma0_over_E must be > 0"),
        (lambda: lj_law.load_curve(RHO, 0.0), "sigma0_over_E must be > 0"),
        (lambda: lj_law.contact_for_load([0.0, 0.1], [RHO, RHO], [SIG, 0.0]), "> 0"),
        (lambda: lj_law.contact_for_load(math.nan, RHO, SIG), "F_over_Eh"),
        (lambda: lj_law.contact_for_load(3.0, RHO, SIG), "beyond the loads"),
        (lambda: lj_law.load_curve(RHO, SIG, F_max_over_Eh=3.0), "beyond the loads"),
        (lambda: lj_law.load_curve(RHO, SIG, F_max_over_Eh=-1.0), "F_max_over_Eh"),
    ],
)
def test_bad_input_is_refused_before_any_solve(call, match):
    with pytest.raises(ValueError, match=match) as exc:
        call()
    assert not isinstance(exc.value, NoEquilibriumError)


# --------------------------------------------------------------------------------------------
# a law is a module


def test_the_modules_share_names_and_argument_order():
    import inspect

    from linecontact.laws import dugdale

    for name in ("pull_off", "contact_for_load", "load_curve"):
        md, lj = (inspect.signature(getattr(m, name)) for m in (dugdale, lj_law))
        positional = [p for p in lj.parameters.values() if p.kind is p.POSITIONAL_OR_KEYWORD]
        assert [p.name for p in positional] == list(md.parameters)[: len(positional)]
    assert dugdale.pull_off is lc.pull_off and lc.laws.lennard_jones is lj_law


@pytest.mark.parametrize(
    "call",
    [
        lambda c: lc.pull_off(RHO, SIG, law="lennard-jones"),
        lambda c: lc.contact_for_load(0.1, RHO, SIG, law="lennard-jones"),
        lambda c: lc.load_curve(RHO, SIG, law="lennard-jones"),
        lambda c: lc.load_curve(RHO, SIG, F_max_over_Eh=1.0),
        lambda c: c.pull_off(law="lennard-jones"),
        lambda c: c.contact(load=0.1, law="lennard-jones"),
    ],
)
def test_the_law_keyword_is_gone_a_law_is_a_module(fibre, call):
    # deleted before 1.0 (issue 32): linecontact.laws.lennard_jones and the Cylinder's
    # lennard_jones_* methods are the Lennard-Jones law
    with pytest.raises(TypeError, match="law|F_max_over_Eh"):
        call(fibre[0])


def test_the_load_limit_is_ten_rigid_pull_offs():
    _, _, scale = native_groups(RHO, SIG)
    assert LJ_LOAD_MAX == pytest.approx(-10 * lennard_jones_rigid_pull_off()[0], rel=0.02)
    with pytest.raises(ValueError, match=f"F_over_Eh = {LJ_LOAD_MAX * scale:.6g}"):
        lj_law.contact_for_load(1.01 * LJ_LOAD_MAX * scale, RHO, SIG)


# --------------------------------------------------------------------------------------------
# the command line


@pytest.mark.filterwarnings("error::DeprecationWarning")  # the CLI calls the module
def test_cli_curve_lennard_jones_json(capsys, curve):
    code, out, err = run(
        capsys, "curve", "--R-over-h", "100", "--sigma0-over-E", "0.01", "--law", LJ, "--json"
    )
    assert code == 0, err
    assert "deprecated" not in err
    doc = document(out)
    p = doc["parameters"]
    assert p["law"] == LJ and p["R_over_h"] == RHO and p["sigma0_over_E"] == SIG
    assert p["mu"] == pytest.approx(curve.mu, rel=1e-15) and "maugis_parameter" in p
    recs = doc["results"]
    assert set(recs[0]) == {
        "F_over_Eh",
        "a_over_R",
        "central_gap_over_h",
        "error_estimate_over_Eh",
        "stable",
        "turning_point",
        "pulloff",
    }
    F = np.array([r["F_over_Eh"] for r in recs])
    assert F.shape == curve.F_over_Eh.shape  # the API's curve (to the Newton tolerance)
    np.testing.assert_allclose(
        F, curve.F_over_Eh, rtol=1e-9, atol=1e-9 * abs(curve.F_over_Eh).max()
    )
    assert sum(r["pulloff"] for r in recs) == 1
    i = next(k for k, r in enumerate(recs) if r["pulloff"])
    assert recs[i]["F_over_Eh"] == min(r["F_over_Eh"] for r in recs)


@pytest.mark.filterwarnings("error::DeprecationWarning")  # the CLI calls the module
def test_cli_curve_lennard_jones_si_json(capsys):
    argv = [
        "--radius",
        "50e-9",
        "--modulus",
        "20e9",
        "--work-of-adhesion",
        "0.05",
        "--z0",
        "0.3e-9",
    ]
    code, out, err = run(capsys, "curve", *argv, "--law", LJ, "--length", "1e-6", "--json")
    assert code == 0, err
    assert "deprecated" not in err
    doc = document(out)
    p = doc["parameters"]
    assert p["law"] == LJ and p["z0_m"] == 0.3e-9 and p["radius_m"] == 50e-9
    assert p["mu"] == pytest.approx(0.05 * math.sqrt(50 / 0.3) / (20e9 * 0.3e-9), rel=1e-12)
    Eh = 20e9 * p["h_m"]
    for r in doc["results"]:
        for k in ("F_N_per_m", "a_m", "central_gap_m", "error_estimate_N_per_m", "F_total_N"):
            assert k in r
        assert r["F_N_per_m"] == pytest.approx(r["F_over_Eh"] * Eh, rel=1e-15)
        assert r["error_estimate_N_per_m"] == pytest.approx(
            r["error_estimate_over_Eh"] * Eh, rel=1e-15
        )
        assert r["central_gap_m"] == pytest.approx(r["central_gap_over_h"] * p["h_m"], rel=1e-15)
    assert doc["units"]["F_N_per_m"] == "N/m" and doc["units"]["central_gap_m"] == "m"


@pytest.mark.filterwarnings("error::DeprecationWarning")  # the CLI calls the module
def test_cli_normal_lennard_jones_reports_a_load_below_the_pull_off(capsys):
    code, out, err = run(
        capsys,
        "normal",
        "--R-over-h",
        "100",
        "--sigma0-over-E",
        "0.01",
        "--F-over-Eh",
        "-1",
        "0.05",
        "--law",
        LJ,
        "--json",
    )
    assert code == 0, err
    assert "deprecated" not in err
    doc = document(out)
    assert doc["parameters"]["law"] == LJ
    below, ok = doc["results"]
    assert below["state"] == "no-equilibrium" and below["a_over_R"] is None
    assert "pull-off" in below["reason"] and below["F_over_Eh"] == -1.0
    assert ok["state"] == "contact" and ok["a_over_R"] > 0 and ok["error_estimate_over_Eh"] > 0


@pytest.mark.parametrize(
    ("argv", "code_", "words"),
    [
        # the Lennard-Jones group said in the flags typed (no mu on the command line)
        (
            ["curve", "--R-over-h", "100", "--sigma0-over-E", repr(SIG_BAD), "--law", LJ],
            2,
            "--sigma0-over-E sqrt(--R-over-h) / 1.04 = ",
        ),
        (["curve", "--R-over-h", "100", "--sigma0-over-E", "0", "--law", LJ], 2, "> 0"),
        (["curve", "--R-over-h", "100", "--sigma0-over-E", "0.01", "--law", "lj"], 2, "--law"),
        (
            ["curve", "--R-over-h", "100", "--sigma0-over-E", "0.01", "--law", LJ, "--num", "5"],
            2,
            "--num applies to --law dugdale",
        ),
        (
            ["curve", "--R-over-h", "100", "--sigma0-over-E", "0.01", "--F-max-over-Eh", "1"],
            2,
            "apply to --law lennard-jones",
        ),
        (
            ["normal", "--R-over-h", "100", "--sigma0-over-E", "0.01", "--a-over-R", "0.01"]
            + ["--law", LJ],
            2,
            "give loads",
        ),
        (
            ["normal", "--radius", "50e-9", "--modulus", "20e9", "--work-of-adhesion", "0.05"]
            + ["--z0", "0.3e-9", "--load", "1e3", "--law", LJ],
            2,
            "N/m",
        ),
        (
            ["normal", "--R-over-h", "100", "--sigma0-over-E", "0.01", "--F-over-Eh", "-1"]
            + ["--law", LJ],
            1,
            "pull-off",
        ),
    ],
)
def test_cli_lennard_jones_exit_codes(capsys, argv, code_, words):
    code, out, err = run(capsys, *argv)
    assert code == code_
    assert err.count("error:") == 1 and "Traceback" not in err and words in err
    if code_ == 2:
        assert out == ""
