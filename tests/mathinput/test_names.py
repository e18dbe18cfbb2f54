"""Declared names: Greek spellings, subscripts, case, glued runs, and refusing what reads two ways."""

from __future__ import annotations

import pytest
import sympy

from physics.errors import AmbiguousInput, UnknownFunction, UnknownSymbol
from tests.mathinput.support import read, same, sym

SPELLINGS = [
    # (typed, declared, the declared name it must mean)
    ("theta", ("theta",), "theta"),
    ("θ", ("theta",), "theta"),
    ("theta", ("θ",), "θ"),
    ("θ", ("θ",), "θ"),
    ("ϑ", ("theta",), "theta"),
    ("α", ("alpha",), "alpha"),
    ("μ", ("mu",), "mu"),
    ("µ", ("mu",), "mu"),  # the micro sign
    ("ω", ("omega",), "omega"),
    ("Δ", ("Delta",), "Delta"),
    ("Delta", ("Δ",), "Δ"),
    ("λ", ("lambda",), "lambda"),
    ("v_0", ("v_0",), "v_0"),
    ("v0", ("v_0",), "v_0"),
    ("U0", ("U0",), "U0"),
    ("U_0", ("U0",), "U0"),
    ("r0", ("r0", "r"), "r0"),
    ("v0", ("v_0", "v"), "v_0"),
    ("θ_0", ("theta_0",), "theta_0"),
    ("θ0", ("theta_0",), "theta_0"),
    ("theta0", ("theta_0",), "theta_0"),
    ("mu_k", ("mu_k",), "mu_k"),
    ("μ_k", ("mu_k",), "mu_k"),
    ("μk", ("mu_k",), "mu_k"),
    ("m1", ("m1", "m2"), "m1"),
    ("m_1", ("m1",), "m1"),
    ("M", ("m", "M"), "M"),
    ("m", ("m", "M"), "m"),
    ("mu", ("mu", "m", "u"), "mu"),  # a declared name beats a split
]


@pytest.mark.parametrize(
    ("typed", "declared", "meant"), SPELLINGS, ids=[f"{s[0]}-as-{s[2]}" for s in SPELLINGS]
)
def test_each_spelling_reads_as_its_declared_name(typed, declared, meant):
    parsed = read(typed, *declared)
    assert parsed.expr == sym(meant)
    assert parsed.read_as.text == meant


GLUED = [
    ("mgh", ("m", "g", "h"), sym("m") * sym("g") * sym("h")),
    ("mgsin(theta)", ("m", "g", "theta"), sym("m") * sym("g") * sympy.sin(sym("theta"))),
    ("mgsinθ", ("m", "g", "theta"), sym("m") * sym("g") * sympy.sin(sym("theta"))),
    ("mgcosθ", ("m", "g", "theta"), sym("m") * sym("g") * sympy.cos(sym("theta"))),
    ("2mg", ("m", "g"), 2 * sym("m") * sym("g")),
    ("πr²", ("r",), sympy.pi * sym("r") ** 2),
    ("m1m2", ("m1", "m2"), sym("m1") * sym("m2")),
    ("Mm", ("m", "M"), sym("m") * sym("M")),
    ("μmg", ("mu", "m", "g"), sym("mu") * sym("m") * sym("g")),
    ("mumg", ("mu", "m", "g"), sym("mu") * sym("m") * sym("g")),
    ("mv0", ("m", "v_0"), sym("m") * sym("v_0")),
    # a number glued after a function, as physics types `sin 2θ`
    ("sin2θ", ("theta",), sympy.sin(2 * sym("theta"))),
    ("mgsin2θ", ("m", "g", "theta"), sym("m") * sym("g") * sympy.sin(2 * sym("theta"))),
    ("cos2ωt", ("omega", "t"), sympy.cos(2 * sym("omega") * sym("t"))),
    ("sin2θcos2θ", ("theta",), sympy.sin(2 * sym("theta")) * sympy.cos(2 * sym("theta"))),
    ("m2g", ("m2", "g"), sym("m2") * sym("g")),  # a declared name with its digit is no function's
    # a number ending the word, as `ln2` and `sqrt2` are typed (they were unknown symbols)
    ("τ ln2", ("tau",), sym("tau") * sympy.log(2)),
    ("τln2", ("tau",), sym("tau") * sympy.log(2)),
    ("2ln2 τ", ("tau",), 2 * sympy.log(2) * sym("tau")),
    ("sqrt2 τ", ("tau",), sympy.sqrt(2) * sym("tau")),
    ("τ sin30°", ("tau",), sym("tau") / 2),  # glued before its degree sign: 30°, as typed
    ("mgcos60°", ("m", "g"), sym("m") * sym("g") / 2),
]


