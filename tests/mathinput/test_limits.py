"""Hostile answers are refused as TooLarge before anything expensive runs (no timing asserts: each
case here would run for minutes or eat gigabytes if a check were missing, and the test timeout catches it)."""

from __future__ import annotations

import pytest

from physics.errors import TooLarge
from physics.mathinput import DEFAULT_LIMITS, InputLimits, parse_math
from tests.mathinput.support import names, read

HOSTILE = [
    ("one megabyte", "x" * 1_000_000),
    ("one megabyte of spaces", " " * 1_000_000),
    ("9^9^9", "9^9^9"),
    ("exponent too big for a float", "9^9^922"),
    ("fractional exponent too big for a float", "3^(9^922/7)"),
    ("2^2^2^2^2^2", "2^2^2^2^2^2"),
    ("1e999999", "1e999999"),
    ("1e-999999", "1e-999999"),
    ("long sci exponent", "1e" + "9" * 100),
    ("factorial(10^9)", "factorial(10^9)"),
    ("10^9!", "10^9!"),
    ("(10^9)!", "(10^9)!"),
    ("101!", "101!"),
    ("100000 nested brackets", "(" * 100_000 + "x" + ")" * 100_000),
    ("(x+2)^10000", "(x+2)^10000"),
    ("x^(2^100)", "x^(2^100)"),
    ("x^(-101)", "x^(-101)"),
    ("merged powers", "((x+2)^100)^100"),
    ("merged product of powers", "(x+2)^60 (x+2)^60"),
    ("10^401", "10^401"),
    ("10^-401", "10^-401"),
    ("big power of a fraction", "(1/3)^-3000"),
    ("product of big numbers", "(2^4000)(2^4000)"),
    ("deep root of a number", "16^(1/2^100)"),
    ("sqrt(2)^1000", "sqrt(2)^1000"),
    ("pi^1000", "pi^1000"),
    ("41 digits", "1" * 41),
    ("too many tokens", "x+" * 300 + "x"),
    ("41 nested brackets", "(" * 41 + "x" + ")" * 41),
    ("41 unary minus", "-" * 41 + "x"),
    ("41 nested powers", "x" + "^x" * 41),
    ("glued run too long", "x" * 100),
    ("superscript flood", "x" + "⁹" * 30),
    # sympy asks whether sec(...) is real by reducing its argument modulo π, with π to as many bits as
    # the argument's magnitude (e^(10^40)) has.
    ("function of an astronomical constant", "sec(sinh(10^40)^2)"),
    ("atanh of an astronomical constant", "atanh(exp(2^4000))"),
    # Building a root or abs() of roots of negatives, sympy asks whether each inner root is real, and
    # that asks the same of the roots inside it: seconds at eight deep, 0.6 s for abs of a sum at three.
    ("cube roots of negatives nested nine deep", "(-" * 9 + "x" + ")^(1/3)" * 9),
    ("LaTeX cube roots of negatives nested nine deep", r"\sqrt[3]{-" * 9 + "x" + "}" * 9),
    (
        "abs of a sum of roots of negatives three deep",
        "abs(" + "+".join(["(-(-(-x)^(1/5))^(1/5))^(1/5)"] * 4) + ")",
    ),
    ("fifth roots of a negative sum nested seven deep", "(-1-" * 7 + "x" + ")^(1/5)" * 7),
    # A function asks whether its argument is real, and sympy writes out the real and imaginary parts
    # of an argument that may be complex: (a + ib)^100 in 101 terms, functions of them twice over.
    ("function of a function of a complex power", "tanh(cosh(acos(x)^100))"),
    ("abs of a function of a complex power", "abs(cosh(acos(x)^100))"),
    # sympy reduces the angle modulo 2π and cannot decide the comparison with π past its precision.
    ("inverse trig of trig of a huge angle", "asin(sin(10^300))"),
    ("LaTeX inverse trig of trig of a huge angle", r"\arccos\left(\cos\left(2^{1000}\right)\right)"),
    ("LaTeX squared cosh nested five deep", r"\cosh^2\cosh^2\cosh^2\cosh^2\cosh^2\arccos x"),
]


