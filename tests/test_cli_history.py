"""CLI cycle and history: wiring and format (the numbers are tested in test_history)."""

import json

import numpy as np
import pytest

from linecontact import (
    Cylinder,
    cyclic_loss,
    cyclic_loss_coulomb,
    tangential_history,
    tangential_history_coulomb,
)
from linecontact.cli import main

SI = ["--radius", "50e-9", "--modulus", "100e9", "--sigma0", "1e9", "--h", "0.5e-9"]


def run(capsys, *argv):
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def records(text):
    doc = json.loads(text)
    assert set(doc) == {"linecontact", "command", "parameters", "units", "results"}
    return doc["parameters"], doc["results"]


def test_cycle_json_contract(capsys):
    code, out, err = run(
        capsys,
        "cycle",
        "--tau0-over-E",
        "0.01",
        "--T-amplitude-over-Ea",
        "0.005",
        "0.015",
        "0.02",
        "--json",
    )
    assert code == 0, err
    params, recs = records(out)
    ref = cyclic_loss(0.01, [0.005, 0.015])
    assert params["friction"] == "constant" and params["tau0_over_E"] == 0.01
    assert [r["W_over_Ea2"] for r in recs[:2]] == list(ref.W_over_Ea2)
    assert [r["c_over_a"] for r in recs[:2]] == list(ref.c_over_a)
    assert [r["T_amplitude_over_Ea"] for r in recs] == [0.005, 0.015, 0.02]
    # at full slip: reported, not an error; the loss is not computed
    assert recs[2]["state"] == "sliding" and recs[2]["W_over_Ea2"] is None


def test_cycle_coulomb_in_both_load_units(capsys):
    args = ["cycle", "--friction", "coulomb", "--mu", "0.3", "--a-over-R", "0.01", "--json"]
    _, out, _ = run(capsys, *args, "--T-amplitude-over-muF", "0.1", "0.5")
    params, recs = records(out)
    ref = cyclic_loss_coulomb(0.3, 0.01, [0.1, 0.5])
    assert [r["W_over_Ea2"] for r in recs] == list(ref.W_over_Ea2)
    assert params["a_over_R"] == 0.01 and params["mu"] == 0.3
    T = [float(t) for t in ref.T_amplitude_over_Ea]
    _, out2, _ = run(capsys, *args, "--T-amplitude-over-Ea", *map(repr, T))
    _, recs2 = records(out2)
    assert np.allclose([r["W_over_Ea2"] for r in recs2], ref.W_over_Ea2, rtol=1e-14)


def test_cycle_si_with_length(capsys):
    code, out, err = run(
        capsys,
        "cycle",
        *SI,
        "--load",
        "1",
        "--tau0",
        "1e9",
        "--tangential-amplitude",
        "0.5",
        "2",
        "9",
        "--length",
        "5e-6",
        "--json",
    )
    assert code == 0, err
    params, recs = records(out)
    cyl = Cylinder.from_modulus(50e-9, 100e9, cohesive_stress=1e9, adhesion_range=0.5e-9)
    ref = cyl.cyclic_loss(1.0, [0.5, 2.0], friction_stress=1e9)
    assert [r["W_J_per_m"] for r in recs[:2]] == list(ref.energy_per_cycle)
    assert [r["W_total_J"] for r in recs[:2]] == list(ref.energy_per_cycle * 5e-6)
    assert params["a_m"] == ref.contact_half_width
    assert params["T_full_slip_N_per_m"] == ref.full_slip_load
    assert recs[2]["state"] == "sliding" and recs[2]["W_J_per_m"] is None


def test_history_records_one_per_step_with_zones(capsys):
    code, out, err = run(
        capsys,
        "history",
        "--tau0-over-E",
        "0.01",
        "--T-over-Ea",
        "0.016",
        "-0.008",
        "0.004",
        "0.03",
        "--json",
    )
    assert code == 0, err
    params, recs = records(out)
    ref = tangential_history(0.01, [0.016, -0.008, 0.004, 0.03])
    assert [r["step"] for r in recs] == [1, 2, 3, 4]
    assert [r["memory"] for r in recs] == ref.memory.tolist()
    assert [r["dissipation_over_Ea2"] for r in recs[:3]] == list(ref.dissipation_over_Ea2[:3])
    assert [k for _, _, k in recs[2]["zones"]] == ["stick", "locked+", "locked-", "slip+"]
    assert recs[3]["state"] == "sliding" and recs[3]["c_over_a"] is None
    assert recs[3]["zones"] == [[0.0, 1.0, "sliding"]]


