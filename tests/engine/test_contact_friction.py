"""Friction at a contact: kinetic friction on rigid bodies (with its torque) and between two moving bodies,
the sliding phase until a contact grips, and static friction at its limit; each by Lagrange and Newton,
simulated, with the energy books kept. (The `rolling` element's sliding mode and a rolling body's least
coefficient are the guide's examples, tested with it.)"""

from __future__ import annotations

from functools import cache
from typing import Any

import pytest
import sympy

from physics.engine import Derivation, derive, load_model
from physics.errors import DerivationError, SpecErrors

NAMES = ("m", "M", "R", "mu", "mu_s", "g", "v", "theta")
SYMBOLS = {name: sympy.Symbol(name, positive=True) for name in NAMES}
m, M, R, mu, mu_s, g, v, theta = (SYMBOLS[n] for n in NAMES)


def skidding_ball(velocity: str = "v") -> dict[str, Any]:
    """A ball launched along a floor without spin: friction at its lowest point slows it and spins it up."""
    return {
        "coordinates": ["x", "phi"],
        "bodies": {
            "ball": {"mass": "m", "inertia": "2*m*R^2/5", "position": {"x": "x", "y": "R"}, "angle": "phi"}
        },
        "gravity": "g",
        "constraints": {"floor": {"kind": "surface", "gap": "y_ball - R"}},
        "friction": [
            {
                "constraint": "floor",
                "body": "ball",
                "coefficient": "mu",
                "sliding": "x",
                "contact": {"y": "-R"},
            }
        ],
        "state": {"x_dot": velocity},
        "quantities": {
            "a": {"acceleration": "x"},
            "alpha": {"acceleration": "phi"},
            "t": {"slip_time": "floor"},
            "d": {"slip_distance": "x"},
            "vf": {"slip_end_velocity": "x"},
        },
    }


def block_on_cart() -> dict[str, Any]:
    """A block slides along a cart on smooth rails; friction between them drags the cart along."""
    return {
        "coordinates": ["X", "s"],
        "bodies": {
            "cart": {"mass": "M", "position": {"x": "X", "y": 0}},
            "block": {"mass": "m", "position": {"x": "X + s", "y": "R"}},
        },
        "gravity": "g",
        "constraints": {
            "rails": {"kind": "surface", "gap": "y_cart"},
            "top": {"kind": "surface", "gap": "y_block - y_cart - R"},
        },
        "friction": [
            {"constraint": "top", "body": "block", "coefficient": "mu", "sliding": "s", "against": "cart"}
        ],
        "state": {"s_dot": "v"},
        "quantities": {
            "cart": {"acceleration": "X"},
            "t": {"slip_time": "top"},
            "common": {"slip_end_velocity": "X"},
        },
    }


def held_block() -> dict[str, Any]:
    """A block held on an incline by static friction (no coordinate: the contact holds it)."""
    return {
        "coordinates": [],
        "bodies": {"block": {"mass": "m", "position": {"x": 0, "y": 0}}},
        "gravity": "g",
        "constraints": {
            "slope": {"kind": "surface", "gap": "x_block*sin(theta) + y_block*cos(theta)"},
            "hold": {"kind": "other", "gap": "y_block*sin(theta) - x_block*cos(theta)"},
        },
        "domain": {"ranges": {"theta": ["0", "pi/2"]}},
        "quantities": {
            "grip": {"force": "hold"},
            "steepest": {"slipping": "theta", "friction": "hold", "normal": "slope", "coefficient": "mu_s"},
        },
    }


MODELS = {
    "ball": skidding_ball,
    "cart": block_on_cart,
    "held": held_block,
}


@cache
def derived(name: str) -> Derivation:
    return derive(load_model(MODELS[name](), SYMBOLS))


@pytest.mark.parametrize(
    ("model", "quantity", "expected"),
    [
        ("ball", "a", -mu * g),
        ("ball", "alpha", -5 * mu * g / (2 * R)),  # counterclockwise: the ball spins up clockwise
        ("ball", "t", 2 * v / (7 * mu * g)),
        ("ball", "d", 12 * v**2 / (49 * mu * g)),
        ("ball", "vf", 5 * v / 7),
        ("cart", "cart", mu * m * g / M),
        ("cart", "t", M * v / (mu * g * (m + M))),
        ("cart", "common", m * v / (m + M)),
        ("held", "grip", m * g * sympy.sin(theta)),
        ("held", "steepest", sympy.atan(mu_s)),
    ],
)
@pytest.mark.sample(2)
def test_friction_at_a_contact_is_derived_by_two_methods_and_simulated(
    model: str, quantity: str, expected: sympy.Expr
) -> None:
    derivation = derived(model)
    assert sympy.simplify(derivation.quantities[quantity] - expected) == 0
    assert {"lagrange", "newton"} <= set(derivation.agreement[quantity])
    assert derivation.simulation[quantity].max_relative_error < 1e-3


