"""CLI slide-init and roll: wiring and format only (the numbers are tested in test_tangential)."""

import json
import math

import numpy as np
import pytest

from linecontact import (
    Cylinder,
    contact_for_load,
    sliding_initiation,
    sliding_initiation_coulomb,
    steady_rolling,
    steady_rolling_coulomb,
)
from linecontact.cli import main


def run(capsys, *argv):
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def records(text):
    """The records of a --json output, each with the run's parameters merged in."""
    doc = json.loads(text)
    assert set(doc) == {"linecontact", "command", "parameters", "units", "results"}
    return [{**doc["parameters"], **r} for r in doc["results"]]


def test_slide_init_json_contract(capsys):
    code, out, err = run(
        capsys, "slide-init", "--tau0-over-E", "0.01", "--d-over-a", "0.2", "0.5", "--json"
    )
    assert code == 0, err
    recs = records(out)
    ref = sliding_initiation(0.01, [0.2, 0.5])
    assert [r["d_over_a"] for r in recs] == [0.2, 0.5]
    assert [r["T_over_Ea"] for r in recs] == list(ref.T_over_Ea)
    assert all(r["state"] == "stick-slip" and r["friction"] == "constant" for r in recs)


def test_roll_json_contract(capsys):
    code, out, err = run(
        capsys, "roll", "--tau0-over-E", "0.01", "--d-over-a", "-0.5", "0.5", "--json"
    )
    assert code == 0, err
    recs = records(out)
    ref = steady_rolling(0.01, [-0.5, 0.5])
    for rec, T, c in zip(recs, ref.T_over_Ea, ref.creep_over_V, strict=True):
        assert set(rec) >= {"d_over_a", "T_over_Ea", "creep_over_V", "state"}
        assert rec["T_over_Ea"] == T and rec["creep_over_V"] == c < 0


def test_given_load_with_sliding_is_reported_not_an_error(capsys):
    code, out, err = run(
        capsys,
        "roll",
        "--tau0-over-E",
        "0.01",
        "--T-over-Ea",
        "0.01",
        "0.03",
        "--method",
        "collocation",
        "--json",
    )
    assert code == 0, err
    ok, sliding = records(out)
    assert ok["state"] == "stick-slip" and ok["converged"] is True
    assert ok["n_collocation"] > 0 and ok["residual_force"] < 1e-12
    assert ok["d_over_a"] == pytest.approx(-0.5, abs=1e-13)
    assert sliding == {
        **sliding,
        "state": "sliding",
        "d_over_a": None,
        "creep_over_V": None,
        "T_over_Ea": 0.03,
    }


def test_table_output(capsys):
    code, out, _ = run(capsys, "slide-init", "--tau0-over-E", "0.01", "--T-over-Ea", "0.01", "0.02")
    assert code == 0
    lines = out.splitlines()
    assert lines[0].startswith("# initiation of sliding, constant friction stress")
    assert "tau0_over_E = 0.01" in lines[1]
    assert lines[2].split() == ["d_over_a", "T_over_Ea", "T_over_T_full_slip", "state"]
    assert lines[3].split()[-1] == "stick-slip" and lines[4].split()[-1] == "sliding"


def test_coulomb_nondimensional(capsys):
    code, out, err = run(
        capsys,
        "roll",
        "--friction",
        "coulomb",
        "--mu",
        "0.3",
        "--a-over-R",
        "0.01",
        "--T-over-muF",
        "0.75",
        "--json",
    )
    assert code == 0, err
    (rec,) = records(out)
    ref = steady_rolling_coulomb(0.3, 0.01, T_over_muF=0.75)
    assert rec["friction"] == "coulomb" and rec["T_over_muF"] == 0.75
    assert rec["d_over_a"] == ref.d_over_a == pytest.approx(0.0, abs=1e-15)
    assert rec["creep_over_V"] == ref.creep_over_V and rec["T_over_Ea"] == ref.T_over_Ea
    # --T-over-Ea is converted with the Hertz load
    code, out, _ = run(
        capsys,
        "slide-init",
        "--friction",
        "coulomb",
        "--mu",
        "0.3",
        "--a-over-R",
        "0.01",
        "--T-over-Ea",
        repr(float(ref.T_over_Ea)),
        "--json",
    )
    (rec,) = records(out)
    assert rec["T_over_muF"] == pytest.approx(0.75, rel=1e-14)
    assert rec["d_over_a"] == pytest.approx(
        sliding_initiation_coulomb(0.3, 0.01, T_over_muF=0.75).d_over_a, rel=1e-14
    )


