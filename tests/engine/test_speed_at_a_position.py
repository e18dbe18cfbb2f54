"""Speed at a position: by work and energy and by integrating the equation of motion (v dv/dq), proved
equal and measured on an integrated motion; a force where the motion arrives uses the speed it has there."""

from __future__ import annotations

import copy
from pathlib import Path
from typing import Any

import pytest
import sympy
import yaml
from sympy import cos, sin, sqrt

from physics.engine import derive, load_model
from physics.engine.mechanics import Mechanics
from physics.engine.newton import NewtonMethod
from physics.errors import DerivationError, SpecErrors

BANK = Path(__file__).resolve().parents[2] / "problems" / "bank"
m, R, g, mu, theta, L = sympy.symbols("m R g mu theta L", positive=True)
SYMBOLS = {str(s): s for s in (m, R, g, mu, theta, L)}


def slide() -> dict[str, Any]:
    data = yaml.safe_load((BANK / "quarter-circle-slide" / "model.yaml").read_text())
    assert isinstance(data, dict)
    return data


def rough_incline() -> dict[str, Any]:
    """A block released from rest slides a distance L down a rough incline."""
    return {
        "elements": {
            "ramp": {
                "kind": "incline",
                "body": "block",
                "mass": "m",
                "angle": "theta",
                "coordinate": "s",
                "friction": "mu",
            }
        },
        "gravity": "g",
        "state": {"s": 0},
        "domain": {"ranges": {"theta": ["0", "pi/2"]}, "positive": ["tan(theta) - mu"]},
        "quantities": {
            "speed": {"speed": "block", "at": {"s": "L"}},
            "rate": {"velocity": "s", "at": {"s": "L"}},
        },
    }


def test_the_quarter_circle_slide_gives_sqrt_2gR_and_three_mg_by_independent_routes() -> None:
    result = derive(load_model(slide(), SYMBOLS))
    assert sympy.simplify(result.quantities["speed_at_bottom"] - sqrt(2 * g * R)) == 0
    assert sympy.simplify(result.quantities["normal_force_at_bottom"] - 3 * m * g) == 0
    assert set(result.agreement["speed_at_bottom"]) == {"lagrange", "newton", "conservation", "dalembert"}
    assert set(result.agreement["normal_force_at_bottom"]) == {"lagrange", "newton"}
    for name in ("speed_at_bottom", "normal_force_at_bottom"):
        check = result.simulation[name]
        assert check.points >= 3 and check.max_relative_error < 1e-3
        assert "reach" in check.compared
    steps = {s.title for method in result.methods for s in method.steps}
    assert any(t.startswith("Work and energy") for t in steps)
    assert any("written for the square of its rate" in t for t in steps)


def test_the_normal_force_mistakes_name_the_missing_centripetal_term() -> None:
    mistakes = derive(load_model(slide(), SYMBOLS)).mistakes["normal_force_at_bottom"]
    by_answer = {sympy.simplify(k.expr): k.feedback for k in mistakes}
    assert "at rest" in by_answer[m * g]
    speed = {sympy.simplify(k.expr) for k in derive(load_model(slide(), SYMBOLS)).mistakes["speed_at_bottom"]}
    assert sqrt(g * R) in speed  # the factor 2 of the kinetic energy forgotten


def test_friction_on_an_incline_does_work_mu_m_g_cos_theta_per_length() -> None:
    result = derive(load_model(rough_incline(), SYMBOLS))
    expected = sqrt(2 * g * L * (sin(theta) - mu * cos(theta)))
    assert sympy.simplify(result.quantities["speed"] - expected) == 0
    assert set(result.agreement["speed"]) >= {"lagrange", "newton", "conservation"}
    assert result.simulation["rate"].max_relative_error < 1e-3
    assert any("Work of the non-conservative forces" in s.title for s in result.methods[2].steps)


def falling(drag: str) -> dict[str, Any]:
    """A ball dropped from rest falls a height h against drag."""
    return {
        "coordinates": ["y"],
        "bodies": {"ball": {"mass": "m", "position": {"y": "y"}}},
        "forces": [{"body": "ball", drag: "c"}],
        "gravity": "g",
        "state": {"y": 0},
        "quantities": {"v": {"velocity": "y", "at": {"y": "-h"}}},
    }


