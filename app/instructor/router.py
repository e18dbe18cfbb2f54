"""The instructor pages: sign-in, problems (statement, worked solutions, variants), upload and edit,
class results, submissions (with the CSV export), and scores an LMS refused.

    GET       /instructor                              -> the problem list
    GET|POST  /instructor/sign-in, POST /instructor/sign-out
    GET       /instructor/problems                     every live problem
    GET|POST  /instructor/problems/new                 paste or upload YAML: preview, then save
    GET       /instructor/problems/{id}[?student=S]    statement, figure, solutions, S's variant
    GET|POST  /instructor/problems/{id}/edit           a new version of one's own problem
    GET       /instructor/problems/{id}/results        how the class did, per part
    GET       /instructor/submissions[.csv]            every submission, filtered by problem and student
    GET       /instructor/deliveries                   grade passback the LMS refused or has not taken

Scoped as the API is (`session.py`): only an API-key session names students, sees their work, uploads
and sees grade passback; an LMS instructor session acts only for itself.
"""

from __future__ import annotations

import io
import logging
import re
from collections.abc import Callable, Mapping
from dataclasses import replace
from typing import Annotated, Any, Literal
from urllib.parse import urlencode

import yaml
from fastapi import APIRouter, Depends, FastAPI, Query, Request
from fastapi.responses import RedirectResponse, Response
from starlette.concurrency import run_in_threadpool
from starlette.datastructures import UploadFile

from app.courses import access
from app.courses.records import EnrolmentRecord, StaffRole
from app.db import class_results as results_repository
from app.db.errors import ProblemExists
from app.db.errors import ProblemNotFound as StoredProblemNotFound
from app.db.records import ProblemRecord, Role
from app.deps import ServicesDep, budget_wait
from app.errors import AppError, Busy, GraderFault
from app.instructor import session as auth
from app.instructor.described import Described, MistakeInfo, describe
from app.instructor.findings import Finding, part_findings
from app.instructor.plots import Bar, bar_chart
from app.instructor.preview import preview as preview_of
from app.instructor.starter import starter_source
from app.lti.platforms import platform_origins
from app.routers.authoring import store_new_problem, store_new_version
from app.services import Services
from app.transfer import export_submissions
from app.web.layout import page
from app.web.rendering import render_inline, tex_to_mathml
from physics.mathinput.render import in_student_style
from physics.wording import counted
from problems.loader import MAX_DOCUMENT_BYTES, parse_problem
from problems.variants import fill_statement, fixed_variant
from problems.vetting import stage_not_run

router = APIRouter(prefix="/instructor", include_in_schema=False)
log = logging.getLogger("physcheck.instructor")

PAGE_SIZE = 50
SCRIPT = "/static/instructor.js"
_ID = re.compile(r"^[A-Za-z0-9][A-Za-z0-9._-]{0,99}$")
_KEY_ONLY = (
    "A session opened from an LMS acts only for itself: sign in with an instructor API key to see "
    "students' work."
)


class PageError(Exception):
    def __init__(self, status: int, title: str, message: str):
        super().__init__(message)
        self.status, self.title, self.message = status, title, message


async def signed_in(request: Request, services: ServicesDep) -> auth.Visitor:
    who = await auth.visitor(request, services)
    wait = budget_wait(services, who.principal)
    if wait is not None:
        raise PageError(429, "Too many requests", f"Too many requests; try again in {wait} s.")
    return who


Visitor = Annotated[auth.Visitor, Depends(signed_in)]


def install_page_handlers(app: FastAPI) -> None:
    """Sign-in redirects and refusals as pages, not the API's JSON errors."""

    @app.exception_handler(auth.SignInRequired)
    async def sign_in_required(request: Request, _: Exception) -> Response:
        target = request.url.path + (f"?{request.url.query}" if request.url.query else "")
        return RedirectResponse(f"/instructor/sign-in?{urlencode({'next': target})}", status_code=303)

    @app.exception_handler(auth.NotAnInstructor)
    async def not_an_instructor(request: Request, _: Exception) -> Response:
        return _message(
            request,
            403,
            "For instructors only",
            "These pages need an instructor key or an "
            "instructor's LMS session. Students answer problems from their course or at /p/<problem>.",
        )

    @app.exception_handler(auth.BadCsrf)
    async def bad_csrf(request: Request, _: Exception) -> Response:
        return _message(
            request,
            403,
            "Form expired",
            "This form is out of date or did not come from "
            "this site. Go back, reload the page and send it again.",
        )

    @app.exception_handler(PageError)
    async def page_error(request: Request, error: PageError) -> Response:
        return _message(request, error.status, error.title, error.message)


