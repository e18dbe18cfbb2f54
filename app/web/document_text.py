"""Every text of a problem document that people read, and whether each renders cleanly: the check
`physcheck bank verify` (and an upload's preview) runs so that no statement shows raw TeX."""

from __future__ import annotations

from collections.abc import Iterator

from app.web.rendering import render_issues
from problems.kinds import kind_of
from problems.schema import ProblemDocument


def readable_texts(doc: ProblemDocument) -> Iterator[tuple[str, str]]:
    """(path, text) for the statement, symbol meanings, prompts, and what each part's kind shows."""
    yield "statement", doc.statement
    for name, symbol in doc.symbols.items():
        yield f"symbols.{name}.meaning", symbol.meaning
    for index, part in enumerate(doc.parts):
        yield f"parts[{index}].prompt", part.prompt
        yield from kind_of(part).texts(part, f"parts[{index}]")


def render_problems(doc: ProblemDocument) -> list[tuple[str, str]]:
    """(path, why) for each text that does not render cleanly; empty when all do."""
    return [(path, issue) for path, text in readable_texts(doc) for issue in render_issues(text)]
