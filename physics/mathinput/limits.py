"""Size limits on math input, checked before anything is evaluated, so a hostile answer fails fast."""

from __future__ import annotations

from dataclasses import dataclass

from physics.pickling import pickled_by_fields


@pickled_by_fields
@dataclass(frozen=True)
class InputLimits:
    max_length: int = 2000  # characters
    max_tokens: int = 400
    max_depth: int = 40  # nesting of parentheses / operators
    max_number_digits: int = 40  # digits in one number literal
    max_exponent: int = 100  # |integer exponent| on a non-numeric base, e.g. (x+2)^10000 refused
    max_int_bits: int = 4096  # magnitude of any exact integer/rational built from literals, e.g. 9^9^9
    max_sci_exponent: int = 400  # |k| in 1.5e<k> and 10^k
    max_factorial: int = 100  # n in n! / factorial(n)


DEFAULT_LIMITS = InputLimits()
