"""The application factory: settings in, a FastAPI app out; nothing is built at import time."""

from __future__ import annotations

import asyncio
import functools
import threading
from collections.abc import AsyncIterator, Callable
from contextlib import asynccontextmanager
from typing import Any

import httpx
from fastapi import FastAPI
from starlette.concurrency import run_in_threadpool
from starlette.types import ASGIApp

from app.authoring import AuthoringPool
from app.catalog import Catalog
from app.check_fast_path import CheckFastPath
from app.deps import budget_wait
from app.errors import install_error_handlers
from app.grading.pool import GradingPool
from app.heap import freeze_long_lived
from app.instructor import courses as instructor_courses
from app.instructor import router as instructor_routes
from app.instructor.sign_in_limit import SignInLimiter
from app.logs import configure_logging
from app.lti import router as lti_routes
from app.lti.context import LtiContext
from app.lti.outbox import OutboxWorker
from app.middleware import RequestContext
from app.openapi import install_docs
from app.ratelimit import preview_limiter, rate_limiters
from app.routers import authoring as authoring_routes
from app.routers import check, courses, health, problems, student_data, submissions
from app.services import Services
from app.settings import Settings, get_settings
from app.startup import Storage, open_storage_when_reachable
from app.web import router as web_routes
from app.web.layout import STATIC_PATH, static_files
from physics.units.registry import spelling_table


def _warm_up(catalog: Catalog) -> None:
    catalog.warm_up()  # ready once every problem is compiled or found stored; then opens the stored ones
    # The unit table a numeric check's spec is read against (a fifth of a CPU-second), built after
    # ready like the opening of stored problems, rather than by the first numeric check.
    spelling_table()
    freeze_long_lived()  # the bank, compiled and opened, stays until the process exits


class Physcheck(FastAPI):
    """FastAPI with two layers outside its own stack: RequestContext (every request's id, body cap and
    log line) and CheckFastPath (the common `POST /v1/check`, which skips the stack inside)."""

    def __init__(self, *, max_body_bytes: int, **kwargs: Any):
        self.max_body_bytes = max_body_bytes
        # FastAPI's own OpenTelemetry bridge asks, on every request, whether a provider was configured
        # (reading the environment each time): none ever is here, and it cost a check 3 % of the
        # server's CPU. Our log (app/logs.py) is the service's record of requests.
        super().__init__(telemetry={"tracing": False, "metrics": False, "logs": False}, **kwargs)

    def build_middleware_stack(self) -> ASGIApp:
        inner = super().build_middleware_stack()
        return RequestContext(CheckFastPath(inner, self), max_bytes=self.max_body_bytes)


def create_app(
    settings: Settings | None = None,
    *,
    pool: GradingPool | None = None,
    lms_transport: httpx.AsyncBaseTransport | None = None,
    open_storage: Callable[[Settings], Storage] = open_storage_when_reachable,
) -> FastAPI:
    """Build the app; a `pool` passed in is shared (tests) and not closed by the app; `lms_transport`
    carries requests to LMSs (tests pass a loopback one to a fake platform); `open_storage` gives the
    stores (tests pass one on the in-memory fakes)."""
    settings = settings or get_settings()
    configure_logging(settings.log_level)

    @asynccontextmanager
    async def lifespan(app: FastAPI) -> AsyncIterator[None]:
        grading = pool or GradingPool(
            workers=settings.check_workers,
            timeout=settings.check_timeout_seconds,
            memory_mb=settings.check_memory_mb,
            max_tasks=settings.worker_max_tasks,
            queue_size=settings.check_queue_size,
            max_answer_chars=settings.max_answer_chars,
            per_owner=settings.student_checks_in_flight,
            log_answers=settings.log_answers,
            lanes=settings.check_lanes,
        )
        # The workers' fork server imports the checker while this process opens storage: side by side.
        try:
            storage, _ = await asyncio.gather(
                run_in_threadpool(open_storage, settings),
                run_in_threadpool(grading.start if pool is None else lambda: None),
            )
        except BaseException:
            if pool is None:
                grading.close()
            raise
        # Started on the first upload: most instances never vet one.
        authoring = AuthoringPool(
            settings.upload_timeout_seconds, settings.check_memory_mb, settings.upload_queue_size
        )
        key_limiter, student_limiter = rate_limiters(
            settings.redis_url,
            settings.rate_limit_per_minute,
            settings.student_rate_limit_per_minute,
            settings.redis_prefix,
        )
        app.state.services = Services(
            settings=settings,
            database=storage.database,
            stores=storage.stores,
            pool=grading,
            keys=storage.keys,
            key_limiter=key_limiter,
            student_limiter=student_limiter,
            catalog=storage.catalog,
            authoring=authoring,
            sign_in_limiter=SignInLimiter.build(
                settings.redis_url, settings.sign_in_attempts_per_minute, settings.redis_prefix
            ),
            preview_limiter=preview_limiter(
                settings.redis_url, settings.preview_rate_limit_per_minute, settings.redis_prefix
            ),
        )
        app.state.lti = LtiContext(
            storage.stores,
            settings,
            transport=lms_transport,
            student_view=storage.catalog.student_view,
            authenticate_key=storage.keys.authenticate,
            figure=storage.catalog.figure,
            rate_limit=functools.partial(budget_wait, app.state.services),
        )
        outbox = OutboxWorker(storage.stores.outbox, storage.stores.tool_keys, lms_transport)
        await outbox.start()
        if settings.warm_up:
            threading.Thread(target=_warm_up, args=(storage.catalog,), name="warm-up", daemon=True).start()
        else:
            storage.catalog.warm.set()
        try:
            yield
        finally:
            await outbox.stop()
            if pool is None:
                grading.close()
            authoring.close()
            storage.close()

    app = Physcheck(
        max_body_bytes=settings.max_body_bytes,
        title="physcheck",
        version="1",
        summary="Checks physics answers: symbolic, numeric with units, against engine-derived references.",
        lifespan=lifespan,
        docs_url=None,
        redoc_url=None,
    )
    install_docs(app)
    install_error_handlers(app)
    app.include_router(health.router)
    app.include_router(check.router)
    app.include_router(problems.router)
    app.include_router(submissions.router)
    app.include_router(student_data.router)
    app.include_router(authoring_routes.router)
    app.include_router(courses.router)
    app.include_router(lti_routes.router)
    app.include_router(web_routes.router)
    app.mount(STATIC_PATH, static_files(), name="static")
    app.include_router(instructor_routes.router)
    app.include_router(instructor_courses.router)
    instructor_routes.install_page_handlers(app)
    return app