def _message(
    request: Request, status: int, title: str, message: str, who: auth.Visitor | None = None
) -> Response:
    return page(
        request, "instructor/message.html", {"title": title, "message": message, "who": who}, status=status
    )


async def _frames(services: Services, who: auth.Visitor) -> list[str]:
    """An LMS session's pages may sit in the LMS's frame; a key session's are never framed."""
    if who.principal.api_key:
        return []

    return await run_in_threadpool(platform_origins, services.stores.platforms)


async def _page(
    request: Request,
    services: Services,
    who: auth.Visitor,
    template: str,
    context: Mapping[str, Any],
    *,
    status: int = 200,
) -> Response:
    return page(
        request,
        template,
        {"who": who, "scripts": [SCRIPT], **context},
        status=status,
        frame_ancestors=await _frames(services, who),
    )


def _need_key(who: auth.Visitor) -> None:
    if not who.acts_for_students:
        raise PageError(403, "Needs an instructor API key", _KEY_ONLY)


def _record(services: Services, problem_id: str) -> ProblemRecord:
    if not _ID.match(problem_id):
        raise PageError(404, "No such problem", f"There is no problem {problem_id!r}.")
    try:
        return services.catalog.get(problem_id)
    except StoredProblemNotFound:
        raise PageError(404, "No such problem", f"There is no problem {problem_id!r}.") from None


def _usable_record(services: Services, who: auth.Visitor, problem_id: str) -> ProblemRecord:
    """The problem if the visitor may use it: built-in, shared to the bank, or an upload of their
    courses' staff; to anyone else an upload does not exist."""
    record = _record(services, problem_id)
    colleagues = access.colleagues(services.stores, who.principal)
    if not access.may_use_problem(
        record, who.principal, colleagues, services.stores.courses.shared_problems()
    ):
        raise PageError(404, "No such problem", f"There is no problem {problem_id!r}.")
    return record


def _reachable(services: Services, who: auth.Visitor) -> Callable[[str], bool]:
    """Whether the visitor may see a student's work (a student of their courses, or in no course);
    remembered per student for one page."""
    known: dict[str, bool] = {}

    def reach(student: str) -> bool:
        if student not in known:
            known[student] = student == who.principal.own_identity or access.may_reach_student(
                services.stores, who.principal, student
            )
        return known[student]

    return reach


# Where an instructor's work is: their courses (a first-run guide when there are none), not the bank.
HOME = "/instructor/courses"


def _safe_next(target: str | None) -> str:
    if target and target.startswith("/instructor") and "//" not in target and "\\" not in target:
        return target
    return HOME


def _secure(services: Services) -> bool:
    return services.settings.base_url.startswith("https://")


# ---- signing in --------------------------------------------------------------------------------------


@router.get("")
async def home() -> Response:
    return RedirectResponse(HOME, status_code=303)


def _sign_in_form(
    request: Request, services: Services, next_url: str, *, error: str | None = None, status: int = 200
) -> Response:
    nonce = request.cookies.get(auth.PRE_COOKIE) or auth.form_nonce()
    response = page(
        request,
        "instructor/sign_in.html",
        {
            "title": "Instructor sign-in",
            "csrf": auth.csrf_token(services.settings.secret, "pre:" + nonce),
            "next": next_url,
            "error": error,
        },
        status=status,
    )
    response.set_cookie(
        auth.PRE_COOKIE,
        nonce,
        max_age=3600,
        path=auth.COOKIE_PATH,
        httponly=True,
        samesite="strict",
        secure=_secure(services),
    )
    return response


@router.get("/sign-in")
async def sign_in_page(request: Request, services: ServicesDep, next: str | None = None) -> Response:
    return _sign_in_form(request, services, _safe_next(next))


