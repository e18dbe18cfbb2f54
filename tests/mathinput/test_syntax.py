"""Every rule of the contract's student syntax: text -> the sympy expression built with constructors."""

from __future__ import annotations

import pytest
import sympy
from sympy import Abs, E, Rational, acos, asin, atan, cos, exp, factorial, log, pi, sin, sqrt, tan

from physics.errors import AmbiguousInput
from tests.mathinput.support import read, same, sym

m, M, g, theta, x, y = sym("m"), sym("M"), sym("g"), sym("theta"), sym("x"), sym("y")
a, b, c, h, v, k, r = sym("a"), sym("b"), sym("c"), sym("h"), sym("v"), sym("k"), sym("r")
WEDGE = ("m", "M", "g", "theta")
XY = ("x", "y")
WAVE = ("A", "omega", "t", "k", "x", "f", "g", "h")
A, omega, t, f = sym("A"), sym("omega"), sym("t"), sym("f")

CASES = [
    # operators and precedence
    ("x+y", XY, x + y),
    ("x-y", XY, x - y),
    ("x*y", XY, x * y),
    ("x/y", XY, x / y),
    ("x^2", XY, x**2),
    ("x**2", XY, x**2),
    ("x^y^2", XY, x ** (y**2)),
    ("2^3^2", XY, sympy.Integer(512)),
    ("-x^2", XY, -(x**2)),
    ("-x", XY, -x),
    ("x^-2", XY, x**-2),
    ("x^(-2)", XY, x**-2),
    ("x - -y", XY, x + y),
    ("x*-y", XY, -x * y),
    ("x/y/2", XY, x / y / 2),
    ("x/y*2", XY, 2 * x / y),
    ("(x+y)", XY, x + y),
    ("[x+y]^2", XY, (x + y) ** 2),
    ("{x+y}/2", XY, (x + y) / 2),
    ("((x))", XY, x),
    # implicit multiplication binds like *
    ("2m g", WEDGE, 2 * m * g),
    ("m g sin(θ)", WEDGE, m * g * sin(theta)),
    ("2(x+1)", XY, 2 * (x + 1)),
    ("(x)(y)", XY, x * y),
    ("(x+1)(y+1)", XY, (x + 1) * (y + 1)),
    ("x y^2", XY, x * y**2),
    ("2x^2", XY, 2 * x**2),
    ("m(g+M)", WEDGE, m * (g + M)),
    ("x^2 y/2", XY, x**2 * y / 2),
    # functions
    ("sqrt(x)", XY, sqrt(x)),
    ("exp(x)", XY, exp(x)),
    ("ln(x)", XY, log(x)),
    ("log(x)", XY, log(x)),
    ("log10(x)", XY, log(x, 10)),
    ("abs(x-y)", XY, Abs(x - y)),
    ("|x-y|", XY, Abs(x - y)),
    ("2|x-y|", XY, 2 * Abs(x - y)),
    ("||x-y| - 1|", XY, Abs(Abs(x - y) - 1)),
    ("sin(x)+cos(x)+tan(x)", XY, sin(x) + cos(x) + tan(x)),
    ("sec(x)+csc(x)+cot(x)", XY, sympy.sec(x) + sympy.csc(x) + sympy.cot(x)),
    ("asin(x)+acos(x)+atan(x)", XY, asin(x) + acos(x) + atan(x)),
    ("arcsin(x)+arccos(x)+arctan(x)", XY, asin(x) + acos(x) + atan(x)),
    ("sinh(x)+cosh(x)+tanh(x)", XY, sympy.sinh(x) + sympy.cosh(x) + sympy.tanh(x)),
    ("factorial(5)", XY, sympy.Integer(120)),
    ("5!", XY, sympy.Integer(120)),
    ("x!", XY, factorial(x)),
    ("(x+1)!", XY, factorial(x + 1)),
    ("sin^2(x)", XY, sin(x) ** 2),
    ("sin²(x)", XY, sin(x) ** 2),
    ("sin^-1(x)", XY, asin(x)),
    ("sin^(-1)(x)", XY, asin(x)),
    ("cos⁻¹(x)", XY, acos(x)),
    ("tan^-1 x", XY, atan(x)),
    ("ln^2 x", XY, log(x) ** 2),
    ("sin(x)^2", XY, sin(x) ** 2),
    # functions without brackets take the next factor
    ("sin theta", WEDGE, sin(theta)),
    ("sin θ cos θ", WEDGE, sin(theta) * cos(theta)),
    ("m sin^2 θ", WEDGE, m * sin(theta) ** 2),
    ("sin 2θ", WEDGE, sin(2 * theta)),
    ("sin θ^2", WEDGE, sin(theta**2)),
    ("sin x /2", XY, sin(x) / 2),  # a space ends the argument; `sin x/2` is asked about (test_errors.py)
    ("sqrt x", XY, sqrt(x)),
    ("cos sin x", XY, cos(sin(x))),
    # ...or the word typed without a space that starts with it, as physics writes `A cos ωt`
    ("A cos ωt", WAVE, A * cos(omega * t)),
    ("A cos ω t", WAVE, A * cos(omega) * t),
    ("sin kx cos ωt", WAVE, sin(k * x) * cos(omega * t)),
    ("A sin(kx - ωt)", WAVE, A * sin(k * x - omega * t)),
    ("cos 2ωt", WAVE, cos(2 * omega * t)),
    ("sin 2πft", WAVE, sin(2 * pi * f * t)),
    ("√2gh", WAVE, sqrt(2 * g * h)),
    ("sqrt 2gh", WAVE, sqrt(2 * g * h)),
    ("sin^2 ωt", WAVE, sin(omega * t) ** 2),
    ("sin ωt^2", WAVE, sin(omega * t**2)),
    ("sinθcosθ", WEDGE, sin(theta) * cos(theta)),
    ("m sinθ g", WEDGE, m * sin(theta) * g),
    ("sin|x|", XY, sin(Abs(x))),
    (
        "-m g sin(θ)cos(θ)/(M + m sin^2 θ)",
        WEDGE,
        -m * g * sin(theta) * cos(theta) / (M + m * sin(theta) ** 2),
    ),
    # constants
    ("pi", XY, pi),
    ("π", XY, pi),
    ("2 pi", XY, 2 * pi),
    ("2π x", XY, 2 * pi * x),
    ("e", XY, E),
    ("e^x", XY, exp(x)),
    ("exp^(2)(x)", XY, exp(x) ** 2),  # a power of exp with its argument after it (exp^(x) alone is asked)
    ("2e", XY, 2 * E),
    # degrees
    ("30°", XY, pi / 6),
    ("sin(30°)", XY, Rational(1, 2)),
    ("sin 30°", XY, Rational(1, 2)),
    ("(1+30)°", XY, 31 * pi / 180),  # on a symbol it is refused (test_errors.py): x is an angle already
    ("45 deg", XY, pi / 4),
    ("45deg", XY, pi / 4),
    ("45º", XY, pi / 4),
    # Unicode operators and spaces
    ("x − y", XY, x - y),
    ("x × y", XY, x * y),
    ("x · y", XY, x * y),
    ("x ⋅ y", XY, x * y),
    ("x ÷ y", XY, x / y),
    ("x ⁄ y", XY, x / y),  # fraction slash
    ("x ∕ y", XY, x / y),  # division slash
    ("√x", XY, sqrt(x)),
    ("√(x+1)", XY, sqrt(x + 1)),
    ("2√3", XY, 2 * sqrt(3)),
    ("x²", XY, x**2),
    ("x⁻²y", XY, y / x**2),
    ("x³⁻¹", XY, None),  # placeholder replaced below: a sign after digits is a new superscript
    ("x\u00a0y", XY, x * y),
    ("x\u3000y", XY, x * y),
    ("x\u2009y", XY, x * y),
]
CASES = [case for case in CASES if case[2] is not None]


