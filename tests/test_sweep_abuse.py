"""Sweeps under abuse: a store never mixes two builds, files only where a file belongs.

- The resume key fingerprints the code: blocks kept by a build whose kernel differs are
  computed again (shown with two copies of the package, one with a patched kernel, run in
  their own processes), a store of another build is refused without ``--overwrite``.
- ``-o`` onto a FIFO, a symlink to a device, a directory or a socket is refused with one
  error line, and nothing at the path changes; a symlink to a regular file is written
  through (the link stays).
- One writer per store; the kept blocks follow the umask.
- A sweep too large for the disk or memory, or for planning, is refused at once with its
  size; a scheduler that is not one is one error line within a bounded time; nothing swept
  is one point; a swept flag is never a fixed parameter of the provenance; masked arrays.
"""

from __future__ import annotations

import errno
import json
import os
import shutil
import socket
import stat
import subprocess
import sys
import threading
import time
from pathlib import Path

import numpy as np
import pytest

import linecontact as lc
from linecontact._files import atomic_file, regular_target
from linecontact.cli import main

pytest.importorskip("xarray")
pytest.importorskip("zarr")

PKG = Path(lc.__file__).resolve().parent
WORDS = [
    "pulloff",
    "--R-over-h",
    "10:1000:12:log",
    "--sigma0-over-E",
    "0.01",
    "--chunk-points",
    "2",
]


def _copy_package(dest: Path, patch: bool) -> Path:
    """A copy of the package at ``dest/linecontact``; ``patch``: its pull-off kernel changed
    (the minimum it reports halved, so that the pull-off is twice it)."""
    shutil.copytree(PKG, dest / "linecontact", ignore=shutil.ignore_patterns("__pycache__"))
    if patch:
        f = dest / "linecontact" / "normal" / "pulloff.py"
        text = f.read_text()
        line = 'd["F_minimum_over_Eh"] = d["F_pulloff_over_Eh"]'
        assert text.count(line) == 1
        f.write_text(text.replace(line, line + " / 2.0"))
    return dest


def _run(path: Path, args: list[str], **kw) -> subprocess.CompletedProcess[str]:
    env = {**os.environ, "PYTHONPATH": str(path), "OPENBLAS_NUM_THREADS": "1"}
    return subprocess.run(
        [sys.executable, *args], env=env, capture_output=True, text=True, timeout=300, **kw
    )


KEEP_THREE = """
import sys
import linecontact
from linecontact.sweeps._plan import plan, blocks
from linecontact.sweeps._points import evaluate
from linecontact.sweeps._store import Partial
assert linecontact.__file__.startswith(sys.argv[1]), linecontact.__file__
words = sys.argv[3:]
p = plan(words[0], words[1:-2], None, int(words[-1]))
part = Partial(p, sys.argv[2])
bl = blocks(p.shape, p.chunk_points)
with part.locked():
    part.open(False)
    for k in range(3):
        part.put(evaluate(p, k, bl[k]))
print(len(bl))
"""


def test_blocks_of_a_build_with_another_kernel_are_computed_again(tmp_path):
    a = _copy_package(tmp_path / "a", patch=False)
    b = _copy_package(tmp_path / "b", patch=True)
    out = tmp_path / "s.zarr"
    kept = _run(a, ["-c", KEEP_THREE, str(a), str(out), *WORDS])
    assert kept.returncode == 0, kept.stderr
    assert int(kept.stdout) == 6
    assert len(list(Path(f"{out}.partial").glob("block-*.npz"))) == 3
    # the same command with a patched kernel: the three blocks are not reused
    resumed = _run(b, ["-m", "linecontact", "sweep", *WORDS, "-o", str(out)])
    assert resumed.returncode == 0, resumed.stderr
    assert "another build of linecontact" in resumed.stderr and "3 blocks" in resumed.stderr
    ds = lc.open_sweep(out).load()
    np.testing.assert_allclose(
        ds.F_pulloff_over_Eh, 2.0 * ds.F_minimum_over_Eh, rtol=1e-15, err_msg="a block of A"
    )
    # the finished store of build B is refused by build A, and recomputed with --overwrite
    again = _run(a, ["-m", "linecontact", "sweep", *WORDS, "-o", str(out)])
    assert again.returncode == 2
    assert "another build" in again.stderr and again.stderr.count("\n") == 1, again.stderr
    over = _run(a, ["-m", "linecontact", "sweep", *WORDS, "-o", str(out), "--overwrite"])
    assert over.returncode == 0, over.stderr
    ds = lc.open_sweep(out).load()
    np.testing.assert_allclose(ds.F_pulloff_over_Eh, ds.F_minimum_over_Eh, rtol=1e-15)