@pytest.mark.parametrize(("typed", "declared", "expected"), GLUED, ids=[g[0] for g in GLUED])
def test_glued_run_that_splits_one_way_is_that_product(typed, declared, expected):
    assert same(read(typed, *declared).expr, expected)


def test_glued_run_reads_back_with_explicit_products():
    assert read("mgh", "m", "g", "h").read_as.text == "m*g*h"


def test_a_number_glued_after_a_function_keeps_where_each_piece_was_typed():
    with pytest.raises(UnknownSymbol) as caught:
        read("mgsin2q", "m", "g", "theta")
    assert caught.value.position == 0  # the split needs every piece to read: q does not
    assert read("v sin2θ", "v", "theta").read_as.text == "v*sin(2*theta)"


@pytest.mark.parametrize("typed", ["sin2", "sin2θ2", "log2", "sin30"])
def test_a_function_and_number_with_nothing_or_a_number_after_stays_unknown(typed):
    # sin30 would be 30 radians, log2 may name a base: refused, where ln2 and sqrt2 are read
    with pytest.raises(UnknownSymbol):
        read(typed, "theta")


def test_a_function_and_number_before_a_bracket_stays_unknown():
    with pytest.raises(UnknownFunction):
        read("ln2(θ)", "theta")


AMBIGUOUS_NAMES = [
    ("mgh", ("m", "g", "h", "gh"), {"m*g*h", "m*gh"}),
    ("vx", ("v_x", "v", "x"), {"v*x", "v_x"}),
    ("Δx", ("Delta_x", "Delta", "x"), {"Delta*x", "Delta_x"}),
]


@pytest.mark.parametrize(
    ("typed", "declared", "readings"), AMBIGUOUS_NAMES, ids=[a[0] for a in AMBIGUOUS_NAMES]
)
def test_glued_run_that_splits_two_ways_is_refused_listing_both(typed, declared, readings):
    with pytest.raises(AmbiguousInput) as caught:
        read(typed, *declared)
    assert set(caught.value.readings) == readings
    assert caught.value.position == 0
    for reading in readings:
        assert reading in caught.value.message


def test_undeclared_greek_name_does_not_join_a_split():
    assert read("mu", "m", "u").expr == sym("m") * sym("u")


UNKNOWN = [
    ("q", ("m", "g"), "q", 0),
    ("m g q", ("m", "g"), "q", 4),
    ("xyz", ("x", "y"), "xyz", 0),
    ("omega", ("theta",), "omega", 0),
    ("ω", ("theta",), "ω", 0),
    ("Theta", ("theta",), "Theta", 0),
    ("mgk", ("m", "g"), "mgk", 0),
    ("E", ("e",), "E", 0),
]


@pytest.mark.parametrize(("typed", "declared", "symbol", "position"), UNKNOWN, ids=[u[0] for u in UNKNOWN])
def test_unknown_symbol_is_refused_listing_the_allowed_names(typed, declared, symbol, position):
    with pytest.raises(UnknownSymbol) as caught:
        read(typed, *declared)
    assert caught.value.symbol == symbol
    assert caught.value.position == position
    assert caught.value.allowed == declared
    for name in declared:
        assert name in caught.value.message


