"""The LTI 1.3 message flow: OIDC login initiation, launch, and the deep-linking answer.

Login stores (state hash, nonce, platform, browser) and sends the browser to the platform; launch
takes that row back exactly once (deleted on first use, whatever the outcome), verifies the id_token,
spends the nonce, and opens a session. Storage is the context's stores (each call atomic on its own),
called from a worker thread; HTTP stays async.
"""

from __future__ import annotations

import json
import re
import secrets
import uuid
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from datetime import datetime, timedelta
from typing import Any
from urllib.parse import urlencode, urlsplit

from starlette.concurrency import run_in_threadpool

from app.auth import Role
from app.courses import passback
from app.courses.records import AssignmentNotFound, AssignmentRecord, StaffRole
from app.db.errors import ProblemNotFound
from app.lti.context import LtiContext
from app.lti.errors import MalformedRequest, NoSuchProblem, NotPermitted, PlatformNotFound
from app.lti.id_token import (
    CLAIM_DEPLOYMENT_ID,
    CLAIM_MESSAGE_TYPE,
    CLAIM_VERSION,
    DEEP_LINKING_REQUEST,
    LTI_VERSION,
    MAX_TOKEN_CHARS,
    LaunchClaims,
    verify_id_token,
)
from app.lti.pages import ProblemChoice
from app.lti.platforms import PlatformRecord
from app.lti.sessions import SessionRecord, open_session, role_from_claims, student_id, token_hash
from app.storage import ProblemStore, Stores
from app.storage.protocols import LoginState, PendingDeepLink

LOGIN_LIFETIME = timedelta(minutes=10)
DEEP_LINK_LIFETIME = timedelta(hours=1)
# Nonces are remembered a while past the longest id_token life we accept.
NONCE_RETENTION = timedelta(hours=2)
BROWSER_COOKIE = "physcheck_lti_browser"
PROBLEM_ID = re.compile(r"^[A-Za-z0-9][A-Za-z0-9._-]{0,99}$")
# Platforms' hints are opaque and may themselves be JWTs (Canvas's lti_message_hint is).
_MAX_PARAM_CHARS = 8192

CLAIM_CONTENT_ITEMS = "https://purl.imsglobal.org/spec/lti-dl/claim/content_items"
CLAIM_DL_DATA = "https://purl.imsglobal.org/spec/lti-dl/claim/data"


def _param(
    params: Mapping[str, str], name: str, *, required: bool = True, limit: int = _MAX_PARAM_CHARS
) -> str | None:
    value = params.get(name)
    if value is None or value == "":
        if required:
            raise MalformedRequest(f"missing_{name}", f"The request lacks the '{name}' parameter.")
        return None
    if len(value) > limit:
        raise MalformedRequest(f"bad_{name}", f"The '{name}' parameter is too long.")
    return value


# ---- login initiation ------------------------------------------------------------------------------


@dataclass(frozen=True)
class LoginRedirect:
    url: str
    browser_token: str  # the cookie that binds the state to this browser (new or kept)


async def begin_login(
    context: LtiContext, params: Mapping[str, str], browser_token: str | None
) -> LoginRedirect:
    """Third-party initiated login: check who is asking, remember (state, nonce) for this browser,
    and send it to the platform's authorization endpoint."""
    issuer = _param(params, "iss")
    login_hint = _param(params, "login_hint")
    target = _param(params, "target_link_uri")
    client_id = _param(params, "client_id", required=False)
    deployment_id = _param(params, "lti_deployment_id", required=False)
    message_hint = _param(params, "lti_message_hint", required=False)
    assert issuer is not None and login_hint is not None and target is not None
    parts = urlsplit(target)
    if f"{parts.scheme}://{parts.netloc}" != context.origin:
        raise MalformedRequest("foreign_target", "The target_link_uri does not point to this tool.")
    if browser_token is None or not 20 <= len(browser_token) <= 100:
        browser_token = secrets.token_urlsafe(32)
    state = secrets.token_urlsafe(32)
    nonce = secrets.token_urlsafe(32)

    stores = context.stores

    def store() -> PlatformRecord:
        now = context.clock()
        try:
            platform = stores.platforms.find(issuer, client_id)
        except PlatformNotFound as error:
            raise MalformedRequest("unknown_platform", "This LMS is not registered with the tool.") from error
        if deployment_id is not None and not stores.platforms.is_deployed(platform.id, deployment_id):
            raise NotPermitted("unknown_deployment", "This deployment is not registered with the tool.")
        login = LoginState(nonce, token_hash(browser_token), platform.id, now + LOGIN_LIFETIME)
        stores.launches.save_login(token_hash(state), login, now)
        return platform

    platform = await run_in_threadpool(store)
    query = {
        "scope": "openid",
        "response_type": "id_token",
        "response_mode": "form_post",
        "prompt": "none",
        "client_id": platform.client_id,
        "redirect_uri": context.url("/lti/launch"),
        "login_hint": login_hint,
        "state": state,
        "nonce": nonce,
    }
    if message_hint is not None:
        query["lti_message_hint"] = message_hint
    separator = "&" if urlsplit(platform.auth_url).query else "?"
    return LoginRedirect(platform.auth_url + separator + urlencode(query), browser_token)


