"""``.ci/run`` cannot pass a failed step: each of its steps is made to fail in turn.

The script runs in a copy of its folder with every command it calls replaced by a stub on
``PATH`` (``python``, ``ruff``, ``mypy``, ``chromium``; ``.ci/check-site`` beside it) that
logs its arguments and fails when its words start with ``FAIL``. With no step failing the
script ends with 0 and runs every step in order; with any one failing it ends non-zero and
runs no step after it (the README's test command last: its status is the script's).
"""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]

#: The steps of .ci/run, as the words each stub sees (the program and its arguments).
STEPS = [
    "python -m pip install ruff==0.17.6 mypy==2.4.1 numpy>=1.23 matplotlib>=3.6",
    "ruff check .",
    "ruff format --check .",
    "mypy",
    "python -m pip install .[docs]",
    "python -m sphinx -W --keep-going -b html docs docs/_build/html",
    "check-site docs/_build/html",
    "python -m pip install .[test]",
    "python -m pytest",
]

STUB = """#!/usr/bin/env bash
words="$(basename "$0")${*:+ $*}"
echo "$words" >> "$CI_LOG"
case "$words" in
    "$FAIL"*) exit 3 ;;
esac
exit 0
"""


@pytest.fixture(scope="module")
def sandbox(tmp_path_factory) -> Path:
    if shutil.which("bash") is None:
        pytest.skip("no bash")
    root = tmp_path_factory.mktemp("ci")
    (root / ".ci").mkdir()
    shutil.copy(ROOT / ".ci" / "run", root / ".ci" / "run")
    bin_ = root / "bin"
    bin_.mkdir()
    for name in ("python", "ruff", "mypy", "chromium"):
        (bin_ / name).write_text(STUB)
        (bin_ / name).chmod(0o755)
    (root / ".ci" / "check-site").write_text(STUB)
    (root / ".ci" / "check-site").chmod(0o755)
    return root


def _run(root: Path, fail: str) -> tuple[int, list[str]]:
    log = root / f"log-{abs(hash(fail))}"
    log.unlink(missing_ok=True)
    env = {
        "PATH": f"{root / 'bin'}:/usr/bin:/bin",
        "CI_LOG": str(log),
        "FAIL": fail or "no step fails",
        "HOME": str(root),
    }
    done = subprocess.run(
        ["bash", str(root / ".ci" / "run")], env=env, capture_output=True, text=True, timeout=60
    )
    lines = log.read_text().splitlines() if log.exists() else []
    return done.returncode, lines


def test_every_step_runs_in_order_when_none_fails(sandbox):
    code, ran = _run(sandbox, "")
    assert code == 0
    assert ran == STEPS


@pytest.mark.parametrize(
    "step", range(len(STEPS)), ids=[f"{k}-{s.split()[-1]}" for k, s in enumerate(STEPS)]
)
def test_a_failed_step_fails_the_script(sandbox, step):
    code, ran = _run(sandbox, STEPS[step])
    assert code != 0, f"{STEPS[step]!r} failed and .ci/run ended with 0"
    assert ran == STEPS[: step + 1], ran  # nothing after the failed step


def test_the_last_line_is_the_readmes_test_command():
    readme = (ROOT / "README.md").read_text()
    test_command = "python -m pip install '.[test]' && python -m pytest"
    assert test_command in readme.split("\n\n", 2)[1]
    lines = [ln for ln in (ROOT / ".ci" / "run").read_text().splitlines() if ln.strip()]
    assert lines[-1] == test_command
    # no other `&&` or `||` list at the top level of the script (each hides a failure from
    # set -e); the chromium install's alternatives are inside an `if`
    body = [ln for ln in lines[:-1] if not ln.lstrip().startswith("#")]
    top = [ln for ln in body if not ln.startswith(" ")]
    assert not [ln for ln in top if "&&" in ln or "||" in ln], top
    assert "set -euo pipefail" in lines
