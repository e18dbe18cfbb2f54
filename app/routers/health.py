"""Liveness and readiness for load balancers and orchestrators."""

from __future__ import annotations

from typing import Any

from fastapi import APIRouter
from fastapi.responses import JSONResponse
from starlette.concurrency import run_in_threadpool

from app.deps import ServicesDep
from app.errors import error_body
from app.openapi import ErrorBody, Ready

router = APIRouter(tags=["health"])
_READY: dict[int | str, dict[str, Any]] = {
    200: {"model": Ready},
    503: {
        "model": ErrorBody,
        "description": "Not ready: the database does not answer, grading is restarting, or still compiling.",
    },
}


@router.get("/health")
async def health() -> dict[str, str]:
    """The process is up (it does not look at the database)."""
    return {"status": "ok"}


@router.get("/ready", response_model=None, responses=_READY)
async def ready(services: ServicesDep) -> dict[str, str] | JSONResponse:
    """Ready for traffic: the database answers, grading workers are up and the problems are compiled."""
    if not await run_in_threadpool(services.stores.ping):
        return JSONResponse(
            error_body("not_ready", "The database is not reachable."),
            status_code=503,
            headers={"Retry-After": "5"},
        )
    if not services.pool.ready:
        return JSONResponse(
            error_body("not_ready", "Grading is restarting after a fault."),
            status_code=503,
            headers={"Retry-After": "2"},
        )
    if not services.catalog.warm.is_set():
        progress = services.catalog.deriving
        said = "" if progress is None else f" ({progress[0]} of {progress[1]} derived)"
        return JSONResponse(error_body("not_ready", f"Still compiling the problems{said}."), status_code=503)
    return {"status": "ready"}
