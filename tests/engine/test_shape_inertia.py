"""A standard body's moment of inertia taken for another's is a known mistake, told as such."""

from __future__ import annotations

import pytest
import sympy

from physics.engine import derive
from physics.engine.results import KnownMistake
from problems.modelinfo import load_doc_model
from problems.symbols import symbol_table
from tests.bank import bank_documents

g, m, M, R, theta = sympy.symbols("g m M R theta", positive=True)
m1, m2 = sympy.symbols("m1 m2", positive=True)


def _mistakes(problem: str, quantity: str) -> tuple[KnownMistake, ...]:
    doc = bank_documents()[problem]
    return derive(load_doc_model(doc, symbol_table(doc))).mistakes[quantity]


def _told(mistakes: tuple[KnownMistake, ...], answer: sympy.Expr) -> str:
    return next((slip.feedback for slip in mistakes if sympy.simplify(slip.expr - answer) == 0), "")


@pytest.mark.parametrize(
    ("problem", "quantity", "answer", "said"),
    [
        # a disk's ½MR² taken for a hoop's MR², and the other way round
        ("atwood-massive-pulley", "acceleration", (m2 - m1) * g / (m1 + m2 + M), "a thin hoop's, $M R^{2}$"),
        ("flywheel", "acceleration", g * m / (M + m), "the wheel: this answer uses a thin hoop's"),
        # a solid sphere's 2/5 for a shell's 2/3
        ("rolling-incline", "acceleration_sphere", 3 * g * sympy.sin(theta) / 5, "a thin spherical shell's"),
        ("rolling-incline", "acceleration_hoop", 2 * g * sympy.sin(theta) / 3, "a uniform disk's"),
    ],
)
def test_a_shape_taken_for_another_is_told_which_and_what_the_body_has(problem, quantity, answer, said):
    told = _told(_mistakes(problem, quantity), answer)
    assert said in told and "about its centre of mass it is" in told


def test_a_rods_inertia_about_its_end_used_as_its_own_is_told():
    length = sympy.Symbol("L", positive=True)
    told = _told(_mistakes("physical-pendulum", "angular_frequency"), sympy.sqrt(6 * g / (7 * length)))
    assert "a rod's about its end" in told and r"\frac{m L^{2}}{12}" in told


def test_a_radius_of_gyration_names_no_shape():
    # the yo-yo's m k²: k is no length of the body's, so no hoop, disk or sphere is offered for it
    assert not any("moment of inertia of" in slip.feedback for slip in _mistakes("yo-yo", "acceleration"))


def test_a_body_named_by_an_element_is_called_by_its_mass():
    # the pulley element's wheel is `stringWheel`, no word a student reads
    told = [
        s.feedback for s in _mistakes("atwood-massive-pulley", "acceleration") if "inertia of" in s.feedback
    ]
    assert told and all("the body of mass $M$" in said and "stringWheel" not in said for said in told)