@pytest.mark.parametrize(("text", "declared", "expected"), CASES, ids=[c[0] for c in CASES])
def test_syntax_reads_as_the_expected_expression(text, declared, expected):
    got = read(text, *declared).expr
    assert same(got, expected), (got, expected)


NUMBERS = [
    ("0.5", Rational(1, 2)),
    (".5", Rational(1, 2)),
    ("3.1416", Rational(31416, 10000)),
    ("4.58e3", sympy.Integer(4580)),
    ("4.58E-3", Rational(458, 100000)),
    ("4.58e+3", sympy.Integer(4580)),
    ("4.58×10^3", sympy.Integer(4580)),
    ("4.58*10^-3", Rational(458, 100000)),
    ("4.58 x 10^3", sympy.Integer(4580)),
    ("4.58 x 10^-3", Rational(458, 100000)),
    ("50%", Rational(1, 2)),
    ("12.5 %", Rational(1, 8)),
    ("1e-400", Rational(1, 10**400)),
    ("0001.500", Rational(3, 2)),
]


@pytest.mark.parametrize(("text", "expected"), NUMBERS, ids=[n[0] for n in NUMBERS])
def test_numbers_are_exact_rationals(text, expected):
    got = read(text).expr
    assert got == expected
    assert not got.has(sympy.Float)


