"""The jobs of ``linecontact serve``: a computation's states and the store that keeps them.

Split from :mod:`linecontact.web._app` (the application), which creates the jobs, runs them
on its worker pool and answers ``/api/v1/jobs``; here a job's document (written once when it
ends, the result's JSON text spliced in, never parsed again) and the store's size and age
limits. The error document and the ``warnings`` key of every answer are here too.
"""

from __future__ import annotations

import asyncio
import json
import time
import uuid
from typing import Any

from ._workers import Outcome

#: Finished jobs kept: the last 100, for an hour, their results 128 MiB in all.
MAX_JOBS = 100
JOB_MAX_AGE = 3600.0
MAX_JOB_BYTES = 128 * 1024 * 1024


def _error(parameter: str | None, message: str) -> dict[str, Any]:
    return {"error": {"parameter": parameter, "message": message}}


def _name(flag: str | None) -> str | None:
    """A flag as the request names it (``--work-of-adhesion`` -> ``work_of_adhesion``)."""
    return None if flag is None else flag.lstrip("-").replace("-", "_")


def _with_warnings(body: str, said: list[str]) -> str:
    """The command's JSON text with ``"warnings"`` (the notes the command line prints) added.

    The key goes last, next to ``results``, spliced into the text (a large result is never
    parsed again): the command's own keys and records stay exactly as ``--json`` prints them.
    """
    text = body.rstrip()
    if not text.endswith("}"):  # pragma: no cover - the command's JSON is an object
        return text
    return text[:-1] + ', "warnings": ' + json.dumps(said) + "}"


class _Job:
    """A computation of the jobs API: queued, running, then done, failed or cancelled.

    Once it ends its document is written once (the result's JSON text spliced in, never
    parsed again) and its elapsed time stops.
    """

    def __init__(self, command: str, values: dict[str, Any]) -> None:
        self.id = uuid.uuid4().hex
        self.command, self.values = command, values
        self.created = time.monotonic()
        self.started: float | None = None
        self.ended: float | None = None
        self.cancelled = False
        self.progress: tuple[int, int] | None = None  # (done, total), where the job says
        self.task: asyncio.Task[Any] | None = None
        self._text: bytes | None = None  # the document, once ended

    @property
    def size(self) -> int:
        """Bytes the job keeps (its document once ended)."""
        return len(self._text) if self._text is not None else 0

    def mark_started(self) -> None:
        self.started = time.monotonic()

    def report(self, done: int, total: int) -> None:
        self.progress = (done, total)

    def _doc(self, state: str) -> dict[str, Any]:
        end = time.monotonic() if self.ended is None else self.ended
        doc: dict[str, Any] = {
            "id": self.id,
            "command": self.command,
            "state": state,
            "elapsed_s": round(end - self.created, 3),
        }
        if self.progress is not None:
            doc["progress"] = {"done": self.progress[0], "total": self.progress[1]}
        return doc

    def finish(self, out: Outcome) -> None:
        """Record the outcome (nothing where the job was cancelled first)."""
        if self.ended is not None:
            return
        self.ended = time.monotonic()
        doc = self._doc("done" if out.status == 200 else "failed")
        doc["status"] = out.status
        if out.status != 200:
            doc.update(_error(_name(out.flag), out.message))
            self._text = json.dumps(doc).encode()
            return
        if out.warnings:
            doc["warnings"] = out.warnings
        head = json.dumps(doc)  # the result's text spliced in: never parsed here
        result = _with_warnings(out.body, out.warnings)
        self._text = (head[:-1] + ', "result": ' + result + "}").encode()

    def cancel(self) -> None:
        """Cancel it: a queued job never runs, a running one's worker is ended and replaced."""
        if self.ended is not None:
            return
        self.cancelled = True
        self.ended = time.monotonic()
        doc = self._doc("cancelled")
        doc["status"] = 499
        doc.update(_error(None, "the computation was cancelled (DELETE)"))
        self._text = json.dumps(doc).encode()
        if self.task is not None:
            self.task.cancel()

    def document(self) -> bytes:
        """Its state as JSON: the text written when it ended, or its state now."""
        if self._text is not None:
            return self._text
        return json.dumps(self._doc("queued" if self.started is None else "running")).encode()


class _JobStore:
    """The jobs, within a size and an age limit.

    The oldest finished ones are evicted first; a queued or running one never is.
    """

    def __init__(self, max_jobs: int, max_age: float, max_bytes: int) -> None:
        self.max_jobs, self.max_age, self.max_bytes = max_jobs, max_age, max_bytes
        self._jobs: dict[str, _Job] = {}

    def __iter__(self) -> Any:
        return iter(list(self._jobs.values()))

    def __len__(self) -> int:
        return len(self._jobs)

    def add(self, job: _Job) -> bool:
        """Keep ``job`` (False: the store is full of jobs in progress)."""
        self.prune(room=1)
        if len(self._jobs) + 1 > self.max_jobs:
            return False
        self._jobs[job.id] = job
        return True

    def get(self, job_id: str) -> _Job | None:
        self.prune()
        return self._jobs.get(job_id)

    def prune(self, room: int = 0) -> None:
        """Evict the finished jobs over the age limit, then the oldest over the size limit."""
        now = time.monotonic()
        ended = sorted(
            (j for j in self._jobs.values() if j.ended is not None),
            key=lambda j: j.ended or 0.0,
        )
        count = len(self._jobs) + room
        total = sum(j.size for j in ended)
        for j in ended:
            old = now - (j.ended or now) > self.max_age
            if not (old or count > self.max_jobs or total > self.max_bytes):
                break
            del self._jobs[j.id]
            count -= 1
            total -= j.size
