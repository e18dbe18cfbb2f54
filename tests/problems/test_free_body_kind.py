"""Free-body parts, tried as students would: the model's forces drawn in any order, written any way the
page or a student writes them, each within the tolerance, are accepted; a force missing, one extra (the
"force of motion"), one pointing the wrong way are refused, each said. Ad hoc (`POST /v1/check`) and on
the bank's moving wedge, whose model puts the forces on the block and on the wedge."""

from __future__ import annotations

from functools import cache

import pytest
import yaml
from latex2mathml.converter import convert
from pydantic import TypeAdapter

from physics.checking import run_job
from physics.verdict import Outcome, Verdict
from problems.compiled import build_problem, compile_problem
from problems.errors import ProblemInvalid
from problems.kinds import CheckIn
from problems.loader import parse_problem
from problems.variants import draw_variant
from tests.bank import bank_documents

SCENES = {
    # a block sliding down a rough incline of 30°
    "incline": [
        {"kind": "weight", "angle": 270},
        {"kind": "normal", "angle": 60},
        {"kind": "friction", "angle": 30},
    ],
    # a mass hanging from a string
    "hanging": [{"kind": "weight", "angle": 270}, {"kind": "tension", "angle": 90}],
    # a wedge under a block, on a floor (the block's normal force pushes it down and back)
    "wedge": [
        {"kind": "weight", "angle": 270},
        {"kind": "normal", "angle": 90},
        {"kind": "normal", "angle": 240},
    ],
    # a block on a spring on a 30° incline, no friction
    "spring": [
        {"kind": "weight", "angle": 270},
        {"kind": "normal", "angle": 60},
        {"kind": "spring", "angle": 30},
    ],
}


def check(scene: str, answer: str) -> Verdict:
    body = {"kind": "free_body", "answer": answer, "expected": SCENES[scene], "body": "the block"}
    return run_job(TypeAdapter(CheckIn).validate_python(body).job())


RIGHT = [
    ("incline", "weight 270; normal 60; friction 30"),
    ("incline", "normal 60; friction 30; weight 270"),
    ("incline", "weight@270, normal@60, friction@30"),
    ("incline", "weight 270\nnormal 60\nfriction 30"),
    ("incline", "gravity 270; N 60; f 30"),
    ("incline", "mg 270; normal 60; friction 30"),
    ("incline", "weight -90; normal 60; friction 30"),
    ("incline", "weight 270°; normal 60°; friction 30°"),
    ("incline", "weight 270 deg; normal 60 deg; friction 30 deg"),
    ("incline", "weight 265; normal 65; friction 25"),
    ("incline", "weight 278; normal 52; friction 38"),
    ("incline", "Weight 270; Normal 60; Friction 30"),
    ("incline", "weight 630; normal 420; friction 390"),
    ("incline", "weight 270.5; normal 59.5; friction 30.2"),
    ("incline", " weight 270 ;  normal 60 ; friction 30 "),
    ("hanging", "weight 270; tension 90"),
    ("hanging", "tension 90; weight 270"),
    ("hanging", "T 90; W 270"),
    ("hanging", "weight 275; tension 85"),
    ("hanging", "tension 450; weight -90"),
    ("hanging", "weight@270;tension@90"),
    ("wedge", "weight 270; normal 90; normal 240"),
    ("wedge", "normal 240; normal 90; weight 270"),
    ("wedge", "weight 270; normal 95; normal 235"),
    ("wedge", "N 90, N 240, mg 270"),
    ("wedge", "weight 270; normal -120; normal 90"),
    ("spring", "weight 270; normal 60; spring 30"),
    ("spring", "spring 30; normal 60; weight 270"),
    ("spring", "weight 270; normal 64; spring 26"),
    ("spring", "weight 270, normal 60, spring 30"),
]

WRONG = [
    ("incline", "weight 270; normal 60", "friction force is missing"),
    ("incline", "weight 270; friction 30", "normal force is missing"),
    ("incline", "normal 60; friction 30", "weight is missing"),
    ("incline", "weight 270; normal 60; friction 210", "points the wrong way"),
    ("incline", "weight 270; normal 240; friction 30", "perpendicular"),
    ("incline", "weight 270; normal 90; friction 30", "perpendicular"),
    ("incline", "weight 90; normal 60; friction 30", "straight down"),
    ("incline", "weight 270; normal 60; friction 30; motion 210", "force of motion"),
    ("incline", "weight 270; normal 60; friction 30; applied 210", "no applied force"),
    ("incline", "weight 270; normal 60; friction 30; normal 60", "no normal force"),
    ("incline", "weight 270; normal 60; friction 45", "wrong way"),
    ("incline", "weight 270; normal 75; friction 30", "wrong way"),
    ("incline", "weight 270; normal 60; tension 30", None),
    ("incline", "weight 270; normal 60; friction 30; tension 90", "no tension"),
    ("incline", "weight 250; normal 60; friction 30", "straight down"),
    ("hanging", "weight 270", "tension is missing"),
    ("hanging", "tension 90", "weight is missing"),
    ("hanging", "weight 270; tension 270", "wrong way"),
    ("hanging", "weight 270; tension 90; motion 270", "force of motion"),
    ("hanging", "weight 270; tension 90; normal 90", "no normal force"),
    ("hanging", "weight 270; tension 120", "wrong way"),
    ("hanging", "weight 270; normal 90", None),
    ("wedge", "weight 270; normal 90", "missing"),
    ("wedge", "weight 270; normal 90; normal 60", "wrong way"),
    ("wedge", "weight 270; normal 240", "missing"),
    ("wedge", "weight 270; normal 90; normal 240; motion 180", "force of motion"),
    ("wedge", "weight 270; normal 90; normal 240; friction 0", "no friction"),
    ("spring", "weight 270; normal 60", "spring force is missing"),
    ("spring", "weight 270; normal 60; spring 210", "wrong way"),
    ("spring", "weight 270; normal 60; spring 30; friction 30", "no friction"),
    ("spring", "weight 270; normal 60; applied 30", None),
]


