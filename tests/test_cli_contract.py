"""The output contract of every subcommand, in every format, nondimensional and SI.

Wiring and format only: the four formats carry the same provenance block and the same
records; the contracted keys are there; every number has a unit; a file written with ``-o``
is the text printed on stdout and nothing else is left in its directory.
"""

import csv
import json
import math

import pytest

from linecontact import __version__
from linecontact.cli import main

SI = ["--radius", "50e-9", "--modulus", "100e9", "--sigma0", "1e9", "--h", "0.5e-9"]
SI2 = ["--radius", "50e-9", "--modulus", "100e9", "--sigma0", "1e9", "--h2", "0.5e-9"]

CASES = {
    ("cycle", "nd"): (
        ["cycle", "--tau0-over-E", "0.01", "--T-amplitude-over-Ea", "0.005", "0.015", "0.03"],
        ["T_amplitude_over_Ea", "W_over_Ea2", "c_over_a", "state"],
        3,
    ),
    ("cycle", "si"): (
        [
            "cycle",
            *SI,
            "--load",
            "1",
            "--tau0",
            "1e9",
            "--tangential-amplitude",
            "0.5",
            "2",
            "--length",
            "5e-6",
        ],
        ["T_amplitude_over_Ea", "W_over_Ea2", "c_over_a", "W_J_per_m", "c_m", "W_total_J"],
        2,
    ),
    ("history", "nd"): (
        ["history", "--tau0-over-E", "0.01", "--T-over-Ea", "0.016", "-0.008", "0.004"],
        ["step", "T_over_Ea", "state", "c_over_a", "slip_direction", "memory", "zones"],
        3,
    ),
    ("history", "si"): (
        ["history", *SI, "--load", "1", "--tau0", "1e9", "--tangential-load", "1", "-1", "1"],
        ["step", "T_N_per_m", "c_m", "displacement_m", "dissipation_J_per_m", "zones"],
        3,
    ),
    ("normal", "nd"): (
        ["normal", "--R-over-h", "100", "--sigma0-over-E", "0.01", "--a-over-R", "0.01", "0.05"],
        ["a_over_R", "c_over_R", "F_over_Eh", "c_over_a", "stable", "state"],
        2,
    ),
    ("normal", "si"): (
        ["normal", *SI, "--load", "-1", "0", "1", "--length", "5e-6"],
        ["a_over_R", "c_over_R", "F_over_Eh", "a_m", "c_m", "F_N_per_m", "F_total_N"],
        3,
    ),
    ("pulloff", "nd"): (
        ["pulloff", "--R-over-h", "100", "--sigma0-over-E", "0.2"],
        ["F_pulloff_over_Eh", "a_over_R_at_pulloff", "mechanism", "F_zero_width_over_Eh"],
        1,
    ),
    ("pulloff", "si"): (
        ["pulloff", *SI, "--length", "5e-6"],
        ["F_pulloff_over_Eh", "mechanism", "F_pulloff_N_per_m", "F_pulloff_total_N"],
        1,
    ),
    ("pulloff", "sphere"): (
        ["pulloff", "--body", "sphere", *SI],
        ["F_pulloff_over_EhR", "F_pulloff_over_piwR", "mechanism", "F_pulloff_N", "a_at_pulloff_m"],
        1,
    ),
    ("normal", "sphere"): (
        ["normal", "--body", "sphere", *SI, "--force", "-1e-8", "0", "1e-7"],
        ["a_over_R", "F_over_EhR", "delta_over_h", "a_m", "c_m", "F_N", "delta_m", "stable"],
        3,
    ),
    ("curve", "sphere"): (
        [
            "curve",
            "--body",
            "sphere",
            "--R-over-h",
            "1e4",
            "--sigma0-over-E",
            "0.001",
            "--num",
            "7",
        ],
        ["branch", "a_over_R", "F_over_EhR", "delta_over_h", "pull_off_load"],
        7 + 40 + 1,  # the branches and the pull-off inserted (the other: at zero radius)
    ),
    ("curve", "nd"): (
        [
            "curve",
            "--R-over-h",
            "100",
            "--sigma0-over-E",
            "0.2",
            "--num",
            "8",
            "--num-noncontact",
            "3",
        ],
        [
            "branch",
            "central_gap_over_h",
            "a_over_R",
            "c_over_R",
            "F_over_Eh",
            "stable",
            "turning_point",
            "pulloff",
        ],
        11,
    ),
    ("curve", "si"): (
        ["curve", *SI, "--num", "8", "--num-noncontact", "3", "--length", "5e-6"],
        [
            "branch",
            "a_over_R",
            "F_over_Eh",
            "a_m",
            "c_m",
            "F_N_per_m",
            "central_gap_m",
            "F_total_N",
        ],
        11,
    ),
    ("slide-init", "nd"): (
        ["slide-init", "--tau0-over-E", "0.01", "--d-over-a", "0.2", "0.5"],
        ["d_over_a", "T_over_Ea", "T_over_T_full_slip", "state"],
        2,
    ),
    ("slide-init", "si"): (
        [
            "slide-init",
            *SI,
            "--load",
            "1",
            "--tau0",
            "1e8",
            "--tangential-load",
            "0.1",
            "0.3",
            "--length",
            "5e-6",
        ],
        ["d_over_a", "T_over_Ea", "state", "d_m", "T_N_per_m", "T_total_N"],
        2,
    ),
    ("roll", "nd"): (
        ["roll", "--tau0-over-E", "0.01", "--d-over-a", "-0.5", "0.5"],
        ["d_over_a", "T_over_Ea", "creep_over_V", "state"],
        2,
    ),
    ("roll", "si"): (
        ["roll", *SI, "--load", "1", "--tau0", "1e8", "--tangential-load", "0.1", "0.3"],
        ["d_over_a", "T_over_Ea", "creep_over_V", "d_m", "T_N_per_m"],
        2,
    ),
    ("slide", "nd"): (
        [
            "slide",
            "--R-over-h2",
            "100",
            "--h1-over-h2",
            "1.5",
            "--sigma0-over-E",
            "0.01",
            "--a-over-R",
            "0.01",
            "0.02",
        ],
        ["a_over_R", "c1_over_R", "c2_over_R", "e_over_R", "F_over_Eh2", "M_over_Eh2R"],
        2,
    ),
    ("slide", "si"): (
        ["slide", *SI2, "--h1", "1e-9", "--load", "0.05", "1", "--tau0", "5e8", "--length", "5e-6"],
        [
            "a_over_R",
            "c1_over_R",
            "F_over_Eh2",
            "M_over_Eh2R",
            "a_m",
            "F_N_per_m",
            "M_N",
            "T_N_per_m",
            "F_total_N",
            "M_total_N_m",
            "T_total_N",
        ],
        2,
    ),
    ("push", "nd"): (
        ["push", "--R-over-h2", "100", "--h1-over-h2", "2", "--sigma0-over-E", "0.04"]
        + ["--tau0-over-E", "0.002", "--F-over-Eh2", "0.5", "--H-over-R", "0.5", "1.5"],
        [
            "H_over_R",
            "a_rest_over_R",
            "a_slide_over_R",
            "Q_roll_over_Eh2",
            "Q_slide_over_Eh2",
            "H_critical_over_R",
            "first_motion",
        ],
        2,
    ),
    ("push", "si"): (
        ["push", "--radius", "50e-9", "--modulus", "48e9", "--sigma0", "1e8", "--h2", "0.3e-9"]
        + ["--h1", "0.6e-9", "--tau0", "1e6", "--height", "25e-9", "50e-9", "--push", "0.03"]
        + ["--length", "5e-6"],
        [
            "H_over_R",
            "first_motion",
            "state",
            "H_m",
            "a_slide_m",
            "Q_roll_N_per_m",
            "Q_slide_N_per_m",
            "H_critical_m",
            "Q_roll_total_N",
        ],
        2,
    ),
}
IDS = [f"{c}-{m}" for c, m in CASES]


