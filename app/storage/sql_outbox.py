"""The grade passback outbox in the database (the SQL side of `SqlScoreOutbox`; the rules are
`app.lti.outbox`'s): scores queued inside the transaction that files a graded submission, claimed by
delivery workers (FOR UPDATE SKIP LOCKED on PostgreSQL and a conditional UPDATE everywhere), finished."""

from __future__ import annotations

from datetime import datetime

from sqlalchemy import exists, func, or_, select, update
from sqlalchemy.exc import IntegrityError
from sqlalchemy.orm import Session, aliased

from app.db.database import Database
from app.db.models import ProblemVersion, Submission
from app.db.records import SubmissionRecord
from app.lti.grades import score_of
from app.lti.models import LtiGradeTarget, LtiPlatform, LtiScoreOutbox
from app.lti.outbox import (
    FAILED,
    PENDING,
    SENDING,
    SUPERSEDE,
    SUPERSEDED,
    ClaimedScore,
    DeliveryProblem,
    Outcome,
    claim_values,
    claimed_score,
    delivery_problem,
    finished_values,
    sent_timestamp,
    wakes_platform,
)
from physics.verdict import Outcome as Verdicts


def enqueue_scores(
    session: Session,
    problem_id: str,
    student: str,
    score_given: float,
    score_maximum: float,
    timestamp: datetime,
) -> int:
    """Queue the score for every grade target of (student, problem) recorded at launch; returns how
    many. Call inside the transaction that stores the graded submission."""
    query = select(LtiGradeTarget).where(
        LtiGradeTarget.student == student, LtiGradeTarget.problem_id == problem_id
    )
    targets = list(session.scalars(query.order_by(LtiGradeTarget.id).with_for_update()))
    for target in targets:
        # A row being sent (status `sending`) is left alone: it goes first, this one after it.
        session.execute(
            update(LtiScoreOutbox)
            .where(LtiScoreOutbox.target_id == target.id, LtiScoreOutbox.status == PENDING)
            .values(**SUPERSEDE)
            .execution_options(synchronize_session=False)
        )
        sent = sent_timestamp(timestamp, target.last_timestamp)
        target.last_timestamp = sent
        session.add(
            LtiScoreOutbox(
                target_id=target.id,
                score_given=score_given,
                score_maximum=score_maximum,
                timestamp=sent,
                status=PENDING,
                attempts=0,
                next_attempt_at=timestamp,
                created_at=timestamp,
            )
        )
    session.flush()
    return len(targets)


def add_grade_target(
    session: Session, platform_id: int, *, student: str, problem_id: str, lineitem_url: str, sub: str
) -> None:
    """Record where a launched student's score on a problem goes, once (a concurrent launch may win)."""
    existing = session.scalars(
        select(LtiGradeTarget).where(
            LtiGradeTarget.platform_id == platform_id,
            LtiGradeTarget.student == student,
            LtiGradeTarget.problem_id == problem_id,
            LtiGradeTarget.lineitem_url == lineitem_url,
        )
    ).one_or_none()
    if existing is None:
        try:
            with session.begin_nested():
                session.add(
                    LtiGradeTarget(
                        platform_id=platform_id,
                        student=student,
                        problem_id=problem_id,
                        lineitem_url=lineitem_url,
                        sub=sub,
                        last_timestamp=None,
                    )
                )
        except IntegrityError:
            pass  # a concurrent launch recorded it


def list_delivery_problems(session: Session, *, limit: int = 200) -> list[DeliveryProblem]:
    """Scores that failed, are still being retried, or were superseded after failed tries, newest
    first: for instructors."""
    query = (
        select(LtiScoreOutbox, LtiGradeTarget, LtiPlatform)
        .join(LtiGradeTarget, LtiGradeTarget.id == LtiScoreOutbox.target_id)
        .join(LtiPlatform, LtiPlatform.id == LtiGradeTarget.platform_id)
        .where(or_(LtiScoreOutbox.status == FAILED, LtiScoreOutbox.attempts > 0))
        .where(LtiScoreOutbox.status.in_((FAILED, PENDING, SENDING, SUPERSEDED)))
        .order_by(LtiScoreOutbox.id.desc())
        .limit(limit)
    )
    return [delivery_problem(row, target, platform) for row, target, platform in session.execute(query)]