# A slip for a declared name, pointed out after the list of names: a Latin stand-in for a Greek letter,
# the letter o typed for a zero subscript. Each hint's start, which must be absent where it has no case.
STAND_IN, LETTER_O, CAPITAL_PI, SPACED = "stands for", "with a zero", "the number π", "without the space"
LOOKALIKE = "looks like the Latin"
DEGREES = "Write the degree sign for degrees"
POWER = "Write a power with ^"
CASE = "Names are case-sensitive"
SUBSCRIPT = "The symbol has a subscript"
TIMES = "is a times sign"
EXPONENT = "Write a power of ten without a space"
SLIP_HINTS = [
    # (typed, declared, which hint, the sentence the refusal must hold, or None: no such hint)
    ("wt", ("omega", "t"), STAND_IN, "If w stands for ω, type omega or ω."),
    ("A cos(w0 t)", ("A", "omega_0", "t"), STAND_IN, "If w stands for ω, type omega or ω."),
    ("u g", ("mu", "g"), STAND_IN, "If u stands for μ, type mu or μ."),
    ("g sina", ("alpha", "g"), STAND_IN, "If a stands for α, type alpha or α."),  # a keyboard without Greek
    ("wt", ("w", "omega", "x"), STAND_IN, None),  # w is declared: the unknown word is something else
    ("wt", ("theta", "t"), STAND_IN, None),  # no omega to mean
    ("mu g", ("mu_k", "g"), STAND_IN, None),  # mu is spelled out: its u stands for nothing
    ("vo t", ("v_0", "t"), LETTER_O, "If vo is v with a zero, type v0 or v_0 (a zero, not the letter o)."),
    ("v_o t", ("v_0", "t"), LETTER_O, "If v_o is v with a zero, type v0 or v_0"),
    ("xO + v_0 t", ("x_0", "v_0", "t"), LETTER_O, "If xO is x with a zero, type x0 or x_0"),
    ("vo t", ("v", "t"), LETTER_O, None),  # no v_0 to mean
    ("go t", ("v_0", "g", "t"), LETTER_O, None),
    # π as a calculator, a spreadsheet or Mathematica spells it, and the capital letter
    ("2 PI x", ("x",), CAPITAL_PI, "If you mean the number π, type pi or π (in small letters)."),
    ("2Pi x", ("x",), CAPITAL_PI, "type pi or π"),
    ("2Π x", ("x",), CAPITAL_PI, "type pi or π"),
    ("2 Px", ("x",), CAPITAL_PI, None),
    ("θ_o t", ("theta_0", "t"), LETTER_O, "If θ_o is θ with a zero, type θ0 or θ_0"),  # a Greek letter
    ("θₒ t", ("theta_0", "t"), LETTER_O, "If θ_o is θ with a zero"),  # the subscript letter o, as θ_o
    # a name typed in two words, as `\Delta x` is (a space ends a LaTeX command) but not in plain text
    ("Δ x/t", ("Delta_x", "t"), SPACED, "If Δ x is Δx, type it without the space."),
    ("Delta x/t", ("Delta_x", "t"), SPACED, "If Delta x is Deltax, type it without the space."),
    ("Δ t", ("Delta_x", "t"), SPACED, None),
    # a Cyrillic or Greek letter that looks Latin, from a keyboard set to another alphabet: the unknown
    # word looked like the declared one the message listed
    ("mс^2", ("m", "c"), LOOKALIKE, "Its с is a Cyrillic letter that looks like the Latin c: type the Latin"),
    ("m + Μ", ("m", "M"), LOOKALIKE, "Its Μ is a Greek letter that looks like the Latin M"),
    ("ν t", ("v", "t"), LOOKALIKE, "Its ν is a Greek letter that looks like the Latin v"),
    ("ν t", ("x", "t"), LOOKALIKE, None),  # no v to mean: perhaps a frequency
    # a function of an angle with its number glued on and no degree sign: 30 rad, or 30°?
    ("m sin30", ("m",), DEGREES, "Did you mean sin(30°)? Write the degree sign for degrees, or sin(30) for"),
    ("mcos60", ("m",), DEGREES, "Did you mean cos(60°)?"),
    # a power typed as a plain digit, as a text message writes m c²
    ("mc2", ("m", "c"), POWER, "Did you mean m c^2? Write a power with ^."),
    ("1/2 mv2", ("m", "v"), POWER, "Did you mean m v^2?"),
    ("mω2L", ("m", "omega", "L"), POWER, "Did you mean m omega^2 L? Write a power with ^."),
    ("mω2Lx", ("m", "omega", "L"), POWER, None),  # no x after the power
    ("v2 t", ("v_1", "v", "t"), POWER, None),  # a subscript mistyped, beside v_1
    ("x2", ("m", "c"), POWER, None),  # no x to raise
    # a name in the other case, as a phone capitalises the first letter
    ("2 pi sqrt(l/g)", ("L", "g"), CASE, "Names are case-sensitive: did you mean L?"),
    ("V0 t", ("v0", "t"), CASE, "did you mean v0?"),
    ("V_0 t", ("v_0", "t"), CASE, "did you mean v_0?"),
    ("X t", ("x", "y", "t"), CASE, "did you mean x?"),
    ("K t", ("k", "K_0", "t"), CASE, "did you mean k?"),
    ("Q t", ("x", "t"), CASE, None),  # no q to mean
    ("Mg x", ("m", "g", "x"), CASE, "Names are case-sensitive: did you mean mg?"),  # a phone's first capital
    ("Xt", ("x", "t"), CASE, "did you mean xt?"),
    # a letter without the subscript it is declared with
    ("μ g", ("mu_k", "g"), SUBSCRIPT, "Did you mean μ_k? The symbol has a subscript."),
    ("v t", ("v_0", "t"), SUBSCRIPT, "Did you mean v_0?"),
    ("μ g", ("mu_k", "mu_s", "g"), SUBSCRIPT, None),  # which of the two?
    # the letter x typed for a times sign between names, as between numbers it is read
    ("m x g x h", ("m", "g", "h"), TIMES, "If x is a times sign, write * or a space instead."),
    ("m X 2 g", ("m", "g", "h"), TIMES, "If X is a times sign"),
    ("m + x", ("m", "g"), TIMES, None),  # after a plus: a symbol that is not declared
    # a power of ten typed apart from its number
    ("2 E3 x", ("x",), EXPONENT, "Did you mean 2E3? Write a power of ten without a space before its E."),
    ("x E3", ("x",), EXPONENT, None),
]