@pytest.mark.parametrize("text", [h[1] for h in HOSTILE], ids=[h[0] for h in HOSTILE])
def test_hostile_input_is_refused_as_too_large(text):
    with pytest.raises(TooLarge) as caught:
        read(text, "x")
    assert caught.value.reason == "too_large"
    assert caught.value.position is not None
    assert 0 <= caught.value.position <= len(text)


def test_deep_nesting_is_too_large_not_a_recursion_error_even_with_lifted_size_limits():
    lifted = InputLimits(max_length=10**6, max_tokens=10**6)
    with pytest.raises(TooLarge):
        parse_math("(" * 100_000 + "x" + ")" * 100_000, names("x"), limits=lifted)


WITHIN_LIMITS = [
    "(x+2)^100",
    "x^-100",
    "10^400",
    "1e400",
    "1e-400",
    "100!",
    "2^4000",
    "1" * 40,
    "(" * 30 + "x" + ")" * 30,
    "x+" * 199 + "x",
    "1^(10^300)",
    "e^200",
    "exp(10^6)",
    "x^(1/100)",
    "(-(-x)^(1/3))^(1/3)",  # roots of what may be negative, two deep
    r"\sqrt{2 x \left(x - \sqrt{x^2 - 1}\right)}",
    "sqrt(1 + sqrt(1 + sqrt(1 + sqrt(1 + x))))",  # roots of what is surely positive, any depth
    "acos(x)^100",  # a power that may be complex, no function asking about it
    "abs(cosh(acos(x)^12))",
    "sqrt(1 - x^2)^3 asin(x)^2 log(x - 1)",
    "log10(" * 12 + "x^2+2" + ")" * 12,
    "asin(sin(10^90))",
]


@pytest.mark.parametrize("text", WITHIN_LIMITS)
def test_input_at_the_limits_is_read(text):
    read(text, "x")


def test_limits_are_configurable():
    tight = InputLimits(max_length=5)
    with pytest.raises(TooLarge):
        parse_math("x+x+x", names("x"), limits=InputLimits(max_length=4))
    parse_math("x+x+x", names("x"), limits=InputLimits(max_length=5))
    assert tight.max_tokens == DEFAULT_LIMITS.max_tokens
    with pytest.raises(TooLarge):
        parse_math("x^3", names("x"), limits=InputLimits(max_exponent=2))
    with pytest.raises(TooLarge):
        parse_math("4!", names("x"), limits=InputLimits(max_factorial=3))


def test_too_long_points_at_the_first_character_past_the_limit():
    with pytest.raises(TooLarge) as caught:
        read("x" * 2001, "x")
    assert caught.value.position == DEFAULT_LIMITS.max_length


def _repeated(piece: str, joiner: str, count: int) -> str:
    return joiner.join([piece] * count)


COSTLY_NUMBERS = [
    # sympy would factor each radicand (seconds in total), so roots share a budget
    ("many roots of 38-digit numbers", _repeated("sqrt(30062827503801437255781353093407281)", "*", 40)),
    ("root of a big fraction", "(12345678901234567890123/98765432109876543210987)^(1/7)"),
    ("high root of a fraction", "(123456789/987654321)^(1/99)"),
    ("root of a huge number", "sqrt(2^4000+1)"),
    # each distinct huge number costs sympy work in trig/log, so their total size is bounded
    ("trig of pi over huge numbers", _repeated("sin(pi/(2^4000+1))", "+", 20)),
]


@pytest.mark.parametrize("text", [c[1] for c in COSTLY_NUMBERS], ids=[c[0] for c in COSTLY_NUMBERS])
def test_costly_exact_numbers_are_refused_as_too_large(text):
    with pytest.raises(TooLarge):
        read(text, "x")


UNDEFINED = ["1/0", "0^-1", "log(0)", "0/0", "x/(x-x)", "factorial(-1)"]


@pytest.mark.parametrize("text", UNDEFINED)
def test_answer_without_a_value_is_a_parse_error(text):
    from physics.errors import ParseError

    with pytest.raises(ParseError) as caught:
        read(text, "x")
    assert "divides by zero" in caught.value.message
