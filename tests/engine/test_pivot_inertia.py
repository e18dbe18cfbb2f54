"""A rigid body's `inertia` is about its centre: typed about the point it turns about (a rod hung from its
end given m L²/3, a hoop on a nail 2 m R², a hoop rolling on its rim 2 m R², a ladder sliding down a
wall m L²/3, a ball skidding on its contact point 7/5 m r²), every method counts m d² twice and agrees,
and the simulation too. Refused where it was written, saying the inertia about the centre; the right
inertias, and a wheel rolling on a thin axle (above m r², no shape's plus m r²), derive. An inertia that is
a shape's about its edge (m L²/3, a rod's about its end) on a body turning about another point (a rod
pivoted L/4 from its centre) is the same slip, refused saying what it is and what the pivot implies."""

from __future__ import annotations

import pytest
import sympy
import yaml

from physics.engine import derivation, load_model
from physics.engine.pivot_inertia import check_pivot_inertias
from physics.errors import DerivationError

uncached = derivation._derive.__wrapped__

ROD = """
elements:
  hinge: {kind: pendulum, body: rod, mass: m, inertia: INERTIA, distance: L/2, coordinate: phi}
gravity: g
state: {phi: -pi/2}
quantities:
  start: {acceleration: phi}
"""
ON_AN_AXLE = """
elements:
  axle: {kind: pendulum, body: BODY, mass: m, inertia: INERTIA, distance: DISTANCE, coordinate: phi}
gravity: g
quantities:
  start: {acceleration: phi}
"""
HOOP_ON_A_NAIL = """
elements:
  nail: {kind: pendulum, body: hoop, mass: m, inertia: INERTIA, distance: R, coordinate: phi}
gravity: g
quantities:
  T: {period: phi}
"""
LADDER = """
# smooth wall at x = 0, smooth floor at y = 0; theta the ladder's angle above the floor
coordinates: [theta]
bodies:
  ladder: {mass: m, inertia: INERTIA, position: {x: "L*cos(theta)/2", y: "L*sin(theta)/2"}, angle: theta}
gravity: g
constraints:
  floor: {kind: surface, gap: "y_ladder - L*sin(phi_ladder)/2"}
  wall: {kind: surface, gap: "x_ladder - L*cos(phi_ladder)/2"}
state: {theta: theta0}
domain:
  ranges: {theta0: ["0", "pi/2"], theta: ["0", "pi/2"]}
quantities:
  alpha: {acceleration: theta}
"""
WHEEL = """
# rolls on a radius r (its rim, or a thin axle on rails) down an incline
elements:
  wheel: {kind: rolling, mass: m, radius: r, inertia: INERTIA, angle: theta, coordinate: s}
gravity: g
domain:
  ranges: {theta: ["0", "pi/2"]}
quantities:
  a: {acceleration: s}
"""
SKIDDING = """
# launched along the floor at v without spin: it skids (kinetic friction at its contact) until it rolls
elements:
  ball: {kind: rolling, mass: m, radius: r, inertia: INERTIA, coordinate: x, friction: mu, spin: phi}
gravity: g
state: {x_dot: v}
quantities:
  skid: {slip_time: ball}
"""
NAMES = "m L R r g theta theta0 mu v m1 m2 M"
m, L, R, r, g, theta, theta0, mu, v, *_ = sympy.symbols(NAMES, positive=True)

# (model, inertia typed, the quantity's value, or the refusal's path and the inertia about the centre)
RIGHT = [
    pytest.param(ROD, "m*L^2/12", "start", 3 * g / (2 * L), id="rod-from-its-end"),
    pytest.param(HOOP_ON_A_NAIL, "m*R^2", "T", 2 * sympy.pi * sympy.sqrt(2 * R / g), id="hoop-on-a-nail"),
    pytest.param(LADDER, "m*L^2/12", "alpha", -3 * g * sympy.cos(theta0) / (2 * L), id="sliding-ladder"),
    pytest.param(
        WHEEL, "m*R^2/2", "a", 2 * g * r**2 * sympy.sin(theta) / (R**2 + 2 * r**2), id="wheel-on-a-thin-axle"
    ),
    pytest.param(SKIDDING, "2*m*r^2/5", "skid", 2 * v / (7 * mu * g), id="ball-skidding-until-it-rolls"),
]
ABOUT_THE_PIVOT = [
    pytest.param(ROD, "m*L^2/3", ("elements", "hinge", "inertia"), "L^2*m/12", id="rod-from-its-end"),
    pytest.param(HOOP_ON_A_NAIL, "2*m*R^2", ("elements", "nail", "inertia"), "R^2*m", id="hoop-on-a-nail"),
    pytest.param(LADDER, "m*L^2/3", ("bodies", "ladder", "inertia"), "L^2*m/12", id="sliding-ladder"),
    pytest.param(WHEEL, "7*m*r^2/5", ("elements", "wheel", "inertia"), "2*m*r^2/5", id="ball-on-its-contact"),
]
SKIDDING_ABOUT_THE_CONTACT = [  # it turns about no fixed point until it rolls: about the point it will
    pytest.param("7*m*r^2/5", "2*m*r^2/5", id="ball"),
    pytest.param("3*m*r^2/2", "m*r^2/2", id="cylinder"),
]


