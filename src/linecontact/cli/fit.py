"""The subcommands of the inverse problems: ``fit-adhesion`` and ``fit-friction``.

Built from their declarations in :mod:`linecontact.operations.fit`.
"""

from __future__ import annotations

import argparse
from typing import Any

from ..operations.fit import OPERATIONS
from ._build import add_operations
from ._build import run as _run

__all__ = ["register"]


def _cmd(args: argparse.Namespace) -> int:
    """Run ``fit-adhesion`` or ``fit-friction`` (:mod:`linecontact.operations.fit`)."""
    return _run(args)


def register(sub: Any) -> None:
    """Add ``fit-adhesion`` and ``fit-friction`` to the subparsers ``sub``."""
    add_operations(sub, OPERATIONS.values(), _cmd)
