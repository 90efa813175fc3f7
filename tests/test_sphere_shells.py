"""The sphere in every shell: one number from Python, the command line, a sweep and the API.

``--body sphere`` on ``pulloff``, ``normal`` and ``curve`` gives the records of
:class:`linecontact.Sphere` (forces in N: ``F_pulloff_N``, ``F_N``); what a sphere has not
(the Lennard-Jones law, a cross-section, ``--length``, a wire's loads per length) is refused
with one ``error:`` line naming the flag, exit status 2; the Python lines of a sphere's
computation run and give its number.
"""

from __future__ import annotations

import json

import numpy as np
import pytest

import linecontact as lc
from linecontact import operations
from linecontact.cli import main
from linecontact.operations._declare import Inputs
from linecontact.operations._written import python

#: one number in every shell, within a few ulp: the shells may call with other array shapes,
#: whose SIMD paths round apart in the last bits on some CPUs (README)
ULP = 1e-14
SI = ["--radius", "1e-6", "--modulus", "50e9", "--sigma0", "1e8", "--h", "1e-9"]
TIP = dict(radius=1e-6, modulus=50e9, cohesive_stress=1e8, adhesion_range=1e-9)


def _cli(capsys, argv: list[str]) -> list[dict]:
    capsys.readouterr()
    main([*argv, "--json"])
    return json.loads(capsys.readouterr().out)["results"]


def test_the_pull_off_is_one_number_in_python_the_cli_and_a_sweep(capsys):
    tip = lc.Sphere.from_modulus(
        TIP["radius"], TIP["modulus"], cohesive_stress=1e8, adhesion_range=1e-9
    )
    want = tip.pull_off().pull_off_force
    rec = _cli(capsys, ["pulloff", "--body", "sphere", *SI])[0]
    assert rec["F_pulloff_N"] == pytest.approx(want, rel=ULP)
    assert rec["F_pulloff_over_EhR"] * 50e9 * 1e-9 * 1e-6 == pytest.approx(want, rel=ULP)
    ds = lc.sweep("pulloff", body="sphere", radius=[1e-6, 2e-6], modulus=50e9, sigma0=1e8, h=1e-9)
    assert ds["F_pulloff_N"].values[0] == pytest.approx(want, rel=ULP)
    two = lc.Sphere.from_modulus(2e-6, 50e9, cohesive_stress=1e8, adhesion_range=1e-9)
    assert ds["F_pulloff_N"].values[1] == pytest.approx(two.pull_off().pull_off_force, rel=ULP)


def test_the_contact_and_the_curve_are_one_number_in_python_and_the_cli(capsys):
    tip = lc.Sphere.from_modulus(1e-6, 50e9, cohesive_stress=1e8, adhesion_range=1e-9)
    forces = [-1e-8, 0.0, 1e-7]
    got = tip.contact(load=forces)
    recs = _cli(capsys, ["normal", "--body", "sphere", *SI, "--force", *map(str, forces)])
    assert [r["a_m"] for r in recs] == pytest.approx(got.contact_radius.tolist(), rel=ULP)
    assert [r["delta_m"] for r in recs] == pytest.approx(got.approach.tolist(), rel=ULP)
    # at the radii found, the state gives the loads back
    back = tip.contact(contact_radius=got.contact_radius).load
    # a load of 0 is a difference of terms of the pull-off's size: rounding of that size
    scale = abs(tip.pull_off().pull_off_force)
    np.testing.assert_allclose(back, forces, rtol=1e-12, atol=1e-13 * scale)
    curve = tip.load_curve(num=20, num_noncontact=5)
    recs = _cli(capsys, ["curve", "--body", "sphere", *SI, "--num", "20", "--num-noncontact", "5"])
    assert [r["F_N"] for r in recs] == pytest.approx(curve.load.tolist(), rel=ULP)
    assert min(r["F_N"] for r in recs) == pytest.approx(tip.pull_off().pull_off_force, rel=ULP)


def test_the_groups_give_the_nondimensional_solvers_numbers(capsys):
    rec = _cli(
        capsys, ["pulloff", "--body", "sphere", "--R-over-h", "1e4", "--sigma0-over-E", "1e-3"]
    )[0]
    p = lc.sphere_pull_off(1e4, 1e-3)
    assert rec["F_pulloff_over_EhR"] == p.F_pulloff_over_EhR
    assert rec["F_pulloff_over_piwR"] == pytest.approx(-1.85145076263, rel=1e-11)
    recs = _cli(
        capsys,
        ["normal", "--body", "sphere", "--R-over-h", "1e4", "--sigma0-over-E", "1e-3",
         "--F-over-EhR", "0", "0.01"],
    )  # fmt: skip
    r = lc.sphere_contact_for_load([0.0, 0.01], 1e4, 1e-3)
    assert [x["a_over_R"] for x in recs] == r.a_over_R.tolist()


