"""A model with a body on z is drawn from the side (the x–y plane, z out of the page) where its bodies
are in the page as drawn: a conical pendulum at phi = 0, with its string, angle and circle. Anything
else with z is drawn as its bodies side by side, and a force the side view would cut is not drawn."""

from __future__ import annotations

import copy
import math
import re

import pytest
import sympy

from physics.engine import load_model
from physics.figures import free_body_figure, model_figure
from physics.figures.figure import Values
from physics.figures.loads import applied_forces, potential_forces
from physics.figures.scene import compose
from tests.engine.test_depth import CONE, CONE_SYMBOLS, LIFT, PUCK, SPRING_SYMBOLS, SPRUNG_BOB, SYMBOLS

VALUES = {"m1": 0.5, "L": 1.2, "alpha": 0.6, "A": 2.0, "g": 9.81}
# from the pivot at the origin down to the bob at +x (SVG's y points down)
STRING = re.compile(r'<line x1="0\.000" y1="-?0\.000" x2="[1-9][\d.]*" y2="[1-9][\d.]*" stroke="#1b1b1b"')
ARROW = re.compile(r'<line [^>]*stroke="#a11111"')
TURNING = re.compile(r'<path d="M [\d.-]+ [\d.-]+ A 0\.500 0\.500 [^>]*/><polygon points=')


@pytest.mark.parametrize(
    ("model", "support"),
    [(CONE, "a fixed point"), (LIFT, "the ceiling of a lift that accelerates upwards at A (the arrow)")],
    ids=["cone", "cone-in-a-lift"],
)
def test_a_conical_pendulum_on_z_is_drawn_from_the_side_with_its_string_angle_and_circle(
    model: dict[str, object], support: str
) -> None:
    svg = model_figure(load_model(model, CONE_SYMBOLS), VALUES, title="Cone")
    assert STRING.search(svg), "the string from the pivot to the bob, drawn aside to +x at phi = 0"
    assert ">α</text>" in svg and "stroke-dasharray" in svg and "<polyline" in svg  # the angle, the circle
    assert f"hangs from {support} on a string of length L" in svg
    assert "the string at the angle α from the vertical" in svg and "bodies of the problem" not in svg


@pytest.mark.parametrize("model", [CONE, LIFT], ids=["cone", "cone-in-a-lift"])
def test_the_bob_of_a_conical_pendulum_shows_its_weight_and_the_tension_towards_the_pivot(
    model: dict[str, object],
) -> None:
    svg = free_body_figure(load_model(model, CONE_SYMBOLS), "bob", VALUES, title="Cone")
    # the string at alpha = 0.6 rad (34°) from the vertical, the bob at +x: T at 90° + 34°
    assert "m₁g at -90° from the +x axis; T at 124° from the +x axis." in svg
    assert len(ARROW.findall(svg)) == 2


def test_a_model_on_z_off_the_page_at_its_state_is_drawn_as_its_bodies_side_by_side() -> None:
    turned = copy.deepcopy(CONE)
    turned["state"]["phi"] = "pi/2"  # the bob straight out of the page: a side view would misplace it
    model = load_model(turned, CONE_SYMBOLS)
    figure = compose(model, VALUES)
    assert figure.fallback is not None and "off the page" in figure.fallback
    assert "not drawn, as where the problem is drawn m₁ is off the page" in free_body_figure(
        model, "bob", VALUES, title="Cone"
    )


def test_a_puck_through_a_hole_is_drawn_side_by_side_and_its_forces_in_the_page() -> None:
    model = load_model(PUCK, SYMBOLS)
    figure = compose(model, {})
    assert figure.fallback is not None and "only a conical pendulum" in figure.fallback
    puck = free_body_figure(model, "puck", {}, title="Puck")
    weight = free_body_figure(model, "weight", {}, title="Puck")
    # at phi = 0 the puck is in the page and the string pulls it along -x, to the hole
    assert "m₁g at -90° from the +x axis; T at 180° from the +x axis; N at 90° from the +x axis" in puck
    assert "m₂g at -90° from the +x axis" in weight and "T at 90° from the +x axis" in weight


@pytest.mark.parametrize(
    ("wind", "drawn"), [({"x": "F"}, True), ({"z": "F"}, False)], ids=["in-the-page", "along-z"]
)
def test_a_given_force_on_the_bob_is_drawn_only_where_it_lies_in_the_page(
    wind: dict[str, str], drawn: bool
) -> None:
    windy = copy.deepcopy(CONE)
    windy["forces"] = [{"body": "bob", "force": wind}]
    symbols = {**CONE_SYMBOLS, "F": sympy.Symbol("F", positive=True)}
    svg = free_body_figure(load_model(windy, symbols), "bob", {**VALUES, "F": 2.0}, title="Cone")
    assert ("not drawn" not in svg) is drawn
    assert len(ARROW.findall(svg)) == (3 if drawn else 0)


