"""Sweeps (linecontact sweep, lc.sweep): each point is what the subcommand gives for it.

The dataset is compared, at sampled points, with the subcommand's own ``--json`` output run
for that point alone; the pull-off computed a block at a time with the same sweep point by
point; a run killed with ``kill -9`` and resumed with one run uninterrupted; a run on a
``dask.distributed`` cluster of processes with one in this process; and every bad input
with its one ``error:`` line, exit status 2 and nothing written.
"""

from __future__ import annotations

import json
import math
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

xr = pytest.importorskip("xarray")
pytest.importorskip("dask")

import linecontact as lc  # noqa: E402
from linecontact.cli import main  # noqa: E402
from linecontact.sweeps._plan import blocks, plan  # noqa: E402
from linecontact.sweeps._points import evaluate  # noqa: E402
from linecontact.sweeps._ranges import flag_values  # noqa: E402

NANOWIRE = ["--modulus", "1.2e11", "--z0", "3e-10"]


def _json(capsys, argv):
    code = main([*argv, "--json"])
    out, _ = capsys.readouterr()
    assert code in (0, 1), argv
    return json.loads(out) if out else None


def _flags_at(ds, index):
    """The words of the swept flags at the point ``index`` (a dict dim -> position)."""
    words = []
    for flag, dim in zip(ds.attrs["swept"], [d for d in ds.dims if d != "record"], strict=True):
        v = ds[dim].values[index[dim]]
        words += [flag, repr(float(v)) if isinstance(v, float | np.floating) else str(v)]
    return words


def _same(value, expected, key):
    if expected is None:  # null in JSON: missing, or a number JSON cannot write (inf)
        missing = value == "" or value is False
        assert missing or (isinstance(value, float) and not math.isfinite(value)), (key, value)
    elif isinstance(expected, bool):
        assert bool(value) == expected, key
    elif isinstance(expected, int | float):
        assert float(value) == pytest.approx(expected, rel=1e-12, abs=1e-300), key
    elif isinstance(expected, str):
        assert str(value) == expected, key


def _check_points(capsys, ds, command, fixed, rng, n=4):
    dims = [d for d in ds.dims if d != "record"]
    for _ in range(n):
        index = {d: int(rng.integers(ds.sizes[d])) for d in dims}
        doc = _json(capsys, [command, *fixed, *_flags_at(ds, index)])
        point = ds.isel(index)
        if doc is None:  # the command refused the point: the sweep says why
            assert str(point["state"].values.ravel()[0]) in ("invalid", "not-converged")
            continue
        recs = doc["results"]
        if "record" in ds.dims:
            assert int((point["state"] != "").sum()) >= len(recs)
        for r, rec in enumerate(recs):
            for key, expected in rec.items():
                if key in ds.dims:
                    continue
                assert key in ds, (command, key)
                v = point[key].values
                v = v[r] if "record" in point[key].dims else v
                _same(v.item() if hasattr(v, "item") else v, expected, key)
        for key in doc["units"]:
            if key in ds.data_vars and ds[key].dtype.kind == "f":
                assert ds[key].attrs["units"] == doc["units"][key]


CASES = [
    (
        "pulloff",
        ["--radius", "10e-9:200e-9:7:log", *NANOWIRE, "--work-of-adhesion", "0.05", "0.3", "1"],
    ),
    ("pulloff", ["--R-over-h", "1:1e4:6:log", "--sigma0-over-E", "0.001:0.3:5"]),
    (
        "pulloff",
        [
            "--radius",
            "20e-9",
            "80e-9",
            "--cylinder-material",
            "ZnO",
            "SiO2",
            "--substrate-material",
            "Si",
            "--work-of-adhesion",
            "0.3",
            "--z0",
            "3e-10",
            "--length",
            "1e-6",
        ],
    ),
    ("normal", ["--R-over-h", "100", "--sigma0-over-E", "0.01", "0.2", "--F-over-Eh", "-2:2:9"]),
    (
        "normal",
        ["--radius", "50e-9", *NANOWIRE, "--work-of-adhesion", "0.1", "1", "--load", "-3:3:7"],
    ),
    (
        "slide-init",
        ["--a-over-R", "0.05", "--tau0-over-E", "0.001:0.01:4", "--T-over-Ea", "0:0.02:5"],
    ),
    (
        "roll",
        [
            "--R-over-h",
            "100",
            "--sigma0-over-E",
            "0.02",
            "--F-over-Eh",
            "0",
            "1",
            "--tau0-over-E",
            "0.005",
            "--T-over-Ea",
            "0:0.004:4",
        ],
    ),
    (
        "push",
        [
            "--R-over-h2",
            "100",
            "--h1-over-h2",
            "1",
            "--sigma0-over-E",
            "0.01",
            "--tau0-over-E",
            "0.001",
            "0.01",
            "--H-over-R",
            "0:2:5",
        ],
    ),
    ("curve", ["--R-over-h", "100", "--sigma0-over-E", "0.01", "0.1", "--num", "20"]),
    ("pulloff", ["--R-over-h", "30", "100", "--sigma0-over-E", "0.02", "--law", "lennard-jones"]),
]


