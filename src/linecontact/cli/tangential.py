"""The subcommands of tangential loading: ``slide-init`` and ``roll``.

Built from their declarations in :mod:`linecontact.operations.tangential`.
"""

from __future__ import annotations

import argparse
from typing import Any

from ..operations.tangential import OPERATIONS
from ._build import add_operations
from ._build import run as _run

__all__ = ["register"]


def _cmd(args: argparse.Namespace) -> int:
    """Run ``slide-init`` or ``roll`` (:mod:`linecontact.operations.tangential`)."""
    return _run(args)


def register(sub: Any) -> None:
    """Add ``slide-init`` and ``roll`` to the subparsers ``sub``."""
    add_operations(sub, OPERATIONS.values(), _cmd)
