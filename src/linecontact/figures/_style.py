"""Shared plumbing of the figures: matplotlib on demand, the Agg canvas, styles, saving.

matplotlib is an optional dependency (``pip install 'linecontact[plot]'``), imported only
when a figure is drawn; no pyplot, no window.
"""

from __future__ import annotations

import pathlib

import numpy as np

from .._version import __version__

_MISSING_MPL = "linecontact paper needs matplotlib: pip install 'linecontact[plot]'"
_CITE = "Sari, Adams & Müftü"
_METADATA_FORMATS = ("png", "svg", "pdf")
_DPI = 150


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


def _new_axes(title: str, xlabel: str, ylabel: str):
    """A figure with one axes on the Agg canvas (no pyplot, no window), shared styling."""
    Figure, FigureCanvasAgg, _, _ = _mpl()
    fig = Figure(figsize=(9.6, 5.4))
    FigureCanvasAgg(fig)
    ax = fig.add_subplot()
    ax.set_title(title, fontsize=11)
    ax.set_xlabel(xlabel, fontsize=12)
    ax.set_ylabel(ylabel, fontsize=12)
    ax.grid(True, color="0.88", linewidth=0.6)
    ax.tick_params(labelsize=10)
    return fig, ax


def _colors(n: int) -> list:
    cmap = _mpl()[3]["viridis"]
    return [cmap(x) for x in np.linspace(0.0, 0.85, n)]


def _sigma_colors(sigmas) -> list:
    """Viridis for sigma0 > 0; light grey for sigma0 = 0 so dashed Hertz stays visible on it."""
    pos = _colors(sum(s > 0 for s in sigmas))[::-1]
    return ["0.72" if s == 0 else pos.pop() for s in sigmas]


def _save(fig, outdir: pathlib.Path, stem: str, formats: tuple[str, ...]) -> list[pathlib.Path]:
    """Stamp the version, lay out, save in every format, release the figure."""
    from matplotlib import rc_context

    tag = f"linecontact {__version__}"
    fig.text(0.995, 0.005, tag, ha="right", va="bottom", fontsize=7, color="0.45")
    fig.tight_layout(rect=(0, 0.02, 1, 1))
    paths = []
    # a fixed hash salt and no date make the SVG output reproducible
    with rc_context({"svg.hashsalt": "linecontact"}):
        for fmt in formats:
            path = outdir / f"{stem}.{fmt}"
            meta = None
            if fmt in _METADATA_FORMATS:
                meta = {"Creator": tag}
                if fmt == "svg":
                    meta["Date"] = None
            fig.savefig(path, format=fmt, dpi=_DPI, metadata=meta)
            paths.append(path)
    fig.clear()
    return paths


def _legends(ax, title: str, colors, labels, entries) -> None:
    """Colour key (top) and line-style key (bottom), both outside the axes on the right."""
    Line2D = _mpl()[2]
    key = ax.legend(
        [Line2D([], [], color=c, lw=2.5) for c in colors],
        labels,
        title=title,
        loc="upper left",
        bbox_to_anchor=(1.02, 1.0),
        fontsize=9,
        title_fontsize=10,
        borderaxespad=0.0,
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
