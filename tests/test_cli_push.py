"""The ``push`` subcommand: its JSON contract, SI columns, and bad input (exit 2, one line)."""

from __future__ import annotations

import json
import re

import numpy as np
import pytest

import linecontact as lc
from linecontact.cli import main

ND = ["push", "--R-over-h2", "100", "--h1-over-h2", "2", "--sigma0-over-E", "0.01"]
ND += ["--tau0-over-E", "1e-3"]
SI = ["push", "--radius", "50e-9", "--modulus", "48e9", "--sigma0", "1e8", "--h2", "0.3e-9"]
SI += ["--h1", "0.6e-9", "--tau0", "1e6"]
CONTRACT = [
    "H_over_R",
    "a_rest_over_R",
    "a_slide_over_R",
    "Q_roll_over_Eh2",
    "Q_slide_over_Eh2",
    "H_critical_over_R",
    "first_motion",
]


def _run(argv, capsys):
    code = main(argv)
    out, err = capsys.readouterr()
    return code, out, err


def test_json_records_carry_the_contract_and_the_api_numbers(capsys):
    code, out, _ = _run([*ND, "--H-over-R", "0.25", "1", "2", "--json"], capsys)
    assert code == 0
    doc = json.loads(out)
    assert set(doc) == {"linecontact", "command", "parameters", "units", "results"}
    ref = lc.push(100.0, 2.0, 0.01, 1e-3, 0.0, [0.25, 1.0, 2.0])
    for i, rec in enumerate(doc["results"]):
        assert set(CONTRACT) <= set(rec) and "state" not in rec
        for k in CONTRACT:
            want = np.asarray(getattr(ref, k))[i]
            assert rec[k] == (want.item() if hasattr(want, "item") else want), k


def test_a_push_given_reports_the_state(capsys):
    code, out, _ = _run([*ND, "--H-over-R", "0.5", "2", "--Q-over-Eh2", "0.015", "--json"], capsys)
    assert code == 0
    states = [r["state"] for r in json.loads(out)["results"]]
    assert states == ["rest", "roll"]  # Q_roll = 0.02 at H = R/2, 0.005 at H = 2R


def test_si_columns(capsys):
    argv = [*SI, "--height", "25e-9", "100e-9", "--length", "5e-6", "--push", "0.02", "--json"]
    code, out, _ = _run(argv, capsys)
    assert code == 0
    doc = json.loads(out)
    rec = doc["results"][0]
    Eh = 48e9 * 0.3e-9
    assert rec["H_m"] == pytest.approx(25e-9) and rec["H_over_R"] == pytest.approx(0.5)
    assert rec["Q_roll_N_per_m"] == pytest.approx(rec["Q_roll_over_Eh2"] * Eh, rel=1e-15)
    assert rec["Q_slide_total_N"] == pytest.approx(rec["Q_slide_N_per_m"] * 5e-6, rel=1e-15)
    # Kendall: Q_roll H = R dw, dw = sigma0 (h1 - h2) = 0.03 J/m^2
    assert rec["Q_roll_N_per_m"] * rec["H_m"] == pytest.approx(50e-9 * 0.03, rel=1e-12)
    assert doc["parameters"]["tau0_Pa"] == 1e6 and "state" in rec


@pytest.mark.parametrize(
    ("argv", "message"),
    [
        (
            [*ND[:4], "0.5", *ND[5:], "--H-over-R", "1"],
            r"--h1-over-h2 must be in \[1, 1000\], got 0.5",
        ),
        ([*ND, "--H-over-R", "3"], r"--H-over-R must be in \[0, 2\], got 3.0"),
        ([*ND], r"give --H-over-R"),
        ([*ND, "--H-over-R", "1", "--F-over-Eh2", "-1"], r"below the pull-off force"),
        ([*ND, "--H-over-R", "1", "--radius", "5e-8"], r"not both"),
        ([*SI, "--height", "2e-7"], r"--height must be in \[0, 1e-07\] m \(2R\), got 2e-07"),
        ([*SI], r"give exactly one of --height or --tip-height"),
        ([*SI, "--height", "5e-8", "--tau0", "-1"], r"--tau0 must be in"),
        ([*SI, "--tip-height", "1e-7"], r"--tip-height must be in \(0, 1e-07\) m \(2R\)"),
        ([*SI, "--height", "5e-8", "--tip-friction", "0.1"], r"goes with --tip-height"),
        ([*ND, "--H-over-R", "1", "--tip-friction", "-1"], r"--tip-friction must be in \[0, 10\]"),
        (
            ["push", "--radius", "5e-8", "--modulus", "48e9", "--tau0", "1e6", "--height", "5e-8"]
            + ["--work-of-adhesion-receding", "0.02", "--work-of-adhesion-advancing", "0.05"]
            + ["--z0", "3e-10"],
            r"--work-of-adhesion-advancing must be <= --work-of-adhesion-receding",
        ),
    ],
)
def test_bad_input_is_one_error_line_and_status_2(argv, message, capsys):
    code, _, err = _run(argv, capsys)
    assert code == 2
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("linecontact push: error: ")
    assert re.search(message, lines[0]), lines[0]