@router.post("/sign-in")
async def sign_in(request: Request, services: ServicesDep) -> Response:
    form = await request.form()
    nonce = request.cookies.get(auth.PRE_COOKIE, "")
    sent = form.get(auth.CSRF_FIELD)
    auth.check_csrf(
        services.settings.secret, "pre:" + nonce, sent if isinstance(sent, str) and nonce else None
    )
    next_url = _safe_next(str(form.get("next") or ""))
    key = str(form.get("key") or "").strip()
    limiter = services.sign_in_limiter
    address = request.client.host if request.client is not None else ""
    wait = None if limiter is None else await run_in_threadpool(limiter.retry_after, address, key)
    if wait is not None:
        refused = _sign_in_form(
            request,
            services,
            next_url,
            error=f"Too many sign-in attempts; try again in {wait} s.",
            status=429,
        )
        refused.headers["Retry-After"] = str(wait)
        return refused
    principal = await run_in_threadpool(services.keys.authenticate, key) if key else None
    if principal is None:
        return _sign_in_form(request, services, next_url, error="This key is unknown or revoked.", status=401)
    if principal.role is not Role.INSTRUCTOR:
        return _sign_in_form(
            request,
            services,
            next_url,
            error="This is a student key. These pages need an instructor key.",
            status=403,
        )
    response = RedirectResponse(next_url, status_code=303)
    response.set_cookie(
        auth.COOKIE,
        auth.session_cookie(services.settings.secret, int(principal.key_id)),
        max_age=auth.LIFETIME_SECONDS,
        path=auth.COOKIE_PATH,
        httponly=True,
        samesite="strict",
        secure=_secure(services),
    )
    response.delete_cookie(auth.PRE_COOKIE, path=auth.COOKIE_PATH)
    return response


@router.post("/sign-out")
async def sign_out(request: Request, services: ServicesDep, who: Visitor) -> Response:
    await auth.require_csrf(request, services, who)
    response = RedirectResponse("/instructor/sign-in", status_code=303)
    response.delete_cookie(auth.COOKIE, path=auth.COOKIE_PATH)
    return response


# ---- problems ----------------------------------------------------------------------------------------


@router.get("/problems")
async def problems(request: Request, services: ServicesDep, who: Visitor, q: str = "") -> Response:
    """The bank, the uploads of the visitor's courses and those shared, by title; `q` searches titles,
    ids and topics."""
    needle = q[:100].casefold().strip()

    def load() -> list[dict[str, Any]]:
        rows = []
        colleagues = access.colleagues(services.stores, who.principal)
        shared = services.stores.courses.shared_problems()
        for record in services.catalog.list():
            if not access.may_use_problem(record, who.principal, colleagues, shared):
                continue
            doc = services.catalog.document(record)
            if needle and needle not in " ".join([doc.title, record.id, *doc.topics]).casefold():
                continue
            rows.append(
                {
                    "id": record.id,
                    "title": doc.title,
                    "topics": doc.topics,
                    "parts": len(doc.parts),
                    "version": record.version,
                    "owner": "built-in"
                    if record.builtin
                    else ("yours" if str(record.owner_key_id) == who.principal.key_id else "uploaded"),
                    "refused": services.catalog.refusal(record) is not None,
                }
            )
        return sorted(rows, key=lambda row: (str(row["title"]).casefold(), row["id"]))

    rows = await run_in_threadpool(load)
    return await _page(
        request,
        services,
        who,
        "instructor/problems.html",
        {"title": "Problems", "rows": rows, "query": q[:100]},
    )


# ---- upload and edit ---------------------------------------------------------------------------------


async def _source(request: Request) -> tuple[str, Literal["json", "yaml"], str | None]:
    """(the YAML or JSON text, its format, the action) from the form: an uploaded file wins over the
    text box. Bytes that are not UTF-8 are shown as such by the vetting."""
    form = await request.form()
    text = str(form.get("source") or "")
    fmt: Literal["json", "yaml"] = "yaml"
    upload = form.get("file")
    if isinstance(upload, UploadFile) and upload.filename:
        data = await upload.read(MAX_DOCUMENT_BYTES + 1)
        if data:
            text = data.decode("utf-8", errors="replace")
            if upload.filename.lower().endswith(".json"):
                fmt = "json"
    action = form.get("action")
    return text, fmt, action if isinstance(action, str) else None


