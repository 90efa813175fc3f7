"""The check of a table's SI contact half-widths: none below 1 fm or above the radius."""

from __future__ import annotations

import numpy as np

from ..cylinder import _ZERO_WIDTH, _warn_widths
from ..output import Table

__all__ = ["check_widths"]


#: The SI contact half-width columns [m] whose values are checked by :func:`check_widths`.
_WIDTHS = {
    "a_m": "the contact half-width",
    "a_at_pulloff_m": "the contact half-width at pull-off",
    "a_rest_m": "the contact half-width at rest",
    "a_slide_m": "the contact half-width while sliding",
}


def check_widths(table: Table) -> None:
    """Warn for SI contact half-widths that are no physical width (below 1 fm, above R).

    A load curve starts from zero width on purpose: its widths are not checked.
    """
    R = table.parameters.get("radius_m")
    if R is None or "branch" in table.columns:
        return
    if table.parameters.get("cross_section", "round") != "round":
        return  # a polygon's contact lies on its facet: a/R says nothing of the strain
    zero = "mechanism" in table.columns and np.any(table.columns["mechanism"] == "zero-width")
    sphere = table.parameters.get("body") == "sphere"
    for name, what in _WIDTHS.items():
        if name in table.columns:
            why = _ZERO_WIDTH if zero and name == "a_at_pulloff_m" else ""
            said = what.replace("half-width", "radius") if sphere else what
            _warn_widths(table.columns[name], R, said, why, body="sphere" if sphere else "cylinder")
