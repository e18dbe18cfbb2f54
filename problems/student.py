"""What one student sees of a problem: the statement with their values, the givens, and each part as
its kind shows it; never a reference."""

from __future__ import annotations

from decimal import Decimal
from typing import TYPE_CHECKING, Any

from problems.kinds import kind_of
from problems.schema import ProblemDocument
from problems.variants import Variant, fill_statement, format_quantity

if TYPE_CHECKING:
    from problems.compiled import CompiledProblem


def _json_number(value: Decimal) -> int | float:
    return (
        int(value) if value == value.to_integral_value() and value.as_tuple().exponent == 0 else float(value)
    )


def needs_compiled(problem: ProblemDocument) -> bool:
    """Whether a part's student view needs the compiled problem (a lab's data is each student's own)."""
    return any(getattr(kind_of(part), "per_student_view", False) for part in problem.parts)


def student_view(
    problem: ProblemDocument, variant: Variant, compiled: CompiledProblem | None = None
) -> dict[str, Any]:
    """What one student may see: statement with their values, givens, parts; never a reference.
    `compiled` adds what a compiled part shows of this student's own (`shown(variant)`: lab data)."""
    parts: list[dict[str, Any]] = []
    for part in problem.parts:
        limit = part.max_attempts if part.max_attempts is not None else problem.max_attempts
        shown = getattr(compiled.parts.get(part.id), "shown", None) if compiled is not None else None
        parts.append(
            {
                "id": part.id,
                "kind": part.kind,
                "prompt": part.prompt,
                "max_attempts": limit,
                **kind_of(part).student_view(part, problem),
                **(shown(variant) if shown is not None else {}),
            }
        )
    return {
        "id": problem.id,
        "title": problem.title,
        "statement": fill_statement(problem.statement, problem, variant),
        "given": {
            name: {
                "value": _json_number(value),
                "unit": problem.given[name].unit,
                "text": format_quantity(value, problem.given[name].unit),
            }
            for name, value in variant.values.items()
            if name in problem.given
        },
        "symbols": {
            name: {"meaning": decl.meaning, "dimension": decl.dimension}
            for name, decl in problem.symbols.items()
        },
        "parts": parts,
    }
