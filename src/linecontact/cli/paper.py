"""The subcommands ``paper`` (the paper's figures) and ``cite`` (how to cite)."""

from __future__ import annotations

import gc
import math
import re
import sys
import textwrap
from typing import Any

from .._version import __version__

# --------------------------------------------------------------------------------------------
# citation data: one place for ``cite``, ``cite --bibtex`` and ``--version``

#: The founding paper. Only fields confirmed from a source are filled in: a stored copy of the
#: ASME Digital Collection's abstract page (whose abstract is the paper's) gives the venue,
#: the proceedings of the ASME/STLE International Joint Tribology Conference 2004 (TRIB2004).
#: No stored source confirmed a journal version, pages or a DOI: they are left out rather
#: than guessed (fill them in here and in CITATION.cff together).
PAPER: dict[str, Any] = {
    "authors": (("Sari", "I."), ("Adams", "G. G."), ("Müftü", "S.")),
    "title": "Nano-scale effects in the adherence, sliding and rolling of a cylinder on a "
    "substrate",
    "booktitle": "Proceedings of the ASME/STLE International Joint Tribology Conference (TRIB2004)",
    "publisher": "ASME",
    "journal": None,
    "year": 2004,
    "volume": None,
    "pages": None,
    "doi": None,
    "url": "https://asmedigitalcollection.asme.org/IJTC/proceedings-abstract/TRIB2004/41812/"
    "59/306869",
}

#: The closed forms the library uses besides the paper's own equations.
CLOSED_FORMS = (
    "J. M. Baney, C.-Y. Hui, J. Adhesion Sci. Technol. 11 (1997) 393, doi:10.1163/156856197X00796",
    "K. L. Johnson, J. A. Greenwood, J. Phys. D 41 (2008) 155315, "
    "doi:10.1088/0022-3727/41/15/155315",
)

_LIBRARY_YEAR = 2026
_PAPER_FIELDS = ("pages", "doi")  # not confirmed: said so (a journal version: none found)


def _paper_authors(sep: str = ", ") -> str:
    return sep.join(f"{initials} {surname}" for surname, initials in PAPER["authors"])


def _paper_line() -> str:
    """The paper as one reference: authors, title, then whichever details are known."""
    ref = f'{_paper_authors()}, "{PAPER["title"]}"'
    journal, volume, year, pages = (PAPER[k] for k in ("journal", "volume", "year", "pages"))
    if journal:
        ref += f", {journal}"
        if volume:
            ref += f" {volume}"
    elif PAPER.get("booktitle"):
        ref += f", in: {PAPER['booktitle']}, {PAPER['publisher']}"
    if year:
        ref += f" ({year})"
    if pages and (journal or PAPER.get("booktitle")):  # pages only of a journal or a book
        ref += f" {pages}"
    if PAPER["doi"]:
        ref += f", doi:{PAPER['doi']}"
    elif PAPER.get("url"):
        ref += f", {PAPER['url']}"
    return ref


def _missing_paper_fields() -> list[str]:
    return [k for k in _PAPER_FIELDS if not PAPER[k]]


def citation_text() -> str:
    """What ``linecontact cite`` prints: the paper, the library, the closed forms."""
    lines = [
        f"linecontact {__version__}: adhesive contact mechanics of a cylinder on a substrate.",
        "",
        "If you use it, please cite the paper it implements:",
        f"  {_paper_line()}",
    ]
    missing = _missing_paper_fields()
    if missing:
        lines.append(f"  ({', '.join(missing)}: not confirmed for this release, left out)")
    lines += [
        "and the library:",
        f"  linecontact {__version__}, software ({_LIBRARY_YEAR})",
        "and the closed forms it uses (their sources: docs/derivations.md, section References):",
        *(f"  {ref}" for ref in CLOSED_FORMS),
        "",
        "BibTeX: linecontact cite --bibtex; the same record: CITATION.cff (how to cite: "
        "docs/citing.md)",
    ]
    return "\n".join(lines)


def _bib_escape(text: str) -> str:
    """``text`` for a brace-delimited BibTeX field: LaTeX specials escaped, umlauts kept."""
    out = re.sub(r"([&%$#_])", r"\\\1", text)
    return out.replace("ü", r"{\"u}")