@pytest.mark.parametrize(("command", "words"), CASES, ids=lambda x: x if isinstance(x, str) else "")
def test_each_point_is_what_the_subcommand_gives(capsys, command, words):
    ds = lc.sweep(command, **_kwargs(words))
    capsys.readouterr()
    fixed, swept = _split(words)
    assert list(ds.attrs["swept"]) == swept
    _check_points(capsys, ds, command, fixed, np.random.default_rng(1))


def _split(words):
    """The fixed words (one value) and the swept flags (several) of ``words``."""
    fixed, swept = [], []
    for flag, vals in _pairs(words):
        if len(vals) > 1 or any(":" in v for v in vals):
            swept.append(flag)
        else:
            fixed += [flag, *vals]
    return fixed, swept


def _kwargs(words):
    kw = {}
    for flag, vals in _pairs(words):
        key = flag[2:].replace("-", "_")
        kw[key] = vals if len(vals) != 1 else vals[0]
        if not vals:
            kw[key] = True
    return kw


def _pairs(words):
    i = 0
    while i < len(words):
        j = i + 1
        while j < len(words) and not words[j].startswith("--"):
            j += 1
        yield words[i], words[i + 1 : j]
        i = j


@pytest.mark.parametrize(
    "words",
    [
        ["--radius", "5e-9:2e-6:40:log", *NANOWIRE, "--work-of-adhesion", "0.001:3:30:log"],
        [
            "--radius",
            "50e-9",
            "--E1",
            "1e9:4e11:9:log",
            "--nu1",
            "0",
            "0.3",
            "0.49",
            "--substrate-material",
            "SiO2",
            "--sigma0",
            "1e8:3e9:5",
            "--h",
            "0.3e-9",
        ],
        ["--R-over-h", "0.5:1e5:25:log", "--sigma0-over-E", "0:0.5:20"],
        [
            "--radius",
            "-1e-9",
            "1e-9",
            "1e-3",
            "--modulus",
            "1e11",
            "--sigma0",
            "1e9",
            "1e20",
            "--h",
            "1e-9",
        ],
        # faceted wires (issue 33): the facet's scan over a whole block; corner radii above
        # the radius refused point by point, in the same words
        ["--cross-section", "hexagon", "--corner-radius", "0:2e-8:5", "--radius", "40e-9:60e-9:3"]
        + ["--modulus", "5e10", "--work-of-adhesion", "0.1", "--z0", "0.3e-9"],
        ["--cross-section", "pentagon", "--corner-radius-over-R", "0:1:6"]
        + ["--R-over-h", "1:1e4:4:log", "--sigma0-over-E", "0.01"],
        ["--cross-section", "hexagon", "--corner-radius", "0:8e-8:5", "--radius", "50e-9"]
        + ["--modulus", "5e10", "--sigma0", "1e8", "--h", "0.3e-9", "--length", "1e-6"],
        ["--radius", "50e-9", "--modulus", "5e10", "--sigma0", "1e8", "--h", "0.3e-9"]
        + ["--length", "1e-6:1e-5:3"],
    ],
)
def test_the_pull_off_a_block_at_a_time_equals_it_point_by_point(words):
    from linecontact.sweeps._fast import pulloff_block

    p = plan("pulloff", words)
    bl = blocks(p.shape, p.chunk_points)
    assert len(bl) == 1
    assert pulloff_block(p, 0, bl[0]) is not None  # a block at once, refused points and all
    whole = evaluate(p, 0, bl[0])
    one = evaluate(p, 0, bl[0], fast=False)
    assert list(whole.data) == list(one.data)
    # a polygon's scan picks its lowest point among nearly equal loads: an array and a scalar
    # call may round them apart in the last bits (SIMD), so its records within 1e-10
    rtol = 1e-10 if "--cross-section" in words else 1e-13
    for k, a in whole.data.items():
        b = one.data[k]
        if a.dtype.kind == "f":
            np.testing.assert_allclose(a, b, rtol=rtol, atol=0, equal_nan=True, err_msg=k)
        else:
            assert (a == b).all(), k
    assert whole.units == one.units


