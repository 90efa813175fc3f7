"""The ASGI application: pages, the HTTP API, jobs, limits and security checks and headers."""

from __future__ import annotations

import asyncio
import contextlib
import ipaddress
import json
import socket
import tempfile
import urllib.parse
from pathlib import Path
from typing import Any

from starlette.applications import Starlette
from starlette.exceptions import HTTPException
from starlette.formparsers import MultiPartException
from starlette.requests import Request
from starlette.responses import HTMLResponse, JSONResponse, Response
from starlette.routing import Mount, Route
from starlette.staticfiles import StaticFiles

from .._version import __version__
from ._jobs import (
    JOB_MAX_AGE,
    MAX_JOB_BYTES,
    MAX_JOBS,
    _error,
    _Job,
    _JobStore,
    _name,
    _with_warnings,
)
from ._pages import PAGES, index_html, page_html
from ._pages import check as check_pages
from ._params import (
    COMMANDS,
    MAX_POINTS,
    ParameterError,
    parameters_of,
    points_of,
    sweep_hint,
    values_of,
)
from ._workers import MAX_RESULT_BYTES, Outcome, Pool, is_slow

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

#: A request over this many points holds only a slow worker (half a second and more).
SLOW_POINTS = 1_000

#: Bytes of an oversized body read and dropped before the 413, so that a client still
#: sending it reads the answer rather than a reset connection.
_DRAIN = 4 * 1024 * 1024

#: Methods that change state: their Origin must be this server's.
_UNSAFE = frozenset({"POST", "PUT", "PATCH", "DELETE"})


class _Hosts:
    """The host names a request may give in its Host header (DNS rebinding fails).

    Loopback names and addresses, and the address the server listens on; on a wildcard
    address (``0.0.0.0``, ``::``) also any IP address and this machine's name, as the server
    is then reached by them (a rebinding attack names a host by a domain of its own).
    """

    def __init__(self, host: str) -> None:
        bound = host.strip().strip("[]").lower().rstrip(".")
        self.wildcard = bound in ("", "0.0.0.0", "::")
        self.names = {"localhost"}
        if self.wildcard:
            self.names.add(socket.gethostname().lower())
        else:
            self.names.add(bound)
        self.bound = host

    def allows(self, name: str) -> bool:
        name = name.rstrip(".")
        if name in self.names:
            return True
        try:
            ip = ipaddress.ip_address(name)
        except ValueError:
            return False
        return ip.is_loopback or self.wildcard


def _split_host(value: str) -> str | None:
    """The host of a Host header, lower case, without its port (None: not a host[:port])."""
    v = value.strip().lower()
    if v.startswith("["):
        end = v.find("]")
        rest = v[end + 1 :] if end > 0 else "x"
        if rest and not (rest.startswith(":") and rest[1:].isdigit()):
            return None
        return v[1:end]
    name, sep, port = v.partition(":")
    if ":" in port or (sep and not port.isdigit()) or not name:
        return None
    return name


def _same_origin(origin: str, scheme: str, host: str) -> bool:
    """Whether the Origin header names this server, as the request's Host header does."""
    defaults = {"http": 80, "https": 443}
    try:
        o = urllib.parse.urlsplit(origin.strip())
        h = urllib.parse.urlsplit(f"{scheme}://{host.strip()}")
        return (
            o.scheme == scheme
            and o.scheme in defaults
            and o.hostname is not None
            and o.hostname == h.hostname
            and (o.port or defaults[o.scheme]) == (h.port or defaults[scheme])
            and o.path in ("", "/")
        )
    except ValueError:  # a port that is no number
        return False


