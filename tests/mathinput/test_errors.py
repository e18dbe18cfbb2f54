"""Every error kind a student can cause, with a message they understand and a position into the text."""

from __future__ import annotations

import pytest

from physics.errors import AmbiguousInput, ParseError
from physics.mathinput import parse_math
from tests.mathinput.support import read

PARSE_ERRORS = [
    # (text, position, words the message must contain)
    ("", 0, "empty"),
    ("   ", 0, "empty"),
    ("2+", 1, "Nothing after '+'"),
    ("x*", 1, "Nothing after '*'"),
    ("x^", 1, "Nothing after '^'"),
    ("x**", 1, "Nothing after '**'"),
    ("(x+)", 2, "Nothing after '+'"),
    ("*x", 0, "Nothing before '*'"),
    ("/x", 0, "Nothing before '/'"),
    ("(*x)", 1, "Nothing before '*'"),
    ("x+*y", 2, "Nothing between '+' and '*'"),
    ("(x+1", 0, "never closed"),
    ("x*(y+(x)", 2, "never closed"),
    ("x(", 1, "never closed"),
    ("x+1)", 3, "Unmatched ')'"),
    ("(x]", 2, "does not match"),
    ("|x", 0, "never closed"),
    ("()", 0, "Empty brackets"),
    ("x # y", 2, "Unexpected character '#'"),
    ("x; y", 1, "Unexpected character ';'"),
    # a command's end, as Maxima and MATLAB type it: refused at the end, as STACK refuses it
    ("x y;", 3, "Leave out the ';' at the end"),
    ("x y ; ", 4, "Leave out the ';' at the end"),
    ("x.y", 1, "Write a product with * or a space, not '.'"),
    ("x' + y", 1, "A prime (x') is not read here"),  # a velocity only in a Lagrangian or energy part
    ("2 y′", 3, "A prime (y′) is not read here"),  # a dot for a product, as some schools write
    ("sin(x).y", 6, "not '.'"),
    ("x..", 1, "Unexpected character '.'"),
    ("4,58", 1, "4,58: a decimal comma is not read; write 4.58"),
    ("x, y", 1, "Commas are not used in answers: give one expression"),
    ("(x, y)", 2, "not a pair or a list"),
    ("atan2(y, x)", 7, "a function of several arguments cannot be written; write the angle as atan(y/x)."),
    ("atan2(3,4)", 7, "a function of several arguments cannot be written; write the angle as atan(y/x)."),
    ("pow(2,5)", 5, "a function of several arguments cannot be written; write a power with ^, as x^2"),
    ("sin(4,58)", 5, "4,58: a decimal comma is not read; write 4.58"),  # one argument: a decimal comma
    ("pow(x, 2)", 5, "cannot be written; write a power with ^, as x^2 or x^(1/2)."),  # code's power
    ("POWER(x, 0.5)", 7, "write a power with ^"),  # a spreadsheet's
    ("nthroot(x, 3)", 9, "write a root as a power, as x^(1/3), or with sqrt(x)."),  # MATLAB's
    ("2 max(x, (y + 1), y)", 7, "a function of several arguments cannot be written."),
    ("sin(x, y)", 5, "sin(…) takes one argument."),
    ("sin(x) (y, x)", 9, "not a pair or a list"),
    ("x = y", 2, "Give the expression alone, without 'x ='"),
    ("≈ 2 x", 0, "without '≈'"),
    # LaTeX is read (test_latex.py); a command it does not know is refused at its backslash
    ("-\\frac{x}{\\vec{y}}", 10, "Unknown LaTeX command \\vec: type the symbol as the problem lists it"),
    (
        "m\\mathbf{y}",
        1,
        "Unknown LaTeX command \\mathbf: type the symbol as the problem lists it (v, v_x, F_net), in plain letters: bold is not read",
    ),  # not "accents"
    ("\\boldsymbol{x}", 0, "in plain letters: bold is not read"),
    (
        "y{\\over x+y}",
        2,
        "\\over has nothing before it: put the numerator before it in the same brace",
    ),  # was "Empty brackets"
    ("\\over x", 0, "\\over has nothing before it"),
    ("x \\sin\\thetay", 6, "Unknown LaTeX command \\thetay: put a space after \\theta, as in \\theta y"),
    (
        "0.5 x y %",
        8,
        "A % goes after a number, as in 50 % y: after y it would divide it by 100.",
    ),  # was y/100
    ("(x + y)%", 7, "A % goes after a number"),
    ("12 500", 3, "12 500: two numbers side by side; for one number, write 12500 (or 12.5e3)"),
    ("x^2 3", 4, "the number after a power is a separate factor"),
    ("x^2 10^3", 4, "the number after a power is a separate factor"),  # not taken for a power of ten
    ("sin", 0, "sin needs an argument"),
    ("sin^2", 0, "sin needs an argument"),
    ("x + sin -x", 8, "brackets"),
    # A calculator's key label for the inverse: not tan of minus something
    ("tan-1(x/y)", 3, "Did you mean the inverse, tan^-1(…) (also written atan(…))?"),
    ("sin -1 x", 4, "Did you mean the inverse, sin^-1(…)"),
    ("cos-2(x)", 3, "Put the argument of cos in brackets"),
    ("sin^(2)", 0, "sin needs an argument"),
    ("sin^x", 4, "Write a power of sin as sin^2(x)"),
    ("!x", 0, "Unexpected '!'"),
    ("x⁻", 1, "superscript"),
    # A degree sign on a symbol, which is an angle already: not θ·π/180, as it read
    ("cos(x°)", 5, "x is an angle already: leave out the ° after it"),
    ("2 sin x deg", 8, "leave out the deg"),
    ("sin (90-x)°", 10, "put the ° after the numbers alone"),
    # e's power written with exp's name, as WeBWorK and calculators show e^x: once "exp needs an argument"
    ("y exp^(-x/2)", 5, "Did you mean e^(-x/2)? Write e's power as e^(-x/2) or exp(-x/2), not both."),
    ("exp^(x)", 3, "Did you mean e^(x)?"),
    # a sign that looks like a Greek letter, offered where the letter is looked for: once "Unexpected character"
    ("sin ∝", 4, "∝ is the sign for 'proportional to', not read here: for α type α or alpha."),
    # π with a spreadsheet's brackets, PI(): once "Empty brackets"
    ("2 pi() x", 4, "π is a number, not a function: type pi without the brackets."),
    ("2π() x", 2, "type π without the brackets"),
    # MATLAB's element-wise operators and Python's module names, as code copied into an answer types them:
    # once "Unexpected character '.'" and "Write a product with * or a space, not '.'"
    ("x*y.^2", 3, "Did you mean ^? .^ is MATLAB's element-wise power: type ^ alone."),
    ("x.*y", 1, "Did you mean *? .* is MATLAB's element-wise product"),
    ("(x+y)./2", 5, "Did you mean /? ./ is MATLAB's element-wise division"),
    ("np.sqrt(x)", 2, "Leave out np.: type the function or constant alone, as in sqrt(x) or pi."),
    ("2*math.pi*x", 6, "Leave out math."),
    # a label before the expression, Maxima's assignment: once "Unexpected character ':'"
    ("a: x y", 1, "Give the expression alone, without ':' (nor what comes before it)."),
    ("f(x) := x y", 5, "without ':'"),
    # the answer in quotation marks, as an instruction quoted how to type it: once "Unexpected character"
    ('"x y"', 0, "Leave out the quotation marks: type the answer alone."),
    ("“x y”", 0, "Leave out the quotation marks"),
    ("'x y'", 0, "Leave out the quotation marks"),
    # a dash longer than the en dash read as a minus: once "Unexpected character"
    ("—x y", 0, "— is a dash, which is not read here: for a minus sign, type -."),
    ("x ― y", 2, "for a minus sign, type -"),
    # a degree sign after a sine's bracket, in a calculator's key order: not sin(30 rad)·π/180, as it read
    ("x sin(30)°", 9, "Did you mean sin(30°)? The ° after sin(30) would turn its value into degrees"),
    ("x cos(60) deg", 10, "Did you mean cos(60°)? The deg after cos(60)"),
    ("x tan(15+15)°", 12, "The ° after tan(15+15) would turn its value into degrees: put the ° inside"),
    # A power of ten marked by both ×10 and e: not 3.0×10^9, as it read
    ("3.0×10e8 x", 6, "Did you mean 3.0×10^8 or 3.0e8?"),
    ("2*10E-3 y", 4, "2×10^-3 or 2E-3"),
    # a calculator's exponent with its ^ left out, as numeric answers refuse it: was graded as 3.0·10 − 3·x
    ("3.0×10-3 x", 6, "Did you mean 3.0×10^-3? Write the power of ten with ^"),
    ("y (3.0 · 10 -3)", 12, "Did you mean 3.0×10^-3?"),
    ("x*2*10−12", 6, "Did you mean 2×10^-12?"),
    ("x y)", 3, "Unmatched"),
    # a mark over a letter, as a vector or a mean is written on paper: once "Unexpected character"
    ("x⃗ + y", 1, "A mark over x (an arrow, a bar, a hat, a dot) is not read: type the symbol as"),
    ("2 ȳ", 3, "A mark over y"),
]


