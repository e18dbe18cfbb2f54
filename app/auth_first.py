"""Who is calling is settled before what they sent is read: a body that is not JSON, sent without a
usable key, is 401 (or 429 when the caller's budget is spent), as a well-formed one would be.

FastAPI decodes a JSON body before it solves a route's dependencies, so an unreadable body would
otherwise be answered 422 to anyone, telling a caller without a key what the route accepts. The
error handlers ask here first, for the routes whose dependencies name the caller.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from typing import Any

from fastapi import Request
from fastapi.dependencies.models import Dependant

from app.deps import current_principal
from app.errors import AppError


def _calls(dependant: Dependant) -> Iterator[Callable[..., Any] | None]:
    pending = [dependant]
    while pending:
        found = pending.pop()
        yield found.call
        pending.extend(found.dependencies)


async def caller_refusal(request: Request) -> AppError | None:
    """The refusal the route's own dependencies would give this caller (401, 429), or None."""
    dependant = getattr(request.scope.get("route"), "dependant", None)
    if not isinstance(dependant, Dependant):
        return None
    if current_principal not in set(_calls(dependant)):
        return None
    try:
        await current_principal(request, request.app.state.services)
    except AppError as refusal:
        return refusal
    return None
