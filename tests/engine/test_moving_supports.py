"""A support moving as prescribed (positions and gaps in the time t): a pendulum hung in a truck that
accelerates at A, and one whose pivot oscillates vertically. Lagrange's equations carry the explicit
time, Newton differentiates the moving gap in time, d'Alembert's inertial forces include the support's
acceleration, the fictitious-forces method works in the frame moving with the support (-m A); energy
is not conserved in the ground's frame, so that method says it does not apply; the simulation
integrates with the clock and keeps the books with the moving constraint's work."""

from __future__ import annotations

from functools import cache

import pytest
import sympy
import yaml
from sympy import atan, cos, sin, sqrt, tan

from physics.engine import Derivation, Model, derivation, load_model
from physics.errors import DerivationError, SpecErrors

uncached = derivation._derive.__wrapped__
NAMES = ("m", "M", "L", "A", "g", "a", "w", "alpha")
SYMBOLS = {name: sympy.Symbol(name, positive=True) for name in NAMES}
m, M, L, A, g, a, w, alpha = (SYMBOLS[n] for n in NAMES)

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
# a bead on a rod turned at w about the origin, in a horizontal plane (seen from above, no gravity): the
# rod's gap turns with the time, so the count of freedoms takes it at an instant (not with t symbolic)
SPUN_ROD = """
coordinates: [r]
bodies:
  bead: {mass: m, position: {x: "r*cos(w*t)", y: "r*sin(w*t)"}}
constraints:
  rod: {kind: other, gap: "y_bead*cos(w*t) - x_bead*sin(w*t)"}
state: {r: L, r_dot: a*w, t: 0}
quantities:
  outward: {acceleration: r}
  push: {force: rod}
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
# the truck a body of its own, its motion prescribed by a constraint whose force is the push it needs
DRIVEN_TRUCK = """
bodies:
  truck: {mass: M, position: {x: "A*t^2/2"}}
elements:
  bob: {kind: pendulum, mass: m, length: L, coordinate: theta, pivot: truck}
gravity: g
constraints:
  drive: {kind: other, gap: "x_truck - A*t^2/2"}
domain:
  ranges: {theta: ["-pi/2", "pi/2"]}
state: {theta: "-atan(A/g)"}
quantities:
  push: {force: drive}
  omega: {angular_frequency: theta}
"""
# an accelerometer: the truck's acceleration that holds the string at alpha behind the vertical
ACCELEROMETER = """
elements:
  bob: {kind: pendulum, mass: m, length: L, coordinate: theta, pivot: {x: "A*t^2/2", y: 0}}
gravity: g
domain:
  ranges: {theta: ["-pi/2", "pi/2"], alpha: ["0", "pi/2"]}
state: {theta: "-alpha"}
quantities:
  truck_acceleration: {solve: A, zero: {acceleration: theta}}
"""
# an incline pushed along at A (its foot at x = A t^2/2): the block slides, and A = g tan(alpha) holds it
PUSHED_INCLINE = """
elements:
  ramp: {kind: incline, body: block, mass: m, angle: alpha, coordinate: s, at: {x: "A*t^2/2", y: 0}}
gravity: g
domain:
  ranges: {alpha: ["0", "pi/2"]}
quantities:
  slide: {acceleration: s}
  normal: {force: ramp}
  hold: {solve: A, zero: {acceleration: s}}
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


@cache
def _derived(text: str) -> Derivation:
    """Derived once in a test process: the truck's derivation is read by two tests."""
    return uncached(_model(text))


def _same(first: sympy.Expr, second: sympy.Expr) -> bool:
    """Equal: simplified, else at a few points where every symbol is positive and g > a w^2."""
    if sympy.simplify(first - second) == 0:
        return True
    points = [
        {m: 1.3, M: 2.0, L: 0.7, A: 2.1, g: 9.8, a: 0.1, w: 3.0, alpha: 0.4},
        {m: 0.4, M: 0.9, L: 2.2, A: 0.3, g: 1.5, a: 0.2, w: 1.1, alpha: 1.1},
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
        (
            DRIVEN_TRUCK,
            {"push": (M + m) * A, "omega": (g**2 + A**2) ** sympy.Rational(1, 4) / sqrt(L)},
            {"push": {"lagrange", "newton", "frames"}, "omega": {"lagrange", "dalembert", "frames"}},
        ),
        (
            ACCELEROMETER,
            {"truck_acceleration": g * tan(alpha)},
            {"truck_acceleration": {"lagrange", "newton", "dalembert", "frames"}},
        ),
        (
            PUSHED_INCLINE,
            {
                "slide": g * sin(alpha) - A * cos(alpha),
                "normal": m * (g * cos(alpha) + A * sin(alpha)),
                "hold": g * tan(alpha),
            },
            {
                "slide": {"lagrange", "newton", "dalembert", "frames"},
                "normal": {"lagrange", "newton", "frames"},
                "hold": {"lagrange", "newton", "dalembert", "frames"},
            },
        ),
        (  # the centrifugal push outward, and the rod's Coriolis push 2 m w r'
            SPUN_ROD,
            {"outward": w**2 * L, "push": 2 * m * a * w**2},
            {"outward": {"lagrange", "newton"}, "push": {"lagrange", "newton"}},
        ),
    ],
    ids=[
        "truck equilibrium",
        "truck from rest",
        "pivot shaken vertically",
        "through the equilibrium",
        "truck a body",
        "accelerometer",
        "incline pushed",
        "rod spun",
    ],
)
@pytest.mark.sample(3)
def test_a_support_moving_as_prescribed_is_derived_by_several_methods_and_simulated(
    text: str, expected: dict[str, sympy.Expr], methods: dict[str, set[str]]
) -> None:
    result = _derived(text)
    for name, value in expected.items():
        assert _same(result.quantities[name], value), (name, result.quantities[name])
        assert methods[name] <= set(result.agreement[name])
        assert name in result.simulation
    assert "energy balance" in result.checks  # with the moving string's work, -lambda dg/dt


def test_energy_conservation_says_it_does_not_apply_in_the_ground_frame() -> None:
    result = _derived(TRUCK)
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
        (  # a spring's fixed end written in the time: a fixed point cannot move
            """
coordinates: [e]
bodies:
  block: {mass: m, position: {y: "A*t^2/2 - e"}}
elements:
  spring: {kind: spring, between: [block, {y: "A*t^2/2"}], stiffness: m}
gravity: g
quantities:
  rest: {equilibrium: e}
""",
            "a fixed point cannot move with the time t: for a support that moves as prescribed, make it a body",
        ),
    ],
    ids=["gap does not move", "no steady rest", "unused time", "string goes slack", "moving anchor"],
)
def test_a_moving_support_stated_wrongly_is_refused_naming_the_cause(text: str, says: str) -> None:
    with pytest.raises((DerivationError, SpecErrors)) as caught:
        uncached(_model(text))
    assert says in str(caught.value)
