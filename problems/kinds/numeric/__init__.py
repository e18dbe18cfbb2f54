"""Numeric parts: a number with units, within a tolerance of the expected value, which is either evaluated
per student from an expression (a symbolic part or a model quantity) at their given values, or stated
(`value`, the same for every student, exact as written: a `POST /v1/check` body is such a part). One
evaluated from a symbolic part recognises that part's known mistakes by their values at the same givens."""

from __future__ import annotations

import dataclasses
from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from decimal import Decimal
from functools import cached_property, lru_cache, partial
from typing import TYPE_CHECKING, Annotated, Any, Literal

import sympy
from pydantic import (
    Field,
    SerializerFunctionWrapHandler,
    StrictBool,
    ValidationInfo,
    field_validator,
    model_serializer,
)
from pydantic_core import PydanticCustomError

from physics import typeset
from physics.checking import NumericJob
from physics.dimensions import DIMENSIONLESS
from physics.errors import AnswerError, SpecError
from physics.numeric import MistakenValue, NumericSpec, Tolerance, round_sigfigs
from physics.numeric.tolerance import accepts
from physics.symbolic import KnownMistake, SymbolSpec, UnknownDimension, expression_dimension
from physics.symbolic.dimensional import DimensionMismatch
from physics.units import parse_units, unit_dimension
from physics.verdict import Outcome, Reason
from problems.fields import (
    DEFAULT_TOLERANCE_DECL,
    PART_ID,
    Attempts,
    CheckBody,
    ExactNumber,
    Name,
    RequestText,
    ShortRequestText,
    Strict,
    Text,
    ToleranceDecl,
)
from problems.kinds.base import (
    ADHOC_PART,
    CheckResult,
    CompileContext,
    MeaningContext,
    MistakeInfo,
    PartInfo,
    Path,
    Reference,
    explain,
)
from problems.kinds.symbolic import described_mistake
from problems.variants import evaluate_reference, format_number, shown_quantity, si_values, unit_scale

if TYPE_CHECKING:
    from problems.compiled import CompiledProblem
    from problems.schema import ProblemDocument
    from problems.variants import Variant

SHOWN_FIGURES = 4  # an expected value an instructor reads, to the part's sigfigs or to these
OFF_BY = Decimal("1.10")  # a value this far off must be rejected
_LEFT_OUT_WHEN_ABSENT = frozenset({"of", "value", "angular_units"})

# Other spellings of common units whose conversion factors are not powers of ten as well as those that are.
_UNIT_ALTERNATIVES: dict[str, tuple[str, ...]] = {
    "m/s": ("km/h", "cm/s"),
    "m/s^2": ("cm/s^2", "mm/s^2"),
    "s": ("ms", "min"),
    "rad/s": ("rad/ms", "rev/min"),
    "N": ("kN", "mN"),
    "J": ("kJ", "mJ"),
    "kg": ("g",),
    "m": ("cm", "mm"),
    "Hz": ("kHz",),
}


class NumericPart(Strict):
    id: Annotated[str, Field(pattern=PART_ID, max_length=64)]
    kind: Literal["numeric"]
    prompt: Text
    # The expected value: stated in `units` (`value`, the same for every student, exact as written), or
    # `of` a symbolic part or model quantity, evaluated at each student's given values. Exactly one.
    value: ExactNumber | None = None
    of: Annotated[Name | None, Field(validate_default=True)] = None  # checked after `value`
    units: Annotated[str, Field(min_length=1, max_length=100)]
    tolerance: ToleranceDecl = DEFAULT_TOLERANCE_DECL
    units_required: bool = True
    arithmetic: bool = True  # the number may be arithmetic (`229/50 m/s^2`); False: a plain decimal
    units_system: Literal["SI"] | None = None  # "SI": refuse answers in ft, lb, atm, …
    # "strict": a hertz counts cycles, so Hz for an angular frequency is the 2π mistake (absent: s⁻¹ both)
    angular_units: Literal["strict"] | None = None
    max_attempts: Attempts | None = None

    @field_validator("of")
    @classmethod
    def _of_or_value(cls, of: str | None, info: ValidationInfo) -> str | None:
        """`of` is required unless `value` is given (a missing `of` is reported where it always was)."""
        if "value" not in info.data:
            return of  # an unreadable value is reported at `value`
        if of is None and info.data["value"] is None:
            raise PydanticCustomError("missing", "required unless value is given")
        if of is not None and info.data["value"] is not None:
            raise ValueError("give of or value, not both")
        return of

    @model_serializer(mode="wrap")
    def _dump(self, handler: SerializerFunctionWrapHandler) -> dict[str, Any]:
        # The one of `of` and `value` not given is left out, and `angular_units` when absent: a document
        # dumps (and hashes, so its stored version holds) as it did before parts had them.
        dumped: dict[str, Any] = handler(self)
        return {
            key: item for key, item in dumped.items() if item is not None or key not in _LEFT_OUT_WHEN_ABSENT
        }

    @property
    def dimensionless(self) -> bool:
        """`units: "1"` asks for a pure number."""
        return is_pure_number(self.units)


