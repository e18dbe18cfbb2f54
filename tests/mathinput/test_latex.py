"""LaTeX pasted from equation editors reads as the plain text it means; any other command is refused at
its backslash, and hostile LaTeX is refused within the reader's size limits."""

from __future__ import annotations

import random

import pytest

from physics.errors import AnswerError, ParseError, TooLarge, UnknownSymbol
from physics.mathinput import DEFAULT_LIMITS, InputLimits, parse_math
from tests.mathinput.support import names, read, same
from tests.mathinput.test_fuzz import DECLARED, _generate, check_one

WEDGE = ("m", "M", "g", "theta")
NAMES = (
    "m",
    "M",
    "g",
    "theta",
    "x",
    "y",
    "v_0",
    "theta_0",
    "v_max",
    "omega",
    "t",
    "Delta",
    "phi",
    "hbar",
    "L",
)

READS_AS_PLAIN = [
    # (LaTeX, the plain text it means)
    (r"-\frac{m g \sin\theta\cos\theta}{M + m\sin^2\theta}", "-m g sin(θ)cos(θ)/(M + m sin^2 θ)"),
    (r"-\dfrac{m g \sin\theta\cos\theta}{M + m\sin^{2}\theta}", "-m g sin(θ)cos(θ)/(M + m sin^2 θ)"),
    (r"\tfrac{x}{y}", "x/y"),
    # the spaces that end a control word are no gap, as in LaTeX: the argument goes on (`cos ωt`)
    (r"x\cos\omega t", "x cos(ω t)"),
    (r"x \cos \omega t", "x cos(ω t)"),
    (r"x\cos\omega\,t", "x cos(ω) t"),
    (r"\sin\theta \cos\theta", "sin(θ) cos(θ)"),
    (r"\frac{1}{2} m v_0^2", "1/2 m v_0^2"),
    (r"\frac12 m v_{0}^{2}", "(1/2) m v_0^2"),
    (r"\frac xy", "x/y"),
    (r"\frac{x}{y}^2", "(x/y)^2"),
    (r"x\frac{1}{y}", "x*(1/y)"),
    (r"\frac{\frac{x}{y}}{M}", "(x/y)/M"),
    (r"\frac{x+1}{y-1}", "(x+1)/(y-1)"),
    (r"\frac{x}{y} \frac{m}{M}", "(x/y)(m/M)"),
    (r"\sqrt{x}", "sqrt(x)"),
    (r"\sqrt{2 g L}", "sqrt(2 g L)"),
    (r"\sqrt2", "sqrt(2)"),
    (r"\sqrt{x}^2", "sqrt(x)^2"),
    (r"\sqrt[3]{x}", "x^(1/3)"),
    (r"\sqrt[ 4 ]{x + y}", "(x+y)^(1/4)"),
    (r"\sqrt[3]8", "2"),
    # functions, with powers as the plain syntax reads them
    (r"\sin\theta", "sin(theta)"),
    (r"\sin \theta", "sin θ"),
    (r"\sin^2\theta", "sin^2 θ"),
    (r"\sin^{2}(x)", "sin^2(x)"),
    (r"\sin^{-1}(x)", "asin(x)"),
    (r"\sin 2\theta", "sin 2θ"),
    (r"\sin{x}", "sin(x)"),
    (r"\cos\left(\omega t\right)", "cos(omega t)"),
    (r"\tan x + \sec x + \csc x + \cot x", "tan x + sec x + csc x + cot x"),
    (r"\arcsin x + \arccos x + \arctan x", "asin(x) + acos(x) + atan(x)"),
    (r"\sinh x + \cosh x + \tanh x", "sinh(x) + cosh(x) + tanh(x)"),
    (r"\exp(x) + \ln x + \log x", "exp(x) + ln(x) + log(x)"),
    (r"\log_{10} x + \log_10 y", "log10(x) + log10(y)"),
    (r"\operatorname{arcsec}(x)", "asec(x)"),
    # letters
    (r"\theta", "theta"),
    (r"\theta", "θ"),
    (r"\vartheta + \varphi", "theta + phi"),
    (r"\Delta x", "Delta x"),
    (r"\theta_{0} + \theta_0", "2 theta_0"),
    (r"2\pi", "2 pi"),
    (r"\pi x^2", "π x^2"),
    (r"\hbar\omega", "hbar omega"),
    (r"m\theta", "m theta"),
    # operators, brackets and spaces
    (r"m \cdot g", "m*g"),
    (r"m \times g", "m*g"),
    (r"m \div g", "m/g"),
    (r"4.58 \times 10^{3}", "4.58*10^3"),
    (r"\left( m + M \right) g", "(m + M) g"),
    (r"\left[ m + M \right]^2", "[m + M]^2"),
    (r"\left| x - y \right|", "|x - y|"),
    (r"\lvert x \rvert", "|x|"),
    (r"\left\{ x + y \right\}", "{x + y}"),
    (r"\{ x + y \} m", "(x + y) m"),
    (r"\bigl( x + y \bigr)", "(x + y)"),
    (r"m\,g\;L\:x\!y\quad t\qquad M", "m g L x y t M"),
    (r"\displaystyle \frac{x}{y}", "x/y"),
    (r"{x + y}^{2}", "(x + y)^2"),
    (r"x^{y^{2}}", "x^(y^2)"),
    (r"x^{-1}", "x^-1"),
    (r"e^{-\frac{t}{x}}", "e^(-t/x)"),
    (r"30^\circ", "30°"),
    (r"\sin(30^{\circ})", "sin(30°)"),
    (r"30{}^{\circ}", "30°"),
    (r"30\degree", "30°"),
    (r"45\%", "45%"),
    # subscripts and names in text fonts
    (r"v_{0} t", "v_0 t"),
    (r"v_{\text{max}}", "v_max"),
    (r"v_{\mathrm{max}}", "v_max"),
    (r"v_\mathrm{max}", "v_max"),
    (r"v_{\max}", "v_max"),  # MathQuill sets a typed max as the operator \max
    (r"v_{\rm max}", "v_max"),  # plain TeX's roman, a font switch
    (r"v_\max", "v_max"),
    # The delimiters of LaTeX math around the whole answer, as copied from a document or a page
    (r"$\frac{x}{y}$", "x/y"),
    (r"$$\frac{x}{y}$$", "x/y"),
    (r"\(\frac{x}{y}\)", "x/y"),
    (r" \[ x^{2} \] ", "x^2"),
    # and what a chatbot wraps its answer in: markdown's bold, LaTeX's box, one inside another
    (r"**x/(x + y)**", "x/(x + y)"),
    (r"\boxed{\frac{x}{y}}", "x/y"),
    (r"\[\boxed{x^{2}}\]", "x^2"),
    (r"**$\boxed{\frac{x}{y}}$**", "x/y"),
    (r"\mathrm{v_0}", "v_0"),
    (r"\mathrm{v}_{0}", "v_0"),
    (r"\text{m}\text{g}", "m g"),
    (r"mv_{0}", "m v_0"),
    # plain TeX's fraction: the brace's text before \over over the text after it (it was refused)
    (r"{x \over x + y}", "x/(x + y)"),
    (r"x y \over M", "(x y)/M"),
    (r"{{x} \over {y}} M", "(x/y) M"),
    (r"{x \over 2}{y \over M}", "(x/2)(y/M)"),
    (r"\frac{x \over y}{M}", "(x/y)/M"),
    (r"\left( {x \over y} \right)^2", "(x/y)^2"),
]