@pytest.mark.parametrize(
    ("text", "readings"),
    [
        ("4.58 x 10^3", ("4.58*10", "4.58*x*10")),
        ("2 x 10^3 x", ("2*10", "2*x*10")),  # a calculator's times sign, then the symbol
        ("3 x 2", ("3*2", "3*x*2")),
        ("2x10^3 x", ("2*10", "2*x*10")),  # the times sign glued to the 10
        ("2x10³", ("2*10", "2*x*10")),
    ],
)
def test_x_between_numbers_is_asked_about_when_declared(text, readings):
    with pytest.raises(AmbiguousInput, match="a times sign or your symbol x") as asked:
        read(text, "x")
    assert asked.value.readings == readings


@pytest.mark.parametrize(
    ("text", "declared", "expected"),
    [
        ("2x10^3 y", ("y",), 2000 * y),  # a calculator's power of ten, its × glued to the 10
        ("2X10^3 y", ("y",), 2000 * y),
        ("2x10³ y", ("y",), 2000 * y),
        ("2X10^3 x", ("x",), 2000 * x),  # a capital X is no x
        ("2x10^3", ("x_10",), 2 * sym("x_10") ** 3),  # x_10 declared: the name
    ],
)
def test_a_glued_times_ten_is_a_power_of_ten_where_x_is_not_declared(text, declared, expected):
    assert read(text, *declared).expr == expected


@pytest.mark.parametrize(
    ("text", "expected"), [("2*x*10^3", 2000 * x), ("2 x*10^3", 2000 * x), ("2×10^3 x", 2000 * x)]
)
def test_x_beside_a_sign_is_the_declared_symbol(text, expected):
    assert read(text, "x").expr == expected


@pytest.mark.parametrize(("text", "expected"), [("50 % x", x / 2), ("x 50 %", x / 2), ("x·12.5%", x / 8)])
def test_a_percentage_of_a_number_beside_a_symbol_is_its_fraction(text, expected):
    assert read(text, "x").expr == expected


COEFFICIENTS = [
    ("1/2 m v^2", ("m", "v"), m * v**2 / 2),
    ("-3/4 x", XY, -3 * x / 4),
    ("x + 1/2 y", XY, x + y / 2),
    ("1/2 (x+y)", XY, (x + y) / 2),
    ("1/2 m v^2 + m g h", ("m", "v", "g", "h"), m * v**2 / 2 + m * g * h),
]


@pytest.mark.parametrize(("text", "declared", "expected"), COEFFICIENTS, ids=[c[0] for c in COEFFICIENTS])
def test_integer_fraction_opening_a_term_is_a_coefficient(text, declared, expected):
    assert same(read(text, *declared).expr, expected)


def test_euler_e_gives_way_to_a_declared_e():
    e_charge = sym("e")
    assert read("2e", "e").expr == 2 * e_charge
    assert read("e^2", "e").expr == e_charge**2


def test_declared_symbol_objects_are_used_as_given():
    theta_real = sympy.Symbol("theta", real=True)
    from physics.mathinput import parse_math

    got = parse_math("sin(θ)", {"theta": theta_real}).expr
    assert got == sin(theta_real)
    assert got.free_symbols == {theta_real}


def test_superscript_sign_after_digits_starts_a_new_power():
    # x³⁻¹ is (x³)⁻¹: two superscripts in a row apply one after the other
    assert read("x³⁻¹", "x").expr == x**-3
