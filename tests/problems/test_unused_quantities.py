"""A model quantity no part asks for is a fault unless listed under `unused:`; a part whose id nearly
names such a quantity (a misspelling on one side) is refused naming both, since it would otherwise be
graded against its typed answer while the derivation is silently ignored."""

from __future__ import annotations

import pytest

from problems.errors import ProblemInvalid
from problems.loader import parse_problem

ATWOOD = """
id: atwood-typo
title: Atwood machine
statement: Two masses $m_1$ and $m_2$ hang over a light pulley.
symbols:
  m1: {meaning: mass on the left, dimension: kg}
  m2: {meaning: mass on the right, dimension: kg}
  g: {meaning: acceleration due to gravity, dimension: m/s^2}
parts:
  - id: acceleration
    kind: symbolic
    prompt: Find the acceleration of $m_2$, positive downward.
    answer: (m2 - m1)*g/m2
model:
  coordinates: [s]
  bodies:
    m1: {mass: m1, position: {y: s}}
    m2: {mass: m2, position: {y: "-s"}}
  gravity: g
  elements:
    string: {kind: pulley, ends: [{body: m1, pulls: up}, {body: m2, pulls: up}]}
  quantities:
    QUANTITIES
"""


def _errors(quantities: str, extra: str = "") -> list[tuple[str, str]]:
    text = ATWOOD.replace("QUANTITIES", quantities) + extra
    with pytest.raises(ProblemInvalid) as caught:
        parse_problem(text)
    return caught.value.errors


def test_a_misspelled_quantity_beside_a_typed_part_is_refused_naming_both() -> None:
    errors = dict(_errors("acceleraton: {acceleration: s}"))
    assert "'acceleration'" in errors["parts[0].id"] and "'acceleraton'" in errors["parts[0].id"]
    assert "no part asks for the quantity 'acceleraton'" in errors["model.quantities.acceleraton"]


def test_a_near_miss_is_refused_even_when_the_quantity_is_listed_unused() -> None:
    errors = dict(_errors("acceleraton: {acceleration: s}", "  unused: [acceleraton]\n"))
    assert list(errors) == ["parts[0].id"]


def test_a_quantity_no_part_asks_for_is_refused_unless_listed_unused() -> None:
    quantities = "acceleration: {acceleration: s}\n    tension: {force: string}"
    errors = dict(_errors(quantities))
    assert list(errors) == ["model.quantities.tension"]
    listed = ATWOOD.replace("QUANTITIES", quantities) + "  unused: [tension]\n"
    assert parse_problem(listed.replace("answer: (m2 - m1)*g/m2", "answer: (m2 - m1)*g/(m1 + m2)"))


def test_an_unused_entry_must_name_a_quantity() -> None:
    errors = dict(_errors("acceleration: {acceleration: s}", "  unused: [tensoin]\n"))
    assert "unknown quantity 'tensoin'" in errors["model.unused[0]"]


def test_a_quantity_an_asked_expression_uses_is_asked() -> None:
    quantities = 'tension: {force: string}\n    acceleration: {expression: "(m2*g - tension)/m2"}'
    assert parse_problem(ATWOOD.replace("QUANTITIES", quantities).replace("    answer: (m2 - m1)*g/m2\n", ""))


EQUATION_PART = """
  - id: newton_m2
    kind: equation
    prompt: Write Newton's second law for $m_2$, positive downward.
    asks: Newton's second law for m2
    unknowns:
      a: {meaning: "the acceleration of $m_2$, downward", quantity: acceleration}
      T: {meaning: "the tension in the string", quantity: tension}
    equation: m2*a = m2*g - T
"""


def test_an_equation_part_asks_for_the_quantities_its_unknowns_take() -> None:
    """The tension is used by the equation part alone: no `unused:` is needed for it."""
    quantities = "acceleration: {acceleration: s}\n    tension: {force: string}"
    text = ATWOOD.replace("QUANTITIES", quantities).replace(
        "model:\n", EQUATION_PART.lstrip("\n") + "model:\n", 1
    )
    text = text.replace("answer: (m2 - m1)*g/m2", "answer: (m2 - m1)*g/(m1 + m2)")
    doc = parse_problem(text)
    assert [p.id for p in doc.parts] == ["acceleration", "newton_m2"]


SCENARIO = """  scenarios:
    heavier:
      bodies: {m2: {mass: 2*m2}}
      quantities:
        acceleration: {acceleration: s}
"""
ASKS_SCENARIO = """  - id: heavier_acceleration
    kind: symbolic
    quantity: heavier.acceleration
    prompt: Find it again with twice the mass on the right.
model:
"""


def test_a_scenario_quantity_no_part_asks_for_is_refused_at_the_scenario() -> None:
    errors = dict(_errors("acceleration: {acceleration: s}", SCENARIO))
    assert (
        "no part asks for the quantity 'heavier.acceleration'"
        in errors["model.scenarios.heavier.quantities.acceleration"]
    )


def test_a_part_asks_for_a_scenario_quantity_by_its_scenario_and_name() -> None:
    text = (ATWOOD.replace("QUANTITIES", "acceleration: {acceleration: s}") + SCENARIO).replace(
        "model:\n", ASKS_SCENARIO, 1
    )
    text = text.replace("answer: (m2 - m1)*g/m2", "answer: (m2 - m1)*g/(m1 + m2)")
    doc = parse_problem(text)
    assert [p.id for p in doc.parts] == ["acceleration", "heavier_acceleration"]
