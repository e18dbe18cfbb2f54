"""read_as shows the student how their input was grouped, rendered from the parse tree."""

from __future__ import annotations

import pytest

from physics.errors import AnswerError
from physics.mathinput import parse_expression, parse_math
from tests.mathinput.support import names, read, same

WEDGE = ("m", "M", "g", "theta")

TEXT = [
    ("-m g sin(θ)cos(θ)/(M + m sin^2 θ)", WEDGE, "-m*g*sin(theta)*cos(theta)/(M + m*sin(theta)**2)"),
    ("mgh", ("m", "g", "h"), "m*g*h"),
    ("((m))", WEDGE, "m"),
    ("m (g + M)", WEDGE, "m*(g + M)"),
    ("(m g)/(M)", WEDGE, "m*g/M"),
    ("m/(g M)", WEDGE, "m/(g*M)"),
    ("m/(g/M)", WEDGE, "m/(g/M)"),
    ("m - (g + M)", WEDGE, "m - (g + M)"),
    ("m - (g - M)", WEDGE, "m - (g - M)"),
    ("m + (g + M)", WEDGE, "m + g + M"),
    ("-(m + g)", WEDGE, "-(m + g)"),
    ("m^2^g", WEDGE, "m**g**g"[:0] + "m**2**g"),
    ("(m^2)^g", WEDGE, "(m**2)**g"),
    ("(-m)^2", WEDGE, "(-m)**2"),
    ("m^(-2)", WEDGE, "m**(-2)"),
    ("m^(g M)", WEDGE, "m**(g*M)"),
    ("m^(1/2)", WEDGE, "m**(1/2)"),
    ("m v0^2", ("m", "v_0"), "m*v_0**2"),
    ("U_0", ("U0",), "U0"),
    ("θ", WEDGE, "theta"),
    ("sin^-1(m/M)", WEDGE, "asin(m/M)"),
    ("arctan θ", WEDGE, "atan(theta)"),
    ("ln m", WEDGE, "log(m)"),
    ("|m - M|", WEDGE, "abs(m - M)"),
    ("√(m g)", WEDGE, "sqrt(m*g)"),
    ("1/2 m g^2", WEDGE, "1/2*m*g**2"),
    ("4.58E3", WEDGE, "4.58e3"),
    ("30°", WEDGE, "30*pi/180"),
    ("50%", WEDGE, "50/100"),
    ("3!", WEDGE, "factorial(3)"),
    ("2πm", WEDGE, "2*pi*m"),
    ("e^m", WEDGE, "e**m"),
    ("m·g × M", WEDGE, "m*g*M"),
    ("m*(-g)", WEDGE, "m*(-g)"),
    ("m + (-g)", WEDGE, "m + (-g)"),
]


@pytest.mark.parametrize(("text", "declared", "expected"), TEXT, ids=[t[0] for t in TEXT])
def test_read_as_text_shows_the_grouping_in_contract_style(text, declared, expected):
    assert read(text, *declared).read_as.text == expected


@pytest.mark.parametrize(("text", "declared", "expected"), TEXT, ids=[t[0] for t in TEXT])
def test_read_as_text_parses_back_to_the_same_expression(text, declared, expected):
    first = read(text, *declared)
    again = parse_math(first.read_as.text, names(*declared))
    assert same(again.expr, first.expr)


LATEX = [
    (
        "-m g sin(θ)cos(θ)/(M + m sin^2 θ)",
        WEDGE,
        r"-\frac{m g \sin\left(\theta\right) \cos\left(\theta\right)}{M + m \sin^{2}\left(\theta\right)}",
    ),
    ("1/2 m v_0^2", ("m", "v_0"), r"\frac{1}{2} m v_{0}^{2}"),
    ("U0/r0", ("U0", "r0"), r"\frac{U_{0}}{r_{0}}"),
    ("sqrt(m/M)", WEDGE, r"\sqrt{\frac{m}{M}}"),
    ("(m+M)^2", WEDGE, r"\left(m + M\right)^{2}"),
    ("|m|", WEDGE, r"\left|m\right|"),
    ("mu_k g", ("mu_k", "g"), r"\mu_{k} g"),
    ("Δ", ("Delta",), r"\Delta"),
    ("2 3.5", WEDGE, None),
    ("2*3", WEDGE, r"2 \cdot 3"),
    ("asin m", WEDGE, r"\arcsin\left(m\right)"),
    ("30°", WEDGE, r"30^{\circ}"),
    ("4.58e-3", WEDGE, r"4.58 \cdot 10^{-3}"),
    ("e^m", WEDGE, r"e^{m}"),
    ("pi m", WEDGE, r"\pi m"),
    ("log10(m)", WEDGE, r"\log_{10}\left(m\right)"),
]
LATEX = [case for case in LATEX if case[2] is not None]


@pytest.mark.parametrize(("text", "declared", "expected"), LATEX, ids=[t[0] for t in LATEX])
def test_read_as_latex_uses_frac_and_named_functions(text, declared, expected):
    assert read(text, *declared).read_as.latex == expected


BESIDE_A_SYMBOL_E = [
    # (typed, read_as text, LaTeX): where a symbol e is declared (a coefficient of restitution), Euler's
    # number is exp(1), set upright; both had read e^2 h, as the symbol's square does
    ("exp(2) h", "exp(2)*h", r"\mathrm{e}^{2} h"),
    ("%e^2 h", "exp(1)**2*h", r"\mathrm{e}^{2} h"),
    ("e^2 h", "e**2*h", r"e^{2} h"),  # the symbol
]


@pytest.mark.parametrize(("typed", "text", "latex"), BESIDE_A_SYMBOL_E, ids=[c[0] for c in BESIDE_A_SYMBOL_E])
def test_eulers_number_is_set_apart_from_a_declared_symbol_e(typed: str, text: str, latex: str) -> None:
    reading = read(typed, "e", "h")
    assert (reading.read_as.text, reading.read_as.latex) == (text, latex)
    assert same(parse_math(text, names("e", "h")).expr, reading.expr)


@pytest.mark.parametrize(
    "text",
    ["-m*g*tan(theta)/(M*(1 + tan(theta)**2) + m*tan(theta)**2)", "sqrt(144*U0/(m*r0**2))", "mgsin(theta)"],
)
def test_parse_expression_reads_as_parse_math_without_rendering(text):
    table = names("m", "M", "g", "theta", "U0", "r0")
    assert parse_expression(text, table) == parse_math(text, table).expr


@pytest.mark.parametrize("text", ["m*", "q*m", "1/0", "m g h h h h h" * 200])
def test_parse_expression_refuses_what_parse_math_refuses(text):
    table = names("m", "g", "h")
    with pytest.raises(AnswerError) as refused:
        parse_math(text, table)
    with pytest.raises(type(refused.value)) as also:
        parse_expression(text, table)
    assert also.value.position == refused.value.position
