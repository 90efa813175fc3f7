"""Where a sweep keeps its blocks as they finish, and the labelled store they end in.

A sweep with ``-o OUT`` keeps each finished block in ``OUT.partial/`` as its own ``.npz``
file, written under a temporary name and renamed when whole: a file there is a whole block,
so a run stopped at any moment (Ctrl-C, ``kill -9``) goes on from the blocks it finished.
``OUT.partial/sweep.json`` holds the sweep's identity (:meth:`Plan.identity`: the command
and its values) and its key (:meth:`Plan.key`: the identity and the digest of the code):
blocks of another sweep are refused (unless ``overwrite``), blocks of this sweep kept by
another build of linecontact (another version, an edited module, another NumPy) are
discarded and computed again, with a warning, so that a store never mixes the numbers of two
builds. One process writes ``OUT`` at a time: it holds a lock on ``OUT.partial/`` (where the
system has ``flock``), and a second is refused with a message. When every block is there,
the dataset is written, block by block, to ``OUT`` (Zarr for ``.zarr``, netCDF for ``.nc``)
under a temporary name and renamed, and ``OUT.partial/`` removed. The files follow the
umask, as files written by ``open`` do.
"""

from __future__ import annotations

import contextlib
import json
import os
import re
import shutil
import stat
import warnings
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import numpy as np

from .._files import atomic_file
from .._fingerprint import code_identity
from ._block import TEXT, Block, codes, is_text
from ._plan import Plan, blocks

try:  # POSIX
    import fcntl
except ImportError:  # pragma: no cover - Windows: no lock, one writer is the user's care
    fcntl = None  # type: ignore[assignment]

__all__ = ["FORMATS", "Partial", "format_of", "need", "real_output", "store_identity", "store_key"]

#: The store formats, by the extension of ``-o``.
FORMATS = {".zarr": "zarr", ".nc": "netcdf", ".nc4": "netcdf"}

_META = "__meta__"

_EXTRA = "pip install 'linecontact[sweep]'"


def need(*modules: str) -> None:
    """ImportError naming the extra when a module of the sweeps is missing."""
    for m in ("xarray", "dask", *modules):
        try:
            __import__(m)
        except ImportError:
            raise ImportError(f"sweeps need {m}, part of the extra [sweep]: {_EXTRA}") from None


def format_of(path: str | os.PathLike[str]) -> str:
    """The store format of ``path`` (by its extension), or a ValueError naming ``-o``."""
    ext = Path(path).suffix.lower()
    if ext not in FORMATS:
        raise ValueError(
            f"-o/--output {str(path)!r}: a sweep writes Zarr (.zarr) or netCDF (.nc), not "
            f"{ext or 'a file without an extension'!r}"
        )
    return FORMATS[ext]


def real_output(path: str | os.PathLike[str]) -> str:
    """The path a store at ``path`` is written to: ``path``, or where its link points."""
    given = os.fspath(path)
    return os.path.realpath(given) if os.path.islink(given) else given


def _store_attrs(path: str | os.PathLike[str]) -> dict[str, Any] | None:
    """The attributes of a finished store at ``path`` (None: not a store of a sweep)."""
    import xarray as xr

    try:
        mode = os.stat(path).st_mode
    except OSError:
        return None
    if not (stat.S_ISDIR(mode) if format_of(path) == "zarr" else stat.S_ISREG(mode)):
        return None  # never opened: a FIFO would block the reader
    try:
        if format_of(path) == "zarr":
            ds = xr.open_zarr(path, consolidated=False)
        else:
            ds = xr.open_dataset(path)
    except Exception:  # noqa: BLE001 - whatever is there, it is not a sweep's store
        return None
    with ds:
        attrs = dict(ds.attrs)
    return attrs if isinstance(attrs.get("sweep_key"), str) else None


def store_key(path: str | os.PathLike[str]) -> str | None:
    """The sweep key of a finished store at ``path`` (None: not a store of a sweep)."""
    attrs = _store_attrs(path)
    return None if attrs is None else attrs["sweep_key"]


def store_identity(path: str | os.PathLike[str]) -> str | None:
    """The sweep identity of a finished store at ``path`` (None: none said)."""
    attrs = _store_attrs(path)
    ident = None if attrs is None else attrs.get("sweep_identity")
    return ident if isinstance(ident, str) else None


def _encode(block: Block) -> dict[str, np.ndarray]:
    """Arrays for ``np.savez``: strings as codes into their categories (no pickles)."""
    out: dict[str, np.ndarray] = {}
    for k, v in block.data.items():
        if is_text(v.dtype):
            cats, at = block.coded(k) if v.dtype.kind == "O" else codes(v)
            out[f"{k}.codes"] = at
            out[f"{k}.cats"] = np.array([str(c) for c in cats.tolist()] or [""])  # no pickle
        else:
            out[k] = v
    return out


def _kind(v: np.ndarray) -> str:
    """``"O"`` for text, else the dtype's kind (``"f"``, ``"b"``)."""
    return "O" if is_text(v.dtype) else v.dtype.kind


