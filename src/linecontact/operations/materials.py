"""The operation ``materials``: the material presets, their moduli and sources."""

from __future__ import annotations

import numpy as np

from ..errors import ParameterError
from ..output import Table
from ..presets import MATERIALS, Material
from ._declare import Inputs, Operation, Parameter

__all__ = ["OPERATIONS"]


def _compute(args: Inputs) -> Table:
    if args.names:
        mats = []
        for name in args.names:
            try:
                mats.append(Material.from_name(name))
            except ValueError:
                raise ParameterError(
                    "names",
                    f"NAME {name!r} is not a material preset: one of {', '.join(MATERIALS)}",
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
    return Table(
        columns,
        command=args.command_line(),
        title="material presets: isotropic-equivalent E and nu for a contact normal to the "
        "surface (E/(1-nu^2) = indentation modulus); confirmed: the value was seen in a "
        "source found by search",
        show=show,
        left=("description", "source"),  # the long texts aligned on the left
    )


OPERATIONS = {
    "materials": Operation(
        name="materials",
        summary="the material presets (E, nu, range, source) of --cylinder-material",
        description="The material presets of --cylinder-material and --substrate-material: "
        "Young's modulus E [Pa], Poisson's ratio nu, the range of reported E and the source "
        "(docs/cli.md; a fibre on cleaved mica or graphite: 'mica', 'HOPG-basal').",
        examples=(
            "linecontact materials",
            "linecontact materials ZnO SiO2 --long",
            "linecontact pulloff --radius 50e-9 --cylinder-material ZnO --substrate-material "
            "SiO2 --work-of-adhesion 0.1 --z0 0.3e-9",
        ),
        parameters=(
            Parameter(
                "names",
                "presets to show, case-insensitive (default: all)",
                kind="text",
                many="several",
                metavar="NAME",
                positional=True,
            ),
            Parameter(
                "long",
                "also show the descriptions (values, caveats) in the table format",
                kind="switch",
                default=False,
            ),
        ),
        compute=_compute,
    )
}
