"""A sweep's blocks as one labelled dataset (xarray), written to Zarr or netCDF, read back.

One dimension per swept flag (its values the coordinate, in the flag's units), one data
variable per record key of the subcommand (the names and units of its JSON records), and
``state`` and ``reason`` for every point; a subcommand that gives several records per point
(``curve``) adds the dimension ``record``. The attributes hold the provenance block
(``linecontact``, ``command``, ``parameters``, ``units``) as the JSON output has it, and
``sweep_key``; in a file they are JSON text, which :func:`open_sweep` decodes.
"""

from __future__ import annotations

import functools
import json
import os
import shutil
import tempfile
from pathlib import Path
from typing import Any

import numpy as np

from .._fingerprint import code_identity
from .._version import __version__
from ._block import TEXT, codes
from ._plan import Plan, blocks
from ._store import Partial, format_of, need, real_output

__all__ = ["JSON_ATTRS", "build", "open_sweep", "write"]

#: The attributes kept as JSON text in a file.
JSON_ATTRS = (
    "linecontact",
    "command",
    "parameters",
    "units",
    "swept",
    "variables",
    "sweep_code",
)


def _fill(kind: str) -> Any:
    return {"b": False, "f": np.nan}.get(kind, "")


def _layout(p: Plan) -> tuple[list[tuple[slice, ...]], tuple[tuple[int, ...], ...], dict]:
    """The blocks, the chunks of each axis and each block's position among the chunks."""
    bl = blocks(p.shape, p.chunk_points)
    starts = [sorted({b[i].start for b in bl}) for i in range(len(p.shape))]
    chunks = tuple(tuple(np.diff([*s, n]).tolist()) for s, n in zip(starts, p.shape, strict=True))
    where = {tuple(s.index(b[i].start) for i, s in enumerate(starts)): k for k, b in enumerate(bl)}
    return bl, chunks, where


#: The attribute of a text variable in a store: the JSON list of its categories (the
#: variable holds int32 codes into it; :func:`open_sweep` gives the text back).
CATEGORIES = "categories"


def _codes_of(partial: Partial, n: int, name: str) -> tuple[Any, list[str]]:
    """``(load, categories)``: a text variable of the kept blocks as codes into one list.

    ``categories`` holds every block's distinct values (``""`` first: the text of a block
    without the variable, or of a padded record); ``load(k)`` gives block ``k``'s codes
    into it (None: the block has no such variable). No string is made per point: writing
    ten million strings to a store and reading them back from the blocks took 7 s of a
    1e7-point sweep's 18 (issue 36).
    """
    index = {"": 0}
    kept: dict[int, tuple[list[str], np.ndarray | None]] = {}
    for k in range(n):
        got = partial.coded(k, name)
        if got is None:  # numbers in this block (a column that is text elsewhere)
            v = partial.load(k, name)
            if v is None:
                continue
            cats, at = codes(np.asarray(v).astype(str).astype(object))
            kept[k] = [str(c) for c in cats.tolist()], at
        else:
            kept[k] = got[0], None  # the codes read again when written (memory)
        for c in kept[k][0]:
            index.setdefault(c, len(index))

    def load(k: int) -> np.ndarray | None:
        if k not in kept:
            return None
        cats, at = kept[k]
        if at is None:
            got = partial.coded(k, name)
            assert got is not None
            at = got[1]
        return np.array([index[c] for c in cats], dtype=np.int32)[at]

    return load, list(index)


