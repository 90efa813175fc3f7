"""Issue 20: small defects found by outside testers, each with its exact case.

(The bound on ``load_curve``'s ``num`` is in ``test_normal.py``'s table of bad input; the
tip's free body over the valid domain in ``test_push.py``.)
"""

from __future__ import annotations

import os
import signal
import stat
import subprocess
import sys
import time
from decimal import Decimal, getcontext
from pathlib import Path

import numpy as np
import pytest

import linecontact as lc
from linecontact import ConvergenceError
from linecontact.output import Table, write
from linecontact.tangential.history import _loss as _history_loss

ENV = {**os.environ, "PYTHONDONTWRITEBYTECODE": "1"}


# --------------------------------------------------------------------------------------------
# 1. files written with -o follow the umask (they were 0600 whatever it was)


@pytest.mark.parametrize(("umask", "mode"), [(0o022, 0o644), (0o002, 0o664), (0o077, 0o600)])
def test_output_files_follow_the_umask(tmp_path, umask, mode):
    table = Table(columns={"x": np.array([1.0, 2.0])}, units={"x": "1"})
    old = os.umask(umask)
    try:
        write(table, "csv", tmp_path / "out.csv")
    finally:
        os.umask(old)
    assert stat.S_IMODE((tmp_path / "out.csv").stat().st_mode) == mode
    assert [p.name for p in tmp_path.iterdir()] == ["out.csv"]  # atomic: no temporary left


@pytest.mark.parametrize(("umask", "mode"), [(0o022, 0o644), (0o002, 0o664)])
def test_figure_files_follow_the_umask(tmp_path, umask, mode):
    from linecontact._files import atomic_file

    old = os.umask(umask)
    try:
        with atomic_file(tmp_path / "fig.png", name="figure") as fh:
            fh.write(b"data")
    finally:
        os.umask(old)
    assert stat.S_IMODE((tmp_path / "fig.png").stat().st_mode) == mode


def test_an_overwritten_file_keeps_its_mode(tmp_path):
    target = tmp_path / "out.csv"
    target.write_text("old\n")
    target.chmod(0o640)
    write(Table(columns={"x": np.array([1.0])}, units={"x": "1"}), "csv", target)
    assert stat.S_IMODE(target.stat().st_mode) == 0o640
    assert target.read_text() != "old\n"


# --------------------------------------------------------------------------------------------
# 2. tip_push at a small height: cos(theta) without cancellation


def test_tip_push_at_a_tiny_height_is_exact():
    # reference: cos(theta) = sqrt(H (2 - H)) in 50-digit decimal arithmetic (the double
    # 1e-15 taken exactly); Q/P = cos(theta) for a frictionless tip. Was 4.0e-4 off.
    getcontext().prec = 50
    for H in (1e-15, 1e-10, 1e-6, 1.999999):
        h = Decimal(H)
        ref = float((h * (2 - h)).sqrt())
        assert lc.tip_push(H, 0.0).Q_per_P == pytest.approx(ref, rel=4e-16)
    # with friction: H_eff = (cos - mu H)/(cos - mu sin) -> 1 as H -> 0 (series: 1 - mu
    # sqrt(H/2) + ...)
    t = lc.tip_push(1e-15, 0.3)
    cos = float((Decimal(1e-15) * (2 - Decimal(1e-15))).sqrt())
    assert t.Q_per_P == pytest.approx(cos + 0.3 * (1 - 1e-15), rel=4e-16)


# --------------------------------------------------------------------------------------------
# 3. and 4. the incremental cyclic loss at tiny amplitudes


def test_cyclic_loss_coulomb_incremental_tiny_amplitude_is_never_negative():
    # was W = -5.6e-38: the loss at 1e-12 of full slip is far below the round-off of the
    # incremental solver's friction work; it is refused (use the closed form) ...
    with pytest.raises(ConvergenceError, match=r"amplitude 1e-12 .*use method='closed-form'"):
        lc.cyclic_loss_coulomb(3.36, 0.01, 1.0e-12, method="incremental")
    # ... and the friction work of each step is B |ds| >= 0: never negative
    h = lc.tangential_history_coulomb(
        3.36, 0.01, [1e-12, -1e-12, 1e-12], method="incremental", on_failure="report"
    )
    assert np.all(h.dissipation_over_Ea2 >= 0)
    # where the loss is resolved it is the closed form (measured 4.4e-7 at Q = 1e-6)
    a = lc.cyclic_loss_coulomb(0.3, 0.01, 1e-6, method="incremental").W_over_Ea2
    b = lc.cyclic_loss_coulomb(0.3, 0.01, 1e-6).W_over_Ea2
    assert a == pytest.approx(b, rel=1e-6)


def test_incremental_refuses_a_tiny_amplitude_up_front(monkeypatch):
    # took > 8 s in the solver before it refused; now refused before the solver is entered
    def not_entered(*args, **kwargs):
        raise AssertionError("the incremental solver was entered")

    monkeypatch.setattr(_history_loss, "_incremental", not_entered)
    message = (
        r"^the incremental solver missed tol=1e-06 at the amplitude 1e-12 of the full-slip "
        r"load \(estimate .*, n=4096\): an amplitude this small needs more than 4096 nodes; "
        r"use method='closed-form'$"
    )
    with pytest.raises(ConvergenceError, match=message):
        lc.cyclic_loss(0.01, 2e-14, method="incremental")  # 1e-12 of full slip
    with pytest.raises(ConvergenceError, match=message):
        lc.cyclic_loss(0.01, [0.01, 2e-14], method="incremental")  # before any point


# --------------------------------------------------------------------------------------------
# 6. a failed write to stdout


