"""One name per quantity: every subcommand's flags against the table in docs/cli.md.

The table ("One name per quantity") gives each quantity its one flag, the subcommands that
take it and the old spellings that remain as deprecated aliases. Every flag of every parser
must be in it under its quantity; no two flags of different names may mean one quantity; an
alias does what its new flag does and says so in one ``warning:`` line.
"""

from __future__ import annotations

import argparse
import json
import pathlib
import re
import warnings

import pytest

from linecontact.cli import build_parser, main
from linecontact.cli._options import COUPLING_EFFECT
from linecontact.errors import CouplingWarning, ModelValidityWarning, UnitsWarning

DOC = pathlib.Path(__file__).resolve().parents[1] / "docs" / "cli.md"

SI = (
    "normal, pulloff, curve, slide-init, roll, cycle, history, fit-adhesion, fit-friction, "
    "slide, push"
)
GROUPS = {"SI": SI, "data": SI + ", fit-bent-wire, map, materials"}


def _commands(cell: str) -> set[str]:
    out: set[str] = set()
    for c in (c.strip() for c in cell.split(",") if c.strip()):  # a group (SI, data) or one
        out |= {x.strip() for x in GROUPS[c].split(",")} if c in GROUPS else {c}
    return out


def _table() -> list[dict]:
    """The rows of the table: quantity, flag, short forms, subcommands, aliases."""
    text = DOC.read_text(encoding="utf-8")
    start = text.index("## One name per quantity")
    rows = []
    for line in text[start:].splitlines()[1:]:
        if line.startswith("## "):
            break
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if not line.startswith("|") or len(cells) != 5 or cells[0] in ("Quantity", "---"):
            continue
        quantity, flag, short, where, aliases = cells
        rows.append(
            {
                "quantity": quantity,
                "flag": flag.strip("`"),
                "short": re.findall(r"^`(-[\w-]+)`", short),
                "commands": _commands(where),
                "aliases": {
                    old: _commands(cmds)
                    for old, cmds in re.findall(r"`(--[\w-]+)` \(([^)]*)\)", aliases)
                },
            }
        )
    return rows


TABLE = _table()


def _parsers() -> dict[str, argparse.ArgumentParser]:
    p = build_parser()
    sub = next(a for a in p._actions if isinstance(a, argparse._SubParsersAction))
    return dict(sub.choices)


PARSERS = _parsers()


def _options(sp: argparse.ArgumentParser):
    """(long flag, action, hidden) of each option of ``sp`` but --help."""
    for a in sp._actions:
        if not a.option_strings or isinstance(a, argparse._HelpAction):
            continue
        long = [s for s in a.option_strings if s.startswith("--")][0]
        yield long, a, a.help == argparse.SUPPRESS


def test_the_table_is_there_and_one_name_each():
    assert len(TABLE) > 50
    flags = [r["flag"] for r in TABLE]
    quantities = [r["quantity"] for r in TABLE]
    assert len(set(flags)) == len(flags), "a flag in two rows"
    assert len(set(quantities)) == len(quantities), "a quantity in two rows"
    for r in TABLE:
        assert r["commands"] <= set(PARSERS), r
        for old, cmds in r["aliases"].items():
            assert cmds <= set(PARSERS), (old, cmds)


@pytest.mark.parametrize("command", sorted(PARSERS))
def test_every_flag_is_in_the_table(command):
    sp = PARSERS[command]
    by_flag = {r["flag"]: r for r in TABLE}
    shorts = {s: r for r in TABLE for s in r["short"]}
    meaning: dict[str, str] = {}  # quantity -> the visible flag of this command
    for long, action, hidden in _options(sp):
        if hidden:  # a deprecated alias: listed under the quantity of its new flag
            target = action.target
            new = [s for s in target.option_strings if s.startswith("--")][0]
            row = by_flag[new]
            assert command in row["aliases"].get(long, set()), (
                f"{command} {long}: an alias of {new} not listed in docs/cli.md"
            )
            assert action.dest == target.dest
            continue
        row = by_flag.get(long) or shorts.get(long)
        assert row is not None, f"{command} {long}: not in the table of docs/cli.md"
        assert command in row["commands"], f"{command} {long}: not listed for {command}"
        if long in shorts:  # a short form (--json) goes with its flag
            continue
        other = meaning.setdefault(row["quantity"], long)
        assert other == long, f"{command}: {other} and {long} both mean {row['quantity']}"


