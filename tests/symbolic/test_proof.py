"""The bounded symbolic step: proves some identities, never claims one it cannot show."""

from __future__ import annotations

import pytest
import sympy

from physics.symbolic import proves_equal
from tests.symbolic.support import a, b, cos, judge, sin, theta

IMAGINARY = sympy.I

PROVABLE = [
    ("identical", a * b, b * a),
    ("pythagorean", sin(theta) ** 2 + cos(theta) ** 2, sympy.Integer(1)),
    ("rational-function", (a**2 - b**2) / (a - b), a + b),
    ("euler-cosine", sympy.exp(IMAGINARY * theta) + sympy.exp(-IMAGINARY * theta), 2 * cos(theta)),
]


@pytest.mark.parametrize(("left", "right"), [p[1:] for p in PROVABLE], ids=[p[0] for p in PROVABLE])
def test_bounded_rewriting_proves_these(left, right):
    assert proves_equal(left, right)


NOT_PROVABLE = [
    ("different", a + b, a * b),
    ("range-dependent-identity", sympy.sqrt(1 - sin(theta) ** 2), cos(theta)),
    ("huge-power", (a + b) ** 40 - a, (a + b) ** 40),
]


@pytest.mark.parametrize(("left", "right"), [p[1:] for p in NOT_PROVABLE], ids=[p[0] for p in NOT_PROVABLE])
def test_no_proof_is_claimed_for_these(left, right):
    assert not proves_equal(left, right)


def test_an_answer_with_complex_intermediates_is_accepted():
    # Not real term by term: the real evaluator has no value, sympy's complex evaluation decides.
    assert judge(sympy.exp(IMAGINARY * theta) + sympy.exp(-IMAGINARY * theta), 2 * cos(theta)).correct
