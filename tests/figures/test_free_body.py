"""Free-body diagrams from models: the forces on a body point the way the physics says."""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET

import pytest

from physics.engine import Model, load_model
from physics.figures import body_forces, free_body_figure
from problems.modelinfo import load_doc_model
from problems.symbols import symbol_table
from tests.bank import bank_documents
from tests.engine.test_contact_friction import SYMBOLS as CART_SYMBOLS
from tests.engine.test_contact_friction import block_on_cart

BANK = bank_documents()
THIRTY = math.radians(30)


def forces(
    problem_id: str, body: str, values: dict[str, float] | None = None
) -> dict[str, tuple[float, float]]:
    doc = BANK[problem_id]
    model = load_doc_model(doc, symbol_table(doc))
    return {f.label: f.direction for f in body_forces(model, body, values or {})}


def close(a: tuple[float, float], b: tuple[float, float]) -> bool:
    return math.isclose(a[0], b[0], abs_tol=1e-9) and math.isclose(a[1], b[1], abs_tol=1e-9)


def test_cart_on_an_incline_feels_its_weight_the_normal_force_and_the_tension_up_the_slope() -> None:
    found = forces("incline-pulley", "m1", {"theta": THIRTY})
    assert set(found) == {"m₁g", "N", "T"}
    assert close(found["m₁g"], (0.0, -1.0))
    assert close(found["N"], (-math.sin(THIRTY), math.cos(THIRTY)))  # out of the slope
    assert close(found["T"], (math.cos(THIRTY), math.sin(THIRTY)))  # up the slope, along the string


def test_friction_opposes_the_sliding_down_the_slope() -> None:
    found = forces("skier-friction", "skier", {"alpha": THIRTY})
    assert close(found["f"], (-math.cos(THIRTY), math.sin(THIRTY)))


def test_the_wedge_feels_the_block_pushing_into_it_and_the_floor_pushing_up() -> None:
    found = forces("moving-wedge", "wedge", {"theta": THIRTY})
    normals = [direction for label, direction in found.items() if label.startswith("N")]
    assert any(close(d, (0.0, 1.0)) for d in normals)
    assert any(close(d, (-math.sin(THIRTY), -math.cos(THIRTY))) for d in normals)


def test_a_bob_hung_from_an_accelerating_truck_feels_the_tension_along_its_string_as_drawn() -> None:
    """The pivot moves in the time t: the string's pull is taken where the scene draws it, at t = 0."""
    found = forces("pendulum-in-truck", "bob", {"A": 2.0, "g": 9.81})
    assert set(found) == {"mg", "T"}
    tilt = math.atan(2.0 / 9.81)  # the bob hangs back, against the acceleration: T leans forward
    assert close(found["T"], (math.sin(tilt), math.cos(tilt)))


@pytest.mark.parametrize("problem_id", sorted(BANK))
def test_every_body_of_every_bank_problem_gets_a_free_body_diagram(problem_id: str) -> None:
    doc = BANK[problem_id]
    model = load_doc_model(doc, symbol_table(doc))
    for body in model.bodies:
        root = ET.fromstring(free_body_figure(model, body.name, {}, title=doc.title))
        assert root.get("role") == "img"
        assert "Forces on" in root.findtext("{http://www.w3.org/2000/svg}desc", "")


SVG = "{http://www.w3.org/2000/svg}"


def diagram_labels(model: Model, body: str) -> dict[str, tuple[float, float]]:
    """The force labels drawn in one body's SVG diagram, with the directions body_forces gives them."""
    root = ET.fromstring(free_body_figure(model, body, {}, title="t"))
    drawn = {text.text for text in root.iter(f"{SVG}text")}
    directions = {f.label: f.direction for f in body_forces(model, body, {})}
    assert set(directions) <= drawn  # every force is labelled in the picture
    assert len(directions) == len(body_forces(model, body, {}))  # and no label repeats within it
    return directions


def opposite(a: tuple[float, float], b: tuple[float, float]) -> bool:
    return close(a, (-b[0], -b[1]))


def bank_model(problem_id: str) -> Model:
    doc = BANK[problem_id]
    return load_doc_model(doc, symbol_table(doc))


@pytest.mark.parametrize(
    ("problem_id", "first", "second"),
    [
        pytest.param("moving-wedge", "block", "wedge", id="block-pushes-the-wedge"),
        pytest.param("blocks-in-contact", "lower", "upper", id="blocks-push-each-other"),
        pytest.param("pushed-blocks", "block1", "block2", id="pushed-blocks"),
        pytest.param("double-pendulum", "bob2", "bob1", id="lower-string-pulls-both-bobs"),
    ],
)
def test_a_contact_between_two_bodies_has_one_label_in_both_diagrams(
    problem_id: str, first: str, second: str
) -> None:
    model = bank_model(problem_id)
    one, other = diagram_labels(model, first), diagram_labels(model, second)
    shared = [label for label in one if label in other and not label.endswith("g")]
    assert shared, (one, other)
    for label in shared:  # action and reaction: the same label, opposite directions
        assert opposite(one[label], other[label]), (label, one, other)