def test_quadratic_drag_is_integrated_and_the_energy_route_says_why_it_stops() -> None:
    c, h = sympy.symbols("c h", positive=True)
    result = derive(load_model(falling("quadratic_drag"), {**SYMBOLS, "c": c, "h": h}))
    expected = -sqrt(m * g / c * (1 - sympy.exp(-2 * c * h / m)))
    assert sympy.simplify(result.quantities["v"] - expected) == 0
    assert set(result.agreement["v"]) >= {"lagrange", "newton"}
    (note,) = [n for method in result.methods if method.name == "conservation" for n in method.notes]
    assert "depends on the speed along the way" in note
    assert result.simulation["v"].max_relative_error < 1e-3


def test_linear_drag_is_refused_with_each_route_s_reason() -> None:
    c, h = sympy.symbols("c h", positive=True)
    with pytest.raises(DerivationError) as caught:
        derive(load_model(falling("drag"), {**SYMBOLS, "c": c, "h": h}))
    message = str(caught.value)
    assert "does not integrate in closed form" in message and "depends on the speed" in message


@pytest.mark.parametrize(
    ("edit", "path", "words"),
    [
        pytest.param(
            {"speed_at_bottom": {"speed": "block"}},
            ("quantities", "speed_at_bottom", "at"),
            "required",
            id="speed-without-at",
        ),
        pytest.param(
            {"v": {"velocity": "theta", "at": {"phi": 0}}},
            ("quantities", "v", "at", "phi"),
            "unknown coordinate",
            id="unknown-coordinate",
        ),
        pytest.param(
            {"v": {"speed": "crate", "at": {"theta": 0}}},
            ("quantities", "v", "speed"),
            "unknown body",
            id="unknown-body",
        ),
        pytest.param(
            {"v": {"speed": "block", "at": {"theta": 0}, "level": 0}},
            ("quantities", "v", "level"),
            "unknown key",
            id="level-on-a-speed",
        ),
        pytest.param(
            {"bottom": {"equilibrium": "theta"}, "v": {"speed": "block", "at": {"theta": "bottom"}}},
            ("quantities", "v", "at", "theta"),
            "not the name of another quantity: bottom is a quantity of this model, so write in its place the "
            "expression it comes to",
            id="at-naming-a-quantity",
        ),
        pytest.param(
            {"v": {"speed": "block", "at": {"theta": "bottom"}}},
            ("quantities", "v", "at", "theta"),
            "`at` takes the value theta reaches as an expression in the problem's symbols, not the name of",
            id="at-naming-no-symbol",
        ),
    ],
)
def test_a_wrong_speed_quantity_is_refused_at_its_path(
    edit: dict[str, Any], path: tuple[str, ...], words: str
) -> None:
    data = slide()
    data["quantities"] = edit
    with pytest.raises(SpecErrors) as caught:
        load_model(data, SYMBOLS)
    found = {e.path: e.message for e in caught.value.errors}
    assert words in found[path]


def test_a_speed_needs_the_start_in_the_state() -> None:
    data = slide()
    del data["state"]
    with pytest.raises(SpecErrors) as caught:
        load_model(data, SYMBOLS)
    (error,) = caught.value.errors
    assert error.path == ("state",) and "theta" in error.message


def test_a_place_the_motion_cannot_reach_is_refused_with_the_reason() -> None:
    data = copy.deepcopy(slide())
    data["state"] = {"theta": "-pi/4"}  # released lower down: it cannot climb to the other rim
    data["quantities"] = {"v": {"speed": "block", "at": {"theta": "pi/2"}}}
    with pytest.raises(DerivationError) as caught:
        derive(load_model(data, SYMBOLS))
    assert "does not reach theta = pi/2" in str(caught.value)


