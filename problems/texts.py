"""Every text of a problem document that people read, with its path (statement, meanings, prompts, and
what each part's kind shows): what the pages check renders cleanly, and what a vetting locates."""

from __future__ import annotations

from collections.abc import Iterator

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