class NumericCheckIn(CheckBody):
    """An ad-hoc numeric check: the expected value in `units`, as a numeric part's stated `value` is."""

    kind: Literal["numeric"]
    answer: RequestText
    expected: ExactNumber
    units: ShortRequestText | None = None
    units_required: StrictBool = True
    tolerance: ToleranceDecl | None = None  # absent: the default, as for a part
    arithmetic: StrictBool = True  # the number may be arithmetic (`229/50 m/s^2`); False: a plain decimal
    units_system: Literal["SI"] | None = None  # "SI": refuse answers in ft, lb, atm, …
    angular_units: Literal["strict"] | None = None  # "strict": Hz for an angular frequency is the 2π mistake

    def job(self) -> NumericJob:
        part = adhoc_part(
            self.expected,
            self.units,
            self.units_required,
            self.tolerance,
            self.arithmetic,
            self.units_system,
            self.angular_units,
        )
        return part.job(self.answer)


@lru_cache(maxsize=256)
def adhoc_part(
    expected: Decimal,
    units: str | None,
    units_required: bool,
    tolerance: ToleranceDecl | None,
    arithmetic: bool,
    units_system: Literal["SI"] | None,
    angular_units: Literal["strict"] | None = None,
) -> CompiledNumericPart:
    """An ad-hoc check as the one part of a problem without a document, its `expected` the part's stated
    `value` (exact, all its digits), compiled as a bank part is (cached: a course re-uses its references);
    SpecError at the body's path."""
    # The body was validated as sent; the part is only its other shape (nothing stripped).
    part = NumericPart.model_construct(
        id=ADHOC_PART,
        kind="numeric",
        prompt="",
        value=expected,
        units="1" if units is None else units,  # no units: a pure number, as `units: "1"` asks
        tolerance=tolerance or DEFAULT_TOLERANCE_DECL,
        units_required=units_required,
        arithmetic=arithmetic,
        units_system=units_system,
        angular_units=angular_units,
    )
    try:
        return NUMERIC.compile(part, (), CompileContext({}, {}, ()))
    except SpecError as error:  # at the body's path: the part's `value` is the body's `expected`
        path = tuple("expected" if name == "value" else name for name in error.path)
        raise SpecError(error.message, path) from None


@dataclass(frozen=True)
class Evaluated:
    """An expected value that depends on the student: `expr` (in SI) at their given values; `mistakes`,
    the known mistakes of the symbolic part it is `of` (in SI too), are recognised at the same values."""

    of: str
    expr: sympy.Expr
    document: ProblemDocument = field(repr=False)
    table: Mapping[str, sympy.Symbol] = field(repr=False)
    mistakes: tuple[KnownMistake, ...] = ()


