"""Grade passback (LTI Assignment and Grade Services) through a durable outbox.

Scores are queued inside the transaction that stores a graded submission (`app.storage`'s score
outbox), so a score is never lost nor sent for a submission that was rolled back. The rules below are
shared by the SQL store and the in-memory fake. `OutboxWorker` claims due rows (several server
instances never hold the same row: FOR UPDATE SKIP LOCKED on PostgreSQL, and a conditional UPDATE on
the row's status everywhere), posts each score with an OAuth2 token got by client assertion, and
files the outcome: delivered, retried later (network errors, 408, 429, 5xx; Retry-After respected), or
failed (what the LMS said, kept for instructors). Each target's timestamps only grow, so a resend after
a crash is idempotent on the LMS side.

Per target (a student's line item) only the newest score matters: a newer score supersedes any older
one not yet sent, and a score waits while an older one for the same target is in flight, so the LMS
sees timestamps in order (Canvas refuses an older one with 400; an LMS that does not check would drop
the grade back). When a platform answers again after an outage, every score waiting for it is due at once.
"""

from __future__ import annotations

import asyncio
import contextlib
import logging
import random
import uuid
from collections.abc import Callable
from dataclasses import dataclass
from datetime import datetime, timedelta
from email.utils import parsedate_to_datetime
from typing import TYPE_CHECKING, Any, Protocol
from urllib.parse import urlsplit, urlunsplit

import httpx

from app.db.types import utc_now

if TYPE_CHECKING:  # the stores name this module's records
    from app.storage.protocols import ScoreOutbox, ToolKeys

log = logging.getLogger("physcheck.lti.outbox")

SCORE_CONTENT_TYPE = "application/vnd.ims.lis.v1.score+json"
SCORE_SCOPE = "https://purl.imsglobal.org/spec/lti-ags/scope/score"
CLIENT_ASSERTION_TYPE = "urn:ietf:params:oauth:client-assertion-type:jwt-bearer"

PENDING, SENDING, DELIVERED, FAILED, SUPERSEDED = "pending", "sending", "delivered", "failed", "superseded"
RETRYABLE_STATUSES = frozenset({408, 425, 429, 500, 502, 503, 504})
FIRST_BACKOFF = timedelta(seconds=5)
MAX_BACKOFF = timedelta(hours=1)
MAX_ATTEMPTS = 30  # about a day at the longest backoff
LEASE = timedelta(minutes=2)  # a claimed row not finished by then (a crashed worker) is claimed again
TOKEN_MARGIN = timedelta(seconds=60)  # renew tokens this long before they expire
MAX_ERROR_CHARS = 2000
TIMESTAMP_STEP = timedelta(milliseconds=1)