def test_many_points_outside_the_domain_name_the_groups(monkeypatch):
    from linecontact.sweeps import _fast

    monkeypatch.setattr(_fast, "_SAID_ONE_BY_ONE", 2)
    ds = lc.sweep("pulloff", R_over_h=[1e-9, 2e-9, 3e-9, 100.0], sigma0_over_E=0.01)
    assert list(ds.state.values) == ["invalid"] * 3 + ["ok"]
    first, _, third = (str(r) for r in ds.reason.values[:3])
    assert "--R-over-h" in first and "1e-09" in first
    assert third.startswith("R/h = 3e-09, sigma0/E = 0.01: outside the domain") and first in third
    assert np.isnan(ds.F_pulloff_over_Eh.values[:3]).all() and ds.F_pulloff_over_Eh.values[3] < 0


def test_a_point_without_a_state_is_nan_with_its_state_and_reason():
    ds = lc.sweep("normal", R_over_h=100, sigma0_over_E=0.01, F_over_Eh=[-5.0, 0.0, 1.0])
    assert list(ds.state.values) == ["no-equilibrium", "contact", "contact"]
    assert math.isnan(ds.a_over_R.values[0]) and "pull-off" in str(ds.reason.values[0])
    assert np.isfinite(ds.a_over_R.values[1:]).all() and list(ds.reason.values[1:]) == ["", ""]
    ds = lc.sweep("pulloff", radius=[-1e-9, 5e-8], modulus=1e11, sigma0=1e9, h=1e-9)
    assert list(ds.state.values) == ["invalid", "ok"]
    assert "--radius" in str(ds.reason.values[0])
    assert math.isnan(ds.F_pulloff_N_per_m.values[0]) and ds.F_pulloff_N_per_m.values[1] < 0


def test_dimensions_coordinates_units_and_provenance(tmp_path):
    out = tmp_path / "grid.zarr"
    ds = lc.sweep(
        "pulloff",
        radius="10e-9:100e-9:3:log",
        work_of_adhesion=[0.1, 0.3],
        modulus=1.2e11,
        z0=3e-10,
        output=out,
    )
    assert ds.F_pulloff_N_per_m.dims == ("radius", "work_of_adhesion")
    np.testing.assert_allclose(ds.radius.values, np.geomspace(10e-9, 100e-9, 3), rtol=1e-15)
    assert ds.radius.attrs["units"] == "m" and ds.work_of_adhesion.attrs["units"] == "J/m^2"
    assert ds.F_pulloff_N_per_m.attrs["units"] == "N/m"
    assert ds.attrs["linecontact"] == {"version": lc.__version__}
    assert ds.attrs["command"][:3] == ["linecontact", "sweep", "pulloff"]
    assert ds.attrs["parameters"]["modulus_Pa"] == 1.2e11  # the same at every point
    assert "radius_m" not in ds.attrs["parameters"]  # swept: not one value
    assert ds.attrs["units"]["F_pulloff_N_per_m"] == "N/m"
    again = lc.open_sweep(out)
    assert again.attrs == ds.attrs
    nc = lc.sweep(
        "pulloff",
        radius="10e-9:100e-9:3:log",
        work_of_adhesion=[0.1, 0.3],
        modulus=1.2e11,
        z0=3e-10,
        output=tmp_path / "grid.nc",
    )
    for k in ds.data_vars:
        assert (nc[k].values == ds[k].values).all() or np.allclose(
            nc[k].values, ds[k].values, rtol=0, equal_nan=True
        ), k
    mem = lc.sweep(
        "pulloff",
        radius="10e-9:100e-9:3:log",
        work_of_adhesion=[0.1, 0.3],
        modulus=1.2e11,
        z0=3e-10,
    )
    xr.testing.assert_equal(mem.drop_attrs(), ds.load().drop_attrs())


