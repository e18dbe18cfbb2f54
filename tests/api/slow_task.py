"""A grading task that hangs on request, to prove the pool kills workers that overrun."""

from __future__ import annotations

import time

from app.grading.worker import SpecProblem, grade
from physics.checking import CheckJob
from physics.verdict import Verdict


def hanging_grade(job: CheckJob) -> Verdict | SpecProblem:
    if job.answer == "hang":
        while True:
            time.sleep(1)
    return grade(job)