async def _edit_page(
    request: Request,
    services: Services,
    who: auth.Visitor,
    *,
    problem_id: str | None,
    source: str,
    errors: list[dict[str, Any]] | None = None,
    not_run: list[dict[str, Any]] | None = None,
    described: Described | None = None,
    document: dict[str, Any] | None = None,
    warnings: list[dict[str, Any]] | None = None,
    figure: str | None = None,
    status: int = 200,
    started_from: str | None = None,
) -> Response:
    action = "/instructor/problems/new" if problem_id is None else f"/instructor/problems/{problem_id}/edit"
    preview_doc, preview_statement = None, None
    if described is not None and document is not None:
        # Vetted already: only the shape is read again (pydantic, no sympy).
        preview_doc = parse_problem(document, "json", check_meaning=False)
        preview_statement = fill_statement(preview_doc.statement, preview_doc, fixed_variant(preview_doc, {}))
    return await _page(
        request,
        services,
        who,
        "instructor/edit.html",
        {
            "title": "New problem" if problem_id is None else f"New version of {problem_id}",
            "problem_id": problem_id,
            "started_from": started_from,
            "action": action,
            "source": source,
            "errors": errors,
            "not_run": not_run or [],
            "described": described,
            "preview_doc": preview_doc,
            "preview_statement": preview_statement,
            "warnings": warnings,
            "figure": figure,
        },
        status=status,
    )


class _BlockDumper(yaml.SafeDumper):
    """Multi-line text (statements, feedback) as `|` blocks, as authors write it."""


def _text(dumper: yaml.SafeDumper, data: str) -> yaml.ScalarNode:
    return dumper.represent_scalar("tag:yaml.org,2002:str", data, style="|" if "\n" in data else None)


_BlockDumper.add_representer(str, _text)


def yaml_text(document: Mapping[str, Any]) -> str:
    """A stored document as YAML to edit, keys in the author's order."""
    return yaml.dump(dict(document), Dumper=_BlockDumper, sort_keys=False, allow_unicode=True, width=100)


def _can_upload(who: auth.Visitor) -> None:
    if not who.principal.api_key or not who.principal.key_id.isdigit():
        raise PageError(403, "Needs an instructor API key", "Upload problems with an instructor API key.")


async def _owned_record(services: Services, who: auth.Visitor, problem_id: str) -> ProblemRecord:
    record = await run_in_threadpool(_record, services, problem_id)
    if record.builtin or str(record.owner_key_id) != who.principal.key_id:
        raise PageError(
            403,
            "Not yours to edit",
            "Only the instructor who uploaded a problem may change it; the built-in bank is read-only.",
        )
    return record


async def _vet_and_maybe_save(
    request: Request, services: Services, who: auth.Visitor, problem_id: str | None
) -> Response:
    try:
        return await _vet_and_maybe_save_form(request, services, who, problem_id)
    finally:
        await request.close()  # the uploaded file's spooled copy