class _Limits:
    """The checks before the application, and the security headers of every response.

    The Host header must name this server (403), a state-changing request's Origin, where
    given, must be this server's (403), and a body over its limit is refused (413), however it
    comes (Content-Length or chunked), before the application reads it: the body is read here,
    within its limit, and handed on.
    """

    def __init__(self, app: Any, max_body: int, max_upload: int, hosts: _Hosts, pool: Pool) -> None:
        self.app, self.max_body, self.max_upload, self.hosts = app, max_body, max_upload, hosts
        self.pool = pool  # the workers (their count of computations started, for tests)

    async def __call__(self, scope: Any, receive: Any, send: Any) -> None:
        if scope["type"] != "http":
            await self.app(scope, receive, send)
            return
        refused = self._refusal(scope)
        if refused is not None:
            await _send_json(send, *refused)
            return
        if scope["method"] in _UNSAFE:
            headers = _headers(scope)
            multipart = b"multipart/form-data" in (headers.get(b"content-type") or [b""])[0]
            limit = self.max_upload if multipart else self.max_body
            got = await _read_body(receive, limit, headers)
            if isinstance(got, tuple):
                await _send_json(send, *got)
                return
            if got is None:  # the client went away
                return
            receive = _replay(got, receive)

        async def secured(message: Any) -> None:
            if message["type"] == "http.response.start":
                message.setdefault("headers", [])
                message["headers"] = list(message["headers"]) + [
                    (k.lower().encode(), v.encode()) for k, v in HEADERS.items()
                ]
            await send(message)

        await self.app(scope, receive, secured)

    def _refusal(self, scope: Any) -> tuple[int, dict[str, Any]] | None:
        headers = _headers(scope)
        hosts = headers.get(b"host", [])
        if len(hosts) != 1:
            return 403, _error("Host", "a request needs exactly one Host header")
        raw = hosts[0].decode("latin-1")
        name = _split_host(raw)
        if name is None or not self.hosts.allows(name):
            return 403, _error(
                "Host",
                f"the Host header {raw!r} does not name this server (a loopback name or "
                f"address, or {self.hosts.bound}): refused, as a DNS rebinding attack would be",
            )
        if scope["method"] not in _UNSAFE:
            return None
        origins = headers.get(b"origin", [])
        if len(origins) > 1:
            return 403, _error("Origin", "a request may have one Origin header")
        if origins:
            origin = origins[0].decode("latin-1")
            if not _same_origin(origin, scope.get("scheme", "http"), raw):
                return 403, _error(
                    "Origin",
                    f"a {scope['method']} from the page of another site ({origin!r}) is refused: "
                    "only this server's pages may change its state",
                )
        site = headers.get(b"sec-fetch-site", [b""])[0].decode("latin-1").lower()
        if site in ("cross-site", "same-site"):
            return 403, _error(
                "Origin",
                f"a {scope['method']} from the page of another site (Sec-Fetch-Site: {site}) "
                "is refused: only this server's pages may change its state",
            )
        return None


def _headers(scope: Any) -> dict[bytes, list[bytes]]:
    out: dict[bytes, list[bytes]] = {}
    for k, v in scope.get("headers") or []:
        out.setdefault(bytes(k).lower(), []).append(bytes(v))
    return out


async def _read_body(
    receive: Any, limit: int, headers: dict[bytes, list[bytes]]
) -> bytes | tuple[int, dict[str, Any]] | None:
    """The body within ``limit`` bytes, a refusal (status, document), or None (disconnected)."""
    lengths = headers.get(b"content-length", [])
    if lengths:
        text = lengths[0].strip()
        if len(lengths) > 1 or not text.isdigit():
            return 400, _error("body", "the Content-Length header is not a number of bytes")
        if int(text) > limit:
            return 413, _error(
                "body", f"the request body is {int(text):,} bytes, over the limit of {limit:,}"
            )
    chunks: list[bytes] = []
    seen = 0
    more = True
    while more:
        message = await receive()
        if message["type"] == "http.disconnect":
            return None
        chunk = message.get("body", b"")
        seen += len(chunk)
        more = bool(message.get("more_body", False))
        if seen > limit:
            dropped = seen
            while more and dropped < limit + _DRAIN:  # read on a little, then answer
                message = await receive()
                if message["type"] == "http.disconnect":
                    return None
                dropped += len(message.get("body", b""))
                more = bool(message.get("more_body", False))
            return 413, _error("body", f"the request body is over the limit of {limit:,} bytes")
        chunks.append(chunk)
    return b"".join(chunks)