@pytest.mark.parametrize(("latex", "plain"), READS_AS_PLAIN, ids=[c[0] for c in READS_AS_PLAIN])
def test_latex_reads_as_the_plain_text_it_means(latex, plain):
    assert read(latex, *NAMES).expr == read(plain, *NAMES).expr


def test_the_wedge_answer_reads_back_as_plain_text():
    parsed = read(r"-\frac{m g \sin\theta\cos\theta}{M + m\sin^2\theta}", *WEDGE)
    assert parsed.read_as.text == "-m*g*sin(theta)*cos(theta)/(M + m*sin(theta)**2)"


LATEX_ERRORS = [
    # (text, position, words the message must contain)
    (r"\foo", 0, r"Unknown LaTeX command \foo: type that part in plain text, as in sqrt(x)"),
    (r"m g \vec{x}", 4, r"Unknown LaTeX command \vec: type the symbol as the problem lists it"),
    (r"x \pm y", 2, r"Unknown LaTeX command \pm: give one answer"),
    (r"x = \frac{m}{M}", 2, "Give the expression alone, without 'x =': type only \\frac{m}{M}"),
    (r"x \approx y", 2, r"Unknown LaTeX command \approx: type only the expression"),
    (r"x \\ y", 2, r"Unknown LaTeX command \\"),
    (r"\int x", 0, r"Unknown LaTeX command \int: an answer is an expression"),
    (r"\Alpha", 0, r"type the letter A (LaTeX has no \Alpha)"),
    (r"\sinx", 0, r"Unknown LaTeX command \sinx: put a space after \sin, as in \sin x."),
    ("\\" + "a" * 500, 0, "Unknown LaTeX command \\" + "a" * 24 + "…:"),
    ("x \\", 2, "A '\\' ends the answer"),
    (r"\frac{x}{y", 8, r"the '{' of \frac is never closed"),
    (r"\frac{x}", 8, r"\frac needs a denominator in braces"),
    (r"\frac{x}+y", 8, r"\frac needs a denominator in braces"),
    (r"\frac{}{y}", 5, r"\frac has an empty numerator"),
    (r"\frac{x}{ }", 8, r"\frac has an empty denominator"),
    (r"\sqrt{}", 5, r"\sqrt has an empty argument"),
    (r"\sqrt", 5, r"\sqrt needs an argument in braces"),
    (r"\sqrt[n]{x}", 5, r"for any other root write a power, as in x^(1/n)"),
    (r"\sqrt[1]{x}", 6, "A root's index is 2 or more"),
    (r"\sqrt{x", 5, r"the '{' of \sqrt is never closed"),
    (r"\frac{x)}{y}", 7, "')' does not match the '{'"),
    (r"\left( x \right.", 9, r"\right. (a bracket left blank) is not read"),
    (r"\left x", 0, r"\left needs a bracket after it"),
    (r"\left( x \right]", 9, "']' does not match the '('"),
    (r"\log_2 x", 4, r"Write a logarithm to another base b as ln(x)/ln(b)"),
    (r"\text{ m/s}", 8, r"\text{…} may only hold a name here"),
    (r"\mathrm x", 8, r"\mathrm needs a name in braces"),
    (r"v_{}", 2, "An empty subscript"),
    (r"v_{0", 2, "the '{' of this subscript is never closed"),
    (r"v_{x+y}", 4, "A subscript holds letters and digits"),
    (r"{x + \frac{y}{M}", 0, "this '{' is never closed"),
    (r"x}", 1, "Unmatched '}'"),
    (r"\circ", 0, r"write degrees as 30^\circ"),
    (r"$x$ + y", 0, "Leave out the $ signs"),  # delimiters around only part of the answer
    (r"\boxed{x}/\boxed{y}", 0, "Unknown LaTeX command \\boxed"),  # two boxes: none around all of it
    (r"x^2 $", 4, "Leave out the $ signs"),
    (r"v_{\sin}", 3, "A subscript holds letters and digits"),
    (r"{x \over y \over M}", 11, r"Two \over in one brace: write each fraction as \frac{a}{b}"),
    (r"x \over y \over M", 10, r"Two \over in one brace"),
    (r"x \overline{y}", 2, r"Unknown LaTeX command \overline"),
    # Mathematica's named characters, as its plain text copies them: once "Unknown LaTeX command \["
    (r"x sin(\[Theta])", 6, r"\[Theta] is Mathematica's name for θ: type θ or theta."),
    (r"\[CapitalOmega] x", 0, r"\[CapitalOmega] is Mathematica's name for Ω: type Ω or Omega."),
    (r"x sin(\[CurlyTheta])", 6, r"\[CurlyTheta] is Mathematica's name for θ"),
    (r"sin(30 \[Degree]) x", 7, r"\[Degree] is Mathematica's name for °: type °."),
    (r"x \[Wolf]", 2, r"\[Wolf] is a Mathematica character, not read here"),
]


