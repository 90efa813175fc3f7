"""CLI ``slide``: wiring and format only (the numbers are tested in test_sliding.py)."""

import json
import math

import numpy as np
import pytest

from linecontact.cli import main
from linecontact.sliding import sliding_contact, sliding_contact_for_load

CONTRACT_KEYS = {"a_over_R", "c1_over_R", "c2_over_R", "e_over_R", "F_over_Eh2", "M_over_Eh2R"}
GROUPS = ["--R-over-h2", "100", "--h1-over-h2", "1.5", "--sigma0-over-E", "0.01"]


def run(capsys, *argv):
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def records(text):
    """The records of a --json output, each with the run's parameters merged in."""
    doc = json.loads(text)
    assert set(doc) == {"linecontact", "command", "parameters", "units", "results"}
    return [{**doc["parameters"], **r} for r in doc["results"]]


def test_json_contract(capsys):
    code, out, err = run(capsys, "slide", *GROUPS, "--a-over-R", "0.01", "0.02", "--json")
    assert code == 0, err
    recs = records(out)
    assert len(recs) == 2
    ref = sliding_contact([0.01, 0.02], 100.0, 1.5, 0.01, method="collocation")  # the CLI's
    for i, rec in enumerate(recs):
        assert CONTRACT_KEYS <= set(rec)
        for k in CONTRACT_KEYS:
            assert isinstance(rec[k], float) and math.isfinite(rec[k])
            assert rec[k] == getattr(ref, k)[i], k
        assert rec["method"] == "collocation" and rec["converged"] is True
        assert rec["c1_minus_c2_over_R"] == rec["c1_over_R"] - rec["c2_over_R"]
        assert "T_over_Eh2" not in rec  # no tau0 given


def test_table_range_and_closed_form(capsys):
    code, out, _ = run(
        capsys, "slide", *GROUPS, "--a-over-R-range", "0.01", "0.05", "3", "--method", "closed-form"
    )
    assert code == 0
    lines = out.strip().splitlines()
    assert lines[0].startswith("# steady sliding") and "closed-form" in lines[0]
    assert "clockwise" in lines[0]
    assert lines[1].startswith("# R_over_h2 = 100, h1_over_h2 = 1.5")
    assert lines[2].split()[:6] == [
        "a_over_R",
        "c1_over_R",
        "c2_over_R",
        "e_over_R",
        "F_over_Eh2",
        "M_over_Eh2R",
    ]
    assert len(lines) == 3 + 3


def test_inverse_with_friction(capsys):
    code, out, _ = run(
        capsys,
        "slide",
        "--R-over-h2",
        "100",
        "--h1-over-h2",
        "2",
        "--sigma0-over-E",
        "0.04",
        "--F-over-Eh2",
        "-0.5",
        "1",
        "--tau0-over-E",
        "0.01",
        "--json",
    )
    assert code == 0
    recs = records(out)
    ref = sliding_contact_for_load(
        [-0.5, 1.0], 100.0, 2.0, 0.04, tau0_over_E=0.01, method="collocation"
    )
    np.testing.assert_allclose([r["a_over_R"] for r in recs], ref.a_over_R, rtol=1e-14)
    np.testing.assert_allclose([r["T_over_Eh2"] for r in recs], ref.T_over_Eh2, rtol=1e-14)
    assert all(r["stable"] for r in recs)


def test_si_mode_matches_groups(capsys):
    # R = 50 nm, E = 100 GPa, sigma0 = 1 GPa, h2 = 0.5 nm, h1 = 0.75 nm
    si = [
        "--radius",
        "50e-9",
        "--modulus",
        "100e9",
        "--sigma0",
        "1e9",
        "--h2",
        "0.5e-9",
        "--h1",
        "0.75e-9",
    ]
    code, out, err = run(capsys, "slide", *si, "--half-width", "1e-9", "--tau0", "5e8", "--json")
    assert code == 0, err
    rec = records(out)[0]
    ref = sliding_contact(0.02, 100.0, 1.5, 0.01, tau0_over_E=0.005, method="collocation")
    for k in ("c1_over_R", "c2_over_R", "e_over_R", "F_over_Eh2", "M_over_Eh2R"):
        assert math.isclose(rec[k], getattr(ref, k), rel_tol=1e-12), k
    Eh = 100e9 * 0.5e-9
    assert math.isclose(rec["F_N_per_m"], rec["F_over_Eh2"] * Eh, rel_tol=1e-15)
    assert math.isclose(rec["M_N"], rec["M_over_Eh2R"] * Eh * 50e-9, rel_tol=1e-15)
    assert math.isclose(rec["T_N_per_m"], 2 * 1e-9 * 5e8, rel_tol=1e-12)
    assert math.isclose(rec["c1_m"], rec["c1_over_R"] * 50e-9, rel_tol=1e-15)
    # a load in N/m is the same state
    code, out, _ = run(capsys, "slide", *si, "--load", repr(rec["F_N_per_m"]), "--json")
    assert code == 0
    assert math.isclose(records(out)[0]["a_m"], 1e-9, rel_tol=1e-9)


