"""The engine's linear solve (exact elimination over the field of fractions) and its remembered simplify."""

from __future__ import annotations

import random
import struct

import pytest
import sympy
from sympy import cos, sin

from physics.engine import tidy
from physics.engine.mechanics import solve_linear
from physics.engine.simulation import eliminated, solve_numeric
from physics.errors import DerivationError

m, g, L, th = sympy.symbols("m g L theta", positive=True)
a, b, lam = sympy.symbols("a b lam", real=True)


def _ladder() -> tuple[list[sympy.Expr], list[sympy.Symbol]]:
    """A ladder's statics in the shape Newton's method builds: one unknown per row, sines and cosines."""
    wall, floor, foot = sympy.symbols("wall floor foot", real=True)
    equations = [
        foot - wall,
        floor - m * g,
        L * cos(th) / 2 * floor - L * sin(th) / 2 * (wall + foot),
    ]
    return equations, [wall, floor, foot]


@pytest.mark.parametrize(
    ("equations", "unknowns"),
    [
        _ladder(),
        ([m * a + lam * sin(th) - m * g, a * sin(th) - b, b - a * sin(th) ** 2 - lam], [a, b, lam]),
        ([sympy.Float(0.5) * a + b - g, a - b * m], [a, b]),  # floats: LUsolve, not exact fractions
    ],
    ids=["trigonometric", "coupled", "floats"],
)
def test_solution_satisfies_the_equations_and_matches_lusolve(
    equations: list[sympy.Expr], unknowns: list[sympy.Symbol]
) -> None:
    solution = solve_linear(equations, unknowns, "test")
    for equation in equations:
        assert sympy.simplify(equation.subs(solution)) == 0
    matrix, rhs = sympy.linear_eq_to_matrix(equations, unknowns)
    for unknown, value in zip(unknowns, matrix.LUsolve(rhs), strict=True):
        assert sympy.simplify(solution[unknown] - value) == 0


def test_ladder_forces_come_out_as_one_simple_fraction() -> None:
    equations, unknowns = _ladder()
    solution = solve_linear(equations, unknowns, "ladder", tidy=lambda e: e)  # exact elimination alone
    assert sympy.cancel(solution[unknowns[0]] - g * m * cos(th) / (2 * sin(th))) == 0
    assert sympy.count_ops(solution[unknowns[0]]) <= 8


def test_singular_system_is_a_derivation_error() -> None:
    with pytest.raises(DerivationError, match="do not determine"):
        solve_linear([a + b - g, 2 * a + 2 * b - 2 * g], [a, b], "singular")


def test_simplify_is_remembered_until_forgotten() -> None:
    tidy.forget()
    expr = sin(th) ** 2 + cos(th) ** 2 + m
    first = tidy.simplify(expr)
    assert first == m + 1
    assert tidy.simplify(expr) is first
    tidy.forget()
    assert tidy._remembered == {}
    assert tidy.simplify(sympy.Matrix([[expr]])) == sympy.Matrix([[m + 1]])  # a mutable matrix passes through


def test_trigsimp_rewrites_each_subexpression_once_per_derivation_with_sympys_result() -> None:
    tidy.forget()
    shared = sin(th) ** 2 + cos(th) ** 2
    first = sympy.trigsimp(m * shared / (m + shared))
    assert first == m / (m + 1)
    assert shared in tidy._rewritten
    unremembered = tidy._trigsimp_module._futrig.__wrapped__
    for expr, rewritten in tidy._rewritten.items():
        assert unremembered(expr) == rewritten
    assert tidy._factored
    for expr, factored in tidy._factored.items():
        assert sympy.factor(expr) == factored
    tidy.forget()
    assert tidy._rewritten == tidy._factored == {}


def test_solve_is_remembered_until_forgotten_and_hands_out_its_own_list() -> None:
    tidy.forget()
    first = tidy.solve(m * a**2 - g, a)
    assert sorted(first, key=str) == sorted(sympy.solve(m * a**2 - g, a), key=str)
    first.clear()
    assert len(tidy.solve(m * a**2 - g, a)) == 2  # the caller's list is its own
    tidy.forget()
    assert tidy._solved == {}


def _bits(solve, matrix: list[list[float]], rhs: list[float]) -> list[bytes] | str:
    try:
        return [struct.pack("d", v) for v in solve([list(row) for row in matrix], list(rhs))]
    except DerivationError as error:
        return error.message


@pytest.mark.parametrize("unknowns", [1, 2])
def test_one_or_two_unknowns_are_solved_numerically_to_the_last_bit_as_by_the_general_elimination(
    unknowns: int,
) -> None:
    rng = random.Random(unknowns)
    special = [0.0, -0.0, 1.0, -2.0, 1e-301, float("inf"), float("nan")]  # zeros' signs, a singular pivot

    def entry() -> float:
        return rng.uniform(-3, 3) if rng.random() < 0.6 else rng.choice(special)

    for _ in range(3000):
        matrix = [[entry() for _ in range(unknowns)] for _ in range(unknowns)]
        rhs = [entry() for _ in range(unknowns)]
        assert _bits(solve_numeric, matrix, rhs) == _bits(eliminated, matrix, rhs)
