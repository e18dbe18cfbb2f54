"""A mixed number as a recipe or a ruler writes it (`1 1/2`, `1½`, `1 ½`): one and a half, never the
product 1·½ that the same characters spell in math. Refused, with the fraction or decimal to type."""

from __future__ import annotations

from fractions import Fraction

from physics.errors import LikelySlip


def mixed_number_slip(whole: int, part: Fraction, typed: str, position: int) -> LikelySlip:
    """The refusal of `typed` (`1 1/2`, `2¾`): whole and part as one fraction, and as a decimal where
    it ends (`3/2 or 1.5`; `4/3` alone for 1⅓)."""
    value = whole + part
    written = f"{value.numerator}/{value.denominator}"
    bottom = value.denominator
    while bottom % 2 == 0:
        bottom //= 2
    while bottom % 5 == 0:
        bottom //= 5
    if bottom == 1:  # a decimal that ends: the denominator's only factors are 2 and 5
        written += f" or {_decimal(value)}"
    return LikelySlip(
        f"Write a mixed number as one fraction or a decimal ({written}), not {typed}, which reads as "
        "a product of the numbers.",
        position,
    )


def _decimal(value: Fraction) -> str:
    digits = 1
    while (value * 10**digits).denominator != 1:
        digits += 1
    shown = str(int(value * 10**digits)).rjust(digits + 1, "0")
    return f"{shown[:-digits]}.{shown[-digits:]}"
