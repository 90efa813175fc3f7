"""The command line starts fast and says little: help on one screen, short table headers.

A run imports only its own subcommand's module (``linecontact.cli.COMMANDS``); every
``linecontact SUB --help`` fits one screen at 100 columns (the details are in docs/cli.md);
a table names material presets, their citations stay in the JSON and CSV provenance.
"""

import json
import subprocess
import sys

import pytest

from linecontact.cli import COMMANDS, build_parser, main

WIDTH = 100


def _help(capsys, monkeypatch, *argv):
    monkeypatch.setenv("COLUMNS", str(WIDTH))
    with pytest.raises(SystemExit) as exc:
        main([*argv, "--help"])
    assert exc.value.code == 0
    return capsys.readouterr().out


@pytest.mark.parametrize("command", list(COMMANDS))
def test_every_subcommand_help_fits_one_screen(capsys, monkeypatch, command):
    out = _help(capsys, monkeypatch, command)
    lines = out.splitlines()
    assert len(lines) < 40, f"{command} --help: {len(lines)} lines"
    shown = sum(max(1, -(-len(s) // WIDTH)) for s in lines)  # as a terminal wraps them
    assert shown < 40, f"{command} --help: {shown} lines on a {WIDTH}-column screen"
    assert lines[0].startswith(f"usage: linecontact {command}")
    assert "Si3N4" not in out  # the presets' names are `linecontact materials`'s


def test_the_top_level_help_lists_every_subcommand_with_its_summary(capsys, monkeypatch):
    out = "".join(_help(capsys, monkeypatch).split())  # wrapped lines (and hyphens) joined
    for name, (_, summary) in COMMANDS.items():
        assert name + "".join(summary.split()) in out, name


def test_the_registry_says_what_the_modules_say():
    sub = build_parser()._subparsers._group_actions[0]  # every module's full parser
    assert list(sub.choices) == list(COMMANDS)
    summaries = {a.dest: a.help for a in sub._choices_actions}
    assert summaries == {name: summary for name, (_, summary) in COMMANDS.items()}
    for name, (module, _) in COMMANDS.items():
        assert sub.choices[name].get_default("func").__module__ == f"linecontact.cli.{module}"


def test_a_stub_is_never_a_full_parser_and_a_run_gets_its_own():
    sub = build_parser(["pulloff", "--R-over-h", "100"])._subparsers._group_actions[0]
    assert list(sub.choices) == list(COMMANDS)
    for name, p in sub.choices.items():
        full = name == "pulloff"  # an operation's subcommand is built alone
        assert (p.get_default("func") is not None) == full, name


_PROBE = """
import sys
from linecontact.cli import main
try:
    main({argv!r})
except SystemExit:
    pass
mods = sorted(m for m in sys.modules if m.startswith("linecontact.cli."))
heavy = sorted(m for m in ("scipy.linalg", "matplotlib", "linecontact.figures") if m in sys.modules)
print("MODULES", " ".join(mods), "|", " ".join(heavy), file=sys.stderr)
"""


@pytest.mark.parametrize(
    ("argv", "modules"),
    [
        (["--help"], ["linecontact.cli._options"]),
        (
            ["normal", "--a-over-R", "0.02", "--R-over-h", "100", "--sigma0-over-E", "0.01"],
            ["linecontact.cli._build", "linecontact.cli._options"],
        ),
        (
            ["slide-init", "--help"],
            ["linecontact.cli._build", "linecontact.cli._options"],
        ),
    ],
)
def test_a_run_imports_only_its_own_subcommand(argv, modules):
    proc = subprocess.run(
        [sys.executable, "-c", _PROBE.format(argv=argv)],
        capture_output=True,
        text=True,
        timeout=120,
        stdin=subprocess.DEVNULL,
    )
    line = [s for s in proc.stderr.splitlines() if s.startswith("MODULES")][-1]
    mods, heavy = line.removeprefix("MODULES").split("|")
    assert mods.split() == modules
    assert heavy.split() == []


SI_PULLOFF = [
    "pulloff",
    "--radius",
    "50e-9",
    "--cylinder-material",
    "ZnO",
    "--substrate-material",
    "SiO2",
    "--work-of-adhesion",
    "0.1",
    "--z0",
    "0.3e-9",
    "--quiet",
]


def test_a_table_names_the_presets_without_their_citations(capsys):
    assert main([*SI_PULLOFF, "--format", "table"]) == 0
    out = capsys.readouterr().out
    assert max(len(s) for s in out.splitlines()) <= 200
    assert "cylinder_material = ZnO" in out and "substrate_material = SiO2" in out
    assert "Kobiakov" not in out and "doi:" not in out
    assert main([*SI_PULLOFF, "--json"]) == 0
    params = json.loads(capsys.readouterr().out)["parameters"]
    assert params["cylinder_material"] == "ZnO" and "Kobiakov" in params["cylinder_source"]
    assert params["substrate_material"] == "SiO2" and params["substrate_source"]