def _bib_entry(kind: str, key: str, fields: list[tuple[str, object]]) -> str:
    """One BibTeX entry; empty fields are left out, a DOI is not escaped (it is a link)."""
    body = ",\n".join(
        f"  {name:<9} = {{{value if name in ('doi', 'url') else _bib_escape(str(value))}}}"
        for name, value in fields
        if value
    )
    return f"@{kind}{{{key},\n{body}\n}}"


def citation_bibtex() -> str:
    """What ``linecontact cite --bibtex`` prints: the paper and the library (@software).

    The paper is an @inproceedings (TRIB2004), or an @article once a journal version is
    confirmed.
    """
    authors = " and ".join(f"{surname}, {initials}" for surname, initials in PAPER["authors"])
    missing = _missing_paper_fields()
    proceedings = not PAPER["journal"] and PAPER.get("booktitle")
    paper = _bib_entry(
        "inproceedings" if proceedings else "article",
        "sari_adams_muftu",
        [
            ("author", authors),
            ("title", f"{{{PAPER['title']}}}"),
            *(
                (k, PAPER[k])
                for k in (
                    ("booktitle", "publisher", "year")
                    if proceedings
                    else ("journal", "year", "volume")
                )
            ),
            ("pages", re.sub(r"(?<!-)-(?!-)", "--", str(PAPER["pages"] or "")) or None),
            ("doi", PAPER["doi"]),
            ("url", None if PAPER["doi"] else PAPER.get("url")),
            ("note", f"{', '.join(missing)} not confirmed" if missing else None),
        ],
    )
    library = _bib_entry(
        "software",
        "linecontact",
        [
            ("author", "{linecontact developers}"),
            ("title", "linecontact: adhesive contact mechanics of a cylinder on a substrate"),
            ("version", __version__),
            ("year", _LIBRARY_YEAR),
            ("license", "MIT"),
            ("note", f"Python package, version {__version__}"),
        ],
    )
    return f"{paper}\n\n{library}"


#: ``linecontact cite`` (kept for ``linecontact --version`` and other importers).
CITATION = citation_text() + "\n"


def _cmd_cite(args) -> int:
    print(citation_bibtex() if args.bibtex else citation_text())
    return 0


# --------------------------------------------------------------------------------------------
# paper


def _formats_arg(text: str) -> tuple[str, ...]:
    """``--image-format`` as a tuple of format names, checked (ValueError names the option)."""
    from ..figures._style import FORMATS

    names = [t.strip().lower().lstrip(".") for t in text.split(",")]
    if not all(names):
        raise ValueError(
            f"--image-format {text!r}: give a comma-separated list of {', '.join(FORMATS)} "
            "without empty entries"
        )
    bad = [n for n in names if n not in FORMATS]
    if bad:
        raise ValueError(
            f"--image-format {text!r}: unknown format {bad[0]!r}; choose from {', '.join(FORMATS)}"
        )
    return tuple(dict.fromkeys(names))


def _size_arg(text: str) -> tuple[float, float]:
    """``--size WxH`` in inches as (width, height), checked (ValueError names the option)."""
    from ..figures._style import MAX_SIZE, MIN_SIZE

    m = re.fullmatch(r"\s*([0-9.eE+-]+)\s*[xX×]\s*([0-9.eE+-]+)\s*", text)
    try:
        w, h = (float(m.group(1)), float(m.group(2))) if m else (math.nan, math.nan)
    except ValueError:
        w = h = math.nan
    if not (math.isfinite(w) and math.isfinite(h)):
        raise ValueError(f"--size {text!r}: give WIDTHxHEIGHT in inches, e.g. 9.6x5.4")
    (w0, h0), (w1, h1) = MIN_SIZE, MAX_SIZE
    if not (w0 <= w <= w1 and h0 <= h <= h1):
        raise ValueError(
            f"--size {text!r}: width must be {w0:g} to {w1:g} in and height {h0:g} to {h1:g} in"
        )
    return w, h


def _cmd_paper(args) -> int:
    # the options are checked before anything is imported, created or drawn
    formats = _formats_arg(args.image_format)
    size = _size_arg(args.size)
    from ..figures import paper_figures
    from ..figures._style import _mpl

    # Run as the command (not main([...]) in a process that goes on): after the imports,
    # freeze the objects so that the garbage collector skips them while drawing (and the
    # forked worker does not copy their pages), and freeze again before the process exits,
    # which spares the interpreter's final collections over some 10^5 objects (~0.15 s).
    exiting = getattr(args, "argv", ()) is None
    if exiting:
        _mpl()
        gc.freeze()

    _draw_and_list(paper_figures, args, formats, size)
    if exiting:
        gc.freeze()
    return 0