@pytest.mark.parametrize("model", [CONE, LIFT], ids=["cone", "cone-in-a-lift"])
def test_the_sign_of_the_bob_going_round_has_a_head_saying_which_way(model: dict[str, object]) -> None:
    svg = model_figure(load_model(model, CONE_SYMBOLS), VALUES, title="Cone")
    # an arc alone, below the circle, reads as a stray mark; its head makes it the sign of a rotation
    assert TURNING.search(svg), "the arc under the axis, followed by its arrowhead"


@pytest.mark.parametrize(
    ("state", "drawn"),
    [({"X": 0, "Y": "-L0 - m1*g/k", "Z": 0}, True), ({"X": "a", "Y": "-h", "Z": "b"}, False)],
    ids=["hanging-in-the-page", "pulled-across-the-page"],
)
def test_a_springs_pull_on_a_bob_on_z_is_drawn_only_where_it_lies_in_the_page(
    state: dict[str, object], drawn: bool
) -> None:
    """The spring's pull is taken in the x–y plane: drawn where the spring lies in the page (the bob
    hanging under the anchor), never cut to its x–y part (the bob at z = b pulled back along z)."""
    hung = {**SPRUNG_BOB, "state": state}
    svg = free_body_figure(
        load_model(hung, SPRING_SYMBOLS), "bob", {**VALUES, "k": 20.0, "L0": 0.5}, title="Bob"
    )
    assert ("m₁g at -90° from the +x axis; Fₖ at 90° from the +x axis." in svg) is drawn
    assert ("not drawn" in svg) is not drawn


@pytest.mark.parametrize(
    ("state", "direction"),
    [({"X": 0, "Y": "-L0 - m1*g/k", "Z": 0}, (0.0, 1.0)), ({"X": "a", "Y": "-h", "Z": "b"}, None)],
    ids=["hanging-in-the-page", "pulled-across-the-page"],
)
def test_a_springs_force_with_a_part_along_z_has_no_direction_in_the_page(
    state: dict[str, object], direction: tuple[float, float] | None
) -> None:
    """Whoever asks for it, a pull along z is refused, never cut to its x–y part (a wrong arrow)."""
    model = load_model({**SPRUNG_BOB, "state": state}, SPRING_SYMBOLS)
    values = Values(model, {**VALUES, "k": 20.0, "L0": 0.5, "a": 0.3, "b": 0.4, "h": 1.0})
    if direction is not None:
        assert potential_forces(model, "bob", values) == [("Fₖ", direction)]
        return
    with pytest.raises(ValueError, match="part along z"):
        potential_forces(model, "bob", values)


@pytest.mark.parametrize(
    ("forces", "state", "expected"),
    [
        ([{"body": "bob", "force": {"x": "F"}}], {}, [("F", (1.0, 0.0))]),
        ([{"body": "bob", "force": {"x": "F", "z": "F"}}], {}, None),
        # swinging in the page at theta = alpha = 0.6: the drag against it, along the arc
        ([{"body": "bob", "drag": "b"}], {"theta_dot": "1"}, [("bv", (-math.cos(0.6), -math.sin(0.6)))]),
        ([{"body": "bob", "drag": "b"}], {"phi_dot": "1"}, None),
    ],
    ids=["given-in-the-page", "given-along-z", "drag-swinging-in-the-page", "drag-going-round"],
)
def test_a_given_force_or_drag_with_a_part_along_z_has_no_direction_in_the_page(
    forces: list[dict[str, object]],
    state: dict[str, str],
    expected: list[tuple[str, tuple[float, float]]] | None,
) -> None:
    """As a spring's pull: refused, never cut to its x–y part (the bob going round at phi = 0 moves
    along z, and its drag is along -z)."""
    data = {**CONE, "forces": forces, "state": {**CONE["state"], **state}}
    symbols = {**CONE_SYMBOLS, "F": sympy.Symbol("F", positive=True), "b": sympy.Symbol("b", positive=True)}
    model = load_model(data, symbols)
    values = Values(model, {**VALUES, "F": 2.0, "b": 0.3})
    if expected is not None:
        found = applied_forces(model, "bob", values)
        assert [(label, pytest.approx(direction)) for label, direction in found] == expected
        return
    with pytest.raises(ValueError, match="part along z"):
        applied_forces(model, "bob", values)
