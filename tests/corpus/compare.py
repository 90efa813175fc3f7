"""Run the corpus of command lines with two versions of linecontact and compare their outputs.

Usage (from the repository root)::

    python tests/corpus/compare.py REV        # this checkout against the commit REV
    python tests/corpus/compare.py REV --record tests/corpus/status.json

Each line of ``tests/corpus/cases.txt`` is one command line (without ``linecontact``), run
as ``python -m linecontact ...`` in this directory (its CSV files are the ``--data``) once
with the source of a git worktree of ``REV`` and once with this checkout's; stdout, stderr
and the exit status must be byte-identical. Issue 32 moved every subcommand onto the
operations' declarations with this check against its parent commit (all identical); the
same machine runs both, so no last-bit difference between CPUs can enter.
``--record`` writes each case's exit status (what ``tests/test_corpus.py`` checks).
"""

from __future__ import annotations

import argparse
import json
import os
import shlex
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parents[1]


def cases() -> list[str]:
    """The command lines of the corpus."""
    lines = (HERE / "cases.txt").read_text(encoding="utf-8").splitlines()
    return [s.strip() for s in lines if s.strip() and not s.startswith("#")]


def run(src: Path, line: str, cwd: Path) -> tuple[int, str, str]:
    """``python -m linecontact LINE`` with the package of ``src``: (status, stdout, stderr)."""
    env = dict(os.environ, PYTHONPATH=str(src), COLUMNS="100")
    p = subprocess.run(
        [sys.executable, "-m", "linecontact", *shlex.split(line)],
        capture_output=True,
        text=True,
        env=env,
        cwd=cwd,
        timeout=600,
        stdin=subprocess.DEVNULL,
    )
    return p.returncode, p.stdout, p.stderr


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("rev", help="the commit to compare with (a worktree of it is made)")
    ap.add_argument("--record", metavar="FILE", help="write each case's exit status to FILE")
    args = ap.parse_args(argv)
    with tempfile.TemporaryDirectory() as tmp:
        before = Path(tmp) / "before"
        subprocess.run(
            ["git", "-C", str(ROOT), "worktree", "add", "--detach", str(before), args.rev],
            check=True,
            capture_output=True,
        )
        try:
            work = Path(tmp) / "cwd"
            work.mkdir()
            for f in HERE.glob("*.csv"):
                (work / f.name).write_bytes(f.read_bytes())
            differ, status = 0, {}
            for line in cases():
                a = run(before / "src", line, work)
                b = run(ROOT / "src", line, work)
                status[line] = b[0]
                if a != b:
                    differ += 1
                    print(f"DIFFERS: {line}")
                    for name, x, y in zip(("status", "stdout", "stderr"), a, b, strict=True):
                        if x != y:
                            print(f"  {name} before: {x!r}"[:400])
                            print(f"  {name} now:    {y!r}"[:400])
        finally:
            subprocess.run(
                ["git", "-C", str(ROOT), "worktree", "remove", "--force", str(before)],
                capture_output=True,
            )
    print(f"{len(status)} command lines, {differ} differ")
    if args.record:
        Path(args.record).write_text(json.dumps(status, indent=1) + "\n", encoding="utf-8")
    return 1 if differ else 0


if __name__ == "__main__":
    raise SystemExit(main())