def build(p: Plan, partial: Partial, parameters: dict[str, Any]) -> Any:
    """The dataset of a sweep whose blocks are all kept (lazy where they are on disk)."""
    import xarray as xr

    bl, chunks, where = _layout(p)
    metas = [partial.meta(k) for k in range(len(bl))]
    names: list[str] = []
    kinds: dict[str, str] = {}
    units: dict[str, str] = {}
    records = 1
    nd = len(p.shape)
    for m in metas:
        for name, shape in m["shapes"].items():
            if name not in kinds:
                names.append(name)
            kind = m["kinds"][name]
            old = kinds.get(name, kind)
            kinds[name] = "O" if "O" in (old, kind) else ("f" if "f" in (old, kind) else kind)
            if len(shape) > nd:
                records = max(records, shape[-1])
        for name, u in m["units"].items():
            units.setdefault(name, u)
    for name in ("state", "reason"):  # last, as in the records
        if name in names:
            names.remove(name)
            names.append(name)
    names = [n for n in names if n not in p.dims]  # a record that is a swept input: its axis
    dims = list(p.dims) + (["record"] if records > 1 else [])
    lazy = partial.dir is not None
    data_vars = {}
    for name in names:
        var_attrs = {"units": units[name]} if name in units and kinds[name] in "fb" else {}
        coded = lazy and kinds[name] == "O"
        if coded:  # text for a store: codes into the categories of every block
            load, categories = _codes_of(partial, len(bl), name)
            var_attrs[CATEGORIES] = json.dumps(categories)
            dtype: Any = np.dtype(np.int32)
            fill: Any = 0
        else:  # in memory: Python strings, no copies
            load = functools.partial(partial.load, name=name)
            dtype = {"O": np.dtype(object), "b": np.dtype(bool)}.get(kinds[name], np.dtype(float))
            fill = _fill(kinds[name])

        def piece(
            k: int, name: str = name, dtype: Any = dtype, fill: Any = fill, load: Any = load
        ) -> np.ndarray:
            shape = tuple(s.stop - s.start for s in bl[k])
            v = load(k)
            full = (*shape, records) if records > 1 else shape
            if v is None:
                return np.full(full, fill, dtype=dtype)
            v = np.asarray(v)
            if v.dtype != dtype:
                v = v.astype(str).astype(object) if dtype.kind == "O" else v.astype(dtype)
            if records == 1:
                return v.reshape(shape)
            if v.ndim == len(shape):  # one record per point in this block
                v = (
                    np.repeat(v[..., None], records, axis=-1)
                    if name in ("state", "reason")
                    else (
                        np.concatenate(
                            [v[..., None], np.full((*shape, records - 1), fill, dtype)], -1
                        )
                    )
                )
            if v.shape[-1] < records:
                pad = np.full((*shape, records - v.shape[-1]), fill, dtype=dtype)
                v = np.concatenate([v, pad], axis=-1)
            return v

        if lazy:
            import dask.array as da

            def fn(block_id: tuple[int, ...] | None = None, piece: Any = piece) -> np.ndarray:
                assert block_id is not None
                return piece(where[block_id[: len(p.shape)]])

            allchunks = chunks + (((records,),) if records > 1 else ())
            arr: Any = da.map_blocks(
                fn, chunks=allchunks, dtype=dtype, meta=np.empty((0,) * len(dims), dtype)
            )
        else:
            arr = np.empty((*p.shape, records) if records > 1 else p.shape, dtype=dtype)
            for k, b in enumerate(bl):
                arr[b] = piece(k)
        data_vars[name] = (dims, arr, var_attrs)
    coords = {}
    for a in p.axes:
        vals = np.asarray(a.values, float) if a.unit else np.asarray(a.values, dtype=object)
        coords[a.name] = (
            a.name,
            vals,
            {"units": a.unit, "flag": a.flag} if a.unit else {"flag": a.flag},
        )
    all_units = {a.name: a.unit for a in p.axes if a.unit}
    all_units.update({n: units[n] for n in names if n in units and kinds[n] in "f"})
    attrs: dict[str, Any] = {
        "linecontact": {"version": __version__},
        "command": list(p.argv),
        "parameters": parameters,
        "units": all_units,
        "swept": [a.flag for a in p.axes],
        "variables": names,
        "sweep_key": p.key(),
        "sweep_identity": p.identity(),
        "sweep_code": code_identity(),
    }
    return xr.Dataset(data_vars, coords=coords, attrs=attrs)


def write(ds: Any, output: str | os.PathLike[str], overwrite: bool) -> None:
    """Write ``ds`` to ``output`` (Zarr or netCDF) whole or not at all."""
    import dask

    fmt = format_of(output)
    out = Path(real_output(output))  # a link to a store: the store is replaced, not the link
    enc = ds.chunk(_store_chunks(ds)) if ds.chunks else ds.copy()
    enc.attrs = {k: json.dumps(v) if k in JSON_ATTRS else v for k, v in ds.attrs.items()}
    tmp = Path(tempfile.mkdtemp(prefix=f".{out.name}.tmp-", dir=out.parent))
    target = tmp / out.name
    try:
        threads = min(4, os.cpu_count() or 1)  # a few blocks at a time: bounded memory
        try:
            with dask.config.set(scheduler="threads", num_workers=threads):
                if fmt == "zarr":
                    enc.to_zarr(
                        target,
                        mode="w",
                        consolidated=False,
                        encoding=_zarr_encoding(enc),
                        write_empty_chunks=True,  # (not each chunk compared with its fill)
                    )
                else:
                    enc.to_netcdf(target, engine=_netcdf_engine())
        except OSError as exc:
            if exc.filename is None and exc.errno is not None:
                raise OSError(exc.errno, exc.strerror, str(out)) from exc
            raise
        if out.exists():
            if not overwrite:
                raise ValueError(f"-o/--output {str(out)!r} exists: give --overwrite to replace it")
            if out.is_dir():  # a Zarr store: moved aside, the new one moved in, the old removed
                old = tmp / f"{out.name}.old"
                os.replace(out, old)
        os.replace(target, out)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