@dataclass(frozen=True)
class CompiledNumericPart:
    """A numeric part: its expected value evaluated per student, or stated (a Decimal in `units`, exact)."""

    id: str
    value: Evaluated | Decimal
    units: str
    units_required: bool
    tolerance: Tolerance
    derived: bool = False  # its expression is a model quantity derived by the engine
    arithmetic: bool = True
    units_system: str | None = None
    angular_units: str | None = None

    @property
    def expression(self) -> sympy.Expr | None:
        return self.value.expr if isinstance(self.value, Evaluated) else None

    def prepare(self) -> None:
        return None  # nothing is computed lazily

    def solution(self) -> Reference:
        """The expression the value is evaluated from, or the value stated."""
        if isinstance(self.value, Evaluated):
            expr = self.value.expr
            return Reference(sympy.sstr(expr), typeset.latex(expr), self.units)
        text = format_number(self.value)
        mantissa, times_ten, power = text.partition(" × 10^")
        latex = rf"{mantissa} \times 10^{{{power}}}" if times_ten else text
        return Reference(text, latex, self.units)

    def reference(self, variant: Variant | None) -> Decimal:
        """The expected value for this student, in `units`: stated, or evaluated to 12 significant figures."""
        if isinstance(self.value, Decimal):
            return self.value
        return evaluate_reference(self.value.expr, self._values(variant), self.units, where=self.id)

    def spec(self, variant: Variant | None) -> NumericSpec:
        if isinstance(self.value, Decimal):
            return self._stated
        values = self._values(variant)
        expected = evaluate_reference(self.value.expr, values, self.units, where=self.id)
        return self._spec(expected, self._mistaken(self.value.mistakes, values, expected))

    def _values(self, variant: Variant | None) -> dict[sympy.Symbol, sympy.Expr]:
        if variant is None or not isinstance(self.value, Evaluated):
            raise ValueError(f"part {self.id!r} is evaluated per student: its value needs their variant")
        return si_values(self.value.document, variant, self.value.table)

    def _mistaken(
        self, mistakes: Sequence[KnownMistake], values: Mapping[sympy.Symbol, sympy.Expr], expected: Decimal
    ) -> tuple[MistakenValue, ...]:
        """The mistakes' values at this student's values, but for those the tolerance would take for the
        right value (no answer could show that mistake) and those that are no finite real number there."""
        found = []
        for mistake in mistakes:
            value = self.mistaken_value(mistake, values, expected)
            if value is not None:
                found.append(MistakenValue(value, mistake.feedback))
        return tuple(found)

    def mistaken_value(
        self, mistake: KnownMistake, values: Mapping[sympy.Symbol, sympy.Expr], expected: Decimal
    ) -> Decimal | None:
        """The mistake's value in `units`, or None where no answer could show it (see `_mistaken`)."""
        try:
            value = evaluate_reference(mistake.expr, values, self.units)
        except SpecError:
            return None
        return None if accepts(self.tolerance, value, expected) else value

    @cached_property
    def _stated(self) -> NumericSpec:
        """A stated value's question: every student's, made once (by the compile, which checks it)."""
        return self._spec(self.reference(None))

    def _spec(self, expected: Decimal, mistakes: tuple[MistakenValue, ...] = ()) -> NumericSpec:
        dimensionless = is_pure_number(self.units)
        return NumericSpec(
            expected=expected,
            units=None if dimensionless else self.units,
            units_required=self.units_required and not dimensionless,
            tolerance=self.tolerance,
            arithmetic=self.arithmetic,
            units_system=self.units_system,
            angular_units=self.angular_units,
            mistakes=mistakes,
        )

    def question(self, variant: Variant | None = None) -> NumericSpec:
        return self.spec(variant)

    def job(self, answer: str, variant: Variant | None = None) -> NumericJob:
        return NumericJob(answer, self.spec(variant))


