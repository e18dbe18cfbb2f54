"""Tolerances for numeric answers, checked in exact arithmetic; every key given must pass.

Each kind is a small pure function chosen by `ToleranceKind`; bounds are inclusive.
"""

from __future__ import annotations

from dataclasses import dataclass
from decimal import Decimal
from enum import Enum
from fractions import Fraction

from physics.errors import SpecError

MAX_SIGFIGS = 40


class ToleranceKind(Enum):
    RELATIVE = "rel"
    ABSOLUTE = "abs"
    SIGFIGS = "sigfigs"


@dataclass(frozen=True)
class Tolerance:
    """`rel`: |answer − expected| ≤ rel·|expected|; `abs`: ≤ abs (in the spec's units); `sigfigs`:
    the answer shows exactly n significant figures and equals expected rounded half-up to n."""

    rel: Decimal | None = None
    abs: Decimal | None = None
    sigfigs: int | None = None

    def __post_init__(self) -> None:
        for key, bound in (("rel", self.rel), ("abs", self.abs)):
            if bound is not None and (not bound.is_finite() or bound < 0):
                raise SpecError(f"tolerance {key} must be a finite number ≥ 0, not {bound}", ("tolerance", key))
        if self.sigfigs is not None and not 1 <= self.sigfigs <= MAX_SIGFIGS:
            raise SpecError(
                f"tolerance sigfigs must be a whole number from 1 to {MAX_SIGFIGS}", ("tolerance", "sigfigs")
            )

    @property
    def kinds(self) -> tuple[ToleranceKind, ...]:
        given = ((ToleranceKind.RELATIVE, self.rel), (ToleranceKind.ABSOLUTE, self.abs))
        kinds = [kind for kind, bound in given if bound is not None]
        if self.sigfigs is not None:
            kinds.append(ToleranceKind.SIGFIGS)
        return tuple(kinds)


DEFAULT_TOLERANCE = Tolerance(rel=Decimal("0.01"))


def within_relative(value: Fraction, expected: Fraction, rel: Fraction) -> bool:
    return abs(value - expected) <= rel * abs(expected)


def within_absolute(value: Fraction, expected: Fraction, bound: Fraction) -> bool:
    return abs(value - expected) <= bound


def floor_log10(value: Fraction) -> int:
    """The exponent e with 10^e ≤ |value| < 10^(e+1), exactly; value must not be zero."""
    magnitude = abs(value)
    exponent = len(str(magnitude.numerator)) - len(str(magnitude.denominator))
    while Fraction(10) ** exponent > magnitude:
        exponent -= 1
    while Fraction(10) ** (exponent + 1) <= magnitude:
        exponent += 1
    return exponent


def round_sigfigs(value: Fraction, figures: int) -> Fraction:
    """`value` rounded to `figures` significant figures, halves away from zero (4.585 → 4.59, −4.585 → −4.59)."""
    if value == 0:
        return Fraction(0)
    step = Fraction(10) ** (floor_log10(value) - figures + 1)
    units = abs(value) / step
    rounded = int(units)
    if units - rounded >= Fraction(1, 2):
        rounded += 1
    result = rounded * step
    return result if value > 0 else -result


def matches_sigfigs(value: Fraction, expected: Fraction, figures: int) -> bool:
    """The value part of the sigfigs rule (the figures shown are checked when the answer is read)."""
    return value == round_sigfigs(expected, figures)
