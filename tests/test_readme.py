"""The README's tour and the details page run as printed.

Every Python block of README.md and docs/usage.md runs (in a fresh process, a temporary
folder); every command of the README's tour parses, and those that compute run; the domain
table of docs/usage.md is the code's.
"""

import re
import shlex
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
README = ROOT / "README.md"
USAGE = ROOT / "docs" / "usage.md"
BLOCKS = [
    block
    for page in (README, USAGE)
    if page.exists()
    for block in re.findall(r"```python\n(.*?)```", page.read_text(encoding="utf-8"), re.S)
]


def _tour() -> list[list[str]]:
    if not README.exists():
        return []
    text = README.read_text(encoding="utf-8")
    section = text[text.index("## A tour in 60 seconds") :]
    block = re.search(r"```bash\n(.*?)```", section, re.S).group(1)
    return [shlex.split(line)[1:] for line in block.splitlines() if line.startswith("linecontact ")]


TOUR = _tour()


@pytest.mark.skipif(not README.exists(), reason="README.md is not beside the tests")
def test_the_tour_touches_every_capability():
    commands = {words[0] for words in TOUR}
    assert {
        "pulloff", "normal", "slide-init", "roll", "slide", "push", "map", "cycle",
        "fit-adhesion", "sweep", "serve",
    } <= commands  # fmt: skip
    assert any("lennard-jones" in words for words in TOUR)
    assert len(README.read_text(encoding="utf-8").splitlines()) < 250


@pytest.mark.parametrize("words", TOUR, ids=[" ".join(w[:1]) for w in TOUR])
def test_each_tour_command_runs(words, tmp_path, monkeypatch, capsys):
    from linecontact.cli import build_parser, main

    build_parser(words).parse_args(words)  # every line parses
    if words[0] in ("serve", "map"):  # a server; a map of some seconds (tests/test_adhesion_map)
        return
    monkeypatch.chdir(tmp_path)
    assert main(words) == 0, capsys.readouterr().err
    # valid inputs: a model note at most (Dundurs beta), never a units warning ...
    err = capsys.readouterr().err
    for line in err.splitlines():
        assert "warning:" not in line or "Dundurs beta" in line, line
    # ... and --quiet silences the model notes: nothing on stderr
    assert main([*words, "--quiet"]) == 0
    assert capsys.readouterr().err == ""


@pytest.mark.skipif(not USAGE.exists(), reason="docs/usage.md is not beside the tests")
def test_the_pages_have_python_examples():
    assert len(BLOCKS) >= 3


@pytest.mark.parametrize("block", BLOCKS, ids=[f"block{i}" for i in range(len(BLOCKS))])
def test_readme_python_block_runs(block, tmp_path):
    p = subprocess.run(
        [sys.executable, "-c", block], capture_output=True, text=True, cwd=tmp_path, timeout=120
    )
    assert p.returncode == 0, p.stderr
    assert "Traceback" not in p.stderr
    # a warning the block prints is one it announces ("warns: ..." in a comment); the
    # README's block announces none (its filter silences the model notes it names)
    warned = re.findall(r"^\S*:\d+: (\w*Warning): ", p.stderr, re.M)
    if warned:
        assert "# (warns" in block or "# warns" in block, p.stderr
    assert not warned or block not in README_BLOCKS, p.stderr


README_BLOCKS = (
    re.findall(r"```python\n(.*?)```", README.read_text(encoding="utf-8"), re.S)
    if README.exists()
    else []
)


@pytest.mark.skipif(not USAGE.exists(), reason="docs/usage.md is not beside the tests")
def test_the_domain_table_is_the_code_s():
    from linecontact.domain import DOMAIN

    text = USAGE.read_text(encoding="utf-8")
    section = text[text.index("## Validated domain") :]
    section = section[: section.index("\n## ", 5)]
    num = r"([-+.e\d]+|inf)"
    rows = re.findall(rf"^\| `(\w+)` \| ([\[(]){num}, {num}([\])]) \|", section, re.M)
    table = {k: (float(lo), b1 == "[", float(hi), b2 == "]") for k, b1, lo, hi, b2 in rows}
    assert table == DOMAIN


GUIDE = ROOT / "docs" / "guide.md"


def _guide() -> list[list[str]]:
    if not GUIDE.exists():
        return []
    text = GUIDE.read_text(encoding="utf-8")
    out = []
    for block in re.findall(r"```bash\n(.*?)```", text, re.S):
        for line in block.replace("\\\n", " ").splitlines():
            if line.startswith("linecontact "):
                out.append(shlex.split(line)[1:])
    return out


@pytest.mark.parametrize("words", _guide(), ids=[" ".join(w[:1]) for w in _guide()])
def test_each_command_of_the_guide_runs(words, tmp_path, monkeypatch, capsys):
    """The user guide's commands parse; those that need no file, server or minutes run."""
    from linecontact.cli import build_parser, main

    build_parser(words).parse_args(words)
    if words[0] in ("serve", "map") or "--data" in words:
        return
    monkeypatch.chdir(tmp_path)
    assert main(words) == 0, capsys.readouterr().err


@pytest.mark.skipif(not README.exists(), reason="README.md is not beside the tests")
def test_the_tour_s_fit_prints_an_uncertainty_not_round_off(capsys):
    """The tour's fit shows a propagated uncertainty and its interval in its table."""
    import json

    from linecontact.cli import main

    (words,) = [w for w in TOUR if w[0] == "fit-adhesion"]
    assert main([*words, "--json"]) == 0
    rec = json.loads(capsys.readouterr().out)["results"][0]
    w, sd, (lo, hi) = (
        rec["work_of_adhesion"],
        rec["work_of_adhesion_sd"],
        rec["work_of_adhesion_ci95"],
    )
    assert sd > 1e-3 * w, sd  # an uncertainty, not round-off of an exact value
    assert lo < w - sd < w + sd < hi and rec["uncertainty"].startswith("propagated from")
    assert main(words) == 0
    table = capsys.readouterr().out
    assert "work_of_adhesion_ci95" in table and f"[{lo:.6g}, {hi:.6g}]" in table


@pytest.mark.skipif(not README.exists(), reason="README.md is not beside the tests")
def test_every_flag_the_tour_names_is_one_a_command_takes():
    from linecontact.cli import build_parser

    text = README.read_text(encoding="utf-8")
    intro = text[text.index("## A tour in 60 seconds") :].split("```", 1)[0]
    flags = set(re.findall(r"(--[a-z][\w-]*)", intro))
    assert {"--work-of-adhesion-receding", "--h1", "--quiet"} <= flags
    subparsers = build_parser().parse_args(["cite"])._subparsers.choices  # every command
    known = {f for p in subparsers.values() for f in p._option_string_actions}
    assert flags <= known, flags - known
    # the receding work of adhesion is said for push: push takes it
    assert "--work-of-adhesion-receding" in subparsers["push"]._option_string_actions
