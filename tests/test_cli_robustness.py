"""CLI bad and edge input: one ``error:`` line and exit 2 (1 for a solver failure), never a
traceback or an "internal error"; ``--json`` output strict JSON. Wiring only."""

import json
import re

import pytest

from linecontact.cli import main

SI0 = ["--radius", "50e-9", "--modulus", "100e9", "--sigma0", "1e9"]  # no range
G = ["--R-over-h", "100", "--sigma0-over-E", "0.2"]
SI = ["--radius", "50e-9", "--modulus", "100e9", "--sigma0", "1e9", "--h", "0.5e-9"]


def run(capsys, *argv):
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def records(text):
    """The records of a --json output, each with the run's parameters merged in."""
    doc = json.loads(text)
    assert set(doc) == {"linecontact", "command", "parameters", "units", "results"}
    return [{**doc["parameters"], **r} for r in doc["results"]]


def strict_json(text):
    def refuse(c):
        raise ValueError(f"not strict JSON: {c}")

    return json.loads(text, parse_constant=refuse)


@pytest.mark.parametrize(
    "argv, message",
    [
        (
            [],
            r"give a command: normal, pulloff, curve, slide-init, roll, cycle, history, slide, "
            r"push, fit-adhesion, fit-friction, fit-bent-wire, paper, figures, map, materials, "
            r"sweep, serve or cite",
        ),
        (
            ["curve", *G, "-o", "/nonexistent-dir/curve.csv"],
            r"cannot write -o/--output '/nonexistent-dir/curve.csv': the directory "
            r"'/nonexistent-dir' does not exist",
        ),
        (
            ["normal", *G, "--a-over-R-range", "0.001", "inf", "5"],
            r"--a-over-R-range STOP must be a finite number > 0, got inf",
        ),
        (
            ["normal", *G, "--a-over-R-range", "0", "0.1", "5"],
            r"--a-over-R-range START must be a finite number > 0, got 0.0",
        ),
        (
            ["normal", *G, "--a-over-R-range", "0.001", "0.1", "1000001"],
            r"--a-over-R-range NUM must be an integer in \[1, 1000000\], got 1000001.0",
        ),
        (
            [
                "slide",
                "--R-over-h2",
                "100",
                "--h1-over-h2",
                "2",
                "--sigma0-over-E",
                "0.01",
                "--a-over-R-range",
                "0.001",
                "0.1",
                "nan",
            ],
            r"--a-over-R-range NUM must be an integer in \[1, 1000000\], got nan",
        ),
        (["curve", *G, "--num", "1000001"], r"--num must be an integer in \[2, 1000000\]"),
        (
            ["normal", *G, "--F-over-Eh", "-inf"],
            r"--F-over-Eh must be a finite number in \[-1e\+12, 1e\+12\], got -inf",
        ),
        (
            ["slide-init", "--tau0-over-E", "0.01", "--d-over-a", "-1e-1"],
            r"--d-over-a must be in \[0, 1\), got -0.1",
        ),
        (
            [
                "roll",
                "--friction",
                "coulomb",
                "--mu",
                "0.3",
                "--a-over-R",
                "0.01",
                "--T-over-Ea",
                "-1",
            ],
            r"--T-over-Ea must be in \[0, 1e\+12\], got -1.0",
        ),
        (
            ["pulloff", "--radius", "50e-9", "--modulus", "100e9", "--sigma0", "1e9"],
            r"SI inputs need the adhesion range --h \[m\]",
        ),
        (
            [
                "slide",
                "--radius",
                "50e-9",
                "--modulus",
                "100e9",
                "--sigma0",
                "1e9",
                "--h1",
                "1e-9",
                "--load",
                "1",
            ],
            r"SI inputs need the adhesion range --h2 \[m\]",
        ),
        (
            [
                "pulloff",
                "--radius",
                "50e-9",
                "--modulus",
                "100e9",
                "--work-of-adhesion",
                "1e300",
                "--z0",
                "0.3e-9",
            ],
            r"--work-of-adhesion must be in \[1e-100, 1e\+100\], got 1e\+300",
        ),
        (
            [
                "normal",
                "--radius",
                "50e-9",
                "--modulus",
                "1e-300",
                "--sigma0",
                "1e9",
                "--h",
                "0.5e-9",
                "--load",
                "1",
            ],
            r"--sigma0=1000000000\.0 Pa must be at most 1e\+06 times the modulus, 1e-294 Pa "
            r"here, got --modulus=1e-300 Pa",
        ),
        (
            ["pulloff", "--R-over-h", "1e12", "--sigma0-over-E", "1e6", "--json"],
            r"kappa = \(4/pi\) --sigma0-over-E sqrt\(2 --R-over-h\) must be <= 1e\+12",
        ),
        # the validated domain said in SI units and flags (E h = 50 N/m, R = 50 nm)
        (
            ["normal", *SI0, "--h", "0.5e-9", "--half-width", "1e-3"],
            r"--half-width must be in \[5e-158, 5e-07\] m \(1e-150 to 10 radii, the domain of "
            r"the solvers\), got 0\.001$",
        ),
        (
            ["normal", *SI0, "--h", "0.5e-9", "--load", "1e20"],
            r"--load must be in \[-5e\+13, 5e\+13\] N/m \(-1e\+12 to 1e\+12 times the modulus "
            r"times the adhesion range, the domain of the solvers\)",
        ),
        (
            ["normal", *SI0, "--h", "0.5e-9", "--load", "1", "1e6"],
            r"--load=1000000\.0 N/m needs a contact of half-width 7\.979\d*e-07 m, 15\.958\d* "
            r"radii: beyond the domain of the solvers \(at most 10 radii\)$",
        ),
        (
            ["normal", *SI0, "--h", "1e-21", "--load", "1"],
            r"--radius / --h must be in \[0\.001, 1e\+12\] \(the domain of the solvers\), got "
            r"--radius=5e-08 m, --h=1e-21 m; is --h in metres\?",
        ),
        (
            ["slide", *SI0, "--h2", "0.5e-9", "--h1", "1e-20", "--half-width", "1e-9"],
            r"--h1 must be in \[5e-13, 5e-07\] m \(0\.001 to 1000 times the adhesion range, "
            r"the domain of the solvers\)",
        ),
        (
            [
                "slide",
                *SI0,
                "--h2",
                "0.5e-9",
                "--h1",
                "5e-10",
                "--tau0",
                "1e13",
                "--half-width",
                "1e-9",
            ],
            r"--tau0 must be in \[0, 1e\+11\] Pa \(0 to 1 times the modulus, the domain",
        ),
        (
            ["slide", *SI0, "--h2", "0.5e-9", "--h1", "5e-10", "--half-width", "1e-3"],
            r"--half-width must be in \[5e-28, 5e-07\] m \(1e-20 to 10 radii, the domain",
        ),
        (
            ["slide", *SI0, "--h2", "0.5e-9", "--h1", "5e-10", "--load", "1e7"],
            r"--load=10000000\.0 N/m needs a contact of half-width 2\.52\d*e-06 m",
        ),
        (
            ["roll", *SI0, "--h", "0.5e-9", "--load", "1", "--tau0", "1e13", "--d-over-a", "0.1"],
            r"--tau0 must be in \[0\.1, 1e\+11\] Pa \(1e-12 to 1 times the modulus, the domain",
        ),
        (
            [
                *["roll", *SI0, "--h", "0.5e-9", "--load", "1", "--tau0", "1e8"],
                *["--tangential-load", "1e40"],
            ],
            r"--tangential-load must be in \[0, [0-9.e+]+\] N/m \(0 to 1e\+12 times the modulus "
            r"times the contact half-width, the domain of the solvers\)",
        ),
    ],
)
def test_bad_input_one_error_line_exit_2(capsys, argv, message):
    """Before: help on stdout and no error line (no command); 'internal error
    (FileNotFoundError ...); please report it' (unwritable -o); a NaN-laden message
    naming a_over_R (infinite range end); the memory exhausted (NUM = 1e9); a converted
    T_over_muF=-424.4 named for --T-over-Ea -1; ZeroDivisionError; an overflow warning;
    pull-off -0.0 printed as the result."""
    code, out, err = run(capsys, *argv)
    assert code == 2, (out, err)
    # one error line, after the warnings of inputs that look like wrong units
    lines = err.splitlines()
    assert ": error: " in lines[-1] and all(": warning: " in x for x in lines[:-1]), err
    assert "internal error" not in err and "Traceback" not in err
    assert re.search(message, err), err


