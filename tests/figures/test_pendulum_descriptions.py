"""A screen-reader user hears what each pendulum-like bank problem shows: the body that swings called
what the problem calls it (a bob or a ball on a string, not a block), and how it moves."""

from __future__ import annotations

import re

import pytest

from tests.figures.test_figures import SVG, figure_of

# problem id -> (what its description must say, words it must not use)
DESCRIPTIONS = {
    "simple-pendulum": ("A bob m hangs from a fixed point on a string of length L.", ("block",)),
    "conical-pendulum": (
        "A bob m hangs from a fixed point on a string of length L and goes round a horizontal circle "
        "(dashed) at the rate ω, the string sweeping out a cone about the vertical (dashed) through that point.",
        ("block",),
    ),
    "vertical-circle": (
        "A ball m on a string of length L is whirled in a vertical circle (dashed) about the string's fixed "
        "end; it is drawn at the top.",
        ("block", "hangs"),
    ),
    "pendulum-on-cart": (
        "A cart M rolls on a horizontal floor; a bob m hangs from it on a rod of length L.",
        ("block", "string"),
    ),
    "ballistic-pendulum": ("A block M hangs from a fixed point on a string of length L; a bullet m", ()),
    "rod-bullet": (
        "A rigid body M swings about a fixed pivot at its end; a bullet m flies into it horizontally where "
        "it hangs (dashed), and sticks.",
        ("block",),
    ),
    "double-pendulum": ("A hangs from a fixed pivot", ("block", "bob1", "p₁")),
}


@pytest.mark.parametrize(("problem_id", "said", "unsaid"), [(k, *v) for k, v in DESCRIPTIONS.items()])
def test_pendulum_description_names_the_body_and_its_motion(
    problem_id: str, said: str, unsaid: tuple[str, ...]
) -> None:
    description = figure_of(problem_id).findtext(f"{SVG}desc", "")
    assert said in description
    for word in unsaid:
        assert not re.search(rf"\b{word}\b", description), (word, description)


def test_double_pendulum_describes_both_bobs() -> None:
    description = figure_of("double-pendulum").findtext(f"{SVG}desc", "")
    # by the letters its notation gives the bobs and the angles, never the model's names bob1 and p1
    assert "A hangs from a fixed pivot" in description and "at the angle φ₁" in description
    assert "B hangs from A" in description and "at the angle φ₂" in description


@pytest.mark.parametrize(
    ("problem_id", "shape"), [("simple-pendulum", "circle"), ("ballistic-pendulum", "polygon")]
)
def test_a_bob_is_drawn_round_and_a_block_square(problem_id: str, shape: str) -> None:
    root = figure_of(problem_id)
    filled = [
        e for e in root.iter() if e.tag in {f"{SVG}circle", f"{SVG}polygon"} and e.get("fill") != "none"
    ]
    assert filled[0].tag == f"{SVG}{shape}", [e.tag for e in filled]
