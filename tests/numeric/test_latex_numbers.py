"""Numeric answers pasted as LaTeX read as the plain answers they show: the same value, significant
figures and units; what cannot be read is refused at what was typed."""

from __future__ import annotations

import pytest

from physics.errors import AnswerError, ParseError
from physics.numeric import read_numeric_answer

LATEX_ANSWERS = [
    # (LaTeX, the plain answer it shows)
    (r"4.58\,\mathrm{m/s^2}", "4.58 m/s^2"),
    (r"4.58 \text{ m/s}^2", "4.58 m/s^2"),
    (r"4.58\ \mathrm{m}\,\mathrm{s}^{-2}", "4.58 m s^-2"),
    (r"4.58\,\frac{\mathrm{m}}{\mathrm{s}^{2}}", "4.58 m/s^2"),
    (r"4.58 \times 10^{3}\,\mathrm{m}", "4.58×10^3 m"),
    (r"4.58\cdot10^{-3}~\mathrm{kg}", "4.58e-3 kg"),
    (r"-1.20\times 10^{2}\,\mathrm{N}", "-1.20e2 N"),
    (r"12\,\mu\mathrm{m}", "12 µm"),
    (r"45\%", "45%"),
    (r"45\,\%", "45%"),
    (r"30^{\circ}", "30°"),
    (r"25\,^{\circ}\mathrm{C}", "25 °C"),
    (r"2.2\,\mathrm{k}\Omega", "2.2 kΩ"),
    (r"\frac{229}{50}\,\mathrm{m/s^2}", "229/50 m/s^2"),
    (r"2\pi\,\mathrm{rad}", "2π rad"),
    (r"2\pi \cdot \mathrm{rad}", "2π rad"),
    (r"\sqrt{2}\,\mathrm{m}", "sqrt(2) m"),
    (r"9.8\sin 30^\circ", "9.8 sin 30°"),
    (r"\frac{1}{2}", "1/2"),
    (r"0.5\,\mathrm{kg} \cdot 9.8\,\mathrm{m/s^2}", "0.5 kg * 9.8 m/s^2"),
    (r"2\,\mathrm{m} \times 3\,\mathrm{s}", "2 m * 3 s"),
]


@pytest.mark.parametrize(("latex", "plain"), LATEX_ANSWERS, ids=[a[0] for a in LATEX_ANSWERS])
def test_a_latex_answer_reads_as_the_plain_answer_it_shows(latex, plain):
    got, expected = read_numeric_answer(latex), read_numeric_answer(plain)
    assert got.value == expected.value
    assert got.units == expected.units
    assert got.text == expected.text
    if expected.literal is not None:  # significant figures survive the LaTeX
        assert got.literal is not None
        assert got.literal.sigfig_range == expected.literal.sigfig_range


def test_latex_units_start_where_they_were_typed():
    answer = read_numeric_answer(r"4.58\,\mathrm{m/s^2}")
    assert answer.units_position == 6


LATEX_ERRORS = [
    # (LaTeX, position, words the message must contain)
    (r"4.58\,\mathrm{m/s^2", 13, "never closed"),
    (r"4.58\,\mathrm{m}\foo", 16, r"Unknown LaTeX command \foo in the units"),
    (r"\frac{229}{50}\,\mathrm{m/s^2}\vec", 30, r"Unknown LaTeX command \vec"),
    (r"\frac{229}{50", 10, r"the '{' of \frac is never closed"),
    (r"4.58\,\mathrm{m}^{1.5}", 19, "whole numbers"),
    (r"a = 4.58\,\mathrm{m/s^2}", 2, r"Give the value alone, without 'a =': type only 4.58\,\mathrm{m/s^2}"),
    (r"\approx 4.58", 0, r"Unknown LaTeX command \approx: type only the expression"),
    # LaTeX's decimal comma, braced so that no space follows it: the decimal comma's own message
    (r"4{,}58\,\mathrm{m/s^2}", 2, "4,58: a decimal comma is not read; write 4.58"),
    (r"\frac{4{,}58}{2}\,\mathrm{m/s^2}", 8, "4,58: a decimal comma is not read; write 4.58"),
    # siunitx's quantity, as a LaTeX-writing student sets one: once "type that part in plain text" alone
    (r"\SI{4.58}{m/s^2}", 0, r"Unknown LaTeX command \SI: type the value and its units in plain text, as in"),
    (r"\qty{4.58}{\metre\per\second\squared}", 0, "siunitx's commands are not read"),
]


@pytest.mark.parametrize(("latex", "position", "words"), LATEX_ERRORS, ids=[e[0] for e in LATEX_ERRORS])
def test_a_latex_answer_that_cannot_be_read_is_refused_at_what_was_typed(latex, position, words):
    with pytest.raises(ParseError) as caught:
        read_numeric_answer(latex)
    assert caught.value.position == position
    assert words in caught.value.message


@pytest.mark.parametrize(
    "text",
    [
        r"\frac{" * 60 + "1" + "}{2}" * 60,
        "\\" * 199,
        r"4.58\,\mathrm{" * 14,
    ],
    ids=["deep fractions", "backslashes", "open fonts"],
)
def test_latex_answers_beyond_the_reader_are_refused(text):
    with pytest.raises(AnswerError) as caught:
        read_numeric_answer(text)
    assert 0 <= (caught.value.position or 0) <= len(text)