def test_normal_problem_from_the_groups(capsys):
    code, out, err = run(
        capsys,
        "slide-init",
        "--R-over-h",
        "100",
        "--sigma0-over-E",
        "0.01",
        "--F-over-Eh",
        "0.5",
        "--tau0-over-E",
        "0.01",
        "--d-over-a",
        "0.5",
        "--json",
    )
    assert code == 0, err
    (rec,) = records(out)
    assert rec["a_over_R"] == contact_for_load(0.5, 100, 0.01).a_over_R
    assert rec["F_over_Eh"] == 0.5


def test_si_mode_matches_the_api(capsys):
    argv = [
        "--radius",
        "50e-9",
        "--modulus",
        "100e9",
        "--sigma0",
        "1e9",
        "--h",
        "0.5e-9",
        "--load",
        "1.0",
        "--tau0",
        "1e9",
        "--tangential-load",
        "1",
        "5",
        "--json",
    ]
    code, out, err = run(capsys, "slide-init", *argv)
    assert code == 0, err
    recs = records(out)
    cyl = Cylinder.from_modulus(50e-9, 100e9, cohesive_stress=1e9, adhesion_range=0.5e-9)
    ref = cyl.sliding_initiation(1.0, friction_stress=1e9, tangential_load=[1, 5])
    assert [r["d_m"] for r in recs] == list(ref.stick_zone_end)
    assert all(r["a_m"] == ref.contact_half_width for r in recs)
    assert [r["T_N_per_m"] for r in recs] == pytest.approx([1, 5], rel=1e-14)
    assert recs[0]["T_full_slip_N_per_m"] == pytest.approx(2 * ref.contact_half_width * 1e9)
    # --T-over-Ea in SI mode goes through the same contact
    code, out, _ = run(
        capsys, "slide-init", *argv[:-4], "--T-over-Ea", repr(recs[1]["T_over_Ea"]), "--json"
    )
    assert records(out)[0]["d_over_a"] == pytest.approx(recs[1]["d_over_a"], rel=1e-12)


def test_si_mode_coulomb_needs_no_adhesion_range(capsys):
    code, out, err = run(
        capsys,
        "roll",
        "--friction",
        "coulomb",
        "--mu",
        "0.3",
        "--radius",
        "1e-3",
        "--E1",
        "200e9",
        "--nu1",
        "0.3",
        "--E2",
        "200e9",
        "--nu2",
        "0.3",
        "--load",
        "1e4",
        "--d-over-a",
        "0",
        "--json",
    )
    assert code == 0, err
    (rec,) = records(out)
    E = 1 / (2 * (1 - 0.09) / 200e9)
    a = math.sqrt(4 * 1e4 * 1e-3 / (math.pi * E))
    assert rec["a_m"] == pytest.approx(a, rel=1e-12)
    assert rec["T_N_per_m"] == pytest.approx(0.75 * 0.3 * 1e4, rel=1e-12)
    assert rec["creep_over_V"] == pytest.approx(-0.3 * a / 1e-3 / 2, rel=1e-12)


