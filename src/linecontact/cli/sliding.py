"""The ``slide`` subcommand: steady sliding with different trailing and leading adhesion.

Built from its declaration in :mod:`linecontact.operations.sliding`.
"""

from __future__ import annotations

import argparse
from typing import Any

from ..operations.sliding import OPERATIONS
from ._build import add_operations
from ._build import run as _run

__all__ = ["register"]


def _cmd(args: argparse.Namespace) -> int:
    """Run ``slide`` (:mod:`linecontact.operations.sliding`)."""
    return _run(args)


def register(sub: Any) -> None:
    """Add ``slide`` to the subparsers ``sub``."""
    add_operations(sub, OPERATIONS.values(), _cmd)