@pytest.mark.parametrize(("text", "position", "words"), LATEX_ERRORS, ids=[e[0][:40] for e in LATEX_ERRORS])
def test_latex_error_points_at_the_offending_command(text, position, words):
    with pytest.raises(ParseError) as caught:
        read(text, *NAMES)
    assert caught.value.position == position
    assert words in caught.value.message


NAME_ERRORS = [
    # (text, declared, the unknown word, its position): a command or a braced subscript is one name
    (r"m\theta_{1}", ("m", "theta"), "theta_1", 1),
    (r"x_{mg}", ("x_m", "g"), "x_mg", 0),  # x_{mg} is never x_m times g
    (r"\theta", ("t", "h", "e", "a"), "theta", 0),  # a command is never split into letters
    (r"m + \mathrm{mg}", ("m", "g"), "mg", 4),
    (r"2 \Omega", ("omega",), "Omega", 2),
]


@pytest.mark.parametrize(
    ("text", "declared", "word", "position"), NAME_ERRORS, ids=[e[0] for e in NAME_ERRORS]
)
def test_a_name_typed_as_one_is_not_split(text, declared, word, position):
    with pytest.raises(UnknownSymbol) as caught:
        read(text, *declared)
    assert caught.value.symbol == word
    assert caught.value.position == position


