"""Lab-data parts (the seed's incline lab): each student gets their own measurements of a model quantity
at several settings, generated from the engine's closed form (checked against its simulation) with
realistic noise and reproducible from the student's seed, shown as a table, a plot and a CSV; the part
asks for the fitted value of one parameter, graded against the least-squares fit of that student's data
within twice its standard error (`physics.fitting`)."""

from __future__ import annotations

import dataclasses
from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass
from decimal import Decimal
from typing import TYPE_CHECKING, Annotated, Any, Literal

import sympy
from pydantic import Field

from physics import typeset
from physics.checking import QuestionJob, read_expression
from physics.errors import SpecError
from physics.fitting import Fit, fit_parameter, measurements, proportional_fit
from physics.mathinput import InputLimits
from physics.numeric import MistakenValue, NumericSpec, Tolerance
from physics.pickling import pickled_by_fields
from physics.verdict import Outcome, Reason
from problems.fields import PART_ID, Attempts, CheckBody, Name, RequestText, ShortRequestText, Strict, Text
from problems.kinds.base import CheckResult, CompileContext, MeaningContext, PartInfo, Path, Reference
from problems.modelinfo import missing_quantity
from problems.variants import format_number, si_values, unit_scale

if TYPE_CHECKING:
    from problems.compiled import CompiledProblem
    from problems.schema import ProblemDocument
    from problems.variants import Variant

WITHIN = 2  # standard errors an answer may be from the fit
Setting = Annotated[float, Field(ge=-1e6, le=1e6)]


class DataCheckIn(CheckBody):
    """An ad-hoc lab check: the measurements themselves (settings and values, in SI), the model's
    quantity in the setting, the fitted symbol and any other symbols' values; the answer is graded
    against the least-squares fit of these data within twice its standard error."""

    kind: Literal["data"]
    answer: RequestText
    quantity: ShortRequestText  # e.g. "g*sin(theta)"
    vary: Annotated[str, Field(pattern=r"^[A-Za-z][A-Za-z0-9_]{0,19}$")]
    fit: Annotated[str, Field(pattern=r"^[A-Za-z][A-Za-z0-9_]{0,19}$")]
    settings: Annotated[list[Setting], Field(min_length=3, max_length=200)]
    measured: Annotated[list[Setting], Field(min_length=3, max_length=200)]
    values: dict[Annotated[str, Field(max_length=40)], Setting] = Field(default_factory=dict, max_length=20)
    units: ShortRequestText | None = None  # the fitted value's units, SI (absent: a pure number)

    def job(self) -> DataJob:
        return DataJob(
            self.answer,
            self.quantity,
            self.vary,
            self.fit,
            tuple(self.settings),
            tuple(self.measured),
            tuple(self.values.items()),
            self.units,
        )


@pickled_by_fields
@dataclass(frozen=True)
class DataJob:
    """An ad-hoc lab check, its texts read in the worker."""

    answer: str
    quantity: str
    vary: str
    fit: str
    settings: tuple[float, ...]
    measured: tuple[float, ...]
    values: tuple[tuple[str, float], ...] = ()
    units: str | None = None
    limits_config: InputLimits = dataclasses.field(default_factory=InputLimits)

    def question(self) -> NumericSpec:
        if len(self.settings) != len(self.measured):
            raise SpecError("as many measurements as settings are needed", ("measured",))
        names = {name: sympy.Symbol(name, real=True) for name in (self.vary, self.fit, *dict(self.values))}
        quantity = read_expression(self.quantity, names, ("quantity",))
        parameter, vary = names[self.fit], names[self.vary]
        if not quantity.has(parameter):
            raise SpecError(f"the quantity does not depend on {self.fit}", ("quantity",))
        fixed = {names[name]: value for name, value in self.values}
        try:
            fit = fit_parameter(quantity, vary, parameter, self.settings, self.measured, fixed, 1.0)
        except ValueError as error:
            raise SpecError(str(error), ("measured",)) from None
        return _spec(fit.value, WITHIN * fit.standard_error, self.units or "1")