def _replay(body: bytes, receive: Any) -> Any:
    sent = False

    async def replayed() -> Any:
        nonlocal sent
        if not sent:
            sent = True
            return {"type": "http.request", "body": body, "more_body": False}
        return await receive()  # the disconnect, in time

    return replayed


async def _send_json(send: Any, status: int, doc: dict[str, Any]) -> None:
    body = json.dumps(doc).encode()
    headers = [(b"content-type", b"application/json"), (b"content-length", str(len(body)).encode())]
    headers += [(k.lower().encode(), v.encode()) for k, v in HEADERS.items()]
    await send({"type": "http.response.start", "status": status, "headers": headers})
    await send({"type": "http.response.body", "body": body})


#: The preference (``Prefer: python``, RFC 7240) of a request that wants the Python lines
#: of the library calls that computed its answer (the pages' "the same elsewhere").
PYTHON_PREFERENCE = "python"


def _prefers_python(request: Request) -> bool:
    words = request.headers.get("prefer", "").replace(";", ",").split(",")
    return any(w.strip().lower() == PYTHON_PREFERENCE for w in words)


def _respond(out: Outcome, python: bool = False) -> Response:
    """The answer; with ``python``, its JSON has the key ``"python"`` too (the lines)."""
    if out.status == 200:
        headers = {"X-Linecontact-Seconds": f"{out.seconds:.6f}", "Vary": "Prefer"}
        if out.warnings:
            headers["X-Linecontact-Warnings"] = json.dumps(out.warnings)
        body = _with_warnings(out.body, out.warnings)
        if python:
            body = body[:-1] + ', "python": ' + json.dumps(out.python) + "}"
            headers["Preference-Applied"] = PYTHON_PREFERENCE
        return Response(body + "\n", media_type="application/json", headers=headers)
    return JSONResponse(_error(_name(out.flag), out.message), status_code=out.status)


def _without_path(out: Outcome, path: str, given: str) -> Outcome:
    """``out`` with the server's temporary ``path`` replaced by the name the user ``given``.

    In the JSON text (where the path is a JSON string, and in the command line), the message
    and the warnings: no answer shows a path of the server's.
    """
    if not path:
        return out
    quoted = json.dumps(path)[1:-1]
    named = json.dumps(given)[1:-1]
    out.body = out.body.replace(quoted, named)
    out.message = out.message.replace(path, given)
    out.warnings = [w.replace(path, given) for w in out.warnings]
    out.python = out.python.replace(path, given)
    return out


class _RequestError(Exception):
    """A request refused before it is computed: its status, parameter and message."""

    def __init__(self, status: int, parameter: str | None, message: str) -> None:
        super().__init__(message)
        self.status, self.parameter, self.message = status, parameter, message

    def response(self) -> Response:
        return JSONResponse(_error(self.parameter, self.message), status_code=self.status)


