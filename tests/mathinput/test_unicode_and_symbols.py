"""Textbook characters read as the names and numbers they are; `2E-3` refused where `E` is a symbol."""

from __future__ import annotations

import pytest
import sympy

from physics.errors import AmbiguousInput, AnswerError, LikelySlip, ParseError
from physics.mathinput import parse_math
from tests.mathinput.support import names, same, sym

TEXTBOOK = [
    # (typed, declared names, the expression meant)
    ("v₀ t", ("v_0", "t"), sym("v_0") * sym("t")),
    ("v₀", ("v0",), sym("v0")),
    ("ε₀ E", ("epsilon_0", "E"), sym("epsilon_0") * sym("E")),
    ("1/(4π ε₀ r^2)", ("epsilon_0", "r"), 1 / (4 * sympy.pi * sym("epsilon_0") * sym("r") ** 2)),
    ("r₁ + r₂", ("r_1", "r_2"), sym("r_1") + sym("r_2")),
    ("m₁₂", ("m_12",), sym("m_12")),
    ("½ m v^2", ("m", "v"), sym("m") * sym("v") ** 2 / 2),
    ("½m v²", ("m", "v"), sym("m") * sym("v") ** 2 / 2),
    ("¼ m", ("m",), sym("m") / 4),
    ("¾ x", ("x",), 3 * sym("x") / 4),
    ("⅓ x", ("x",), sym("x") / 3),
    ("x^½", ("x",), sympy.sqrt(sym("x"))),
    ("x^²", ("x",), sym("x") ** 2),  # the caret, then a superscript from a palette: one power
    ("x^-² y", ("x", "y"), sym("y") / sym("x") ** 2),  # the caret and minus typed, then the palette's ²
    ("x^−³", ("x",), sym("x") ** -3),
    ("x**⁻² y", ("x", "y"), sym("y") / sym("x") ** 2),
    ("x⁻½ y", ("x", "y"), sym("y") / sympy.sqrt(sym("x"))),  # a raised minus, then a fraction: once refused
    # A vulgar fraction is typed as a number is: a function without brackets takes it with the word
    # glued to it, as `sin 2θ` (not sin(½)·θ)
    ("sin ½θ", ("theta",), sympy.sin(sym("theta") / 2)),
    ("cos½θ x", ("theta", "x"), sympy.cos(sym("theta") / 2) * sym("x")),
    ("sin(½) x", ("x",), sympy.sin(sympy.Rational(1, 2)) * sym("x")),  # `sin ½ x` is asked (test_errors.py)
    ("ħ/2", ("hbar",), sym("hbar") / 2),
    # A fraction set in raised and lowered digits (a word processor's, or a "fraction generator"'s) is
    # the number, as `½` is: `⁵⁄₇` was refused as "Unexpected '⁵'"
    ("⁵⁄₇ g sin θ", ("g", "theta"), 5 * sym("g") * sympy.sin(sym("theta")) / 7),
    ("⁵⁄₇g", ("g",), 5 * sym("g") / 7),
    ("¹/₂ m v²", ("m", "v"), sym("m") * sym("v") ** 2 / 2),  # a plain slash between them
    ("¹∕₁₂ m L²", ("m", "L"), sym("m") * sym("L") ** 2 / 12),  # the division slash
    ("sin ¹⁄₂θ", ("theta",), sympy.sin(sym("theta") / 2)),  # a number, as `sin ½θ`
    ("g ⁵⁄₇", ("g",), 5 * sym("g") / 7),
    ("⅔ m g", ("m", "g"), 2 * sym("m") * sym("g") / 3),
    # An exponent typed in raised letters, as a phone's keyboard gives them: it was refused, "a superscript
    # sign needs superscript digits after it"
    ("A e⁻ᵏᵗ", ("A", "k", "t"), sym("A") * sympy.exp(-sym("k") * sym("t"))),
    ("e⁻ᵗᐟᵗᵃᵘ", ("t", "tau"), sympy.exp(-sym("t") / sym("tau"))),  # ᐟ, a generator's raised slash
    # the product after a raised slash, raised to the run's end, is all its divisor: was asked, "Did you
    # mean (b·t/2)·m or b·t/(2·m)?"
    ("A e⁻ᵇᵗᐟ²ᵐ", ("A", "b", "t", "m"), sym("A") * sympy.exp(-sym("b") * sym("t") / (2 * sym("m")))),
    (
        "A e⁻ᵇᵗᐟ²ᵐ t",
        ("A", "b", "t", "m"),
        sym("A") * sym("t") * sympy.exp(-sym("b") * sym("t") / (2 * sym("m"))),
    ),
    ("e^⁻ᵗᐟᴿᴸ", ("t", "R", "L"), sympy.exp(-sym("t") / (sym("R") * sym("L")))),
    ("e⁻ᵗᐟ⁽ᴿᴸ⁾", ("t", "R", "L"), sympy.exp(-sym("t") / (sym("R") * sym("L")))),
    # a sign or a bracket after it, or a second slash: read as typed
    ("e⁻ᵗᐟ²⁺ᵏ", ("t", "k"), sympy.exp(-sym("t") / 2 + sym("k"))),
    ("e⁽⁻ᵗᐟ²⁾ᵏ", ("t", "k"), sympy.exp(-sym("t") * sym("k") / 2)),
    ("e⁻ᵗᐟ²ᐟᵏ", ("t", "k"), sympy.exp(-sym("t") / (2 * sym("k")))),
    ("e⁻ᵚᵗ", ("omega", "t"), sympy.exp(-sym("omega") * sym("t"))),  # ᵚ, the turned m, for ω
    ("e^ᵏᵗ", ("k", "t"), sympy.exp(sym("k") * sym("t"))),  # the caret, then the raised run: one power
    ("xʸ", ("x", "y"), sym("x") ** sym("y")),
    ("x⁽ᵏ⁺¹⁾", ("x", "k"), sym("x") ** (sym("k") + 1)),
    ("sin(30ᵒ) x", ("x",), sympy.sin(sympy.pi / 6) * sym("x")),  # a raised o after a number: a degree
    # Subscript letters, as LaTeX's v_{max}: the name's subscript, never split into a product
    ("vₘₐₓ t", ("v_max", "t"), sym("v_max") * sym("t")),
    ("tvₘₐₓ", ("v_max", "t"), sym("v_max") * sym("t")),
    ("vₘₐₓt", ("v_max", "t"), sym("v_max") * sym("t")),
    ("μₖ Fₙ", ("mu_k", "F_n"), sym("mu_k") * sym("F_n")),
    ("sin(30º) x", ("x",), sympy.sin(sympy.pi / 6) * sym("x")),  # º for °: option-0 on a Mac keyboard
    ("sin(30˚) x", ("x",), sympy.sin(sympy.pi / 6) * sym("x")),  # the ring above
    ("ℏ ω", ("hbar", "omega"), sym("hbar") * sym("omega")),
    ("hbar ω", ("hbar", "omega"), sym("hbar") * sym("omega")),
    ("（m+M）g", ("m", "M", "g"), (sym("m") + sym("M")) * sym("g")),
    ("［m+M］g", ("m", "M", "g"), (sym("m") + sym("M")) * sym("g")),
    ("｛m+M｝g", ("m", "M", "g"), (sym("m") + sym("M")) * sym("g")),
    ("２m＊g", ("m", "g"), 2 * sym("m") * sym("g")),
    ("٢m g", ("m", "g"), 2 * sym("m") * sym("g")),  # an Arabic keyboard's digit
    (
        "ｍ ｇ ｓｉｎ（θ）",
        ("m", "g", "theta"),
        sym("m") * sym("g") * sympy.sin(sym("theta")),
    ),  # fullwidth letters
    ("cosec(x)", ("x",), sympy.csc(sym("x"))),
    ("cosec x", ("x",), sympy.csc(sym("x"))),
    ("sec(x)", ("x",), sympy.sec(sym("x"))),
    ("cot(x)", ("x",), sympy.cot(sym("x"))),
    ("Abs(x)", ("x",), sympy.Abs(sym("x"))),
    ("∣x − y∣", ("x", "y"), sympy.Abs(sym("x") - sym("y"))),  # the divides sign, as some editors set a bar
    ("log_10(x)", ("x",), sympy.log(sym("x"), 10)),  # the base typed as LaTeX writes it
    ("log_{10}(x)", ("x",), sympy.log(sym("x"), 10)),
    ("log_e(x)", ("x",), sympy.log(sym("x"))),
    ("arccosec(x)", ("x",), sympy.acsc(sym("x"))),
    # An equation copied from Word: mathematical italic letters (ℎ is Word's italic h), and the invisible
    # function application after sin
    ("𝑚𝑔ℎ", ("m", "g", "h"), sym("m") * sym("g") * sym("h")),
    ("𝑚𝑔 sin\u2061𝜃", ("m", "g", "theta"), sym("m") * sym("g") * sympy.sin(sym("theta"))),
    ("m\u2062g", ("m", "g"), sym("m") * sym("g")),  # invisible times
    ("𝐅/𝑚", ("F", "m"), sym("F") / sym("m")),  # bold, as a vector is printed
    ("𝑣₀ ℯ^(−𝑡/𝜏)", ("v_0", "t", "tau"), sym("v_0") * sympy.exp(-sym("t") / sym("tau"))),
    ("𝟐𝑥", ("x",), 2 * sym("x")),
    # Characters that show nothing, from a web page or a right-to-left keyboard, are not there
    ("m g sin\u200bθ", ("m", "g", "theta"), sym("m") * sym("g") * sympy.sin(sym("theta"))),
    ("\u200fm g\u200e", ("m", "g"), sym("m") * sym("g")),
    ("\ufeffx", ("x",), sym("x")),
    ("v\u200b0", ("v", "v0"), sym("v0")),  # as it shows: v0, not v·0
    ("m\u00adg", ("m", "g"), sym("m") * sym("g")),  # soft hyphen
    # Cube and fourth roots, with the argument rules of √ (`√2gh`)
    ("∛x", ("x",), sym("x") ** sympy.Rational(1, 3)),
    ("∛(x y)", ("x", "y"), (sym("x") * sym("y")) ** sympy.Rational(1, 3)),
    ("∛xy", ("x", "y"), (sym("x") * sym("y")) ** sympy.Rational(1, 3)),
    ("∛x y", ("x", "y"), sym("x") ** sympy.Rational(1, 3) * sym("y")),
    ("∛27 x", ("x",), 3 * sym("x")),
    ("∜x", ("x",), sym("x") ** sympy.Rational(1, 4)),
    # A degree sign typed as a power of a letter o, as plain text writes 30°
    ("sin(30^o) x", ("x",), sympy.sin(sympy.pi / 6) * sym("x")),
    ("sin(30^{o}) x", ("x",), sympy.sin(sympy.pi / 6) * sym("x")),
    ("sin 30^° x", ("x",), sympy.sin(sympy.pi / 6) * sym("x")),
    # The full stop of a sentence, as a numeric answer takes it
    ("x y.", ("x", "y"), sym("x") * sym("y")),
    ("sqrt(x) . ", ("x",), sympy.sqrt(sym("x"))),
    ("x/2.", ("x",), sym("x") / 2),
    # Maxima's constants, as STACK students type them: never 2 percent times π
    ("2*%pi*x", ("x",), 2 * sympy.pi * sym("x")),
    ("2 %pi x", ("x",), 2 * sympy.pi * sym("x")),
    ("x %e^2", ("x",), sym("x") * sympy.E**2),
    ("x 50 %", ("x",), sym("x") / 2),  # a percent sign alone is still a percent
    # Product signs that look like the ones read: bullet (option-8 on a Mac), asterisk operator
    ("m•g", ("m", "g"), sym("m") * sym("g")),
    ("m ∗ g", ("m", "g"), sym("m") * sym("g")),
    ("2E-3", ("x",), sympy.Rational(2, 1000)),  # E is not a symbol here: scientific notation
    ("2e3", ("E",), sympy.Integer(2000)),  # only the letter typed counts
]


