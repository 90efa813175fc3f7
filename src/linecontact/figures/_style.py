"""Shared plumbing of the figures: matplotlib on demand, the Agg canvas, styles, saving.

matplotlib is an optional dependency (``pip install 'linecontact[plot]'``), imported only
when a figure is drawn; no pyplot, no window.

Layout is fixed, not computed: every figure states its margins in inches (:class:`Margins`,
measured once with ``tight_layout`` at the default size and checked by the tests), so a
figure is laid out without the extra text-measuring pass of ``tight_layout``. Every figure
is created at the output resolution (:data:`DPI`), so the text measured while drawing is
measured once.
"""

from __future__ import annotations

import math
import os
import pathlib
from collections.abc import Callable, Hashable
from dataclasses import dataclass, field

import numpy as np

from .._files import atomic_file
from .._version import __version__

_MISSING_MPL = "linecontact paper needs matplotlib: pip install 'linecontact[plot]'"
_CITE = "Sari, Adams & Müftü"

#: File formats that :func:`linecontact.figures.paper_figures` writes.
FORMATS = ("png", "svg", "pdf")
#: Resolution of the PNG files and of the canvas, dots per inch.
DPI = 150
#: Default size of the one-panel figures, inches (width, height).
DEFAULT_SIZE = (9.6, 5.4)
#: Smallest and largest accepted sizes, inches (width, height). Fonts and the margins
#: around the axes are fixed (points, inches): below the smallest size the longest titles
#: (Figs. 9, 10) and axis labels (Figs. 11, 12) no longer fit; larger sizes give the plot
#: more room.
MIN_SIZE = (9.5, 5.2)
MAX_SIZE = (30.0, 20.0)
#: zlib level of the PNG files: 1 is several times faster than 6 and the files are
#: about 6 % larger (the figures are mostly flat colour).
_PNG_COMPRESS_LEVEL = 1


# --------------------------------------------------------------------------------------------
# matplotlib plumbing (imported lazily)


def _mpl():
    """Import the matplotlib pieces used here, or raise the install hint."""
    try:
        from matplotlib import colormaps
        from matplotlib.backends.backend_agg import FigureCanvasAgg
        from matplotlib.figure import Figure
        from matplotlib.lines import Line2D
    except ImportError as err:  # pragma: no cover - exercised only without matplotlib
        raise ImportError(_MISSING_MPL) from err
    return Figure, FigureCanvasAgg, Line2D, colormaps


@dataclass(frozen=True)
class Margins:
    """Space around the axes, inches: left, right (legends), bottom (with the stamp), top."""

    left: float
    right: float
    bottom: float = 0.72
    top: float = 0.353


@dataclass
class Run:
    """One drawing run in one process: the figure size, progress, the data sets computed.

    ``data(key, compute, what)`` computes a data set once per run and process and hands
    the same object to every figure that draws it.
    """

    size: tuple[float, float] = DEFAULT_SIZE
    say: Callable[[str], object] = field(default=lambda msg: None, repr=False)
    _cache: dict = field(default_factory=dict, repr=False)

    def data(self, key: Hashable, compute: Callable[[], object], what: str = ""):
        """The data set ``key``, computed by ``compute()`` on first use (``what`` is said)."""
        if key not in self._cache:
            if what:
                self.say(f"computing {what}")
            self._cache[key] = compute()
        return self._cache[key]


@dataclass(frozen=True)
class Job:
    """One figure: its file stem and builder, and how to share the work between processes.

    Figures of one ``group`` draw the same data sets and are drawn in the same process;
    ``cost`` is the rough time to compute and draw the figure (seconds, PNG, default size,
    measured), by which the groups are shared out.
    """

    stem: str
    build: Callable[[Run], object]
    group: str
    cost: float


_MATHTEXT: dict = {}  # process id -> the mathtext parser shared by the Agg renderers


