"""Tolerances for numeric answers, checked in exact arithmetic; every key given must pass.

Each kind is a small pure function chosen by `ToleranceKind`; bounds are inclusive. `sigfigs` rounds by
the one rule of `physics.numeric.rounding`.
"""

from __future__ import annotations

from dataclasses import dataclass
from decimal import Decimal
from enum import Enum
from fractions import Fraction

from physics.errors import SpecError
from physics.numeric.decimals import as_decimal
from physics.numeric.rounding import round_sigfigs

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


def matches_sigfigs(value: Fraction, expected: Fraction, figures: int) -> bool:
    """The value part of the sigfigs rule (the figures shown are checked when the answer is read)."""
    return value == Fraction(round_sigfigs(expected, figures))


def accepts(tolerance: Tolerance, value: Decimal, expected: Decimal) -> bool:
    """Whether every key of `tolerance` takes the exact `value` for `expected` (sigfigs: the two round
    alike), as a mistake's value it takes for the right one cannot be told from it."""
    if not tolerance.kinds:
        return value == expected
    for kind in tolerance.kinds:
        match kind:
            case ToleranceKind.RELATIVE:
                assert tolerance.rel is not None
                ok = within_relative(Fraction(value), Fraction(expected), Fraction(tolerance.rel))
            case ToleranceKind.ABSOLUTE:
                assert tolerance.abs is not None
                ok = within_absolute(Fraction(value), Fraction(expected), Fraction(tolerance.abs))
            case ToleranceKind.SIGFIGS:
                assert tolerance.sigfigs is not None
                ok = round_sigfigs(value, tolerance.sigfigs) == round_sigfigs(expected, tolerance.sigfigs)
        if not ok:
            return False
    return True
