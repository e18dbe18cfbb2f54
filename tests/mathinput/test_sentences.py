"""An answer typed as a sentence is refused saying to type the expression alone, showing it; words that
are declared symbols, or names a student may have meant, are read or asked about as before."""

from __future__ import annotations

import pytest

from physics.errors import ParseError, UnknownSymbol
from tests.mathinput.support import read

PENDULUM = ("L", "g", "T")
SENTENCES = [
    # (typed, declared, the expression the refusal shows, the sentence it quotes): each was once
    # 'Unknown symbol "The"'
    ("The period is 2π√(L/g)", PENDULUM, "2π√(L/g)", "The period is"),
    ("The period T is 2π√(L/g) seconds", PENDULUM, "2π√(L/g)", "The period T is"),
    ("Period equals 2*pi*sqrt(L/g).", PENDULUM, "2*pi*sqrt(L/g)", "Period equals"),
    ("the answer is m g sin θ newtons", ("m", "g", "theta"), "m g sin θ", "the answer is"),
    ("this gives (m+M) g", ("m", "M", "g"), "(m+M) g", "this gives"),
    ("It is \\frac{m g}{k}", ("m", "g", "k"), "\\frac{m g}{k}", "It is"),
    # the answer's declared name and a verb: once 'Unknown symbol "is"'
    ("T is 2π√(L/g)", PENDULUM, "2π√(L/g)", "T is"),
    ("T equals 2π√(L/g) seconds", PENDULUM, "2π√(L/g)", "T equals"),
]


@pytest.mark.parametrize(
    ("typed", "declared", "expression", "sentence"), SENTENCES, ids=[c[0] for c in SENTENCES]
)
def test_an_answer_typed_as_a_sentence_is_refused_showing_the_expression_to_type(
    typed: str, declared: tuple[str, ...], expression: str, sentence: str
) -> None:
    with pytest.raises(ParseError) as caught:
        read(typed, *declared)
    assert caught.value.message == (
        f'"{sentence}" is a sentence, which is not read: type only the expression, as in {expression}.'
    )
    assert caught.value.position == 0


NOT_SENTENCES = [
    # (typed, declared, the unknown symbol named): words that may be names, asked about as names
    ("vx vy", ("m",), "vx"),  # two undeclared names, no sentence's word among them
    ("Delta x/t", ("Delta_x", "t"), "Delta"),  # `\Delta x` in plain text: said to type it without the space
    ("The m g", ("m", "g"), "The"),  # one word before the expression
    ("the answer is", ("m",), "the"),  # no expression after the words
]


@pytest.mark.parametrize(("typed", "declared", "unknown"), NOT_SENTENCES, ids=[c[0] for c in NOT_SENTENCES])
def test_words_that_may_be_names_are_not_taken_for_a_sentence(
    typed: str, declared: tuple[str, ...], unknown: str
) -> None:
    with pytest.raises(UnknownSymbol) as caught:
        read(typed, *declared)
    assert caught.value.symbol == unknown


def test_a_sentence_word_that_reads_as_declared_symbols_is_read() -> None:
    assert read("the g", "t", "h", "e", "g").read_as.text == "t*h*e*g"


EQUATIONS = [
    # (typed, the refusal, where): an equation's one side a name, shown the other side to type (once
    # "Give the expression alone, without '=' (nor the name before it)." for each)
    ("T = 2π√(L/g)", "Give the expression alone, without 'T =': type only 2π√(L/g).", 2),
    ("T=2π√(L/g) seconds", "Give the expression alone, without 'T =': type only 2π√(L/g).", 1),
    ("T ≈ 2π√(L/g)", "Give the expression alone, without 'T ≈': type only 2π√(L/g).", 2),
    ("2π√(L/g) = T", "Give the expression alone, without '= T': type only 2π√(L/g).", 9),
    # neither side a name alone: said without showing one
    ("T(L) = 2π√(L/g)", "Give the expression alone, without '=' (nor the name before it).", 5),
    ("T = 2π√(L/g) = 2 s", "Give the expression alone, without '=' (nor the name before it).", 2),
]


@pytest.mark.parametrize(("typed", "message", "position"), EQUATIONS, ids=[c[0] for c in EQUATIONS])
def test_an_answer_typed_as_an_equation_is_refused_showing_the_side_to_type(
    typed: str, message: str, position: int
) -> None:
    with pytest.raises(ParseError) as caught:
        read(typed, *PENDULUM)
    assert (caught.value.message, caught.value.position) == (message, position)