@pytest.mark.parametrize(
    ("argv", "flag"),
    [
        (["normal", "--body", "sphere", *SI, "--law", "lennard-jones", "--force", "0"], "--law"),
        (["curve", "--body", "sphere", "--R-over-h", "1e10", "--sigma0-over-E", "0.01",
          "--law", "lennard-jones"], "--law"),  # Tabor's parameter over 50: no curve
        (["curve", "--body", "sphere", "--R-over-h", "100", "--sigma0-over-E", "0.01",
          "--law", "lennard-jones", "--num", "5"], "--num"),
        (["curve", "--body", "sphere", *SI, "--law", "lennard-jones", "--a-max", "1e-8"],
         "--a-max"),
        (["curve", "--body", "sphere", "--R-over-h", "1e6", "--sigma0-over-E", "0.5",
          "--law", "lennard-jones"], "--law"),  # the sphere's range, not the wire's 400
        (["curve", "--body", "sphere", *SI, "--F-max", "1e-9"], "--F-max"),
        (["pulloff", "--body", "sphere", *SI, "--cross-section", "hexagon"], "--cross-section"),
        (["pulloff", "--body", "sphere", *SI, "--corner-radius", "1e-9"], "--corner-radius"),
        (["pulloff", "--body", "sphere", *SI, "--corner-radius", "0"], "--corner-radius"),
        (["pulloff", "--body", "sphere", *SI, "--length", "1e-6"], "--length"),
        (["normal", "--body", "sphere", *SI, "--load", "1"], "--load"),
        (["normal", "--body", "sphere", "--R-over-h", "10", "--sigma0-over-E", "0.1",
          "--F-over-Eh", "1"], "--F-over-Eh"),
        (["normal", *SI, "--force", "1e-9"], "--force"),
        (["normal", "--body", "sphere", *SI, "--force", "-1"], "--force"),
        (["normal", "--body", "sphere", *SI, "--force", "1e12"], "--force"),
        (["normal", "--body", "sphere", *SI, "--force", "1e-9", "--branch", "unstable"],
         "--branch"),
        (["curve", "--body", "sphere", *SI, "--F-max", "1"], "--F-max"),
        (["pulloff", "--body", "ball", *SI], "--body"),
    ],
)  # fmt: skip
def test_what_a_sphere_has_not_is_one_error_line_naming_the_flag(capsys, argv, flag):
    capsys.readouterr()
    try:
        status = main(argv)
    except SystemExit as e:  # argparse's own refusal (an invalid choice)
        status = e.code
    err = capsys.readouterr().err.strip().splitlines()
    assert status == 2 and len(err) == 1, err
    assert "error:" in err[0] and flag in err[0], err[0]


def test_a_spheres_python_lines_give_its_number():
    op = operations.get("pulloff")
    values = {"body": "sphere", "radius": 1e-6, "modulus": 5e10, "sigma0": 1e8, "h": 1e-9}
    inputs = Inputs(op, values)
    table = op.run(inputs)
    code = python(inputs)
    assert "sphere = lc.Sphere.from_modulus(1e-6, 5e10, cohesive_stress=1e8" in code
    assert "result = sphere.pull_off()" in code
    space: dict = {}
    exec(code.replace("print(result)", ""), space)  # the lines written, nothing else
    assert space["result"].pull_off_force == pytest.approx(table.columns["F_pulloff_N"][0], rel=ULP)


