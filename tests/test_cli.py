"""CLI: wiring and format only (the numbers are tested in the physics tests)."""

import json
import math
import os
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from linecontact import __version__ as lc_version
from linecontact import contact_for_load, normal_contact, pull_off, zero_width_load
from linecontact.cli import main

#: The project root (this file is tests/test_cli.py in it).
PROJECT = Path(__file__).resolve().parents[1]
#: An environment variable that points at the shared CLI-contract checker.
CHECKER_ENV = "LINECONTACT_CONTRACT_CHECKER"
#: Where the checker lives relative to a folder that holds ``shared/`` (the project root's
#: parent in the usual layout: ``<root>/../shared/tools/check-cli-contract``).
CHECKER_PATH = Path("shared", "tools", "check-cli-contract")


def run(capsys, *argv):
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def records(text):
    """The records of a --json output, each with the run's parameters merged in."""
    doc = json.loads(text)
    assert set(doc) == {"linecontact", "command", "parameters", "units", "results"}
    return [{**doc["parameters"], **r} for r in doc["results"]]


def test_normal_json_contract(capsys):
    code, out, err = run(
        capsys,
        "normal",
        "--R-over-h",
        "100",
        "--sigma0-over-E",
        "0.01",
        "--a-over-R",
        "0.01",
        "0.05",
        "--json",
    )
    assert code == 0, err
    recs = records(out)
    assert len(recs) == 2
    ref = normal_contact([0.01, 0.05], 100, 0.01)
    for rec, a, c, F in zip(recs, ref.a_over_R, ref.c_over_R, ref.F_over_Eh, strict=True):
        assert rec["a_over_R"] == a and rec["c_over_R"] == c and rec["F_over_Eh"] == F


def test_normal_range_and_collocation(capsys):
    code, out, _ = run(
        capsys,
        "normal",
        "--R-over-h",
        "200",
        "--sigma0-over-E",
        "0.02",
        "--a-over-R-range",
        "0.01",
        "0.05",
        "5",
        "--method",
        "collocation",
        "--json",
    )
    assert code == 0
    recs = records(out)
    np.testing.assert_allclose([r["a_over_R"] for r in recs], np.linspace(0.01, 0.05, 5))
    assert all(r["method"] == "collocation" and r["n_collocation"] >= 16 for r in recs)


def test_normal_inverse_branches(capsys):
    po = pull_off(100, 0.2)
    F = 0.5 * (po.F_pulloff_over_Eh + po.F_zero_width_over_Eh)
    code, out, _ = run(
        capsys,
        "normal",
        "--R-over-h",
        "100",
        "--sigma0-over-E",
        "0.2",
        "--F-over-Eh",
        repr(F),
        "--branch",
        "unstable",
        "--json",
    )
    assert code == 0
    rec = records(out)[0]
    assert rec["stable"] is False and rec["a_over_R"] < po.a_over_R_at_pulloff
    assert math.isclose(rec["F_over_Eh"], F, rel_tol=1e-9)


def test_pulloff_json(capsys):
    code, out, _ = run(capsys, "pulloff", "--R-over-h", "100", "--sigma0-over-E", "0.01", "--json")
    assert code == 0
    (rec,) = records(out)
    assert rec["mechanism"] == "zero-width" and rec["a_over_R_at_pulloff"] < 1 / 100
    assert rec["F_zero_width_over_Eh"] == zero_width_load(100, 0.01)
    assert rec["F_pulloff_over_Eh"] == pytest.approx(rec["F_zero_width_over_Eh"], rel=1e-8)
    code, out, _ = run(capsys, "pulloff", "--R-over-h", "100", "--sigma0-over-E", "0.2", "--json")
    (rec,) = records(out)
    assert rec["mechanism"] == "snap-off" and rec["a_over_R_at_pulloff"] > 0
    assert rec["F_pulloff_over_Eh"] < rec["F_zero_width_over_Eh"] < 0


def test_si_mode_matches_groups(capsys):
    # R = 50 nm, E = 100 GPa, sigma0 = 1 GPa, h = 0.5 nm  ->  R/h = 100, sigma0/E = 0.01
    code, out, _ = run(
        capsys,
        "pulloff",
        "--radius",
        "50e-9",
        "--modulus",
        "100e9",
        "--sigma0",
        "1e9",
        "--h",
        "0.5e-9",
        "--json",
    )
    assert code == 0
    (rec,) = records(out)
    assert math.isclose(
        rec["F_pulloff_over_Eh"], pull_off(100, 0.01).F_pulloff_over_Eh, rel_tol=1e-12
    )
    assert math.isclose(
        rec["F_pulloff_N_per_m"], rec["F_pulloff_over_Eh"] * 100e9 * 0.5e-9, rel_tol=1e-12
    )