BAD = [
    (
        [
            "--R-over-h2",
            "100",
            "--h1-over-h2",
            "-1",
            "--sigma0-over-E",
            "0.01",
            "--a-over-R",
            "0.01",
        ],
        "--h1-over-h2 must be in [0.001, 1000], got -1.0",
    ),
    (
        ["--R-over-h2", "0", "--h1-over-h2", "2", "--sigma0-over-E", "0.01", "--a-over-R", "0.01"],
        "--R-over-h2 must be in [0.001, 1e+12], got 0.0",
    ),
    (
        ["--R-over-h2", "100", "--h1-over-h2", "2", "--sigma0-over-E", "nan", "--a-over-R", "0.01"],
        "--sigma0-over-E must be a finite number",
    ),
    (
        [
            "--R-over-h2",
            "100",
            "--h1-over-h2",
            "2",
            "--sigma0-over-E",
            "0.01",
            "--a-over-R",
            "-0.01",
        ],
        "--a-over-R must be in [1e-20, 10], got -0.01",
    ),
    (
        ["--R-over-h2", "100", "--h1-over-h2", "2", "--sigma0-over-E", "0.01"],
        "exactly one of --a-over-R",
    ),
    (
        ["--R-over-h2", "100", "--sigma0-over-E", "0.01", "--a-over-R", "0.01"],
        "give --h1-over-h2, the trailing over the leading range",
    ),
    (  # SI, with the works of adhesion or the ranges: --h1 [m]
        ["--radius", "5e-8", "--modulus", "1e11", "--work-of-adhesion-advancing", "0.5"]
        + ["--z0", "5e-10", "--load", "0.05"],
        "give the trailing (receding) range --h1 [m] (or --h1-over-h2)",
    ),
    (
        ["--radius", "5e-8", "--modulus", "1e11", "--sigma0", "1e9", "--h2", "5e-10"]
        + ["--load", "0.05", "--h1", "1e-9", "--h1-over-h2", "2"],
        "give the trailing range as --h1 [m] or as --h1-over-h2, not both",
    ),
    (
        ["--h1-over-h2", "2", "--sigma0-over-E", "0.01", "--a-over-R", "0.01"],
        "give --R-over-h2, --h1-over-h2 and --sigma0-over-E",
    ),
    (
        [
            "--R-over-h2",
            "100",
            "--h1-over-h2",
            "2",
            "--sigma0-over-E",
            "0.04",
            "--radius",
            "1e-8",
            "--a-over-R",
            "0.01",
        ],
        "not both",
    ),
    (
        [
            "--R-over-h2",
            "100",
            "--h1-over-h2",
            "2",
            "--sigma0-over-E",
            "0.04",
            "--half-width",
            "1e-9",
        ],
        "--half-width and --load are SI inputs",
    ),
    (
        [
            "--modulus",
            "1e11",
            "--sigma0",
            "1e9",
            "--h2",
            "1e-9",
            "--h1-over-h2",
            "2",
            "--half-width",
            "1e-9",
        ],
        "SI inputs need --radius",
    ),
    (
        [
            "--R-over-h2",
            "100",
            "--h1-over-h2",
            "2",
            "--sigma0-over-E",
            "0.01",
            "--tau0-over-E",
            "-1",
            "--a-over-R",
            "0.01",
        ],
        "--tau0-over-E must be in [0, 1]",
    ),
]


@pytest.mark.parametrize(("argv", "message"), BAD)
def test_bad_input_exit_2(capsys, argv, message):
    code, _, err = run(capsys, "slide", *argv)
    assert code == 2
    assert err.startswith("linecontact slide: error:") and message in err
    assert "Traceback" not in err and len(err.strip().splitlines()) == 1


def test_help_states_the_conventions(capsys):
    with pytest.raises(SystemExit) as exc:
        main(["slide", "--help"])
    assert exc.value.code == 0
    out = " ".join(capsys.readouterr().out.split())
    assert "clockwise positive" in out and "--h1-over-h2" in out and "--h2" in out


def test_load_below_pull_off_is_a_record(capsys):
    argv = ["--R-over-h2", "100", "--h1-over-h2", "2", "--sigma0-over-E", "0.04"]
    code, out, err = run(capsys, "slide", *argv, "--F-over-Eh2", "-5", "1", "--json")
    assert code == 0 and err == ""
    below, ok = records(out)
    assert below["state"] == "no-equilibrium" and "below the pull-off force" in below["reason"]
    assert below["F_over_Eh2"] == -5 and below["a_over_R"] is None and below["stable"] is False
    assert ok["state"] == "contact" and ok["F_over_Eh2"] == pytest.approx(1, rel=1e-9)
    code, out, err = run(capsys, "slide", *argv, "--F-over-Eh2", "-5")
    assert code == 1 and err.count("\n") == 1 and "no point could be computed" in err
    assert "no-equilibrium" in out
