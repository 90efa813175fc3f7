"""The paper's figures (Figs. 2--14), redrawn from the library's solvers, and our own.

One module per family of figures, each with the parameters it draws and why:
:mod:`linecontact.figures.normal` (Figs. 2--6), :mod:`linecontact.figures.tangential`
(Figs. 7, 13, 14), :mod:`linecontact.figures.sliding` (Figs. 8--12), and beyond the paper
:mod:`linecontact.figures.push` (the pushed fibre, :func:`push_figures`),
:mod:`linecontact.figures.history` (load histories), :mod:`linecontact.figures.fit` (the
fits of ``linecontact fit-adhesion/fit-friction --plot``),
:mod:`linecontact.figures.bent_wire` (a bent wire's fit, ``fit-bent-wire --plot``),
:mod:`linecontact.figures.adhesion_map` (the adhesion map of line contact) and
:mod:`linecontact.figures.sphere` (the adhesive sphere's load curves, adhesion map and COS
alpha; with the pushed fibre's, the histories' and the map, :func:`extra_figures`); the
shared plumbing in
:mod:`linecontact.figures._style`.
matplotlib is imported only when a figure is drawn.
"""

from __future__ import annotations

import os
import pathlib
import sys
import warnings
from collections.abc import Callable, Iterable, Sequence

from . import adhesion_map as _adhesion_map
from . import history as _history
from . import normal as _normal
from . import push as _push
from . import sliding as _sliding
from . import sphere as _sphere
from . import tangential as _tangential
from ._style import (
    DEFAULT_SIZE,
    DPI,
    FORMATS,
    MAX_SIZE,
    MIN_SIZE,
    Job,
    Run,
    _mpl,
    _save,
    check_formats,
    check_size,
)

__all__ = [
    "DEFAULT_SIZE",
    "DPI",
    "FORMATS",
    "MAX_SIZE",
    "MIN_SIZE",
    "extra_figures",
    "paper_figures",
    "push_figures",
]


def _jobs() -> list[Job]:
    """Every figure, in the order of the files returned: figure order, Fig. 2 to Fig. 14.

    The stems begin ``figNN_`` (two digits), so their order is the figures' order.
    """
    return sorted(_normal.jobs() + _tangential.jobs() + _sliding.jobs(), key=lambda j: j.stem)


def paper_figures(
    outdir: str | os.PathLike = "paper-figures",
    *,
    formats: str | Iterable[str] = ("png",),
    size: Sequence[float] = DEFAULT_SIZE,
    progress: Callable[[str], object] | None = None,
    processes: int | None = None,
) -> list[pathlib.Path]:
    """Draw the figures of the paper (Figs. 2--14) into ``outdir``.

    Parameters
    ----------
    outdir : str or os.PathLike
        Output directory, created (with its parents) if missing; existing files of the same
        names are replaced. Files are named ``fig02_load_R100.png`` and so on.
    formats : str or iterable of str, default ("png",)
        File formats, any of ``"png"``, ``"svg"``, ``"pdf"`` (:data:`FORMATS`; a single
        string is one format; case and a leading dot are ignored, repeats dropped). PNG is
        written at 150 dpi (:data:`DPI`); every file carries ``Creator: linecontact
        <version>`` in its metadata and the version in its lower right corner.
    size : (float, float), default (9.6, 5.4)
        Width and height of every figure, inches (:data:`DEFAULT_SIZE`; the two-panel
        Fig. 8 too, so that all print at one size). Each must lie between
        :data:`MIN_SIZE` = (9.5, 5.2) and :data:`MAX_SIZE` = (30, 20): fonts and the
        margins around the axes (legends on the right) are fixed, so a larger figure gives
        the plot more room, and below the smallest size the longest titles and labels no
        longer fit.
    progress : callable, optional
        Called with a short message (a str) before each step, and last with the summary
        ``"wrote N files to DIR"``; nothing is printed otherwise.
    processes : int, optional
        Number of processes that draw: 1 draws everything in this process; 2 (the default
        where ``os.fork`` is safe to use, Linux, and at least two CPUs are available) also
        forks one worker that draws about half of the figures. Each data set is computed
        once, in the process that draws its figures. Larger values are treated as 2.

    Returns
    -------
    list of pathlib.Path
        The files written, figure by figure in figure order (Fig. 2 to Fig. 14, whichever
        process drew them), each in the order of ``formats``.

    Raises
    ------
    ImportError
        If matplotlib is not installed.
    ValueError
        If ``formats`` is empty or names another format, ``size`` is out of range or
        ``processes`` is not a positive integer.
    OSError
        If ``outdir`` cannot be created or a file cannot be written. Each file is written
        under a temporary name in ``outdir`` and renamed when complete: a failure leaves no
        partial file.

    Notes
    -----
    The parameters of each figure and the reasons for them are in the docstrings of
    :mod:`linecontact.figures.normal`, :mod:`~linecontact.figures.tangential` and
    :mod:`~linecontact.figures.sliding`.
    """
    _mpl()
    fmts = check_formats(formats)
    wh = check_size(size)
    nproc = _processes(processes)
    say = progress if progress is not None else (lambda msg: None)
    out = pathlib.Path(outdir)
    out.mkdir(parents=True, exist_ok=True)
    if not out.is_dir():  # pragma: no cover - mkdir raises first on the platforms we know
        raise NotADirectoryError(f"{out} is not a directory")

    jobs = _jobs()
    shares = _share(jobs, nproc)
    if len(shares) > 1:
        done = _draw_in_two(shares, out, fmts, wh, say)
    else:
        done = _draw(shares[0], out, fmts, wh, say)
    written = [p for job in jobs for p in done[job.stem]]
    say(f"wrote {len(written)} files to {out}")
    return written


