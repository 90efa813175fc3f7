"""The subcommands of normal contact: ``normal``, ``pulloff`` and ``curve``.

Built from their declarations in :mod:`linecontact.operations.normal`.
"""

from __future__ import annotations

import argparse
from typing import Any

from ..operations.normal import OPERATIONS
from ._build import add_operations
from ._build import run as _run

__all__ = ["register"]


def _cmd(args: argparse.Namespace) -> int:
    """Run ``normal``, ``pulloff`` or ``curve`` (:mod:`linecontact.operations.normal`)."""
    return _run(args)


def register(sub: Any) -> None:
    """Add ``normal``, ``pulloff`` and ``curve`` to the subparsers ``sub``."""
    add_operations(sub, OPERATIONS.values(), _cmd)
