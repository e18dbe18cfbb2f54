"""check_numeric: read a numeric answer, check its units and figures, then compare exactly."""

from __future__ import annotations

import dataclasses
import re
from dataclasses import dataclass
from fractions import Fraction
from functools import cached_property

from physics.dimensions import describe
from physics.errors import (
    AmbiguousInput,
    AnswerError,
    MissingUnits,
    SigfigsError,
    UnexpectedUnits,
    UnknownUnit,
)
from physics.numeric.answer import NumericAnswer, read_numeric_answer
from physics.numeric.diagnosis import diagnose
from physics.numeric.spec import NumericSpec
from physics.numeric.tolerance import (
    Tolerance,
    ToleranceKind,
    matches_sigfigs,
    within_absolute,
    within_relative,
)
from physics.units import ParsedUnits, parse_units
from physics.units.registry import lookup, suggestion
from physics.verdict import Judgement, Outcome, Reason, Verdict

CORRECT = Judgement(True, Reason.EQUIVALENT, "Correct.")


def _units_of(read: NumericAnswer, spec: NumericSpec, target: ParsedUnits | None) -> ParsedUnits | None:
    """The units the answer's number is in (None: a pure number), or MissingUnits / UnexpectedUnits."""
    if read.units is None:
        if target is not None and spec.units_required:
            raise MissingUnits(
                f"Your answer needs units, for example {read.text} {_example_units(read, target)}.", read.end
            )
        return target
    if target is None:
        raise UnexpectedUnits("This answer is a pure number: remove the units.", read.units_position)
    if spec.units_system == "SI":
        foreign = [atom.symbol for atom, _ in read.units.factors if not atom.si]
        if foreign:
            raise UnknownUnit(
                f"This answer must be in SI units: {foreign[0]} is not one (for example, use {target.text}).",
                read.units_position,
                foreign[0],
            )
    return read.units


def _example_units(read: NumericAnswer, target: ParsedUnits) -> str:
    """The target's units, but radians for a bare angle in π (`pi/6` where degrees are asked): the
    student meant π/6 rad, and "pi/6 °" would tell them to write a thirtieth of a degree."""
    (atom, power), *more = target.factors
    if not more and power == 1 and atom.angle and atom.name != "radian" and "pi" in read.text:
        return "rad"
    return target.text


def _check_figures_shown(read: NumericAnswer, tolerance: Tolerance) -> None:
    if tolerance.sigfigs is None:
        return
    number = read.literal
    if number is None:
        raise SigfigsError(
            f"Give your answer as a decimal number with {tolerance.sigfigs} significant figures "
            f"(such as 4.58), not as arithmetic ({read.text}).",
            0,
        )
    fewest, most = number.sigfig_range
    if fewest <= tolerance.sigfigs <= most:
        return
    shown = str(fewest) if fewest == most else f"{fewest} to {most}"
    raise SigfigsError(
        f"Give your answer to {tolerance.sigfigs} significant figures (yours shows {shown}).", number.position
    )


@dataclass(frozen=True)
class _Comparison:
    """The expected value in the spec's units and in the answer's, and the answer's path between them."""

    expected: Fraction
    expected_as_written: Fraction
    answer_units: ParsedUnits | None
    target: ParsedUnits | None
    tolerance: Tolerance
    cycles: Fraction | None = None  # 2π or 1/2π: how a hertz counts against angle units (strict), if it does
    offset: bool = True  # False: a temperature read as a difference, the zeros of °C and K not shifting it

    @cached_property
    def _linear(self) -> tuple[Fraction, Fraction]:
        """(scale, shift) with value_in_target = value_as_written · scale + shift."""
        if self.answer_units is None or self.target is None:
            return Fraction(1), Fraction(0)
        shift = self.answer_units.convert(Fraction(0), self.target)
        scale = self.answer_units.convert(Fraction(1), self.target) - shift
        return (scale if self.cycles is None else scale * self.cycles), (
            shift if self.offset else Fraction(0)
        )

    def as_difference(self) -> _Comparison | None:
        """The comparison of a temperature difference, where the two units' zeros differ (°C against K);
        None where they do not."""
        scale, shift = self._linear
        if shift == 0:
            return None
        return dataclasses.replace(self, expected_as_written=self.expected / scale, offset=False)

    @cached_property
    def _bounds(self) -> tuple[Fraction, Fraction]:
        """The rel and abs bounds as Fractions (0 where not given; `kinds` says which apply)."""
        return Fraction(self.tolerance.rel or 0), Fraction(self.tolerance.abs or 0)

    def in_target(self, value: Fraction) -> Fraction:
        scale, shift = self._linear
        return value * scale + shift

    def passes(self, written: Fraction, exact: bool = True) -> bool:
        """Whether `written` (a value in the answer's units) meets every tolerance key given."""
        value = self.in_target(written)
        tolerance = self.tolerance
        kinds = tolerance.kinds
        if not kinds:
            return value == self.expected
        rel, absolute = self._bounds
        for kind in kinds:
            match kind:
                case ToleranceKind.RELATIVE:
                    ok = within_relative(value, self.expected, rel)
                case ToleranceKind.ABSOLUTE:
                    ok = within_absolute(value, self.expected, absolute)
                case ToleranceKind.SIGFIGS:
                    assert tolerance.sigfigs is not None
                    if exact:
                        ok = matches_sigfigs(written, self.expected_as_written, tolerance.sigfigs)
                    else:  # a corrected guess has lost the literal's digits: half a unit in the last place
                        rel = Fraction(5, 10**tolerance.sigfigs)
                        ok = within_relative(written, self.expected_as_written, rel)
            if not ok:
                return False
        return True


