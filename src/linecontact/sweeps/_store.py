"""Where a sweep keeps its blocks as they finish, and the labelled store they end in.

A sweep with ``-o OUT`` keeps each finished block in ``OUT.partial/`` as its own ``.npz``
file, written under a temporary name and renamed when whole: a file there is a whole block,
so a run stopped at any moment (Ctrl-C, ``kill -9``) goes on from the blocks it finished.
``OUT.partial/sweep.json`` holds the sweep's key (:meth:`Plan.key`): a store of another
sweep is refused. When every block is there, the dataset is written, block by block, to
``OUT`` (Zarr for ``.zarr``, netCDF for ``.nc``) under a temporary name and renamed, and
``OUT.partial/`` removed.
"""

from __future__ import annotations

import json
import os
import shutil
import tempfile
from pathlib import Path
from typing import Any

import numpy as np

from ._block import TEXT, Block, codes, is_text
from ._plan import Plan

__all__ = ["FORMATS", "Partial", "format_of", "need", "store_key"]

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


def store_key(path: str | os.PathLike[str]) -> str | None:
    """The sweep key of a finished store at ``path`` (None: not a store of a sweep)."""
    import xarray as xr

    try:
        if format_of(path) == "zarr":
            ds = xr.open_zarr(path, consolidated=False)
        else:
            ds = xr.open_dataset(path)
    except Exception:  # noqa: BLE001 - whatever is there, it is not a sweep's store
        return None
    with ds:
        key = ds.attrs.get("sweep_key")
    return key if isinstance(key, str) else None


def _encode(data: dict[str, np.ndarray]) -> dict[str, np.ndarray]:
    """Arrays for ``np.savez``: strings as codes into their categories (no pickles)."""
    out: dict[str, np.ndarray] = {}
    for k, v in data.items():
        if is_text(v.dtype):
            cats, at = codes(v)
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

    def open(self, overwrite: bool) -> None:
        """Start or resume: a directory of another sweep is refused unless ``overwrite``."""
        if self.dir is None:
            return
        key = self.plan.key()
        manifest = self.dir / "sweep.json"
        if self.dir.exists():
            try:
                theirs = json.loads(manifest.read_text()).get("key")
            except (OSError, ValueError):
                theirs = None
            if theirs != key:
                if not overwrite:
                    raise ValueError(
                        f"-o/--output {str(self.output)!r}: {str(self.dir)!r} holds the blocks "
                        "of another sweep (another command, flags or version); give "
                        "--overwrite to replace it"
                    )
                shutil.rmtree(self.dir)
        self.dir.mkdir(exist_ok=True)
        if not manifest.exists():
            info = {"key": key, "command": list(self.plan.argv), "shape": self.plan.shape}
            _atomic_write(manifest, json.dumps(info).encode())

    def done(self) -> set[int]:
        """The numbers of the blocks kept whole."""
        if self.dir is None:
            return set(self.memory)
        out = set()
        for f in self.dir.glob("block-*.npz"):
            try:
                out.add(int(f.stem.split("-")[1]))
            except ValueError:
                continue
        return out

    def put(self, block: Block) -> None:
        """Keep a finished block (atomically: whole or not at all)."""
        if self.dir is None:
            self.memory[block.index] = block
            return
        meta: dict[str, Any] = {"units": block.units, "parameters": block.parameters}
        meta["warnings"] = block.warnings
        meta["shapes"] = {k: v.shape for k, v in block.data.items()}
        meta["kinds"] = {k: _kind(v) for k, v in block.data.items()}
        arrays = _encode(block.data)
        arrays[_META] = np.array(json.dumps(meta))
        fd, tmp = tempfile.mkstemp(prefix=".tmp-", suffix=".npz", dir=self.dir)
        try:
            with os.fdopen(fd, "wb") as f:
                np.savez(f, **arrays)  # type: ignore[arg-type]
                f.flush()
                os.fsync(f.fileno())
            os.replace(tmp, self.dir / f"block-{block.index:06d}.npz")
        except BaseException:
            Path(tmp).unlink(missing_ok=True)
            raise

    def meta(self, index: int) -> dict[str, Any]:
        """The units, parameters, warnings, shapes and kinds of a kept block."""
        if self.dir is None:
            b = self.memory[index]
            return {
                "units": b.units,
                "parameters": b.parameters,
                "warnings": b.warnings,
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

    def remove(self) -> None:
        """Forget the kept blocks (once the store is written)."""
        if self.dir is not None:
            shutil.rmtree(self.dir, ignore_errors=True)
        self.memory.clear()


def _atomic_write(path: Path, data: bytes) -> None:
    fd, tmp = tempfile.mkstemp(prefix=".tmp-", dir=path.parent)
    try:
        with os.fdopen(fd, "wb") as f:
            f.write(data)
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