# (model, the inertia typed; what the refusal says it is, and what to write; the element it is written in): a
# shape's inertia about its edge on a body turning about another point
ATWOOD = """
coordinates: [s]
bodies:
  m1: {mass: m1, position: {y: s}}
  m2: {mass: m2, position: {y: "-s"}}
gravity: g
elements:
  string: {kind: pulley, ends: [{body: m1, pulls: up}, {body: m2, pulls: up}], mass: M, radius: R, inertia: INERTIA}
quantities:
  a: {acceleration: s}
"""
ABOUT_AN_EDGE_ELSEWHERE = [
    pytest.param(
        ON_AN_AXLE.replace("BODY", "rod").replace("DISTANCE", "L/4"),
        "m*L^2/3",
        "rod's moment of inertia L^2*m/3 is a rod's about its end (L^2*m/12 + m*(L/2)^2)",
        "Write L^2*m/12 (about the point it turns about, L^2*m/12 + m*(L/4)^2 = 7*L^2*m/48)",
        "axle",
        id="rod-a-quarter-from-its-end",
    ),
    pytest.param(
        ON_AN_AXLE.replace("BODY", "disk").replace("DISTANCE", "R/2"),
        "3*m*R^2/2",
        "disk's moment of inertia 3*R^2*m/2 is a uniform disk's about a point on its rim (R^2*m/2 + R^2*m)",
        "Write R^2*m/2 (about the point it turns about, R^2*m/2 + m*(R/2)^2 = 3*R^2*m/4)",
        "axle",
        id="disk-halfway-to-its-rim",
    ),
    pytest.param(
        ATWOOD,
        "3*M*R^2/2",
        "a uniform disk's about a point on its rim (M*R^2/2 + M*R^2), but it turns about its centre",
        "Write M*R^2/2;",
        "string",
        id="pulley-on-its-axle",
    ),
]


def _model(text: str, inertia: str) -> object:
    symbols = {name: sympy.Symbol(name, positive=True) for name in NAMES.split()}
    return load_model(yaml.safe_load(text.replace("INERTIA", f'"{inertia}"')), symbols)


@pytest.mark.parametrize(("text", "inertia", "name", "expected"), RIGHT)
def test_an_inertia_about_the_centre_derives(
    text: str, inertia: str, name: str, expected: sympy.Expr
) -> None:
    found = uncached(_model(text, inertia)).quantities[name]
    assert sympy.simplify(found - expected) == 0


@pytest.mark.parametrize(("text", "inertia", "path", "about_centre"), ABOUT_THE_PIVOT)
def test_an_inertia_typed_about_the_point_the_body_turns_about_is_refused_where_written(
    text: str, inertia: str, path: tuple[str, ...], about_centre: str
) -> None:
    with pytest.raises(DerivationError) as caught:
        uncached(_model(text, inertia))
    assert caught.value.path == path
    assert "is its inertia about the point it turns about" in caught.value.message
    assert f"about its centre it is {about_centre}" in caught.value.message


@pytest.mark.parametrize(("inertia", "about_centre"), SKIDDING_ABOUT_THE_CONTACT)
def test_an_inertia_typed_about_a_skidding_bodys_contact_point_is_refused_where_written(
    inertia: str, about_centre: str
) -> None:
    with pytest.raises(DerivationError) as caught:
        uncached(_model(SKIDDING, inertia))
    assert caught.value.path == ("elements", "ball", "inertia")
    assert "is its inertia about its contact point" in caught.value.message
    assert f"about its centre it is {about_centre}" in caught.value.message


@pytest.mark.parametrize(("text", "inertia", "what", "fix", "element"), ABOUT_AN_EDGE_ELSEWHERE)
def test_a_shapes_inertia_about_its_edge_on_a_body_turning_about_another_point_is_refused_where_written(
    text: str, inertia: str, what: str, fix: str, element: str
) -> None:
    with pytest.raises(DerivationError) as caught:
        check_pivot_inertias(_model(text, inertia))
    assert caught.value.path == ("elements", element, "inertia")
    assert what in caught.value.message
    assert fix in caught.value.message


def test_a_shapes_inertia_about_its_centre_on_a_body_turning_about_another_point_is_left_alone() -> None:
    check_pivot_inertias(_model(ON_AN_AXLE.replace("BODY", "rod").replace("DISTANCE", "L/4"), "m*L^2/12"))