@pytest.mark.parametrize(("text", "position", "words"), PARSE_ERRORS, ids=[repr(p[0]) for p in PARSE_ERRORS])
def test_parse_error_points_at_the_fault(text, position, words):
    with pytest.raises(ParseError) as caught:
        read(text, "x", "y")
    assert caught.value.position == position
    assert caught.value.reason == "parse_error"
    if words:
        assert words in caught.value.message


AMBIGUOUS_DIVISIONS = [
    # (text, position of the /, reading 1, reading 2)
    ("p^2/2m", 3, "(p^2/2)·m", "p^2/(2·m)"),
    ("v^2/2g", 3, "(v^2/2)·g", "v^2/(2·g)"),
    ("m v/q B", 3, "(m·v/q)·B", "m·v/(q·B)"),
    ("a/b c", 1, "(a/b)·c", "a/(b·c)"),
    ("a/b(a+b)", 1, "(a/b)·(a + b)", "a/(b·(a + b))"),
    ("1/2m", 1, "(1/2)·m", "1/(2·m)"),  # no space: reads like 2m, not a coefficient
    ("a*1/2 m", 3, "(a·1/2)·m", "a·1/(2·m)"),  # not at the start of the term
    ("0.5/2 m", 3, "(0.5/2)·m", "0.5/(2·m)"),  # not an integer fraction
    ("m + a/b c", 5, "(a/b)·c", "a/(b·c)"),
]


