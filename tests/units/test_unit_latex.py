"""Units pasted as LaTeX read as the plain units they show, with errors at what was typed."""

from __future__ import annotations

import pytest

from physics.errors import AnswerError, ParseError, UnknownUnit
from physics.units import parse_units

LATEX_UNITS = [
    # (LaTeX, the plain units it shows)
    (r"\mathrm{m/s^2}", "m/s^2"),
    (r"\text{ m/s}^2", "m/s^2"),  # the power is printed on the s
    (r"\mathrm{m}/\mathrm{s}^{2}", "m/s^2"),
    (r"\mathrm{m}\,\mathrm{s}^{-2}", "m s^-2"),
    (r"\mathrm{kg}\cdot\mathrm{m}^{2}/\mathrm{s}^{2}", "kg·m^2/s^2"),
    (r"\mathrm{N}\times\mathrm{m}", "N*m"),
    (r"\mathrm{kg\,m/s^2}", "kg m/s^2"),
    (r"\frac{\mathrm{m}}{\mathrm{s}^{2}}", "m/s^2"),
    (r"\frac{\mathrm{J}}{\mathrm{kg}}\,\mathrm{K}", "(J/kg) K"),
    (r"\mu\mathrm{m}", "µm"),  # TeX prints side by side what is typed side by side
    (r"\mu m", "µm"),
    (r"\mathrm{k}\Omega", "kΩ"),
    (r"\Omega", "Ω"),
    (r"^{\circ}\mathrm{C}", "°C"),
    (r"{}^{\circ}\mathrm{C}", "°C"),
    (r"^\circ", "°"),
    (r"\text{m}~\text{s}^{-1}", "m s^-1"),
    (r"\operatorname{rad}/\mathrm{s}", "rad/s"),
    (r"m/s^{2}", "m/s^2"),
    (r"{\rm m/s^2}", "m/s^2"),  # plain TeX's roman, a font switch
    (r"\rm kg\,m^2", "kg m^2"),
]


@pytest.mark.parametrize(("latex", "plain"), LATEX_UNITS, ids=[u[0] for u in LATEX_UNITS])
def test_latex_units_read_as_the_plain_units_they_show(latex, plain):
    assert parse_units(latex) == parse_units(plain)


@pytest.mark.parametrize("plain", ["m/s^2", "kg·m^2/s^2", "J/(kg·K)", "µm", "kΩ", "°C", "N·m", "rad/s", "°"])
def test_the_latex_of_units_reads_back_as_the_same_units(plain):
    units = parse_units(plain)
    assert parse_units(units.latex) == units


LATEX_UNIT_ERRORS = [
    # (LaTeX, position, words the message must contain)
    (r"\mathrm{m/s^2", 7, "this '{' is never closed"),
    (r"\mathrm{m}}", 10, "Unmatched '}'"),
    (r"\mathrm m", 8, r"\mathrm needs braces after it"),
    (r"\mathrm{m}\foo", 10, r"Unknown LaTeX command \foo in the units"),
    (r"\frac{\mathrm{m}}", 17, r"\frac{…} needs braces after it"),
    (r"\mathrm{m}\,\mathrm{s}^{1.5}", 25, "whole numbers"),
    (r"\mathrm{m}\\", 10, r"Unknown LaTeX command \\"),
    ("\\mathrm{m}\\", 10, "A '\\' ends the units"),
]


@pytest.mark.parametrize(
    ("latex", "position", "words"), LATEX_UNIT_ERRORS, ids=[e[0] for e in LATEX_UNIT_ERRORS]
)
def test_latex_unit_errors_point_at_what_was_typed(latex, position, words):
    with pytest.raises(ParseError) as caught:
        parse_units(latex)
    assert caught.value.position == position
    assert words in caught.value.message


def test_an_unknown_unit_in_latex_is_named_at_its_position():
    with pytest.raises(UnknownUnit) as caught:
        parse_units(r"\mathrm{m}/\mathrm{xyz}")
    assert caught.value.unit == "xyz"
    assert caught.value.position == 19


@pytest.mark.parametrize("text", ["\\" * 100, "{" * 100, r"\frac{" * 16, r"\mathrm{" * 12 + "m" + "}" * 12])
def test_hostile_latex_units_are_refused(text):
    with pytest.raises(AnswerError):
        parse_units(text)