# --------------------------------------------------------------------------------------------
# drawing, in one process or two


def _draw(
    jobs: Sequence[Job],
    out: pathlib.Path,
    fmts: tuple[str, ...],
    size: tuple[float, float],
    say: Callable[[str], object],
) -> dict[str, list[pathlib.Path]]:
    """Draw and save ``jobs`` in this process; the files of each figure by stem."""
    run = Run(size=size, say=say)
    done = {}
    for job in jobs:
        say(f"drawing {job.stem} ({', '.join(fmts)})")
        fig = job.build(run)
        done[job.stem] = _save(fig, out, job.stem, fmts)
    return done


def _processes(processes: int | None) -> int:
    if processes is None:
        if not sys.platform.startswith("linux"):
            return 1  # fork is unsafe (macOS) or absent (Windows); spawning costs more
        try:
            ncpu = len(os.sched_getaffinity(0))
        except (AttributeError, OSError):  # pragma: no cover
            ncpu = os.cpu_count() or 1
        return 2 if ncpu >= 2 else 1
    if isinstance(processes, bool) or not isinstance(processes, int) or processes < 1:
        raise ValueError(f"processes must be a positive integer, got {processes!r}")
    if processes > 1 and not sys.platform.startswith("linux"):
        return 1
    return min(processes, 2)


def _share(jobs: Sequence[Job], nproc: int) -> list[list[Job]]:
    """Share the groups of figures out between ``nproc`` processes, largest group first.

    Figures of one group stay together (they draw the same data sets); each share keeps
    the order of ``jobs``; the lightest share comes first (it is drawn by this process,
    which also relays the worker's messages).
    """
    if nproc == 1:
        return [list(jobs)]
    groups: dict[str, float] = {}
    for job in jobs:
        groups[job.group] = groups.get(job.group, 0.0) + job.cost
    load = [0.0] * nproc
    where: dict[str, int] = {}
    for group, cost in sorted(groups.items(), key=lambda kv: -kv[1]):
        k = load.index(min(load))
        where[group] = k
        load[k] += cost
    order = sorted(range(nproc), key=lambda k: load[k])
    shares = [[job for job in jobs if where[job.group] == k] for k in order]
    return [s for s in shares if s]


def _draw_in_two(
    shares: list[list[Job]],
    out: pathlib.Path,
    fmts: tuple[str, ...],
    size: tuple[float, float],
    say: Callable[[str], object],
) -> dict[str, list[pathlib.Path]]:
    """Draw ``shares[0]`` here and ``shares[1]`` in a forked worker, at the same time.

    The worker inherits the imported modules (matplotlib included) and sends its progress
    messages and at the end its files (or its exception) through a pipe; its messages are
    relayed between figures drawn here. If this process fails, the worker is still waited
    for, so that neither leaves a partial file behind.
    """
    import multiprocessing

    # build the mathtext grammar (pure Python, ~0.15 s) once, before the fork, rather than
    # in both processes; the font it loads is opened anew by the worker (matplotlib clears
    # its font cache after a fork)
    from matplotlib.mathtext import MathTextParser

    MathTextParser("path").parse("$x$")

    ctx = multiprocessing.get_context("fork")
    recv, send = ctx.Pipe(duplex=False)
    worker = ctx.Process(
        target=_worker, args=(send, shares[1], out, fmts, size), name="linecontact-figures"
    )
    with warnings.catch_warnings():
        # Python >= 3.12 warns that fork() in a process with threads (BLAS pools) may
        # deadlock the child; the worker only runs numpy, matplotlib and file writes
        warnings.filterwarnings("ignore", message=".*fork.*", category=DeprecationWarning)
        worker.start()
    send.close()
    result: dict = {}

    def relay(block: bool) -> None:
        while "done" not in result and (block or recv.poll()):
            try:
                kind, value = recv.recv()
            except EOFError:
                worker.join()
                result["done"] = RuntimeError(
                    "the second process drawing the figures stopped without a result "
                    f"(exit code {worker.exitcode})"
                )
                return
            if kind == "say":
                say(value)
            else:
                result["done"] = value

    try:

        def say_here(msg: str) -> None:
            relay(block=False)
            say(msg)

        done = _draw(shares[0], out, fmts, size, say_here)
        relay(block=True)
    finally:
        worker.join()
        recv.close()
    theirs = result["done"]
    if isinstance(theirs, BaseException):
        raise theirs
    done.update(theirs)
    return done