@pytest.mark.parametrize(
    ("typed", "declared", "which", "hint"), SLIP_HINTS, ids=[f"{g[0]}-{g[1]}" for g in SLIP_HINTS]
)
def test_a_likely_slip_for_a_declared_name_is_pointed_out(typed, declared, which, hint):
    with pytest.raises(UnknownSymbol) as caught:
        read(typed, *declared)
    if hint is None:
        assert which not in caught.value.message
    else:
        assert hint in caught.value.message


UNKNOWN_FUNCTIONS = [
    ("f(x)", "f", 0),
    ("2 + g(x)", "g", 4),
    ("exec(x)", "exec", 0),
    ("Sin(x)", "Sin", 0),
]


@pytest.mark.parametrize(
    ("typed", "function", "position"), UNKNOWN_FUNCTIONS, ids=[u[0] for u in UNKNOWN_FUNCTIONS]
)
def test_undeclared_name_before_a_bracket_is_an_unknown_function(typed, function, position):
    with pytest.raises(UnknownFunction) as caught:
        read(typed, "x")
    assert caught.value.function == function
    assert caught.value.position == position
    assert "sin" in caught.value.allowed
    assert "sqrt" in caught.value.message


@pytest.mark.parametrize(
    ("typed", "meant"),
    [
        ("Sin(x)", "sin"),
        ("SQRT(x)", "sqrt"),
        ("Ln(x)", "ln"),
        # glued to names before it, as a phone capitalises: once "Unknown function" alone
        ("xCos(x)", "x cos(…)"),
        ("xxSQRT(x)", "xx sqrt(…)"),
    ],
)
def test_a_function_in_capitals_is_refused_naming_it_in_small_letters(typed: str, meant: str) -> None:
    with pytest.raises(UnknownFunction) as caught:
        read(typed, "x")
    assert f"Did you mean {meant}? Function names are in small letters." in caught.value.message


OTHER_FUNCTION_NAMES = [
    # (typed, declared, the name to type): Russian and European names, refused naming the function to
    # type; they were "Unknown function" or "Unknown symbol" with no more
    ("tg(x)", ("x",), "tan"),
    ("tg x", ("x",), "tan"),
    ("ctg(x)", ("x",), "cot"),
    ("cotg x", ("x",), "cot"),
    ("arctg(x)", ("x",), "atan"),
    ("arcctg x", ("x",), "acot"),
    ("m g tgθ", ("m", "g", "theta"), "tan"),
    ("τ lg(2)", ("tau",), "log10"),  # ISO 80000-2's common logarithm
]


@pytest.mark.parametrize(
    ("typed", "declared", "meant"), OTHER_FUNCTION_NAMES, ids=[c[0] for c in OTHER_FUNCTION_NAMES]
)
def test_a_function_under_its_russian_or_european_name_is_refused_naming_the_one_to_type(
    typed: str, declared: tuple[str, ...], meant: str
) -> None:
    with pytest.raises((UnknownFunction, UnknownSymbol)) as caught:
        read(typed, *declared)
    assert f"Did you mean {meant}? Write {meant} for" in caught.value.message


MATLAB_DEGREE_FUNCTIONS = [
    # (typed, declared, the start of the question): MATLAB's functions of degrees, once "Unknown function"
    # alone, then "Did you mean sin?" without the argument to type
    ("sind(30) x", ("x",), "Did you mean sin(30°)? sind is MATLAB's sin of an angle in degrees"),
    ("x cosd(θ)", ("x", "theta"), "Did you mean cos(θ)? cosd is MATLAB's cos of an angle in degrees"),
    ("x tand θ", ("x", "theta"), "Did you mean tan(θ)? tand"),
    ("x sind 45.5", ("x",), "Did you mean sin(45.5°)?"),
    ("x sind30", ("x",), "Did you mean sin(30°)?"),
    # a number in an expression with a symbol: not sin(90 - θ), of 90 rad
    ("x cosd(90 - θ)", ("x", "theta"), "Did you mean cos? cosd is MATLAB's cos of an angle in degrees"),
]


