"""FastAPI dependencies as `Annotated` aliases: the services, the caller, and role checks."""

from __future__ import annotations

from typing import Annotated

from fastapi import Depends, Path, Request, Security
from starlette.concurrency import run_in_threadpool

from app.auth import Principal, bearer_token
from app.errors import AppError, CourseRequired, Forbidden, NotFound, RateLimited, Unauthenticated
from app.lti.sessions import principal_from_session, unsettled_course
from app.openapi import bearer_scheme
from app.ratelimit import MemoryRateLimiter
from app.services import Services
from app.storage import ProblemStore, SubmissionStore


async def get_services(request: Request) -> Services:
    # async: a plain attribute read, not worth a trip through the thread pool (as every sync dependency)
    services: Services = request.app.state.services
    return services


ServicesDep = Annotated[Services, Depends(get_services)]

# Courses and assignments are numbered by 64-bit integers in both databases. A larger number names no
# record, and SQLite's driver raises OverflowError on it instead of finding nothing.
RECORD_ID_MAX = 2**63 - 1
RecordId = Annotated[int, Path(ge=1, le=RECORD_ID_MAX)]


def get_problem_store(services: ServicesDep) -> ProblemStore:
    return services.stores.problems


def get_submission_store(services: ServicesDep) -> SubmissionStore:
    return services.stores.submissions


Problems = Annotated[ProblemStore, Depends(get_problem_store)]
Submissions = Annotated[SubmissionStore, Depends(get_submission_store)]


async def current_principal(
    request: Request, services: ServicesDep, _scheme: Annotated[object, Security(bearer_scheme)] = None
) -> Principal:
    """The caller: a bearer API key, or else the session an LTI launch opened (POSTs need its CSRF token).

    On the event loop when the key was seen active moments ago and the rate limit is counted in memory
    (the common case); whatever needs the database or Redis runs in the thread pool.
    """
    principal = await authenticated(request, services)
    if counted_in_memory(services):
        spend_budget(services, principal)
    else:
        await run_in_threadpool(spend_budget, services, principal)
    return principal


async def preview_principal(
    request: Request, services: ServicesDep, _scheme: Annotated[object, Security(bearer_scheme)] = None
) -> Principal:
    """The caller of a live preview: its own budget per student (or key), so that typing never spends
    the budget answers and pages need."""
    principal = await authenticated(request, services)
    limiter = services.preview_limiter
    who = principal.student or f"key:{principal.key_id}"
    if isinstance(limiter, MemoryRateLimiter):
        wait = limiter.retry_after(who)
    else:
        wait = await run_in_threadpool(limiter.retry_after, who)
    if wait is not None:
        raise RateLimited(f"Too many previews; try again in {wait} s.", retry_after=wait)
    return principal


async def authenticated(request: Request, services: Services) -> Principal:
    """The caller, no budget spent: Unauthenticated when there is none."""
    authorization = request.headers.get("authorization")
    if authorization is None:
        principal = await run_in_threadpool(principal_from_session, request)
        # checked first: a call naming a course the browser is not signed in to acts as no session
        refused = await run_in_threadpool(_course_unsettled, services, request)
        if refused is not None:
            raise refused
        if principal is None:
            raise Unauthenticated(
                "Send an API key as 'Authorization: Bearer <key>', or open this from your course."
            )
    else:
        token = bearer_token(authorization)
        found = None if token is None else await key_principal(services, token)
        if found is None:
            raise Unauthenticated(
                "This API key is unknown or revoked; send it as 'Authorization: Bearer <key>'."
            )
        principal = found
    return principal


def _course_unsettled(services: Services, request: Request) -> AppError | None:
    """A browser signed in to several courses calls the API naming none where more than one could
    take the call, or names one it is not signed in to: either had acted as the latest course's
    student, filing an answer in a course the student may not have meant. The refusal of the first
    names the courses to choose from."""
    unsettled = unsettled_course(request)
    if unsettled is None:
        return None
    if unsettled.unknown is not None:
        return NotFound(f"This browser is not signed in to course {unsettled.unknown}.")
    ids = sorted(unsettled.rivals)
    named = "; ".join(f"{i}: {services.stores.courses.get_course(i).title}" for i in ids)
    choices = " or ".join(f"?course={i}" for i in ids)
    return CourseRequired(
        f"This browser is signed in to {len(ids)} courses this could be for ({named}): name one with {choices}.",
        [
            {
                "path": "course",
                "message": f"required: one of the courses {', '.join(map(str, ids))}, which could each take this",
            }
        ],
    )


def spend_budget(services: Services, principal: Principal) -> None:
    """`budget_wait`, refused with 429 and Retry-After when the budget is spent."""
    wait = budget_wait(services, principal)
    if wait is not None:
        raise RateLimited(f"Too many requests; try again in {wait} s.", retry_after=wait)


async def key_principal(services: Services, token: str) -> Principal | None:
    """The key's principal, from memory on the event loop when it was seen active moments ago, else
    from the database in the thread pool; None for an unknown or revoked key."""
    found = services.keys.cached(token)
    if found is None:
        found = await run_in_threadpool(services.keys.authenticate, token)
    return found


def counted_in_memory(services: Services) -> bool:
    return isinstance(services.key_limiter, MemoryRateLimiter) and isinstance(
        services.student_limiter, MemoryRateLimiter
    )


def budget_wait(services: Services, principal: Principal) -> int | None:
    """Spend one request of the key's budget and of its student's; None if allowed, else the seconds
    to wait. Every route a key reaches calls this once per request (the student page's too)."""
    wait = services.key_limiter.retry_after(principal.key_id)
    if wait is None and principal.student is not None:
        wait = services.student_limiter.retry_after(principal.student)
    return wait


CurrentPrincipal = Annotated[Principal, Depends(current_principal)]
PreviewPrincipal = Annotated[Principal, Depends(preview_principal)]


async def instructor(principal: CurrentPrincipal) -> Principal:
    if not principal.is_instructor:
        raise Forbidden("This needs an instructor key.")
    return principal


Instructor = Annotated[Principal, Depends(instructor)]
