"""A support moving as prescribed (positions and gaps in the time t): a pendulum hung in a truck that
accelerates at A, and one whose pivot oscillates vertically. Lagrange's equations carry the explicit
time, Newton differentiates the moving gap in time, d'Alembert's inertial forces include the support's
acceleration, the fictitious-forces method works in the frame moving with the support (-m A); energy
is not conserved in the ground's frame, so that method says it does not apply; the simulation
integrates with the clock and keeps the books with the moving constraint's work."""

from __future__ import annotations

import pytest
import sympy
import yaml
from sympy import atan, sin, sqrt

from physics.engine import Model, derivation, load_model
from physics.errors import DerivationError, SpecErrors

uncached = derivation._derive.__wrapped__
NAMES = ("m", "L", "A", "g", "a", "w")
SYMBOLS = {name: sympy.Symbol(name, positive=True) for name in NAMES}
m, L, A, g, a, w = (SYMBOLS[n] for n in NAMES)

TRUCK = """
elements:
  bob: {kind: pendulum, mass: m, length: L, coordinate: theta, pivot: {x: "A*t^2/2", y: 0}}
gravity: g
domain:
  ranges: {theta: ["-pi/2", "pi/2"]}
state: {theta: "-atan(A/g)"}
quantities:
  hanging: {equilibrium: theta}
  omega: {angular_frequency: theta}
  tension: {force: bob}
"""
# the same truck written low-level: the bob's position and the string's gap both move with the pivot
TRUCK_BY_HAND = """
coordinates: [theta]
bodies:
  bob: {mass: m, position: {x: "A*t^2/2 + L*sin(theta)", y: "-L*cos(theta)"}}
gravity: g
constraints:
  string: {kind: string, gap: "L - sqrt((x_bob - A*t^2/2)^2 + y_bob^2)"}
domain:
  ranges: {theta: ["-pi/2", "pi/2"]}
state: {theta: 0}
quantities:
  swing: {acceleration: theta}
  tension: {force: string}
"""
SWINGING_THROUGH = """
elements:
  bob: {kind: pendulum, mass: m, length: L, coordinate: theta, pivot: {x: "A*t^2/2", y: 0}}
gravity: g
domain:
  ranges: {theta: ["-pi/2", "pi/2"]}
state: {theta: 0}
quantities:
  rate: {velocity: theta, at: {theta: "-atan(A/g)"}}
"""
SHAKEN = """
elements:
  bob: {kind: pendulum, mass: m, length: L, coordinate: theta, pivot: {x: 0, y: "a*cos(w*t)"}}
gravity: g
domain:
  ranges: {theta: ["0", "pi/2"]}
  positive: ["g - a*w^2"]
state: {theta: "pi/6", t: 0}
quantities:
  swing: {acceleration: theta}
"""


def _model(text: str) -> Model:
    return load_model(yaml.safe_load(text), SYMBOLS)


def _same(first: sympy.Expr, second: sympy.Expr) -> bool:
    """Equal: simplified, else at a few points where every symbol is positive and g > a w^2."""
    if sympy.simplify(first - second) == 0:
        return True
    points = [
        {m: 1.3, L: 0.7, A: 2.1, g: 9.8, a: 0.1, w: 3.0},
        {m: 0.4, L: 2.2, A: 0.3, g: 1.5, a: 0.2, w: 1.1},
    ]
    return all(abs(complex((first - second).subs(point).evalf())) < 1e-12 for point in points)


@pytest.mark.parametrize(
    ("text", "expected", "methods"),
    [
        (
            TRUCK,
            {
                "hanging": -atan(A / g),
                "omega": (g**2 + A**2) ** sympy.Rational(1, 4) / sqrt(L),
                "tension": m * sqrt(g**2 + A**2),
            },
            {
                "hanging": {"lagrange", "dalembert", "frames"},
                "omega": {"lagrange", "dalembert", "frames"},
                "tension": {"lagrange", "newton", "frames"},
            },
        ),
        (
            TRUCK_BY_HAND,
            {"swing": -A / L, "tension": m * g},
            {
                "swing": {"lagrange", "newton", "dalembert", "frames"},
                "tension": {"lagrange", "newton", "frames"},
            },
        ),
        (
            SHAKEN,
            {"swing": -(g - a * w**2) * sin(sympy.pi / 6) / L},
            {"swing": {"lagrange", "newton", "dalembert", "frames"}},
        ),
        (  # released at rest in the truck, it swings back through the equilibrium: (g_eff - g) = L w^2 / 2
            SWINGING_THROUGH,
            {"rate": -sqrt(2 * (sqrt(g**2 + A**2) - g) / L)},
            {"rate": {"lagrange", "newton", "dalembert", "frames"}},
        ),
    ],
    ids=["truck equilibrium", "truck from rest", "pivot shaken vertically", "through the equilibrium"],
)
def test_a_support_moving_as_prescribed_is_derived_by_several_methods_and_simulated(
    text: str, expected: dict[str, sympy.Expr], methods: dict[str, set[str]]
) -> None:
    result = uncached(_model(text))
    for name, value in expected.items():
        assert _same(result.quantities[name], value), (name, result.quantities[name])
        assert methods[name] <= set(result.agreement[name])
        assert name in result.simulation
    assert "energy balance" in result.checks  # with the moving string's work, -lambda dg/dt


def test_energy_conservation_says_it_does_not_apply_in_the_ground_frame() -> None:
    result = uncached(_model(TRUCK))
    [conservation] = [r for r in result.methods if r.name == "conservation"]
    assert not conservation.results
    assert all("energy is not conserved in the ground's frame" in note for note in conservation.notes)


@pytest.mark.parametrize(
    ("text", "says"),
    [
        (  # the gap left fixed while the positions move
            TRUCK_BY_HAND.replace("(x_bob - A*t^2/2)^2", "x_bob^2"),
            "the positions move with the time t but the gap does not",
        ),
        (  # a shaken pivot has no equilibrium relative to it
            SHAKEN.replace("swing: {acceleration: theta}", "omega: {angular_frequency: theta}"),
            "the support's motion is not a uniform acceleration",
        ),
        (  # a time in the state that nothing uses
            TRUCK_BY_HAND.replace('"A*t^2/2 + L*sin(theta)"', '"L*sin(theta)"')
            .replace("(x_bob - A*t^2/2)^2", "x_bob^2")
            .replace("state: {theta: 0}", "state: {theta: 0, t: 1}"),
            "no force or position depends on the time t",
        ),
        (  # the shaken pivot's string goes slack where a w^2 > g
            SHAKEN.replace('positive: ["g - a*w^2"]', "positive: []"),
            "the string would push where",
        ),
    ],
    ids=["gap does not move", "no steady rest", "unused time", "string goes slack"],
)
def test_a_moving_support_stated_wrongly_is_refused_naming_the_cause(text: str, says: str) -> None:
    with pytest.raises((DerivationError, SpecErrors)) as caught:
        uncached(_model(text))
    assert says in str(caught.value)
