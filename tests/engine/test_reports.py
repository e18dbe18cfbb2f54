"""Worked solutions and the engine's hygiene: steps in LaTeX per method, no text evaluation anywhere."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from tests.engine.conftest import bank_derivation

ENGINE = Path(__file__).resolve().parents[2] / "physics" / "engine"


@pytest.mark.parametrize("problem", ["atwood", "yo-yo", "mass-spring"])
def test_each_method_writes_its_steps_in_latex(problem: str) -> None:
    derivation = bank_derivation(problem)
    for report in derivation.methods:
        if report.results:
            assert report.steps, report.name
            assert all(step.title and step.latex for step in report.steps)
    names = [r.name for r in derivation.methods]
    assert names == ["lagrange", "newton", "conservation", "dalembert"]


def test_a_method_that_cannot_give_a_quantity_says_why() -> None:
    conservation = next(r for r in bank_derivation("atwood").methods if r.name == "conservation")
    assert "tension" not in conservation.results
    assert any(note.startswith("tension:") for note in conservation.notes)


def test_proofs_say_how_equality_was_shown() -> None:
    proofs = bank_derivation("atwood").proofs
    assert all("symbolic" in how or "sampled" in how for how in proofs.values())


def test_engine_never_evaluates_text() -> None:
    forbidden = re.compile(r"\b(eval|exec|sympify|parse_expr)\s*\(|\bS\(\"")
    for path in ENGINE.glob("*.py"):
        assert not forbidden.search(path.read_text()), path.name