def _worker(send, jobs, out, fmts, size) -> None:  # pragma: no cover - runs in the child
    """The forked worker: draw ``jobs``, send progress, then the files or the exception."""
    try:
        done = _draw(jobs, out, fmts, size, lambda msg: send.send(("say", msg)))
        send.send(("done", done))
    except BaseException as exc:  # noqa: BLE001 - handed to the parent, which raises it
        try:
            send.send(("done", exc))
        except Exception:  # noqa: BLE001 - an exception that does not pickle
            send.send(("done", RuntimeError(f"{type(exc).__name__}: {exc}")))
    finally:
        send.close()


def push_figures(
    outdir: str | os.PathLike = "figures",
    *,
    formats: str | Iterable[str] = ("png",),
    size: Sequence[float] = DEFAULT_SIZE,
    progress: Callable[[str], object] | None = None,
) -> list[pathlib.Path]:
    """Draw the figures of the pushed fibre (:mod:`linecontact.figures.push`) into ``outdir``.

    The motion maps over the push height and the hysteresis or the friction stress, with
    the boundary ``H*``, and the lateral force against the push's progress. ``formats``,
    ``size``, ``progress``, the errors and the atomic writes are those of
    :func:`paper_figures`; one process draws.

    Returns
    -------
    list of pathlib.Path
        The files written, figure by figure, each in the order of ``formats``.
    """
    return _draw_in_one(_push.jobs, outdir, formats, size, progress)


def extra_figures(
    outdir: str | os.PathLike = "figures",
    *,
    formats: str | Iterable[str] = ("png",),
    size: Sequence[float] = DEFAULT_SIZE,
    progress: Callable[[str], object] | None = None,
) -> list[pathlib.Path]:
    """The figures beyond the paper (``linecontact figures``) into ``outdir``.

    Those of the pushed fibre (:func:`push_figures`), the load histories
    (:mod:`linecontact.figures.history`: loops, loss per cycle, traction and slip after
    reversals), then the adhesion map of line contact
    on its coarse grid (:mod:`linecontact.figures.adhesion_map`, ``adhesion_map.png``; its
    Lennard-Jones curves take most of the time, about 10 s), then the adhesive sphere's
    (:mod:`linecontact.figures.sphere`: Maugis--Dugdale load curves, its adhesion map, the
    COS alpha against the Maugis parameter; ``sphere01_*.png`` to ``sphere03_*.png``, about
    7 s). ``formats``,
    ``size``, ``progress``, the errors and the atomic writes are those of
    :func:`paper_figures`; one process draws.

    Returns
    -------
    list of pathlib.Path
        The files written, figure by figure, each in the order of ``formats``.
    """
    return _draw_in_one(
        lambda: _push.jobs() + _history.jobs() + _adhesion_map.jobs() + _sphere.jobs(),
        outdir,
        formats,
        size,
        progress,
    )


def _draw_in_one(
    make_jobs: Callable[[], list[Job]],
    outdir: str | os.PathLike,
    formats: str | Iterable[str],
    size: Sequence[float],
    progress: Callable[[str], object] | None,
) -> list[pathlib.Path]:
    """Check the options, then draw ``make_jobs()`` in this process into ``outdir``."""
    _mpl()
    fmts = check_formats(formats)
    wh = check_size(size)
    say = progress if progress is not None else (lambda msg: None)
    out = pathlib.Path(outdir)
    out.mkdir(parents=True, exist_ok=True)
    jobs = make_jobs()
    done = _draw(jobs, out, fmts, wh, say)
    written = [p for job in jobs for p in done[job.stem]]
    say(f"wrote {len(written)} files to {out}")
    return written