@pytest.mark.parametrize(
    ("problem_id", "bodies", "kind"),
    [
        pytest.param("double-incline", ("m1", "m2"), "N", id="two-slopes"),
        pytest.param("atwood-massive-pulley", ("m1", "m2"), "T", id="two-strings"),
        pytest.param("rolling-incline", ("cylinder", "hoop", "sphere", "point"), "N", id="four-racers"),
        pytest.param("rolling-incline", ("cylinder", "hoop", "sphere"), "f", id="three-grips"),
    ],
)
def test_separate_contacts_of_one_kind_get_separate_labels(
    problem_id: str, bodies: tuple[str, ...], kind: str
) -> None:
    model = bank_model(problem_id)
    contacts = [{label for label in diagram_labels(model, body) if label.startswith(kind)} for body in bodies]
    assert all(contacts), contacts
    for i, mine in enumerate(contacts):
        for theirs in contacts[i + 1 :]:
            assert not mine & theirs, contacts


def test_friction_against_a_moving_surface_is_drawn_on_both_bodies_with_one_label() -> None:
    model = load_model(block_on_cart(), CART_SYMBOLS)
    block, cart = diagram_labels(model, "block"), diagram_labels(model, "cart")
    friction = [label for label in block if label.startswith("f")]
    assert len(friction) == 1 and friction[0] in cart
    assert close(block[friction[0]], (-1.0, 0.0))  # the block slides forward on the cart
    assert opposite(block[friction[0]], cart[friction[0]])


def _drawn(problem_id: str, body: str) -> ET.Element:
    doc = BANK[problem_id]
    return ET.fromstring(free_body_figure(load_doc_model(doc, symbol_table(doc)), body, {}, title="t"))


def _texts(root: ET.Element) -> dict[str, tuple[float, float]]:
    ns = "{http://www.w3.org/2000/svg}"
    return {
        "".join(t.itertext()): (float(t.get("x", "0")), float(t.get("y", "0")))
        for t in root.iter(f"{ns}text")
    }


def _circles(root: ET.Element) -> int:
    return sum(1 for _ in root.iter("{http://www.w3.org/2000/svg}circle"))


def test_a_rolling_contacts_friction_acts_at_the_rim_not_on_an_axle() -> None:
    # a lone lever arm was drawn at half the radius, inside a circle that reads as an axle
    root = _drawn("rolling-cylinder-pulled", "cylinder")
    assert _circles(root) == 1
    assert "R" in _texts(root)


@pytest.mark.parametrize(
    ("problem_id", "body"), [("flywheel", "wheel"), ("atwood-massive-pulley", "stringWheel")]
)
def test_labels_of_close_parallel_forces_and_of_lever_arms_do_not_meet(problem_id: str, body: str) -> None:
    placed = list(_texts(_drawn(problem_id, body)).values())
    for i, (x1, y1) in enumerate(placed):
        for x2, y2 in placed[i + 1 :]:
            assert abs(x1 - x2) > 0.3 or abs(y1 - y2) > 0.3, placed


def _arrow_tails(root: ET.Element) -> list[tuple[tuple[float, float], tuple[float, float]]]:
    """Each force arrow's tail and unit direction, y up (the SVG's y points down)."""
    tails = []
    for line in root.iter(f"{SVG}line"):
        if line.get("stroke") != "#a11111":
            continue
        x1, y1, x2, y2 = (float(line.get(k, "0")) for k in ("x1", "y1", "x2", "y2"))
        length = math.hypot(x2 - x1, y2 - y1)
        tails.append(((x1, -y1), ((x2 - x1) / length, (y1 - y2) / length)))
    return tails


@pytest.mark.parametrize(
    ("problem_id", "body", "surface_forces"),
    [
        pytest.param("rolling-incline", "cylinder", ("N₁",), id="rolling-down-a-slope"),
        pytest.param("rolling-cylinder-pulled", "cylinder", ("N",), id="pulled-on-a-floor"),
        pytest.param("bowl-rolling", "ball", ("N", "f"), id="rolling-in-a-bowl"),
        pytest.param("bowling-ball-skid", "ball", ("N", "f"), id="skidding-kinetic-friction"),
    ],
)
def test_a_round_bodys_normal_force_and_friction_act_where_it_touches_the_surface(
    problem_id: str, body: str, surface_forces: tuple[str, ...]
) -> None:
    # N had been drawn from the top of a rolling body, as if pulled from above
    model = bank_model(problem_id)
    forces = {f.label: f for f in body_forces(model, body, {})}
    normal = forces[surface_forces[0]]
    assert normal.contact is not None and opposite(normal.contact, normal.direction)
    root = _drawn(problem_id, body)
    circle = next(root.iter(f"{SVG}circle"))
    centre, radius = (
        (float(circle.get("cx", "0")), -float(circle.get("cy", "0"))),
        float(circle.get("r", "0")),
    )
    touching = (centre[0] + normal.contact[0] * radius, centre[1] + normal.contact[1] * radius)
    tails = _arrow_tails(root)
    for label in surface_forces:
        direction = forces[label].direction
        tail = next(
            t
            for t, d in tails
            if math.isclose(d[0], direction[0], abs_tol=1e-2)
            and math.isclose(d[1], direction[1], abs_tol=1e-2)
        )
        assert math.dist(tail, touching) < 0.01, (label, tail, touching)
        assert f"{label} at " in root.findtext(f"{SVG}desc", "")
    assert "at the contact" in root.findtext(f"{SVG}desc", "")


def test_a_ladders_normal_forces_keep_their_lever_arms_not_its_rim() -> None:
    # a ladder's floor turns with it: its foot touches, not a rim; it is not moved to a contact point
    model = bank_model("ladder-slipping")
    assert all(force.contact is None for force in body_forces(model, "ladder", {}))
