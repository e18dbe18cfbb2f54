"""Trajectories without drag: time of flight, range and maximum height by constant-acceleration
kinematics and by energy and momentum, proved equal and measured on an integrated flight."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest
import sympy
import yaml
from sympy import cos, sin, sqrt

from physics.engine import derive, load_model
from physics.errors import DerivationError, SpecErrors

BANK = Path(__file__).resolve().parents[2] / "problems" / "bank"
m, v0, alpha, g, h, theta = sympy.symbols("m v0 alpha g h theta", positive=True)
SYMBOLS = {str(s): s for s in (m, v0, alpha, g, h, theta)}
ALL = {"lagrange", "newton", "conservation"}


def launch() -> dict[str, Any]:
    data = yaml.safe_load((BANK / "projectile" / "model.yaml").read_text())
    assert isinstance(data, dict)
    return data


def test_flight_over_level_ground_is_derived_by_kinematics_and_by_energy_and_momentum() -> None:
    result = derive(load_model(launch(), SYMBOLS))
    expected = {
        "time_of_flight": 2 * v0 * sin(alpha) / g,
        "range": v0**2 * sin(2 * alpha) / g,
        "max_height": (v0 * sin(alpha)) ** 2 / (2 * g),
    }
    for name, value in expected.items():
        assert sympy.simplify(result.quantities[name] - value) == 0, name
        assert set(result.agreement[name]) >= ALL, name
        check = result.simulation[name]
        assert check.points >= 3 and check.max_relative_error < 1e-3 and "integrated flight" in check.compared
    assert "limit range (alpha → pi/2)" in result.checks  # the model's stated limit was checked


def test_flight_mistakes_name_the_factor_2_and_the_swapped_components() -> None:
    mistakes = derive(load_model(launch(), SYMBOLS)).mistakes
    flight = {sympy.simplify(k.expr): k.feedback for k in mistakes["time_of_flight"]}
    assert "time to the top" in flight[v0 * sin(alpha) / g]
    assert "swapped" in flight[2 * v0 * cos(alpha) / g]
    height = {sympy.simplify(k.expr): k.feedback for k in mistakes["max_height"]}
    assert "horizontally" in height[v0**2 / (2 * g)]


def test_a_landing_level_below_the_launch_takes_the_later_root() -> None:
    data = launch()
    data["limits"] = []
    data["quantities"] = {
        "T": {"time_of_flight": "ball", "level": "-h"},
        "R": {"range": "ball", "level": "-h"},
    }
    result = derive(load_model(data, SYMBOLS))
    vy = v0 * sin(alpha)
    flight = (vy + sqrt(vy**2 + 2 * g * h)) / g
    assert sympy.simplify(result.quantities["T"] - flight) == 0
    assert sympy.simplify(result.quantities["R"] - v0 * cos(alpha) * flight) == 0
    assert set(result.agreement["R"]) >= ALL


# (slope, launch velocity, the domain's positives; time of flight, range along the slope): the classic
# range up and down an incline through the launch point, R = 2 v0² cos α sin(α ∓ θ) / (g cos² θ)
ONTO_A_SLOPE = [
    pytest.param(
        "theta",
        ("v0*cos(alpha)", "v0*sin(alpha)"),
        ["alpha - theta"],
        2 * v0 * sin(alpha - theta) / (g * cos(theta)),
        2 * v0**2 * cos(alpha) * sin(alpha - theta) / (g * cos(theta) ** 2),
        id="up-an-incline",
    ),
    pytest.param(
        "-theta",
        ("v0*cos(alpha)", "v0*sin(alpha)"),
        [],
        2 * v0 * sin(alpha + theta) / (g * cos(theta)),
        2 * v0**2 * cos(alpha) * sin(alpha + theta) / (g * cos(theta) ** 2),
        id="down-an-incline",
    ),
    pytest.param(
        "-theta",
        ("v0", "0"),
        [],
        2 * v0 * sympy.tan(theta) / g,
        2 * v0**2 * sin(theta) / (g * cos(theta) ** 2),
        id="thrown-level-off-a-slope",
    ),
]


def _onto_a_slope(slope: str, velocity: tuple[str, str], positive: list[str]) -> dict[str, Any]:
    data = launch()
    data["limits"] = []
    data["state"] = {"x": 0, "y": 0, "x_dot": velocity[0], "y_dot": velocity[1]}
    data["domain"] = {"ranges": {"alpha": ["0", "pi/2"], "theta": ["0", "pi/2"]}, "positive": positive}
    data["quantities"] = {
        "T": {"time_of_flight": "ball", "slope": slope},
        "R": {"range": "ball", "slope": slope},
    }
    return data


@pytest.mark.parametrize(("slope", "velocity", "positive", "flight", "distance"), ONTO_A_SLOPE)
def test_a_landing_on_a_slope_through_the_launch_point_gives_the_range_along_it(
    slope: str, velocity: tuple[str, str], positive: list[str], flight: sympy.Expr, distance: sympy.Expr
) -> None:
    result = derive(load_model(_onto_a_slope(slope, velocity, positive), SYMBOLS))
    assert sympy.simplify(result.quantities["T"] - flight) == 0
    assert sympy.simplify(result.quantities["R"] - distance) == 0
    assert set(result.agreement["R"]) >= ALL
    assert "along the slope" in result.simulation["R"].compared


def test_the_range_along_a_slope_offers_the_level_ground_and_the_horizontal_distance_as_mistakes() -> None:
    data = _onto_a_slope("-theta", ("v0*cos(alpha)", "v0*sin(alpha)"), [])  # derived above: cached
    mistakes = {sympy.simplify(k.expr): k.feedback for k in derive(load_model(data, SYMBOLS)).mistakes["R"]}
    assert "level ground" in mistakes[sympy.simplify(v0**2 * sin(2 * alpha) / g)]
    horizontal = 2 * v0**2 * cos(alpha) * sin(alpha + theta) / (g * cos(theta))
    assert "horizontal distance" in next(
        f for e, f in mistakes.items() if sympy.simplify(e - horizontal) == 0
    )


def test_a_flight_with_drag_is_refused_with_each_method_s_reason() -> None:
    data = launch()
    data["limits"] = []
    data["forces"] = [{"body": "ball", "quadratic_drag": "m/h"}]
    data["quantities"] = {"H": {"max_height": "ball"}}
    with pytest.raises(DerivationError) as caught:
        derive(load_model(data, SYMBOLS))
    message = str(caught.value)
    assert "changes along the flight" in message and "energy is not conserved" in message


def test_a_landing_level_that_is_not_a_length_is_refused_at_its_path() -> None:
    from physics.dimensions import DIMENSIONLESS, Dimension

    length, time = Dimension({"length": 1}), Dimension({"time": 1})
    dimensions = {
        "m": Dimension({"mass": 1}),
        "v0": length / time,
        "alpha": DIMENSIONLESS,
        "g": length / time**2,
    }
    data = {**launch(), "limits": [], "quantities": {"T": {"time_of_flight": "ball", "level": "-v0"}}}
    with pytest.raises(SpecErrors) as caught:
        load_model(data, {n: SYMBOLS[n] for n in dimensions}, {**dimensions})
    found = {e.path: e.message for e in caught.value.errors}
    assert "expected a length" in found[("quantities", "T", "level")], found


@pytest.mark.parametrize(
    ("edit", "path", "words"),
    [
        pytest.param(
            {"quantities": {"T": {"time_of_flight": "rock"}}},
            ("quantities", "T", "time_of_flight"),
            "unknown body",
            id="unknown-body",
        ),
        pytest.param(
            {"quantities": {"H": {"max_height": "ball", "level": 0}}},
            ("quantities", "H", "level"),
            "unknown key",
            id="level-on-the-height",
        ),
        pytest.param(
            {"quantities": {"T": {"time_of_flight": "ball", "level": "h +"}}},
            ("quantities", "T", "level"),
            "cannot read",
            id="unreadable-level",
        ),
        pytest.param(
            {"quantities": {"T": {"time_of_flight": "ball", "level": 0, "slope": "theta"}}},
            ("quantities", "T", "slope"),
            "not both",
            id="level-and-slope",
        ),
        pytest.param(
            {"quantities": {"H": {"max_height": "ball", "slope": "theta"}}},
            ("quantities", "H", "slope"),
            "unknown key",
            id="slope-on-the-height",
        ),
        pytest.param(
            {"state": {"x_dot": "v0"}, "quantities": {"T": {"time_of_flight": "ball"}}},
            ("state",),
            "give where x, y start",
            id="no-launch-point",
        ),
    ],
)
def test_a_wrong_flight_quantity_is_refused_at_its_path(
    edit: dict[str, Any], path: tuple[str, ...], words: str
) -> None:
    data = {**launch(), "limits": [], **edit}
    with pytest.raises(SpecErrors) as caught:
        load_model(data, SYMBOLS)
    found = {e.path: e.message for e in caught.value.errors}
    assert words in found[path], found


@pytest.mark.parametrize(
    ("slope", "words"), [("30", "30° is written 30*pi/180"), ("2*theta + 2", "between -pi/2 and pi/2")]
)
def test_a_slope_past_a_right_angle_is_refused_at_its_path(slope: str, words: str) -> None:
    data = _onto_a_slope(slope, ("v0*cos(alpha)", "v0*sin(alpha)"), [])
    with pytest.raises(DerivationError) as caught:
        derive(load_model(data, SYMBOLS))
    assert caught.value.path == ("quantities", "T", "slope")
    assert words in caught.value.message


# a ball arriving at a floor at (u, -w) bounces off it with restitution e and lands on an incline at
# theta that rises from the bounce point: T = 2 (e w - u tan(theta))/g, the range along the incline u T/cos
u, w, e = sympy.symbols("u w e", positive=True)
BOUNCE_SYMBOLS = {**SYMBOLS, "u": u, "w": w, "e": e}


def _bounced_onto_a_slope(positive: list[str], **asked: Any) -> dict[str, Any]:
    return {
        "coordinates": ["x", "y"],
        "bodies": {"ball": {"mass": "m", "position": {"x": "x", "y": "y"}}},
        "gravity": "g",
        "state": {"x": 0, "y": 0, "x_dot": "u", "y_dot": "-w"},
        "impact": {"bodies": ["ball", {"fixed": "floor"}], "normal": {"y": -1}, "restitution": "e"},
        "domain": {"ranges": {"e": ["0", "1"], "theta": ["0", "pi/2"]}, "positive": positive},
        "quantities": {
            "T": {"time_of_flight": "ball", "after": "impact", "slope": "theta", **asked},
            "R": {"range": "ball", "after": "impact", "slope": "theta", **asked},
        },
    }


def test_a_bounce_onto_an_incline_through_the_bounce_point_lands_along_it() -> None:
    result = derive(load_model(_bounced_onto_a_slope(["e*w - u*tan(theta)"]), BOUNCE_SYMBOLS))
    flight = 2 * (e * w - u * sympy.tan(theta)) / g
    assert sympy.simplify(result.quantities["T"] - flight) == 0
    assert sympy.simplify(result.quantities["R"] - u * flight / cos(theta)) == 0
    assert set(result.agreement["R"]) >= {"newton", "conservation"}
    assert "along the slope" in result.simulation["R"].compared
    assert "after an integrated contact" in result.simulation["R"].compared


def test_a_bounce_that_leaves_below_the_incline_is_refused_saying_so() -> None:
    """Without e w > u tan(theta) the ball would leave the bounce into the incline at some points."""
    with pytest.raises(DerivationError) as caught:
        derive(load_model(_bounced_onto_a_slope([]), BOUNCE_SYMBOLS))
    assert "never comes down to the slope through the launch point" in str(caught.value)
    assert "declare the launch steeper than the slope under domain.positive" in str(caught.value)


def test_bounces_counted_before_a_landing_on_a_slope_are_refused_at_the_count() -> None:
    with pytest.raises(SpecErrors) as caught:
        load_model(_bounced_onto_a_slope(["e*w - u*tan(theta)"], bounces=2), BOUNCE_SYMBOLS)
    found = {e.path: e.message for e in caught.value.errors}
    assert "ends the first flight after the impact" in found[("quantities", "T", "bounces")]