def test_the_same_command_again_goes_on_or_finds_it_done(tmp_path, capsys):
    out = str(tmp_path / "c.zarr")
    argv = [
        "sweep",
        "pulloff",
        "--R-over-h",
        "10:1000:30:log",
        "--sigma0-over-E",
        "0.01",
        "0.1",
        "--law",
        "lennard-jones",
        "-o",
        out,
        "--workers",
        "1",
        "--chunk-points",
        "6",
    ]
    assert main(argv) == 0
    first = lc.open_sweep(out).load()
    capsys.readouterr()
    assert main(argv) == 0  # done before: read, not computed again
    xr.testing.assert_identical(lc.open_sweep(out).load(), first)


def _same_dataset(a, b):
    """Equal coordinates and text; numbers to 1e-9 (BLAS threads move the last bits of the
    Lennard-Jones solver's factorisations: a Dask worker runs one thread)."""
    a, b = a.load(), b.load()
    assert list(a.data_vars) == list(b.data_vars) and a.sizes == b.sizes
    xr.testing.assert_identical(
        a.coords.to_dataset().drop_attrs(deep=False), b.coords.to_dataset().drop_attrs(deep=False)
    )
    for k in a.data_vars:
        if a[k].dtype.kind == "f":  # an error estimate is a difference: fewer digits
            rtol = 1e-6 if k.startswith("error_estimate") else 1e-9
            np.testing.assert_allclose(a[k], b[k], rtol=rtol, atol=0, equal_nan=True, err_msg=k)
        else:
            assert (a[k].values == b[k].values).all(), k


def _blocks_done(partial: Path) -> int:
    return len(list(partial.glob("block-*.npz"))) if partial.is_dir() else 0