async def _vet_and_maybe_save_form(
    request: Request, services: Services, who: auth.Visitor, problem_id: str | None
) -> Response:
    await auth.require_csrf(request, services, who)
    source, fmt, action = await _source(request)
    errors: list[dict[str, Any]]
    not_run: list[dict[str, Any]]
    if not source.strip():
        errors = [{"path": "", "message": "Paste the problem's YAML or choose a file.", "line": None}]
        return await _edit_page(
            request, services, who, problem_id=problem_id, source=source, errors=errors, status=422
        )
    try:
        vetted = await services.authoring.vet(source.encode("utf-8"), fmt, who.principal.key_id)
    except Busy as error:  # the vetting queue is full, this key has one in flight, or it is restarting
        raise PageError(503, "Try again shortly", error.message) from error
    if vetted.document is None:
        errors, not_run = [], []  # the faults, and the stages they kept from running (listed apart)
        for path, message in vetted.errors:
            item = {"path": path, "message": message, "line": vetted.lines.get(path)}
            (not_run if stage_not_run(message) else errors).append(item)
        return await _edit_page(
            request,
            services,
            who,
            problem_id=problem_id,
            source=source,
            errors=errors,
            not_run=not_run,
            status=422,
        )
    if action != "save":
        preview = await run_in_threadpool(preview_of, vetted.document, vetted.compiled)
        return await _edit_page(
            request,
            services,
            who,
            problem_id=problem_id,
            source=source,
            described=preview.described,
            document=vetted.document,
            figure=preview.figure,
            warnings=[
                {"path": path, "message": message, "line": vetted.lines.get(path)}
                for path, message in preview.warnings
            ],
        )
    try:
        if problem_id is None:
            record = await store_new_problem(services, who.principal, vetted)
        else:
            record = await store_new_version(services, who.principal, problem_id, vetted)
    except ProblemExists:
        errors = [{"path": "id", "message": "this id is already taken; choose another", "line": None}]
        return await _edit_page(
            request, services, who, problem_id=problem_id, source=source, errors=errors, status=409
        )
    except AppError as error:
        errors = [
            {"path": d.get("path", ""), "message": d.get("message", ""), "line": None} for d in error.details
        ] or [{"path": "", "message": error.message, "line": None}]
        return await _edit_page(
            request, services, who, problem_id=problem_id, source=source, errors=errors, status=error.status
        )
    return RedirectResponse(f"/instructor/problems/{record.id}?saved={record.version}", status_code=303)


@router.get("/problems/new")
async def new_problem(
    request: Request,
    services: ServicesDep,
    who: Visitor,
    start: Annotated[str | None, Query(alias="from", max_length=64)] = None,
) -> Response:
    _can_upload(who)
    source = ""
    if start:
        found = await run_in_threadpool(starter_source, start, services.settings.bank_dir)
        if found is None:
            raise PageError(404, "No such built-in problem", f"There is no built-in problem {start!r}.")
        source = found
    return await _edit_page(request, services, who, problem_id=None, source=source, started_from=start)


@router.post("/problems/new")
async def new_problem_post(request: Request, services: ServicesDep, who: Visitor) -> Response:
    _can_upload(who)
    return await _vet_and_maybe_save(request, services, who, None)


@router.get("/problems/{problem_id}/edit")
async def edit_problem(problem_id: str, request: Request, services: ServicesDep, who: Visitor) -> Response:
    _can_upload(who)
    record = await _owned_record(services, who, problem_id)
    return await _edit_page(request, services, who, problem_id=problem_id, source=yaml_text(record.document))


@router.post("/problems/{problem_id}/edit")
async def edit_problem_post(
    problem_id: str, request: Request, services: ServicesDep, who: Visitor
) -> Response:
    _can_upload(who)
    await _owned_record(services, who, problem_id)
    return await _vet_and_maybe_save(request, services, who, problem_id)


@router.get("/problems/{problem_id}")
async def problem(
    problem_id: str,
    request: Request,
    services: ServicesDep,
    who: Visitor,
    student: Annotated[str | None, Query(max_length=200)] = None,
    saved: Annotated[int | None, Query()] = None,
) -> Response:
    return await _problem_page(problem_id, request, services, who, student, saved)


async def _problem_page(
    problem_id: str,
    request: Request,
    services: Services,
    who: auth.Visitor,
    student: str | None,
    saved: int | None = None,
    status: int = 200,
) -> Response:
    record = await run_in_threadpool(_usable_record, services, who, problem_id)
    student = (student or "").strip() or None
    if student is not None and student != who.principal.own_identity:
        _need_key(who)
    whose, whose_name, whose_detail = await run_in_threadpool(_whose, services, who, student)

    def load() -> dict[str, Any]:
        catalog = services.catalog
        doc = catalog.document(record)
        variant = catalog.variant(record, whose)
        try:
            compiled = catalog.compiled(record)
        except GraderFault:
            refused = catalog.refusal(record)
            if refused is None:
                raise
            # Its author needs the page most now: what is refused, and the way to edit it.
            statement = fill_statement(doc.statement, doc, variant)
            return {"doc": doc, "record": record, "statement": statement, "refused": refused}
        try:
            figure = catalog.figure(problem_id, whose)
            forces = catalog.free_body_figures(problem_id, whose)
        except Exception:  # an illustration: the page is complete without it
            log.exception("no figure for problem %r", problem_id)
            figure, forces = None, ()
        return {
            "doc": doc,
            "record": record,
            "statement": fill_statement(doc.statement, doc, variant),
            "described": describe(compiled, variant),
            "figure": figure,
            "forces": forces,
        }

    context = await run_in_threadpool(load)
    own = not record.builtin and str(record.owner_key_id) == who.principal.key_id
    taught = await run_in_threadpool(access.taught_courses, services.stores, who.principal)
    return await _page(
        request,
        services,
        who,
        "instructor/problem.html",
        {
            **context,
            "title": context["doc"].title,
            "student": student,
            "whose": whose,
            "whose_name": whose_name,
            "whose_detail": whose_detail,
            "own": own,
            "saved": saved,
            # where the instructor can put it to use (after an upload, the next step)
            "teaching": [course for course, role in taught if role is StaffRole.INSTRUCTOR],
        },
        status=status,
    )


