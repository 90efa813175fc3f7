"""The subcommands ``paper`` (the paper's figures) and ``cite``."""

from __future__ import annotations

import sys

from .._version import __version__

CITATION = f"""linecontact {__version__}: adhesive contact mechanics of a cylinder on a substrate.

If you use it, please cite the paper it implements:
  I. Sari, G. G. Adams, S. Muftu, "Nano-scale effects in the adherence, sliding and rolling
  of a cylinder on a substrate", and the closed forms used (see the README, "References"):
  J. M. Baney, C.-Y. Hui, J. Adhesion Sci. Technol. 11 (1997) 393, doi:10.1163/156856197X00796
  K. L. Johnson, J. A. Greenwood, J. Phys. D 41 (2008) 155315, doi:10.1088/0022-3727/41/15/155315
"""


def _cmd_paper(args) -> int:
    from ..figures import paper_figures

    def progress(msg: str) -> None:
        print(msg, file=sys.stderr)

    try:
        paths = paper_figures(args.outdir, progress=progress)
    except OSError as exc:
        raise ValueError(
            f"cannot write the figures to --outdir {args.outdir!r}: {exc.strerror or exc}"
        ) from None
    print(f"wrote {len(paths)} files to {args.outdir}/:")
    for p in paths:
        print(f"  {p}")
    return 0


def _cmd_cite(args) -> int:
    print(CITATION.rstrip("\n"))
    return 0


def register(sub) -> None:
    """Add ``paper`` and ``cite`` to the subparsers ``sub``."""
    pa = sub.add_parser(
        "paper",
        help="reproduce the paper's figures (PNG and SVG)",
        description="Redraw Figs. 2-14 of the founding paper from the library's solvers, "
        "each overlaid with the closed forms where they exist.",
        epilog="examples:\n  linecontact paper\n  linecontact paper --outdir figs",
    )
    pa.add_argument(
        "--outdir", default="paper-figures", help="directory for the figure files (created)"
    )
    pa.set_defaults(func=_cmd_paper)

    ci = sub.add_parser(
        "cite",
        help="how to cite linecontact and the paper",
        description="The references to cite: the founding paper, the library, the closed forms.",
    )
    ci.set_defaults(func=_cmd_cite)