def create_app(
    *,
    workers: int = 2,
    time_limit: float = 60.0,
    max_body: int = 64 * 1024,
    max_upload: int = 1024 * 1024,
    host: str = "127.0.0.1",
    max_points: int = MAX_POINTS,
    max_result_bytes: int = MAX_RESULT_BYTES,
    max_jobs: int = MAX_JOBS,
    job_max_age: float = JOB_MAX_AGE,
    max_job_bytes: int = MAX_JOB_BYTES,
) -> Any:
    """The web application of ``linecontact serve`` (an ASGI app).

    Parameters
    ----------
    workers : int
        Worker processes computing the requests, from 2 (slow computations use at most all
        but one, so that quick requests always find one) to twice the CPUs (at least 4).
    time_limit : float
        Seconds a computation may take before it is stopped (504) and its worker replaced.
    max_body, max_upload : int
        The largest request body and uploaded file [bytes] (413 beyond them).
    host : str
        The address the server listens on: a request's Host header must name it, or a
        loopback name or address (403 otherwise).
    max_points : int
        The most points one request may ask for (413 beyond it: a larger study is a sweep).
    max_result_bytes : int
        The largest result of a computation [bytes] (413 beyond it, never shipped).
    max_jobs, job_max_age, max_job_bytes : int, float, int
        Jobs kept, seconds a finished job is kept, and bytes of finished jobs' results kept:
        the oldest finished jobs are evicted first (a job in progress never is).

    Returns
    -------
    ASGI application
        Starlette's, behind the Host, Origin and body checks and the security headers.
    """
    wrong = check_pages()  # a page that disagrees with its operation is never served
    if wrong:
        raise RuntimeError(
            "the calculator's pages disagree with the operations: " + "; ".join(wrong)
        )
    for name, value in (
        ("max_body", max_body),
        ("max_upload", max_upload),
        ("max_points", max_points),
        ("max_jobs", max_jobs),
        ("max_job_bytes", max_job_bytes),
    ):
        if not (isinstance(value, int) and value > 0):
            raise ValueError(f"{name} must be an integer > 0, got {value!r}")
    if not (isinstance(job_max_age, int | float) and job_max_age > 0):
        raise ValueError(f"job_max_age must be a number of seconds > 0, got {job_max_age!r}")
    pool = Pool(workers, time_limit, max_result_bytes)
    jobs = _JobStore(max_jobs, float(job_max_age), max_job_bytes)
    limits = {
        "max_points": max_points,
        "max_result_bytes": max_result_bytes,
        "max_body_bytes": max_body,
        "max_upload_bytes": max_upload,
        "time_limit_s": pool.time_limit,
        "max_jobs": max_jobs,
        "job_max_age_s": float(job_max_age),
    }

    async def items_of(request: Request) -> list[tuple[str, str]]:
        """The request's parameters: the query's, then the body's (JSON, form or multipart)."""
        items = list(request.query_params.multi_items())
        if request.method != "POST":
            return items
        body = await request.body()
        mime = request.headers.get("content-type", "").split(";")[0].strip().lower()
        if not body:
            return items
        if mime == "application/json":
            return items + _json_items(body)
        if mime in ("application/x-www-form-urlencoded", "multipart/form-data"):
            try:
                form = await request.form(max_files=1, max_fields=1000)
            except (HTTPException, MultiPartException) as exc:
                detail = getattr(exc, "detail", None) or getattr(exc, "message", "")
                raise _RequestError(400, "body", f"the form is malformed ({detail})") from None
            except (ValueError, UnicodeDecodeError) as exc:
                raise _RequestError(400, "body", f"the form is malformed ({exc})") from None
            return items + [(k, v) for k, v in form.multi_items() if isinstance(v, str)]
        raise _RequestError(
            415,
            "body",
            f"a body of type {mime or 'none'!r} is not read: send application/json, "
            "application/x-www-form-urlencoded or multipart/form-data",
        )

    def checked(command: str, values: dict[str, Any]) -> bool:
        """Refuse a request over its points (413); True where it gets a slow worker."""
        points, parameter = points_of(command, values)
        if points > max_points:
            raise _RequestError(
                413,
                parameter,
                f"this request asks for {points:,} points"
                + (f" ({parameter})" if parameter else "")
                + f", over the limit of {max_points:,} points of one request; "
                + sweep_hint(command),
            )
        return is_slow(command, values) or points > SLOW_POINTS

    async def upload(request: Request, tmpdir: str) -> tuple[list[str], str, str]:
        """``--data FILE`` for an uploaded CSV (a temporary file of the server's).

        Also the file's path and the name the user gave it, which replaces the path in what
        the user reads (a server's path is never shown).
        """
        form = await request.form()
        f = form.get("data")
        if f is None or isinstance(f, str):
            return [], "", ""
        data = await f.read()
        path = Path(tmpdir) / "data.csv"
        path.write_bytes(data)
        given = Path(str(f.filename or "")).name or "the uploaded file"
        return ["--data", str(path)], str(path), given

    async def parsed(request: Request) -> tuple[str, dict[str, Any], bool]:
        command = request.path_params["command"]
        if command not in COMMANDS:
            raise _RequestError(404, "command", f"no such command {command!r}")
        try:
            items = await items_of(request)
            values = values_of(command, items)
        except ParameterError as exc:
            raise _RequestError(422, exc.parameter, str(exc)) from None
        return command, values, checked(command, values)

    async def api(request: Request) -> Response:
        try:
            command, values, slow = await parsed(request)
        except _RequestError as exc:
            return exc.response()
        python = _prefers_python(request)
        if not request.headers.get("content-type", "").startswith("multipart/form-data"):
            return _respond(await pool.run(command, values, slow=slow, python=python), python)
        with tempfile.TemporaryDirectory(prefix="upload-", dir=pool.root) as tmpdir:
            data, path, given = await upload(request, tmpdir)
            request_ = {**values, "data": data[1]} if data else values  # the file's path
            out = await pool.run(command, request_, slow=slow, python=python)
            return _respond(_without_path(out, path, given), python)

    async def start_job(request: Request) -> Response:
        try:
            command, values, slow = await parsed(request)
        except _RequestError as exc:
            return exc.response()
        job = _Job(command, values)
        if not jobs.add(job):
            return JSONResponse(
                _error(
                    None,
                    f"the server holds {max_jobs} jobs in progress, its limit: try again when "
                    "one has ended",
                ),
                status_code=503,
                headers={"Retry-After": "10"},
            )

        async def run() -> None:
            try:
                out = await pool.run(
                    command, values, slow=slow, on_start=job.mark_started, on_progress=job.report
                )
            except asyncio.CancelledError:
                job.cancel()  # cancelled by the server's end (a DELETE cancelled it first)
                raise
            except Exception as exc:  # noqa: BLE001 - never a traceback
                out = Outcome(500, message=f"internal error ({type(exc).__name__}: {exc})")
            job.finish(out)

        job.task = asyncio.create_task(run())
        return Response(job.document(), status_code=202, media_type="application/json")

    async def job_state(request: Request) -> Response:
        job_id = request.path_params["id"]
        job = jobs.get(job_id)
        if job is None:
            return JSONResponse(
                _error(
                    "id",
                    f"no job {job_id!r}: it expired (a finished job is kept "
                    f"{job_max_age:g} s, and only the last {max_jobs}) or never existed",
                ),
                status_code=404,
            )
        if request.method == "DELETE":
            job.cancel()
        return Response(job.document(), media_type="application/json")

    async def openapi(request: Request) -> Response:
        return JSONResponse(_openapi(limits))

    async def index(request: Request) -> Response:
        return HTMLResponse(index_html())

    async def page(request: Request) -> Response:
        name = request.path_params["page"]
        if name not in PAGES:
            return HTMLResponse(index_html(f"no page {name!r}"), status_code=404)
        return HTMLResponse(page_html(name))

    async def http_error(request: Request, exc: Exception) -> Response:
        assert isinstance(exc, HTTPException)
        message = {404: f"no such path {request.url.path!r} (the API: /api/v1/openapi.json)"}
        text = message.get(exc.status_code, str(exc.detail))
        return JSONResponse(
            _error(None, text), status_code=exc.status_code, headers=dict(exc.headers or {})
        )

    async def internal_error(request: Request, exc: Exception) -> Response:
        return JSONResponse(
            _error(None, f"internal error ({type(exc).__name__}); please report it"),
            status_code=500,
        )

    @contextlib.asynccontextmanager
    async def lifespan(app: Any) -> Any:
        await pool.start()
        try:
            yield
        finally:
            tasks = [j.task for j in jobs if j.task is not None and not j.task.done()]
            for task in tasks:
                task.cancel()
            await asyncio.gather(*tasks, return_exceptions=True)
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
        exception_handlers={HTTPException: http_error, Exception: internal_error},
        lifespan=lifespan,
    )
    return _Limits(app, max_body, max_upload, _Hosts(host), pool)