def moving_wedge() -> dict[str, Any]:
    """The bank's moving wedge, the block released from rest at s = 0 (X: the wedge's position)."""
    data = yaml.safe_load((BANK / "moving-wedge" / "model.yaml").read_text())
    data["state"] = {"s": 0, "X": 0}
    drop = "h/sin(theta)"  # down the incline until the block has descended h
    data["quantities"] = {
        "wedge_velocity": {"velocity": "X", "at": {"s": drop}},
        "relative_speed": {"velocity": "s", "at": {"s": drop}},
        "block_speed": {"speed": "block", "at": {"s": drop}},
    }
    return data


def test_a_block_on_a_free_wedge_reaches_the_closed_form_speeds_by_momentum_and_energy() -> None:
    """Horizontal momentum from rest: (M + m) X' + m s' cos(theta) = 0, so X' = -m cos(theta) s'/(M + m).
    Energy: (1/2) M X'^2 + (1/2) m [(X' + s' cos(theta))^2 + (s' sin(theta))^2] = m g h; with X' put in,
    T = (1/2) m s'^2 (M + m sin^2(theta))/(M + m), so s'^2 = 2 g h (M + m)/(M + m sin^2(theta)) (the
    block's speed relative to the wedge) and v_wedge = -m cos(theta) sqrt(2 g h/((M + m)(M + m sin^2))).
    The block's own velocity is (X' + s' cos(theta), -s' sin(theta))."""
    M, h = sympy.symbols("M h", positive=True)
    result = derive(load_model(moving_wedge(), {**SYMBOLS, "M": M, "h": h}))
    relative = sqrt(2 * g * h * (M + m) / (M + m * sin(theta) ** 2))
    wedge = -m * cos(theta) * relative / (M + m)
    block = sqrt((wedge + relative * cos(theta)) ** 2 + (relative * sin(theta)) ** 2)
    expected = {"wedge_velocity": wedge, "relative_speed": relative, "block_speed": block}
    for name, value in expected.items():
        derived = result.quantities[name]
        at = {m: 1.3, M: 2.9, g: 9.81, theta: 0.61, h: 0.7}
        assert abs(float(derived.subs(at)) - float(value.subs(at))) < 1e-12, name
        assert sympy.simplify(derived - value) == 0, name
        assert {"conservation", "lagrange", "newton"} <= set(result.agreement[name])
        assert result.simulation[name].max_relative_error < 1e-3
    steps = {s.title for method in result.methods for s in method.steps}
    assert "The momentum conjugate to $X$ is conserved (no force acts along it)" in steps
    assert any(t.startswith("Work and energy") for t in steps)
    assert any("written for the square of its rate" in t for t in steps)


def test_a_coordinate_no_conserved_momentum_fixes_is_refused_at_the_quantity_saying_what_to_declare() -> None:
    """Two masses joined by springs exchange energy: where x1 gets to 0, x2's place and speed are open."""
    data: dict[str, Any] = {
        "coordinates": ["x1", "x2"],
        "bodies": {"a": {"mass": "m", "position": {"x": "x1"}}, "b": {"mass": "m", "position": {"x": "x2"}}},
        "potentials": [
            {"bodies": ["a"], "anchor": {"x": 0}, "distance": "d", "energy": "mu*d^2/2"},
            {"bodies": ["a", "b"], "distance": "d", "energy": "mu*d^2/2"},
        ],
        "state": {"x1": "L", "x2": 0},
        "quantities": {"v": {"velocity": "x1", "at": {"x1": 0}}},
    }
    with pytest.raises(DerivationError) as caught:
        derive(load_model(data, SYMBOLS))
    error = caught.value
    assert error.path == ("quantities", "v", "at")
    assert "x2 is not determined" in error.message and "Declare x2 fixed" in error.message


