"""Every text of a problem document that people read, and whether each renders cleanly: the check
`physcheck bank verify` (and an upload's preview) runs so that no statement shows raw TeX."""

from __future__ import annotations

from collections.abc import Iterator

from app.web.rendering import render_issues
from problems.schema import ProblemDocument, SymbolicPart


def readable_texts(doc: ProblemDocument) -> Iterator[tuple[str, str]]:
    """(path, text) for the statement, symbol meanings, prompts, mistakes' feedback and limits."""
    yield "statement", doc.statement
    for name, symbol in doc.symbols.items():
        yield f"symbols.{name}.meaning", symbol.meaning
    for index, part in enumerate(doc.parts):
        yield f"parts[{index}].prompt", part.prompt
        if isinstance(part, SymbolicPart):
            for m, mistake in enumerate(part.mistakes):
                yield f"parts[{index}].mistakes[{m}].feedback", mistake.feedback
            for n, limit in enumerate(part.limits):
                yield f"parts[{index}].limits[{n}].description", limit.description


def render_problems(doc: ProblemDocument) -> list[tuple[str, str]]:
    """(path, why) for each text that does not render cleanly; empty when all do."""
    return [(path, issue) for path, text in readable_texts(doc) for issue in render_issues(text)]
