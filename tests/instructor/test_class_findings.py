"""Class results for parts whose feedback names findings: which forces a class forgets on a free-body
part, which term of the Lagrangian it leaves out, counted by students from the verdicts the graders
gave (each answer graded for real, with its student's own values), instructors' tries left out."""

from __future__ import annotations

import html
import re
import shutil
from functools import cache
from pathlib import Path

import pytest
from fastapi.testclient import TestClient

from app.settings import Settings
from physics.checking import run_job
from physics.forces_check import findings_of
from problems.compiled import CompiledProblem, compile_problem
from problems.loader import BANK_DIR
from problems.variants import draw_variant
from tests.bank import bank_documents
from tests.instructor.conftest import new_key, stores_of

PROBLEM = "moving-wedge-lagrangian"
RIGHT_NORMAL = "{normal}"  # the block's normal force, perpendicular to its own incline: 90° - θ
RIGHT_L = "1/2 M X'^2 + 1/2 m (X'^2 + s'^2 + 2 X' s' cos(theta)) + m g s sin(theta)"
NO_WEDGE_L = "1/2 m (X'^2 + s'^2 + 2 X' s' cos(theta)) + m g s sin(theta)"
V_ADDED_L = "1/2 M X'^2 + 1/2 m (X'^2 + s'^2 + 2 X' s' cos(theta)) - m g s sin(theta)"
NO_CROSS_L = "1/2 (M + m) X'^2 + 1/2 m s'^2 + m g s sin(theta)"

# (student, part, answer as typed; {normal} is the student's own right direction for the block's normal)
SUBMISSIONS = [
    ("ada", "forces_on_block", "weight 270"),
    ("ada", "forces_on_block", "weight 270"),
    ("bob", "forces_on_block", "weight 270"),
    ("bob", "forces_on_block", "weight 270; normal {normal}"),
    ("cy", "forces_on_block", "normal {normal}"),
    ("dee", "forces_on_block", "weight 270; normal {normal}; motion 0"),
    ("eve", "forces_on_block", "normal {normal}; motion 0"),
    ("fay", "forces_on_block", "weight 270; normal 90"),
    ("preview:1", "forces_on_block", "weight 270"),
    ("ada", "lagrangian", NO_WEDGE_L),
    ("bob", "lagrangian", NO_WEDGE_L),
    ("bob", "lagrangian", RIGHT_L),
    ("cy", "lagrangian", V_ADDED_L),
    ("dee", "lagrangian", NO_CROSS_L),
    ("eve", "lagrangian", RIGHT_L),
    ("preview:1", "lagrangian", NO_WEDGE_L),
    ("ada", "newton_block_along_incline", "m a = m g sin(theta)"),
]

# part index on the page, finding as told (its start), students told it, of how many tried, submissions
FINDINGS = [
    (5, r"A normal force \(N₁\) is missing\.", 2, 6, 3),
    (5, r"The weight \(mg\) is missing\.", 2, 6, 2),
    (5, r'There is no "force of motion"', 2, 6, 2),
    (5, r"A normal force \(N₁\) points the wrong way", 1, 6, 1),
    (0, r"The kinetic energy of the wedge's motion is missing", 2, 5, 2),
    (0, r"is added instead of subtracted", 1, 5, 1),
    (0, r"The velocities are treated as independent", 1, 5, 1),
]


@cache
def _compiled() -> CompiledProblem:
    return compile_problem(bank_documents()[PROBLEM])


@pytest.fixture(scope="module")
def wedge_only(tmp_path_factory: pytest.TempPathFactory) -> Path:
    bank = tmp_path_factory.mktemp("bank")
    shutil.copytree(BANK_DIR / PROBLEM, bank / PROBLEM)
    return bank


@pytest.fixture
def settings(settings: Settings, wedge_only: Path) -> Settings:
    """The instructor pages' app with the moving wedge as its one problem."""
    return settings.model_copy(update={"bank_dir": wedge_only})


@pytest.fixture
def filed(signed_in: TestClient, settings: Settings) -> TestClient:
    """The signed-in client, its app holding SUBMISSIONS each graded for its student."""
    doc, compiled = bank_documents()[PROBLEM], _compiled()
    stores = stores_of(signed_in)
    for student, part, typed in SUBMISSIONS:
        variant = draw_variant(doc, 1, student, settings.secret)
        answer = typed.format(normal=f"{90 - float(variant.values['theta']):g}")
        stores.submissions.file(
            problem_id=PROBLEM,
            problem_version=1,
            part_id=part,
            student=student,
            answer=answer,
            verdict=run_job(compiled.part(part).job(answer, variant)),
            max_attempts=None,
        )
    return signed_in