def test_the_parts_of_a_word_read_from_latex_keep_their_typed_positions():
    # `\theta_0sin`: the word theta_0sin, whose `sin` was typed at 8, not at 7 as in the word
    with pytest.raises(ParseError) as caught:
        read(r"\theta_0sin", "theta_0")
    assert caught.value.position == 8
    assert "sin needs an argument" in caught.value.message


def test_a_tilde_is_a_space_only_in_latex():
    assert read(r"m~\theta", *WEDGE).expr == read("m theta", *WEDGE).expr
    with pytest.raises(ParseError) as caught:
        read("m~g", *WEDGE)
    assert caught.value.position == 1


HOSTILE = [
    ("deep fractions", r"\frac{" * 60 + "x" + "}{y}" * 60),
    ("deep roots", r"\sqrt{" * 60 + "x" + "}" * 60),
    ("deep left brackets", r"\left(" * 60 + "x" + r"\right)" * 60),
    ("deep braces", "{" * 60 + "x" + "}" * 60),
    ("many fractions", r"\frac{x}{y}+" * 60 + "x"),
    ("100k backslashes", "\\" * 100_000),
    ("100k opening braces", "{" * 100_000),
    ("100k fractions", r"\frac{x}{y}" * 10_000),
    ("huge root index", r"\sqrt[999]{2}"),
    ("power of a fraction", r"\frac{9}{7}^{9^{9}}"),
]


@pytest.mark.timeout(10)
@pytest.mark.parametrize("text", [h[1] for h in HOSTILE], ids=[h[0] for h in HOSTILE])
def test_hostile_latex_is_refused_within_the_size_limits(text):
    with pytest.raises(TooLarge) as caught:
        read(text, "x", "y")
    assert 0 <= (caught.value.position or 0) <= len(text)


@pytest.mark.timeout(10)
@pytest.mark.parametrize(
    "text",
    [
        "\\" * 1999,
        r"\frac{}{}" * 100,
        r"\frac{x}{y}}" + "}" * 100,
        "}" * 1000,
        r"\frac{x}{y" * 100,
        r"\sqrt[" * 300,
        r"\left" * 300,
        r"v_{" * 500,
    ],
    ids=[
        "backslashes",
        "empty fractions",
        "extra braces",
        "closing braces",
        "open fractions",
        "open roots",
        "lefts",
        "subscripts",
    ],
)
def test_broken_latex_is_refused_at_once(text):
    with pytest.raises(AnswerError) as caught:
        read(text, "x", "y")
    assert 0 <= (caught.value.position or 0) <= len(text)


