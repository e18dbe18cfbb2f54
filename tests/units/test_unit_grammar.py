"""The unit-string grammar: equivalent spellings, the `/` rule, glued names, canonical text, errors."""

from __future__ import annotations

import pytest

from physics.errors import AmbiguousInput, AnswerError, ParseError, TooLarge, UnknownUnit
from physics.units import parse_units

SAME_UNITS = [
    # (text, canonical text)
    ("m/s^2", "m/s^2"),
    ("m s^-2", "m/s^2"),
    ("m·s⁻²", "m/s^2"),
    ("m⋅s⁻²", "m/s^2"),
    ("m/s/s", "m/s^2"),
    ("m/s²", "m/s^2"),
    ("m*s**-2", "m/s^2"),
    ("m s^(-2)", "m/s^2"),
    ("m s^−2", "m/s^2"),  # Unicode minus
    ("m s^-²", "m/s^2"),  # the caret and the minus typed, then the palette's ²
    ("m s^−²", "m/s^2"),
    ("m⁄s²", "m/s^2"),  # the fraction slash, the division slash and ÷, as the math reader takes them
    ("m∕s²", "m/s^2"),
    ("m÷s²", "m/s^2"),
    ("kg∙m/s²", "kg·m/s^2"),  # the bullet operator, the bullet and the asterisk operator
    ("kg•m/s²", "kg·m/s^2"),
    ("kg∗m/s²", "kg·m/s^2"),
    ("m/(s s)", "m/s^2"),
    ("m/(s*s)", "m/s^2"),
    ("(m/s)/s", "m/s^2"),
    ("J/kg K", "J/(kg·K)"),
    ("J/(kg K)", "J/(kg·K)"),
    ("J/(kg·K)", "J/(kg·K)"),
    ("J kg^-1 K^-1", "J/(kg·K)"),
    ("J/kg/K", "J/(kg·K)"),
    ("kg·m²/s²", "kg·m^2/s^2"),
    ("kg m^2 s^-2", "kg·m^2/s^2"),
    ("kg m/s^2", "kg·m/s^2"),
    ("kg·m/s²", "kg·m/s^2"),
    ("kg×m/s²", "kg·m/s^2"),
    ("(m/s)^2", "m^2/s^2"),
    ("Nm", "N·m"),
    ("N m", "N·m"),
    ("N·m", "N·m"),
    ("N*m", "N·m"),
    ("kgm/s", "kg·m/s"),
    ("Pas", "Pa·s"),
    ("ss", "s^2"),
    ("mins", "min"),
    ("hrs", "h"),
    ("secs", "s"),
    ("((((m))))", "m"),
    ("1/s", "1/s"),
    ("s^-1", "1/s"),
    ("s⁻¹", "1/s"),
    ("1", "1"),
    ("m/m", "1"),
    ("km/h", "km/h"),
    ("kWh", "kWh"),
    ("um", "µm"),
    ("deg", "°"),
    ("sec", "s"),
    ("  m / s ^ 2  ", "m/s^2"),
]


@pytest.mark.parametrize(("text", "canonical"), SAME_UNITS, ids=[c[0] for c in SAME_UNITS])
def test_spelling_has_canonical_text(text: str, canonical: str) -> None:
    assert parse_units(text).text == canonical


@pytest.mark.parametrize(("text", "canonical"), SAME_UNITS, ids=[c[0] for c in SAME_UNITS])
def test_canonical_text_reads_back_as_the_same_units(text: str, canonical: str) -> None:
    assert parse_units(canonical) == parse_units(text)


def test_everything_after_a_single_slash_is_the_denominator() -> None:
    assert parse_units("J/kg K") == parse_units("J/(kg·K)")
    assert parse_units("J/kg K") != parse_units("J·K/kg")


def test_each_of_several_slashes_divides_by_the_factor_after_it() -> None:
    assert parse_units("m/s/s") == parse_units("m/s^2")
    assert parse_units("kg/m/s^2") == parse_units("kg/(m·s^2)")


LATEX = [
    ("m/s^2", r"\mathrm{m}/\mathrm{s}^{2}"),
    ("N m", r"\mathrm{N}\cdot \mathrm{m}"),
    ("J/(kg K)", r"\mathrm{J}/(\mathrm{kg}\cdot \mathrm{K})"),
    ("µm", r"\mathrm{\mu m}"),
    ("kΩ", r"\mathrm{k}\Omega"),
    ("°", r"{}^{\circ}"),
    ("°C", r"{}^{\circ}\mathrm{C}"),
    ("1/s", r"1/\mathrm{s}"),
]