def _json_items(body: bytes) -> list[tuple[str, str]]:
    """The parameters of a JSON object body (400 where it is no JSON, 422 a bad value)."""
    try:
        doc = json.loads(body.decode("utf-8"))
    except UnicodeDecodeError:
        raise _RequestError(400, "body", "the body is not UTF-8 text") from None
    except RecursionError:
        raise _RequestError(400, "body", "the JSON body is nested too deeply") from None
    except ValueError as exc:
        raise _RequestError(400, "body", f"the body is not JSON ({exc})") from None
    if not isinstance(doc, dict):
        raise _RequestError(422, "body", "the JSON body must be an object of parameters")
    items = []
    for k, v in doc.items():
        for x in v if isinstance(v, list) else [v]:
            if isinstance(x, bool):
                items.append((k, "true" if x else "false"))
            elif isinstance(x, int | float | str):
                items.append((k, str(x)))
            else:
                raise _RequestError(
                    422,
                    k,
                    f"{k}: a value is a number, a string or true/false (or a list of them), "
                    f"got {type(x).__name__ if x is not None else 'null'}",
                )
    return items


def _openapi(limits: dict[str, Any]) -> dict[str, Any]:
    paths: dict[str, Any] = {}
    limit_text = (
        f"At most {limits['max_points']:,} points a request (the values of a flag that takes "
        f"several, a range's NUM, a curve's or a map's counts; a larger study is a sweep, "
        f"`linecontact sweep`), a result of at most {limits['max_result_bytes']:,} bytes, a "
        f"body of {limits['max_body_bytes']:,} bytes, an upload of "
        f"{limits['max_upload_bytes']:,} bytes, {limits['time_limit_s']:g} s a computation. "
        "POST and DELETE: the Origin header, where given, must be this server's; every "
        "request's Host header must name this server (a loopback name or its address)."
    )
    error = {"description": "{error: {parameter, message}}"}
    responses = {
        "200": {"description": "exactly what `linecontact COMMAND --json` prints, then "
                "`warnings`: the notes the command line prints on stderr (a list, [] when "
                "none); with the header `Prefer: python`, then `python`: the Python lines "
                "of the library calls that computed it (empty where it was computed on the "
                "nondimensional groups), and the header `Preference-Applied: python`"},
        "400": {"description": "a malformed body (not JSON, not UTF-8, nested too deeply, "
                "a malformed form)"},
        "403": {"description": "a Host header that does not name this server, or the Origin "
                "of another site"},
        "404": {"description": "no such command"},
        "413": {"description": f"a body or upload too large, a request over "
                f"{limits['max_points']:,} points, or a result over "
                f"{limits['max_result_bytes']:,} bytes"},
        "415": {"description": "a body that is not JSON, a form or multipart"},
        "422": {"description": "a bad parameter"},
        "500": {"description": "a solver missed its tolerance, or the worker computing the "
                "request ended unexpectedly (it is replaced)"},
        "504": {"description": "the computation took longer than its time limit"},
    }  # fmt: skip
    responses = {k: {**error, **v} if k != "200" else v for k, v in responses.items()}
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
        params.append(
            {
                "name": "Prefer",
                "in": "header",
                "description": "`python`: the answer carries the Python lines that computed it",
                "schema": {"type": "string", "enum": [PYTHON_PREFERENCE]},
            }
        )
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
    job_doc = (
        "{id, command, state (queued, running, done, failed, cancelled), elapsed_s (stops "
        "when it ends), progress {done, total} where reported; once ended: status (499 when "
        "cancelled), and result (with its warnings) or error}"
    )
    paths["/api/v1/jobs/{command}"] = {
        "post": {
            "summary": "start COMMAND as a job (the parameters as for /api/v1/{command})",
            "responses": {
                "202": {"description": job_doc},
                "503": {"description": f"{limits['max_jobs']} jobs in progress: try later"},
                **{k: v for k, v in responses.items() if k in ("400", "403", "413", "422")},
            },
        }
    }
    paths["/api/v1/jobs/id/{id}"] = {
        "get": {
            "summary": "a job's state",
            "responses": {
                "200": {"description": job_doc},
                "404": {
                    "description": f"no such job: it expired (finished jobs are kept "
                    f"{limits['job_max_age_s']:g} s, the last {limits['max_jobs']}) or "
                    "never existed"
                },
            },
        },
        "delete": {
            "summary": "cancel a job: queued, it never runs; running, its worker is ended",
            "responses": {"200": {"description": job_doc}, "403": responses["403"]},
        },
    }
    return {
        "openapi": "3.1.0",
        "info": {
            "title": "linecontact",
            "version": __version__,
            "description": limit_text,
            "x-limits": limits,
        },
        "paths": paths,
    }