def test_paper_outdir_that_is_a_file(capsys, tmp_path):
    target = tmp_path / "a-file"
    target.write_text("x")
    code, _, err = run(capsys, "paper", "--outdir", str(target))
    assert code == 2 and err.count("\n") == 1
    assert "cannot write the figures to --outdir" in err and "internal error" not in err


@pytest.mark.parametrize(
    "argv, key, value",
    [
        (["normal", *G, "--F-over-Eh", "-1e-1", "--json"], "F_over_Eh", -0.1),
        (["normal", *G, "--F-over-Eh", "-1.5E+0", "--json"], "F_over_Eh", -1.5),
        (["roll", "--tau0-over-E", "0.01", "--d-over-a", "-5e-1", "--json"], "d_over_a", -0.5),
        (["normal", *SI, "--load", "-5e-1", "--json"], "F_N_per_m", -0.5),
    ],
)
def test_negative_numbers_in_scientific_notation(capsys, argv, key, value):
    """argparse took '-1e-1' for an option: 'argument --F-over-Eh: expected at least one
    argument'."""
    code, out, err = run(capsys, *argv)
    assert code == 0, err
    rec = records(out)[0]
    assert rec[key] == pytest.approx(value, rel=1e-9)


# an adhesive zone of c/a - 1 ~ 1e-9: beyond the collocation's n <= 2048 nodes
THIN = ["--R-over-h", "21153758.746772554", "--sigma0-over-E", "7.749102910688328"]


