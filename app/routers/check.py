"""`POST /v1/check`: check one answer against a reference given in the request."""

from __future__ import annotations

from typing import Annotated

from fastapi import APIRouter, Body

from app.deps import CurrentPrincipal, ServicesDep
from app.schemas.check import CheckIn, VerdictPublic
from physics.errors import TooLarge
from physics.verdict import Verdict

router = APIRouter(tags=["check"])


@router.post("/v1/check", response_model=VerdictPublic)
async def check(
    body: Annotated[CheckIn, Body()], services: ServicesDep, _: CurrentPrincipal
) -> VerdictPublic:
    limit = services.settings.max_answer_chars
    if len(body.answer) > limit:
        # Refused before any worker sees it: the cheapest hostile answer is the longest.
        return VerdictPublic.of(
            Verdict.invalid(TooLarge(f"The answer is longer than {limit} characters.", limit))
        )
    return VerdictPublic.of(await services.pool.check(body.job()))
