"""Instructors' problems: upload (JSON or YAML), new versions, retirement, and worked solutions."""

from __future__ import annotations

import functools
from typing import Annotated, Any, Literal

from fastapi import APIRouter, Path, Request, Response
from starlette.concurrency import run_in_threadpool

from app.auth import Principal
from app.authoring import Vetted
from app.courses import access
from app.db.records import ProblemRecord
from app.deps import Instructor, Problems, ServicesDep
from app.errors import AppError, Forbidden, NotFound
from app.instructor.findings import part_findings
from app.instructor.worked import body_words
from app.lti.outbox import DeliveryProblem
from app.openapi import AUTHENTICATED, errors
from app.schemas import examples
from app.schemas.problems import (
    CountPublic,
    FindingPublic,
    MethodPublic,
    PartResultsPublic,
    ProblemCreated,
    ReferencePublic,
    ResultsPublic,
    SimulationPublic,
    SolutionPublic,
    StepPublic,
)
from app.services import Services
from app.storage import CompiledEntry
from physics.engine.notation import fill_bodies
from problems.compiled import CompiledProblem
from problems.errors import ProblemInvalid

# Every route here is for instructors: a student key is 403.
router = APIRouter(tags=["authoring"], responses=AUTHENTICATED | errors(403))

_YAML_TYPES = {"application/yaml", "application/x-yaml", "text/yaml", "text/x-yaml"}
_BODY_DOC: dict[str, Any] = {
    "requestBody": {
        "required": True,
        "description": "A problem in the bank's own format (see problems/bank/*/problem.yaml), within "
        "the size and shape limits of problems/FORMAT.md.",
        "content": {
            "application/json": {"schema": {"type": "object"}, "examples": examples.UPLOAD_JSON},
            "application/yaml": {"schema": {"type": "string"}, "examples": examples.UPLOAD_YAML},
        },
    }
}


class UnsupportedMediaType(AppError):
    status, code = 415, "unsupported_media_type"


class IdMismatch(AppError):
    status, code = 422, "invalid_problem"


def _format(request: Request) -> Literal["json", "yaml"]:
    media = request.headers.get("content-type", "application/json").split(";")[0].strip().lower()
    if media == "application/json":
        return "json"
    if media in _YAML_TYPES:
        return "yaml"
    raise UnsupportedMediaType(f"Send the problem as application/json or application/yaml, not {media}.")


async def _vetted(request: Request, services: Services, principal: Principal) -> Vetted:
    vetted = await services.authoring.vet(await request.body(), _format(request), principal.key_id)
    if vetted.document is None:
        raise ProblemInvalid(vetted.errors)
    return vetted


def _key_id(principal: Principal) -> int:
    """Problems belong to an API key; an LMS session (no key) cannot own one."""
    if not principal.key_id.isdigit():
        raise Forbidden("Upload problems with an instructor API key.")
    return int(principal.key_id)


def _owned(services: Services, problem_id: str, principal: Principal) -> ProblemRecord:
    record = services.catalog.get(problem_id)
    if record.builtin or str(record.owner_key_id) != principal.key_id:
        raise Forbidden(
            "Only the instructor who uploaded a problem may change it; the built-in bank is read-only."
        )
    return record


@router.post(
    "/v1/problems",
    status_code=201,
    response_model=ProblemCreated,
    openapi_extra=_BODY_DOC,
    responses=errors(409, 413, 415, 422),
)
async def upload(request: Request, services: ServicesDep, principal: Instructor) -> ProblemCreated:
    record = await store_new_problem(services, principal, await _vetted(request, services, principal))
    return ProblemCreated(id=record.id, version=record.version)


def _compiled_entry(services: Services, vetted: Vetted) -> CompiledEntry | None:
    """The vetting worker's compilation, sealed to be stored with the version (never derived again)."""
    assert vetted.document is not None
    if vetted.compiled is None:
        return None
    return services.catalog.entry(vetted.document, vetted.compiled)


async def store_new_problem(services: Services, principal: Principal, vetted: Vetted) -> ProblemRecord:
    """Store a vetted document, with its compiled problem, as a new problem owned by the caller's key
    (the API and the pages)."""
    owner = _key_id(principal)
    document = vetted.document
    assert document is not None
    compiled = await run_in_threadpool(_compiled_entry, services, vetted)
    return await run_in_threadpool(
        functools.partial(
            services.stores.problems.create, document["id"], document, owner_key_id=owner, compiled=compiled
        )
    )


@router.put(
    "/v1/problems/{problem_id}",
    response_model=ProblemCreated,
    openapi_extra=_BODY_DOC,
    responses=errors(404, 413, 415, 422),
)
async def new_version(
    problem_id: Annotated[str, Path(openapi_examples=examples.UPLOADED_PROBLEM_ID)],
    request: Request,
    services: ServicesDep,
    principal: Instructor,
) -> ProblemCreated:
    await run_in_threadpool(_owned, services, problem_id, principal)
    vetted = await _vetted(request, services, principal)
    record = await store_new_version(services, principal, problem_id, vetted)
    return ProblemCreated(id=record.id, version=record.version)


