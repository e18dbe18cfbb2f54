"""A number made by `exact_number` starts with its sign's facts known, and sympy answers every question
about it exactly as about the same number made by sympy.Rational and asked afresh."""

from __future__ import annotations

import pytest
import sympy
from sympy.core.assumptions import _assume_defined
from sympy.core.cache import clear_cache

from physics.mathinput.exact import exact_number

FACTS = sorted(_assume_defined)
NUMBERS = [
    (149, 1),
    (-149, 1),
    (2, 1),
    (9, 1),
    (22201, 1),
    (10**30 + 1, 1),
    (-(10**30), 1),
    (1, 7),
    (-3, 7),
    (981, 100),
    (-981, 100),
    (1, 10**40),
    # singletons: left as sympy makes them
    (0, 1),
    (1, 1),
    (-1, 1),
    (1, 2),
]


def _facts(number: sympy.Rational) -> dict[str, bool | None]:
    return {fact: getattr(number, f"is_{fact}") for fact in FACTS}


@pytest.mark.parametrize(("p", "q"), NUMBERS)
def test_every_fact_of_a_number_is_what_sympy_finds_afresh(p, q):
    clear_cache()  # a new object, asked nothing yet (sympy keeps numbers in its cache)
    fresh = sympy.Rational(p, q)
    expected = _facts(fresh)
    clear_cache()
    made = exact_number(p, q)
    assert made == fresh and type(made) is type(fresh)
    assert _facts(made) == expected
    assert dict(made._assumptions) == dict(fresh._assumptions)  # and sympy knows the same of both


@pytest.mark.parametrize(("p", "q"), [(149, 1), (-3, 7), (981, 100)])
def test_a_new_number_starts_with_its_sign_known(p, q):
    clear_cache()
    made = exact_number(p, q)
    assert made._assumptions is not type(made).default_assumptions
    assert made._assumptions["zero"] is False
    assert made._assumptions["positive"] is (p > 0)


def test_what_sympy_learns_of_one_number_is_not_known_of_another():
    clear_cache()
    seven, nine = exact_number(7, 1), exact_number(9, 1)
    assert seven.is_prime is True
    assert nine.is_prime is False
    assert seven.is_odd and nine.is_odd and exact_number(10, 1).is_even


def test_a_number_sympy_was_asked_about_keeps_what_it_knows():
    clear_cache()
    number = sympy.Integer(123457)
    assert number.is_prime is True
    before = number._assumptions
    assert exact_number(123457, 1) is number
    assert number._assumptions is before