@pytest.mark.parametrize(("typed", "declared", "meant"), TEXTBOOK, ids=[c[0] for c in TEXTBOOK])
def test_textbook_characters_read_as_meant(typed: str, declared: tuple[str, ...], meant: sympy.Expr) -> None:
    assert same(parse_math(typed, names(*declared)).expr, meant)


EXPONENT_CLASHES = [
    # (typed, declared, the two readings offered)
    ("2E-3", ("E",), ("2*10^(-3)", "2*E-3")),
    ("2e3", ("e",), ("2*10^3", "2*e3")),
    ("m + 4.5E+2", ("m", "E"), ("4.5*10^2", "4.5*E+2")),
]


@pytest.mark.parametrize(
    ("typed", "declared", "readings"), EXPONENT_CLASHES, ids=[c[0] for c in EXPONENT_CLASHES]
)
def test_scientific_notation_with_a_declared_letter_is_refused_with_both_readings(
    typed: str, declared: tuple[str, ...], readings: tuple[str, str]
) -> None:
    with pytest.raises(AmbiguousInput) as caught:
        parse_math(typed, names(*declared))
    assert caught.value.readings == readings
    assert caught.value.position == typed.index(readings[0][0])
    for reading in readings:
        assert reading in caught.value.message


LOWERED_OR_RAISED_REFUSED = [
    # (typed, declared, position, words): a subscript letter is no factor, a raised w no ω
    ("vₘ", ("v", "m"), 0, 'Unknown symbol "v_m"'),
    ("e⁻ʷᵗ", ("omega", "t"), 2, "If w stands for ω, type omega or ω"),
    # a raised exponent with its slash typed plain, as no keyboard raises one: was "Nothing between '/' and '^'"
    (
        "A e⁻ᵇᵗ/²ᵐ",
        ("A", "b", "t", "m"),
        6,
        "its '/' is not, so the exponent ends at the '/': write the whole exponent in ^( ), as e^(-bt/(2m))",
    ),
    ("A e⁻ᵇᵗ⁄²ᵐ", ("A", "b", "t", "m"), 6, "as e^(-bt/(2m))"),  # the fraction slash
    ("e⁻ᵗ/ᵗᵃᵘ", ("t", "tau"), 3, "as e^(-t/tau)."),  # one name needs no bracket: was e^(-t/(tau))
    ("e⁻ᵗ/ᴿᴸ", ("t", "R", "L"), 3, "as e^(-t/(RL))."),
    ("e⁻ᵗ/²", ("t",), 3, "as e^(-t/2)."),
    # a raised fraction glued to a factor: its power as much as a coefficient, so asked
    ("x⁵⁄₇", ("x",), 1, "write x^(5/7) for a power, or 5/7 x for a product"),
    ("(x)²⁄₃", ("x",), 3, "write (…)^(2/3) for a power"),
]