# ---- launch ----------------------------------------------------------------------------------------


@dataclass(frozen=True)
class LaunchOutcome:
    session_id: str
    session: SessionRecord
    claims: LaunchClaims
    platform: PlatformRecord
    problem_id: str | None  # resource link launches
    deep_link_id: str | None  # deep linking launches
    assignment: tuple[int, int] | None = None  # (course id, assignment id) of an assignment's link
    course_id: int | None = None  # the course of the LMS context (made on an instructor's first launch)


async def complete_launch(
    context: LtiContext, form: Mapping[str, str], browser_token: str | None
) -> LaunchOutcome:
    """The platform's form post: the login it answers (taken once), the id_token's signature and
    claims, the deployment, the nonce (spent); then a session, and the grade target if any."""
    id_token = _param(form, "id_token", limit=MAX_TOKEN_CHARS)
    state = _param(form, "state")
    assert id_token is not None and state is not None

    stores = context.stores

    def take_state() -> tuple[PlatformRecord, LoginState]:
        # Taken on first use, whatever the outcome: the checks run after it is gone.
        login = stores.launches.take_login(token_hash(state))
        if login is None:
            raise MalformedRequest("unknown_state", "This launch does not match a login in progress.")
        return stores.platforms.get(login.platform_id), login

    platform, login = await run_in_threadpool(take_state)
    if login.expires_at < context.clock():
        raise MalformedRequest("expired_state", "The login took too long; open the activity again.")
    if browser_token is None or not secrets.compare_digest(login.browser_hash, token_hash(browser_token)):
        raise MalformedRequest(
            "state_mismatch", "This launch was started in another browser (or cookies are blocked)."
        )
    nonce = login.nonce
    claims = await verify_id_token(
        id_token,
        platform,
        context.platform_keys,
        now=context.clock(),
        expected_nonce=nonce,
        max_age=timedelta(seconds=context.settings.lti_max_token_age_seconds),
    )
    problem_id: str | None = None
    assignment_id: int | None = None
    if claims.message_type != DEEP_LINKING_REQUEST:
        assignment = claims.custom.get("assignment")
        problem = claims.custom.get("problem")
        if assignment is not None:
            if not str(assignment).isdigit() or len(str(assignment)) > 12:
                raise MalformedRequest("bad_assignment", "This link's 'assignment' is not an assignment id.")
            assignment_id = int(str(assignment))
        elif not isinstance(problem, str) or not PROBLEM_ID.match(problem):
            raise MalformedRequest(
                "no_problem", "This link names no physcheck problem (custom parameter 'problem')."
            )
        else:
            problem_id = problem
    role = role_from_claims(claims.roles)
    if claims.message_type == DEEP_LINKING_REQUEST and role is not Role.INSTRUCTOR:
        raise NotPermitted("not_instructor", "Only instructors can add problems to a course.")

    def open_launch() -> LaunchOutcome:
        # Refusals first, then the nonce (spent once), then what the launch opens. Each store call is
        # atomic on its own: a fault after the nonce is a server error, and the student launches again.
        now = context.clock()
        if not stores.platforms.is_deployed(platform.id, claims.deployment_id):
            raise NotPermitted("unknown_deployment", "This deployment is not registered with the tool.")
        if problem_id is not None:
            _require_problem(stores.problems, problem_id)
        assignment = (
            None if assignment_id is None else _require_assignment(stores, platform, claims, assignment_id)
        )
        if not stores.launches.spend_nonce(platform.id, claims.nonce[:255], now + NONCE_RETENTION, now):
            raise NotPermitted("replayed", "This launch was already used; open the activity again.")
        identity = student_id(platform.id, claims.sub)
        course_id = _join_course(stores, platform, claims, role, identity)
        if assignment is not None:
            course_id = assignment.course_id
            if role is Role.STUDENT:
                stores.courses.enrol(course_id, identity, claims.name)
            if claims.lineitem_url is not None:
                stores.outbox.add_target(
                    platform,
                    student=identity,
                    problem_id=passback.target_key(assignment.id),
                    lineitem_url=claims.lineitem_url,
                    sub=claims.sub,
                )
        if problem_id is not None and claims.lineitem_url is not None:
            stores.outbox.add_target(
                platform,
                student=student_id(platform.id, claims.sub),
                problem_id=problem_id,
                lineitem_url=claims.lineitem_url,
                sub=claims.sub,
            )
        session_id, record = open_session(
            stores.lti_sessions, platform_id=platform.id, sub=claims.sub, role=role, name=claims.name, now=now
        )
        deep_link_id = None
        if claims.deep_link_return_url is not None:
            deep_link_id = _save_deep_link(stores, platform, claims, token_hash(session_id), now)
        placed = None if assignment is None else (assignment.course_id, assignment.id)
        return LaunchOutcome(
            session_id, record, claims, platform, problem_id, deep_link_id, placed, course_id
        )

    return await run_in_threadpool(open_launch)


