"""When two sampled values count as equal: relative tolerance plus an absolute floor from the scale.

Working precision is 133 bits (~40 digits) and values must agree to 2^-83 (~1e-25): 50 bits are left
for rounding and cancellation, yet pi and 355/113 (8e-8 apart) or sqrt(2) and 1.41421356 are far apart.
The floor, tolerance x typical |reference|, lets a value that should be 0 match an exact 0.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from mpmath import libmp

from physics.symbolic.numeric import BY_VALUE, ONE, RND, ZERO, Column, Mpf

PREC = 133
TOLERANCE_BITS = 83
# A second look at two points with twice the precision catches differences below the first tolerance
# (an answer typing 30 digits of pi is still not pi; API: "3.1416 is not π").
PRECISE_PREC = 266
PRECISE_TOLERANCE_BITS = 200


def close(a: Mpf, b: Mpf, scale: Mpf, tolerance_bits: int) -> bool:
    difference = libmp.mpf_abs(libmp.mpf_sub(a, b, 64, RND))
    if difference == ZERO:
        return True
    largest = max(libmp.mpf_abs(a), libmp.mpf_abs(b), key=BY_VALUE)
    allowed = libmp.mpf_shift(libmp.mpf_add(largest, scale, 64, RND), -tolerance_bits)
    return bool(libmp.mpf_le(difference, allowed))


def typical_scale(values: Sequence[Mpf | None]) -> Mpf:
    """Median |value| over the defined points; 1 when they are all zero (values are O(1) by design)."""
    magnitudes = sorted((libmp.mpf_abs(v) for v in values if v is not None), key=BY_VALUE)
    if not magnitudes:
        return ONE
    median: Mpf = magnitudes[len(magnitudes) // 2]
    return median if median != ZERO else ONE


@dataclass(frozen=True)
class Agreement:
    """How an answer's column compares with a target's at the same points."""

    differs: bool  # some point where both are defined and the values differ
    answer_missing: tuple[int, ...]  # the target is defined there, the answer is not
    target_missing: tuple[int, ...]
    compared: int

    @property
    def agrees(self) -> bool:
        return not self.differs and not self.answer_missing and not self.target_missing and self.compared > 0


def agreement(answer: Column, target: Column, scale: Mpf, tolerance_bits: int = TOLERANCE_BITS) -> Agreement:
    answer_missing, target_missing = [], []
    compared = 0
    for index, (a, b) in enumerate(zip(answer, target, strict=True)):
        if a is None and b is None:
            continue
        if a is None:
            answer_missing.append(index)
        elif b is None:
            target_missing.append(index)
        elif close(a, b, scale, tolerance_bits):
            compared += 1
        else:
            return Agreement(True, tuple(answer_missing), tuple(target_missing), compared)
    return Agreement(False, tuple(answer_missing), tuple(target_missing), compared)


def negated(column: Column) -> Column:
    return [None if v is None else libmp.mpf_neg(v) for v in column]


def constant_ratio(answer: Column, target: Column, scale: Mpf) -> Mpf | None:
    """answer/target when it is the same number at every point where both are defined, else None."""
    tiny = libmp.mpf_shift(scale, -40)
    ratios: list[Mpf] = []
    for a, b in zip(answer, target, strict=True):
        if (a is None) != (b is None):
            return None
        if a is None or b is None:
            continue
        if libmp.mpf_le(libmp.mpf_abs(b), tiny):
            if not libmp.mpf_le(libmp.mpf_abs(a), tiny):
                return None
            continue
        ratios.append(libmp.mpf_div(a, b, PREC, RND))
    if len(ratios) < 2:
        return None
    first = ratios[0]
    if all(close(r, first, ZERO, TOLERANCE_BITS) for r in ratios[1:]):
        return first
    return None