LOOP_SIDE = """
# a ball rolling round the inside of a loop; its centre on the circle of radius R - r, the grip's arc
# written with acos (valid over the loop's half, theta in [0, pi])
coordinates: [theta]
bodies:
  ball:
    mass: m
    inertia: "2*m*r^2/5"
    position: {x: "(R - r)*sin(theta)", y: "-(R - r)*cos(theta)"}
    angle: "-(R - r)*theta/r"
gravity: g
constraints:
  track: {kind: surface, gap: "R - r - sqrt(x_ball^2 + y_ball^2)"}
  rolling: {kind: rolling, gap: "r*phi_ball + (R - r)*acos(-y_ball/(R - r))"}
state: {theta: pi/6, theta_dot: "v0/(R - r)"}
domain:
  ranges: {theta: ["0", "pi"]}
  positive: ["R - r", "7*v0^2 - 27*g*(R - r)"]
quantities:
  side: {velocity: theta, at: {theta: pi/2}}
"""


@pytest.mark.slow
def test_newton_takes_a_ball_rolling_round_a_loop_to_its_side() -> None:
    """Newton's acceleration comes out of the acos grip as a ratio of trigonometric polynomials equal to
    5 g sin(theta)/(7 (r - R)); integrated as it was, it took minutes (an upload's time ran out): it is
    written in cos(theta) alone and cancelled first."""
    r, v0 = sympy.symbols("r v0", positive=True)
    model = load_model(yaml.safe_load(LOOP_SIDE), {**SYMBOLS, "r": r, "v0": v0})
    newton = NewtonMethod(model, Mechanics(model))  # the method whose integration took minutes; alone
    newton.derive()
    found = newton.answer(model.quantity("side"))
    rho = R - r
    expected = sqrt(v0**2 - 5 * sqrt(3) * g * rho / 7) / rho
    point = {R: 3, r: sympy.Rational(1, 2), g: sympy.Rational(49, 5), v0: 9}
    assert abs(sympy.N((found - expected).subs(point))) < 1e-12


def thrown(height: str, quantity: str = "speed") -> dict[str, Any]:
    """A ball thrown from the ground at v0, angle theta; asked about where y reaches `height`."""
    target = {quantity: "ball" if quantity == "speed" else "y", "at": {"y": height}}
    return {
        "coordinates": ["x", "y"],
        "bodies": {"ball": {"mass": "m", "position": {"x": "x", "y": "y"}}},
        "gravity": "g",
        "state": {"x": 0, "y": 0, "x_dot": "v0*cos(theta)", "y_dot": "v0*sin(theta)"},
        "domain": {"ranges": {"theta": ["0", "pi/2"]}},
        "quantities": {"there": target},
    }


TOP = "v0^2*sin(theta)^2/(2*g)"
v0 = sympy.Symbol("v0", positive=True)


@pytest.mark.parametrize(
    ("height", "quantity", "expected", "said"),
    [
        (TOP, "speed", v0 * cos(theta), "where its rate vanishes: its turning point"),
        (TOP, "velocity", sympy.Integer(0), "where its rate vanishes: its turning point"),
        # 0.9 of the top is passed twice, rising then falling: the first arrival, rising, and it says so
        (f"9/10*{TOP}", "velocity", v0 * sin(theta) / sqrt(10), "the velocity is taken at the first arrival"),
    ],
    ids=["speed-at-the-top", "rate-at-the-top", "rate-below-the-top"],
)
def test_a_projectile_reaches_its_top_at_zero_vertical_rate_and_a_lower_height_first_rising(
    height: str, quantity: str, expected: sympy.Expr, said: str
) -> None:
    result = derive(load_model(thrown(height, quantity), {**SYMBOLS, "v0": v0}))
    assert sympy.simplify(result.quantities["there"] - expected) == 0
    assert {"lagrange", "newton", "conservation", "dalembert"} <= set(result.agreement["there"])
    assert result.simulation["there"].max_relative_error < 1e-3
    derived = [method for method in result.methods if method.name in result.agreement["there"]]
    assert all(any(said in s.title for s in method.steps) for method in derived)


def test_a_height_above_a_projectile_s_top_is_refused_as_never_reached() -> None:
    with pytest.raises(DerivationError) as caught:
        derive(load_model(thrown(f"11/10*{TOP}"), {**SYMBOLS, "v0": v0}))
    assert "does not reach y = 11*v0^2*sin(theta)^2/(20*g): there y_dot^2 = -v0^2*sin(theta)^2/10" in str(
        caught.value
    )