def test_curve_csv_and_json(capsys, tmp_path):
    target = tmp_path / "curve.csv"
    code, _, err = run(
        capsys,
        "curve",
        "--R-over-h",
        "100",
        "--sigma0-over-E",
        "0.1",
        "--num",
        "20",
        "--num-noncontact",
        "5",
        "-o",
        str(target),
    )
    assert code == 0 and "wrote" in err
    text = target.read_text().splitlines()
    head = [t for t in text if t.startswith("#")]
    assert [t.split(":")[0] for t in head] == [
        "# linecontact",
        "# command",
        "# parameters",
        "# units",
    ]
    assert json.loads(head[2].split(": ", 1)[1])["R_over_h"] == 100
    rows = [r for r in text if not r.startswith("#")]
    assert rows[0].split(",")[0] == "branch" and len(rows) >= 1 + 5 + 20
    code, out, _ = run(
        capsys,
        "curve",
        "--R-over-h",
        "100",
        "--sigma0-over-E",
        "0.1",
        "--num",
        "20",
        "--num-noncontact",
        "5",
        "--json",
    )
    pts = records(out)
    assert sum(p["pulloff"] for p in pts) == 1
    assert {p["branch"] for p in pts} == {"contact", "non-contact"}
    (po,) = [p for p in pts if p["pulloff"]]
    assert po["F_over_Eh"] == pytest.approx(pull_off(100, 0.1).F_pulloff_over_Eh, rel=1e-12)
    assert min(p["F_over_Eh"] for p in pts) == pytest.approx(po["F_over_Eh"])


def test_cite_and_version(capsys):
    code, out, _ = run(capsys, "cite")
    assert code == 0 and "Sari" in out and "doi" in out
    with pytest.raises(SystemExit) as exc:
        main(["--version"])
    assert exc.value.code == 0


BAD = [
    (
        ["normal", "--R-over-h", "-1", "--sigma0-over-E", "0.01", "--a-over-R", "0.01"],
        "--R-over-h must be in",
    ),
    (
        ["normal", "--R-over-h", "100", "--sigma0-over-E", "0.01", "--a-over-R", "0"],
        "--a-over-R must be in",
    ),
    (["normal", "--R-over-h", "100", "--sigma0-over-E", "0.01"], "exactly one of"),
    (["pulloff", "--R-over-h", "100", "--sigma0-over-E", "nan"], "--sigma0-over-E"),
    (["pulloff", "--R-over-h", "100"], "--sigma0-over-E"),
    (["pulloff", "--R-over-h", "100", "--sigma0-over-E", "0.1", "--radius", "1e-8"], "not both"),
    (
        [
            "pulloff",
            "--radius",
            "1e-8",
            "--E1",
            "1e11",
            "--nu1",
            "0.7",
            "--E2",
            "1e11",
            "--nu2",
            "0.3",
            "--sigma0",
            "1e9",
            "--h",
            "1e-9",
        ],
        "--nu1 must be in",
    ),
    (["normal", "--R-over-h", "x", "--sigma0-over-E", "0.1", "--a-over-R", "0.1"], "invalid float"),
    (["curve", "--R-over-h", "100", "--sigma0-over-E", "0.1", "--num", "1"], "num must be"),
]


@pytest.mark.parametrize(("argv", "message"), BAD)
def test_bad_input_exit_2(capsys, argv, message):
    with pytest.raises(SystemExit) if "invalid float" in message else _nullcontext() as exc:
        code = main(argv)
    if "invalid float" in message:
        code = exc.value.code
    _, err = capsys.readouterr()
    assert code == 2
    assert "error:" in err and message in err and "Traceback" not in err
    assert len(err.strip().splitlines()) == 1


class _nullcontext:
    def __enter__(self):
        return None

    def __exit__(self, *exc):
        return False