def _decode(z: Any, name: str) -> np.ndarray:
    if name in z.files:
        return np.asarray(z[name])
    cats = np.asarray(z[f"{name}.cats"]).astype(TEXT)
    return cats[np.asarray(z[f"{name}.codes"])]


class Partial:
    """The blocks of a sweep kept as they finish: in ``OUT.partial/``, or in memory.

    Parameters
    ----------
    plan : Plan
        The sweep.
    output : path or None
        ``OUT`` (the blocks in ``OUT.partial/``), or None (in memory; nothing resumes).
    """

    def __init__(self, plan: Plan, output: str | os.PathLike[str] | None) -> None:
        self.plan = plan
        self.output = None if output is None else Path(output)
        self.dir = None if output is None else Path(f"{output}.partial")
        self.memory: dict[int, Block] = {}

    @contextlib.contextmanager
    def locked(self) -> Iterator[None]:
        """Hold the lock of ``OUT.partial/`` (made if need be) while the block runs.

        A second process writing the same ``OUT`` is refused with a ValueError. On the way
        out, an ``OUT.partial/`` left empty (nothing kept) is removed.
        """
        if self.dir is None:
            yield
            return
        fd = self._lock()
        try:
            yield
        finally:
            with contextlib.suppress(OSError):
                self.dir.rmdir()  # only when empty: nothing of this sweep is kept there
            os.close(fd)

    def _lock(self) -> int:
        assert self.dir is not None
        for _ in range(8):
            try:
                self.dir.mkdir(exist_ok=True)
                fd = os.open(self.dir, os.O_RDONLY | getattr(os, "O_DIRECTORY", 0))
            except OSError as exc:
                raise ValueError(
                    f"-o/--output {str(self.output)!r}: cannot keep its blocks in "
                    f"{str(self.dir)!r}: {exc.strerror or exc}"
                ) from None
            if fcntl is None:
                return fd
            try:
                fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
            except OSError:
                os.close(fd)
                raise ValueError(
                    f"-o/--output {str(self.output)!r}: another linecontact sweep is writing "
                    f"it now (it holds {str(self.dir)!r}); wait for it to end, or stop it, "
                    "then run the command again"
                ) from None
            try:  # the directory locked is still the one at the path (not one just removed)
                here, held = os.stat(self.dir), os.fstat(fd)
                if (here.st_dev, here.st_ino) == (held.st_dev, held.st_ino):
                    return fd
            except OSError:
                pass
            os.close(fd)
        raise ValueError(
            f"-o/--output {str(self.output)!r}: {str(self.dir)!r} keeps being replaced by "
            "another process; run the command again once it has ended"
        )

    def open(self, overwrite: bool) -> None:
        """Start or resume (under :meth:`locked`).

        Blocks of another sweep are refused unless ``overwrite``; blocks of this sweep kept
        by another build of linecontact are discarded, with a warning.
        """
        if self.dir is None:
            return
        key, identity = self.plan.key(), self.plan.identity()
        manifest = self.dir / "sweep.json"
        try:
            theirs = json.loads(manifest.read_text())
        except (OSError, ValueError):
            theirs = None
        if not isinstance(theirs, dict):
            theirs = None
        kept = self.done()
        if theirs is not None and theirs.get("key") != key:
            if theirs.get("identity") != identity:
                if not overwrite:
                    raise ValueError(
                        f"-o/--output {str(self.output)!r}: {str(self.dir)!r} holds the blocks "
                        "of another sweep (another command or flags); give --overwrite to "
                        "replace it"
                    )
            elif kept:
                warnings.warn(
                    f"{str(self.dir)!r} held {len(kept)} blocks of this sweep computed by "
                    f"another build of linecontact ({_build(theirs.get('code'))}; this one: "
                    f"{_build(code_identity())}): they were discarded and are computed "
                    "again, so that the store holds the numbers of one build",
                    UserWarning,
                    stacklevel=4,
                )
            theirs = None
        elif theirs is None and kept:  # blocks without a manifest: not known to be ours
            if not overwrite:
                raise ValueError(
                    f"-o/--output {str(self.output)!r}: {str(self.dir)!r} holds blocks of an "
                    "unknown sweep; give --overwrite to replace them"
                )
        if theirs is None:
            for f in self.dir.iterdir():  # the directory stays: it is the lock
                if f.is_dir() and not f.is_symlink():
                    shutil.rmtree(f)
                else:
                    f.unlink()
            info = {
                "key": key,
                "identity": identity,
                "code": code_identity(),
                "command": list(self.plan.argv),
                "shape": self.plan.shape,
            }
            with atomic_file(manifest, name="the sweep's manifest") as fh:
                fh.write(json.dumps(info).encode())

    def _kept(self) -> dict[int, Path]:
        """Entries named as kept blocks (``block-NNNNNN.npz`` of a block of the plan)."""
        assert self.dir is not None
        out: dict[int, Path] = {}
        n = len(blocks(self.plan.shape, self.plan.chunk_points))
        for f in self.dir.iterdir():
            m = _BLOCK_NAME.fullmatch(f.name)
            if m is not None and int(m.group(1)) < n:
                out[int(m.group(1))] = f
        return out

    def done(self) -> set[int]:
        """The numbers of the blocks kept whole (regular files named as a block of the plan)."""
        if self.dir is None:
            return set(self.memory)
        return {k for k, f in self._kept().items() if f.is_file()}

    def check(self) -> None:
        """Read every kept block whole: a damaged one is removed, with a warning.

        A block that is damaged, or not the block its name says (another block's copy,
        another file), is removed and computed again.
        """
        if self.dir is None:
            return
        bl = blocks(self.plan.shape, self.plan.chunk_points)
        bad: list[str] = []
        for k, f in sorted(self._kept().items()):
            if not _whole(f, k, tuple(s.stop - s.start for s in bl[k])):
                bad.append(f.name)
                if f.is_dir() and not f.is_symlink():
                    shutil.rmtree(f, ignore_errors=True)
                else:
                    f.unlink(missing_ok=True)
        if bad:
            more = f" and {len(bad) - 3} more" if len(bad) > 3 else ""
            warnings.warn(
                f"{str(self.dir)!r}: {len(bad)} kept blocks were damaged or not the block their "
                f"name says ({', '.join(bad[:3])}{more}): they are computed again",
                UserWarning,
                stacklevel=4,
            )

    def put(self, block: Block) -> None:
        """Keep a finished block (atomically: whole or not at all)."""
        if self.dir is None:
            self.memory[block.index] = block
            return
        meta: dict[str, Any] = {"units": block.units, "parameters": block.parameters}
        meta["warnings"] = block.warnings
        meta["at"] = block.at
        meta["index"] = block.index
        meta["shapes"] = {k: v.shape for k, v in block.data.items()}
        meta["kinds"] = {k: _kind(v) for k, v in block.data.items()}
        arrays = _encode(block)
        arrays[_META] = np.array(json.dumps(meta))
        # not flushed to the disk (fsync: a second of a 1e7-point sweep): a block torn by a
        # power failure fails the check of every member's CRC on resume (_whole) and is
        # computed again
        with atomic_file(
            self.dir / f"block-{block.index:06d}.npz", name="a block of the sweep", durable=False
        ) as f:
            np.savez(f, **arrays)  # type: ignore[arg-type]

    def meta(self, index: int) -> dict[str, Any]:
        """The units, parameters, warnings, shapes and kinds of a kept block."""
        if self.dir is None:
            b = self.memory[index]
            return {
                "units": b.units,
                "parameters": b.parameters,
                "warnings": b.warnings,
                "at": b.at,
                "shapes": {k: v.shape for k, v in b.data.items()},
                "kinds": {k: _kind(v) for k, v in b.data.items()},
            }
        with np.load(self.dir / f"block-{index:06d}.npz") as z:
            return json.loads(str(z[_META]))

    def load(self, index: int, name: str) -> np.ndarray | None:
        """One variable of a kept block (None: the block has no such record)."""
        if self.dir is None:
            return self.memory[index].data.get(name)
        with np.load(self.dir / f"block-{index:06d}.npz") as z:
            if name not in z.files and f"{name}.codes" not in z.files:
                return None
            return _decode(z, name)

    def coded(self, index: int, name: str) -> tuple[list[str], np.ndarray] | None:
        """A text variable of a block kept on disk as ``(categories, codes)`` (None: none).

        As :meth:`load` gives it, without making its strings: ``categories[codes]``.
        """
        assert self.dir is not None
        with np.load(self.dir / f"block-{index:06d}.npz") as z:
            if f"{name}.codes" not in z.files:
                return None
            return [str(c) for c in z[f"{name}.cats"].tolist()], np.asarray(z[f"{name}.codes"])

    def remove(self) -> None:
        """Forget the kept blocks (once the store is written)."""
        if self.dir is not None:
            shutil.rmtree(self.dir, ignore_errors=True)
        self.memory.clear()


_BLOCK_NAME = re.compile(r"block-(\d{6})\.npz")


def _whole(path: Path, index: int, shape: tuple[int, ...]) -> bool:
    """True where ``path`` is block ``index`` of ``shape``, every array of it readable."""
    if not path.is_file():
        return False
    try:
        with np.load(path, allow_pickle=False) as z:
            meta = json.loads(str(z[_META]))
            if meta.get("index", index) != index:
                return False
            for name in z.files:  # each read whole: a damaged member fails its CRC
                z[name]
            for s in meta["shapes"].values():
                if tuple(s[: len(shape)]) != shape:
                    return False
    except Exception:  # noqa: BLE001 - whatever is wrong with it, it is not a block of ours
        return False
    return True


def _build(ident: Any) -> str:
    """A build of linecontact in words: its version and the start of its code digest."""
    if not isinstance(ident, dict):
        return "a build that did not say which"
    words = f"version {ident.get('version', '?')}, code {str(ident.get('code', '?'))[:12]}"
    return words + f", NumPy {ident.get('numpy', '?')}, SciPy {ident.get('scipy', '?')}"