def _draw_and_list(draw, args, formats, size) -> None:
    """Run a figure function into ``--outdir`` (progress on stderr) and list the files."""

    def progress(msg: str) -> None:
        # the function's own summary ("wrote N files to DIR") is printed once, below, with
        # the files in figure order
        if not msg.startswith("wrote "):
            print(msg, file=sys.stderr)

    from ._options import write_failure

    try:
        paths = draw(args.outdir, formats=formats, size=size, progress=progress)
    except OSError as exc:  # a file in it (matplotlib names none): the directory
        raise write_failure(f"the figures to --outdir {args.outdir!r}", exc) from None
    print(f"wrote {len(paths)} files to {args.outdir}/:")
    for p in paths:
        print(f"  {p}")


def _cmd_figures(args) -> int:
    formats = _formats_arg(args.image_format)
    size = _size_arg(args.size)
    from ..figures import extra_figures

    _draw_and_list(extra_figures, args, formats, size)
    return 0


def _figure_arguments(parser, outdir: str, size_help: str) -> None:
    """The options ``--outdir`` (default ``outdir``), ``--image-format`` and ``--size``.

    Those of ``paper`` and ``figures``, with ``--format`` the deprecated ``--image-format``.
    """
    from ._options import deprecated_alias

    parser.add_argument(
        "--outdir",
        default=outdir,
        metavar="DIR",
        help="directory to write into, created if missing; files of the same names are "
        "replaced (default: %(default)s)",
    )
    parser.add_argument(
        "--image-format",
        default="png",
        metavar="LIST",
        help="comma-separated file formats, any of png, svg, pdf; PNG at 150 dpi "
        "(default: %(default)s)",
    )
    parser.add_argument("--size", default="9.6x5.4", metavar="WxH", help=size_help)
    deprecated_alias(parser, "--format", "--image-format")


def register(sub) -> None:
    """Add ``paper``, ``figures`` and ``cite`` to the subparsers ``sub``."""
    pa = sub.add_parser(
        "paper",
        help="redraw the paper's Figs. 2-14 (PNG by default)",
        description=textwrap.fill(
            "Redraw Figs. 2-14 of Sari, Adams & Müftü from the library's solvers, one file per "
            "figure and format (fig02_load_R100.png, ...).",
            88,
        ),
        epilog="examples:\n  linecontact paper\n"
        "  linecontact paper --outdir figs --image-format png,svg --size 12x6.75",
    )
    _figure_arguments(
        pa,
        "paper-figures",
        "width x height of every figure in inches, from 9.5x5.2 to 30x20 (fonts stay "
        "the same size; the two-panel Fig. 8 too) (default: %(default)s)",
    )
    pa.set_defaults(func=_cmd_paper)

    fi = sub.add_parser(
        "figures",
        help="draw the figures beyond the paper: the pushed fibre's motion maps and force, "
        "load-history loops and loss, the adhesion map, the sphere's curves, map and alpha",
        description=textwrap.fill(
            "Draw the figures beyond the paper: the pushed fibre's first motion and lateral "
            "force (push01_*.png, ...; docs/push.md), the loops, loss, traction and slip of "
            "tangential load histories (history01_*.png, ...; docs/load-histories.md) and the "
            "adhesion map on a coarse grid (adhesion_map.png; `linecontact map` draws it "
            "finer, with its data) and the sphere's load curves, adhesion map and COS alpha "
            "against lambda (sphere01_*.png, ...; docs/sphere.md); details: docs/cli.md.",
            88,
        ),
        epilog="examples:\n  linecontact figures\n"
        "  linecontact figures --outdir figs --image-format png,pdf",
    )
    _figure_arguments(
        fi,
        "figures",
        "width x height of the figures in inches, from 9.5x5.2 to 30x20 (default: %(default)s)",
    )
    fi.set_defaults(func=_cmd_figures)

    ci = sub.add_parser(
        "cite",
        help="how to cite linecontact and the paper",
        description="Print the founding paper, the library and the closed forms to cite.",
        epilog="examples:\n  linecontact cite\n  linecontact cite --bibtex > linecontact.bib",
    )
    ci.add_argument(
        "--bibtex",
        action="store_true",
        help="print BibTeX entries (@article, @software) instead of text (default: text)",
    )
    ci.set_defaults(func=_cmd_cite)
