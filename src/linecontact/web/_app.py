"""The ASGI application: pages, the HTTP API, jobs, limits and security headers."""

from __future__ import annotations

import asyncio
import contextlib
import json
import os
import tempfile
import time
import uuid
from pathlib import Path
from typing import Any

from starlette.applications import Starlette
from starlette.requests import Request
from starlette.responses import HTMLResponse, JSONResponse, Response
from starlette.routing import Mount, Route
from starlette.staticfiles import StaticFiles

from .._version import __version__
from ._pages import PAGES, index_html, page_html
from ._params import COMMANDS, ParameterError, argv_of, parameters_of
from ._workers import Outcome, Pool

__all__ = ["create_app"]

STATIC = Path(__file__).parent / "static"

#: Security headers of every response: scripts and styles from this server only.
HEADERS = {
    "Content-Security-Policy": (
        "default-src 'self'; script-src 'self'; style-src 'self'; img-src 'self' data: blob:; "
        "connect-src 'self'; object-src 'none'; base-uri 'none'; frame-ancestors 'none'; "
        "form-action 'self'"
    ),
    "X-Content-Type-Options": "nosniff",
    "X-Frame-Options": "DENY",
    "Referrer-Policy": "no-referrer",
    "Cross-Origin-Opener-Policy": "same-origin",
}


class _Limits:
    """Security headers, and bodies over their limit refused with 413 before they are read."""

    def __init__(self, app: Any, max_body: int, max_upload: int) -> None:
        self.app, self.max_body, self.max_upload = app, max_body, max_upload

    async def __call__(self, scope: Any, receive: Any, send: Any) -> None:
        if scope["type"] != "http":
            await self.app(scope, receive, send)
            return
        headers = dict(scope.get("headers") or [])
        multipart = b"multipart/form-data" in headers.get(b"content-type", b"")
        limit = self.max_upload if multipart else self.max_body
        length = headers.get(b"content-length")
        if length is not None and length.isdigit() and int(length) > limit:
            await _send_json(send, 413, _error("body", f"the request body is over {limit} bytes"))
            return
        seen = 0

        async def limited() -> Any:
            nonlocal seen
            message = await receive()
            if message["type"] == "http.request":
                seen += len(message.get("body", b""))
                if seen > limit:
                    raise _TooLarge(limit)
            return message

        async def secured(message: Any) -> None:
            if message["type"] == "http.response.start":
                message.setdefault("headers", [])
                for k, v in HEADERS.items():
                    message["headers"].append((k.lower().encode(), v.encode()))
            await send(message)

        try:
            await self.app(scope, limited, secured)
        except _TooLarge as exc:
            await _send_json(
                send, 413, _error("body", f"the request body is over {exc.limit} bytes")
            )


class _TooLarge(Exception):
    def __init__(self, limit: int) -> None:
        self.limit = limit


async def _send_json(send: Any, status: int, doc: dict[str, Any]) -> None:
    body = json.dumps(doc).encode()
    headers = [(b"content-type", b"application/json"), (b"content-length", str(len(body)).encode())]
    headers += [(k.lower().encode(), v.encode()) for k, v in HEADERS.items()]
    await send({"type": "http.response.start", "status": status, "headers": headers})
    await send({"type": "http.response.body", "body": body})


def _error(parameter: str | None, message: str) -> dict[str, Any]:
    return {"error": {"parameter": parameter, "message": message}}


def _name(flag: str | None) -> str | None:
    """A flag as the request names it (``--work-of-adhesion`` -> ``work_of_adhesion``)."""
    return None if flag is None else flag.lstrip("-").replace("-", "_")


def _respond(out: Outcome) -> Response:
    if out.status == 200:
        headers = {"X-Linecontact-Seconds": f"{out.seconds:.6f}"}
        if out.warnings:
            headers["X-Linecontact-Warnings"] = json.dumps(out.warnings)
        return Response(out.body + "\n", media_type="application/json", headers=headers)
    return JSONResponse(_error(_name(out.flag), out.message), status_code=out.status)


class _Job:
    def __init__(self, command: str, argv: list[str]) -> None:
        self.id = uuid.uuid4().hex
        self.command, self.argv = command, argv
        self.started = time.monotonic()
        self.outcome: Outcome | None = None
        self.cancelled = False
        self.worker: Any = None
        self.progress: tuple[int, int] | None = None  # (done, total), where the job says
        self.task: asyncio.Task[Any] | None = None

    def state(self) -> dict[str, Any]:
        if self.cancelled:
            state = "cancelled"
        elif self.outcome is None:
            state = "running"
        else:
            state = "done" if self.outcome.status == 200 else "failed"
        doc: dict[str, Any] = {
            "id": self.id,
            "command": self.command,
            "state": state,
            "elapsed_s": round(time.monotonic() - self.started, 3),
        }
        if self.progress is not None:
            doc["progress"] = {"done": self.progress[0], "total": self.progress[1]}
        if self.outcome is not None and not self.cancelled:
            if self.outcome.status == 200:
                doc["result"] = json.loads(self.outcome.body)
            else:
                doc.update(_error(_name(self.outcome.flag), self.outcome.message))
        return doc