def test_the_table_lists_no_flag_a_command_lacks():
    for r in TABLE:
        for command in r["commands"]:
            have = {long for long, _, hidden in _options(PARSERS[command]) if not hidden}
            assert r["flag"] in have, f"{command} has no {r['flag']} (docs/cli.md says so)"
        for old, commands in r["aliases"].items():
            for command in commands:
                hidden = {long for long, _, h in _options(PARSERS[command]) if h}
                assert old in hidden, f"{command} has no deprecated {old}"


def _run(capsys, *argv: str):
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def _results(out: str) -> dict:
    d = json.loads(out)
    d.pop("command")
    return d


SI0 = ["--radius", "50e-9", "--modulus", "100e9"]


@pytest.mark.parametrize(
    ("old", "new"),
    [
        (
            ["normal", *SI0, "--sigma0", "1e9", "--h", "0.5e-9", "--a", "2e-9", "--json"],
            ["normal", *SI0, "--sigma0", "1e9", "--h", "0.5e-9", "--half-width", "2e-9", "--json"],
        ),
        (
            [
                "fit-friction",
                "--normal-load",
                "0.5",
                "--friction-force",
                "0.2",
                "--radius",
                "50e-9",
                "--modulus",
                "51.7e9",
                "--work-of-adhesion",
                "0.1",
                "--receding-work-of-adhesion",
                "0.15",
                "--z0",
                "0.3e-9",
                "--samples",
                "100",
                "--json",
            ],
            [
                "fit-friction",
                "--load",
                "0.5",
                "--friction-force",
                "0.2",
                "--radius",
                "50e-9",
                "--modulus",
                "51.7e9",
                "--work-of-adhesion",
                "0.1",
                "--work-of-adhesion-receding",
                "0.15",
                "--z0",
                "0.3e-9",
                "--samples",
                "100",
                "--json",
            ],
        ),
        (
            [
                "push",
                *SI0,
                "--work-of-adhesion",
                "0.1",
                "--z0",
                "0.3e-9",
                "--h1",
                "0.6e-9",
                "--tau0",
                "1e6",
                "--height",
                "25e-9",
                "--json",
            ],
            [
                "push",
                *SI0,
                "--work-of-adhesion-advancing",
                "0.1",
                "--z0",
                "0.3e-9",
                "--h1",
                "0.6e-9",
                "--tau0",
                "1e6",
                "--height",
                "25e-9",
                "--json",
            ],
        ),
    ],
    ids=["half-width", "fit-friction", "push"],
)
def test_an_old_spelling_gives_the_same_results_and_names_the_new(capsys, old, new):
    code_new, out_new, err_new = _run(capsys, *new)
    code_old, out_old, err_old = _run(capsys, *old)
    assert code_old == code_new == 0
    assert _results(out_old) == _results(out_new)
    assert "deprecated" not in err_new
    notes = [line for line in err_old.splitlines() if "deprecated" in line]
    assert notes and all(": warning: --" in n and "use --" in n for n in notes)
    assert len(notes) == len({n for n in notes})
    # --quiet does not hide how to spell it
    _, _, err_quiet = _run(capsys, *old, "--quiet")
    assert [line for line in err_quiet.splitlines() if "deprecated" in line] == notes


