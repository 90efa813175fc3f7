"""The subcommand ``serve``: the calculator in the browser and the HTTP API."""

from __future__ import annotations

import argparse
import ipaddress
import sys
from typing import Any

from ._options import add_command

__all__ = ["register"]


def _loopback(host: str) -> bool:
    if host == "localhost":
        return True
    try:
        return ipaddress.ip_address(host).is_loopback
    except ValueError:
        return False


def _cmd_serve(args: argparse.Namespace) -> int:
    if not 0 <= args.port <= 65535:
        raise ValueError(f"--port must be in [0, 65535], got {args.port}")
    if args.workers < 2:
        raise ValueError(
            f"--workers must be at least 2 (one kept for quick requests), got {args.workers}"
        )
    if not args.time_limit > 0:
        raise ValueError(f"--time-limit must be > 0 s, got {args.time_limit}")
    try:
        import uvicorn

        from ..web import create_app
    except ImportError as exc:
        raise ImportError(
            f"linecontact serve needs {exc.name}: pip install 'linecontact[web]'"
        ) from None
    if not _loopback(args.host):
        print(
            f"linecontact serve: warning: listening on {args.host}: anyone who can reach this "
            "machine can use the calculator (there is no login); the default is 127.0.0.1",
            file=sys.stderr,
        )
    app = create_app(workers=args.workers, time_limit=args.time_limit)
    shown = f"[{args.host}]" if ":" in args.host else args.host
    print(f"linecontact serve: http://{shown}:{args.port}/ (Ctrl-C stops it)", file=sys.stderr)
    uvicorn.run(app, host=args.host, port=args.port, log_level="warning")
    return 0


def register(sub: Any) -> None:
    """Add ``serve`` to the subparsers ``sub``."""
    sv = add_command(
        sub,
        "serve",
        "a calculator in the browser and an HTTP API (local web server)",
        "Starts a local web application: one page per task (pull-off, contact, load curve, "
        "push, cyclic loss, fit, map, Lennard-Jones), and GET/POST /api/v1/COMMAND returning "
        "what `linecontact COMMAND --json` prints. Needs pip install 'linecontact[web]'.",
        ["linecontact serve", "linecontact serve --port 8080 --workers 4"],
    )
    sv.add_argument(
        "--host", default="127.0.0.1", help="address to listen on (another host: a warning)"
    )
    sv.add_argument("--port", type=int, default=8000, help="port")
    sv.add_argument("--workers", type=int, default=2, help="worker processes, >= 2")
    sv.add_argument(
        "--time-limit", type=float, default=60.0, metavar="S", help="seconds per computation"
    )
    sv.set_defaults(func=_cmd_serve)