def test_module_entry_point():
    p = subprocess.run(
        [
            sys.executable,
            "-m",
            "linecontact",
            "pulloff",
            "--R-over-h",
            "10",
            "--sigma0-over-E",
            "0.001",
            "--json",
        ],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert p.returncode == 0, p.stderr
    assert records(p.stdout)[0]["mechanism"] in ("zero-width", "snap-off")


def find_contract_checker(environ=os.environ, root=PROJECT):
    """The shared CLI-contract checker: ``$LINECONTACT_CONTRACT_CHECKER`` if set, else
    ``shared/tools/check-cli-contract`` in the project root's parent or a folder above it
    (a worktree may sit one level deeper than the main checkout).

    Returns ``(path or None, the places looked at)``.
    """
    if environ.get(CHECKER_ENV):
        path = Path(environ[CHECKER_ENV]).expanduser()
        return path, [f"${CHECKER_ENV} = {path}"]
    looked = [parent / CHECKER_PATH for parent in root.parents]
    return next((p for p in looked if p.is_file()), None), [str(p) for p in looked]


def test_contract_checker_is_found_where_it_lives(tmp_path, monkeypatch):
    # beside the project root: <parent>/shared/tools/check-cli-contract
    root = tmp_path / "work" / "wt-tests"
    checker = tmp_path / "work" / CHECKER_PATH
    checker.parent.mkdir(parents=True)
    root.mkdir()
    assert find_contract_checker({}, root) == (None, [str(p / CHECKER_PATH) for p in root.parents])
    checker.write_text("")
    assert find_contract_checker({}, root)[0] == checker
    # from a worktree one level deeper
    assert find_contract_checker({}, tmp_path / "work" / "trees" / "t1")[0] == checker
    # the environment variable wins, and is reported as such
    other = tmp_path / "elsewhere" / "checker"
    path, looked = find_contract_checker({CHECKER_ENV: str(other)}, root)
    assert path == other and looked == [f"${CHECKER_ENV} = {other}"]


def _linecontact_on_path(tmp_path):
    """A PATH whose first ``linecontact`` runs this interpreter's package: the console script
    installed beside ``sys.executable`` if there is one, else a shim in ``tmp_path`` that runs
    ``python -m linecontact``. None where neither is possible (no script, not POSIX)."""
    bindir = Path(sys.executable).parent
    if not (bindir / "linecontact").is_file():
        if os.name != "posix":
            return None
        bindir = tmp_path / "bin"
        bindir.mkdir()
        shim = bindir / "linecontact"
        shim.write_text(f'#!/bin/sh\nexec "{sys.executable}" -m linecontact "$@"\n')
        shim.chmod(0o755)
    return os.pathsep.join([str(bindir), os.environ.get("PATH", "")])


def test_shared_cli_contract(tmp_path):
    checker, looked = find_contract_checker()
    if checker is None:
        pytest.skip("the shared CLI-contract checker is absent; looked at " + ", ".join(looked))
    if not checker.is_file():  # named by the environment variable: a setup error, not a skip
        pytest.fail(f"${CHECKER_ENV} names {checker}, which is not a file")
    path = _linecontact_on_path(tmp_path)
    if path is None:  # pragma: no cover - Windows without the console script
        pytest.skip("no linecontact console script beside this interpreter")
    p = subprocess.run(
        [sys.executable, str(checker)],
        capture_output=True,
        text=True,
        timeout=600,
        env={**os.environ, "PATH": path},
    )
    assert "BROKEN" not in p.stdout, p.stdout
    assert p.returncode == 0, p.stdout + p.stderr
    # the subcommands that exist were checked (not all reported "not yet")
    for name in ("normal", "pulloff", "slide-init", "roll", "slide"):
        assert re.search(rf"^{re.escape(name)}\s+ok$", p.stdout, re.M), p.stdout


def test_coupling_warning_is_one_line(capsys):
    code, out, err = run(
        capsys,
        "pulloff",
        "--radius",
        "50e-9",
        "--E1",
        "70e9",
        "--nu1",
        "0.17",
        "--E2",
        "160e9",
        "--nu2",
        "0.22",
        "--sigma0",
        "1e9",
        "--h",
        "0.5e-9",
        "--json",
    )
    assert code == 0 and records(out)[0]["mechanism"] in ("zero-width", "snap-off")
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("linecontact pulloff: warning: Dundurs beta")


def test_table_rounds_a_load_of_round_off_size_to_zero(capsys):
    # at the width where the load crosses zero the closed form leaves ~1e-15 of round-off
    a = contact_for_load(0.0, 100.0, 0.01).a_over_R
    F = normal_contact(a, 100.0, 0.01).F_over_Eh
    assert F != 0 and abs(F) < 1e-13
    argv = ["normal", "--R-over-h", "100", "--sigma0-over-E", "0.01", "--a-over-R", repr(a)]
    code, out, _ = run(capsys, *argv)
    assert code == 0 and out.splitlines()[-1].split()[2] == "0"
    code, out, _ = run(capsys, *argv, "--json")
    assert records(out)[0]["F_over_Eh"] == F  # full precision in JSON


def test_every_option_is_documented_and_every_command_has_examples(capsys):
    from linecontact.cli import build_parser

    parser = build_parser()
    sub = parser._subparsers._group_actions[0]
    assert set(sub.choices) == {
        "normal",
        "pulloff",
        "curve",
        "slide-init",
        "roll",
        "cycle",
        "history",
        "slide",
        "push",
        "paper",
        "figures",
        "map",
        "materials",
        "fit-adhesion",
        "fit-friction",
        "fit-bent-wire",
        "cite",
        "sweep",
        "serve",
    }
    for name, p in sub.choices.items():
        for action in p._actions:
            assert action.help, f"{name} {action.option_strings} has no help"
        assert p.description, name
        if name != "cite":
            assert "examples:" in (p.epilog or ""), name
    with pytest.raises(SystemExit):
        main(["normal", "--help"])
    out = capsys.readouterr().out
    assert "(default: closed-form)" in out and "[m]" in out and "[N/m]" in out


def test_version_is_one_line(capsys):
    with pytest.raises(SystemExit) as exc:
        main(["--version"])
    assert exc.value.code == 0
    assert capsys.readouterr().out == f"linecontact {lc_version}\n"


@pytest.mark.parametrize(
    "argv",
    [
        ["normal", "--R-over-h", "100", "--sigma0-over-E", "0.01", "--a-over-R", "0.01"],
        ["slide-init", "--tau0-over-E", "0.01", "--d-over-a", "0.5"],
        [
            "slide",
            "--R-over-h2",
            "100",
            "--h1-over-h2",
            "2",
            "--sigma0-over-E",
            "0.01",
            "--a-over-R",
            "0.01",
        ],
    ],
)
def test_length_needs_si_inputs(capsys, argv):
    code, out, err = run(capsys, *argv, "--length", "5e-6")
    assert code == 2 and out == "" and err.count("\n") == 1
    assert "--length [m] gives the totals of SI forces" in err


def test_pulloff_law_lennard_jones_si_json():
    import json
    import subprocess
    import sys

    out = subprocess.run(
        [
            sys.executable,
            "-m",
            "linecontact",
            "pulloff",
            "--radius",
            "50e-9",
            "--modulus",
            "10e9",
            "--work-of-adhesion",
            "0.05",
            "--z0",
            "0.3e-9",
            "--law",
            "lennard-jones",
            "--json",
        ],
        capture_output=True,
        text=True,
        check=True,
    )
    doc = json.loads(out.stdout)
    (rec,) = doc["results"]
    assert doc["parameters"]["law"] == "lennard-jones"
    assert rec["F_pulloff_N_per_m"] < 0 and rec["error_estimate_over_Eh"] > 0
    bad = subprocess.run(
        [
            sys.executable,
            "-m",
            "linecontact",
            "pulloff",
            "--R-over-h",
            "100",
            "--sigma0-over-E",
            "inf",
            "--law",
            "lennard-jones",
        ],
        capture_output=True,
        text=True,
    )
    assert bad.returncode == 2 and bad.stderr.count("error:") == 1
    assert "Traceback" not in bad.stderr and "--sigma0-over-E" in bad.stderr


@pytest.mark.parametrize(
    ("argv", "said"),
    [
        (["pulloff", "--foo", "1"], "linecontact pulloff: error: unrecognized arguments: --foo 1"),
        (["pulloff", "--body", "sphere", "--num", "3"], "linecontact pulloff: error: unrecognized"),
        (["--foo"], "linecontact: error: unrecognized arguments: --foo"),
    ],
)
def test_an_unknown_flag_is_named_by_its_command(capsys, argv, said):
    # found by fuzzing: every unknown flag was said by the top parser, whatever the command
    with pytest.raises(SystemExit) as exc:
        main(argv)
    assert exc.value.code == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert err[-1].startswith(said)