def test_the_same_build_resumes_its_blocks_without_a_word(tmp_path, recwarn):
    out = tmp_path / "s.nc"
    kw = dict(R_over_h="10:1000:12:log", sigma0_over_E=0.01, chunk_points=2)
    p = lc.sweeps._plan.plan("pulloff", WORDS[1:-2], None, 2)
    part = lc.sweeps._store.Partial(p, out)
    with part.locked():
        part.open(False)
        part.put(lc.sweeps._points.evaluate(p, 0, lc.sweeps._plan.blocks(p.shape, 2)[0]))
    ds = lc.sweep("pulloff", output=out, **kw)
    assert not [w for w in recwarn if "another build" in str(w.message)]
    assert ds.sizes["R_over_h"] == 12


def _guard_replace(monkeypatch, root: Path):
    """``os.replace`` that fails the test for any target outside ``root``."""
    real = os.replace

    def guarded(src, dst, *a, **k):
        assert Path(os.path.abspath(dst)).is_relative_to(root), f"replaced {dst}"
        return real(src, dst, *a, **k)

    monkeypatch.setattr(os, "replace", guarded)


def _fifo(path: Path) -> Path:
    os.mkfifo(path)
    return path


def _socket(path: Path) -> Path:
    s = socket.socket(socket.AF_UNIX)
    s.bind(str(path))
    s.close()
    return path


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="POSIX")
@pytest.mark.parametrize(
    ("make", "kind"),
    [
        (lambda d: _fifo(d / "f"), "FIFO"),
        (lambda d: (d / "dev").symlink_to("/dev/null") or d / "dev", "character device"),
        (lambda d: (d / "d").mkdir() or d / "d", "directory"),
        (lambda d: _socket(d / "s"), "socket"),
    ],
    ids=["fifo", "symlink-to-device", "directory", "socket"],
)
def test_o_is_refused_where_no_regular_file_is(tmp_path, capsys, monkeypatch, make, kind):
    _guard_replace(monkeypatch, tmp_path)
    path = make(tmp_path)
    before = os.lstat(path)
    code = main(["pulloff", "--R-over-h", "100", "--sigma0-over-E", "0.01", "-o", str(path)])
    err = capsys.readouterr().err.strip().splitlines()
    assert code == 2 and len(err) == 1, err
    assert "-o/--output" in err[0] and kind in err[0] and str(path) in err[0], err[0]
    after = os.lstat(path)
    assert (after.st_ino, after.st_mode) == (before.st_ino, before.st_mode)
    assert sorted(p.name for p in tmp_path.iterdir()) == [path.name]  # no temporary left


def test_a_symlink_to_a_file_is_written_through(tmp_path, capsys):
    real = tmp_path / "real.csv"
    real.write_text("old\n")
    os.chmod(real, 0o640)
    link = tmp_path / "link.csv"
    link.symlink_to(real)
    code = main(["pulloff", "--R-over-h", "100", "--sigma0-over-E", "0.01", "-o", str(link)])
    assert code == 0, capsys.readouterr().err
    assert link.is_symlink() and os.readlink(link) == str(real)
    assert "F_pulloff_over_Eh" in real.read_text()
    assert stat.S_IMODE(real.stat().st_mode) == 0o640


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="POSIX")
def test_a_sweep_and_a_figure_are_refused_over_a_fifo(tmp_path, capsys, monkeypatch):
    _guard_replace(monkeypatch, tmp_path)
    fifo = _fifo(tmp_path / "s.nc")
    code = main(["sweep", "pulloff", "--R-over-h", "10", "100", "--sigma0-over-E", "0.01", "-o"])
    assert code == 2  # no path: a usage error
    capsys.readouterr()
    argv = ["sweep", "pulloff", "--R-over-h", "10", "100", "--sigma0-over-E", "0.01"]
    assert main([*argv, "-o", str(fifo)]) == 2
    err = capsys.readouterr().err
    assert "-o/--output" in err and err.count("\n") == 1, err
    assert stat.S_ISFIFO(os.lstat(fifo).st_mode)
    with pytest.raises(ValueError, match="FIFO"):
        with atomic_file(_fifo(tmp_path / "fig.png"), name="figure"):
            pass
    assert regular_target(tmp_path / "new.csv") == str(tmp_path / "new.csv")


