"""The catalogue of operations: every computation the shells offer, declared once.

An operation (:class:`Operation`) names its parameters (:class:`Parameter`: name, unit, kind,
one or several values, choices, default, a line of help) and the function that computes its
records from typed values. The command line builds its subcommands from these declarations;
the HTTP API and the sweeps call :func:`call` with typed values: no shell parses another
shell's text.

>>> from linecontact import operations
>>> table = operations.call("pulloff", {"R_over_h": 100, "sigma0_over_E": 0.01})
>>> round(float(table.columns["F_pulloff_over_Eh"][0]), 4)
-0.2657
"""

from __future__ import annotations

import importlib
from collections.abc import Iterable, Mapping
from typing import Any

from ..output import Table
from ._declare import Entry, Inputs, Operation, Parameter, command_words
from ._declare import call as _call

__all__ = [
    "FAMILIES",
    "Entry",
    "Inputs",
    "Operation",
    "Parameter",
    "call",
    "catalogue",
    "command_words",
    "get",
]

#: Every operation and the module of this package that declares it (imported when asked for).
FAMILIES: dict[str, str] = {
    "normal": "normal",
    "pulloff": "normal",
    "curve": "normal",
    "slide-init": "tangential",
    "roll": "tangential",
    "cycle": "history",
    "history": "history",
    "fit-adhesion": "fit",
    "fit-friction": "fit",
    "fit-bent-wire": "bent_wire",
    "slide": "sliding",
    "push": "push",
    "map": "adhesion_map",
    "materials": "materials",
}


def get(name: str) -> Operation:
    """The operation ``name`` (ValueError: no such operation)."""
    family = FAMILIES.get(name)
    if family is None:
        raise ValueError(f"no operation {name!r}: one of {', '.join(FAMILIES)}")
    module = importlib.import_module(f"{__name__}.{family}")
    return module.OPERATIONS[name]


def catalogue() -> dict[str, Operation]:
    """Every operation, by name, in the order of :data:`FAMILIES`."""
    return {name: get(name) for name in FAMILIES}


def call(name: str, values: Mapping[str, Any] | Iterable[tuple[str, Any]]) -> Table:
    """Compute the operation ``name`` with ``values`` (keywords or fields, typed or text).

    A key the operation does not declare, or a value of the wrong kind or count, is a
    :class:`~linecontact.errors.ParameterError` that names the key as given.
    """
    return _call(get(name), values)