_RELEASE_RULES = {
    "after_attempts": "when they have answered every part correctly or used its last attempt",
    "always": "at once, as the problem says",
    "never": "never: the problem says so",
}


@router.get("/problems/{problem_id}/solution")
async def solution(
    problem_id: str,
    request: Request,
    services: ServicesDep,
    who: Visitor,
    student: Annotated[str | None, Query(max_length=200)] = None,
) -> Response:
    """The worked solution as a hand-out (print stylesheet), with one student's values or one's own."""
    record = await run_in_threadpool(_usable_record, services, who, problem_id)
    student = (student or "").strip() or None
    if student is not None and student != who.principal.own_identity:
        _need_key(who)
    whose, whose_name, whose_detail = await run_in_threadpool(_whose, services, who, student)

    def load() -> dict[str, Any] | None:
        catalog = services.catalog
        doc = catalog.document(record)
        variant = catalog.variant(record, whose)
        try:
            compiled = catalog.compiled(record)
        except GraderFault:
            if catalog.refusal(record) is None:
                raise
            return None  # no solution under this code: the problem's page says why
        try:
            figure = catalog.figure(problem_id, whose)
            forces = catalog.free_body_figures(problem_id, whose)
        except Exception:  # an illustration: the solution is complete without it
            log.exception("no figure for problem %r", problem_id)
            figure, forces = None, ()
        return {
            "doc": doc,
            "record": record,
            "statement": fill_statement(doc.statement, doc, variant),
            "described": describe(compiled, variant),
            "figure": figure,
            "forces": forces,
            "release_rule": _RELEASE_RULES[doc.solutions],
        }

    context = await run_in_threadpool(load)
    if context is None:  # the engine refuses this version: its faults and "Edit it", as a conflict
        return await _problem_page(problem_id, request, services, who, student, status=409)
    return await _page(
        request,
        services,
        who,
        "instructor/solution.html",
        {
            **context,
            "title": f"Worked solution: {context['doc'].title}",
            "whose": whose,
            "whose_name": whose_name,
            "whose_detail": whose_detail,
        },
    )


# ---- class results -----------------------------------------------------------------------------------


def _mistake_bar(mistakes: Mapping[str, MistakeInfo], feedback: str, submissions: int) -> Bar:
    """A chart's bar for a known mistake, labelled with its formula typeset (else its feedback), and
    described for screen readers in the student style of typing (`g·m/M`, never sympy's `g*m/M`)."""
    known = mistakes.get(feedback)
    spoken = in_student_style(known.text) if known is not None else feedback.replace("$", "")
    shown = tex_to_mathml(known.latex) if known is not None else render_inline(feedback)
    return Bar(spoken, submissions, counted(submissions, "answer"), shown)


def _findings_chart(chart: str, title: str, findings: list[Finding], tried: int) -> Any:
    return bar_chart(
        chart,
        title,
        [
            Bar(
                f.text.replace("$", ""),
                f.students,
                f"{f.students} of {counted(tried, 'student')}",
                render_inline(f.text),
            )
            for f in findings
        ],
    )


def _percent(part: results_repository.PartResults) -> str:
    share = part.percent_correct
    return "–" if share is None else f"{share:.0f} %"