def _zarr_encoding(ds: Any) -> dict[str, dict[str, Any]]:
    """Blosc's LZ4 with byte shuffling for every variable of a Zarr store.

    Zarr's default (Zstandard) spent 2.4 s on the 800 MB of a 1e7-point pull-off sweep
    where LZ4 spends 0.9 s, and its store was larger (575 against 537 MB: the numbers of a
    sweep barely compress; shuffling the bytes is what finds the little there is).
    """
    import zarr

    if int(zarr.__version__.split(".")[0]) >= 3:
        from zarr.codecs import BloscCodec

        codec: dict[str, Any] = {
            "compressors": BloscCodec(cname="lz4", clevel=5, shuffle="shuffle")
        }
    else:  # pragma: no cover - zarr 2
        from numcodecs import Blosc

        codec = {"compressor": Blosc(cname="lz4", clevel=5, shuffle=Blosc.SHUFFLE)}
    return {name: dict(codec) for name in ds.data_vars}


#: The most values of one chunk of a store (16 MB of floats): blocks of a few points (a
#: point-by-point sweep) are joined, a block of two million points is cut. (Each chunk
#: costs its own task and file: a 1e7-point sweep wrote in 3.5, 3.1 and 2.8 s with chunks
#: of 0.4, 1 and 2 million values.)
STORE_CHUNK = 2_000_000


def _store_chunks(ds: Any) -> dict[str, int]:
    """Chunks of about :data:`STORE_CHUNK` values: whole inner dimensions, outer ones cut."""
    sizes = list(ds.sizes.items())
    out: dict[str, int] = {}
    inner = 1
    for name, n in reversed(sizes):
        take = max(1, min(n, STORE_CHUNK // inner))
        out[name] = take
        inner *= take
    return out


def _decoded(var: Any) -> Any:
    """A text variable of a store from its codes: lazily where the store is read lazily."""
    attrs = dict(var.attrs)
    cats = np.array(json.loads(attrs.pop(CATEGORIES)), dtype=TEXT)
    data = var.data
    if hasattr(data, "map_blocks"):  # dask
        text = data.map_blocks(lambda c: cats[c], dtype=TEXT, meta=np.empty((0,) * data.ndim, TEXT))
    else:
        text = cats[np.asarray(data)]
    out = var.copy(data=text)
    out.attrs = attrs
    return out


def _netcdf_engine() -> str:
    for engine, module in (("netcdf4", "netCDF4"), ("h5netcdf", "h5netcdf")):
        try:
            __import__(module)
        except ImportError:
            continue
        return engine
    raise ImportError("a netCDF store needs netCDF4: pip install 'linecontact[sweep]'")


def open_sweep(path: str | os.PathLike[str]) -> Any:
    """Open the store of a sweep (``.zarr`` or ``.nc``) as an :class:`xarray.Dataset`.

    The values are read when used (lazily); the attributes ``linecontact``, ``command``,
    ``parameters``, ``units`` and ``swept`` come back as the Python objects the sweep wrote.

    Parameters
    ----------
    path : str or path-like
        The store a sweep wrote (``linecontact sweep ... -o PATH``, or
        :func:`linecontact.sweep` with ``output=PATH``).

    Returns
    -------
    xarray.Dataset
    """
    need()
    import xarray as xr

    p = Path(path)
    if not p.exists():
        partial = Path(f"{path}.partial")
        more = " (its blocks so far are in it: run the sweep again to finish it)"
        raise FileNotFoundError(
            f"no sweep store at {str(path)!r}{more if partial.exists() else ''}"
        )
    if format_of(p) == "zarr":
        ds = xr.open_zarr(p, consolidated=False)
    else:
        ds = xr.open_dataset(p)
    if "sweep_key" not in ds.attrs:
        ds.close()
        raise ValueError(f"{str(path)!r} is not the store of a linecontact sweep")
    attrs = {
        k: json.loads(v) if k in JSON_ATTRS and isinstance(v, str) else v
        for k, v in ds.attrs.items()
    }
    for name in list(ds.data_vars):  # text kept as codes (:func:`build`)
        if CATEGORIES in ds[name].attrs:
            ds[name] = _decoded(ds[name])
    order = [n for n in attrs.get("variables", []) if n in ds.data_vars]
    ds = ds[order + [n for n in ds.data_vars if n not in order]]
    ds.attrs = attrs
    return ds
