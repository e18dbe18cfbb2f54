"""`POST /v1/check`: check one answer against a reference given in the request."""

from __future__ import annotations

from typing import Annotated

from fastapi import APIRouter, Body, Response

from app.deps import CurrentPrincipal, ServicesDep
from app.openapi import AUTHENTICATED, errors
from app.schemas import examples
from app.schemas.check import CheckIn, VerdictPublic

router = APIRouter(tags=["check"], responses=AUTHENTICATED)


@router.post("/v1/check", response_model=VerdictPublic, responses=errors(413, 422))
async def check(
    body: Annotated[CheckIn, Body(openapi_examples=examples.CHECK)],
    services: ServicesDep,
    principal: CurrentPrincipal,
) -> Response:
    verdict = await services.pool.check(body.job(), principal.grading_share)
    # The body as VerdictPublic renders it (the response model documents it), made once per verdict.
    return Response(services.verdict_json(verdict), media_type="application/json")