@pytest.mark.skipif(not os.path.exists("/dev/full"), reason="needs /dev/full")
@pytest.mark.parametrize(
    "args, prog",
    [
        (["cite"], "linecontact cite"),
        (["cite", "--bibtex"], "linecontact cite"),
        # argparse swallows a failed write of its help; the command line does not
        (["--help"], "linecontact"),
        (["pulloff", "--help"], "linecontact"),
        (["--version"], "linecontact"),
    ],
)
def test_output_to_dev_full_is_an_error_line_not_an_internal_error(args, prog):
    with open("/dev/full", "w") as full:
        proc = subprocess.run(
            [sys.executable, "-m", "linecontact", *args],
            stdout=full,
            stderr=subprocess.PIPE,
            text=True,
            timeout=120,
            env=ENV,
        )
    assert proc.returncode == 2
    assert proc.stderr == (
        f"{prog}: error: cannot write to standard output: No space left on device\n"
    )


def test_help_into_a_closed_pipe_is_quiet():
    proc = subprocess.run(
        f"{sys.executable} -m linecontact pulloff --help | head -c 1",
        shell=True,
        capture_output=True,
        text=True,
        timeout=120,
        env=ENV,
    )
    assert proc.returncode == 0 and proc.stdout == "u" and "Traceback" not in proc.stderr


# --------------------------------------------------------------------------------------------
# 7. Ctrl-C while the command line imports


def _numpy_loaded(pid: int) -> bool:
    try:
        return "_multiarray_umath" in Path(f"/proc/{pid}/maps").read_text()
    except OSError:
        return False


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="reads /proc/PID/maps")
@pytest.mark.parametrize("how", ["-m", "script"])
def test_ctrl_c_during_the_imports_exits_130_without_a_traceback(how):
    if how == "-m":
        cmd = [sys.executable, "-m", "linecontact", "cite"]
    else:  # what the console script linecontact = "linecontact.cli:main" runs
        script = Path(sys.executable).with_name("linecontact")
        if not script.exists():
            pytest.skip("the console script is not installed next to the interpreter")
        cmd = [str(script), "cite"]
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=ENV)
    # wait until NumPy's extension is mapped: the package's imports are under way (SciPy
    # and the rest take several times longer)
    deadline = time.monotonic() + 60
    while not _numpy_loaded(proc.pid) and proc.poll() is None and time.monotonic() < deadline:
        time.sleep(0.001)
    if proc.poll() is not None:
        pytest.skip("the imports finished before they could be interrupted")
    proc.send_signal(signal.SIGINT)
    out, err = proc.communicate(timeout=60)
    assert "Traceback" not in err
    if proc.returncode == 0:  # a machine fast enough to finish first: nothing to test
        pytest.skip("the run finished before the interrupt arrived")
    assert proc.returncode == 130
    assert err.endswith("interrupted\n") and err.count("\n") == 1


# --------------------------------------------------------------------------------------------
# 8. a contact of zero width is not a contact


def test_equilibria_lists_no_contact_of_zero_width():
    # the tester's load -0.0023139 is below this pull-off force (-0.00231376...): no state;
    # at the pull-off force itself (mechanism "zero-width") the contact branch's root is
    # a = 0 (underflowing to 5e-299 one ulp above): the touch-down state, listed once
    R, s = 37.53, 1.336e-4
    po = lc.pull_off(R, s)
    assert po.mechanism == "zero-width"
    assert lc.equilibria(-0.0023139, R, s) == ()
    F0 = float(po.F_pulloff_over_Eh)
    for F in (F0, np.nextafter(F0, 0.0), F0 * (1 - 1e-16)):
        states = lc.equilibria(F, R, s)
        assert all(e.a_over_R > 0 for e in states if e.branch == "contact"), states
        assert [e.branch for e in states] == ["non-contact"]
        assert states[0].c_over_R == pytest.approx(float(po.c_over_R_at_pulloff), rel=1e-12)
    # a resolved width is kept
    states = lc.equilibria(F0 * (1 - 1e-10), R, s)
    assert [e.branch for e in states] == ["contact", "non-contact"]
    assert states[0].a_over_R == pytest.approx(8.9e-8, rel=0.01)


# --------------------------------------------------------------------------------------------
# 9. masked arrays are refused, not silently unmasked


MASKED = np.ma.masked_array([0.01, 0.02], mask=[0, 1])


@pytest.mark.parametrize(
    ("call", "name"),
    [
        (lambda: lc.normal_contact(MASKED, 100.0, 0.01), "a_over_R"),
        (lambda: lc.contact_for_load(MASKED, 100.0, 0.01), "F_over_Eh"),
        (lambda: lc.pull_off(np.ma.masked_array([100.0], mask=[1]), 0.01), "R_over_h"),
        (lambda: lc.cyclic_loss(MASKED, 0.001), "tau0_over_E"),
        (lambda: lc.tip_push(np.ma.masked_array([0.5, 1.5], mask=[0, 0]), 0.1), "H_over_R"),
    ],
)
def test_masked_input_is_refused(call, name):
    with pytest.raises(
        ValueError,
        match=rf"^{name} is a masked array: masked arrays are not supported: fill or "
        "compress them first",
    ):
        call()


@pytest.mark.parametrize(
    "argv",
    [
        ["pulloff", "--R-over-h", "100", "--sigma0-over-E", "0.01"],
        ["map", "--json"],  # a minute of work, refused before it starts
    ],
)
def test_output_in_a_missing_directory_is_refused_before_the_work(capsys, tmp_path, argv):
    from linecontact.cli import main

    out = str(tmp_path / "missing" / "x.json")
    assert main([*argv, "-o", out]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "the directory" in err and "does not exist" in err
    assert "computing" not in err