class NumericKind:
    def asked_quantities(self, part: NumericPart) -> frozenset[str]:
        return frozenset() if part.of is None else frozenset({part.of})

    name = "numeric"
    expression_answer = False

    def check_meaning(self, part: NumericPart, path: Path, context: MeaningContext) -> None:
        out, quantities = context.out, context.quantities
        if (
            part.of is not None
            and part.of not in context.expression_parts
            and (quantities is None or part.of not in quantities)
        ):
            out.add((*path, "of"), f"{part.of!r} is neither a symbolic part nor a model quantity")
        if not part.dimensionless:
            out.attempt(partial(unit_dimension, part.units, (*path, "units")))
            if part.units_system == "SI":
                out.attempt(partial(si_units_at, part.units, (*path, "units")))

    def compile(self, part: NumericPart, path: Path, context: CompileContext) -> CompiledNumericPart:
        value: Evaluated | Decimal
        if part.of is not None:
            value, derived = _evaluated(part, part.of, path, context)
        elif part.value is not None:
            value, derived = part.value, False
        else:  # the schema requires one of them
            raise SpecError("needs of or value", path)
        compiled = CompiledNumericPart(
            part.id,
            value,
            part.units,
            part.units_required,
            part.tolerance.tolerance(),
            derived,
            arithmetic=part.arithmetic,
            units_system=part.units_system,
            angular_units=part.angular_units,
        )
        if isinstance(value, Decimal):
            # The same question for every student: made now, so units it cannot use are the part's
            # fault at its path, not a fault found when a student answers.
            try:
                compiled.spec(None)
            except SpecError as error:
                fields = tuple("value" if name == "expected" else name for name in error.path)
                raise SpecError(error.message, (*path, *fields)) from None
        return compiled

    def student_view(self, part: NumericPart, doc: ProblemDocument) -> dict[str, Any]:
        tolerance = {
            key: int(value) if key == "sigfigs" else float(value)
            for key, value in part.tolerance.model_dump(exclude_none=True).items()
        }
        return {"units": part.units, "symbols": [], "tolerance": tolerance}

    def selftest(
        self, problem: str, part: CompiledNumericPart, students: Sequence[Variant]
    ) -> list[CheckResult]:
        """Across students' variants, the reference value (also in other units) accepted, 10 % off rejected,
        each known mistake's value named as that mistake."""
        results: list[CheckResult] = []
        sigfigs = part.tolerance.sigfigs
        dimensionless = is_pure_number(part.units)
        # A stated value is every student's: one student's checks are all of them.
        for index, variant in enumerate(students if isinstance(part.value, Evaluated) else students[:1]):
            spec = part.spec(variant)
            reference = spec.expected
            attempts: list[tuple[str, str, bool]] = []
            suffix = "" if dimensionless else f" {part.units}"
            attempts.append((f"variant {index}", answer_text(reference, sigfigs) + suffix, True))
            if reference != 0:
                attempts.append(
                    (f"variant {index} 10% off", answer_text(reference * OFF_BY, sigfigs) + suffix, False)
                )
            mistaken = [
                (f"variant {index} mistake {j}", answer_text(mistake.value, sigfigs) + suffix)
                for j, mistake in enumerate(spec.mistakes, start=1)
            ]
            for alternative in unit_alternatives(part.units):
                factor = unit_scale(part.units) / unit_scale(alternative)
                if sigfigs is not None and not _power_of_ten(factor):
                    continue  # rounding to n figures in another unit is a different number
                converted = Decimal(
                    str(sympy.Float(sympy.Rational(*reference.as_integer_ratio()) * factor, 30))
                )
                attempts.append(
                    (
                        f"variant {index} in {alternative}",
                        f"{answer_text(converted, sigfigs)} {alternative}",
                        True,
                    )
                )
            for label, text, should_pass in attempts:
                verdict = spec.grade(text)
                ok = (
                    verdict.outcome is Outcome.CORRECT
                ) == should_pass and verdict.outcome is not Outcome.INVALID
                detail = "" if ok else f"expected {reference}: " + explain(text, verdict)
                results.append(CheckResult(problem, part.id, label, ok, detail))
            for label, text in mistaken:
                verdict = spec.grade(text)
                ok = verdict.reason is Reason.KNOWN_MISTAKE
                detail = "" if ok else "expected a known mistake: " + explain(text, verdict)
                results.append(CheckResult(problem, part.id, label, ok, detail))
        return results

    def texts(self, part: NumericPart, path: str) -> Iterator[tuple[str, str]]:
        return iter(())

    def describe(
        self, part: CompiledNumericPart, info: PartInfo, compiled: CompiledProblem, variant: Variant | None
    ) -> PartInfo:
        expected, full, error = _shown_value(part, variant)
        tolerance = part.tolerance
        return dataclasses.replace(
            info,
            latex=part.solution().latex,
            units=part.units,
            tolerance=tolerance_text(tolerance.rel, tolerance.abs, tolerance.sigfigs, part.units),
            expected=expected,
            expected_full=full,
            error=error,
            mistakes=() if error else _described_mistakes(part, compiled, variant),
        )


NUMERIC = NumericKind()


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


def _shown_value(
    part: CompiledNumericPart, variant: Variant | None
) -> tuple[str | None, str | None, str | None]:
    if variant is None and not isinstance(part.value, Decimal):  # evaluated per student: whose?
        return None, None, None
    try:
        value = part.reference(variant)
    except SpecError as error:
        return None, None, error.message
    # A part graded to n significant figures shows the value an answer must equal, by the same rule.
    shown = shown_quantity(round_sigfigs(value, part.tolerance.sigfigs or SHOWN_FIGURES), part.units)
    return shown, shown_quantity(value, part.units), None


def _described_mistakes(
    part: CompiledNumericPart, compiled: CompiledProblem, variant: Variant | None
) -> tuple[MistakeInfo, ...]:
    """The known mistakes an answer is recognised as, written as its symbolic part shows them (a model
    quantity's are the engine's); for a variant, only those its tolerance tells from the right value
    there, each with its value."""
    if not isinstance(part.value, Evaluated) or not part.value.mistakes:
        return ()
    of = part.value.of
    symbolic = compiled.parts.get(of)
    known: tuple[KnownMistake, ...] = getattr(getattr(symbolic, "context", None), "mistakes", ())
    written = getattr(compiled.document.part(of), "mistakes", ()) if symbolic is not None else ()
    values = None if variant is None else part._values(variant)
    expected = None if variant is None else part.reference(variant)
    found = []
    for mistake in part.value.mistakes:
        # its place among the symbolic part's says whether the author wrote it, and as what
        index = known.index(mistake) if mistake in known else len(written)
        info = described_mistake(mistake.expr, mistake.feedback, written, index, compiled.table)
        if values is not None and expected is not None:
            value = part.mistaken_value(mistake, values, expected)
            if value is None:
                continue
            shown = round_sigfigs(value, part.tolerance.sigfigs or SHOWN_FIGURES)
            info = dataclasses.replace(info, value=shown_quantity(shown, part.units))
        found.append(info)
    return tuple(found)


