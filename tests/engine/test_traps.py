"""Known traps and the seed's numbers: multiplier signs, the seed's tan form, the textbook values."""

from __future__ import annotations

import math

import pytest
import sympy
from sympy.physics.mechanics import LagrangesMethod, dynamicsymbols

from physics.engine.proof import prove_equal
from tests.engine.conftest import bank_derivation, bank_model, s


def test_string_tension_is_positive_whatever_sign_sympy_gives_its_multiplier() -> None:
    """sympy's solve_multipliers() and rhs() give the multiplier opposite signs; ours is the tension."""
    m1, m2, g = (s("atwood", n) for n in ("m1", "m2", "g"))
    y1, y2 = dynamicsymbols("y1 y2")
    lagrangian = (m1 * y1.diff() ** 2 + m2 * y2.diff() ** 2) / 2 - m1 * g * y1 - m2 * g * y2
    method = LagrangesMethod(lagrangian, [y1, y2], hol_coneqs=[y1 + y2])
    method.form_lagranges_equations()
    from_solve = next(iter(method.solve_multipliers().values()))
    from_rhs = method.rhs()[-1]
    tension = bank_derivation("atwood").quantities["tension"]
    assert sympy.simplify(from_solve + from_rhs) == 0  # the trap itself
    assert sympy.simplify(tension - from_rhs) == 0
    assert tension.subs({m1: 1, m2: 2, g: 10}) > 0


@pytest.mark.slow
def test_wedge_acceleration_equals_the_seeds_tan_form_on_the_angle_range() -> None:
    m, big, th, g = (s("moving-wedge", n) for n in ("m", "M", "theta", "g"))
    seed = -m * g * sympy.tan(th) / (big * (1 + sympy.tan(th) ** 2) + m * sympy.tan(th) ** 2)
    derived = bank_derivation("moving-wedge").quantities["wedge_acceleration"]
    how = prove_equal(derived, seed, bank_model("moving-wedge"), "wedge_acceleration", ("engine", "seed"))
    assert how == "symbolic" or how.startswith("sampled")


@pytest.mark.slow
@pytest.mark.parametrize(
    ("quantity", "values", "expected", "places"),
    [
        pytest.param("friction_coefficient", {"alpha": math.radians(3.5)}, 0.061, 3, id="coasting-skier-mu"),
        pytest.param(
            "acceleration",
            {"alpha": math.radians(35), "mu": 0.13, "g": 9.81, "m": 2300},
            4.58,
            2,
            id="block-on-35-degree-hill",
        ),
    ],
)
def test_seed_numbers(quantity: str, values: dict[str, float], expected: float, places: int) -> None:
    expr = bank_derivation("skier-friction").quantities[quantity]
    value = float(expr.subs({s("skier-friction", k): v for k, v in values.items()}))
    assert round(value, places) == expected


def test_yo_yo_falls_slower_than_free_fall_and_tension_below_weight() -> None:
    m, r, k, g = (s("yo-yo", n) for n in ("m", "r", "k", "g"))
    result = bank_derivation("yo-yo").quantities
    point = {m: 2, r: sympy.Rational(1, 100), k: sympy.Rational(3, 100), g: 10}
    assert 0 < result["acceleration"].subs(point) < 10
    assert 0 < result["tension"].subs(point) < 20
