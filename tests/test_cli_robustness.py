"""CLI bad and edge input: one ``error:`` line and exit 2 (1 for a solver failure), never a
traceback or an "internal error"; ``--json`` output strict JSON. Wiring only."""

import json

import pytest

from linecontact.cli import main

G = ["--R-over-h", "100", "--sigma0-over-E", "0.2"]
SI = ["--radius", "50e-9", "--modulus", "100e9", "--sigma0", "1e9", "--h", "0.5e-9"]


def run(capsys, *argv):
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def strict_json(text):
    def refuse(c):
        raise ValueError(f"not strict JSON: {c}")

    return json.loads(text, parse_constant=refuse)


@pytest.mark.parametrize("argv, key, value", [
    (["normal", *G, "--F-over-Eh", "-1e-1", "--json"], "F_over_Eh", -0.1),
    (["normal", *G, "--F-over-Eh", "-1.5E+0", "--json"], "F_over_Eh", -1.5),
    (["normal", *G, "--F-over-Eh", "-inf"], None, "F_over_Eh must be a finite number, got -inf"),
    (["roll", "--tau0-over-E", "0.01", "--d-over-a", "-5e-1", "--json"], "d_over_a", -0.5),
    (["normal", *SI, "--load", "-5e-1", "--json"], "F_N_per_m", -0.5),
])
def test_negative_numbers_in_scientific_notation(capsys, argv, key, value):
    """argparse took '-1e-1' for an option: 'argument --F-over-Eh: expected at least one
    argument'."""
    code, out, err = run(capsys, *argv)
    if key is None:  # reaches the API, which names the parameter
        assert code == 2 and value in err
        return
    assert code == 0, err
    rec = strict_json(out)[0]
    assert rec[key] == pytest.approx(value, rel=1e-9)