def test_python_refuses_a_wires_problem_and_another_law_naming_the_pair():
    tip = lc.Sphere.from_modulus(1e-6, 50e9, cohesive_stress=1e8, adhesion_range=1e-9)
    with pytest.raises(AttributeError, match="push is not written for a sphere"):
        tip.push  # noqa: B018 - the attribute's refusal is the test
    lj = lc.Sphere.from_modulus(1e-6, 50e9, adhesion=lc.LennardJones(0.1, 3e-10))
    with pytest.raises(ValueError, match="contact is not written for a sphere under the lennard"):
        lj.contact(load=0.0)
    with pytest.raises(ValueError, match="under displacement control is not written"):
        lj.pull_off(control="displacement")
    with pytest.raises(ValueError, match="max_radius, num and num_noncontact are the Dugdale"):
        lj.load_curve(num=10)
    with pytest.raises(ValueError, match=r"max_load must be in \[0, 3\.14159e-06\] N"):
        lj.load_curve(max_load=-1e-9)
    with pytest.raises(ValueError, match="max_load is the Lennard-Jones curve's end"):
        tip.load_curve(max_load=1e-9)
    with pytest.raises(ValueError, match=r"max_load must be one number \[N\]"):
        lj.load_curve(max_load=np.array([1e-9]))
    with pytest.raises(ValueError, match="under it a sphere's problems are pull_off, load_curve"):
        lj.contact(load=0.0)
    probe = lc.Sphere.from_modulus(1e-3, 1e9, adhesion=lc.LennardJones(1.0, 3e-10))
    with pytest.raises(ValueError, match=r"over 50, .* or a radius below 3\.38e-06 m"):
        probe.load_curve()  # Tabor's parameter 333, said in SI terms with what to do
    with pytest.raises(ValueError, match="give exactly one of load"):
        tip.contact()
    with pytest.raises(lc.NoEquilibriumError, match=r"load = -1e-06 N is below the pull-off"):
        tip.contact(load=[0.0, -1e-6])
    with pytest.raises(ValueError, match=r"load must be in \[-5e\+07, 5e\+07\] N"):
        tip.contact(load=1e10)
    with pytest.raises(ValueError, match=r"contact_radius must be in"):
        tip.contact(contact_radius=-1.0)
    with pytest.raises(ValueError, match=r"max_radius must be in .* m"):
        tip.load_curve(max_radius=-1e-9)
    with pytest.raises(ValueError, match=r"control must be 'load' or 'displacement'"):
        tip.pull_off(control="force")
    # Tabor's parameter from its definition, (R w^2/(E^2 z0^3))^(1/3), z0 the law's
    z0 = 16 * tip.adhesion_range / (9 * 3**0.5)
    w = tip.work_of_adhesion
    mu = (1e-6 * w * w / (50e9**2 * z0**3)) ** (1 / 3)
    assert tip.tabor_parameter == pytest.approx(mu, rel=1e-14)


def test_the_lennard_jones_spheres_pull_off_is_one_number_in_python_and_the_cli(capsys):
    tip = lc.Sphere.from_modulus(20e-9, 50e9, work_of_adhesion=0.1, equilibrium_spacing=3e-10)
    lj = tip.under(lc.LennardJones)
    want = lj.pull_off()
    si = ["--radius", "20e-9", "--modulus", "50e9", "--work-of-adhesion", "0.1", "--z0", "3e-10"]
    rec = _cli(capsys, ["pulloff", "--body", "sphere", "--law", "lennard-jones", *si])[0]
    assert rec["F_pulloff_N"] == pytest.approx(want.pull_off_force, rel=ULP)
    # in pi w R: the Lennard-Jones sphere's own number, and below the matched Dugdale step's
    assert want.pull_off_force / (np.pi * 0.1 * 20e-9) == pytest.approx(
        want.nondimensional.F_pulloff_over_piwR, rel=1e-12
    )
    assert want.pull_off_force < tip.pull_off().pull_off_force < 0
    nd = ["--R-over-h", str(tip.R_over_h), "--sigma0-over-E", str(tip.sigma0_over_E)]
    capsys.readouterr()
    main(["pulloff", "--body", "sphere", "--law", "lennard-jones", *nd, "--json"])
    doc = json.loads(capsys.readouterr().out)
    assert doc["parameters"]["tabor_parameter"] == pytest.approx(tip.tabor_parameter, rel=1e-12)
    rec = doc["results"][0]
    assert rec["F_pulloff_over_piwR"] == pytest.approx(
        want.nondimensional.F_pulloff_over_piwR, rel=1e-9
    )


def test_a_colloidal_probe_beyond_the_self_consistent_range_is_the_limit_form(capsys):
    # a 50 um probe on a soft substrate: Tabor's parameter beyond 50
    probe = lc.Sphere.from_modulus(
        50e-6, 0.3e9, work_of_adhesion=0.1, equilibrium_spacing=3e-10
    ).under(lc.LennardJones)
    assert 55 < probe.tabor_parameter < 65
    got = probe.pull_off()
    assert got.nondimensional.method == "limit"
    assert got.pull_off_force == pytest.approx(-1.5 * np.pi * 0.1 * 50e-6, rel=2e-3)  # JKR
    si = ["--radius", "50e-6", "--modulus", "0.3e9", "--work-of-adhesion", "0.1", "--z0", "3e-10"]
    rec = _cli(capsys, ["pulloff", "--body", "sphere", "--law", "lennard-jones", *si])[0]
    assert rec["F_pulloff_N"] == pytest.approx(got.pull_off_force, rel=ULP)
    assert rec["method"] == "limit"
    assert rec["error_estimate"] == pytest.approx(got.nondimensional.error_estimate, rel=ULP)


