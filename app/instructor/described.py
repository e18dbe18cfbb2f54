"""A compiled problem as an instructor reads it: every part's reference (TeX), its known mistakes and
limiting cases, the worked solution by each method, and one variant's expected numbers.

Plain, picklable data: the upload vetting worker builds it for a preview before anything is stored,
and the problem pages build it from the catalog's compiled problem. No FastAPI here.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from decimal import Decimal
from typing import Any, assert_never

import sympy

from app.instructor.worked import Comparison, MethodInfo, worked_solutions
from physics.answer_text import typed_text
from physics.choice import label
from physics.errors import PhyscheckError, SpecError
from physics.mathinput import parse_math
from physics.mathinput.render import in_student_style
from physics.numeric import round_sigfigs
from problems.compiled import CompiledChoicePart, CompiledNumericPart, CompiledProblem, CompiledSymbolicPart
from problems.variants import Variant, format_number, format_quantity

SHOWN_FIGURES = 4


@dataclass(frozen=True)
class MistakeInfo:
    latex: str
    text: str  # the same, as plain text (chart labels)
    feedback: str
    by_author: bool  # written in the problem (else found by the engine)


@dataclass(frozen=True)
class LimitInfo:
    where: str  # TeX, e.g. "k = 0"
    description: str


@dataclass(frozen=True)
class PartInfo:
    id: str
    kind: str
    prompt: str
    latex: str  # the reference (for a numeric part, the expression it is evaluated from)
    units: str | None
    tolerance: str | None  # numeric parts: "within 1 %", …
    expected: str | None  # numeric parts, for the variant described: "4.580 m/s²" (to the part's sigfigs)
    expected_full: str | None  # …and the 12 significant figures it is checked against
    mistakes: tuple[MistakeInfo, ...]
    limits: tuple[LimitInfo, ...]
    error: str | None = None  # the numeric reference could not be evaluated for this variant


@dataclass(frozen=True)
class Described:
    parts: tuple[PartInfo, ...]
    methods: tuple[MethodInfo, ...]  # the worked solutions, in the seed's order (worked.py)
    agreement: tuple[tuple[str, tuple[str, ...]], ...]  # quantity -> methods that agree on it
    methods_agree: bool
    given: tuple[tuple[str, str], ...]  # the variant's values: (symbol, "2.5 kg")
    # checks of the model beside method agreement (energy bookkeeping, limits): name -> what was shown
    checks: tuple[tuple[str, str], ...] = ()
    # quantity -> what a numerical simulation compared, and its largest relative error
    simulation: tuple[tuple[str, str, float], ...] = ()
    comparison: Comparison | None = None  # the methods compared, where two or more answer


def tolerance_text(rel: Decimal | None, abs_: Decimal | None, sigfigs: int | None, units: str) -> str:
    said = []
    if rel is not None:
        said.append(f"within {format_number((rel * 100).normalize())} %")
    if abs_ is not None:
        unit = "" if units == "1" else f" {units}"
        said.append(f"within ± {format_number(abs_)}{unit}")
    if sigfigs is not None:
        said.append(f"exactly {sigfigs} significant figures")
    return " and ".join(said)


def _limit_where(substitutions: Mapping[sympy.Symbol, sympy.Expr]) -> str:
    terms = []
    for symbol, value in substitutions.items():
        arrow = r"\to" if value in (sympy.oo, -sympy.oo) or value == 0 else "="
        terms.append(f"{sympy.latex(symbol)} {arrow} {sympy.latex(value)}")
    return ",\\ ".join(terms)


def _numeric(part: CompiledNumericPart, variant: Variant | None) -> tuple[str | None, str | None, str | None]:
    if variant is None and not isinstance(part.value, Decimal):  # evaluated per student: whose?
        return None, None, None
    try:
        value = part.reference(variant)
    except SpecError as error:
        return None, None, error.message
    # A part graded to n significant figures shows the value an answer must equal, by the same rule.
    shown = format_quantity(round_sigfigs(value, part.tolerance.sigfigs or SHOWN_FIGURES), part.units)
    return shown, format_quantity(value, part.units), None


def _mistake(
    expr: sympy.Expr,
    feedback: str,
    written: Sequence[Any],
    index: int,
    authored: int,
    compiled: CompiledProblem,
) -> MistakeInfo:
    """A known mistake as the author typed it (`r0/2^(1/6)`, read by our own reader and typeset from its
    parse tree), or for one the engine found, as sympy writes it."""
    if index < authored:
        try:
            read = parse_math(str(written[index].answer), compiled.table).read_as
            return MistakeInfo(read.latex, in_student_style(read.text), feedback, True)
        except PhyscheckError:
            pass
    return MistakeInfo(sympy.latex(expr), typed_text(expr), feedback, index < authored)


def _part(
    part_id: str, kind: str, prompt: str, compiled: CompiledProblem, variant: Variant | None
) -> PartInfo:
    part = compiled.parts[part_id]
    doc_part = compiled.document.part(part_id)
    if isinstance(part, CompiledSymbolicPart):
        authored = len(getattr(doc_part, "mistakes", ()))
        return PartInfo(
            id=part_id,
            kind=kind,
            prompt=prompt,
            latex=sympy.latex(part.expected),
            units=None,
            tolerance=None,
            expected=None,
            expected_full=None,
            mistakes=tuple(
                _mistake(m.expr, m.feedback, getattr(doc_part, "mistakes", ()), i, authored, compiled)
                for i, m in enumerate(part.context.mistakes)
            ),
            limits=tuple(
                LimitInfo(_limit_where(case.substitutions), case.description) for case in part.context.limits
            ),
        )
    if isinstance(part, CompiledNumericPart):
        expected, full, error = _numeric(part, variant)
        tolerance = part.tolerance
        return PartInfo(
            id=part_id,
            kind=kind,
            prompt=prompt,
            latex=part.solution().latex,
            units=part.units,
            tolerance=tolerance_text(tolerance.rel, tolerance.abs, tolerance.sigfigs, part.units),
            expected=None if expected is None else expected,
            expected_full=full,
            mistakes=(),
            limits=(),
            error=error,
        )
    if isinstance(part, CompiledChoicePart):
        question = part.multiple
        return PartInfo(
            id=part_id,
            kind=kind,
            prompt=prompt,
            latex=part.solution().latex,
            units=None,
            tolerance=None,
            expected=part.solution().text,
            expected_full=None,
            mistakes=tuple(
                MistakeInfo(rf"\text{{{label(j)}}}", label(j), choice.feedback, True)
                for j, choice in enumerate(question.choices)
                if choice.feedback is not None
            ),
            limits=(),
        )
    assert_never(part)


def describe(compiled: CompiledProblem, variant: Variant | None = None) -> Described:
    """Everything an instructor checks a problem by; numeric values for `variant` when given."""
    doc = compiled.document
    parts = tuple(_part(spec.id, spec.kind, spec.prompt, compiled, variant) for spec in doc.parts)
    derived = compiled.derived
    derivation = derived.raw if derived is not None else None
    methods: tuple[MethodInfo, ...] = ()
    comparison: Comparison | None = None
    if derivation is not None:
        methods, comparison = worked_solutions(compiled, derivation, variant)
    agreement = () if derived is None else tuple((q, tuple(m)) for q, m in derived.agreement.items())
    given: tuple[tuple[str, str], ...] = ()
    if variant is not None:
        given = tuple(
            (name, format_quantity(value, doc.given[name].unit))
            for name, value in variant.values.items()
            if name in doc.given
        )
    checks: tuple[tuple[str, str], ...] = ()
    simulation: tuple[tuple[str, str, float], ...] = ()
    if derivation is not None:
        checks = tuple((str(k), str(v)) for k, v in dict(getattr(derivation, "checks", {})).items())
        simulation = tuple(
            (str(name), str(check.compared), float(check.max_relative_error))
            for name, check in dict(getattr(derivation, "simulation", {})).items()
        )
    return Described(
        parts=tuple(parts),
        methods=methods,
        agreement=agreement,
        methods_agree=derived is not None and not derived.disagreements,
        given=given,
        checks=checks,
        simulation=simulation,
        comparison=comparison,
    )
