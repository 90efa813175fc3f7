"""The subcommands of tangential load histories: ``cycle`` and ``history``.

Built from their declarations in :mod:`linecontact.operations.history`.
"""

from __future__ import annotations

import argparse
from typing import Any

from ..operations.history import OPERATIONS
from ._build import add_operations
from ._build import run as _run

__all__ = ["register"]


def _cmd(args: argparse.Namespace) -> int:
    """Run ``cycle`` or ``history`` (:mod:`linecontact.operations.history`)."""
    return _run(args)


def register(sub: Any) -> None:
    """Add ``cycle`` and ``history`` to the subparsers ``sub``."""
    add_operations(sub, OPERATIONS.values(), _cmd)
