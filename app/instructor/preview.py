"""What the edit page shows of a vetted upload before it is saved: built here, in the server, from the
vetting worker's compiled problem (opened, never derived again) and the document's own texts."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from app.catalog import model_and_values
from app.derivation import unpack
from app.instructor.described import Described, describe
from app.web.document_text import render_problems
from physics.figures import model_figure
from problems.loader import parse_problem
from problems.schema import ProblemDocument
from problems.variants import Variant, fixed_variant


@dataclass(frozen=True)
class Preview:
    described: Described | None  # what the engine derived, at the givens' midpoints
    figure: str | None = None  # SVG drawn from the model at the same values
    warnings: list[tuple[str, str]] = field(default_factory=list)  # texts that will not render cleanly


def preview(document: dict[str, Any], compiled: bytes | None) -> Preview:
    """`document` and `compiled` as a vetting worker sent them back (only the shape is read again)."""
    doc = parse_problem(document, "json", check_meaning=False)
    variant = fixed_variant(doc, {})  # midpoint values: the numbers a preview shows before any student
    opened = None if compiled is None else unpack(compiled, 0)
    return Preview(
        described=None if opened is None else describe(opened, variant),
        figure=_figure(doc, variant),
        warnings=render_problems(doc),
    )


def _figure(doc: ProblemDocument, variant: Variant) -> str | None:
    """The figure a student would see, or None: it only illustrates."""
    try:
        drawn = model_and_values(doc, variant)
        if drawn is None:
            return None
        model, values, title = drawn
        return model_figure(model, values, title=title)
    except Exception:  # a model the figures cannot draw yet still makes a good problem
        return None