def test_a_second_writer_of_one_store_is_refused(tmp_path, capsys):
    out = tmp_path / "s.zarr"
    p = lc.sweeps._plan.plan("pulloff", WORDS[1:-2], None, 2)
    with lc.sweeps._store.Partial(p, out).locked():
        assert main(["sweep", *WORDS, "-o", str(out)]) == 2
        err = capsys.readouterr().err
        assert "another linecontact sweep is writing it" in err and err.count("\n") == 1, err
    assert main(["sweep", *WORDS, "-o", str(out)]) == 0  # the lock let go: it runs
    assert not Path(f"{out}.partial").exists()


@pytest.mark.parametrize("mask", [0o022, 0o027, 0o077])
def test_kept_blocks_follow_the_umask(tmp_path, mask):
    out = tmp_path / "s.zarr"
    p = lc.sweeps._plan.plan("pulloff", WORDS[1:-2], None, 2)
    old = os.umask(mask)
    try:
        part = lc.sweeps._store.Partial(p, out)
        with part.locked():
            part.open(False)
            part.put(lc.sweeps._points.evaluate(p, 0, lc.sweeps._plan.blocks(p.shape, 2)[0]))
            files = list(Path(f"{out}.partial").iterdir())
            assert {f.name for f in files} == {"sweep.json", "block-000000.npz"}
            for f in files:
                assert stat.S_IMODE(f.stat().st_mode) == 0o666 & ~mask, f
    finally:
        os.umask(old)


def test_a_sweep_too_large_is_refused_at_once_with_its_size(tmp_path, capsys, monkeypatch):
    from linecontact.sweeps import _engine

    base = ["sweep", "pulloff", "--sigma0-over-E", "0.01"]
    x = str(tmp_path / "x.zarr")
    start = time.monotonic()
    # more points than a sweep takes: counted from the ranges, never expanded
    big = ["--R-over-h", "10:1e3:100000", "--sigma0-over-E", "0.001:0.1:50000", "0.2:0.3:50000"]
    assert main(["sweep", "pulloff", *big, "-o", x]) == 2
    err = capsys.readouterr().err
    assert "1e+10 points" in err and "--sigma0-over-E (100000)" in err, err
    assert main([*base, "--R-over-h", "10:1e3:1000000000", "-o", x]) == 2
    assert "1000000000 values" in capsys.readouterr().err
    assert time.monotonic() - start < 30
    assert list(tmp_path.iterdir()) == []
    # 1e9 points that the disk cannot hold: the estimate, before anything is written
    monkeypatch.setattr(
        shutil, "disk_usage", lambda p: shutil._ntuple_diskusage(10**12, 10**12 - 10**9, 10**9)
    )
    argv = [*base[:2], "--R-over-h", "10:1e3:40000:log", "--sigma0-over-E", "0.001:0.1:25000"]
    assert main([*argv, "-o", str(tmp_path / "x.zarr")]) == 2
    err = capsys.readouterr().err.strip()
    assert "1000000000 points" in err and "GB on disk" in err and "1 GB free" in err, err
    assert list(tmp_path.iterdir()) == []
    # in memory: the memory the machine has
    monkeypatch.setattr(_engine, "_available_memory", lambda: 10**8)
    with pytest.raises(ValueError, match=r"GB in memory, more than the 0\.1 GB"):
        lc.sweep("pulloff", R_over_h="10:1e3:1000:log", sigma0_over_E="0.001:0.1:1000")


class _NotDask(threading.Thread):
    """A TCP server that is no Dask scheduler: it answers garbage, or nothing at all."""

    def __init__(self, reply: bytes | None) -> None:
        super().__init__(daemon=True)
        self.sock = socket.create_server(("127.0.0.1", 0))
        self.port = self.sock.getsockname()[1]
        self.reply, self.stop, self.conns = reply, threading.Event(), []

    def run(self) -> None:
        self.sock.settimeout(0.2)
        while not self.stop.is_set():
            try:
                conn, _ = self.sock.accept()
            except OSError:
                continue
            self.conns.append(conn)
            if self.reply is not None:
                try:
                    conn.sendall(self.reply)
                except OSError:
                    pass

    def close(self) -> None:
        self.stop.set()
        self.join(5)
        for c in self.conns:
            c.close()
        self.sock.close()