def test_solver_failure_exit_1_one_line(capsys):
    # the only point does not converge: its record says so, and the run exits 1
    code, out, err = run(
        capsys,
        "normal",
        *THIN,
        "--a-over-R",
        "1.6596315985408394",
        "--method",
        "collocation",
        "--json",
        "--quiet",
    )
    assert code == 1 and err.count("\n") == 1
    assert "no point could be computed" in err and "did not converge" in err
    assert "RuntimeWarning" not in err
    (rec,) = records(out)
    assert rec["state"] == "not-converged" and rec["c_over_R"] is None
    assert rec["converged"] is False and "did not converge" in rec["reason"]


def test_one_unconverged_point_does_not_fail_the_run(capsys):
    code, out, err = run(
        capsys,
        "normal",
        *THIN,
        "--a-over-R",
        "1.6596315985408394",
        "1e-6",
        "--method",
        "collocation",
        "--json",
        "--quiet",
    )
    assert code == 0 and err == ""
    bad, good = records(out)
    assert bad["state"] == "not-converged" and bad["F_over_Eh"] is None
    assert good["state"] == "contact" and good["converged"] is True and good["reason"] is None


@pytest.mark.parametrize(
    "argv, message",
    [
        (
            ["normal", *G, "--a-over-R", "0.01", "--branch", "unstable"],
            r"--branch applies to given loads \(--F-over-Eh or --load\)",
        ),
        (
            ["normal", *G, "--F-over-Eh", "1", "--method", "collocation"],
            r"--method collocation applies to given contact half-widths",
        ),
        (
            ["normal", *SI, "--load", "1", "--method", "collocation"],
            r"--method collocation applies to given contact half-widths",
        ),
    ],
)
def test_options_that_do_not_apply_are_refused(capsys, argv, message):
    """Both were silently ignored: the output carried the closed form or the stable state."""
    code, out, err = run(capsys, *argv)
    assert code == 2 and out == "" and err.count("\n") == 1
    assert re.search(message, err), err


@pytest.mark.parametrize("cmd", [["normal"], ["slide-init", "--tau0", "1e8", "--d-over-a", "0.5"]])
def test_si_load_below_pull_off_in_newton_per_metre(capsys, cmd):
    code, out, err = run(capsys, *cmd, *SI, "--load", "-1000", "--json")
    assert code == 1 and err.count("\n") == 1, err
    assert "no point could be computed" in err and "below the pull-off force" in err, err
    assert "N/m" in err
    recs = records(out)
    assert len(recs) == 1
    for rec in recs:
        assert rec["state"] == "no-equilibrium" and "N/m" in rec["reason"]