@pytest.mark.parametrize(
    ("typed", "declared", "position", "words"),
    LOWERED_OR_RAISED_REFUSED,
    ids=[c[0] for c in LOWERED_OR_RAISED_REFUSED],
)
def test_raised_and_lowered_letters_are_read_as_typed_or_refused_where_typed(
    typed: str, declared: tuple[str, ...], position: int, words: str
) -> None:
    with pytest.raises(AnswerError) as caught:
        parse_math(typed, names(*declared))
    assert caught.value.position == position
    assert words in caught.value.message


MIXED_NUMBERS = [
    # (typed, position of the fraction, the fix the message gives): one and a half as a recipe writes
    # it; `1 ½ m` and `3\frac{1}{2} m` were read 1·½·m and 3·½·m, and graded
    ("1½ m", 1, "(3/2 or 1.5), not 1½"),
    ("1 ½ m", 2, "(3/2 or 1.5), not 1 ½"),
    ("1 ⁵⁄₇ m", 2, "(12/7), not 1 ⁵⁄₇"),
    ("1 1/2 m", 2, "(3/2 or 1.5), not 1 1/2"),
    ("2 3/4m", 2, "(11/4 or 2.75), not 2 3/4"),
    ("1 1/3 m", 2, "(4/3), not 1 1/3"),
    ("3\\frac{1}{2} m", 1, "(7/2 or 3.5), not 3\\frac{1}{2}"),
    ("3 \\tfrac12 m", 2, "(7/2 or 3.5), not 3 \\tfrac12"),
]