class DataPart(Strict):
    id: Annotated[str, Field(pattern=PART_ID, max_length=64)]
    kind: Literal["data"]
    prompt: Text
    measure: Name  # the model quantity measured (e.g. the acceleration down the incline)
    vary: Name  # the given symbol set at each setting (e.g. theta)
    at: Annotated[list[Setting], Field(min_length=3, max_length=30)]  # settings, in vary's given unit
    noise: Annotated[float, Field(gt=0, le=0.5)] = 0.02  # relative standard deviation of a measurement
    fit: Name  # the symbol whose value the fit gives (e.g. g)
    units: Annotated[str, Field(min_length=1, max_length=40)]  # the answer's (and the fit's) units
    measured_units: Annotated[str, Field(min_length=1, max_length=40)]  # the measurements' units
    measured_name: Annotated[str, Field(min_length=1, max_length=60)] = "y"  # column heading, e.g. "a"
    max_attempts: Attempts | None = None


@dataclass(frozen=True)
class Lab:
    """One student's data: settings (in their unit), measurements (in theirs), and the fit."""

    settings: tuple[float, ...]
    measured: tuple[float, ...]
    fit: Fit  # in the part's units


@dataclass(frozen=True)
class CompiledDataPart:
    id: str
    quantity: sympy.Expr
    vary: sympy.Symbol
    parameter: sympy.Symbol
    document: Any = dataclasses.field(repr=False)
    table: Mapping[str, sympy.Symbol] = dataclasses.field(repr=False)
    settings: tuple[float, ...] = ()
    noise: float = 0.02
    units: str = "1"
    measured_units: str = "1"
    vary_unit: str = "1"
    linear: bool = False  # the quantity is proportional to the fitted parameter
    derived: bool = True

    @property
    def expression(self) -> sympy.Expr | None:
        return None

    def prepare(self) -> None:
        return None

    def solution(self) -> Reference:
        return Reference(
            f"least-squares fit of {sympy.sstr(self.parameter)}",
            rf"\hat{{{typeset.latex(self.parameter)}}} = \text{{least-squares fit of }} {typeset.latex(self.quantity)}",
            self.units,
        )

    def lab(self, variant: Variant) -> Lab:
        """The student's measurements and their fit (the same for the same student and version)."""
        values = {s: float(v) for s, v in si_values(self.document, variant, self.table).items()}
        true = values[self.parameter]
        fixed = {s: v for s, v in values.items() if s not in (self.vary, self.parameter)}
        x_scale = float(unit_scale(self.vary_unit))
        y_scale = float(unit_scale(self.measured_units))
        xs = [x * x_scale for x in self.settings]
        seed = f"{variant.problem}|{variant.version}|{variant.student}|{self.id}"
        ys_si = measurements(
            self.quantity, self.vary, xs, {**fixed, self.parameter: true}, self.noise, seed + "|si"
        )
        shown = tuple(float(f"{y / y_scale:.3g}") for y in ys_si)
        fit = fit_parameter(
            self.quantity, self.vary, self.parameter, xs, [y * y_scale for y in shown], fixed, true
        )
        p_scale = float(unit_scale(self.units))
        return Lab(self.settings, shown, Fit(fit.value / p_scale, fit.standard_error / p_scale))

    def question(self, variant: Variant | None = None) -> NumericSpec:
        """The student's fit, with the values wrong fits of their data give as its known mistakes (read
        once and held against each, within the fit's tolerance)."""
        if variant is None:
            raise ValueError(f"part {self.id!r} grades each student's own data: it needs their variant")
        return self.question_of(self.lab(variant))

    def question_of(self, lab: Lab) -> NumericSpec:
        """`question` for data already drawn."""
        spec = _spec(lab.fit.value, WITHIN * lab.fit.standard_error, self.units)
        wrong: list[MistakenValue] = []
        if self.linear:
            y_scale = float(unit_scale(self.measured_units)) / float(unit_scale(self.units))
            for unit_name, scale in (("radians", float(unit_scale(self.vary_unit))), (self.vary_unit, 1.0)):
                slope = proportional_fit([x * scale for x in lab.settings], lab.measured) * y_scale
                wrong.append(
                    MistakenValue(
                        _value(slope),
                        f"That is the slope of the measurements against ${typeset.latex(self.vary)}$ itself (in "
                        f"{unit_name}): they are proportional to ${typeset.latex(sympy.diff(self.quantity, self.parameter))}$, "
                        "so fit them against that.",
                    )
                )
        for factor, said in ((2, "2 times"), (sympy.Rational(1, 2), "half")):
            wrong.append(
                MistakenValue(
                    _value(lab.fit.value * float(factor)),
                    f"That is {said} the value your data give: check the factor relating the slope to "
                    f"${typeset.latex(self.parameter)}$.",
                )
            )
        apart = tuple(w for w in wrong if abs(w.value - spec.expected) > 2 * _tolerance(spec))
        return dataclasses.replace(spec, mistakes=apart)

    def job(self, answer: str, variant: Variant | None = None) -> QuestionJob:
        return QuestionJob(answer, self.question(variant))

    def shown(self, variant: Variant) -> dict[str, Any]:
        """The student's own data, for their view: rows, CSV and the plot (server-drawn SVG's points)."""
        lab = self.lab(variant)
        return {
            "data": {
                "settings": list(lab.settings),
                "measured": list(lab.measured),
                # as the table and the CSV file show them
                "rows": [
                    (f"{x:g}", measured_text(y)) for x, y in zip(lab.settings, lab.measured, strict=True)
                ],
                **_plot(lab),
            }
        }


