"""The scripts in examples/ run, print what they say, and write what they promise."""

import subprocess
import sys
from pathlib import Path

import pytest

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
pytestmark = pytest.mark.skipif(not EXAMPLES.is_dir(), reason="examples/ is not beside tests/")


def run(tmp_path, name, *args):
    p = subprocess.run(
        [sys.executable, str(EXAMPLES / name), *args],
        capture_output=True,
        text=True,
        cwd=tmp_path,
        timeout=120,
    )
    assert p.returncode == 0, p.stderr
    assert "Traceback" not in p.stderr
    return p.stdout


def test_nanowire_pull_off(tmp_path):
    out = run(tmp_path, "nanowire_pull_off.py")
    assert "pull-off force" in out and "N/m" in out and "uN on a 5 um wire" in out
    assert "mechanism" in out and ("zero-width" in out or "snap-off" in out)
    rows = [r for r in out.splitlines() if r.strip() and r.strip()[0] in "-0123456789"]
    assert len(rows) == 5


def test_load_curve_plot(tmp_path):
    out = run(tmp_path, "load_curve_plot.py", "curve.png")
    assert "snap-off" in out and "zero-width" in out
    assert (tmp_path / "curve.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_rolling_creep(tmp_path):
    out = run(tmp_path, "rolling_creep.py")
    assert "creep" in out and "Carter" in out
    creep = [float(r.split()[-1]) for r in out.splitlines()[2:10]]
    assert len(creep) == 8 and all(c < 0 for c in creep)
    # the stick zone grows with the load at a fixed tractive force: the creep falls
    assert all(abs(b) < abs(a) for a, b in zip(creep, creep[1:], strict=False))


def test_fit_pull_off(tmp_path):
    pytest.importorskip("matplotlib")
    out = run(tmp_path, "fit_pull_off.py", "fit.png")
    assert "synthetic" in out and "95 %" in out and "correlation" in out
    w = float(next(r for r in out.splitlines() if r.strip().startswith("w  =")).split()[2])
    assert abs(w / 0.1 - 1) < 0.10
    assert "JKR" in out and "DMT" in out
    lines = (tmp_path / "pulloff.csv").read_text(encoding="utf-8").splitlines()
    assert lines[0].startswith("# synthetic:")
    assert lines[1] == "radius_m,pull_off_force_N_per_m,pull_off_force_sd_N_per_m"
    rows = [[float(v) for v in r.split(",")] for r in lines[2:]]
    assert len(rows) == 5 and all(F < 0 < sd for _, F, sd in rows)
    assert (tmp_path / "fit.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_sweep_pulloff(tmp_path):
    pytest.importorskip("xarray")
    out = run(tmp_path, "sweep_pulloff.py", "sweep.png")
    assert "{'radius': 40, 'work_of_adhesion': 3} points" in out
    assert out.count("pull-off") == 3 and "snap-off" in out
    assert (tmp_path / "sweep.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


@pytest.mark.parametrize(
    ("name", "says"),
    [
        ("push_resistance.py", ["critical height H* =", "slide", "roll"]),
        ("cyclic_loss.py", ["full slip at T* =", "J/m per cycle"]),
        ("lennard_jones_curve.py", ["pull-off F/(Eh): Maugis-Dugdale", "Lennard-Jones"]),
        (
            "afm_tip.py",
            [
                "    10   0.129  0.111  transition  dmt       -1.9306   +0.223   -0.036",
                "  1000   0.598  0.517  transition  jkr       -1.6842",
            ],
        ),
        (
            "bent_wire_fit.py",
            [
                "the truth inside them: True and True",
                "noise from the residuals 2.04 nm (truth 2)",
                "tau0 = f/(2a) = 1.918 MPa",
            ],
        ),
        (
            "faceted_wire.py",
            [
                "facet width 50.00 nm, pull-off  -17.107 N/m (corner-pinned",
                "strength cap  -18.099 N/m",
                "a = 22.76 nm, tau0 =   11.0 MPa (10.1 times the round wire's a)",
            ],
        ),
    ],
)
def test_the_plotting_examples(tmp_path, name, says):
    out = run(tmp_path, name, "fig.png")
    for text in says:
        assert text in out, (name, text)
    assert (tmp_path / "fig.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