def test_each_table_has_thirty_right_and_thirty_wrong_diagrams() -> None:
    assert len(RIGHT) >= 30 and len(WRONG) >= 30


@pytest.mark.parametrize(("scene", "answer"), RIGHT)
def test_the_models_forces_drawn_any_way_are_accepted(scene: str, answer: str) -> None:
    verdict = check(scene, answer)
    assert verdict.outcome is Outcome.CORRECT, verdict


@pytest.mark.parametrize(("scene", "answer", "said"), WRONG)
def test_a_wrong_diagram_is_refused_force_by_force(scene: str, answer: str, said: str | None) -> None:
    verdict = check(scene, answer)
    assert verdict.outcome is Outcome.INCORRECT, verdict
    if said is not None:
        assert said in verdict.feedback, verdict.feedback


@pytest.mark.parametrize("answer", ["", "weight", "weight up", "wieght 270", "weight 270; ; 1+1 90"])
def test_what_is_not_a_list_of_forces_is_invalid(answer: str) -> None:
    assert check("hanging", answer).outcome is Outcome.INVALID


@cache
def _wedge():
    doc = bank_documents()["moving-wedge-lagrangian"]
    return doc, compile_problem(doc)


def test_the_bank_block_gets_the_normal_force_perpendicular_to_its_own_incline() -> None:
    doc, compiled = _wedge()
    variant = draw_variant(doc, 1, "alice", "secret")
    theta = float(variant.values["theta"])
    part = compiled.part("forces_on_block")
    right = run_job(part.job(f"weight 270; normal {90 - theta:g}", variant))
    assert right.outcome is Outcome.CORRECT, right
    upright = run_job(part.job("weight 270; normal 90", variant))
    assert upright.outcome is Outcome.INCORRECT and "perpendicular" in upright.feedback
    wedge = run_job(
        compiled.part("forces_on_wedge").job(f"weight 270; normal 90; normal {270 - theta:g}", variant)
    )
    assert wedge.outcome is Outcome.CORRECT, wedge


def test_the_reading_typesets_each_angle_in_degrees():
    verdict = check("incline", "weight 270; normal 60.5")
    assert verdict.read_as is not None
    assert verdict.read_as.text == "weight 270°; normal 60.5°"
    mathml = convert(verdict.read_as.latex)
    assert "^" not in mathml  # inside \text{} a superscript was printed as the characters ^\circ
    assert mathml.count("&#x02218;") == 2  # a ring operator (the degree) above each angle


IN_AND_ACROSS_THE_PAGE = [
    pytest.param("weight", {}, "weight 270; tension 90", None, id="a-body-in-the-plane"),
    # at phi = 0 the puck is in the page, the string pulling it along -x, to the hole
    pytest.param(
        "puck", {}, "weight 270; tension 180; normal 90", None, id="a-body-on-z-whose-forces-lie-in-the-page"
    ),
    pytest.param("puck", {"state": {"r": "R", "phi": "pi/2"}}, None, "it is off the page", id="off-the-page"),
    pytest.param(
        "puck",
        {"forces": [{"body": "puck", "force": {"z": "mu*m1*g"}}]},
        None,
        "a given force on it has a part along z",
        id="a-force-across-the-page",
    ),
]


@pytest.mark.parametrize(("body", "change", "drawn", "reason"), IN_AND_ACROSS_THE_PAGE)
def test_free_body_part_on_a_body_on_z_is_refused_where_a_force_crosses_the_page(
    body: str, change: dict[str, object], drawn: str | None, reason: str | None
) -> None:
    """The diagram is drawn in the x–y plane: a force along z would be graded without its z part, so
    it is refused saying which; a body on z whose forces all lie in the page is drawn and graded."""
    from tests.engine.test_depth import PUCK

    model = {**PUCK, "unused": ["speed", "tension"], **change}
    symbols = {name: {"meaning": name, "dimension": unit} for name, unit in _PUCK_UNITS.items()}
    part = {"id": "forces", "kind": "free_body", "prompt": "Draw the forces.", "body": body}
    document = {"id": "puck-z", "title": "Puck", "statement": "A puck.", "symbols": symbols}
    doc = parse_problem(yaml.safe_dump({**document, "parts": [part], "model": model}), "yaml")
    if drawn is not None:
        assert build_problem(doc, 1, use_model=False).part("forces").solution().text == drawn
        return
    with pytest.raises(ProblemInvalid, match=rf"parts\[0\]\.body: .*'puck' moves along z: {reason}"):
        build_problem(doc, 1, use_model=False)


_PUCK_UNITS = {"m1": "kg", "m2": "kg", "g": "m/s^2", "R": "m", "l": "m", "mu": "1", "k": "N/m", "v": "m/s"}