@pytest.mark.parametrize(
    ("typed", "declared", "asked"), MATLAB_DEGREE_FUNCTIONS, ids=[c[0] for c in MATLAB_DEGREE_FUNCTIONS]
)
def test_matlabs_function_of_degrees_is_refused_naming_what_to_type(
    typed: str, declared: tuple[str, ...], asked: str
) -> None:
    with pytest.raises((UnknownFunction, UnknownSymbol)) as caught:
        read(typed, *declared)
    assert asked in caught.value.message


MATLAB_DEGREE_FUNCTIONS_BESIDE_A_DECLARED_D = [
    # (typed, declared, the function, the readings asked about): with d declared these were graded as
    # sin(d)·θ
    ("m g sind θ", ("m", "g", "d", "theta"), "sin", "Did you mean sin θ or sin(d)·θ?"),
    ("m g cosd(θ)", ("m", "g", "d", "theta"), "cos", "Did you mean cos(θ) or cos(d)·(θ)? "),
    ("m g sind(θ/2)", ("m", "g", "d", "theta"), "sin", "Did you mean sin(θ/2) or sin(d)·(θ/2)? "),
    ("m g sind(theta)", ("m", "g", "d", "theta"), "sin", "Did you mean sin(theta) or sin(d)·(theta)? "),
    ("x mgtand 30", ("x", "m", "g", "d"), "tan", "Did you mean tan 30 or tan(d)·30?"),
]


@pytest.mark.parametrize(
    ("typed", "declared", "name", "asked"),
    MATLAB_DEGREE_FUNCTIONS_BESIDE_A_DECLARED_D,
    ids=[c[0] for c in MATLAB_DEGREE_FUNCTIONS_BESIDE_A_DECLARED_D],
)
def test_matlabs_function_of_degrees_is_asked_about_where_d_is_a_symbol(
    typed: str, declared: tuple[str, ...], name: str, asked: str
) -> None:
    with pytest.raises(AmbiguousInput) as caught:
        read(typed, *declared)
    assert caught.value.message.startswith(asked)
    assert (
        f"{name}d is MATLAB's {name} of an angle in degrees, which is not read here" in caught.value.message
    )
    assert f"type {name}(d)" in caught.value.message
    assert "…" not in caught.value.message  # the argument as typed, never elided
    assert typed[caught.value.position :].startswith(f"{name}d")


def test_a_function_glued_to_a_declared_d_inside_a_word_reads_as_before() -> None:
    # only a word ending in sind, cosd, … is MATLAB's: sin(d·θ) where dθ is typed on
    assert same(read("sindθ", "d", "theta").expr, sympy.sin(sym("d") * sym("theta")))


def test_tg_of_declared_t_and_g_is_their_product_as_before() -> None:
    assert same(read("v0 - tg", "v0", "t", "g").expr, sym("v0") - sym("t") * sym("g"))


def test_lg_of_declared_l_and_g_is_their_product() -> None:
    assert same(read("lg", "l", "g").expr, sym("l") * sym("g"))


def test_declared_name_before_a_bracket_is_multiplication():
    assert same(read("m(g+M)", "m", "g", "M").expr, sym("m") * (sym("g") + sym("M")))


def test_a_table_reads_a_word_the_same_when_asked_again_and_past_its_memory():
    from physics.mathinput import names as table_module

    declared = {name: sympy.Symbol(name, positive=True) for name in ("m", "M", "g", "theta", "mu_k")}
    fresh = table_module.NameTable(declared)
    words = ["mgsin", "theta", "mu_k", "μk", "Mg", "q", "cos", "pi", "e"]
    first = {word: fresh.resolve(word) for word in words}
    # Fill the table's memory with other words, then ask again: the same readings, remembered or not.
    for index in range(table_module._MAX_RESOLVED + 10):
        fresh.resolve(f"x{index}")
    assert {word: fresh.resolve(word) for word in words} == first
    assert {word: table_module.NameTable(declared).resolve(word) for word in words} == first
    assert first["mgsin"].unique is not None and len(first["mgsin"].unique) == 3
    assert first["q"].readings == ()