def _evaluated(part: NumericPart, of: str, path: Path, context: CompileContext) -> tuple[Evaluated, bool]:
    """The expression `of` names, to evaluate per student, and whether the model derived it."""
    derived, doc = context.derived, context.doc
    if doc is None:
        raise SpecError(f"{of!r} is evaluated at a problem's given values", (*path, "of"))
    if of in context.expressions:
        expr, from_model = context.expressions[of]
        known = context.mistakes.get(of, ())
    elif derived is not None and of in derived.quantities:
        expr, from_model = derived.quantities[of], True
        known = derived.mistakes.get(of, ())  # the engine's, as a symbolic part asking for it has them
    else:
        raise SpecError(f"{of!r} is neither a symbolic part nor a model quantity", (*path, "of"))
    missing = sorted(s.name for s in expr.free_symbols if s.name not in doc.given)
    if missing:
        raise SpecError(f"needs given values for {', '.join(missing)}", (*path, "of"))
    _require_dimension(expr, part, of, context.specs, context.table, path)
    mistakes = tuple(m for m in known if _recognisable(m.expr, part, doc, context))
    return Evaluated(of, expr, doc, context.table, mistakes), from_model


def _recognisable(expr: sympy.Expr, part: NumericPart, doc: ProblemDocument, context: CompileContext) -> bool:
    """A mistake a numeric answer can show: the givens evaluate it, to a value in the part's units (one
    of another dimension is no number an answer in those units could be)."""
    if any(symbol.name not in doc.given for symbol in expr.free_symbols):
        return False
    try:
        return _dimension_fits(expr, part, context.specs, context.table)
    except DimensionMismatch:
        return False


def is_pure_number(units: str) -> bool:
    """`units: "1"` asks for a pure number."""
    return units.strip() == "1"


def si_units_at(text: str, path: Path) -> None:
    """A part that asks for SI answers must state its own units in SI."""
    try:
        units = parse_units(text)
    except AnswerError:
        return  # unit_dimension reports it
    foreign = [atom.symbol for atom, _ in units.factors if not atom.si]
    if foreign:
        raise SpecError(f"{foreign[0]} is not an SI unit, but the part asks for SI answers", path)


def _require_dimension(
    expr: sympy.Expr,
    part: NumericPart,
    of: str,
    specs: Mapping[str, SymbolSpec],
    table: Mapping[str, sympy.Symbol],
    path: Path,
) -> None:
    try:
        fits = _dimension_fits(expr, part, specs, table)
    except DimensionMismatch as error:
        raise SpecError(
            f"the expression for {of} is dimensionally inconsistent: {error}", (*path, "of")
        ) from None
    if not fits:
        raise SpecError(f"{part.units} does not match the dimension of {of}", (*path, "units"))


def _dimension_fits(
    expr: sympy.Expr, part: NumericPart, specs: Mapping[str, SymbolSpec], table: Mapping[str, sympy.Symbol]
) -> bool:
    """Whether `expr` has the dimension of the part's units (DimensionMismatch: it has none)."""
    dims = {table[n]: s.dimension for n, s in specs.items() if s.dimension is not None}
    try:
        have = expression_dimension(expr, dims)
    except UnknownDimension:
        return True  # a symbol without a declared dimension: nothing to compare against
    return have == (DIMENSIONLESS if part.dimensionless else unit_dimension(part.units))


def answer_text(value: Decimal, sigfigs: int | None) -> str:
    """A student's way of writing `value`: to the asked sigfigs, else 6 significant figures."""
    return format_number(round_sigfigs(value, sigfigs or 6)).replace(" × 10^", "e")


def unit_alternatives(units: str) -> list[str]:
    """Other units of the same dimension a student might answer in (km/h for m/s, cm/s^2, ...)."""
    return list(_UNIT_ALTERNATIVES.get(units.strip(), ()))


def _power_of_ten(factor: sympy.Expr) -> bool:
    if not factor.is_Rational or factor <= 0:
        return False
    p, q = int(factor.p), int(factor.q)
    return (p == 1 or str(p).rstrip("0") == "1") and (q == 1 or str(q).rstrip("0") == "1")
