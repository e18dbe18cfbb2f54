"""Every text of a problem document that people read, and whether each renders cleanly: the check
`physcheck bank verify` (and an upload's preview) runs so that no statement shows raw TeX."""

from __future__ import annotations

from app.web.rendering import render_issues
from problems.schema import ProblemDocument
from problems.texts import readable_texts


def render_problems(doc: ProblemDocument) -> list[tuple[str, str]]:
    """(path, why) for each text that does not render cleanly; empty when all do."""
    return [(path, issue) for path, text in readable_texts(doc) for issue in render_issues(text)]