@router.get("/problems/{problem_id}/results")
async def results(problem_id: str, request: Request, services: ServicesDep, who: Visitor) -> Response:
    _need_key(who)
    record = await run_in_threadpool(_usable_record, services, who, problem_id)

    def load() -> dict[str, Any]:
        doc = services.catalog.document(record)
        part_ids = [p.id for p in doc.parts]
        found = services.stores.submissions.class_results(problem_id, part_ids)
        try:
            described = describe(services.catalog.compiled(record))
        except GraderFault:
            if services.catalog.refusal(record) is None:
                raise
            described = None  # the answers given stay readable; mistakes are named by their feedback
        return {"doc": doc, "parts": found, "described": described}

    data = await run_in_threadpool(load)
    described = data["described"]
    mistakes = {m.feedback: m for info in described.parts for m in info.mistakes} if described else {}
    overview = bar_chart(
        "overview",
        "Students with a correct answer, per part",
        [
            Bar(
                f"Part {i + 1}: {part.part_id}",
                part.percent_correct or 0.0,
                f"{part.correct} of {part.tried} ({_percent(part)})",
            )
            for i, part in enumerate(data["parts"])
        ],
        maximum=100.0,
    )
    sections = []
    for index, part in enumerate(data["parts"]):
        chart = f"part-{index}"
        findings = part_findings(data["doc"].parts[index], part)
        sections.append(
            {
                "index": index,
                "part": part,
                "percent": _percent(part),
                "attempts_chart": bar_chart(
                    f"{chart}-attempts",
                    f"Part {index + 1}: attempts used up to the first correct answer",
                    [
                        Bar(counted(n, "attempt"), students, counted(students, "student"))
                        for n, students in part.first_correct.items()
                    ],
                ),
                "reasons_chart": bar_chart(
                    f"{chart}-reasons",
                    f"Part {index + 1}: wrong answers by reason",
                    [
                        Bar(c.key.replace("_", " "), c.submissions, counted(c.submissions, "answer"))
                        for c in part.wrong_reasons
                    ],
                ),
                "mistakes_chart": bar_chart(
                    f"{chart}-mistakes",
                    f"Part {index + 1}: wrong answers by known mistake",
                    [_mistake_bar(mistakes, c.key, c.submissions) for c in part.mistakes],
                ),
                "findings": findings,
                "findings_chart": None
                if findings is None
                else _findings_chart(
                    f"{chart}-findings",
                    f"Part {index + 1}: what the class's wrong answers miss, by students",
                    findings,
                    part.tried,
                ),
            }
        )
    return await _page(
        request,
        services,
        who,
        "instructor/results.html",
        {
            "title": f"Class results: {data['doc'].title}",
            "doc": data["doc"],
            "record": record,
            "overview": overview,
            "sections": sections,
            "mistakes": mistakes,
        },
    )


# ---- submissions -------------------------------------------------------------------------------------


def _filters(problem: str | None, student: str | None) -> tuple[str | None, str | None]:
    return (problem or "").strip() or None, (student or "").strip() or None


def _whose(services: Services, who: auth.Visitor, student: str | None) -> tuple[str, str, str]:
    """The identity whose variant a page shows, its name and what tells it apart (an email or an id):
    the visitor's own preview, or the student typed (by identity, or by a name, email or id on the
    rosters of the visitor's courses)."""
    if student is None:
        return who.principal.own_identity, who.principal.own_identity, ""
    students = access.students_taught(services.stores, who.principal)
    whose = _named_student(student, students)
    enrolment = students.get(whose)
    if enrolment is None:
        return whose, whose, ""
    return whose, enrolment.name or enrolment.shown_id, enrolment.detail


def _named_student(typed: str, students: Mapping[str, EnrolmentRecord]) -> str:
    """The identity the Student filter means: as typed when it is one (or nobody's), else the one
    student of the instructor's courses with that name (in any case), email or id (an instructor
    knows Ada, not `course:3:join-9f1c…`); a name two students share is refused, naming them apart."""
    if typed in students:
        return typed
    wanted = typed.casefold()
    matching = sorted(
        identity
        for identity, e in students.items()
        if wanted in (e.name.casefold(), e.email.casefold(), e.shown_id.casefold())
    )
    if len(matching) > 1:
        raise PageError(
            422,
            "Which student?",
            f"{len(matching)} students are named {typed!r}: filter by one's email or id instead: "
            + ", ".join(f"{students[i].name} ({students[i].detail})" for i in matching)
            + ".",
        )
    return matching[0] if matching else typed