@pytest.mark.parametrize(("typed", "position", "fix"), MIXED_NUMBERS, ids=[m[0] for m in MIXED_NUMBERS])
def test_a_mixed_number_is_refused_with_its_fraction_and_decimal(typed: str, position: int, fix: str) -> None:
    with pytest.raises(LikelySlip) as caught:
        parse_math(typed, names("m"))
    assert caught.value.position == position
    assert f"Write a mixed number as one fraction or a decimal {fix}" in caught.value.message


NOT_MIXED_NUMBERS = [
    # (typed, read as): a number that is an exponent, or a fraction of symbols, is a factor as before
    ("m^2 ½", "m**2/2"),
    ("m^2 \\frac{1}{2}", "m**2/2"),
    ("3\\frac{m}{2}", "3*m/2"),
    ("½ m", "1/2*m"),
]


@pytest.mark.parametrize(("typed", "read_as"), NOT_MIXED_NUMBERS, ids=[m[0] for m in NOT_MIXED_NUMBERS])
def test_a_number_beside_a_fraction_that_is_no_mixed_number_is_a_product(typed: str, read_as: str) -> None:
    assert same(parse_math(typed, names("m")).expr, parse_math(read_as, names("m")).expr)


def test_vulgar_fraction_read_as_shows_the_fraction() -> None:
    assert parse_math("½ m v^2", names("m", "v")).read_as.text == "1/2*m*v**2"