def test_the_lennard_jones_spheres_curve_is_one_curve_in_python_and_the_cli(capsys):
    tip = lc.Sphere.from_modulus(20e-9, 50e9, work_of_adhesion=0.1, equilibrium_spacing=3e-10)
    lj = tip.under(lc.LennardJones)
    unit = np.pi * 0.1 * 20e-9
    c = lj.load_curve(max_load=2 * unit)
    # a second way: the curve in Tabor's units, scaled here
    ref = lc.sphere_lj_curve(lj.tabor_parameter, F_max=2.0)
    assert c.load.tolist() == pytest.approx((ref.F_over_piwR * unit).tolist(), rel=1e-12)
    assert c.approach.tolist() == pytest.approx((ref.approach_over_z0 * 3e-10).tolist(), rel=1e-12)
    assert c.load_error.tolist() == pytest.approx((ref.error_estimate * unit).tolist(), rel=1e-9)
    assert c.load[-1] >= 2 * unit and c.stable[-1]
    assert c.pull_off_force == pytest.approx(lj.pull_off().pull_off_force, rel=1e-4)
    assert np.min(c.load) >= c.pull_off_force * (1 + 1e-12)
    si = ["--radius", "20e-9", "--modulus", "50e9", "--work-of-adhesion", "0.1", "--z0", "3e-10"]
    capsys.readouterr()
    main(["curve", "--body", "sphere", "--law", "lennard-jones", *si, "--json"])
    doc = json.loads(capsys.readouterr().out)
    default = lj.load_curve()
    assert [r["F_N"] for r in doc["results"]] == pytest.approx(default.load.tolist(), rel=ULP)
    assert [r["F_error_N"] for r in doc["results"]] == pytest.approx(
        default.load_error.tolist(), rel=1e-9
    )
    assert [r["a_m"] for r in doc["results"]] == pytest.approx(
        default.contact_radius.tolist(), rel=ULP, abs=1e-30
    )
    assert doc["parameters"]["F_pulloff_N"] == pytest.approx(default.pull_off_force, rel=ULP)
    assert doc["parameters"]["tabor_parameter"] == pytest.approx(lj.tabor_parameter, rel=ULP)


def test_the_curves_refusal_says_a_change_that_works(capsys):
    argv = ["curve", "--body", "sphere", "--law", "lennard-jones", "--R-over-h", "1e6"]
    assert main([*argv, "--sigma0-over-E", "0.5"]) == 2
    err = capsys.readouterr().err
    assert "over 50" in err and "400" not in err
    below = float(err.split("--sigma0-over-E below ")[1].split(",")[0])
    assert main([*argv, "--sigma0-over-E", str(0.999 * below), "--json"]) == 0  # it works


def test_a_sweep_of_the_lennard_jones_pull_off_gives_pythons_numbers():
    pytest.importorskip("xarray")
    radii, E = [20e-9, 50e-6], 0.3e9  # Tabor's parameter 0.5 and 59: both methods
    ds = lc.sweep(
        "pulloff", body="sphere", law="lennard-jones", radius=radii, modulus=E,
        work_of_adhesion=0.1, z0=3e-10,
    )  # fmt: skip
    for R, method in zip(radii, ("self-consistent", "limit"), strict=True):
        tip = lc.Sphere.from_modulus(R, E, work_of_adhesion=0.1, equilibrium_spacing=3e-10)
        want = tip.under(lc.LennardJones).pull_off()
        got = ds.sel(radius=R)
        assert float(got["F_pulloff_N"]) == pytest.approx(want.pull_off_force, rel=1e-9)
        assert str(got["method"].values) == method == want.nondimensional.method


def test_a_sweep_of_the_contact_and_the_curve_gives_pythons_numbers():
    pytest.importorskip("xarray")
    common = dict(body="sphere", radius=[20e-9, 1e-6], modulus=50e9, sigma0=1e8, h=1e-9)
    ds = lc.sweep("normal", force=[0.0, 1e-8], **common)
    curve = lc.sweep("curve", num=10, num_noncontact=3, **common)
    for R in (20e-9, 1e-6):
        tip = lc.Sphere.from_modulus(R, 50e9, cohesive_stress=1e8, adhesion_range=1e-9)
        got = ds["a_m"].sel(radius=R).transpose("force").values.tolist()
        assert got == pytest.approx(tip.contact(load=[0.0, 1e-8]).contact_radius.tolist(), rel=ULP)
        c = tip.load_curve(num=10, num_noncontact=3)
        F = curve["F_N"].sel(radius=R).values
        assert F[: c.load.size].tolist() == pytest.approx(c.load.tolist(), rel=ULP)


def test_a_spheres_width_warnings_speak_of_a_sphere(capsys):
    # found by fuzzing: the wire's words (half-width, half-plane, cylinder) for a sphere
    tiny = ["--radius", "1e-9", "--modulus", "1e12", "--work-of-adhesion", "1e-3", "--z0", "1e-9"]
    assert main(["curve", "--body", "sphere", "--law", "lennard-jones", *tiny]) == 0
    err = capsys.readouterr().err
    assert "the contact radius" in err and "half-space theory" in err
    assert "half-width" not in err and "cylinder" not in err
