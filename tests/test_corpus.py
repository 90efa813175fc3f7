"""The corpus of command lines (``tests/corpus/cases.txt``): each ends as it was recorded.

``tests/corpus/compare.py REV`` runs the corpus with two versions and compares their
outputs byte for byte (issue 32 moved every subcommand onto the operations' declarations
with it: identical). Here, on any machine, each command line gives the exit status
recorded (``status.json``), one ``error:`` line naming a flag where it is refused, and
where it asks for JSON the provenance object with its records.
"""

from __future__ import annotations

import json
import shlex
import shutil
import warnings
from pathlib import Path

import pytest

from linecontact.cli import main

CORPUS = Path(__file__).resolve().parent / "corpus"
CASES = [
    s.strip()
    for s in (CORPUS / "cases.txt").read_text(encoding="utf-8").splitlines()
    if s.strip() and not s.startswith("#")
]
STATUS = json.loads((CORPUS / "status.json").read_text(encoding="utf-8"))


def test_every_case_has_its_recorded_status():
    assert sorted(STATUS) == sorted(CASES)
    assert len(CASES) >= 50
    assert {0, 2} <= set(STATUS.values())  # runs and refusals both


@pytest.mark.parametrize("line", CASES)
def test_a_command_line_ends_as_recorded(line, tmp_path, monkeypatch, capsys):
    for f in CORPUS.glob("*.csv"):
        shutil.copy(f, tmp_path / f.name)
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("COLUMNS", "100")
    argv = shlex.split(line)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        try:
            status = main(argv)
        except SystemExit as exc:  # --help (0) and argparse's own refusals (2)
            status = int(exc.code or 0)
    out, err = capsys.readouterr()
    assert status == STATUS[line], (line, err)
    if status == 2:
        said = [s for s in err.splitlines() if ": error: " in s]
        # the flag, or a positional by its name in the help (``materials NAME``)
        assert len(said) == 1 and ("--" in said[0] or "NAME" in said[0]), err
    elif "--json" in argv and status == 0:
        doc = json.loads(out)
        assert set(doc) >= {"linecontact", "command", "parameters", "units", "results"}
        assert doc["command"][:2] == ["linecontact", argv[0]] and doc["results"]
