"""The one rounding rule: a value to n significant figures, exactly, as the decimal that shows them.

Grading (`sigfigs` tolerances), the self-test's typed answers, the instructor's shown references and
the drawing of given values all round here, so what is shown and what is graded cannot disagree.
The rule is half-up (halves away from zero: 4.585 → 4.59, −4.585 → −4.59), as API.md states; drawing
given values passes its own direction (half-even, or towards the range it must stay in).
"""

from __future__ import annotations

import math
from decimal import ROUND_CEILING, ROUND_FLOOR, ROUND_HALF_EVEN, ROUND_HALF_UP, Decimal
from fractions import Fraction

ROUNDINGS = (ROUND_HALF_UP, ROUND_HALF_EVEN, ROUND_CEILING, ROUND_FLOOR)


def floor_log10(value: Fraction | Decimal) -> int:
    """The exponent e with 10^e ≤ |value| < 10^(e+1), exactly; value must not be zero."""
    if isinstance(value, Decimal):
        return value.adjusted()
    magnitude = abs(value)
    exponent = len(str(magnitude.numerator)) - len(str(magnitude.denominator))
    while Fraction(10) ** exponent > magnitude:
        exponent -= 1
    while Fraction(10) ** (exponent + 1) <= magnitude:
        exponent += 1
    return exponent


def round_sigfigs(value: Fraction | Decimal | int, figures: int, rounding: str = ROUND_HALF_UP) -> Decimal:
    """`value` to `figures` significant figures, as a Decimal that shows exactly that many (2.5 to 3 is 2.50).

    `rounding` is one of ROUNDINGS (the decimal module's names); 0 stays 0.
    """
    if figures < 1:
        raise ValueError(f"round to at least one significant figure, not {figures}")
    exact = value if isinstance(value, Decimal) else Fraction(value)
    if exact == 0:
        return Decimal(0)
    exponent = floor_log10(exact) - figures + 1
    scaled = Fraction(exact) / Fraction(10) ** exponent  # figures digits before the point
    if rounding == ROUND_HALF_UP:
        whole = math.floor(abs(scaled) + Fraction(1, 2)) * (1 if scaled > 0 else -1)
    elif rounding == ROUND_HALF_EVEN:
        whole = round(scaled)
    elif rounding == ROUND_CEILING:
        whole = math.ceil(scaled)
    elif rounding == ROUND_FLOOR:
        whole = math.floor(scaled)
    else:
        raise ValueError(f"rounding must be one of {', '.join(ROUNDINGS)}, not {rounding!r}")
    if abs(whole) == 10**figures:  # 9.96 to 2 figures is 10: one digit more, so one place up
        whole //= 10
        exponent += 1
    digits = tuple(int(d) for d in str(abs(whole)))
    return Decimal((0 if whole > 0 else 1, digits, exponent))