@pytest.mark.parametrize(
    ("text", "position", "first", "second"), AMBIGUOUS_DIVISIONS, ids=[a[0] for a in AMBIGUOUS_DIVISIONS]
)
def test_division_before_a_juxtaposed_product_is_refused_with_both_readings(text, position, first, second):
    with pytest.raises(AmbiguousInput) as caught:
        read(text, "p", "m", "v", "g", "q", "B", "a", "b", "c")
    error = caught.value
    assert error.position == position
    assert error.readings == (first, second)
    assert error.message == f"Did you mean {first} or {second}? Add parentheses."


AMBIGUOUS_ARGUMENTS = [
    # (text, position of the function or root, reading 1, reading 2): a bare argument with a `/` typed
    # on, once read as the first alone (the documented rule), where students mostly mean the second
    ("sin θ/2", 0, "sin(theta)/2", "sin(theta/2)"),
    ("2 sin θ/2 cos θ/2", 2, "sin(theta)/2", "sin(theta/2)"),
    ("sin^2 θ/2", 0, "sin(theta)^2/2", "sin(theta/2)^2"),
    ("cos ωt/2", 0, "cos(omega·t)/2", "cos(omega·t/2)"),
    ("2π√m/k", 2, "sqrt(m)/k", "sqrt(m/k)"),
    ("√a/b c", 0, "sqrt(a)/b", "sqrt(a/b)"),  # the space ends the word, as ever
    ("sqrt a/b", 0, "sqrt(a)/b", "sqrt(a/b)"),
    ("∛a/b", 0, "a^(1/3)/b", "(a/b)^(1/3)"),
    ("ln a/2", 0, "log(a)/2", "log(a/2)"),
    ("√3/2", 0, "sqrt(3)/2", "sqrt(3/2)"),
    # a root's bare argument with a bracket typed on: the root's bar often reaches over it
    ("√2a(1 - b)", 0, "sqrt(2·a)·(1 - b)", "sqrt(2·a·(1 - b))"),
    ("sqrt 2a(1 - b)", 0, "sqrt(2·a)·(1 - b)", "sqrt(2·a·(1 - b))"),
    ("√2a/(1 + b)", 0, "sqrt(2·a)/(1 + b)", "sqrt(2·a/(1 + b))"),  # a function's is divided (below)
    # or a function typed on: `√gRtanθ` was graded as √(gR)·tan θ
    ("√2bcosθ", 0, "sqrt(2·b)·cos(theta)", "sqrt(2·b·cos(theta))"),
    ("sqrt bttanθ", 0, "sqrt(b·t)·tan(theta)", "sqrt(b·t·tan(theta))"),
]


@pytest.mark.parametrize(
    ("text", "position", "first", "second"), AMBIGUOUS_ARGUMENTS, ids=[a[0] for a in AMBIGUOUS_ARGUMENTS]
)
def test_division_typed_on_to_a_bare_argument_is_refused_with_both_readings(text, position, first, second):
    with pytest.raises(AmbiguousInput) as caught:
        read(text, "theta", "omega", "t", "m", "k", "a", "b", "c")
    error = caught.value
    assert error.position == position
    assert error.readings == (first, second)
    assert error.message == f"Did you mean {first} or {second}? Add parentheses."


