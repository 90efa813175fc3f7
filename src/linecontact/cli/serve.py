"""The subcommand ``serve``: the calculator in the browser and the HTTP API."""

from __future__ import annotations

import argparse
import ipaddress
import socket
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


def _bind(host: str, port: int) -> socket.socket:
    """A socket listening on ``host:port`` (ValueError, for one ``error:`` line, if it cannot)."""
    family = socket.AF_INET6 if ":" in host else socket.AF_INET
    sock = socket.socket(family, socket.SOCK_STREAM)
    try:
        sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        sock.bind((host, port))
        sock.listen(2048)
    except (OSError, OverflowError) as exc:
        sock.close()
        why = getattr(exc, "strerror", None) or str(exc)
        raise ValueError(f"--host {host} --port {port}: cannot listen there ({why})") from None
    return sock


def _cmd_serve(args: argparse.Namespace) -> int:
    if not 0 <= args.port <= 65535:
        raise ValueError(f"--port must be in [0, 65535], got {args.port}")
    if not 0 < args.time_limit < float("inf"):
        raise ValueError(f"--time-limit must be > 0 s, got {args.time_limit}")
    try:
        import uvicorn

        from ..web import create_app
        from ..web._http import JSONErrorsH11Protocol
        from ..web._workers import max_workers
    except ImportError as exc:
        raise ImportError(
            f"linecontact serve needs {exc.name}: pip install 'linecontact[web]'"
        ) from None
    top = max_workers()
    if not 2 <= args.workers <= top:
        raise ValueError(
            f"--workers must be from 2 (one kept for quick requests) to {top} (twice the CPUs, "
            f"at least 4), got {args.workers}"
        )
    sock = _bind(args.host, args.port)  # before any worker starts, and before the URL
    port = sock.getsockname()[1]  # --port 0: the one the system chose
    if not _loopback(args.host):
        print(
            f"linecontact serve: warning: listening on {args.host}: anyone who can reach this "
            "machine can use the calculator (there is no login); the default is 127.0.0.1",
            file=sys.stderr,
        )
    app = create_app(workers=args.workers, time_limit=args.time_limit, host=args.host)
    shown = f"[{args.host}]" if ":" in args.host else args.host
    url = f"http://{shown}:{port}/"

    class Server(uvicorn.Server):
        """uvicorn's server that says its URL once it answers (workers started, listening)."""

        async def startup(self, sockets: list[socket.socket] | None = None) -> None:
            await super().startup(sockets=sockets)
            if not self.should_exit:
                print(f"linecontact serve: {url} (Ctrl-C stops it)", file=sys.stderr, flush=True)

    config = uvicorn.Config(app, log_level="warning", http=JSONErrorsH11Protocol)
    try:
        Server(config).run(sockets=[sock])
    finally:
        sock.close()
    return 0


def register(sub: Any) -> None:
    """Add ``serve`` to the subparsers ``sub``."""
    sv = add_command(
        sub,
        "serve",
        "a calculator in the browser and an HTTP API (local web server)",
        "Starts a local web application: one page per task (pull-off, contact, load curve, "
        "push, cyclic loss, fit, map, Lennard-Jones), and GET/POST /api/v1/COMMAND returning "
        "what `linecontact COMMAND --json` prints. A request may ask for at most 10,000 points "
        "(a larger study is `linecontact sweep`); requests must name this server in their "
        "Host header, and a POST or DELETE from another site's page is refused (docs/web.md). "
        "Needs pip install 'linecontact[web]'.",
        ["linecontact serve", "linecontact serve --port 8080 --workers 4"],
    )
    sv.add_argument(
        "--host", default="127.0.0.1", help="address to listen on (another host: a warning)"
    )
    sv.add_argument("--port", type=int, default=8000, help="port (0: one the system chooses)")
    sv.add_argument(
        "--workers",
        type=int,
        default=2,
        help="worker processes, from 2 to twice the CPUs (at least 4): the computations are "
        "CPU-bound, more would only share the cores, and each takes 50 to 200 MB",
    )
    sv.add_argument(
        "--time-limit", type=float, default=60.0, metavar="S", help="seconds per computation"
    )
    sv.set_defaults(func=_cmd_serve)
