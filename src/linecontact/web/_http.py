"""uvicorn's HTTP/1.1 protocol (h11), with its own refusals as the API's JSON errors.

A request that h11 cannot parse (a request line or headers over its 16 KiB, a malformed
request) never reaches the application: uvicorn answers it 400 in plain text. This protocol
answers it as the application would: ``{"error": {"parameter": null, "message": ...}}`` with
the security headers.
"""

from __future__ import annotations

import json

import h11
from uvicorn.protocols.http.h11_impl import H11Protocol

from ._app import HEADERS

__all__ = ["JSONErrorsH11Protocol"]


class JSONErrorsH11Protocol(H11Protocol):
    """uvicorn's h11 protocol whose 400 for an unparsable request is a JSON error."""

    def send_400_response(self, msg: str) -> None:
        """Answer a request h11 could not parse (then close the connection)."""
        doc = {"error": {"parameter": None, "message": f"a malformed HTTP request ({msg})"}}
        body = json.dumps(doc).encode()
        headers = [
            (b"content-type", b"application/json"),
            (b"content-length", str(len(body)).encode()),
            (b"connection", b"close"),
            *((k.lower().encode(), v.encode()) for k, v in HEADERS.items()),
        ]
        try:
            event = h11.Response(status_code=400, headers=headers, reason=b"Bad Request")
            self.transport.write(self.conn.send(event) or b"")
            self.transport.write(self.conn.send(h11.Data(data=body)) or b"")
            self.transport.write(self.conn.send(h11.EndOfMessage()) or b"")
        except h11.LocalProtocolError:  # h11 cannot answer in this state: uvicorn's own way
            super().send_400_response(msg)
            return
        self.transport.close()
