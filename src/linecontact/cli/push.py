"""The ``push`` subcommand: a fibre pushed sideways, will it stay, roll or slide.

Built from its declaration in :mod:`linecontact.operations.push`.
"""

from __future__ import annotations

import argparse
from typing import Any

from ..operations.push import OPERATIONS
from ._build import add_operations
from ._build import run as _run

__all__ = ["register"]


def _cmd(args: argparse.Namespace) -> int:
    """Run ``push`` (:mod:`linecontact.operations.push`)."""
    return _run(args)


def register(sub: Any) -> None:
    """Add ``push`` to the subparsers ``sub``."""
    add_operations(sub, OPERATIONS.values(), _cmd)