def _require_problem(problems: ProblemStore, problem_id: str) -> None:
    """Refused at launch, before a session or grade target exists: a student would otherwise land on
    a page that cannot load and the gradebook would wait for a score that never comes."""
    try:
        problems.get(problem_id)
    except ProblemNotFound as error:
        raise NoSuchProblem(
            "unknown_problem",
            f"This link names the problem '{problem_id}', which physcheck does not have (it may have "
            "been retired). Ask your instructor to replace the link.",
        ) from error


def _require_assignment(
    stores: Stores, platform: PlatformRecord, claims: LaunchClaims, assignment_id: int
) -> AssignmentRecord:
    """The assignment a link names, refused at launch unless it belongs to the course of the LMS
    context launching it (a link copied into another LMS course must be added there again)."""
    try:
        assignment = stores.courses.get_assignment(assignment_id)
    except AssignmentNotFound:
        assignment = None
    course = None if assignment is None else stores.courses.get_course(assignment.course_id)
    if (
        assignment is None
        or course is None
        or claims.context_id is None
        or (course.lti_platform_id, course.lti_context_id) != (platform.id, claims.context_id)
    ):
        raise NoSuchProblem(
            "unknown_assignment",
            "This link names a physcheck assignment that is not this course's (it may have been deleted, "
            "or the link was copied from another course). Ask your instructor to add it again.",
        )
    return assignment


def _join_course(
    stores: Stores, platform: PlatformRecord, claims: LaunchClaims, role: Role, identity: str
) -> int | None:
    """The LMS context's course: made on an instructor's first launch from it, with the instructor
    (or TA) on its staff; a student's launch changes nothing here."""
    if claims.context_id is None:
        return None
    context = (platform.id, claims.context_id)
    if role is not Role.INSTRUCTOR:
        course = stores.courses.course_for_context(*context)
        return None if course is None else course.id
    title = claims.context_title or f"Course {claims.context_id[:40]}"
    course = stores.courses.create_course(title, owner=identity, owner_name=claims.name, lti_context=context)
    staff_role = (
        StaffRole.TA if any(r.endswith("#TeachingAssistant") for r in claims.roles) else StaffRole.INSTRUCTOR
    )
    known = {s.member: s.role for s in stores.courses.staff(course.id)}
    if known.get(identity) is not staff_role and not (identity in known and staff_role is StaffRole.TA):
        stores.courses.add_staff(course.id, identity, staff_role, claims.name)
    return course.id


def _save_deep_link(
    stores: Stores, platform: PlatformRecord, claims: LaunchClaims, session_hash: str, now: datetime
) -> str:
    assert claims.deep_link_return_url is not None
    request_id = secrets.token_urlsafe(32)
    stores.launches.save_deep_link(
        PendingDeepLink(
            id=request_id,
            session_hash=session_hash,
            platform_id=platform.id,
            deployment_id=claims.deployment_id,
            return_url=claims.deep_link_return_url,
            data=None if claims.deep_link_data is None else json.dumps(claims.deep_link_data),
            accept_multiple=claims.deep_link_accept_multiple,
            expires_at=now + DEEP_LINK_LIFETIME,
        ),
        now,
    )
    return request_id


# ---- deep linking ----------------------------------------------------------------------------------


def problem_choices(problems: ProblemStore) -> list[ProblemChoice]:
    """Every live problem (the bank and instructors' own), with its line item's maximum: one point
    per part."""
    choices = []
    for record in problems.list():
        title = record.document.get("title")
        parts = record.document.get("parts")
        count = len(parts) if isinstance(parts, list) and parts else 1
        choices.append(ProblemChoice(record.id, title if isinstance(title, str) else record.id, float(count)))
    return choices


