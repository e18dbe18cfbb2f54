"""Everything the LTI routes need, in one object: the app keeps it in `app.state.lti`, and
`get_lti_context` (a FastAPI dependency, overridable) hands it to the routes."""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from datetime import datetime
from typing import Annotated, Any
from urllib.parse import urlsplit

import httpx
from fastapi import Depends, Request

from app.auth import Principal
from app.db.types import utc_now
from app.lti.platform_keys import PlatformKeyCache
from app.settings import Settings
from app.storage import Stores

HTTP_TIMEOUT_SECONDS = 10.0


@dataclass
class LtiContext:
    stores: Stores  # the app's: the LTI code reaches storage only through them
    settings: Settings
    # Outgoing HTTP (platform JWKS); tests pass a loopback transport to a fake LMS.
    transport: httpx.AsyncBaseTransport | None = None
    clock: Callable[[], datetime] = utc_now
    # For the student page: (problem_id, student) -> the API's student view (raise LookupError if
    # unknown), and a student key -> Principal (None if unknown or revoked).
    student_view: Callable[[str, str], Mapping[str, Any]] | None = None
    authenticate_key: Callable[[str], Principal | None] | None = None
    # (problem_id, student) -> the problem's figure as SVG text with that student's values, or None.
    figure: Callable[[str, str], str | None] | None = None
    # Spends one request of a key's rate budget (the API's): None if allowed, else seconds to wait.
    rate_limit: Callable[[Principal], int | None] | None = None
    platform_keys: PlatformKeyCache = field(init=False)

    def __post_init__(self) -> None:
        self.platform_keys = PlatformKeyCache(self.http_client, self.clock)

    def http_client(self) -> httpx.AsyncClient:
        return httpx.AsyncClient(transport=self.transport, timeout=HTTP_TIMEOUT_SECONDS)

    def url(self, path: str) -> str:
        """An absolute URL of ours, from the configured `base_url`."""
        return self.settings.base_url.rstrip("/") + path

    @property
    def origin(self) -> str:
        parts = urlsplit(self.settings.base_url)
        return f"{parts.scheme}://{parts.netloc}"


def get_lti_context(request: Request) -> LtiContext:
    context: LtiContext = request.app.state.lti
    return context


LtiContextDep = Annotated[LtiContext, Depends(get_lti_context)]
