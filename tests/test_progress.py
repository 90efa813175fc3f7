"""Progress bars on stderr: the map's curves, the fits' refits; never on stdout.

Shown where stderr is a terminal (never under pytest's capture) or when forced
(``progress=True``, ``--progress``); a plain line where tqdm is not installed.
"""

from __future__ import annotations

import json
import sys

import numpy as np
import pytest

import linecontact as lc
import linecontact.adhesion_map as am
from linecontact import _progress
from linecontact import inverse as inv
from linecontact._progress import progress_bar
from linecontact.cli import main

MAP = ["--mu-min", "0.01", "--mu-max", "0.02", "--n-mu", "2", "--y-max", "2", "--n-y", "6"]
E = float(lc.composite_modulus(72e9, 0.17, 163e9, 0.22))
R = np.array([10e-9, 40e-9, 160e-9, 640e-9, 2560e-9])
F = inv.pull_off_force(R, E, 0.1, 0.3e-9)


def _count(bar_steps, progress):
    with progress_bar(3, "test", progress, unit=" steps") as bar:
        for _ in range(bar_steps):
            bar.update(1)


def test_a_forced_bar_is_on_stderr_and_never_on_stdout(capsys):
    _count(3, True)
    out, err = capsys.readouterr()
    assert out == "" and "test" in err and "3/3" in err and err.endswith("\n")


@pytest.mark.parametrize("progress", [False, None])
def test_no_bar_where_stderr_is_not_a_terminal_or_when_off(capsys, progress):
    _count(3, progress)
    assert capsys.readouterr() == ("", "")


def test_the_default_shows_it_on_a_terminal(capsys, monkeypatch):
    monkeypatch.setattr(_progress, "_isatty", lambda: True)
    _count(3, None)
    assert "3/3" in capsys.readouterr().err
    _count(3, False)  # off is off, terminal or not
    assert capsys.readouterr().err == ""


def test_a_plain_line_without_tqdm(capsys, monkeypatch):
    monkeypatch.setitem(sys.modules, "tqdm", None)  # import tqdm raises ImportError
    with progress_bar(2, "fit", True, unit=" refits") as bar:
        bar.update(1)
        bar.update(1)
    out, err = capsys.readouterr()
    assert out == "" and err == "\rfit: 1/2 refits\rfit: 2/2 refits\n"
    _count(3, False)
    assert capsys.readouterr() == ("", "")


def _fake_row(mu, y):
    y = np.asarray(y)
    return am._Row(-2.0, 0.0, np.sqrt(y), 1e-9, 1e-4, 20)


def test_the_library_map_counts_its_curves(capsys, monkeypatch):
    monkeypatch.setattr(am, "_map_row", _fake_row)
    msgs: list[str] = []
    quiet = am.adhesion_map([0.01, 0.02], [0.5, 2.0], workers=1, progress=msgs.append)
    assert capsys.readouterr() == ("", "") and msgs[-1].startswith("2/2 curves")
    shown = am.adhesion_map([0.01, 0.02], [0.5, 2.0], workers=1, progress=True)
    out, err = capsys.readouterr()
    assert out == "" and err.startswith("\rmap: ") and "2/2" in err
    assert np.array_equal(quiet.half_width_lj, shown.half_width_lj)


def test_cli_map_progress_shows_the_bar_and_the_same_map(capsys, monkeypatch, tmp_path):
    pytest.importorskip("matplotlib")
    monkeypatch.setattr(am, "_map_row", _fake_row)
    argv = ["map", "--outdir", str(tmp_path), "--image-format", "svg", "--workers", "1", *MAP]
    assert main(argv) == 0
    plain = capsys.readouterr()
    assert plain.err == ""  # not a terminal: no bar
    assert main([*argv, "--progress"]) == 0
    out, err = capsys.readouterr()
    assert out == plain.out and err.startswith("\rmap: ") and "2/2" in err


def test_fit_pull_off_counts_its_refits(capsys):
    quiet = inv.fit_pull_off(
        R, F, E, sd=0.03 * np.abs(F), bootstrap=30, modulus_sd=E / 20, samples=5
    )
    assert capsys.readouterr() == ("", "")  # a library call shows nothing unless asked
    shown = inv.fit_pull_off(
        R, F, E, sd=0.03 * np.abs(F), bootstrap=30, modulus_sd=E / 20, samples=5, progress=True
    )
    out, err = capsys.readouterr()
    assert out == "" and err.startswith("\rfit: ") and "35/35" in err
    assert shown.work_of_adhesion_ci95 == quiet.work_of_adhesion_ci95
    assert shown.work_of_adhesion_sd_inputs == quiet.work_of_adhesion_sd_inputs
    inv.fit_pull_off(R, F, E, bootstrap=0, progress=True)  # no refits: no bar
    assert capsys.readouterr() == ("", "")


def test_cli_fit_adhesion_progress_shows_the_bar_and_the_same_fit(capsys, tmp_path):
    data = tmp_path / "pulloff.csv"
    pairs = zip(R[:2], F[:2], strict=True)  # two pull-offs
    rows = "\n".join(f"{r:.17g},{f:.17g},{0.03 * abs(f):.17g}" for r, f in pairs)
    data.write_text(f"radius_m,pull_off_force_N_per_m,pull_off_force_sd_N_per_m\n{rows}\n")
    argv = ["fit-adhesion", "--data", str(data), "--modulus", str(E), "--modulus-sd", "10%"]
    argv += ["--z0", "0.3e-9", "--bootstrap", "0"]  # w alone: 100 quick refits
    assert main([*argv, "--quiet", "--json"]) == 0
    plain = capsys.readouterr()
    assert plain.err == ""  # not a terminal: no bar
    assert main([*argv, "--quiet", "--json", "--progress"]) == 0
    out, err = capsys.readouterr()
    assert err.startswith("\rfit: ") and "100/100" in err  # the modulus's 100 draws
    got, want = json.loads(out), json.loads(plain.out)
    assert got["results"] == want["results"] and got["parameters"] == want["parameters"]
