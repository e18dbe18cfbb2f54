"""A rolling grip written by hand turns the body the way friction at its contact point does: a ball
rolling down towards +x turns clockwise. With the angle's sign flipped in both the position and the gap,
the model is consistent, every method agrees and the simulation too, yet the contact point would slide
at twice the centre's speed: refused at the grip. The rolling element, and a ball in a bowl, derive."""

from __future__ import annotations

import pytest
import sympy
import yaml

from physics.engine import derivation, load_model
from physics.errors import DerivationError

uncached = derivation._derive.__wrapped__

SLOPE = """
coordinates: [s]
bodies:
  ball: {mass: m, inertia: "2*m*R^2/5", position: {x: "s*cos(theta)", y: "-s*sin(theta)"}, angle: ANGLE}
gravity: g
constraints:
  slope: {kind: surface, gap: "x_ball*sin(theta) + y_ball*cos(theta)"}
  grip: {kind: rolling, gap: GRIP}
domain:
  ranges: {theta: ["0", "pi/2"]}
quantities:
  a: {acceleration: s}
"""
BOWL = """
coordinates: [theta]
bodies:
  ball: {mass: m, inertia: "2*m*R^2/5", position: {x: "(L - R)*sin(theta)", y: "-(L - R)*cos(theta)"}, angle: ANGLE}
gravity: g
constraints:
  bowl: {kind: surface, gap: "L - R - sqrt(x_ball^2 + y_ball^2)"}
  grip: {kind: rolling, gap: GRIP}
domain:
  ranges: {theta: ["-pi/2", "pi/2"]}
  positive: ["L - R"]
state: {theta: "pi/6"}
quantities:
  a: {acceleration: theta}
"""

# (model, the ball's angle, the grip's gap, refused)
CASES = [
    pytest.param(SLOPE, '"-s/R"', '"x_ball*cos(theta) - y_ball*sin(theta) + R*phi_ball"', False, id="slope"),
    pytest.param(
        SLOPE, '"s/R"', '"x_ball*cos(theta) - y_ball*sin(theta) - R*phi_ball"', True, id="slope-spun-back"
    ),
    # the grip's gap written the other way round is the same grip: its force's sign is the author's
    pytest.param(
        SLOPE,
        '"-s/R"',
        '"-x_ball*cos(theta) + y_ball*sin(theta) - R*phi_ball"',
        False,
        id="slope-gap-negated",
    ),
    pytest.param(
        BOWL, '"-(L - R)*theta/R"', '"R*phi_ball + (L - R)*atan(x_ball/(-y_ball))"', False, id="bowl"
    ),
    pytest.param(
        BOWL, '"(L - R)*theta/R"', '"R*phi_ball - (L - R)*atan(x_ball/(-y_ball))"', True, id="bowl-spun-back"
    ),
]


@pytest.mark.parametrize(("text", "angle", "gap", "refused"), CASES)
@pytest.mark.sample(2)
def test_a_grip_that_turns_the_body_the_wrong_way_is_refused(
    text: str, angle: str, gap: str, refused: bool
) -> None:
    names = ["m", "R", "L", "g"] + (["theta"] if text is SLOPE else [])  # the bowl's theta is its coordinate
    symbols = {n: sympy.Symbol(n, positive=True) for n in names}
    model = load_model(yaml.safe_load(text.replace("ANGLE", angle).replace("GRIP", gap)), symbols)
    if not refused:
        uncached(model)
        return
    with pytest.raises(DerivationError, match="the grip turns ball the wrong way for rolling") as caught:
        uncached(model)
    assert caught.value.path == ("constraints", "grip")


# (model, the ball's angle, the grip's gap): geared as if the contact point were elsewhere than its radius
GEARED_WRONG = [
    # the bowl's radius over the ball's, L/R, for (L - R)/R: the arc along the bowl, not the centre's
    pytest.param(BOWL, '"-L*theta/R"', '"R*phi_ball + L*atan(x_ball/(-y_ball))"', id="bowl-L-over-R"),
    pytest.param(
        SLOPE, '"-2*s/R"', '"x_ball*cos(theta) - y_ball*sin(theta) + R*phi_ball/2"', id="slope-half"
    ),
]


@pytest.mark.parametrize(("text", "angle", "gap"), GEARED_WRONG)
def test_a_grip_geared_to_another_radius_than_the_bodys_is_refused(text: str, angle: str, gap: str) -> None:
    names = ["m", "R", "L", "g"] + (["theta"] if text is SLOPE else [])
    symbols = {n: sympy.Symbol(n, positive=True) for n in names}
    model = load_model(yaml.safe_load(text.replace("ANGLE", angle).replace("GRIP", gap)), symbols)
    with pytest.raises(DerivationError, match="would slide") as caught:
        uncached(model)
    assert caught.value.path == ("constraints", "grip")
    assert "a solid sphere's of radius R" in caught.value.message