def _share_mathtext(canvas) -> None:
    """Give the canvas's renderer the one mathtext parser of this process.

    matplotlib caches parsed mathtext per parser and gives every renderer (every figure)
    a parser of its own, so the labels that recur from figure to figure (legend entries,
    axis labels) were parsed again for each; with one parser they are parsed once. The
    parsed text holds the process's FreeType fonts, which a forked process must not use
    (matplotlib opens them anew after a fork), hence one parser per process id.
    """
    renderer = canvas.get_renderer()
    if not hasattr(renderer, "mathtext_parser"):  # pragma: no cover - another matplotlib
        return
    pid = os.getpid()
    if pid not in _MATHTEXT:
        _MATHTEXT.clear()
        _MATHTEXT[pid] = renderer.mathtext_parser
    renderer.mathtext_parser = _MATHTEXT[pid]


def _new_figure(run: Run, margins: Margins, height_scale: float = 1.0):
    """An empty figure on the Agg canvas (no pyplot, no window) with a fixed layout."""
    Figure, FigureCanvasAgg, _, _ = _mpl()
    width, height = run.size[0], run.size[1] * height_scale
    fig = Figure(figsize=(width, height), dpi=DPI)
    _share_mathtext(FigureCanvasAgg(fig))
    fig.subplots_adjust(
        left=margins.left / width,
        right=1 - margins.right / width,
        bottom=margins.bottom / height,
        top=1 - margins.top / height,
    )
    return fig


def _new_axes(run: Run, margins: Margins, title: str, xlabel: str, ylabel: str):
    """A figure with one axes, fixed layout and the shared styling."""
    fig = _new_figure(run, margins)
    ax = fig.add_subplot()
    ax.set_title(title, fontsize=11)
    ax.set_xlabel(xlabel, fontsize=12)
    ax.set_ylabel(ylabel, fontsize=12)
    ax.grid(True, color="0.88", linewidth=0.6)
    ax.tick_params(labelsize=10)
    return fig, ax


def _map_axes(run: Run, margins: Margins, title: str, xlabel: str, ylabel: str, x, y):
    """A map's axes (:func:`_new_axes`), both scales logarithmic, spanning the grid ``x, y``."""
    fig, ax = _new_axes(run, margins, title, xlabel, ylabel)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlim(x[0], x[-1])
    ax.set_ylim(y[0], y[-1])
    return fig, ax


def _pct(v: float) -> str:
    """A fraction in percent, as the maps' titles and legends write it."""
    return f"{100 * v:g} %"


def _colors(n: int) -> list:
    cmap = _mpl()[3]["viridis"]
    return [cmap(x) for x in np.linspace(0.0, 0.85, n)]


def _sigma_colors(sigmas) -> list:
    """Viridis for sigma0 > 0; light grey for sigma0 = 0 so dashed Hertz stays visible on it."""
    pos = _colors(sum(s > 0 for s in sigmas))[::-1]
    return ["0.72" if s == 0 else pos.pop() for s in sigmas]


# --------------------------------------------------------------------------------------------
# checks and saving


def check_formats(formats) -> tuple[str, ...]:
    """``formats`` as a tuple of lower-case names from :data:`FORMATS`, duplicates dropped.

    Raises
    ------
    ValueError
        If ``formats`` is empty or names a format not in :data:`FORMATS`.
    """
    fmts = (formats,) if isinstance(formats, str) else tuple(formats)
    if not fmts:
        raise ValueError(f"formats must name at least one of {', '.join(FORMATS)}; got none")
    out: list[str] = []
    for f in fmts:
        name = f.strip().lower().lstrip(".") if isinstance(f, str) else f
        if name not in FORMATS:
            raise ValueError(f"unknown format {f!r} in formats: choose from {', '.join(FORMATS)}")
        if name not in out:
            out.append(name)
    return tuple(out)


def check_size(size) -> tuple[float, float]:
    """``size`` as a (width, height) pair of floats in inches, within the accepted range.

    Raises
    ------
    ValueError
        If ``size`` is not two finite numbers between :data:`MIN_SIZE` and :data:`MAX_SIZE`.
    """
    try:
        w, h = (float(v) for v in size)
    except (TypeError, ValueError):
        raise ValueError(f"size must be (width, height) in inches, got {size!r}") from None
    (w0, h0), (w1, h1) = MIN_SIZE, MAX_SIZE
    if not (math.isfinite(w) and math.isfinite(h) and w0 <= w <= w1 and h0 <= h <= h1):
        raise ValueError(
            f"size {w:g} x {h:g} in is outside the accepted range: width {w0:g} to {w1:g} in, "
            f"height {h0:g} to {h1:g} in"
        )
    return w, h