def measured_text(value: float) -> str:
    """A measurement as the lab notebook writes it: three significant figures, trailing zeros kept
    (1.60, not 1.6: the precision is part of the datum)."""
    return f"{value:#.3g}".rstrip(".")


PLOT_WIDTH, PLOT_HEIGHT, MARGIN = 320, 200, 40


def _plot(lab: Lab) -> dict[str, Any]:
    """Pixel positions of the points on a plot from 0 (both axes), and its axis ends."""
    x_top = max(max(lab.settings), 0.0) or 1.0
    y_top = max(max(lab.measured), 0.0) or 1.0
    inner_w, inner_h = PLOT_WIDTH - 2 * MARGIN, PLOT_HEIGHT - 2 * MARGIN
    points = [
        (round(MARGIN + inner_w * x / x_top, 1), round(PLOT_HEIGHT - MARGIN - inner_h * y / y_top, 1))
        for x, y in zip(lab.settings, lab.measured, strict=True)
    ]
    return {
        "points": points,
        "x_top": f"{x_top:g}",
        "y_top": f"{y_top:.3g}",
        "width": PLOT_WIDTH,
        "height": PLOT_HEIGHT,
        "margin": MARGIN,
    }


def _tolerance(spec: NumericSpec) -> Decimal:
    return spec.tolerance.abs or Decimal(0)


def _value(value: float) -> Decimal:
    return Decimal(f"{value:.12g}")


def _spec(value: float, within: float, units: str) -> NumericSpec:
    expected = _value(value)
    allowed = Decimal(f"{max(within, abs(value) * 1e-9):.6g}")
    return NumericSpec(
        expected=expected, units=None if units == "1" else units, tolerance=Tolerance(abs=allowed)
    )