def run(capsys, argv):
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def parse_json(text):
    doc = json.loads(text)
    assert list(doc) == ["linecontact", "command", "parameters", "units", "results"]
    return {k: doc[k] for k in ("linecontact", "command", "parameters", "units")}, doc["results"]


def parse_jsonl(text):
    lines = text.splitlines()
    head = json.loads(lines[0])
    assert list(head) == ["linecontact", "command", "parameters", "units"]
    return head, [json.loads(t) for t in lines[1:]]


def _csv_value(s):
    if s == "":
        return None
    if s in ("true", "false"):
        return s == "true"
    if s.startswith("["):  # a list (the zones of a history) as its JSON text
        return json.loads(s)
    try:
        v = float(s)
    except ValueError:
        return s
    return int(v) if s.lstrip("-").isdigit() else v


def parse_csv(text):
    lines = text.splitlines()
    head = {}
    while lines[0].startswith("# "):
        key, value = lines.pop(0)[2:].split(": ", 1)
        head[key] = json.loads(value)
    assert list(head) == ["linecontact", "command", "parameters", "units"]
    rows = list(csv.reader(lines))
    keys = rows[0]
    return head, [dict(zip(keys, map(_csv_value, row), strict=True)) for row in rows[1:]]


def same(a, b):
    if isinstance(a, float) and isinstance(b, (int, float)) and not isinstance(b, bool):
        return a == b or math.isclose(a, b, rel_tol=0, abs_tol=0)
    return a == b