def create_app(
    *,
    workers: int = 2,
    time_limit: float = 60.0,
    max_body: int = 64 * 1024,
    max_upload: int = 1024 * 1024,
) -> Any:
    """The web application of ``linecontact serve`` (an ASGI app).

    Parameters
    ----------
    workers : int
        Worker processes computing the requests (>= 2; slow computations use at most all but
        one, so that quick requests always find one).
    time_limit : float
        Seconds a computation may take before it is stopped (504) and its worker replaced.
    max_body, max_upload : int
        The largest request body and uploaded file [bytes] (413 beyond them).
    """
    pool = Pool(workers, time_limit)
    jobs: dict[str, _Job] = {}

    async def params_of(request: Request) -> list[tuple[str, str]]:
        items = list(request.query_params.multi_items())
        if request.method == "POST":
            ctype = request.headers.get("content-type", "")
            if ctype.startswith("application/json"):
                try:
                    doc = await request.json()
                except ValueError:
                    raise ParameterError("body", "the body is not JSON") from None
                if not isinstance(doc, dict):
                    raise ParameterError("body", "the JSON body must be an object of parameters")
                for k, v in doc.items():
                    vals = v if isinstance(v, list) else [v]
                    items += [
                        (k, "true" if x is True else "false" if x is False else str(x))
                        for x in vals
                    ]
            elif ctype.startswith(("application/x-www-form-urlencoded", "multipart/form-data")):
                form = await request.form()
                for k, v in form.multi_items():
                    if isinstance(v, str):
                        items.append((k, v))
        return items

    async def upload(request: Request, tmpdir: str) -> list[str]:
        """``--data FILE`` for an uploaded CSV (a temporary file of the server's)."""
        if not request.headers.get("content-type", "").startswith("multipart/form-data"):
            return []
        form = await request.form()
        f = form.get("data")
        if f is None or isinstance(f, str):
            return []
        data = await f.read()
        path = os.path.join(tmpdir, "data.csv")
        with open(path, "wb") as out:
            out.write(data)
        return ["--data", path]

    async def api(request: Request) -> Response:
        command = request.path_params["command"]
        if command not in COMMANDS:
            return JSONResponse(_error("command", f"no such command {command!r}"), status_code=404)
        with tempfile.TemporaryDirectory(prefix="linecontact-web-") as tmpdir:
            try:
                argv = argv_of(command, await params_of(request))
                argv += await upload(request, tmpdir)
            except ParameterError as exc:
                return JSONResponse(_error(exc.parameter, str(exc)), status_code=422)
            return _respond(await pool.run(command, argv))

    async def start_job(request: Request) -> Response:
        command = request.path_params["command"]
        if command not in COMMANDS:
            return JSONResponse(_error("command", f"no such command {command!r}"), status_code=404)
        try:
            argv = argv_of(command, await params_of(request))
        except ParameterError as exc:
            return JSONResponse(_error(exc.parameter, str(exc)), status_code=422)
        job = _Job(command, argv)
        jobs[job.id] = job

        async def run() -> None:
            job.outcome = await pool.run(command, argv, job=job)

        job.task = asyncio.create_task(run())
        return JSONResponse(job.state(), status_code=202)

    async def job_state(request: Request) -> Response:
        job = jobs.get(request.path_params["id"])
        if job is None:
            return JSONResponse(_error("id", "no such job"), status_code=404)
        if request.method == "DELETE":
            job.cancelled = True
            if job.worker is not None:
                with contextlib.suppress(OSError, ValueError):
                    job.worker.proc.kill()
        return JSONResponse(job.state())

    async def openapi(request: Request) -> Response:
        return JSONResponse(_openapi())

    async def index(request: Request) -> Response:
        return HTMLResponse(index_html())

    async def page(request: Request) -> Response:
        name = request.path_params["page"]
        if name not in PAGES:
            return HTMLResponse(index_html(f"no page {name!r}"), status_code=404)
        return HTMLResponse(page_html(name))

    @contextlib.asynccontextmanager
    async def lifespan(app: Any) -> Any:
        await pool.start()
        try:
            yield
        finally:
            for job in jobs.values():
                if job.task is not None:
                    job.task.cancel()
            await pool.stop()

    app = Starlette(
        routes=[
            Route("/", index),
            Route("/api/v1/openapi.json", openapi),
            Route("/api/v1/jobs/{command}", start_job, methods=["POST"]),
            Route("/api/v1/jobs/id/{id}", job_state, methods=["GET", "DELETE"]),
            Route("/api/v1/{command}", api, methods=["GET", "POST"]),
            Mount("/static", StaticFiles(directory=STATIC), name="static"),
            Route("/{page}", page),
        ],
        lifespan=lifespan,
    )
    return _Limits(app, max_body, max_upload)


def _openapi() -> dict[str, Any]:
    paths: dict[str, Any] = {}
    for command in COMMANDS:
        params = []
        for p in parameters_of(command):
            schema: dict[str, Any] = {
                "number": {"type": "number"},
                "integer": {"type": "integer"},
                "boolean": {"type": "boolean"},
                "string": {"type": "string"},
            }[p["kind"]]
            if p["choices"]:
                schema["enum"] = p["choices"]
            if p["many"]:
                schema = {"type": "array", "items": schema}
            params.append(
                {
                    "name": p["name"],
                    "in": "query",
                    "description": f"{p['help']} (the CLI's {p['flag']})",
                    "schema": schema,
                    "style": "form",
                    "explode": True,
                }
            )
        responses = {
            "200": {"description": f"exactly what `linecontact {command} --json` prints"},
            "422": {"description": "a bad parameter: {error: {parameter, message}}"},
            "413": {"description": "the body or the upload is too large"},
            "504": {"description": "the computation took longer than its time limit"},
        }
        paths[f"/api/v1/{command}"] = {
            "get": {
                "summary": f"linecontact {command}",
                "parameters": params,
                "responses": responses,
            },
            "post": {
                "summary": f"linecontact {command} (parameters as a form, JSON or query)",
                "parameters": params,
                "responses": responses,
            },
        }
    return {
        "openapi": "3.1.0",
        "info": {"title": "linecontact", "version": __version__},
        "paths": paths,
    }
