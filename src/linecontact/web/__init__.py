"""A calculator in the browser and an HTTP API: ``linecontact serve``.

:func:`create_app` is an ASGI application (Starlette; ``linecontact serve`` runs it with
uvicorn). Pages, one per task, each a form with units to choose and the material presets,
whose results carry their record keys and full-precision values (``data-key``,
``data-value``), with a plot, downloads and the equivalent command and Python lines; every
page's state is its query string. ``GET`` or ``POST /api/v1/<command>`` returns exactly the
JSON of ``linecontact <command> --json`` (bad input: 422 with ``{"error": {"parameter",
"message"}}``); ``/api/v1/openapi.json`` describes it. Computations run in a bounded number of
worker processes with a time limit; a request may ask for at most 10,000 points and get at
most 16 MiB (a larger study is a sweep); bodies and uploads have a size limit; jobs are kept
within a size and an age limit and can be cancelled, queued or running. Every request's Host
header must name this server and a state-changing one's Origin must be its own; every error
is JSON, and every response carries a content security policy that allows this server's
scripts only. Needs the extra ``[web]``.
"""

from __future__ import annotations

from ._app import create_app

__all__ = ["create_app"]