def test_deep_latex_nesting_is_too_large_even_with_lifted_size_limits():
    lifted = InputLimits(max_length=10**6, max_tokens=10**6)
    with pytest.raises(TooLarge):
        parse_math(r"\frac{" * 20_000 + "x" + "}{x}" * 20_000, names("x"), limits=lifted)


def test_latex_tokens_count_toward_the_token_limit():
    fits = r"\frac{x}{x}+" * 20 + "x"
    read(fits, "x")
    with pytest.raises(TooLarge):
        read(r"\frac{x}{x}+" * (DEFAULT_LIMITS.max_tokens // 8) + "x", "x")


def payloads(marker: str) -> list[str]:
    return [
        rf"\text{{__import__('os').system('touch {marker}')}}",
        rf"\frac{{__import__('os').system('touch {marker}')}}{{1}}",
        rf"\operatorname{{eval}}(\text{{touch {marker}}})",
        r"\mathrm{exec}(x)",
        r"\mathrm{__class__}",
        rf"\input{{{marker}}}",
        rf"\write18{{touch {marker}}}",
        rf"\immediate\write18{{touch {marker}}}",
        r"\def\x{\x}\x",
        r"\catcode`\^=13",
        r"\newcommand{\x}{x}",
        r"\sqrt[__import__('os')]{x}",
        r"x_{__import__}",
        r"\left( __import__ \right)",
    ]


def test_latex_payloads_are_refused_and_nothing_runs(tmp_path):
    marker = tmp_path / "pwned"
    for payload in payloads(str(marker)):
        with pytest.raises(AnswerError):
            read(payload, "x")
    assert not marker.exists()


@pytest.mark.parametrize("seed", range(3))
def test_the_latex_of_a_reading_reads_back_to_the_same_expression(seed):
    rng = random.Random(seed)
    for _ in range(80):
        text, _, _ = _generate(rng, 4)
        try:
            parsed = parse_math(text, DECLARED)
        except AnswerError:
            continue
        again = parse_math(parsed.read_as.latex, DECLARED)
        assert same(again.expr, parsed.expr), (text, parsed.read_as.latex)


LATEX_TOKENS = [
    "\\frac{", "}{", "}", "{", "\\sqrt", "\\sqrt[3]{", "\\sin", "\\theta", "\\left(", "\\right)", "\\cdot",
    "\\,", "_{", "^{", "^\\circ", "\\mathrm{", "\\foo", "~", "x", "2", "+", "-", "\\pi", "v_{0}", "\\left|",
    "\\right|", "\\", " ", "\\{", "\\}", "\\log_{10}", "\\text{", "m", "^",
]  # fmt: skip


@pytest.mark.parametrize("seed", range(4))
def test_random_latex_raises_only_answer_errors_and_reads_back_consistently(seed):
    rng = random.Random(seed)
    for _ in range(250):
        check_one("".join(rng.choice(LATEX_TOKENS) for _ in range(rng.randint(1, 12))))


@pytest.mark.parametrize(
    ("latex", "meant"),
    [
        (r"\Delta x/\Delta t", "Delta_x/Delta_t"),  # MathQuill's Δx: the space ending \Delta is no gap
        (r"\frac{\Delta x}{\Delta t}", "Delta_x/Delta_t"),
        (r"\Delta x \Delta t", "Delta_x*Delta_t"),
    ],
)
def test_a_latex_letter_and_the_word_after_it_are_the_name_they_show(latex: str, meant: str) -> None:
    assert read(latex, "Delta_x", "Delta_t").read_as.text == meant


def test_a_latex_letter_that_is_a_name_stays_apart_from_the_word_after_it() -> None:
    assert read(r"\Delta x", "Delta", "x", "Delta_x").read_as.text == "Delta*x"
    with pytest.raises(UnknownSymbol):
        read(r"\Delta\, x", "Delta_x")  # a space typed with \, is a gap