def test_history_csv_zones_are_json_text(capsys):
    _, out, _ = run(
        capsys,
        "history",
        "--tau0-over-E",
        "0.01",
        "--T-over-Ea",
        "0.016",
        "-0.008",
        "--format",
        "csv",
    )
    import csv

    rows = list(csv.reader(line for line in out.splitlines() if not line.startswith("#")))
    zones = [json.loads(r[rows[0].index("zones")]) for r in rows[1:]]
    assert zones[1][1][2] == "locked+"


def test_history_coulomb_and_incremental(capsys):
    args = ["history", "--friction", "coulomb", "--mu", "0.3", "--a-over-R", "0.01"]
    _, out, _ = run(capsys, *args, "--T-over-muF", "0.5", "-0.2", "0.3", "--json")
    _, recs = records(out)
    ref = tangential_history_coulomb(0.3, 0.01, [0.5, -0.2, 0.3])
    assert [r["c_over_a"] for r in recs] == list(ref.c_over_a)
    _, out2, _ = run(
        capsys, *args, "--T-over-muF", "0.5", "-0.2", "0.3", "--method", "incremental", "--json"
    )
    params, recs2 = records(out2)
    assert params["method"] == "incremental"
    assert np.allclose([r["c_over_a"] for r in recs2], ref.c_over_a, atol=1e-13)
    assert all(r["converged"] for r in recs2)


def test_history_si(capsys):
    code, out, err = run(
        capsys,
        "history",
        *SI,
        "--load",
        "1",
        "--tau0",
        "1e9",
        "--tangential-load",
        "1",
        "-1",
        "1",
        "--length",
        "5e-6",
        "--json",
    )
    assert code == 0, err
    params, recs = records(out)
    assert [r["T_N_per_m"] for r in recs] == [1.0, -1.0, 1.0]
    assert recs[1]["dissipation_total_J"] == pytest.approx(recs[1]["dissipation_J_per_m"] * 5e-6)
    assert params["length_m"] == 5e-6


@pytest.mark.parametrize(
    ("argv", "message"),
    [
        (
            ["cycle", "--tau0-over-E", "0.01", "--T-amplitude-over-Ea", "-1"],
            "--T-amplitude-over-Ea",
        ),
        (["cycle", "--tau0-over-E", "0.01", "--T-amplitude-over-Ea", "0"], "--T-amplitude-over-Ea"),
        (
            ["cycle", "--tau0-over-E", "0.01", "--T-amplitude-over-Ea", "nan"],
            "--T-amplitude-over-Ea",
        ),
        (["cycle", "--tau0-over-E", "0", "--T-amplitude-over-Ea", "0.1"], "--tau0-over-E"),
        (["cycle", "--T-amplitude-over-Ea", "0.1"], "--tau0-over-E"),
        (
            ["cycle", "--tau0-over-E", "0.01", "--T-amplitude-over-muF", "0.1"],
            "--T-amplitude-over-muF is for --friction coulomb",
        ),
        (
            ["cycle", "--friction", "coulomb", "--mu", "0.3", "--T-amplitude-over-muF", "0.1"],
            "--a-over-R",
        ),
        (["cycle", "--tau0-over-E", "0.01", "--tangential-amplitude", "1"], "SI input"),
        (["cycle", "--tau0-over-E", "0.01"], "give exactly one of --T-amplitude-over-Ea"),
        (["history", "--tau0-over-E", "0.01", "--T-over-Ea", "0.01", "inf"], "--T-over-Ea"),
        (["history", "--tau0-over-E", "0.01", "--T-over-Ea", "0.01", "--mu", "0.3"], "--mu"),
        (
            ["history", "--tau0-over-E", "0.01", "--T-over-Ea", "0.01", "--length", "1e-6"],
            "--length",
        ),
    ],
)
def test_bad_input_one_error_line_exit_2(capsys, argv, message):
    code, out, err = run(capsys, *argv)
    assert code == 2
    assert out == ""
    assert err.count("\n") == 1 and "error:" in err and message in err, err
    assert "Traceback" not in err


def test_a_large_negative_si_load_is_judged_in_si_units(capsys):
    code, out, err = run(
        capsys,
        "history",
        *SI,
        "--load",
        "1",
        "--tau0",
        "1e9",
        "--tangential-load",
        "-1e30",
    )
    assert code == 2, err
    assert (
        "--tangential-load must be at most 3.1859e+14 N/m in magnitude (1e+12 times the "
        "modulus times the contact half-width" in err
    ), err
