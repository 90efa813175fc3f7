"""The one table of moved names: what was deleted before 1.0, and what replaces it.

Before 1.0 a name is deleted instead of deprecated (issue 32). A deleted name stays in
:data:`MOVED` so that its error names the replacement; a name that the README of the last
release (0.2.0) taught keeps working one more version, with one ``DeprecationWarning`` per
use naming the replacement. Each entry says the version that removes it from this table
(``tests/test_moved.py`` fails once :data:`linecontact.__version__` reaches it).

A package where an old name lived looks it up here from its module-level ``__getattr__``
(:func:`resolve`), and an ``import`` of an old module name is answered by :class:`_Finder`.
"""

from __future__ import annotations

import importlib
import sys
import warnings
from importlib.machinery import ModuleSpec
from typing import Any, NamedTuple


class Moved(NamedTuple):
    """Where an old name went."""

    #: The dotted name that replaces it.
    new: str
    #: The version that takes the entry off the table.
    until: str
    #: True: the old name still gives the new object, with a ``DeprecationWarning``;
    #: False: it is gone, and its error names the new one.
    works: bool


#: Old dotted name -> where it went.
MOVED: dict[str, Moved] = {
    # the README of 0.2.0 taught these (0.2.0's public SI functions): one more version
    "linecontact.cylinder_sliding_initiation": Moved(
        "linecontact.Cylinder.sliding_initiation", "0.4.0", works=True
    ),
    "linecontact.cylinder_steady_rolling": Moved(
        "linecontact.Cylinder.steady_rolling", "0.4.0", works=True
    ),
    # deprecated after 0.2.0, never in a release: deleted
    "linecontact.cylinder_push": Moved("linecontact.Cylinder.push", "1.0.0", works=False),
    "linecontact.cylinder_tangential_history": Moved(
        "linecontact.Cylinder.tangential_history", "1.0.0", works=False
    ),
    "linecontact.cylinder_cyclic_loss": Moved(
        "linecontact.Cylinder.cyclic_loss", "1.0.0", works=False
    ),
    "linecontact.cylinder.cylinder_sliding": Moved(
        "linecontact.Cylinder.sliding", "1.0.0", works=False
    ),
    "linecontact.reference": Moved("linecontact.closed_forms", "1.0.0", works=False),
    # a law is a value of the body, not a prefix of its methods (issue 32): the methods of
    # a Cylinder with adhesion=LennardJones(w, z0)
    **{
        f"linecontact.Cylinder.lennard_jones_{name}": Moved(
            f"linecontact.Cylinder.{name}", "1.0.0", works=False
        )
        for name in ("contact", "pull_off", "load_curve")
    },
}


class MovedNameError(ImportError):
    """A name deleted before 1.0: the message names its replacement.

    An ``ImportError`` (not an ``AttributeError``, which ``from linecontact import name``
    would replace by its own message without the replacement).
    """


def _message(old: str, moved: Moved) -> str:
    if old.startswith("linecontact.Cylinder.lennard_jones_"):
        method = moved.new.rpartition(".")[2]
        return (
            f"{old} was deleted before 1.0: a law is the cylinder's value, use "
            f"cyl.under(linecontact.LennardJones).{method}(...), or the {method} of a Cylinder "
            f"built with adhesion=linecontact.LennardJones(w, z0): use {moved.new}"
        )
    return f"{old} was deleted before 1.0: use {moved.new}"


def _target(dotted: str) -> Any:
    """The object of a dotted name: the longest importable module, then attributes."""
    parts = dotted.split(".")
    for i in range(len(parts), 0, -1):
        try:
            obj = importlib.import_module(".".join(parts[:i]))
        except ImportError:
            continue
        for attr in parts[i:]:
            obj = getattr(obj, attr)
        return obj
    raise ImportError(dotted)  # pragma: no cover - the table names real objects


def resolve(module: str, name: str) -> Any:
    """``module.name`` from the table (a module's ``__getattr__``), else AttributeError."""
    old = f"{module}.{name}"
    moved = MOVED.get(old)
    if moved is None:
        raise AttributeError(f"module {module!r} has no attribute {name!r}")
    if not moved.works:
        raise MovedNameError(_message(old, moved), name=old)
    warnings.warn(
        f"{old} is deprecated and goes in {moved.until}: use {moved.new}",
        DeprecationWarning,
        stacklevel=3,
    )
    return _target(moved.new)


class _Finder:
    """Answers ``import linecontact.reference`` (a deleted module) with its replacement.

    Last on ``sys.meta_path``: asked only for a name that no module has.
    """

    @staticmethod
    def find_spec(fullname: str, path: object = None, target: object = None) -> ModuleSpec | None:
        moved = MOVED.get(fullname)
        if moved is None or moved.works:
            return None
        raise ModuleNotFoundError(_message(fullname, moved), name=fullname)


def install_finder() -> None:
    """Put :class:`_Finder` last on ``sys.meta_path`` (once)."""
    if not any(f is _Finder for f in sys.meta_path):
        sys.meta_path.append(_Finder)