def test_epsilon_0_declared_accepts_the_greek_letter_with_a_subscript() -> None:
    read = parse_math("q/(4 π ε₀ r²)", names("q", "epsilon_0", "r"))
    assert read.read_as.text == "q/(4*pi*epsilon_0*r**2)"


def test_every_character_variant_is_outside_ascii() -> None:
    # The tokenizer reads plain ASCII text as it is, without looking each character up as a variant.
    from physics.mathinput.vocabulary import CHARACTER_VARIANTS

    assert [ch for ch in CHARACTER_VARIANTS if ch.isascii()] == []
    assert parse_math("2·x − y", names("x", "y")).read_as.text == "2*x - y"


def test_an_error_after_a_zero_width_character_is_placed_where_it_was_typed() -> None:
    with pytest.raises(ParseError) as caught:
        parse_math("\u200b\u200bm g ;", names("m", "g"))
    assert caught.value.position == 6


def test_a_word_after_a_zero_width_character_is_placed_where_it_was_typed() -> None:
    with pytest.raises(AnswerError) as caught:
        parse_math("m\u200f q", names("m"))
    assert caught.value.position == 3


@pytest.mark.parametrize(
    ("typed", "position"),
    [("sin(30^0) x", 6), ("sin(30⁰) x", 6), ("2^0 x", 1), ("x 30^{0}", 4), ("x 30^(0)", 4)],
)
def test_a_degree_typed_as_a_power_zero_is_refused_asking_which(typed: str, position: int) -> None:
    with pytest.raises(ParseError) as caught:
        parse_math(typed, names("x"))
    assert caught.value.position == position
    assert "Did you mean" in caught.value.message and "to the power 0 (which is 1)?" in caught.value.message


def test_a_power_zero_of_ten_or_of_a_symbol_is_read() -> None:
    assert same(parse_math("x 10^0", names("x")).expr, sym("x"))
    assert same(parse_math("x^0 y", names("x", "y")).expr, sym("y"))
    assert same(parse_math("x 2^(0+1)", names("x")).expr, 2 * sym("x"))
