"""Every bank problem gets a figure from its model: well-formed SVG, named and described for screen
readers, with the problem's symbols on it and nothing outside its drawing."""

from __future__ import annotations

import xml.etree.ElementTree as ET

import pytest

from physics.figures import model_figure, symbol_label
from problems.modelinfo import load_doc_model
from problems.symbols import symbol_table
from problems.variants import draw_variant, si_values
from tests.bank import bank_documents

SVG = "{http://www.w3.org/2000/svg}"
BANK = bank_documents()
# What each figure must show: labels of bodies, angles and lengths, and words of its description.
EXPECTED = {
    "atwood": ({"m₁", "m₂"}, "pulley"),
    "atwood-slack": ({"m₁", "m₂"}, "The string goes slack"),
    "ballistic-pendulum": ({"M", "m", "θ", "L"}, "bullet"),
    "rod-bullet": ({"M", "m"}, "a bullet m flies into it"),
    "ball-hits-rod": ({"M", "m", "u"}, "drawn as a rod"),
    "incline-pulley": ({"m₁", "m₂", "θ"}, "pulley"),
    "lennard-jones": ({"m", "r"}, "apart"),
    "mass-spring": ({"m", "k"}, "spring"),
    "moving-wedge": ({"m", "M", "θ"}, "wedge"),
    "rolling-incline": ({"cylinder", "hoop", "sphere", "θ"}, "incline"),
    "skier-friction": ({"m", "α", "μ"}, "friction"),
    "spring-incline": ({"m", "k", "θ"}, "spring"),
    "table-two-pulleys": ({"M", "m₁", "m₂", "μ"}, "edge"),
    "double-atwood": ({"m₁", "m₂", "m₃"}, "light pulley"),
    "pendulum-on-cart": ({"M", "m", "L"}, "cart"),
    "bead-rotating-hoop": ({"m", "ω"}, "axis"),
    "orbit-effective-potential": ({"m", "M", "r"}, "centre"),
    "double-incline": ({"m₁", "m₂", "α", "β"}, "pulley"),
    "yo-yo": ({"m", "r"}, "axle"),
    "cart-collision": ({"m₁", "m₂", "u₁", "u₂"}, "collision"),
    "collision-scenarios": ({"m₁", "m₂", "u"}, "collision"),
    "conical-pendulum-rate": ({"m", "L"}, "sweeping out a cone"),
    "glancing-pucks": ({"m", "u", "φ"}, "elastic collision"),
    "bouncing-ball": ({"m"}, "the fixed floor about to meet in a collision: m moving down"),
    "banked-curve": (
        {"m", "θ", "R"},
        "goes round a curve about the vertical axis drawn dashed, a distance R",
    ),
    "cart-hits-block-on-incline": ({"m₁", "m₂", "u"}, "elastic collision"),
    "projectile": ({"m", "v₀", "α"}, "launched from the ground"),
    "ladder-slipping": ({"m", "L", "θ"}, "leans against a vertical wall"),
    "quarter-circle-slide": ({"m", "R"}, "quarter-circle track of radius R, with m at its top"),
    "damped-oscillator": ({"m", "k", "b"}, "a spring k and, beside it, a dashpot b"),
    "incline-push-friction": ({"m", "θ", "μ", "F"}, "F pushes m"),
    "pushed-blocks": ({"m₁", "m₂", "μ", "F"}, "F pushes m₁"),
    "double-pendulum": (
        {"A", "B", "m", "L", "φ₁", "φ₂"},  # the letters its notation gives, not bob1 and p1
        "B hangs from A on a light rod of length L",
    ),
    "falling-drag": ({"pebble", "ball", "m", "bv", "cv²", "v"}, "pebble moving down at v, with drag bv"),
    "movable-pulley": ({"m₁", "m₂"}, "under a light movable pulley carrying m₂"),
    "spring-drop": ({"m", "k", "h"}, "falls from rest from a height h onto a vertical spring k"),
    "pendulum-in-truck": ({"m", "L", "A"}, "A truck accelerates at A"),
}


def figure_of(problem_id: str, student: str = "ada") -> ET.Element:
    doc = BANK[problem_id]
    table = symbol_table(doc)
    values = si_values(doc, draw_variant(doc, 1, student, "secret"), table)
    svg = model_figure(
        load_doc_model(doc, table), {s.name: float(v) for s, v in values.items()}, title=doc.title
    )
    return ET.fromstring(svg)


@pytest.mark.parametrize("problem_id", sorted(BANK))
def test_every_bank_problem_gets_a_described_figure(problem_id: str) -> None:
    """A problem added to the bank: look at its figure, then add what it must show to EXPECTED."""
    root = figure_of(problem_id)
    assert root.findtext(f"{SVG}desc", "").strip()
    assert len(list(root.iter(f"{SVG}text"))) >= 1


@pytest.mark.parametrize("problem_id", sorted(EXPECTED))
def test_figure_shows_the_problems_symbols_and_says_what_it_draws(problem_id: str) -> None:
    root = figure_of(problem_id)
    labels, word = EXPECTED[problem_id]
    texts = {element.text for element in root.iter(f"{SVG}text")}
    assert labels <= texts, f"missing labels {labels - texts}"
    assert root.get("role") == "img"
    assert root.find(f"{SVG}title") is not None and BANK[problem_id].title in root.findtext(f"{SVG}title", "")
    assert word in root.findtext(f"{SVG}desc", "")
    assert not [e for e in root.iter() if e.get("style") is not None]  # a strict CSP would drop them


@pytest.mark.parametrize("problem_id", sorted(BANK))
def test_every_shape_lies_inside_the_view_box(problem_id: str) -> None:
    root = figure_of(problem_id)
    left, top, width, height = (float(v) for v in root.get("viewBox", "").split())
    for element in root.iter():
        for x_name, y_name in (("x1", "y1"), ("x2", "y2"), ("cx", "cy"), ("x", "y")):
            if element.get(x_name) is not None:
                x, y = float(element.get(x_name, 0)), float(element.get(y_name, 0))
                assert left <= x <= left + width and top <= y <= top + height, (element.tag, x, y)


@pytest.mark.parametrize(
    ("name", "label"),
    [("theta", "θ"), ("m1", "m₁"), ("U0", "U₀"), ("v_0", "v₀"), ("Omega", "Ω"), ("sigma", "σ")],
)
def test_symbols_are_labelled_as_the_statement_typesets_them(name: str, label: str) -> None:
    assert symbol_label(name) == label


def test_a_turning_curve_is_said_after_the_body_on_it_so_the_sentence_names_what_turns() -> None:
    sentences = figure_of("bead-rotating-hoop").findtext(f"{SVG}desc", "").split(". ")
    turning = [i for i, sentence in enumerate(sentences) if "turns about the vertical axis" in sentence]
    moving = [i for i, sentence in enumerate(sentences) if "moves along the curve" in sentence]
    assert turning and moving and moving[0] < turning[0]
    assert not sentences[turning[0]].startswith("It ")
