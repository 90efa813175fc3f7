"""The subcommand ``materials``: the material presets, their moduli and sources."""

from __future__ import annotations

import argparse
from typing import Any

import numpy as np

from ..output import FORMATS, Table
from ..presets import MATERIALS, Material
from ._options import add_command, add_output_options, command_line, emit

__all__ = ["register"]


def _format(args: argparse.Namespace) -> str:
    """The output format :func:`~linecontact.cli._options.emit` will write."""
    if args.format is not None:
        return str(args.format)
    ext = "" if args.output is None else args.output.rsplit(".", 1)[-1].lower()
    return ext if ext in FORMATS and ext != "table" else "table"


def _cmd_materials(args: argparse.Namespace) -> int:
    if args.names:
        mats = []
        for name in args.names:
            try:
                mats.append(Material.from_name(name))
            except ValueError:
                raise ValueError(
                    f"NAME {name!r} is not a material preset: one of {', '.join(MATERIALS)}"
                ) from None
    else:
        mats = list(MATERIALS.values())
    columns = {
        "name": np.array([m.name for m in mats], dtype=object),
        "E_Pa": np.array([m.E for m in mats], float),
        "nu": np.array([m.nu for m in mats], float),
        "E_low_Pa": np.array([m.E_range[0] for m in mats], float),
        "E_high_Pa": np.array([m.E_range[1] for m in mats], float),
        "description": np.array([m.description for m in mats], dtype=object),
        "source": np.array([m.source for m in mats], dtype=object),
        "confirmed": np.array([m.confirmed for m in mats], bool),
    }
    show: tuple[str, ...] = ("name", "E_Pa", "nu", "E_low_Pa", "E_high_Pa", "confirmed", "source")
    if args.long:
        show = (*show[:-1], "description", "source")
    if _format(args) == "table":  # the readable table: the long texts aligned on the left
        for key in ("description", "source"):
            width = max(len(t) for t in columns[key])
            columns[key] = np.array([t.ljust(width) for t in columns[key]], dtype=object)
    table = Table(
        columns,
        command=command_line(args),
        title="material presets: isotropic-equivalent E and nu for a contact normal to the "
        "surface (E/(1-nu^2) = indentation modulus); confirmed: the value was seen in a "
        "source found by search",
        show=show,
    )
    emit(args, table)
    return 0


def register(sub: Any) -> None:
    """Add ``materials`` to the subparsers ``sub``."""
    p = add_command(
        sub,
        "materials",
        "the material presets (E, nu, range, source) of --cylinder-material",
        "The material presets of --cylinder-material and --substrate-material: Young's "
        "modulus E [Pa], Poisson's ratio nu, the range of reported E and the source "
        "(docs/cli.md; a fibre on cleaved mica or graphite: 'mica', 'HOPG-basal').",
        [
            "linecontact materials",
            "linecontact materials ZnO SiO2 --long",
            "linecontact pulloff --radius 50e-9 --cylinder-material ZnO --substrate-material "
            "SiO2 --work-of-adhesion 0.1 --z0 0.3e-9",
        ],
    )
    p.usage = "%(prog)s [options] [NAME ...]"
    p.add_argument(
        "names",
        nargs="*",
        metavar="NAME",
        help="presets to show, case-insensitive (default: all)",
    )
    p.add_argument(
        "--long",
        action="store_true",
        help="also show the descriptions (values, caveats) in the table format",
    )
    add_output_options(p)
    p.set_defaults(func=_cmd_materials)
