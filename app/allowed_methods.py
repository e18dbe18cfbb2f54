"""The methods a resource allows, for the `Allow` header of a 405 (RFC 9110 §15.5.6: all of them).

Starlette answers 405 with the methods of the first route whose path matched, and FastAPI makes one
route per method, so `OPTIONS /v1/assignments/1` said `Allow: GET` where GET, PUT and DELETE are served.
The table is the OpenAPI document's paths, read once per application.
"""

from __future__ import annotations

import re
from typing import Any

from fastapi import FastAPI
from starlette.routing import compile_path

_HTTP_METHODS = ("get", "put", "post", "delete", "patch")


def allowed_methods(app: FastAPI, path: str) -> str | None:
    """`Allow`'s value for a path the API serves, or None for a path it does not document."""
    table: list[tuple[re.Pattern[str], str]] | None = getattr(app.state, "allowed_methods", None)
    if table is None:
        table = app.state.allowed_methods = _table(app.openapi())
    return next((methods for pattern, methods in table if pattern.match(path)), None)


def _table(document: dict[str, Any]) -> list[tuple[re.Pattern[str], str]]:
    table = []
    for template, operations in document.get("paths", {}).items():
        methods = [m.upper() for m in _HTTP_METHODS if m in operations]
        if "GET" in methods:
            methods.insert(methods.index("GET") + 1, "HEAD")  # Starlette serves HEAD wherever GET
        pattern, _, _ = compile_path(template)
        table.append((pattern, ", ".join(methods)))
    return table
