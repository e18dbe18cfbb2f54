"""Symbols and contexts shared by the symbolic tests (built with constructors, never from text)."""

from __future__ import annotations

import sympy

from physics.dimensions import DIMENSIONLESS, Dimension
from physics.symbolic import (
    KnownMistake,
    LimitCase,
    SymbolicContext,
    SymbolSpec,
    judge_symbolic,
    make_symbol,
    prepare_reference,
)
from physics.verdict import Judgement

KG = Dimension({"mass": 1})
METRE = Dimension({"length": 1})
SECOND = Dimension({"time": 1})
SPEED = Dimension({"length": 1, "time": -1})
ACCELERATION = Dimension({"length": 1, "time": -2})
FORCE = Dimension({"mass": 1, "length": 1, "time": -2})
ENERGY = Dimension({"mass": 1, "length": 2, "time": -2})

SPECS = {
    "m": SymbolSpec("m", KG),
    "M": SymbolSpec("M", KG),
    "g": SymbolSpec("g", ACCELERATION),
    "v": SymbolSpec("v", SPEED),
    "L": SymbolSpec("L", METRE),
    "t": SymbolSpec("t", SECOND),
    "mu": SymbolSpec("mu", DIMENSIONLESS),
    "a": SymbolSpec("a"),
    "b": SymbolSpec("b"),
    "x": SymbolSpec("x", real=True),
    "y": SymbolSpec("y", real=True, nonzero=True),
    "n": SymbolSpec("n", integer=True),
    "U0": SymbolSpec("U0", ENERGY),
    "r0": SymbolSpec("r0", METRE),
    "r": SymbolSpec("r", METRE),
}
ACUTE = SymbolSpec("theta", DIMENSIONLESS, low=sympy.Integer(0), high=sympy.pi / 2)
UP_TO_PI = SymbolSpec("theta", DIMENSIONLESS, low=sympy.Integer(0), high=sympy.pi)

S = {name: make_symbol(spec) for name, spec in SPECS.items()}
m, M, g, v, L, t, mu = (S[k] for k in ("m", "M", "g", "v", "L", "t", "mu"))
a, b, x, y, n = (S[k] for k in ("a", "b", "x", "y", "n"))
U0, r0, r = S["U0"], S["r0"], S["r"]
theta = make_symbol(ACUTE)
assert theta == make_symbol(UP_TO_PI)  # both ranges give a positive theta: one sympy symbol
sin, cos, tan, sqrt, log, pi = sympy.sin, sympy.cos, sympy.tan, sympy.sqrt, sympy.log, sympy.pi


def context(
    expr: sympy.Basic,
    *more: sympy.Basic,
    angle: SymbolSpec = ACUTE,
    constraints: tuple[sympy.Basic, ...] = (),
    mistakes: tuple[KnownMistake, ...] = (),
    limits: tuple[LimitCase, ...] = (),
) -> SymbolicContext:
    """A context declaring every symbol the given expressions use (theta with the given range)."""
    names = {s.name for e in (expr, *more) for s in e.free_symbols}
    specs = {name: (angle if name == "theta" else SPECS[name]) for name in names}
    return SymbolicContext(
        {make_symbol(spec): spec for spec in specs.values()},
        constraints=constraints,
        mistakes=mistakes,
        limits=limits,
    )


def judge(answer: sympy.Expr, expected: sympy.Expr, ctx: SymbolicContext | None = None) -> Judgement:
    return judge_symbolic(answer, prepare_reference(expected, ctx or context(answer, expected)))