BAD = [
    (
        ["slide-init", "--tau0-over-E", "0", "--d-over-a", "0.5"],
        "--tau0-over-E must be in [1e-12, 1], got 0.0",
    ),
    (
        ["roll", "--tau0-over-E", "0.01", "--d-over-a", "1.5"],
        "--d-over-a must be in (-1, 1), got 1.5",
    ),
    (
        ["slide-init", "--tau0-over-E", "0.01", "--d-over-a", "1"],
        "--d-over-a must be in [0, 1), got 1.0",
    ),
    (
        ["roll", "--tau0-over-E", "nan", "--d-over-a", "0.5"],
        "--tau0-over-E must be a finite number in [1e-12, 1], got nan",
    ),
    (
        ["roll", "--tau0-over-E", "0.01", "--T-over-Ea", "-1"],
        "--T-over-Ea must be in [0, 1e+12], got -1.0",
    ),
    (
        ["roll", "--tau0-over-E", "0.01"],
        "give exactly one of --d-over-a, --T-over-Ea, --T-over-muF (Coulomb) or "
        "--tangential-load [N/m] (SI)",
    ),
    (
        ["roll", "--tau0-over-E", "0.01", "--d-over-a", "0", "--T-over-Ea", "0.01"],
        "give exactly one of --d-over-a",
    ),
    (["roll", "--d-over-a", "0.5"], "give the friction stress --tau0-over-E"),
    (
        ["roll", "--tau0-over-E", "0.01", "--mu", "0.3", "--d-over-a", "0.5"],
        "--mu is the Coulomb friction coefficient: add --friction coulomb",
    ),
    (
        ["roll", "--friction", "coulomb", "--a-over-R", "0.01", "--d-over-a", "0.5"],
        "--friction coulomb needs the friction coefficient --mu",
    ),
    (
        ["roll", "--friction", "coulomb", "--mu", "0.3", "--d-over-a", "0.5"],
        "Coulomb friction needs the Hertz half-width: give --a-over-R",
    ),
    (
        [
            "slide-init",
            "--friction",
            "coulomb",
            "--mu",
            "0",
            "--a-over-R",
            "0.01",
            "--d-over-a",
            "0.5",
        ],
        "--mu must be in [1e-06, 100], got 0.0",
    ),
    (
        [
            "slide-init",
            "--friction",
            "coulomb",
            "--mu",
            "0.3",
            "--tau0-over-E",
            "0.01",
            "--a-over-R",
            "0.01",
            "--d-over-a",
            "0.5",
        ],
        "--tau0-over-E and --tau0 are for --friction constant",
    ),
    (
        ["slide-init", "--tau0-over-E", "0.01", "--T-over-muF", "0.5"],
        "--T-over-muF is for --friction coulomb; use --T-over-Ea",
    ),
    (["slide-init", "--tau0", "1e9", "--d-over-a", "0.5"], "--tau0 [Pa] is an SI input"),
    (
        ["slide-init", "--tau0-over-E", "0.01", "--tangential-load", "1"],
        "--tangential-load [N/m] is an SI input",
    ),
    (
        [
            "slide-init",
            "--tau0-over-E",
            "0.01",
            "--d-over-a",
            "0.5",
            "--radius",
            "5e-8",
            "--modulus",
            "1e11",
            "--h",
            "5e-10",
        ],
        "SI inputs need the normal load --load [N/m]",
    ),
    (
        ["slide-init", "--tau0-over-E", "0.01", "--d-over-a", "0.5", "--load", "1"],
        "--load [N/m] is an SI input",
    ),
    (
        [
            "slide-init",
            "--tau0-over-E",
            "0.01",
            "--d-over-a",
            "0.5",
            "--R-over-h",
            "100",
            "--sigma0-over-E",
            "0.01",
        ],
        "with --R-over-h and --sigma0-over-E give the normal load",
    ),
    (
        [
            "slide-init",
            "--tau0-over-E",
            "0.01",
            "--d-over-a",
            "0.5",
            "--R-over-h",
            "100",
            "--sigma0-over-E",
            "0.01",
            "--F-over-Eh",
            "-100",
        ],
        "below the pull-off force",
    ),
    (
        [
            "roll",
            "--friction",
            "coulomb",
            "--mu",
            "0.3",
            "--R-over-h",
            "100",
            "--sigma0-over-E",
            "0.01",
            "--F-over-Eh",
            "1",
            "--d-over-a",
            "0",
        ],
        "Coulomb friction is the counterpart for the non-adhesive Hertz contact",
    ),
    (
        [
            "roll",
            "--friction",
            "coulomb",
            "--mu",
            "0.3",
            "--radius",
            "5e-8",
            "--modulus",
            "1e11",
            "--sigma0",
            "1e9",
            "--h",
            "5e-10",
            "--load",
            "1",
            "--d-over-a",
            "0",
        ],
        "Coulomb friction is the macro-scale counterpart",
    ),
    (
        ["roll", "--tau0-over-E", "0.01", "--d-over-a", "0.5", "--method", "exact"],
        "argument --method: invalid choice",
    ),
]


@pytest.mark.parametrize(("argv", "message"), BAD, ids=[" ".join(a)[:60] for a, _ in BAD])
def test_bad_input_one_line_exit_2(capsys, argv, message):
    code, out, err = run(capsys, *argv) if "--method" not in argv[-2:] else _argparse(capsys, argv)
    assert code == 2 and out == ""
    lines = err.strip().splitlines()
    assert len(lines) == 1 and "error:" in lines[0] and "Traceback" not in err
    assert message in lines[0], lines[0]


def _argparse(capsys, argv):
    with pytest.raises(SystemExit) as exc:
        main(argv)
    out, err = capsys.readouterr()
    return exc.value.code, out, err


def test_help_lists_the_subcommands(capsys):
    with pytest.raises(SystemExit):
        main(["--help"])
    out = capsys.readouterr().out
    assert "slide-init" in out and "roll" in out


def test_collocation_diagnostics_in_records(capsys):
    code, out, _ = run(
        capsys,
        "slide-init",
        "--tau0-over-E",
        "0.02",
        "--d-over-a",
        "0.9",
        "--method",
        "collocation",
        "--json",
    )
    (rec,) = records(out)
    assert rec["method"] == "collocation" and rec["n_collocation"] >= 16
    assert rec["residual_stick"] < 1e-12 and rec["converged"] is True
    assert rec["T_over_Ea"] == pytest.approx(2 * 0.02 * np.sqrt(1 - 0.81), rel=1e-13)