def test_kill_9_then_resume_equals_an_uninterrupted_run(tmp_path):
    words = [
        "pulloff",
        "--R-over-h",
        "3:3000:24:log",
        "--sigma0-over-E",
        "0.02",
        "0.2",
        "--law",
        "lennard-jones",
        "--chunk-points",
        "2",
        "--workers",
        "1",
    ]
    out = tmp_path / "lj.zarr"
    cmd = [sys.executable, "-m", "linecontact", "sweep", *words, "-o", str(out)]
    env = {**os.environ, "OPENBLAS_NUM_THREADS": "1"}
    proc = subprocess.Popen(cmd, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    partial = Path(f"{out}.partial")
    deadline = time.monotonic() + 120
    while _blocks_done(partial) < 3 and proc.poll() is None and time.monotonic() < deadline:
        time.sleep(0.05)
    proc.send_signal(signal.SIGKILL)
    proc.wait()
    done = _blocks_done(partial)
    assert 3 <= done < 24, done  # stopped part way
    assert not out.exists()
    # a file being written when it was killed is a temporary one: never read as a block
    assert all(not f.name.startswith("block-") for f in partial.glob(".tmp-*"))
    resumed = subprocess.run(cmd, env=env, capture_output=True, text=True, timeout=300)
    assert resumed.returncode == 0, resumed.stderr
    assert not partial.exists()
    whole = lc.sweep(words[0], **_kwargs(words[1:-4]), chunk_points=2)
    _same_dataset(lc.open_sweep(out), whole)


def test_a_dask_cluster_of_processes_gives_the_same_dataset(tmp_path):
    distributed = pytest.importorskip("distributed")
    kw = dict(R_over_h="3:300:6:log", sigma0_over_E=[0.02, 0.2], law="lennard-jones")
    here = lc.sweep("pulloff", **kw, chunk_points=2)
    with distributed.LocalCluster(
        n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None
    ) as cluster:
        there = lc.sweep(
            "pulloff",
            **kw,
            chunk_points=2,
            scheduler=cluster.scheduler_address,
            output=tmp_path / "d.zarr",
        )
        _same_dataset(there, here)
    local = lc.sweep("pulloff", **kw, chunk_points=2, workers=2)
    _same_dataset(local, here)


BAD = [
    (["pulloff", "--radius", "1e-9:1e-8:0"], "--radius"),
    (["pulloff", "--radius", "1e-8:1e-9:5:log"], "--radius"),
    (["pulloff", "--radius", "0:1e-8:5:log"], "--radius"),
    (["pulloff", "--radius", "1e-9:1e-8:2.5"], "--radius"),
    (["pulloff", "--radius", "1e-9:1e-8:5:lin"], "--radius"),
    (["pulloff", "--radious", "1e-9", "2e-9"], "--radious"),
    (["pulloff", "--radius", "1e-9", "2e-9", "--json"], "--json"),
    (["paper", "--radius", "1e-9"], "paper"),
    (["history", "--R-over-h", "100"], "history"),
    (["pulloff", "--R-over-h", "100", "200"], "--sigma0-over-E"),
]


@pytest.mark.parametrize(("words", "named"), BAD)
def test_bad_input_is_one_error_line_exit_2_and_nothing_written(tmp_path, capsys, words, named):
    out = tmp_path / "x.zarr"
    code = main(["sweep", *words, "-o", str(out)])
    _, err = capsys.readouterr()
    lines = err.strip().splitlines()
    assert code == 2 and len(lines) == 1, err
    assert lines[0].startswith("linecontact sweep: error:") and named in lines[0], lines[0]
    assert list(tmp_path.iterdir()) == []


def test_a_scheduler_that_does_not_answer_is_one_error_line(tmp_path, capsys):
    pytest.importorskip("distributed")
    out = tmp_path / "x.zarr"
    argv = ["sweep", "pulloff", "--R-over-h", "10", "100", "--sigma0-over-E", "0.01"]
    code = main([*argv, "--scheduler", "tcp://127.0.0.1:9", "-o", str(out)])
    err = capsys.readouterr().err.strip().splitlines()
    assert code == 2 and len(err) == 1 and "--scheduler" in err[0], err
    assert list(tmp_path.iterdir()) == []


def test_the_store_is_refused_unless_it_is_this_sweeps(tmp_path, capsys):
    out = tmp_path / "x.nc"
    base = ["sweep", "pulloff", "--R-over-h", "10", "100", "--sigma0-over-E", "0.01", "-o"]
    assert main([*base, str(out)]) == 0
    other = ["sweep", "pulloff", "--R-over-h", "10", "100", "--sigma0-over-E", "0.02", "-o"]
    capsys.readouterr()
    assert main([*other, str(out)]) == 2
    err = capsys.readouterr().err
    assert "--overwrite" in err and err.count("\n") == 1
    assert lc.open_sweep(out).attrs["parameters"]["sigma0_over_E"] == 0.01
    assert main([*other, str(out), "--overwrite"]) == 0
    assert lc.open_sweep(out).attrs["parameters"]["sigma0_over_E"] == 0.02
    for bad in ([*base, str(tmp_path / "x.csv")], [*base, str(tmp_path / "no" / "x.zarr")]):
        capsys.readouterr()
        assert main(bad) == 2
        assert "-o/--output" in capsys.readouterr().err
    capsys.readouterr()
    assert main(base[:-1]) == 2 and "-o" in capsys.readouterr().err


def test_the_extra_is_named_when_it_is_missing(monkeypatch):
    monkeypatch.setitem(sys.modules, "xarray", None)
    with pytest.raises(ImportError, match=r"linecontact\[sweep\]"):
        lc.sweep("pulloff", R_over_h=[10, 100], sigma0_over_E=0.01)


@given(
    start=st.floats(1e-12, 1e12),
    ratio=st.floats(1.0, 1e6),
    num=st.integers(1, 500),
)
def test_a_log_range_has_num_values_from_start_to_stop(start, ratio, num):
    stop = start * ratio
    vals = flag_values("--x", [f"{start!r}:{stop!r}:{num}:log"], float)
    assert len(vals) == num and vals[0] == pytest.approx(start, rel=1e-12)
    if num > 1:
        assert vals[-1] == pytest.approx(stop, rel=1e-12)
        assert all(b >= a for a, b in zip(vals, vals[1:], strict=False))


def test_values_and_ranges_join_in_order():
    assert flag_values("--x", ["1", "2:4:3", "10"], float) == [1.0, 2.0, 3.0, 4.0, 10.0]
    assert flag_values("--n", ["2:6:3"], int) == [2, 4, 6]
    with pytest.raises(ValueError, match="--n takes integers"):
        flag_values("--n", ["1:2:3"], int)


def test_blocks_tile_the_grid():
    for shape, n in (((7, 5, 3), 4), ((3163, 3163), 200_000), ((10,), 3), ((2, 2), 100)):
        bl = blocks(shape, n)
        seen = np.zeros(shape, int)
        for b in bl:
            seen[b] += 1
            assert math.prod(s.stop - s.start for s in b) <= max(n, shape[-1])
        assert (seen == 1).all()


def test_the_progress_bar_is_on_stderr_when_asked(tmp_path, capsys):
    argv = ["sweep", "pulloff", "--R-over-h", "10:1000:5:log", "--sigma0-over-E", "0.01"]
    assert main([*argv, "-o", str(tmp_path / "a.zarr"), "--progress"]) == 0
    out, err = capsys.readouterr()
    assert out == "" and "sweep pulloff" in err and "5/5" in err
    assert main([*argv, "-o", str(tmp_path / "b.zarr")]) == 0  # not a terminal: no bar
    out, err = capsys.readouterr()
    assert out == "" and "sweep pulloff" not in err and err.startswith("wrote ")


def test_a_script_without_a_main_guard_runs_two_workers(tmp_path):
    """The local pool forks where it can: a plain script's ``workers=2`` needs no guard (a
    local Dask cluster spawned its workers, which re-ran the script and failed to start)."""
    script = tmp_path / "plain.py"
    script.write_text(
        "import linecontact as lc\n"
        "kw = dict(R_over_h='3:300:4:log', sigma0_over_E=[0.02, 0.2], law='lennard-jones')\n"
        "two = lc.sweep('pulloff', **kw, chunk_points=2, workers=2)\n"
        "one = lc.sweep('pulloff', **kw, chunk_points=2)\n"
        "import numpy as np\n"
        "a, b = two['F_pulloff_over_Eh'].values, one['F_pulloff_over_Eh'].values\n"
        "print('same', bool(np.allclose(a, b, rtol=1e-9, atol=0)), a.size)\n"
    )
    env = {**os.environ, "OPENBLAS_NUM_THREADS": "1"}
    done = subprocess.run(
        [sys.executable, str(script)], env=env, capture_output=True, text=True, timeout=300
    )
    assert done.returncode == 0, done.stderr[-2000:]
    assert "same True 8" in done.stdout, done.stdout


def test_text_is_stored_as_codes_and_read_back_as_the_sweep_gave_it(tmp_path):
    # a store keeps text as int32 codes into its attribute "categories" (issue 36: ten
    # million strings cost 7 s of 18); open_sweep gives back the text of the sweep in
    # memory, reasons with numbers in them and the padding of curves of several records
    # included, in blocks of one point (every block its own categories)
    cases = [
        ("normal", dict(R_over_h=100, sigma0_over_E=0.01, F_over_Eh=[-5.0, 0.0, 1.0])),
        ("pulloff", dict(R_over_h=[1e-9, 2e-9, 100.0], sigma0_over_E=[0.01, 0.1])),
        ("curve", dict(R_over_h=100, sigma0_over_E=[0.01, 0.1], num=[5, 8])),
    ]
    for command, kw in cases:
        out = tmp_path / f"{command}.zarr"
        mem = lc.sweep(command, **kw)
        lc.sweep(command, **kw, output=str(out), chunk_points=1)
        raw = xr.open_zarr(out, consolidated=False)
        back = lc.open_sweep(out)
        for name in ("state", "reason"):
            assert raw[name].dtype == np.int32
            cats = json.loads(raw[name].attrs["categories"])
            assert cats[0] == "" and len(set(cats)) == len(cats)
            assert "categories" not in back[name].attrs
            assert _words(back[name]) == _words(mem[name]), name
        text = [n for n in mem.data_vars if mem[n].dtype.kind == "O"]
        for name in text:
            assert _words(back[name]) == _words(mem[name]), name
        for name in set(mem.data_vars) - set(text):  # (blocks of one point: another path)
            np.testing.assert_allclose(back[name].values, mem[name].values, rtol=1e-12)


def _words(v):
    return [str(x) for x in np.asarray(v.values).ravel().tolist()]
