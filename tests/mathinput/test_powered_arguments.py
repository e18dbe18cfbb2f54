"""A bare function argument with a power (`sin θ^2`) reads as sin(θ²), by the usual convention, and
`read_as.note` says so with how to write (sin θ)²; written any other way, there is no note."""

from __future__ import annotations

import pytest
import sympy

from physics.mathinput import parse_math
from tests.mathinput.support import names, read, sym

SYMBOLS = ("theta", "x", "n", "t", "omega", "m", "M")

NOTED = [
    # (answer, the note)
    ("sin θ^2", "sin θ^2 is read as sin(θ²); for (sin θ)² write sin^2 θ or (sin θ)^2"),
    ("cos x^2", "cos x^2 is read as cos(x²); for (cos x)² write cos^2 x or (cos x)^2"),
    ("sin 2θ^2", "sin 2θ^2 is read as sin(2θ²); for (sin 2θ)² write sin^2 2θ or (sin 2θ)^2"),
    ("sin θ²", "sin θ² is read as sin(θ²); for (sin θ)² write sin^2 θ or (sin θ)^2"),
    (
        "sin theta**2",
        "sin theta**2 is read as sin(theta²); for (sin theta)² write sin^2 theta or (sin theta)^2",
    ),
    ("m sinθ^3", "sinθ^3 is read as sin(θ³); for (sin θ)³ write sin^3 θ or (sin θ)^3"),
    ("ln x^2", "ln x^2 is read as ln(x²); for (ln x)² write ln^2 x or (ln x)^2"),
    ("sin cos x^2", "cos x^2 is read as cos(x²); for (cos x)² write cos^2 x or (cos x)^2"),
    # not a whole power: `sin^-1 x` would be arcsin, so only the bracketed form is offered
    ("sin x^-1", "sin x^-1 is read as sin(x^-1); for (sin x)^-1 write (sin x)^-1"),
    ("sin x^(n+1)", "sin x^(n+1) is read as sin(x^(n+1)); for (sin x)^(n+1) write (sin x)^(n+1)"),
    (
        "\\sin\\theta^{2}",
        "\\sin\\theta^{2} is read as \\sin(\\theta²); for (\\sin \\theta)² write \\sin^2 \\theta or (\\sin \\theta)^2",
    ),
    (
        "sin θ^2 + cos x^2 + sin θ^2",
        "sin θ^2 is read as sin(θ²); for (sin θ)² write sin^2 θ or (sin θ)^2. "
        "cos x^2 is read as cos(x²); for (cos x)² write cos^2 x or (cos x)^2",
    ),
]


@pytest.mark.parametrize(("answer", "note"), NOTED, ids=[c[0] for c in NOTED])
def test_a_bare_argument_with_a_power_is_read_inside_and_says_so(answer: str, note: str) -> None:
    assert read(answer, *SYMBOLS).read_as.note == note


NOT_NOTED = [
    "sin(θ)^2",  # bracketed: the power is the function's
    "sin^2 θ",
    "sin²θ",
    "sin(θ^2)",  # bracketed: the power is the argument's
    "sin θ",
    "sin^2 θ^2",  # the function's power is written: the reader chose where each goes
    "sin^-1 x^2",
    "√x^2",  # the radical sign covers what follows
    "sin 2^2θ",  # the power is inside the argument, not at its end
    "sin(2) θ^2",  # sin(2)·θ²: the power is outside the argument (`sin 2 θ^2` is asked: test_errors.py)
    "cos omega t^2",
    "sin|x|^2",
    "x^2",
]


@pytest.mark.parametrize("answer", NOT_NOTED)
def test_no_note_where_the_power_is_not_on_a_bare_argument(answer: str) -> None:
    assert read(answer, *SYMBOLS).read_as.note is None


theta, x, omega, t = sym("theta"), sym("x"), sym("omega"), sym("t")
READINGS = [
    # (answer, as read, the other reading)
    ("sin θ^2", sympy.sin(theta**2), sympy.sin(theta) ** 2),
    ("sin 2θ^2", sympy.sin(2 * theta**2), sympy.sin(2 * theta) ** 2),
    ("sin θ²/2", sympy.sin(theta**2) / 2, sympy.sin(theta) ** 2 / 2),
    ("x sin cos x^2", x * sympy.sin(sympy.cos(x**2)), x * sympy.sin(sympy.cos(x) ** 2)),
    ("sin ωt^2", sympy.sin(omega * t**2), sympy.sin(omega * t) ** 2),
    ("sin(θ)^2", sympy.sin(theta) ** 2, sympy.sin(theta) ** 2),  # no other reading
    ("sin(θ^2)", sympy.sin(theta**2), sympy.sin(theta**2)),
]


@pytest.mark.parametrize(("answer", "taken", "other"), READINGS, ids=[c[0] for c in READINGS])
def test_the_other_reading_puts_the_power_on_the_function(
    answer: str, taken: sympy.Expr, other: sympy.Expr
) -> None:
    declared = names(*SYMBOLS)
    assert parse_math(answer, declared).expr == taken
    assert parse_math(answer, declared, powers_outside=True).expr == other