def _case_hint(typed: str, target: ParsedUnits) -> str:
    """`Kg` is read as kelvin·gram (a glued name splits); say so when `kg` is what fits."""
    hint = suggestion(typed)
    if hint is None:
        return ""
    try:
        fits = parse_units(hint).dimension == target.dimension
    except AnswerError:
        return ""
    return f" Units are case-sensitive: did you mean {hint}?" if fits else ""


def _wrong_dimension(read: NumericAnswer, answer_units: ParsedUnits, target: ParsedUnits) -> Judgement:
    return Judgement(
        False,
        Reason.WRONG_DIMENSION,
        f"Your answer has the units of {describe(answer_units.dimension)}; "
        f"{describe(target.dimension)} is expected." + _case_hint(read.units_text, target),
    )


# A trigonometric function of a bare whole or decimal number: `sin(28)`, `cos 60`, radians as typed.
_TRIG_OF_A_NUMBER = re.compile(r"(?<![A-Za-z])(sin|cos|tan)(\s*\(\s*|\s+)(\d+(?:\.\d+)?)(?![\d.°])")


def check_numeric(answer: str, spec: NumericSpec) -> Verdict:
    """Check a numeric answer (`4.58 m/s^2`) against `spec`: invalid, or graded with a reason; a wrong
    one whose angles, read in degrees, would make it right says so (`9.8*sin(28) m/s^2`: radians).

    Raises SpecError only for a spec that cannot be used; anything about the answer is a verdict.
    """
    verdict = _checked(answer, spec)
    if verdict.outcome is not Outcome.INCORRECT or verdict.reason is Reason.WRONG_DIMENSION:
        return verdict
    first = _TRIG_OF_A_NUMBER.search(answer)
    if first is None:
        return verdict
    in_degrees = _TRIG_OF_A_NUMBER.sub(lambda m: f"{m.group(1)}{m.group(2)}{m.group(3)}°", answer)
    if _checked(in_degrees, spec).outcome is not Outcome.CORRECT:
        return verdict
    example = f"{first.group(1)}({first.group(3)}°)"
    return dataclasses.replace(
        verdict,
        feedback=f"{verdict.feedback} It would be right with its angles in degrees: a number in sin, cos or "
        f"tan is in radians unless it has a degree sign, as in {example}.",
    )


def _checked(answer: str, spec: NumericSpec) -> Verdict:
    target = spec.target_units()
    try:
        read = read_numeric_answer(
            answer, target.dimension if target is not None else None, arithmetic=spec.arithmetic
        )
        answer_units = _units_of(read, spec, target)
    except AnswerError as error:
        return Verdict.invalid(error)
    read_as = read.read_as(answer_units)
    try:
        _check_figures_shown(read, spec.tolerance)
    except SigfigsError as error:
        return Verdict.invalid(error, read_as)
    if answer_units is not None and target is not None and answer_units.dimension != target.dimension:
        return _noted(Verdict.graded(_wrong_dimension(read, answer_units, target), read_as))
    comparison = _compared(spec.expected_value, answer_units, target, spec)
    if comparison.passes(read.value):
        judgement = CORRECT
    elif (difference := comparison.as_difference()) is not None and difference.passes(read.value):
        return Verdict.invalid(_temperature_or_difference(read, comparison, difference), read_as)
    else:
        judgement = _known_mistake(read.value, answer_units, target, spec) or diagnose(
            read.value, comparison.expected_as_written, comparison.passes
        )
    remark = _cycles_or_radians(answer_units, target)
    if remark:
        # Said before the verdict's "Correct." (a page shows its own word for the verdict first and
        # drops a final "Correct."), after the reason of a wrong answer.
        feedback = f"{remark} {judgement.feedback}" if judgement.correct else f"{judgement.feedback} {remark}"
        judgement = dataclasses.replace(judgement, feedback=feedback)
    return _noted(Verdict.graded(judgement, read_as))