def _write_png(fig, fh, tag: str) -> None:
    """Draw ``fig`` and write it as an RGB PNG (the figure is opaque) with its metadata."""
    import matplotlib
    from PIL import Image, PngImagePlugin

    fig.canvas.draw()
    buf = fig.canvas.buffer_rgba()
    img = Image.frombuffer("RGBA", (buf.shape[1], buf.shape[0]), buf, "raw", "RGBA", 0, 1)
    info = PngImagePlugin.PngInfo()
    info.add_text(
        "Software", f"Matplotlib version{matplotlib.__version__}, https://matplotlib.org/"
    )
    info.add_text("Creator", tag)
    img.convert("RGB").save(
        fh, format="png", pnginfo=info, dpi=(DPI, DPI), compress_level=_PNG_COMPRESS_LEVEL
    )


def _save(fig, outdir: pathlib.Path, stem: str, formats: tuple[str, ...]) -> list[pathlib.Path]:
    """Stamp the version, save in every format (each file atomically), release the figure."""
    from matplotlib import rc_context

    tag = f"linecontact {__version__}"
    fig.text(0.995, 0.005, tag, ha="right", va="bottom", fontsize=7, color="0.45")
    paths = []
    # a fixed hash salt and no date make the SVG output reproducible
    with rc_context({"svg.hashsalt": "linecontact"}):
        for fmt in formats:
            path = outdir / f"{stem}.{fmt}"
            with atomic_file(path, name="figure") as fh:
                if fmt == "png":
                    _write_png(fig, fh, tag)
                else:
                    meta: dict[str, str | None] = {"Creator": tag}
                    if fmt == "svg":
                        meta["Date"] = None
                    fig.savefig(fh, format=fmt, dpi=DPI, metadata=meta)
            paths.append(path)
    fig.clear()
    return paths


# --------------------------------------------------------------------------------------------
# shared artists


def _legends(ax, title: str, colors, labels, entries) -> None:
    """Colour key (top) and line-style key (bottom), both outside the axes on the right."""
    Line2D = _mpl()[2]
    key = side_legend(
        ax,
        [Line2D([], [], color=c, lw=2.5) for c in colors],
        labels,
        title,
        fontsize=9,
        title_fontsize=10,
        frameon=None,
    )
    ax.add_artist(key)
    ax.legend(
        [Line2D([], [], **kw) for _, kw in entries],
        [t for t, _ in entries],
        loc="lower left",
        bbox_to_anchor=(1.02, 0.0),
        fontsize=8.5,
        borderaxespad=0.0,
    )


def side_legend(
    ax,
    handles,
    labels,
    title: str,
    *,
    fontsize: float = 8.5,
    title_fontsize: float = 9,
    frameon: bool | None = False,
):
    """A legend outside the axes on the right, from their top (no frame unless ``frameon``).

    ``frameon=None``: the style's frame. Returns the legend.
    """
    return ax.legend(
        handles,
        labels,
        title=title,
        loc="upper left",
        bbox_to_anchor=(1.02, 1.0),
        fontsize=fontsize,
        title_fontsize=title_fontsize,
        frameon=frameon,
        borderaxespad=0.0,
    )


def _sigma_labels(sigmas) -> list[str]:
    return ["0 (Hertz)" if s == 0 else f"{s:g}" for s in sigmas]


_COL_KW = dict(ls="none", marker="s", ms=4.5, mec="k", mew=0.5)
_PO_KW = dict(ls="none", marker="o", ms=10, mfc="none", mew=1.6)
_OPEN_KW = dict(ls="none", marker="o", ms=6, mfc="none", mew=1.3)
_FILLED_KW = dict(ls="none", marker="o", ms=6)


def _branch_lines(ax, x, y, unstable, color, lw: float) -> None:
    """Solid where stable under load control, dotted on the dF/da < 0 part."""
    if unstable.any():
        k = int(np.flatnonzero(unstable)[-1])  # the minimum closes the unstable part
        ax.plot(x[: k + 1], y[: k + 1], color=color, lw=lw, ls=":")
        ax.plot(x[k:], y[k:], color=color, lw=lw)
    else:
        ax.plot(x, y, color=color, lw=lw)