@router.get("/submissions")
async def submissions(
    request: Request,
    services: ServicesDep,
    who: Visitor,
    problem: Annotated[str | None, Query(max_length=100)] = None,
    student: Annotated[str | None, Query(max_length=200)] = None,
    cursor: Annotated[str | None, Query(max_length=200)] = None,
) -> Response:
    _need_key(who)
    problem, student = _filters(problem, student)

    def load() -> tuple[Any, dict[str, str], dict[str, EnrolmentRecord], str | None]:
        reach = _reachable(services, who)
        students = access.students_taught(services.stores, who.principal)
        wanted = student if student is None else _named_student(student, students)
        if wanted is not None and not reach(wanted):
            raise PageError(404, "No such student", f"There is no student {student!r} in your courses.")
        found = services.stores.submissions.page(
            problem_id=problem, student=wanted, limit=PAGE_SIZE, cursor=cursor or None
        )
        # Students of courses the visitor does not teach are left out (a page may come back shorter).
        found = replace(found, items=[item for item in found.items if reach(item.student)])
        # by title, as instructors know their problems (ids told them less: skier-friction, atwood-slack)
        colleagues = access.colleagues(services.stores, who.principal)
        shared = services.stores.courses.shared_problems()
        titles = {
            record.id: services.catalog.document(record).title
            for record in services.catalog.list()
            if access.may_use_problem(record, who.principal, colleagues, shared)  # not others' uploads
        }
        return found, dict(sorted(titles.items(), key=lambda item: item[1].casefold())), students, wanted

    try:
        found, titles, students, wanted = await run_in_threadpool(load)
    except AppError as error:  # pragma: no cover - defensive; storage errors are below
        raise PageError(error.status, "Cannot list submissions", error.message) from None
    except ValueError:
        raise PageError(422, "Cannot list submissions", "That page link is not valid any more.") from None
    query = {k: v for k, v in (("problem", problem), ("student", wanted)) if v}
    return await _page(
        request,
        services,
        who,
        "instructor/submissions.html",
        {
            "title": "Submissions",
            "items": found.items,
            "next": None if found.next is None else "?" + urlencode({**query, "cursor": found.next}),
            "csv": "/instructor/submissions.csv" + ("?" + urlencode(query) if query else ""),
            "problem": problem,
            "student": student,
            "wanted": students.get(wanted or ""),
            "students": students,
            "titles": titles,
            "preview_prefix": results_repository.PREVIEW_PREFIX,
        },
    )


@router.get("/submissions.csv")
async def submissions_csv(
    services: ServicesDep,
    who: Visitor,
    problem: Annotated[str | None, Query(max_length=100)] = None,
    student: Annotated[str | None, Query(max_length=200)] = None,
) -> Response:
    _need_key(who)
    problem, student = _filters(problem, student)
    out = io.StringIO()
    reach = _reachable(services, who)
    await run_in_threadpool(
        lambda: export_submissions(
            services.stores.submissions,
            problem,
            out,
            student=student,
            progress=False,
            include=reach,
            person=access.students_taught(services.stores, who.principal).get,
        )
    )
    name = "submissions" + (f"-{problem}" if problem and _ID.match(problem) else "") + ".csv"
    return Response(
        out.getvalue(),
        media_type="text/csv; charset=utf-8",
        headers={
            "Content-Disposition": f'attachment; filename="{name}"',
            "Cache-Control": "no-store",
            "X-Content-Type-Options": "nosniff",
        },
    )


# ---- LMS delivery problems ---------------------------------------------------------------------------


@router.get("/deliveries")
async def deliveries(request: Request, services: ServicesDep, who: Visitor) -> Response:
    _need_key(who)

    items = await run_in_threadpool(services.stores.outbox.delivery_problems)
    return await _page(
        request,
        services,
        who,
        "instructor/deliveries.html",
        {"title": "LMS delivery problems", "items": items},
    )
