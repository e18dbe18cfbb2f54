"""What the assignment builder's fields show: the saved assignment's settings when editing, sensible
defaults for a new one (it opens now), or, when saving was refused, what the instructor typed (a
missing problem pick must not cost them the dates they had set)."""

from __future__ import annotations

from collections.abc import Mapping
from datetime import datetime
from typing import Any
from zoneinfo import ZoneInfo

from app.courses.records import AssignmentSpec

LOCAL = "%Y-%m-%dT%H:%M"  # what <input type="datetime-local"> sends and shows
NAMES = ("title", "opens_at", "due_at", "late", "per_day", "limit", "max_attempts", "solutions")


def local(moment: datetime, timezone: str) -> str:
    return moment.astimezone(ZoneInfo(timezone)).strftime(LOCAL)


def fields_of(spec: AssignmentSpec | None, timezone: str, now: datetime) -> dict[str, str]:
    """The saved settings (`spec`), or a new assignment's: opening now, closed to late work, a 10 %
    a day penalty up to 50 % if the instructor turns late work on, each problem's own attempts."""
    if spec is None:
        return {
            "title": "",
            "opens_at": local(now, timezone),
            "due_at": "",
            "late": "closed",
            "per_day": "10",
            "limit": "50",
            "max_attempts": "",
            "solutions": "after_due",
        }
    return {
        "title": spec.title,
        "opens_at": local(spec.opens_at, timezone),
        "due_at": local(spec.due_at, timezone),
        "late": spec.late.kind.value,
        "per_day": f"{spec.late.per_day * 100:g}",
        "limit": f"{spec.late.limit * 100:g}",
        "max_attempts": str(spec.max_attempts or ""),
        "solutions": spec.solutions.value,
    }


def fields_typed(form: Mapping[str, Any]) -> dict[str, str]:
    """The fields as the refused form sent them, to show again."""
    return {name: str(form.get(name) or "")[:200] for name in NAMES}