@pytest.mark.parametrize("case", list(CASES), ids=IDS)
def test_every_format_carries_the_same_block_and_records(capsys, case):
    argv, keys, n = CASES[case]
    code, out, err = run(capsys, [*argv, "--format", "json"])
    assert code == 0, err
    head, recs = parse_json(out)
    assert head["linecontact"] == {"version": __version__}
    assert head["command"] == ["linecontact", *argv, "--format", "json"]
    assert len(recs) == n
    for rec in recs:
        assert set(keys) <= set(rec), set(keys) - set(rec)
    # every number of the block and the records has a unit
    numbers = {
        k
        for r in recs
        for k, v in r.items()
        if isinstance(v, (int, float)) and not isinstance(v, bool)
    }
    numbers |= {
        k
        for k, v in head["parameters"].items()
        if isinstance(v, (int, float)) and not isinstance(v, bool)
    }
    assert numbers <= set(head["units"]), sorted(numbers - set(head["units"]))
    # inputs the same at every point are in the block, not on the records
    assert not set(head["parameters"]) & {k for r in recs for k in r}
    for fmt, parse in (("jsonl", parse_jsonl), ("csv", parse_csv)):
        code, text, err = run(capsys, [*argv, "--format", fmt])
        assert code == 0, err
        h2, r2 = parse(text)
        assert h2["parameters"] == head["parameters"] and h2["units"] == head["units"]
        assert h2["command"][-1] == fmt
        assert len(r2) == n
        for a, b in zip(recs, r2, strict=True):
            assert list(a) == list(b)
            assert all(same(a[k], b[k]) for k in a), (fmt, a, b)
    code, text, err = run(capsys, [*argv, "--format", "table"])
    assert code == 0, err
    lines = text.splitlines()
    assert lines[0].startswith("# ") and lines[1].startswith("# ")
    assert len([t for t in lines if not t.startswith("#")]) == 1 + n


@pytest.mark.parametrize(
    "case",
    [("normal", "si"), ("pulloff", "nd"), ("slide", "si")],
    ids=["normal-si", "pulloff-nd", "slide-si"],
)
@pytest.mark.parametrize("fmt", ["json", "jsonl", "csv", "table"])
def test_a_file_is_the_printed_text(capsys, tmp_path, case, fmt):
    argv, _, _ = CASES[case]
    code, printed, _ = run(capsys, [*argv, "--format", fmt])
    target = tmp_path / f"out.{fmt}"
    code2, out, err = run(capsys, [*argv, "--format", fmt, "-o", str(target)])
    assert code == code2 == 0 and out == "" and err == f"wrote {target}\n"
    text = target.read_text()
    # the command line differs by the -o option only
    assert (
        text.replace(f',"-o","{target}"', "")
        .replace(f', "-o", "{target}"', "")
        .replace(f" -o {target}", "")
        == printed
        or fmt == "table"
    )
    assert sorted(p.name for p in tmp_path.iterdir()) == [target.name]


def test_the_format_follows_the_file_extension(capsys, tmp_path):
    argv, _, _ = CASES[("pulloff", "nd")]
    for ext, check in (("json", parse_json), ("jsonl", parse_jsonl), ("csv", parse_csv)):
        target = tmp_path / f"po.{ext}"
        assert run(capsys, [*argv, "-o", str(target)])[0] == 0
        _, recs = check(target.read_text())
        assert recs[0]["mechanism"] == "snap-off"


def test_indent_is_json_dumps_indent(capsys):
    argv, _, _ = CASES[("slide-init", "nd")]
    code, out, _ = run(capsys, [*argv, "--json", "--indent", "2"])
    assert code == 0
    assert out == json.dumps(json.loads(out), indent=2) + "\n"
    code, compact, _ = run(capsys, [*argv, "--json"])
    assert (
        "\n" not in compact.rstrip("\n")
        and json.loads(compact)["results"] == json.loads(out)["results"]
    )


@pytest.mark.parametrize("target", ["/nonexistent-dir/x.json", "{tmp}/a-file/x.json", "{tmp}"])
def test_unwritable_output_is_one_error_line_and_no_file(capsys, tmp_path, target):
    (tmp_path / "a-file").write_text("x")
    target = target.format(tmp=tmp_path)
    argv, _, _ = CASES[("pulloff", "nd")]
    code, out, err = run(capsys, [*argv, "--json", "-o", target])
    assert code == 2 and out == "" and err.count("\n") == 1
    assert err.startswith(
        (
            "linecontact pulloff: error: cannot write -o/--output",
            "linecontact pulloff: error: -o/--output",
        )
    ), err
    assert target in err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a-file"]
