"""Every bank model: each quantity derived by at least two methods that agree, the simulation agrees,
and the result equals what physics says (typed here, in the test, never in the engine or the model)."""

from __future__ import annotations

import pytest
import sympy
from sympy import cos, pi, sin, sqrt, tan

from tests.engine.conftest import SLOW_PROBLEMS, SYMBOLS, bank_derivation, s, symbols
from tests.sampling import sampled


def _known() -> list[tuple[str, str, sympy.Expr, frozenset[str]]]:
    """(problem, quantity, known result, methods that must take part)."""
    m, M, th, g = (s("moving-wedge", n) for n in ("m", "M", "theta", "g"))
    three = frozenset({"lagrange", "newton", "conservation"})
    two = frozenset({"lagrange", "newton"})
    # the seed document's wedge: also in the wedge's frame (fictitious force) and by d'Alembert's principle
    five = three | {"frames", "dalembert"}
    rows = [
        ("moving-wedge", "wedge_acceleration", -m * g * sin(th) * cos(th) / (M + m * sin(th) ** 2), five),
        (
            "moving-wedge",
            "block_relative_acceleration",
            (M + m) * g * sin(th) / (M + m * sin(th) ** 2),
            five,
        ),
        ("moving-wedge", "normal_force", M * m * g * cos(th) / (M + m * sin(th) ** 2), two | {"frames"}),
    ]
    m, r, k, g = (s("yo-yo", n) for n in ("m", "r", "k", "g"))
    rows += [
        ("yo-yo", "acceleration", g * r**2 / (r**2 + k**2), three),
        ("yo-yo", "tension", m * g * k**2 / (r**2 + k**2), two),
    ]
    u0, r0, r, m = (s("lennard-jones", n) for n in ("U0", "r0", "r", "m"))
    u = u0 * ((r0 / r) ** 12 - 2 * (r0 / r) ** 6)
    rows += [
        ("lennard-jones", "equilibrium_separation", r0, three),
        ("lennard-jones", "force", -sympy.diff(u, r), three),
        ("lennard-jones", "spring_constant", 72 * u0 / r0**2, three),
        ("lennard-jones", "oscillation_frequency", 12 * sqrt(u0 / m) / r0, three),
    ]
    m, big, length, th, g = (s("ballistic-pendulum", n) for n in ("m", "M", "L", "theta", "g"))
    collision = frozenset({"newton", "conservation"})
    rows += [
        (
            "ballistic-pendulum",
            "bullet_speed",
            (m + big) / m * sqrt(2 * g * length * (1 - cos(th))),
            collision,
        ),
        ("ballistic-pendulum", "energy_fraction_lost", big / (m + big), collision),
    ]
    al, mu, g = (s("skier-friction", n) for n in ("alpha", "mu", "g"))
    rows += [
        ("skier-friction", "friction_coefficient", tan(al), two),
        ("skier-friction", "acceleration", g * (sin(al) - mu * cos(al)), two),
    ]
    m1, m2, th, g = (s("incline-pulley", n) for n in ("m1", "m2", "theta", "g"))
    rows += [
        ("incline-pulley", "acceleration", (m2 - m1 * sin(th)) * g / (m1 + m2), three),
        ("incline-pulley", "tension", m1 * m2 * g * (1 + sin(th)) / (m1 + m2), two),
    ]
    m, _, th, g = (s("rolling-incline", n) for n in ("m", "R", "theta", "g"))
    rows += [
        ("rolling-incline", "acceleration_cylinder", sympy.Rational(2, 3) * g * sin(th), three),
        ("rolling-incline", "acceleration_hoop", g * sin(th) / 2, three),
        ("rolling-incline", "acceleration_sphere", sympy.Rational(5, 7) * g * sin(th), three),
        ("rolling-incline", "acceleration_sliding", g * sin(th), three),
        ("rolling-incline", "friction_cylinder", m * g * sin(th) / 3, two),
    ]
    m, k = (s("mass-spring", n) for n in ("m", "k"))
    rows += [
        ("mass-spring", "angular_frequency", sqrt(k / m), three),
        ("mass-spring", "period", 2 * pi * sqrt(m / k), three),
    ]
    m1, m2, g = (s("atwood", n) for n in ("m1", "m2", "g"))
    rows += [
        ("atwood", "acceleration", (m2 - m1) * g / (m1 + m2), three),
        ("atwood", "tension", 2 * m1 * m2 * g / (m1 + m2), two),
    ]
    # A ball launched without spin: friction slows it (mu g) and spins it up (5 mu g / 2R) until
    # v = omega R; energy is not conserved, so Lagrange and Newton only.
    v0, mu, g = (s("bowling-ball-skid", n) for n in ("v0", "mu", "g"))
    rows += [
        ("bowling-ball-skid", "skid_time", 2 * v0 / (7 * mu * g), two),
        ("bowling-ball-skid", "skid_distance", 12 * v0**2 / (49 * mu * g), two),
        ("bowling-ball-skid", "rolling_speed", sympy.Rational(5, 7) * v0, two),
    ]
    # Released level with the centre of a frictionless quarter circle: v^2 = 2gR at the bottom, where
    # N - mg = m v^2/R.
    m, radius, g = (s("quarter-circle-slide", n) for n in ("m", "R", "g"))
    rows += [
        ("quarter-circle-slide", "speed_at_bottom", sqrt(2 * g * radius), three),
        ("quarter-circle-slide", "normal_force_at_bottom", 3 * m * g, two),
    ]
    return rows


KNOWN = _known()
# Half the rows each run (the three checks below share a problem's derivation, so they share the draw).
CASES = sampled(
    [
        pytest.param(p, q, e, methods, id=f"{p}:{q}", marks=[pytest.mark.slow] if p in SLOW_PROBLEMS else [])
        for p, q, e, methods in KNOWN
    ],
    7,
    "bank-derivations",
)


@pytest.mark.parametrize(("problem", "quantity", "expected", "methods"), CASES)
def test_derived_quantity_equals_the_known_result(
    problem: str, quantity: str, expected: sympy.Expr, methods: frozenset[str]
) -> None:
    derivation = bank_derivation(problem)
    assert sympy.simplify(derivation.quantities[quantity] - expected) == 0
    table = set(symbols(problem).values())
    assert derivation.quantities[quantity].free_symbols <= table  # the table's own Symbol objects


@pytest.mark.parametrize(("problem", "quantity", "expected", "methods"), CASES)
def test_each_quantity_is_agreed_by_the_expected_methods(
    problem: str, quantity: str, expected: sympy.Expr, methods: frozenset[str]
) -> None:
    derivation = bank_derivation(problem)
    assert methods <= set(derivation.agreement[quantity])  # a method that joins later may agree too
    assert len(derivation.agreement[quantity]) >= 2
    for report in derivation.methods:
        if report.name in methods:
            assert sympy.simplify(report.results[quantity] - expected) == 0, report.name


@pytest.mark.parametrize(("problem", "quantity", "expected", "methods"), CASES)
def test_simulation_agrees_with_each_quantity(
    problem: str, quantity: str, expected: sympy.Expr, methods: frozenset[str]
) -> None:
    check = bank_derivation(problem).simulation[quantity]
    assert check.points >= 3
    assert 0 <= check.max_relative_error < 1e-3
    assert check.compared


def test_every_bank_problem_is_covered() -> None:
    assert {p for p, *_ in KNOWN} == set(SYMBOLS)