def test_a_tip_and_the_two_works_of_adhesion(capsys):
    argv = ["push", "--radius", "50e-9", "--modulus", "48e9", "--tau0", "1e6"]
    argv += ["--work-of-adhesion-receding", "0.05", "--work-of-adhesion-advancing", "0.025"]
    argv += ["--z0", "0.3e-9", "--tip-height", "25e-9", "75e-9", "--tip-friction", "0.2"]
    code, out, _ = _run([*argv, "--json"], capsys)
    assert code == 0
    doc = json.loads(out)
    s0, h1 = lc.adhesion_from_work(0.05, 0.3e-9)
    h2 = 0.025 / s0
    ref = lc.push(50e-9 / h2, h1 / h2, s0 / 48e9, 1e6 / 48e9, 0.0, [0.5, 1.5], tip_friction=0.2)
    for i, rec in enumerate(doc["results"]):
        assert rec["H_arm_over_R"] == pytest.approx(ref.H_arm_over_R[i], rel=1e-15)
        assert rec["Q_slide_over_Eh2"] == pytest.approx(ref.Q_slide_over_Eh2[i], rel=1e-12)
        assert rec["H_arm_m"] == pytest.approx(ref.H_arm_over_R[i] * 50e-9, rel=1e-15)
    assert doc["parameters"]["work_of_adhesion_advancing_J_per_m2"] == 0.025


BASE = ["push", "--radius", "50e-9", "--modulus", "48e9", "--tau0", "1e6", "--height", "25e-9"]


@pytest.mark.parametrize(
    ("adhesion", "asked", "not_asked"),
    [
        # the works of adhesion (the old --work-of-adhesion is the advancing one): the receding
        (
            ["--work-of-adhesion", "0.05", "--z0", "3e-10"],
            ["--work-of-adhesion-receding", "--h1 [m]"],
            ["--h1-over-h2", "--z0"],
        ),
        (
            ["--work-of-adhesion-advancing", "0.05", "--z0", "3e-10"],
            ["--work-of-adhesion-receding", "--h1 [m]"],
            ["--h1-over-h2", "--z0"],
        ),
        (["--work-of-adhesion-advancing", "0.05"], ["--work-of-adhesion-receding", "--z0"], []),
        (
            ["--work-of-adhesion-receding", "0.05", "--z0", "3e-10"],
            ["--work-of-adhesion-advancing"],
            ["--h1", "--z0"],
        ),
        (["--work-of-adhesion-receding", "0.05"], ["--work-of-adhesion-advancing", "--z0"], []),
        # the ranges: --h1
        (["--sigma0", "1e8", "--h2", "3e-10"], ["--h1 [m]"], ["--work-of-adhesion"]),
        # nothing: both spellings
        ([], ["--sigma0", "--h2", "--h1", "--work-of-adhesion-receding", "--z0"], []),
    ],
)
def test_a_missing_receding_side_is_asked_in_the_user_s_spelling(
    adhesion, asked, not_asked, capsys
):
    code, _, err = _run([*BASE, *adhesion], capsys)
    assert code == 2
    (line,) = [s for s in err.splitlines() if ": error: " in s]
    assert "Traceback" not in err
    for flag in asked:
        assert flag in line, line
    for flag in not_asked:
        assert flag not in line, line
    # every flag the error asks for is one push takes (and its help shows)
    help_text = _help(capsys)
    for flag in re.findall(r"--[a-z][\w-]*", line):
        assert f"{flag} " in help_text, flag


def _help(capsys) -> str:
    with pytest.raises(SystemExit):
        main(["push", "--help"])
    return capsys.readouterr().out


def test_the_groups_ask_for_the_ratio(capsys):
    argv = ["push", "--R-over-h2", "100", "--sigma0-over-E", "0.01", "--tau0-over-E", "1e-3"]
    code, _, err = _run([*argv, "--H-over-R", "1"], capsys)
    assert code == 2 and "give --h1-over-h2" in err and "--h1 " not in err


def test_the_works_of_adhesion_and_the_ranges_each_are_one_entry_of_the_help(capsys):
    text = _help(capsys)
    assert re.search(r"^  --sigma0 S, --h2 H, --h1 H1 ", text, re.M), text
    assert re.search(
        r"^  --work-of-adhesion-advancing W, --work-of-adhesion-receding W1, --z0 Z$", text, re.M
    ), text
