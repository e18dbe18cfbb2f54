"""Symbols get the strongest assumptions their spec makes sound."""

from __future__ import annotations

import pytest
import sympy

from physics.errors import SpecError
from physics.symbolic import SymbolSpec, make_symbol

pi = sympy.pi
zero, one = sympy.Integer(0), sympy.Integer(1)

CASES = [
    ("default-is-positive", SymbolSpec("m"), {"positive": True}),
    ("real-any-sign", SymbolSpec("x", real=True), {"real": True, "positive": None}),
    (
        "real-nonzero",
        SymbolSpec("x", real=True, nonzero=True),
        {"real": True, "nonzero": True, "positive": None},
    ),
    ("negative", SymbolSpec("q", negative=True), {"negative": True}),
    ("positive-integer", SymbolSpec("n", integer=True), {"integer": True, "positive": True}),
    ("real-integer", SymbolSpec("k", integer=True, real=True), {"integer": True, "positive": None}),
    ("acute-range-is-positive", SymbolSpec("theta", low=zero, high=pi / 2), {"positive": True}),
    ("range-from-one", SymbolSpec("x", low=one, high=sympy.oo), {"positive": True}),
    ("range-across-zero-is-real", SymbolSpec("x", low=-one, high=one), {"real": True, "positive": None}),
    ("range-below-zero-is-negative", SymbolSpec("x", low=-pi, high=zero), {"negative": True}),
    (
        "range-overrides-default",
        SymbolSpec("phi", low=-pi / 2, high=pi / 2),
        {"real": True, "positive": None},
    ),
]


@pytest.mark.parametrize(("spec", "facts"), [c[1:] for c in CASES], ids=[c[0] for c in CASES])
def test_spec_gives_the_sound_assumptions(spec, facts):
    symbol = make_symbol(spec)
    assert symbol.name == spec.name
    for fact, value in facts.items():
        assert getattr(symbol, f"is_{fact}") is value, fact


def test_a_symbolic_range_bound_is_a_spec_error():
    with pytest.raises(SpecError) as raised:
        make_symbol(SymbolSpec("x", low=sympy.Symbol("a"), high=one))
    assert raised.value.path == ("symbols", "x", "range", 0)