def test_image_format_and_its_old_spelling():
    parsers = build_parser(["map"])
    for argv, fmt, images, note in (
        (["map", "--image-format", "svg"], None, "svg", False),
        (["map", "--format", "png,pdf"], None, "png,pdf", True),  # the old meaning
        (["map", "--json"], "json", "png", False),
        (["map", "--format", "csv", "-o", "x.csv"], "csv", "png", False),
    ):
        args = parsers.parse_args(argv)
        assert (args.format, args.image_format) == (fmt, images), argv
        assert bool(getattr(args, "_deprecated", None)) == note, argv
    args = build_parser(["paper"]).parse_args(["paper", "--format", "svg"])
    assert args.image_format == "svg" and "--image-format" in args._deprecated[0]


def test_map_format_refuses_what_is_neither(capsys):
    with pytest.raises(SystemExit) as e:
        build_parser(["map"]).parse_args(["map", "--format", "gif"])
    assert e.value.code == 2
    assert "--image-format" in capsys.readouterr().err


def test_units_warnings_are_model_validity_warnings():
    assert issubclass(UnitsWarning, ModelValidityWarning)
    from linecontact import Cylinder

    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        Cylinder.from_modulus(50.0, 100e9, cohesive_stress=1e9, adhesion_range=0.5e-9)
    assert any(issubclass(w.category, UnitsWarning) for w in caught)


UNITS = ["normal", "--radius", "50", "--modulus", "100e9", "--sigma0", "1e9", "--h", "5e-10"]
COUPLED = [
    "normal",
    "--radius",
    "50e-9",
    "--E1",
    "1e9",
    "--nu1",
    "0.45",
    "--E2",
    "400e9",
    "--nu2",
    "0.1",
    "--sigma0",
    "1e8",
    "--h",
    "5e-10",
]


def test_quiet_keeps_the_units_warnings(capsys):
    code, _, err = _run(capsys, *UNITS, "--load", "1", "2")
    assert code == 0 and "is the radius in m?" in err
    code, _, quiet = _run(capsys, *UNITS, "--load", "1", "2", "--quiet")
    assert code == 0 and quiet == err


def test_the_coupling_note_says_its_effect_once_and_quiet_hides_it(capsys):
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        from linecontact import Cylinder

        Cylinder.from_materials(
            50e-9, 1e9, 0.45, 400e9, 0.1, cohesive_stress=1e8, adhesion_range=5e-10
        )
    assert any(issubclass(w.category, CouplingWarning) for w in caught), "beta is not large"
    code, _, err = _run(capsys, *COUPLED, "--load", "0.1", "0.2")
    assert code == 0
    lines = [line for line in err.splitlines() if "Dundurs beta" in line]
    assert len(lines) == 1 and lines[0].count(COUPLING_EFFECT) == 1
    assert "beta^2" in lines[0] and "Johnson 1985" in lines[0]
    code, _, quiet = _run(capsys, *COUPLED, "--load", "0.1", "0.2", "--quiet")
    assert code == 0 and "Dundurs" not in quiet


CHEAP = ["--mu-min", "0.01", "--mu-max", "0.02", "--n-mu", "2", "--y-max", "2", "--n-y", "6"]


def test_map_writes_its_data_with_o_as_the_others(capsys, tmp_path):
    pytest.importorskip("matplotlib")
    out = tmp_path / "maps"
    argv = ["map", "--outdir", str(out), "--image-format", "svg", "--tol", "0.1", *CHEAP]
    code, stdout, err = _run(capsys, *argv, "-o", str(tmp_path / "cells.jsonl"))
    assert code == 0, err
    assert stdout == "" and f"wrote {tmp_path / 'cells.jsonl'}" in err
    lines = (tmp_path / "cells.jsonl").read_text().splitlines()
    assert json.loads(lines[0])["command"][:2] == ["linecontact", "map"]
    assert len(lines) == 1 + 2 * 6  # the provenance, then one record per cell
    assert sorted(p.name for p in out.iterdir()) == ["adhesion_map.csv", "adhesion_map.svg"]
    code, stdout, err = _run(capsys, *argv, "--json")
    assert code == 0, err
    assert len(json.loads(stdout)["results"]) == 2 * 6
