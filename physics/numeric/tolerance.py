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
MAX_SPEC_EXPONENT = 400  # |exponent| of a reference or tolerance value, so Fraction() stays cheap
MAX_SPEC_DIGITS = 60


def as_decimal(value: object, path: tuple[str, ...]) -> Decimal:
    """An author's number as an exact Decimal. A float is read by its shortest repr (4.5807 → 4.5807),
    which is what a JSON number meant; anything unusable is a SpecError at `path`."""
    if isinstance(value, bool) or not isinstance(value, Decimal | int | float | str):
        raise SpecError(f"{path[-1]} must be a number, not {value!r}", path)
    try:
        exact = (
            value
            if isinstance(value, Decimal)
            else Decimal(repr(value) if isinstance(value, float) else value)
        )
    except ArithmeticError as error:  # decimal.InvalidOperation for text that is not a number
        raise SpecError(f"{path[-1]} must be a number, not {value!r}", path) from error
    if not exact.is_finite():
        raise SpecError(f"{path[-1]} must be a finite number, not {value!r}", path)
    if exact and (
        abs(exact.adjusted()) > MAX_SPEC_EXPONENT or len(exact.as_tuple().digits) > MAX_SPEC_DIGITS
    ):
        raise SpecError(f"{path[-1]} is too large or too precise to check against", path)
    return exact


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
        for key in ("rel", "abs"):
            bound = getattr(self, key)
            if bound is None:
                continue
            exact = as_decimal(bound, ("tolerance", key))
            if exact < 0:
                raise SpecError(f"tolerance {key} must be ≥ 0, not {exact}", ("tolerance", key))
            object.__setattr__(self, key, exact)  # frozen: normalising what the author passed
        if self.sigfigs is not None and (
            isinstance(self.sigfigs, bool)
            or not isinstance(self.sigfigs, int)
            or not 1 <= self.sigfigs <= MAX_SIGFIGS
        ):
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