def _compared(
    expected: Fraction, answer_units: ParsedUnits | None, target: ParsedUnits | None, spec: NumericSpec
) -> _Comparison:
    """How an answer in `answer_units` is held against `expected` (a value in the spec's units)."""
    if answer_units is None or target is None:
        return _Comparison(expected, expected, answer_units, target, spec.tolerance)
    cycles = _cycles(answer_units, target, strict=spec.angular_units == "strict")
    as_written = target.convert(expected, answer_units) / (1 if cycles is None else cycles)
    return _Comparison(expected, as_written, answer_units, target, spec.tolerance, cycles)


def _known_mistake(
    value: Fraction, answer_units: ParsedUnits | None, target: ParsedUnits | None, spec: NumericSpec
) -> Judgement | None:
    """The first known mistake whose value the answer is within the tolerance of, as its judgement."""
    for mistake in spec.mistakes:
        if _compared(Fraction(mistake.value), answer_units, target, spec).passes(value):
            return Judgement(False, Reason.KNOWN_MISTAKE, mistake.feedback)
    return None


def _temperature_or_difference(
    read: NumericAnswer, comparison: _Comparison, difference: _Comparison
) -> AmbiguousInput:
    """`10 °C` where K are asked and 10 K is right: a temperature (283.15 K) or a change of 10 °C (10 K)?
    Asked, not graded: the part does not say which it is, and the wrong reading would use an attempt."""
    units = comparison.target.text if comparison.target is not None else ""
    temperature = f"{_shown(comparison.in_target(read.value))} {units}"
    change = f"{_shown(difference.in_target(read.value))} {units}"
    return AmbiguousInput(
        f"Is {read.text} {read.units_text} a temperature ({temperature}) or a change of temperature ({change})? "
        f"Give the answer in {units} to say which.",
        read.units_position,
        (temperature, change),
    )


def _shown(value: Fraction) -> str:
    return f"{float(value):.6g}"


def _cycles_or_radians(answer: ParsedUnits | None, target: ParsedUnits | None) -> str:
    """Hz and rad/s are both s⁻¹ once the radian is a pure number, so either is read and graded (unless
    the part asks for `angular_units: strict`); but the SI keeps the hertz for a frequency f and rad/s
    for an angular frequency ω = 2πf, and a student who mixes them up mostly mixes up f and ω too."""
    if answer is None or target is None:
        return ""
    if _hertz(answer) and _has_unit(target, "radian"):
        return "An angular frequency ω is usually given in rad/s; Hz (cycles per second) is the unit of a frequency f = ω/2π."
    if _has_unit(answer, "radian") and _hertz(target):
        return "A frequency f is usually given in Hz; rad/s is the unit of an angular frequency ω = 2πf."
    return ""


def _cycles(answer: ParsedUnits, target: ParsedUnits, *, strict: bool) -> Fraction | None:
    """The factor that takes the answer's hertz to the target's angle units (or its angle units to the
    target's hertz), a hertz being a cycle per second; else None. Only where one side counts cycles and
    the other angles (Hz against 1/s or Bq is the same s⁻¹); against radians or degrees only under
    `angular_units: strict` (by default Hz and rad/s are both s⁻¹), but against turns always: 60 rpm is
    1 Hz to every reader, and pint's 2π rad/min to anything else."""
    answer_angle = any(atom.angle for atom, _ in answer.factors)
    target_angle = any(atom.angle for atom, _ in target.factors)
    power = _hertz(answer) - _hertz(target)
    if answer_angle == target_angle or power == 0:
        return None
    if not strict and not _counts_turns(answer if answer_angle else target):
        return None
    turn = lookup("rev")
    assert turn is not None
    return turn.scale**power  # pint's 2π, to 50 digits


# The angle units that count whole turns, as a hertz counts cycles.
_TURNS = frozenset({"turn", "revolutions_per_minute", "revolutions_per_second"})


def _counts_turns(units: ParsedUnits) -> bool:
    return all(atom.name in _TURNS for atom, _ in units.factors if atom.angle)


def _hertz(units: ParsedUnits) -> int:
    """The power of hertz (any prefix) in `units`."""
    return sum(power for atom, power in units.factors if atom.name.endswith("hertz"))


def _has_unit(units: ParsedUnits, name: str) -> bool:
    return any(atom.name.endswith(name) for atom, _ in units.factors)


def _noted(verdict: Verdict) -> Verdict:
    """Feedback that starts by saying how a reading was chosen, when the expected dimension chose it."""
    note = verdict.read_as.note if verdict.read_as is not None else None
    if note is None:
        return verdict
    return dataclasses.replace(verdict, feedback=f"{note}. {verdict.feedback}")
