"""A known mistake's feedback helps without giving the part away: no formula in it is the part's answer
(or its square, or its negative). The student reads it with attempts left."""

from __future__ import annotations

import random
import re

import pytest
import sympy
from _pytest.mark import ParameterSet

from physics.mathinput.reader import parse_expression
from problems.schema import SymbolicPart
from tests.bank import bank_documents

MATH = re.compile(r"\$([^$]+)\$")


def _names(symbols: list[str]) -> dict[str, sympy.Symbol]:
    names = {name: sympy.Symbol(name, positive=True) for name in symbols}
    for name in symbols:  # L0 as the feedback's TeX writes it, L_0
        if (found := re.fullmatch(r"([A-Za-z]+)(\d+)", name)) is not None:
            names[f"{found.group(1)}_{found.group(2)}"] = names[name]
    return names


def _stated(feedback: str, names: dict[str, sympy.Symbol]) -> list[tuple[str, sympy.Expr]]:
    """Every right-hand side of an `=` in the feedback's formulas that reads in the problem's names."""
    stated = []
    for formula in MATH.findall(feedback):
        for side in formula.split("=")[1:]:
            try:
                stated.append((side.strip(), parse_expression(side, names)))
            except Exception:  # prose in TeX, another part's unknowns: not a formula of the answer
                continue
    return stated


def _typed_parts() -> list[ParameterSet]:
    cases = []
    for problem in bank_documents().values():
        for part in problem.parts:
            if isinstance(part, SymbolicPart) and part.answer and part.mistakes:
                where = f"{problem.id}.{part.id}"
                cases.append(pytest.param(where, part, _names(list(problem.symbols)), id=where))
    return cases


def _same(a: sympy.Expr, b: sympy.Expr, symbols: set[sympy.Symbol]) -> bool:
    for _ in range(3):
        point = {s: random.Random(hash((str(s), _))).uniform(0.2, 1.3) for s in symbols}
        x, y = complex(a.subs(point).evalf()), complex(b.subs(point).evalf())
        if abs(x - y) > 1e-9 * max(1.0, abs(y)):
            return False
    return True


@pytest.mark.parametrize(("where", "part", "names"), _typed_parts())
def test_a_mistakes_feedback_never_states_the_answer(
    where: str, part: SymbolicPart, names: dict[str, sympy.Symbol]
) -> None:
    assert part.answer is not None
    answer = parse_expression(part.answer, names)
    for mistake in part.mistakes:
        for text, value in _stated(mistake.feedback, names):
            symbols = answer.free_symbols | value.free_symbols
            for form in (answer, -answer, answer**2):
                assert not _same(value, form, symbols), f"{where}: the feedback states {text}"