@pytest.mark.parametrize("model", ["ball", "cart"])
def test_the_energy_books_of_a_sliding_contact_balance(model: str) -> None:
    assert "energy balance" in derived(model).checks


def test_forgetting_the_friction_torque_is_a_known_mistake_of_the_sliding_time() -> None:
    mistakes = {m.expr: m.feedback for m in derived("ball").mistakes["t"]}
    assert "turns the body" in mistakes[v / (mu * g)]


def test_a_ball_launched_backwards_against_the_assumed_slip_is_refused_at_friction() -> None:
    data = skidding_ball("-v")
    data["quantities"] = {"a": {"acceleration": "x"}}
    with pytest.raises(DerivationError) as caught:
        derive(load_model(data, SYMBOLS))
    assert caught.value.path == ("friction", 0)
    assert "slides towards decreasing x" in caught.value.message


def test_a_contact_point_on_the_far_side_from_the_surface_is_refused_with_the_near_one() -> None:
    # at the top of the ball, friction's torque turns it backwards: it would end its skid rolling forward
    # at 5 v/7 while spinning as if rolling backwards (phi' = +5 v/(7 R)), every method agreeing
    data = skidding_ball()
    data["friction"][0]["contact"] = {"y": "R"}
    with pytest.raises(DerivationError) as caught:
        derive(load_model(data, SYMBOLS))
    assert caught.value.path == ("friction", 0, "contact")
    assert "lies on the far side of ball's centre from the surface" in caught.value.message
    assert caught.value.message.endswith("{y: -R}")


def _slid(direction: str, velocity: str) -> dict[str, Any]:
    """A block sent along a rough slope, its coordinate growing `direction` the slope."""
    ramp = {"kind": "incline", "body": "block", "mass": "m", "angle": "theta", "coordinate": "s"}
    return {
        "elements": {"ramp": {**ramp, "direction": direction, "friction": "mu"}},
        "gravity": "g",
        "state": {"s": 0, "s_dot": velocity},
        "domain": {"ranges": {"theta": ["0", "pi/2"]}},
        "quantities": {"far": {"turning_point": "s"}},
    }


# sent up the slope at v: with the coordinate growing down it, the state's velocity is -v, and friction
# written against sliding towards increasing s would push the block up the slope
SLID_UP = [
    pytest.param("up", "v", v**2 / (2 * g * (sympy.sin(theta) + mu * sympy.cos(theta))), id="coordinate-up"),
    pytest.param("down", "-v", None, id="coordinate-down"),
]


@pytest.mark.parametrize(("direction", "velocity", "expected"), SLID_UP)
def test_a_block_sliding_against_its_frictions_assumed_slip_is_refused_where_the_friction_is_written(
    direction: str, velocity: str, expected: sympy.Expr | None
) -> None:
    model = load_model(_slid(direction, velocity), SYMBOLS)
    if expected is not None:
        assert sympy.simplify(derive(model).quantities["far"] - expected) == 0
        return
    with pytest.raises(DerivationError) as caught:
        derive(model)
    assert caught.value.path == ("elements", "ramp", "friction")
    assert "slides towards decreasing s" in caught.value.message


def _faults(data: dict[str, Any]) -> dict[str, str]:
    with pytest.raises(SpecErrors) as caught:
        load_model(data, SYMBOLS)
    return {".".join(map(str, e.path)): e.message for e in caught.value.errors}


def test_friction_faults_are_reported_together_with_their_paths() -> None:
    data = skidding_ball()
    data["friction"][0].pop("contact")
    data["bodies"]["block"] = {"mass": "m", "position": {"x": "x"}}
    data["friction"].append(
        {"constraint": "floor", "body": "block", "coefficient": "mu", "sliding": "x", "contact": {"y": "-R"}}
    )
    data["quantities"]["grip"] = {
        "slipping": "mu_s",
        "friction": "nowhere",
        "normal": "floor",
        "coefficient": "mu_s",
    }
    data["quantities"]["late"] = {"slip_time": "wall"}
    faults = _faults(data)
    assert "contact point" in faults["friction.0.contact"]
    assert "no size" in faults["friction.1.contact"]
    assert "unknown constraint" in faults["quantities.grip.friction"]
    assert "exactly one" in faults["quantities.d.slip_distance"]


def test_a_sliding_time_at_a_contact_without_kinetic_friction_is_refused() -> None:
    data = block_on_cart()
    data["quantities"] = {"t": {"slip_time": "rails"}}
    assert "no kinetic friction" in _faults(data)["quantities.t.slip_time"]
