"""Exact numbers for the builder, made with the facts of their sign already known to sympy.

The first time sympy asks a new number anything about itself (`is_zero`, as Mul does of every
coefficient), it copies the class's facts into a knowledge base of the number's own and deduces from
them again, then deduces from the answer: 50 to 80 µs for each number not met before, more than all
the rest of building a typical product. A number's sign decides most of what sympy asks, and the
facts that follow from its class (integer or fraction) and sign are the same for every number of that
class and sign: they are deduced once per class and sign, by sympy's own rules, and a number made here
starts from a copy of them. Every such fact is true of the number, so sympy answers every question as
it would have; what it does not know yet (is 149 prime?) it deduces as before.
"""

from __future__ import annotations

import sympy
from sympy.core.assumptions import StdFactKB

# The classes whose numbers are made anew for each value; the singletons (0, 1, -1, 1/2) and the
# constants keep their facts for the whole process already.
_VALUED = (sympy.Integer, sympy.Rational)
_known_by_sign: dict[tuple[type[sympy.Rational], int], StdFactKB] = {}


def exact_number(numerator: int, denominator: int) -> sympy.Rational:
    """sympy.Rational(numerator, denominator), with its class's and sign's facts known."""
    # Rational(n, 1) is Integer(n) after a gcd and two more Rational calls: a quarter of the cost direct.
    number = sympy.Integer(numerator) if denominator == 1 else sympy.Rational(numerator, denominator)
    kind = type(number)
    if kind in _VALUED and number._assumptions is kind.default_assumptions:  # never asked anything
        sign = (number.p > 0) - (number.p < 0)
        number._assumptions = _facts(kind, sign)
    return number


def _facts(kind: type[sympy.Rational], sign: int) -> StdFactKB:
    known = _known_by_sign.get((kind, sign))
    if known is None:
        told = {**kind.default_assumptions, "zero": sign == 0, "positive": sign > 0, "negative": sign < 0}
        known = _known_by_sign[kind, sign] = StdFactKB(told)  # everything sympy's rules deduce from them
    # A copy for the number alone (sympy adds what it learns of this number later). StdFactKB.copy()
    # would deduce everything again, which is the work saved here: the facts are copied as they are.
    facts = StdFactKB.__new__(StdFactKB)
    dict.update(facts, known)
    facts.rules = known.rules
    facts._generator = kind.default_assumptions.generator
    return facts