@pytest.mark.parametrize("reply", [b"\xff" * 64, b"HTTP/1.0 400 Bad\r\n\r\n", None])
def test_a_scheduler_that_is_not_one_is_one_line_in_bounded_time(tmp_path, capsys, reply):
    pytest.importorskip("distributed")
    from linecontact.sweeps import _engine

    server = _NotDask(reply)
    server.start()
    try:
        start = time.monotonic()
        with pytest.MonkeyPatch.context() as mp:
            mp.setattr(_engine, "CONNECT_TIMEOUT", 2.0)
            code = main(
                [
                    "sweep",
                    "pulloff",
                    "--R-over-h",
                    "10",
                    "100",
                    "--sigma0-over-E",
                    "0.01",
                    "--scheduler",
                    f"tcp://127.0.0.1:{server.port}",
                    "-o",
                    str(tmp_path / "x.zarr"),
                ]
            )
        took = time.monotonic() - start
    finally:
        server.close()
    err = capsys.readouterr().err.strip().splitlines()
    assert code == 2 and len(err) == 1 and "--scheduler" in err[0], err
    assert "internal error" not in err[0]
    assert took < 30, took
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("address", ["tcp://127.0.0.1:99999", "tcp://:80", "127.0.0.1"])
def test_a_scheduler_address_that_is_none_is_said(address):
    from linecontact.sweeps._engine import _address

    with pytest.raises(ValueError, match="--scheduler"):
        _address(address)


def test_a_sweep_with_nothing_swept_is_the_plain_command(tmp_path, capsys):
    words = ["normal", "--R-over-h", "100", "--sigma0-over-E", "0.01", "--F-over-Eh", "1"]
    assert main([*words, "--json"]) == 0
    plain = json.loads(capsys.readouterr().out)["results"][0]
    out = tmp_path / "one.nc"
    assert main(["sweep", *words, "-o", str(out)]) == 0
    assert "nothing swept" in capsys.readouterr().err
    ds = lc.open_sweep(out).load()
    assert ds.sizes == {} or dict(ds.sizes) == {}
    for k, v in plain.items():
        if isinstance(v, float):
            assert float(ds[k]) == pytest.approx(v, rel=1e-12), k
        elif isinstance(v, str):
            assert str(ds[k].values) == v, k


def test_a_swept_flag_is_never_a_fixed_parameter():
    # one point refused: the other alone is no evidence of what the points share
    ds = lc.sweep("pulloff", R_over_h=[100.0, 1e30], sigma0_over_E=0.01)
    assert list(ds.state.values) == ["ok", "invalid"]
    assert ds.attrs["parameters"] == {"sigma0_over_E": 0.01}
    ds = lc.sweep("normal", R_over_h=[100.0, 1e30], sigma0_over_E=0.01, F_over_Eh=[1.0, 2.0])
    assert "R_over_h" not in ds.attrs["parameters"] and "kappa" not in ds.attrs["parameters"]
    ds = lc.sweep("pulloff", radius=[5e-8, 6e-8], modulus=1e11, work_of_adhesion=0.3, z0=3e-10)
    assert not any(k.startswith("radius") for k in ds.attrs["parameters"])
    assert ds.attrs["parameters"]["modulus_Pa"] == 1e11


def test_a_masked_array_is_refused_not_swept_unmasked():
    kw = dict(modulus=1e11, work_of_adhesion=0.3, z0=3e-10)
    with pytest.raises(ValueError, match=r"radius: a masked array with 1 masked"):
        lc.sweep("pulloff", radius=np.ma.masked_array([5e-8, 6e-8], [0, 1]), **kw)
    ds = lc.sweep("pulloff", radius=np.ma.masked_array([5e-8, 6e-8], [0, 0]), **kw)
    assert ds.sizes["radius"] == 2


def test_a_full_disk_while_keeping_a_block_names_the_file(tmp_path, capsys, monkeypatch):
    def full(*a, **k):
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))

    monkeypatch.setattr(np, "savez", full)
    out = tmp_path / "s.zarr"
    assert main(["sweep", *WORDS, "-o", str(out)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "standard output" not in err[0], err
    assert "no space left" in err[0].lower() and "s.zarr.partial" in err[0], err[0]
