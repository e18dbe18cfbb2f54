"""No input raises anything but an AnswerError, and what is read back parses to the same expression.

Two fuzzers: a seeded mix of the grammar's own tokens (always runs; it reaches deep into the parser),
and hypothesis over arbitrary text (runs where hypothesis is installed).
"""

from __future__ import annotations

import random

import pytest

from physics.errors import AnswerError, TooLarge
from physics.mathinput import parse_math
from tests.mathinput.support import names, same

DECLARED = names("x", "y", "theta", "v_0", "m", "M", "U0", "e1")

TOKENS = [
    "x", "y", "θ", "theta", "v0", "v_0", "m", "M", "U_0", "mM", "xy", "q", "e", "pi", "π", "2", "0", "10",
    "0.5", ".5", "1e3", "2E-2", "4,5", "12 500", "+", "-", "−", "*", "**", "/", "÷", "×", "·", "^", "(", ")",
    "[", "]", "{", "}", "|", "!", "%", "°", "deg", " x ", "²", "⁻¹", "√", "sin", "cos", "asin", "arctan",
    "ln", "log10", "sqrt", "abs", "exp", "factorial", "sinh", " ", "\u00a0", ",", "_", "#", "'", "f(",
    "sin^2", "sin^-1", "9^9^9", "1/2 ", "/2 ", "2m", "mgsin", "\\", "=", "<", "1e999", "x^-", "^^",
]  # fmt: skip


def check_one(text: str) -> None:
    try:
        parsed = parse_math(text, DECLARED)
    except AnswerError as error:
        assert error.position is None or 0 <= error.position <= len(text), (text, error.position)
        assert error.message
        return
    assert parsed.read_as.text
    assert parsed.read_as.latex
    try:
        again = parse_math(parsed.read_as.text, DECLARED)
    except TooLarge:
        return  # the explicit read-back can be longer than the limits allow
    assert same(again.expr, parsed.expr), (text, parsed.read_as.text)


@pytest.mark.parametrize("seed", range(8))
def test_random_token_mixes_raise_only_answer_errors_and_read_back_consistently(seed):
    rng = random.Random(seed)
    for _ in range(250):
        check_one("".join(rng.choice(TOKENS) for _ in range(rng.randint(1, 12))))


def test_arbitrary_text_raises_only_answer_errors():
    hypothesis = pytest.importorskip("hypothesis")
    strategies = pytest.importorskip("hypothesis.strategies")

    @hypothesis.settings(max_examples=400, deadline=None, derandomize=True)
    @hypothesis.given(strategies.text(max_size=60))
    def run(text: str) -> None:
        check_one(text)

    run()


def test_arbitrary_token_sequences_raise_only_answer_errors():
    hypothesis = pytest.importorskip("hypothesis")
    strategies = pytest.importorskip("hypothesis.strategies")

    @hypothesis.settings(max_examples=400, deadline=None, derandomize=True)
    @hypothesis.given(strategies.lists(strategies.sampled_from(TOKENS), max_size=16))
    def run(parts: list[str]) -> None:
        check_one("".join(parts))

    run()
