"""Storage behind small protocols, so the routes, the LTI code and the pages never open sessions.

protocols.py   one Protocol per store (keys, problems, submissions, compiled problems, the LMS score
               outbox, our LTI signing keys, LMS platforms, launch state, LTI sessions)
sql.py         their SQLAlchemy implementation over the `app.db` repositories (SQLite, PostgreSQL);
               sql_lti.py for the launch stores
student_data.py one student's data across the stores, to export or erase (SQL and in-memory)
sql_courses.py / memory_courses.py   courses, rosters, sign-in, assignments (app.courses.records)
memory.py      in-memory fakes that keep the same contract (tests/storage runs it against all three);
               memory_lti.py for the launch stores

`Stores` is what an application holds: one of each, plus `ping` for readiness.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

from app.db.database import Database
from app.db.types import utc_now
from app.storage.memory import FilingHook as MemoryFilingHook
from app.storage.memory import (
    MemoryApiKeyStore,
    MemoryCompiledCache,
    MemoryProblemStore,
    MemoryScoreOutbox,
    MemorySubmissionStore,
    MemoryToolKeys,
    grade_queue,
)
from app.storage.memory_courses import MemoryCourseStore, assignment_grade_queue
from app.storage.memory_lti import MemoryLaunchStore, MemoryLtiSessionStore, MemoryPlatformStore
from app.storage.protocols import (
    ApiKeyStore,
    CompiledCache,
    CompiledEntry,
    CourseStore,
    Filed,
    LaunchStore,
    LtiSessionStore,
    PlatformStore,
    ProblemStore,
    QueuedScore,
    ScoreOutbox,
    SubmissionStore,
    ToolKeys,
)
from app.storage.sql import (
    Clock,
    SqlApiKeyStore,
    SqlCompiledCache,
    SqlProblemStore,
    SqlScoreOutbox,
    SqlSubmissionStore,
    SqlToolKeys,
)
from app.storage.sql_assignment_grades import queue_assignment_grades
from app.storage.sql_courses import SqlCourseStore
from app.storage.sql_lti import SqlLaunchStore, SqlLtiSessionStore, SqlPlatformStore
from app.storage.sql_outbox import queue_grade
from app.storage.student_data import MemoryStudentData, SqlStudentData, StudentDataStore

__all__ = [
    "ApiKeyStore",
    "CompiledCache",
    "CompiledEntry",
    "CourseStore",
    "Filed",
    "LaunchStore",
    "LtiSessionStore",
    "PlatformStore",
    "ProblemStore",
    "QueuedScore",
    "ScoreOutbox",
    "Stores",
    "StudentDataStore",
    "SubmissionStore",
    "ToolKeys",
    "memory_stores",
    "sql_stores",
]


@dataclass(frozen=True)
class Stores:
    keys: ApiKeyStore
    problems: ProblemStore
    submissions: SubmissionStore
    compiled: CompiledCache
    outbox: ScoreOutbox
    tool_keys: ToolKeys
    platforms: PlatformStore
    launches: LaunchStore
    lti_sessions: LtiSessionStore
    student_data: StudentDataStore
    ping: Callable[[], bool] = field(default=lambda: True)
    courses: CourseStore = field(default_factory=MemoryCourseStore)


def sql_stores(database: Database, *, clock: Clock = utc_now) -> Stores:
    """The stores on `database`. A graded submission of a student launched from an LMS queues the
    new score in the submission's own transaction: never lost, never sent for a rolled-back one."""
    return Stores(
        keys=SqlApiKeyStore(database, clock),
        problems=SqlProblemStore(database, clock),
        submissions=SqlSubmissionStore(database, [queue_grade, queue_assignment_grades], clock),
        compiled=SqlCompiledCache(database),
        outbox=SqlScoreOutbox(database),
        tool_keys=SqlToolKeys(database, clock),
        platforms=SqlPlatformStore(database, clock),
        launches=SqlLaunchStore(database),
        lti_sessions=SqlLtiSessionStore(database),
        student_data=SqlStudentData(database),
        ping=database.ping,
        courses=SqlCourseStore(database, clock),
    )


def memory_stores(*, clock: Clock = utc_now) -> Stores:
    """Fresh fakes; a graded submission of a launched student queues its score, as with SQL."""
    compiled = MemoryCompiledCache()
    problems = MemoryProblemStore(clock, compiled)
    outbox = MemoryScoreOutbox()
    hooks: list[MemoryFilingHook] = []
    submissions = MemorySubmissionStore(problems, hooks, clock=clock)
    hooks.append(grade_queue(outbox, problems, submissions.all))
    platforms, lti_sessions, keys = MemoryPlatformStore(), MemoryLtiSessionStore(), MemoryApiKeyStore(clock)
    courses = MemoryCourseStore(clock)
    hooks.append(assignment_grade_queue(outbox, problems, courses, submissions.all))
    return Stores(
        keys=keys,
        problems=problems,
        submissions=submissions,
        compiled=compiled,
        outbox=outbox,
        tool_keys=MemoryToolKeys(),
        platforms=platforms,
        launches=MemoryLaunchStore(),
        lti_sessions=lti_sessions,
        student_data=MemoryStudentData(submissions, outbox, lti_sessions, platforms, keys, courses),
        courses=courses,
    )
