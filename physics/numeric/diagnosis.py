"""Common slips behind a wrong numeric answer: a flipped sign, a power of ten, a simple factor.

Data apart from the algorithm: each slip is the factors it would explain and what to tell the
student. Feedback names the kind of slip, never the expected value.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from fractions import Fraction

from physics.numeric.rounding import floor_log10
from physics.verdict import Judgement, Reason

# π to far more places than any tolerance can see; used only to recognise 2π and degree slips.
_PI = Fraction("3.141592653589793238462643")  # 25 digits: short keeps Fraction arithmetic fast
_MAX_POWER_OF_TEN = 15


@dataclass(frozen=True)
class Slip:
    factors: tuple[Fraction, ...]  # the answer is the expected value times one of these
    reason: Reason
    feedback: str
    exact: bool  # multiplying by these keeps a decimal literal's digits (sign, powers of ten)

    def candidates(self, ratio: Fraction) -> tuple[Fraction, ...]:
        """The factors worth trying when answer/expected is `ratio`."""
        return self.factors


@dataclass(frozen=True)
class PowerOfTenSlip(Slip):
    """Only the one or two powers of ten nearest the ratio can explain it; trying all would be slow."""

    def candidates(self, ratio: Fraction) -> tuple[Fraction, ...]:
        if ratio == 0:
            return ()
        nearest = floor_log10(ratio)
        return tuple(f for f in (Fraction(10) ** nearest, Fraction(10) ** (nearest + 1)) if f in self.factors)


def _both_ways(*factors: Fraction) -> tuple[Fraction, ...]:
    return tuple(f for factor in factors for f in (factor, 1 / factor))


SLIPS: tuple[Slip, ...] = (
    Slip((Fraction(-1),), Reason.SIGN_ERROR, "Check the sign of your answer.", exact=True),
    PowerOfTenSlip(
        _both_ways(*(Fraction(10) ** k for k in range(1, _MAX_POWER_OF_TEN + 1))),
        Reason.CONSTANT_FACTOR,
        "Your answer is off by a power of ten: check your unit prefixes / powers of ten.",
        exact=True,
    ),
    Slip(
        _both_ways(Fraction(2), Fraction(4)),
        Reason.CONSTANT_FACTOR,
        "Your answer is off by a simple factor (such as 2): check for a missing or extra factor.",
        exact=False,
    ),
    Slip(
        _both_ways(2 * _PI),
        Reason.CONSTANT_FACTOR,
        "Your answer is off by a factor of 2π: check whether you mixed up frequency and angular "
        "frequency, or revolutions and radians.",
        exact=False,
    ),
    Slip(
        _both_ways(180 / _PI),
        Reason.CONSTANT_FACTOR,
        "Your answer is off by the factor between degrees and radians: check your angle units "
        "(and your calculator's angle mode).",
        exact=False,
    ),
    Slip(
        _both_ways(Fraction(60), Fraction(3600), Fraction(18, 5)),
        Reason.CONSTANT_FACTOR,
        "Your answer is off by a unit-conversion factor (such as 60 or 3.6): check how you converted "
        "units of time or speed.",
        exact=False,
    ),
    Slip(  # the number right in metres, written in feet (or the other way): the foot, the inch, the
        # pound, the mile and the pound-force to their SI units
        _both_ways(
            Fraction("0.3048"),
            Fraction("0.0254"),
            Fraction("0.45359237"),
            Fraction("1.609344"),
            Fraction("4.4482216152605"),
        ),
        Reason.CONSTANT_FACTOR,
        "Your number would be right in other units than the ones you wrote (it is off by a factor such as "
        "0.3048 m per ft or 0.4536 kg per lb): check your units.",
        exact=False,
    ),
)

WRONG_VALUE = Judgement(
    False, Reason.WRONG_VALUE, "Your answer is not within the accepted tolerance of the correct value."
)


def diagnose(value: Fraction, expected: Fraction, passes: Callable[[Fraction, bool], bool]) -> Judgement:
    """Why `value` (which does not pass) is wrong: the first slip that would explain it, else wrong_value.

    `value` and `expected` are in the same units. `passes(candidate, exact)` says whether a corrected
    candidate would pass; `exact` is False when the correction spoils the literal's digits, so that a
    significant-figures rule can only be applied approximately.
    """
    if value == 0 or expected == 0:
        return WRONG_VALUE
    ratio = value / expected
    for slip in SLIPS:
        if any(passes(value / factor, slip.exact) for factor in slip.candidates(ratio)):
            return Judgement(False, slip.reason, slip.feedback)
    return WRONG_VALUE