def to_millisecond(moment: datetime) -> datetime:
    return moment.replace(microsecond=moment.microsecond // 1000 * 1000)


# ---- the rules, shared by the SQL store and the in-memory fake ---------------------------------------

# What superseding a score not yet sent changes.
SUPERSEDE: dict[str, Any] = {"status": SUPERSEDED, "claimed_by": None, "claimed_until": None}


def sent_timestamp(timestamp: datetime, last: datetime | None) -> datetime:
    """The timestamp a target's new score goes out with: to the millisecond, and after the target's
    last one (by a millisecond when not), so that the LMS sees them grow."""
    stamp = to_millisecond(timestamp)
    return stamp if last is None or stamp > last else last + TIMESTAMP_STEP


def claim_values(newer: bool, busy: bool, claim: str, now: datetime) -> dict[str, Any] | None:
    """What claiming a due score changes: superseded if its target has a newer score; else nothing
    while an older one for its target is in flight (it waits); else sending, leased to this worker."""
    if newer:
        return SUPERSEDE
    if busy:
        return None
    return {"status": SENDING, "claimed_by": claim, "claimed_until": now + LEASE}


def wakes_platform(outcome: Outcome, values: dict[str, Any]) -> bool:
    """Whether a finished delivery ends the backoff of every score waiting for its platform: it
    answered, and not with a retry."""
    return outcome.http_status is not None and values["status"] != PENDING


@dataclass(frozen=True)
class DeliveryProblem:
    """A score the LMS refused (status `failed`), has not yet accepted after some tries (`pending`), or
    that a newer score replaced after failed tries (`superseded`: not a failure, nothing left to do)."""

    outbox_id: int
    student: str
    problem_id: str
    issuer: str
    lineitem_url: str
    score_given: float
    score_maximum: float
    timestamp: datetime
    status: str
    attempts: int
    last_status: int | None
    last_error: str | None


# ---- claiming --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class ClaimedScore:
    id: int
    claim: str
    platform_id: int
    client_id: str
    token_url: str
    lineitem_url: str
    sub: str
    score_given: float
    score_maximum: float
    timestamp: datetime
    attempts: int


class QueuedRow(Protocol):
    """An outbox row as either store keeps it (an ORM row, or the fake's record)."""

    @property
    def id(self) -> int: ...
    @property
    def score_given(self) -> float: ...
    @property
    def score_maximum(self) -> float: ...
    @property
    def timestamp(self) -> datetime: ...
    @property
    def status(self) -> str: ...
    @property
    def attempts(self) -> int: ...
    @property
    def last_status(self) -> int | None: ...
    @property
    def last_error(self) -> str | None: ...


class TargetRow(Protocol):
    @property
    def student(self) -> str: ...
    @property
    def problem_id(self) -> str: ...
    @property
    def lineitem_url(self) -> str: ...
    @property
    def sub(self) -> str: ...


class PlatformRow(Protocol):
    @property
    def id(self) -> int: ...
    @property
    def issuer(self) -> str: ...
    @property
    def client_id(self) -> str: ...
    @property
    def token_url(self) -> str: ...


def claimed_score(claim: str, row: QueuedRow, target: TargetRow, platform: PlatformRow) -> ClaimedScore:
    """What a worker that claimed `row` needs to deliver it."""
    return ClaimedScore(
        id=row.id,
        claim=claim,
        platform_id=platform.id,
        client_id=platform.client_id,
        token_url=platform.token_url,
        lineitem_url=target.lineitem_url,
        sub=target.sub,
        score_given=row.score_given,
        score_maximum=row.score_maximum,
        timestamp=row.timestamp,
        attempts=row.attempts,
    )


def delivery_problem(row: QueuedRow, target: TargetRow, platform: PlatformRow) -> DeliveryProblem:
    return DeliveryProblem(
        outbox_id=row.id,
        student=target.student,
        problem_id=target.problem_id,
        issuer=platform.issuer,
        lineitem_url=target.lineitem_url,
        score_given=row.score_given,
        score_maximum=row.score_maximum,
        timestamp=row.timestamp,
        status=row.status,
        attempts=row.attempts,
        last_status=row.last_status,
        last_error=row.last_error,
    )


@dataclass(frozen=True)
class Outcome:
    status: str  # DELIVERED, SUPERSEDED, PENDING (retry later) or FAILED
    http_status: int | None = None
    message: str | None = None
    retry_after: timedelta | None = None


def finished_values(score: ClaimedScore, outcome: Outcome, now: datetime) -> dict[str, Any]:
    """The columns a finished delivery sets: attempts, status (failed after MAX_ATTEMPTS), the
    LMS's answer, and when to try again."""
    attempts = score.attempts + 1
    values: dict[str, Any] = {
        "attempts": attempts,
        "claimed_by": None,
        "claimed_until": None,
        "last_status": outcome.http_status,
        "last_error": outcome.message[:MAX_ERROR_CHARS] if outcome.message else None,
    }
    status = outcome.status
    if status == PENDING and attempts >= MAX_ATTEMPTS:
        status = FAILED
    values["status"] = status
    if status in (DELIVERED, SUPERSEDED):
        values["delivered_at"] = now
    if status == PENDING:
        values["next_attempt_at"] = now + backoff(attempts, outcome.retry_after)
    return values


def backoff(attempts: int, retry_after: timedelta | None) -> timedelta:
    """Exponential from FIRST_BACKOFF, capped, with up to 10 % jitter so instances spread out; a
    Retry-After from the LMS wins when it asks for longer."""
    delay = min(FIRST_BACKOFF * (1 << min(attempts - 1, 20)), MAX_BACKOFF)
    delay = delay * (1 + random.random() / 10)  # noqa: S311 (jitter, not security)
    if retry_after is not None:
        delay = max(delay, min(retry_after, MAX_BACKOFF))
    return delay


def parse_retry_after(value: str | None, now: datetime) -> timedelta | None:
    if not value:
        return None
    value = value.strip()
    if value.isdigit():
        return timedelta(seconds=int(value))
    try:
        moment = parsedate_to_datetime(value)
    except (TypeError, ValueError):
        return None
    return max(moment - now, timedelta(0)) if moment.tzinfo is not None else None


def scores_url(lineitem_url: str) -> str:
    """The score service: the line item URL with `/scores` appended to its path (query kept)."""
    parts = urlsplit(lineitem_url)
    return urlunsplit(parts._replace(path=parts.path.rstrip("/") + "/scores"))


def score_body(score: ClaimedScore) -> dict[str, Any]:
    return {
        "userId": score.sub,
        "scoreGiven": score.score_given,
        "scoreMaximum": score.score_maximum,
        "activityProgress": "Completed",
        "gradingProgress": "FullyGraded",
        "timestamp": score.timestamp.isoformat(timespec="milliseconds"),
    }


# ---- delivery --------------------------------------------------------------------------------------


class _Retry(Exception):
    def __init__(self, outcome: Outcome) -> None:
        super().__init__(outcome.message)
        self.outcome = outcome


class OutboxWorker:
    """Delivers queued scores. `start()`/`stop()` run it in the background; `run_once()` does one
    pass (tests drive it with a fake clock)."""

    def __init__(
        self,
        outbox: ScoreOutbox,
        tool_keys: ToolKeys,
        transport: httpx.AsyncBaseTransport | None = None,
        *,
        clock: Callable[[], datetime] = utc_now,
        batch_size: int = 20,
        poll_interval: float = 2.0,
    ) -> None:
        self.outbox = outbox
        self.tool_keys = tool_keys
        self.transport = transport
        self.clock = clock
        self.batch_size = batch_size
        self.poll_interval = poll_interval
        self._tokens: dict[tuple[int, str], tuple[str, datetime]] = {}
        self._stopping = asyncio.Event()
        self._task: asyncio.Task[None] | None = None

    async def start(self) -> None:
        self._stopping.clear()
        self._task = asyncio.create_task(self._loop(), name="lti-outbox")

    async def stop(self) -> None:
        self._stopping.set()
        if self._task is not None:
            await self._task
            self._task = None

    async def _loop(self) -> None:
        while not self._stopping.is_set():
            try:
                done = await self.run_once()
            except Exception:
                log.exception("score delivery pass failed")
                done = 0
            if done < self.batch_size:
                with contextlib.suppress(TimeoutError):
                    await asyncio.wait_for(self._stopping.wait(), self.poll_interval)

    async def run_once(self) -> int:
        """Claim due scores and try each once; returns how many were tried."""
        claim = uuid.uuid4().hex
        batch = await asyncio.to_thread(self.outbox.claim, claim, self.clock(), self.batch_size)
        if not batch:
            return 0
        async with httpx.AsyncClient(transport=self.transport, timeout=10.0) as client:
            for score in batch:
                outcome = await self._deliver(client, score)
                if outcome.status == FAILED:
                    log.warning("LMS refused score %s: %s %s", score.id, outcome.http_status, outcome.message)
                await asyncio.to_thread(self.outbox.finish, score, outcome, self.clock())
        return len(batch)

    async def _deliver(self, client: httpx.AsyncClient, score: ClaimedScore) -> Outcome:
        try:
            for fresh_token in (False, True):
                token = await self._token(client, score, renew=fresh_token)
                response = await client.post(
                    scores_url(score.lineitem_url),
                    json=score_body(score),
                    headers={"Authorization": f"Bearer {token}", "Content-Type": SCORE_CONTENT_TYPE},
                )
                if response.status_code == 401 and not fresh_token:
                    continue  # the cached token may have been revoked: one retry with a new one
                return self._classify(response, "score")
            raise AssertionError("unreachable")
        except _Retry as retry:
            return retry.outcome
        except httpx.HTTPError as error:
            return Outcome(PENDING, None, f"network error: {type(error).__name__}")

    def _classify(self, response: httpx.Response, what: str) -> Outcome:
        status = response.status_code
        if 200 <= status < 300:
            return Outcome(DELIVERED, status)
        if status == 409:  # the LMS already holds a newer score for this user: nothing left to do
            return Outcome(SUPERSEDED, status, response.text)
        message = f"{what}: HTTP {status}: {response.text}"
        if status in RETRYABLE_STATUSES:
            return Outcome(
                PENDING, status, message, parse_retry_after(response.headers.get("Retry-After"), self.clock())
            )
        return Outcome(FAILED, status, message)

    async def _token(self, client: httpx.AsyncClient, score: ClaimedScore, *, renew: bool) -> str:
        cache_key = (score.platform_id, SCORE_SCOPE)
        cached = self._tokens.get(cache_key)
        now = self.clock()
        if cached is not None and not renew and cached[1] > now:
            return cached[0]
        assertion = await asyncio.to_thread(self._client_assertion, score)
        response = await client.post(
            score.token_url,
            data={
                "grant_type": "client_credentials",
                "client_assertion_type": CLIENT_ASSERTION_TYPE,
                "client_assertion": assertion,
                "scope": SCORE_SCOPE,
            },
            headers={"Accept": "application/json"},
        )
        if response.status_code != 200:
            raise _Retry(self._classify(response, "token"))
        try:
            document = response.json()
            token = document["access_token"]
            lifetime = int(document.get("expires_in", 3600))
        except (ValueError, KeyError, TypeError) as error:
            raise _Retry(Outcome(FAILED, 200, f"token: unreadable response: {response.text}")) from error
        if not isinstance(token, str) or not token:
            raise _Retry(Outcome(FAILED, 200, "token: no access_token in response"))
        self._tokens[cache_key] = (token, now + timedelta(seconds=lifetime) - TOKEN_MARGIN)
        return token

    def _client_assertion(self, score: ClaimedScore) -> str:
        now = self.clock()
        claims = {
            "iss": score.client_id,
            "sub": score.client_id,
            "aud": score.token_url,
            "iat": int(now.timestamp()),
            "exp": int((now + timedelta(minutes=5)).timestamp()),
            "jti": uuid.uuid4().hex,  # fresh for every request: platforms refuse a reused one
        }
        return self.tool_keys.sign(claims)
