"""Parameter studies: every flag of a subcommand a range, labelled arrays out, in parallel.

``linecontact sweep COMMAND [its flags] -o OUT`` and :func:`sweep` run a subcommand over the
outer product of the values of its swept flags (a flag with several values, or a range
``start:stop:num[:log]``), and return an :class:`xarray.Dataset`: one dimension per swept
flag, named as the flag without dashes, one data variable per record key of the subcommand
(the names and units of its JSON records), ``state`` and ``reason`` for each point, the
provenance block in the attributes. Each point is what ``linecontact COMMAND`` gives for it
(the same code, the same checks); the Dugdale pull-off is computed a block at a time.

The blocks are kept as they finish (``OUT.partial/``); the same command again goes on
where a stopped run ended. ``workers`` > 1 runs them in a pool of local processes,
``scheduler`` on a running ``dask.distributed`` cluster. Needs the extra ``[sweep]``
(xarray, dask[distributed], zarr, netCDF4, tqdm, pandas). docs/sweeps.md.
"""

from __future__ import annotations

import os
from collections.abc import Mapping
from typing import Any

import numpy as np

from ._dataset import open_sweep
from ._engine import run
from ._plan import SWEEPABLE, plan

__all__ = ["SWEEPABLE", "open_sweep", "sweep"]


def _words(flags: Mapping[str, Any]) -> list[str]:
    """Keyword arguments as the subcommand's words (``work_of_adhesion``: its flag)."""
    words: list[str] = []
    for key, value in flags.items():
        flag = "--" + key.replace("_", "-")
        if value is None or value is False:
            continue
        if value is True:
            words.append(flag)
            continue
        if isinstance(value, str):
            words += [flag, value]
            continue
        if np.ma.isMaskedArray(value):
            masked = int(np.ma.count_masked(value))
            if masked:
                raise ValueError(
                    f"{key}: a masked array with {masked} masked values; a sweep computes "
                    f"every value it is given: pass {key}.compressed() to sweep the others"
                )
            value = np.ma.getdata(value)
        vals = np.atleast_1d(np.asarray(value, dtype=object)).ravel().tolist()
        words.append(flag)
        for v in vals:
            words.append(
                v if isinstance(v, str) else repr(float(v)) if isinstance(v, float) else str(v)
            )
    return words


def sweep(
    command: str,
    /,
    *,
    output: str | os.PathLike[str] | None = None,
    workers: int = 1,
    scheduler: str | None = None,
    progress: bool | None = False,
    overwrite: bool = False,
    chunk_points: int | None = None,
    **flags: Any,
) -> Any:
    """Run ``linecontact COMMAND`` over every combination of the values of its flags.

    Parameters
    ----------
    command : str
        The subcommand: one of :data:`SWEEPABLE` (``"pulloff"``, ``"normal"``, ``"push"``,
        ...).
    output : str or path-like, optional
        A store to write (``.zarr`` or ``.nc``); the blocks kept as they finish, so that the
        same call again goes on where a stopped one ended. None: in memory.
    workers : int
        Local processes (1: this process).
    scheduler : str, optional
        The address of a running ``dask.distributed`` scheduler.
    progress : bool or None
        A progress bar on stderr (None: where stderr is a terminal).
    overwrite : bool
        Replace a store (or kept blocks) of another sweep at ``output``.
    chunk_points : int, optional
        The most points of a block (default: 200,000 where a block is one call, else at most
        64).
    **flags
        The subcommand's flags without dashes, ``-`` as ``_`` (``work_of_adhesion=0.3``,
        ``R_over_h=100``): a scalar or a word is fixed; a sequence or array is swept; a string
        ``"start:stop:num"`` or ``"start:stop:num:log"`` is a range; ``True`` is a switch.

    Returns
    -------
    xarray.Dataset
        One dimension per swept flag (in the order given), one variable per record key.

    Raises
    ------
    ValueError
        A flag the subcommand does not have, a bad range, a masked array with masked values,
        a subcommand that cannot be swept, a store of another sweep (or of this sweep by
        another build of linecontact) at ``output``, another process writing ``output``, a
        sweep larger than the memory or the disk it needs.
    ImportError
        The extra ``[sweep]`` is not installed.

    Examples
    --------
    >>> import linecontact as lc
    >>> ds = lc.sweep("pulloff", radius="20e-9:200e-9:4:log", modulus=1.2e11,
    ...               work_of_adhesion=[0.1, 0.3], z0=3e-10)  # doctest: +SKIP
    >>> ds.F_pulloff_N_per_m.sel(work_of_adhesion=0.3)  # doctest: +SKIP
    """
    words = _words(flags)
    argv = ["linecontact", "sweep", command, *words]
    p = plan(command, words, argv, chunk_points)
    return run(
        p, output, workers=workers, scheduler=scheduler, progress=progress, overwrite=overwrite
    )
