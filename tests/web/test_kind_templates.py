"""Each kind's own templates (problems/kinds/<kind>/): the student page shows what a Lagrangian or an
equation part expects (coordinates with how to type their velocities, the unknowns), the instructor page
and the worked solution show the reference, the model's equations and the wrong answers it knows, and
the live preview reads a velocity with its dot; no page branches on a kind."""

from __future__ import annotations

from functools import cache
from pathlib import Path

from app.instructor.described import describe
from app.web.layout import templates
from app.web.student_page import _parts
from physics.checking import preview
from problems.compiled import compile_problem
from problems.student import student_view
from problems.variants import fixed_variant
from tests.bank import bank_documents

TEMPLATES = Path(__file__).resolve().parents[2] / "app" / "web" / "templates"


@cache
def _yoyo():
    return compile_problem(bank_documents()["yo-yo-lagrangian"])


def _student_parts() -> dict[str, dict]:
    doc = bank_documents()["yo-yo-lagrangian"]
    view = student_view(doc, fixed_variant(doc, {}))
    return {part["id"]: part for part in _parts(view)}


def test_a_lagrangian_part_shows_its_coordinates_and_how_to_type_their_velocities() -> None:
    part = _student_parts()["lagrangian"]
    html = templates.env.get_template(f"{part['kind']}/student.html").render(part=part)
    assert "<code>d&#39;</code>" in html or "<code>d'</code>" in html
    assert "string unwound" in html  # the model's words for the coordinate
    assert "constant multiple" in html


def test_an_equation_part_shows_its_unknowns_and_what_it_asks() -> None:
    part = _student_parts()["newton_vertical"]
    html = templates.env.get_template("equation/student.html").render(part=part)
    assert "the tension in the string" in html and "Newton" in html and "<code>T</code>" in html


def test_the_instructor_page_shows_the_models_equations_and_known_mistakes() -> None:
    described = describe(_yoyo())
    macro = '{% import "instructor/_described.html" as d %}{{ d.parts(described) }}'
    html = templates.env.from_string(macro).render(described=described)
    assert "Lagrange&#39;s equation for d" in html or "Lagrange's equation for d" in html
    assert "rotation is missing" in html
    assert "Asked equation" in html and "holds" not in html


def test_no_page_template_branches_on_a_kind() -> None:
    for path in TEMPLATES.rglob("*.html"):
        assert "kind ==" not in path.read_text(), path


def test_the_live_preview_reads_a_velocity_with_its_dot() -> None:
    read = preview(_yoyo().part("lagrangian").job("1/2 m d'^2"))
    assert read.error is None and read.read_as is not None and r"\dot{d}" in read.read_as.latex