def assignment_choices(stores: Stores, member: str) -> list[ProblemChoice]:
    """The assignments of the courses this LMS user teaches, each offered as one link (`assignment:<id>`)
    with one line item: the assignment's total, one point a part."""
    choices = []
    for course, _ in stores.courses.courses_taught(member):
        for assignment in stores.courses.assignments(course.id):
            points = 0
            for problem_id in assignment.problems:
                try:
                    parts = stores.problems.get(problem_id).document.get("parts")
                except ProblemNotFound:
                    continue
                points += len(parts) if isinstance(parts, list) else 0
            title = f"{assignment.title} ({course.title}: {len(assignment.problems)} problems)"
            choices.append(ProblemChoice(passback.target_key(assignment.id), title, float(max(points, 1))))
    return choices


@dataclass(frozen=True)
class DeepLinkRequestRecord:
    id: str
    platform: PlatformRecord
    deployment_id: str
    return_url: str
    data: Any
    csrf_token: str
    accept_multiple: bool
    member: str = ""  # the LMS identity of the instructor choosing


def load_deep_link(stores: Stores, request_id: str, csrf_token: str, now: datetime) -> DeepLinkRequestRecord:
    """The pending request, if the form carries the CSRF token of the session that opened it."""
    row = stores.launches.get_deep_link(request_id) if len(request_id) <= 64 else None
    if row is None or row.expires_at < now:
        raise MalformedRequest("unknown_deep_link", "This selection has expired; start again from the LMS.")
    owner = stores.lti_sessions.get(row.session_hash)
    if owner is None or not secrets.compare_digest(owner.csrf_token.encode(), csrf_token.encode()):
        raise NotPermitted("bad_csrf_token", "The form is not one this tool issued to you.")
    return DeepLinkRequestRecord(
        id=row.id,
        platform=stores.platforms.get(row.platform_id),
        deployment_id=row.deployment_id,
        return_url=row.return_url,
        data=None if row.data is None else json.loads(row.data),
        csrf_token=owner.csrf_token,
        accept_multiple=row.accept_multiple,
        member=owner.student,
    )


def content_item(context: LtiContext, choice: ProblemChoice) -> dict[str, Any]:
    assignment_id = passback.assignment_of(choice.id)
    if assignment_id is not None:  # one link, one line item for the whole assignment
        return {
            "type": "ltiResourceLink",
            "title": choice.title,
            "url": context.url("/lti/launch"),
            "custom": {"assignment": str(assignment_id)},
            "lineItem": {
                "scoreMaximum": choice.score_maximum,
                "label": choice.title,
                "resourceId": f"assignment-{assignment_id}",
            },
        }
    return {
        "type": "ltiResourceLink",
        "title": choice.title,
        "url": context.url("/lti/launch"),
        "custom": {"problem": choice.id},
        "lineItem": {"scoreMaximum": choice.score_maximum, "label": choice.title, "resourceId": choice.id},
    }


def finish_deep_link(
    context: LtiContext, request_id: str, csrf_token: str, problem_ids: Sequence[str]
) -> tuple[str, str]:
    """Sign the deep-linking response for the chosen problems; returns (return URL, JWT). The
    request is used up."""
    now = context.clock()
    stores = context.stores
    request = load_deep_link(stores, request_id, csrf_token, now)
    offered = [*problem_choices(stores.problems), *assignment_choices(stores, request.member)]
    by_id = {choice.id: choice for choice in offered}
    unknown = [pid for pid in problem_ids if pid not in by_id]
    if unknown:
        raise MalformedRequest("unknown_problem", f"No such problem: {', '.join(unknown)[:200]}.")
    if not request.accept_multiple and len(set(problem_ids)) > 1:
        raise MalformedRequest(
            "one_problem_only", "Here the LMS takes one problem per link: go back and choose one."
        )
    claims: dict[str, Any] = {
        "iss": request.platform.client_id,
        "aud": request.platform.issuer,
        "iat": int(now.timestamp()),
        "exp": int((now + timedelta(minutes=5)).timestamp()),
        "nonce": uuid.uuid4().hex,
        CLAIM_DEPLOYMENT_ID: request.deployment_id,
        CLAIM_MESSAGE_TYPE: "LtiDeepLinkingResponse",
        CLAIM_VERSION: LTI_VERSION,
        CLAIM_CONTENT_ITEMS: [content_item(context, by_id[pid]) for pid in dict.fromkeys(problem_ids)],
    }
    if request.data is not None:
        claims[CLAIM_DL_DATA] = request.data
    token = stores.tool_keys.sign(claims)
    stores.launches.drop_deep_link(request_id)
    return request.return_url, token
