"""Mistakes and limits generated from the models: the slips the brief names, with feedback that does
not give the answer away, and limits in which the answer stays finite."""

from __future__ import annotations

import pytest
import sympy
from sympy import cos, sin, sqrt

from tests.engine.conftest import SLOW_PROBLEMS, bank_derivation, s


def _mistakes() -> list[tuple[str, str, sympy.Expr, str]]:
    m, big, th, g = (s("moving-wedge", n) for n in ("m", "M", "theta", "g"))
    u0, r0, mass = (s("lennard-jones", n) for n in ("U0", "r0", "m"))
    bm, bbig, length, bth, bg = (s("ballistic-pendulum", n) for n in ("m", "M", "L", "theta", "g"))
    al, mu, sg = (s("skier-friction", n) for n in ("alpha", "mu", "g"))
    rth, rg = s("rolling-incline", "theta"), s("rolling-incline", "g")
    yg = s("yo-yo", "g")
    return [
        ("moving-wedge", "block_relative_acceleration", g * sin(th), "fixed"),
        ("moving-wedge", "normal_force", m * g * cos(th), "fixed"),
        ("moving-wedge", "wedge_acceleration", -m * g * sin(th) * cos(th) / big, "fixed"),
        (
            "moving-wedge",
            "normal_force",
            big * m * g * sin(th) / (big + m * cos(th) ** 2),
            "sine and a cosine",
        ),
        ("lennard-jones", "oscillation_frequency", sqrt(72 * u0 / r0**2 / mass), "reduced mass"),
        (
            "ballistic-pendulum",
            "bullet_speed",
            sqrt(2 * bg * length * (1 - cos(bth)) * (bm + bbig) / bm),
            "not conserved",
        ),
        ("ballistic-pendulum", "energy_fraction_lost", bm / (bm + bbig), "remains"),
        ("skier-friction", "acceleration", sg * (sin(al) + mu * cos(al)), "opposes"),
        ("rolling-incline", "acceleration_cylinder", rg * sin(rth), "moment of inertia"),
        ("yo-yo", "acceleration", yg, "moment of inertia"),
    ]


@pytest.mark.parametrize(
    ("problem", "quantity", "expr", "hint"),
    [
        pytest.param(
            *row,
            id=f"{row[0]}:{row[1]}:{row[3]}",
            marks=[pytest.mark.slow] if row[0] in SLOW_PROBLEMS else [],
        )
        for row in _mistakes()
    ],
)
def test_the_slip_is_generated_with_targeted_feedback(
    problem: str, quantity: str, expr: sympy.Expr, hint: str
) -> None:
    derivation = bank_derivation(problem)
    matches = [k for k in derivation.mistakes[quantity] if sympy.simplify(k.expr - expr) == 0]
    assert matches, [k.expr for k in derivation.mistakes[quantity]]
    assert hint in matches[0].feedback
    assert str(derivation.quantities[quantity]) not in matches[0].feedback


@pytest.mark.slow
def test_no_mistake_equals_the_answer() -> None:
    for problem in ("moving-wedge", "rolling-incline", "lennard-jones", "ballistic-pendulum"):
        derivation = bank_derivation(problem)
        for name, mistakes in derivation.mistakes.items():
            for mistake in mistakes:
                assert sympy.simplify(mistake.expr - derivation.quantities[name]) != 0, (problem, name)


@pytest.mark.parametrize(
    ("problem", "quantity", "symbol", "value", "word"),
    [
        pytest.param(
            "moving-wedge",
            "block_relative_acceleration",
            "M",
            sympy.oo,
            "fixed",
            marks=pytest.mark.slow,
            id="heavy-wedge",
        ),
        pytest.param(
            "moving-wedge", "wedge_acceleration", "theta", 0, "theta", marks=pytest.mark.slow, id="flat-wedge"
        ),
        pytest.param(
            "moving-wedge", "wedge_acceleration", "m", 0, "lighter", marks=pytest.mark.slow, id="light-block"
        ),
        pytest.param("yo-yo", "acceleration", "k", 0, "rotational inertia", id="yo-yo-without-inertia"),
        pytest.param(
            "skier-friction",
            "acceleration",
            "mu",
            0,
            "friction",
            marks=pytest.mark.slow,
            id="frictionless-slope",
        ),
        pytest.param("atwood", "acceleration", "m1", 0, "lighter", id="light-counterweight"),
    ],
)
def test_physical_limit_is_listed(
    problem: str, quantity: str, symbol: str, value: sympy.Expr, word: str
) -> None:
    limits = bank_derivation(problem).limits[quantity]
    target = s(problem, symbol)
    found = [c for c in limits if c.substitutions.get(target) == value]
    assert found and word in found[0].description


def test_limits_are_finite() -> None:
    derivation = bank_derivation("atwood")
    for name, cases in derivation.limits.items():
        for case in cases:
            ((symbol, value),) = case.substitutions.items()
            assert sympy.limit(derivation.quantities[name], symbol, value).is_finite