def claim_batch(database: Database, claim: str, now: datetime, limit: int) -> list[ClaimedScore]:
    """Take up to `limit` due rows for this worker, oldest timestamp first. On PostgreSQL rows another
    transaction holds are skipped; the conditional UPDATE (status and lease unchanged since we read
    them) makes the claim exclusive on every backend. A due row with a newer score for its target is
    superseded instead (e.g. one whose sender crashed); one whose target has an older score in flight
    waits for it."""
    due = or_(
        (LtiScoreOutbox.status == PENDING) & (LtiScoreOutbox.next_attempt_at <= now),
        (LtiScoreOutbox.status == SENDING) & (LtiScoreOutbox.claimed_until < now),
    )
    other = aliased(LtiScoreOutbox)
    same_target = (other.target_id == LtiScoreOutbox.target_id) & (other.id != LtiScoreOutbox.id)
    newer_exists = exists().where(
        same_target, other.timestamp > LtiScoreOutbox.timestamp, other.status != SUPERSEDED
    )
    in_flight = exists().where(same_target, other.status == SENDING, other.claimed_until >= now)
    claimed: list[ClaimedScore] = []
    with database.session() as session:
        query = (
            select(LtiScoreOutbox, newer_exists, in_flight)
            .where(due)
            .order_by(LtiScoreOutbox.timestamp, LtiScoreOutbox.id)
            .limit(limit)
        )
        rows = list(session.execute(query.with_for_update(skip_locked=True, of=LtiScoreOutbox)))
        for row, newer, busy in rows:
            values = claim_values(newer, busy, claim, now)
            if values is None:
                continue
            unchanged = (
                (LtiScoreOutbox.id == row.id)
                & (LtiScoreOutbox.status == row.status)
                & or_(LtiScoreOutbox.claimed_by.is_(None), LtiScoreOutbox.claimed_by == row.claimed_by)
            )
            result = session.execute(
                update(LtiScoreOutbox)
                .where(unchanged)
                .values(**values)
                .execution_options(synchronize_session=False)
            )
            if result.rowcount != 1 or newer:  # type: ignore[attr-defined]
                continue
            target = session.get(LtiGradeTarget, row.target_id)
            assert target is not None
            platform = session.get(LtiPlatform, target.platform_id)
            assert platform is not None
            claimed.append(claimed_score(claim, row, target, platform))
    return claimed


def finish(database: Database, score: ClaimedScore, outcome: Outcome, now: datetime) -> None:
    """File the outcome, unless our claim was lost (lease expired and another worker took the row)."""
    values = finished_values(score, outcome, now)
    with database.session() as session:
        session.execute(
            update(LtiScoreOutbox)
            .where(LtiScoreOutbox.id == score.id, LtiScoreOutbox.claimed_by == score.claim)
            .values(**values)
            .execution_options(synchronize_session=False)
        )
        if wakes_platform(outcome, values):
            # The platform answers again: whatever waits for it goes now, not at the end of a backoff
            # that grew during the outage.
            on_platform = select(LtiGradeTarget.id).where(LtiGradeTarget.platform_id == score.platform_id)
            session.execute(
                update(LtiScoreOutbox)
                .where(
                    LtiScoreOutbox.status == PENDING,
                    LtiScoreOutbox.next_attempt_at > now,
                    LtiScoreOutbox.target_id.in_(on_platform),
                )
                .values(next_attempt_at=now)
                .execution_options(synchronize_session=False)
            )


def problem_score(
    session: Session, problem_id: str, problem_version: int, student: str
) -> tuple[float, float]:
    """(score given, score maximum) for one student on one problem version's parts."""
    version = session.get(ProblemVersion, (problem_id, problem_version))
    rows = session.execute(
        select(Submission.part_id, func.max(Submission.score))
        .where(
            Submission.problem_id == problem_id,
            Submission.student == student,
            Submission.verdict != Verdicts.INVALID.value,
        )
        .group_by(Submission.part_id)
    ).all()
    best: dict[str, float] = {part_id: float(score or 0.0) for part_id, score in rows}
    return score_of({} if version is None else version.document, best)


def queue_grade(session: Session, stored: SubmissionRecord) -> int:
    """The SQL submission store's filing hook: inside the submission's transaction, queue the
    student's new problem score for every LMS line item it was launched from. Returns how many."""
    if stored.verdict == Verdicts.INVALID:
        return 0
    launched = session.scalar(
        select(
            exists().where(
                LtiGradeTarget.student == stored.student, LtiGradeTarget.problem_id == stored.problem_id
            )
        )
    )
    if not launched:
        return 0
    given, maximum = problem_score(session, stored.problem_id, stored.problem_version, stored.student)
    return enqueue_scores(session, stored.problem_id, stored.student, given, maximum, stored.created_at)