@pytest.fixture
def results_html(filed: TestClient) -> str:
    response = filed.get(f"/instructor/problems/{PROBLEM}/results")
    assert response.status_code == 200
    return response.text


def _part(html: str, index: int) -> str:
    found = re.search(rf'<section class="part" id="part-{index}".*?</section>', html, re.DOTALL)
    assert found, f"no section for part {index}"
    return found.group(0)


def _finding_rows(section: str) -> list[tuple[str, int, int, int]]:
    """The findings table's rows: the finding as shown, students told it, of how many, submissions."""
    rows = re.findall(
        r"<tr><td>((?:(?!<tr>).)*?)</td><td>(\d+) of (\d+)</td><td>(\d+)</td></tr>", section, re.DOTALL
    )
    return [(html.unescape(cell), int(a), int(b), int(c)) for cell, a, b, c in rows]


@pytest.mark.parametrize(("index", "finding", "students", "tried", "submissions"), FINDINGS)
def test_class_results_count_each_finding_by_the_students_told_it(
    results_html: str, index: int, finding: str, students: int, tried: int, submissions: int
):
    counts = [
        numbers for cell, *numbers in _finding_rows(_part(results_html, index)) if re.search(finding, cell)
    ]
    assert counts == [[students, tried, submissions]]


@pytest.mark.parametrize(("index", "finding", "students", "tried", "submissions"), FINDINGS)
def test_the_results_api_counts_each_finding_as_the_page_does(
    filed: TestClient,
    instructor_key: str,
    index: int,
    finding: str,
    students: int,
    tried: int,
    submissions: int,
):
    response = filed.get(
        f"/v1/problems/{PROBLEM}/results", headers={"Authorization": f"Bearer {instructor_key}"}
    )
    assert response.status_code == 200
    part = response.json()["parts"][index]
    assert part["tried"] == tried
    counts = [(f["students"], f["submissions"]) for f in part["findings"] if re.search(finding, f["finding"])]
    assert counts == [(students, submissions)]


def test_the_results_api_gives_no_findings_for_other_kinds_and_refuses_students(
    filed: TestClient, instructor_key: str
):
    student = new_key(stores_of(filed), "student", "Ada", "ada")
    refused = filed.get(f"/v1/problems/{PROBLEM}/results", headers={"Authorization": f"Bearer {student}"})
    assert refused.status_code == 403
    parts = filed.get(
        f"/v1/problems/{PROBLEM}/results", headers={"Authorization": f"Bearer {instructor_key}"}
    )
    equation = parts.json()["parts"][3]
    assert (equation["kind"], equation["findings"], equation["tried"]) == ("equation", None, 1)
    assert [m["students"] for m in equation["mistakes"]] == [1]


def test_findings_are_charted_most_students_first_and_only_for_kinds_that_name_them(results_html: str):
    block, lagrangian = _part(results_html, 5), _part(results_html, 0)
    assert "Part 6: what the class's wrong answers miss, by students" in html.unescape(block)
    assert "Part 1: what the class's wrong answers miss, by students" in html.unescape(lagrangian)
    told = [students for _, students, _, _ in _finding_rows(block)]
    assert len(told) == 4 and told == sorted(told, reverse=True)
    equation = _part(results_html, 3)  # an equation part: its feedback names no findings to count
    assert "Wrong answers by known mistake" in equation
    assert "What the wrong answers miss" not in equation


@pytest.mark.parametrize(
    ("feedback", "findings"),
    [
        ("Correct.", ("Correct.",)),
        ("The weight (mg) is missing.", ("The weight (mg) is missing.",)),
        (
            "A normal force (N₁) points the wrong way: a normal force is perpendicular to the surface, "
            "pushing away from it. There is no friction force on the block here.",
            (
                "A normal force (N₁) points the wrong way: a normal force is perpendicular to the surface, "
                "pushing away from it.",
                "There is no friction force on the block here.",
            ),
        ),
        (
            'The weight (mg) is missing. There is no "force of motion": a moving body needs no force to '
            "keep moving; draw only what pushes or pulls on it.",
            (
                "The weight (mg) is missing.",
                'There is no "force of motion": a moving body needs no force to keep moving; draw only '
                "what pushes or pulls on it.",
            ),
        ),
    ],
)
def test_free_body_feedback_splits_back_into_one_finding_per_force(feedback: str, findings: tuple[str, ...]):
    assert findings_of(feedback) == findings