NUMBER_SPACED_FROM_ITS_WORD = [
    # (text, position of the word, reading 1, reading 2): once sin(2)·θ, an angle of 2 rad times θ
    ("sin 2 θ", 6, "sin(2θ)", "sin(2)·θ"),
    ("m g sin 2 θ", 10, "sin(2θ)", "sin(2)·θ"),
    ("cos 2 ωt", 6, "cos(2ωt)", "cos(2)·ωt"),
    ("sin ½ θ", 6, "sin(½θ)", "sin(½)·θ"),
    ("sin 2 θ^2", 6, "sin(2θ)", "sin(2)·θ"),
]


@pytest.mark.parametrize(
    ("text", "position", "first", "second"),
    NUMBER_SPACED_FROM_ITS_WORD,
    ids=[a[0] for a in NUMBER_SPACED_FROM_ITS_WORD],
)
def test_a_number_spaced_from_the_word_after_it_is_asked_about(text, position, first, second):
    with pytest.raises(AmbiguousInput) as caught:
        read(text, "theta", "omega", "t", "m", "g")
    assert caught.value.position == position
    assert caught.value.readings == (first, second)
    assert caught.value.message.startswith(f"Did you mean {first} or {second}?")


NUMBER_ARGUMENT_KEPT = [
    # (text, reading): a degree sign says the number is the angle; a root's or a log's number is a factor
    ("sin 30° m", "sin(30*pi/180)*m"),
    ("√2 g", "sqrt(2)*g"),
    ("ln 2 t", "log(2)*t"),
    ("sin 2θ", "sin(2*theta)"),
]


@pytest.mark.parametrize(("text", "reading"), NUMBER_ARGUMENT_KEPT, ids=[a[0] for a in NUMBER_ARGUMENT_KEPT])
def test_a_number_argument_that_says_where_it_ends_is_read(text, reading):
    assert read(text, "theta", "m", "g", "t").read_as.text == reading


NOT_AMBIGUOUS_ARGUMENTS = [
    # (text, reading): brackets or a space say where the argument ends; √(2/2) would be 1
    ("sin(θ)/2", "sin(theta)/2"),
    ("sin θ /2", "sin(theta)/2"),
    ("sin θ / 2", "sin(theta)/2"),
    ("sin(θ/2)", "sin(theta/2)"),
    ("√(m/k)/2", "sqrt(m/k)/2"),
    ("√m/√k", "sqrt(m)/sqrt(k)"),
    ("sin θ/cos θ", "sin(theta)/cos(theta)"),
    ("√2/2", "sqrt(2)/2"),
    ("√3/3", "sqrt(3)/3"),
    ("√2(m + k)", "sqrt(2)*(m + k)"),  # a number's root before a bracket, as printed
    ("√(2m)(1 + k)", "sqrt(2*m)*(1 + k)"),
    ("√2m (1 + k)", "sqrt(2*m)*(1 + k)"),
    ("sin θ(1 + k)", "sin(theta)*(1 + k)"),  # a function's: the bracket is no part of its argument
    ("sin θ/(1 + k)", "sin(theta)/(1 + k)"),  # as physics writes g sin θ/(1 + I/(m r²))
    ("√2/(1 + k)", "sqrt(2)/(1 + k)"),
    ("√3cosθ", "sqrt(3)*cos(theta)"),  # a number's root before a function, as printed
    ("√m cosθ", "sqrt(m)*cos(theta)"),
    ("sinθcosθ", "sin(theta)*cos(theta)"),  # a function's argument ends at the next function
]


@pytest.mark.parametrize(
    ("text", "reading"), NOT_AMBIGUOUS_ARGUMENTS, ids=[a[0] for a in NOT_AMBIGUOUS_ARGUMENTS]
)
def test_a_bare_argument_whose_end_is_shown_is_read(text, reading):
    assert read(text, "theta", "m", "k").read_as.text == reading


NOT_AMBIGUOUS = ["a/b*c", "a/(b c)", "a b/c", "(a/b) c", "a/b + c", "a/b/c", "1/2 a b", "a/b^2*c"]


@pytest.mark.parametrize("text", NOT_AMBIGUOUS)
def test_division_without_a_juxtaposed_product_after_it_is_read(text):
    read(text, "a", "b", "c")


@pytest.mark.timeout(10)
@pytest.mark.parametrize(
    "text",
    [
        "sqrt(-1)",
        "log(-1)",
        "acos(2)",
        "sqrtacos(2)²",
        "√acos(2)²pi",
        "acos(2)²^(1/2)πtan(pi/2)",
        "0^(sqrt(-1)!)",
    ],
)
def test_a_constant_with_no_real_value_is_refused_at_once(text):
    # sympy simplifying powers of such constants ran for minutes; nothing physical is imaginary anyway.
    with pytest.raises(ParseError) as raised:
        parse_math(text, {})
    assert "no real value" in raised.value.message
