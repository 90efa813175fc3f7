"""The command line under abuse: a reader that stops early, Ctrl-C, a run stopped mid-write.

``linecontact ... | head`` ends quietly (status 0, nothing on stderr); an interrupt ends
with one line on stderr and status 130; an output file appears whole or not at all, and an
existing one is left as it was. (An unwritable ``-o`` path is in ``test_cli_robustness``.)
"""

from __future__ import annotations

import os
import subprocess
import sys

import pytest

import linecontact.operations.normal as cli_normal
import linecontact.output as output
from linecontact.cli import main

CURVE = ["curve", "--R-over-h", "100", "--sigma0-over-E", "0.01"]


def test_a_reader_that_stops_early_ends_the_run_quietly():
    # the reader closes its end before the first byte is written: every write meets the
    # closed pipe (EPIPE), the first and the interpreter's final flush alike
    proc = subprocess.Popen(
        [sys.executable, "-m", "linecontact", *CURVE, "--num", "2000", "--format", "csv"],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
    )
    assert proc.stdout is not None
    proc.stdout.close()
    _, err = proc.communicate(timeout=120)
    assert err.decode() == ""  # no BrokenPipeError traceback, no "Exception ignored" at exit
    assert proc.returncode == 0


def test_ctrl_c_exits_130_with_one_line(monkeypatch, capsys):
    def interrupted(*args, **kwargs):
        raise KeyboardInterrupt

    monkeypatch.setattr(cli_normal, "load_curve", interrupted)
    assert main(CURVE) == 130
    out, err = capsys.readouterr()
    assert out == ""
    assert err == "linecontact curve: interrupted\n"


@pytest.mark.parametrize("existing", [False, True])
def test_a_run_stopped_mid_write_leaves_no_partial_file(tmp_path, monkeypatch, capsys, existing):
    target = tmp_path / "curve.json"
    if existing:
        target.write_text("the previous run's output\n")

    def stopped(src, dst):  # the data are in the temporary file, the rename never happens
        raise KeyboardInterrupt

    monkeypatch.setattr(output.os, "replace", stopped)
    assert main([*CURVE, "-o", str(target)]) == 130
    assert capsys.readouterr().err == "linecontact curve: interrupted\n"
    # no temporary file left behind; the target is absent or untouched
    assert sorted(p.name for p in tmp_path.iterdir()) == (["curve.json"] if existing else [])
    if existing:
        assert target.read_text() == "the previous run's output\n"


def test_a_killed_run_leaves_no_partial_output(tmp_path):
    # SIGKILL while computing: nothing has been written; the file appears only complete
    target = tmp_path / "curve.csv"
    proc = subprocess.Popen(
        [sys.executable, "-m", "linecontact", *CURVE, "--num", "1000000", "-o", str(target)],
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
    )
    try:
        proc.wait(timeout=0.5)
    except subprocess.TimeoutExpired:
        proc.kill()
        proc.wait(timeout=60)
    if proc.returncode == 0:  # a machine fast enough to finish: the file is whole
        text = target.read_text()
        assert text.startswith("# linecontact:") and text.endswith("\n")
    else:
        assert not target.exists()


@pytest.mark.skipif(os.name != "posix", reason="SIGPIPE semantics")
def test_head_in_a_shell_pipeline_prints_no_error():
    cmd = f"{sys.executable} -m linecontact {' '.join(CURVE)} --num 200000 --format csv | head -n 2"
    r = subprocess.run(["sh", "-c", cmd], capture_output=True, text=True, timeout=120)
    assert r.returncode == 0
    assert r.stderr == ""
    assert len(r.stdout.splitlines()) == 2