async def store_new_version(
    services: Services, principal: Principal, problem_id: str, vetted: Vetted
) -> ProblemRecord:
    """Store a vetted document, with its compiled problem, as the next version of the caller's own
    problem (the API and the pages)."""
    await run_in_threadpool(_owned, services, problem_id, principal)
    document = vetted.document
    assert document is not None
    if document["id"] != problem_id:
        raise IdMismatch(
            f"The document's id {document['id']!r} is not {problem_id!r}.",
            [{"path": "id", "message": f"must be {problem_id!r}"}],
        )
    compiled = await run_in_threadpool(_compiled_entry, services, vetted)
    return await run_in_threadpool(
        functools.partial(services.stores.problems.add_version, problem_id, document, compiled=compiled)
    )


@router.delete("/v1/problems/{problem_id}", status_code=204, responses=errors(404, 422))
async def retire(
    problem_id: str, services: ServicesDep, problems: Problems, principal: Instructor
) -> Response:
    await run_in_threadpool(_owned, services, problem_id, principal)
    await run_in_threadpool(problems.retire, problem_id)
    return Response(status_code=204)


@router.get("/v1/problems/{problem_id}/solution", response_model=SolutionPublic, responses=errors(404, 422))
async def solution(problem_id: str, services: ServicesDep, principal: Instructor) -> SolutionPublic:
    """An upload's solution only to its author's courses' staff, or to anyone once shared."""
    record = await run_in_threadpool(services.catalog.get, problem_id)
    if not await run_in_threadpool(usable, services, principal, record):
        raise NotFound(f"There is no problem {problem_id!r}.")
    compiled = await run_in_threadpool(services.catalog.compiled, record)
    return solution_of(compiled)


@router.get("/v1/problems/{problem_id}/results", response_model=ResultsPublic, responses=errors(404, 422))
async def results(problem_id: str, services: ServicesDep, principal: Instructor) -> ResultsPublic:
    """The class results page's numbers, per part: with, for a free-body or an energy part, what the
    wrong answers miss (a force left out, a kinetic term) by how many students were told it."""
    record = await run_in_threadpool(services.catalog.get, problem_id)
    if not await run_in_threadpool(usable, services, principal, record):
        raise NotFound(f"There is no problem {problem_id!r}.")

    def load() -> ResultsPublic:
        doc = services.catalog.document(record)
        found = services.stores.submissions.class_results(problem_id, [p.id for p in doc.parts])
        parts = []
        for part, counted in zip(doc.parts, found, strict=True):
            findings = part_findings(part, counted)
            parts.append(
                PartResultsPublic(
                    part=part.id,
                    kind=part.kind,
                    tried=counted.tried,
                    correct=counted.correct,
                    graded=counted.graded,
                    previews=counted.previews,
                    wrong_reasons=[CountPublic(**vars(c)) for c in counted.wrong_reasons],
                    mistakes=[CountPublic(**vars(c)) for c in counted.mistakes],
                    findings=None
                    if findings is None
                    else [
                        FindingPublic(finding=f.text, students=f.students, submissions=f.submissions)
                        for f in findings
                    ],
                )
            )
        return ResultsPublic(id=problem_id, parts=parts)

    return await run_in_threadpool(load)


def usable(services: Services, principal: Principal, record: ProblemRecord) -> bool:
    colleagues = access.colleagues(services.stores, principal)
    return access.may_use_problem(record, principal, colleagues, services.stores.courses.shared_problems())


def solution_of(compiled: CompiledProblem) -> SolutionPublic:
    references = []
    for part_id, part in compiled.parts.items():
        reference = part.solution()
        references.append(
            ReferencePublic(
                part=part_id,
                kind=compiled.document.part(part_id).kind,
                text=reference.text,
                latex=reference.latex,
                units=reference.units,
                source="derived" if part.derived else "not derived",
            )
        )
    derived = compiled.derived
    derivation = derived.raw if derived is not None else None
    notation = getattr(derivation, "notation", None)
    bodies = {} if notation is None else body_words(compiled.document, notation, notation.masses)
    methods = (
        []
        if derivation is None
        else [
            MethodPublic(
                name=method.name,
                title=method.title,
                steps=[
                    StepPublic(title=fill_bodies(step.title, bodies), latex=step.latex)
                    for step in method.steps
                ],
                notes=list(method.notes),
            )
            for method in derivation.methods
        ]
    )
    simulation = (
        {}
        if derivation is None
        else {
            name: SimulationPublic(
                compared=check.compared, max_relative_error=check.max_relative_error, points=check.points
            )
            for name, check in derivation.simulation.items()
        }
    )
    agreement = {} if derived is None else {name: list(found) for name, found in derived.agreement.items()}
    return SolutionPublic(
        id=compiled.document.id,
        version=compiled.version,
        references=references,
        methods=methods,
        agreement=agreement,
        proofs={} if derived is None else dict(derived.proofs),
        simulation=simulation,
        checks={} if derivation is None else dict(getattr(derivation, "checks", {})),
        methods_agree=derived is not None
        and not derived.disagreements
        and all(len(m) >= 2 for m in agreement.values()),
    )


@router.get("/v1/lti/delivery-problems", response_model=list[DeliveryProblem])
async def delivery_problems(services: ServicesDep, principal: Instructor) -> list[DeliveryProblem]:
    """Scores an LMS refused (422, 403…) or has not accepted yet, newest first (all courses: API keys only)."""
    if not principal.acts_for_students:
        raise Forbidden("Grade passback across courses is for instructor API keys.")

    return await run_in_threadpool(services.stores.outbox.delivery_problems)