class DataKind:
    def asked_quantities(self, part: DataPart) -> frozenset[str]:
        return frozenset({part.measure})

    name = "data"
    expression_answer = False
    per_student_view = True  # its student view needs the compiled part: each student's own data

    def check_meaning(self, part: DataPart, path: Path, context: MeaningContext) -> None:
        doc, quantities = context.doc, context.quantities
        if quantities is None or part.measure not in quantities:
            context.out.add((*path, "measure"), missing_quantity(part.measure, quantities or ()))
        if part.vary not in doc.given:
            context.out.add(
                (*path, "vary"), f"{part.vary!r} is not a given value (the setting each measurement is at)"
            )
        if part.fit not in doc.given:
            context.out.add(
                (*path, "fit"), f"{part.fit!r} is not a given value (its true value makes the data)"
            )

    def compile(self, part: DataPart, path: Path, context: CompileContext) -> CompiledDataPart:
        doc, derived = context.doc, context.derived
        if doc is None or derived is None:
            raise SpecError("a data part needs the problem's model (its measured quantity)", (*path, "kind"))
        if part.measure not in derived.quantities:
            raise SpecError(missing_quantity(part.measure, derived.quantities), (*path, "measure"))
        for field_name in ("vary", "fit"):
            if getattr(part, field_name) not in doc.given:
                raise SpecError("must be a given value", (*path, field_name))
        quantity = derived.quantities[part.measure]
        parameter, vary = context.table[part.fit], context.table[part.vary]
        if not quantity.has(parameter) or not quantity.has(vary):
            raise SpecError(
                f"{part.measure} must depend on {part.fit} and on {part.vary}", (*path, "measure")
            )
        return CompiledDataPart(
            part.id,
            quantity,
            vary,
            parameter,
            doc,
            context.table,
            tuple(part.at),
            part.noise,
            part.units,
            part.measured_units,
            doc.given[part.vary].unit,
            # simplify takes a while, and the answer is the part's, not a student's
            bool(sympy.simplify(quantity - parameter * sympy.diff(quantity, parameter)) == 0),
        )

    def student_view(self, part: DataPart, doc: ProblemDocument) -> dict[str, Any]:
        return {
            "units": part.units,
            "symbols": [],
            "tolerance": None,
            "setting_name": part.vary,
            "setting_unit": doc.given[part.vary].unit if part.vary in doc.given else "",
            "measured_name": part.measured_name,
            "measured_units": part.measured_units,
        }

    def selftest(
        self, problem: str, part: CompiledDataPart, students: Sequence[Variant]
    ) -> list[CheckResult]:
        """For each student: the fit accepted, a value three standard errors off rejected, and each wrong
        fit recognised; the same data drawn twice for the same student."""
        results: list[CheckResult] = []
        for index, variant in enumerate(students[:5]):
            lab = part.lab(variant)
            question = part.question_of(lab)
            value, error = lab.fit.value, lab.fit.standard_error
            unit = "" if part.units == "1" else f" {part.units}"
            for label, text, right in (
                ("fit", f"{value:.6g}{unit}", True),
                ("3 standard errors off", f"{value + 3 * error:.6g}{unit}", False),
            ):
                verdict = question.grade(text)
                ok = (verdict.outcome is Outcome.CORRECT) == right and verdict.outcome is not Outcome.INVALID
                results.append(
                    CheckResult(
                        problem, part.id, f"student {index} {label}", ok, "" if ok else verdict.feedback
                    )
                )
            for j, wrong in enumerate(question.mistakes, start=1):
                verdict = question.grade(f"{wrong.value}{unit}")
                ok = verdict.reason is Reason.KNOWN_MISTAKE
                results.append(
                    CheckResult(
                        problem, part.id, f"student {index} wrong fit {j}", ok, "" if ok else verdict.feedback
                    )
                )
            results.append(
                CheckResult(problem, part.id, f"student {index} reproducible", part.lab(variant) == lab)
            )
        return results

    def texts(self, part: DataPart, path: str) -> Iterator[tuple[str, str]]:
        return iter(())

    def describe(
        self, part: CompiledDataPart, info: PartInfo, compiled: CompiledProblem, variant: Variant | None
    ) -> PartInfo:
        expected = full = None
        if variant is not None:
            fit = part.lab(variant).fit
            expected = f"{format_number(Decimal(f'{fit.value:.4g}'))} ± {format_number(Decimal(f'{fit.standard_error:.2g}'))} {part.units}"
            full = f"accepted within {WITHIN} standard errors"
        return dataclasses.replace(
            info,
            latex=typeset.latex(part.quantity),
            units=part.units,
            expected=expected,
            expected_full=full,
            facts=(
                (
                    "Each student's data",
                    f"{typeset.latex(part.vary)} = "
                    + ", ".join(format_number(Decimal(str(x))) for x in part.settings),
                ),
            ),
        )


DATA = DataKind()
