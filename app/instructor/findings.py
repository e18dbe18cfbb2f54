"""What a class's incorrect answers to one part have in common, for kinds whose feedback names findings
(a free-body part: the forces left out; a Lagrangian: the kinetic term missing): each finding with how
many students were told it, read back from the feedback stored with each submission."""

from __future__ import annotations

from collections import Counter, defaultdict
from dataclasses import dataclass

from app.db.class_results import PartResults
from problems.kinds import AnyPart, kind_of
from problems.kinds.base import ReportsFindings


@dataclass(frozen=True)
class Finding:
    text: str  # as the student was told it, e.g. "A normal force (N) is missing."
    students: int  # students told it at least once
    submissions: int  # incorrect submissions that said it


def class_findings(kind: ReportsFindings, part: PartResults) -> list[Finding]:
    """The findings in `part`'s incorrect answers, the most students first."""
    students: dict[str, set[str]] = defaultdict(set)
    submissions: Counter[str] = Counter()
    for told in part.wrong_feedback:
        for finding in set(kind.findings(told.feedback)):
            students[finding].add(told.student)
            submissions[finding] += told.submissions
    found = [Finding(text, len(who), submissions[text]) for text, who in students.items()]
    return sorted(found, key=lambda f: (-f.students, -f.submissions, f.text))


def part_findings(part: AnyPart, results: PartResults) -> list[Finding] | None:
    """`class_findings` for a part whose kind names findings, else None (nothing to count)."""
    kind = kind_of(part)
    return class_findings(kind, results) if isinstance(kind, ReportsFindings) else None