@pytest.mark.parametrize(("text", "latex"), LATEX, ids=[c[0] for c in LATEX])
def test_latex_rendering(text: str, latex: str) -> None:
    assert parse_units(text).latex == latex


UNKNOWN = [
    # (text, unknown name, position)
    ("smoot", "smoot", 0),
    ("m/sec2x", None, 5),  # a digit glued to a name is a ParseError, checked below
    ("kg·m/sx", "sx", 5),
    ("KGM", "KGM", 0),
    ("m/s^2 foo", "foo", 6),
    ("smoot", "smoot", 0),
    ("kgg9", None, 0),
    ("xyz", "xyz", 0),
]


@pytest.mark.parametrize(
    ("text", "name", "position"),
    [c for c in UNKNOWN if c[1] is not None],
    ids=[c[0] for c in UNKNOWN if c[1]],
)
def test_unknown_unit_names_the_unit_and_its_position(text: str, name: str, position: int) -> None:
    with pytest.raises(UnknownUnit) as caught:
        parse_units(text)
    assert caught.value.unit == name
    assert caught.value.position == position
    assert caught.value.reason == "unknown_unit"


@pytest.mark.parametrize(
    ("typed", "suggested"),
    [("KM", "km"), ("ev", "eV"), ("pa", "Pa")],  # not EV, the exavolt, nor PA, the petaampere
)
def test_unknown_unit_suggests_the_spelling_with_the_right_case(typed: str, suggested: str) -> None:
    with pytest.raises(UnknownUnit) as caught:
        parse_units(typed)
    assert f"did you mean {suggested!r}?" in caught.value.message


@pytest.mark.parametrize("typed", ["k N", "M J"])
def test_a_prefix_apart_from_its_unit_is_refused_saying_to_join_them(typed: str) -> None:
    with pytest.raises(UnknownUnit) as caught:
        parse_units(typed)
    joined = typed.replace(" ", "")
    assert (
        f"{typed[0]!r} is a prefix, not a unit; join it to its unit, as in {joined}" in caught.value.message
    )
    assert caught.value.position == 0


def test_glued_name_with_two_splits_is_ambiguous() -> None:
    with pytest.raises(AmbiguousInput) as caught:
        parse_units("Nms")
    assert set(caught.value.readings) == {"N·m·s", "N·ms"}
    assert caught.value.position == 0


def test_several_slashes_with_a_product_after_one_is_ambiguous() -> None:
    with pytest.raises(AmbiguousInput) as caught:
        parse_units("J/kg K/s")
    assert caught.value.position == 1
    assert "parentheses" in caught.value.message


MALFORMED = [
    # (text, position of the fault)
    ("", 0),
    ("   ", 0),
    ("m/", 2),
    ("m^", 2),
    ("m^x", 2),
    ("m^1.5", 3),
    ("(m/s", 4),
    ("m/s)", 3),
    ("2 m", 0),
    ("m, s", 1),
    ("m/s;", 3),
    ("m # s", 2),
    ("m $", 2),
    ("m^(-2", 5),
    ("⁻", 0),
    ("m^^2", 2),
    ("m//s", 2),
    ("*m", 0),
]


@pytest.mark.parametrize(("text", "position"), MALFORMED, ids=[repr(c[0]) for c in MALFORMED])
def test_malformed_unit_string_is_a_parse_error_at_the_fault(text: str, position: int) -> None:
    with pytest.raises(ParseError) as caught:
        parse_units(text)
    assert caught.value.position == position


HOSTILE = [
    "m" * 101,
    "m^999999999",
    "m^13",
    "(" * 60,
    "(" * 99 + "m",
    "Nm" * 12,
    "__import__('os')",
    "eval('1')",
    "m" + "\x00",
    "m\u202e",
    "m/" * 50,
]


@pytest.mark.timeout(10)  # hostile input must fail fast; a hang fails here
@pytest.mark.parametrize("text", HOSTILE, ids=[f"hostile-{i}" for i in range(len(HOSTILE))])
def test_hostile_unit_strings_fail_fast_as_answer_errors(text: str) -> None:
    with pytest.raises(AnswerError):
        parse_units(text)


def test_over_long_unit_string_is_too_large() -> None:
    with pytest.raises(TooLarge):
        parse_units("m" * 101)


def test_huge_power_is_too_large() -> None:
    with pytest.raises(TooLarge) as caught:
        parse_units("m^13")
    assert caught.value.position == 2
