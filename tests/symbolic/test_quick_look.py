"""An answer judged on its parse tree (physics.symbolic.quick) gets the very verdict the full path (build
sympy's tree, judge it) gives; everything the tree cannot vouch for goes the full way."""

from __future__ import annotations

import random

import pytest
import sympy

import physics.checking
import physics.symbolic.quick as quick_module
from physics.checking import SymbolDecl, SymbolicQuestion
from physics.mathinput import DEFAULT_LIMITS
from physics.mathinput.reader import read_tree
from physics.symbolic import numeric
from physics.symbolic.judge import EQUIVALENT, FACTOR_FEEDBACK
from physics.symbolic.quick import judged
from physics.verdict import Judgement, Reason, Verdict
from problems.kinds.symbolic import SymbolicJob

ANGLE = ("1", ("0", "pi/2"))
WEDGE = {"m": "kg", "M": "kg", "g": "m/s^2", "theta": ANGLE}
YOYO = {"m": "kg", "r": "m", "k": "m", "g": "m/s^2"}
LJ = {"U0": "J", "r0": "m", "r": "m", "m": "kg"}
PENDULUM = {"m": "kg", "M": "kg", "L": "m", "theta": ANGLE, "g": "m/s^2"}
OSCILLATOR = {"A": "m", "omega": "1/s", "t": "s", "phi": "1", "k": "1/m", "x": "m"}

WEDGE_A = "-m*g*sin(theta)*cos(theta)/(M + m*sin(theta)**2)"
YOYO_A = "g*r**2/(r**2 + k**2)"
LJ_F = "12*U0/r0*((r0/r)**13 - (r0/r)**7)"
PENDULUM_V = "(m + M)/m*sqrt(2*g*L*(1 - cos(theta)))"
WAVE = "A*cos(omega*t - k*x + phi)"


def question(expected: str, symbols: dict[str, object], *, answered: bool = True) -> SymbolicQuestion:
    """The part's question; `answered`: as after a first answer, which computes the precise values."""
    decls = tuple(
        SymbolDecl(name, spec) if isinstance(spec, str) else SymbolDecl(name, spec[0], range=spec[1])  # type: ignore[index]
        for name, spec in symbols.items()
    )
    asked = SymbolicJob("", expected, decls).question().question
    if answered:
        assert asked.reference.precise_values
    return asked


def quick(answer: str, asked: SymbolicQuestion) -> Judgement | None:
    return judged(read_tree(answer, asked.names), asked.reference, DEFAULT_LIMITS.max_exponent)


def in_full(answer: str, asked: SymbolicQuestion, monkeypatch: pytest.MonkeyPatch) -> Verdict:
    with monkeypatch.context() as patched:
        patched.setattr(physics.checking, "judged", lambda *_: None)
        return asked.grade(answer, DEFAULT_LIMITS)


# Right answers as students type them, each recognised on its tree.
RIGHT = [
    ("-m g sin(θ)cos(θ)/(M + m sin^2 θ)", WEDGE_A, WEDGE),
    ("-(m g sin(2θ)/2)/(M + m sin(θ)^2)", WEDGE_A, WEDGE),
    ("-m*g*sin(theta)*cos(theta)/(M + m - m*cos(theta)^2)", WEDGE_A, WEDGE),
    ("g/(1 + k^2/r^2)", YOYO_A, YOYO),
    ("g r²/(r² + k²)", YOYO_A, YOYO),
    (r"\frac{g}{1 + \frac{k^2}{r^2}}", YOYO_A, YOYO),
    ("12 U0 ((r0/r)^13 - (r0/r)^7)/r0", LJ_F, LJ),
    ("12 U0 r0^12/r^13 - 12 U0 r0^6/r^7", LJ_F, LJ),
    ("2(m + M) sqrt(g L) sin(θ/2)/m", PENDULUM_V, PENDULUM),
    ("(1 + M/m) √(2gL(1 - cos θ))", PENDULUM_V, PENDULUM),
    ("A cos(ωt - kx + φ)", WAVE, OSCILLATOR),
    ("A(cos(ωt - kx) cos φ - sin(ωt - kx) sin φ)", WAVE, OSCILLATOR),
    ("A e^0 cos(omega t + phi - k x)", WAVE, OSCILLATOR),
    ("(m + 3 M)^2 m g sin θ cos θ/((m^2 + 6 m M + 9 M^2)(-M - m sin^2 θ))", WEDGE_A, WEDGE),
]


@pytest.mark.parametrize(("answer", "expected", "symbols"), RIGHT)
def test_a_right_answer_is_recognised_on_its_tree_with_the_full_paths_verdict(
    answer: str, expected: str, symbols: dict[str, object], monkeypatch: pytest.MonkeyPatch
) -> None:
    asked = question(expected, symbols)
    assert quick(answer, asked) == EQUIVALENT
    verdict = asked.grade(answer, DEFAULT_LIMITS)
    assert verdict.outcome.value == "correct"
    assert verdict == in_full(answer, asked, monkeypatch)


# Wrong answers whose every reason the tree can find: the full path's reason and feedback.
WRONG = [
    ("-m g sin(θ)cos(θ)/M", WEDGE_A, WEDGE, Reason.WRONG_VALUE),
    ("m g sin(θ)cos(θ)/(M + m sin^2 θ)", WEDGE_A, WEDGE, Reason.SIGN_ERROR),
    ("-2 m g sin(θ)cos(θ)/(M + m sin^2 θ)", WEDGE_A, WEDGE, Reason.CONSTANT_FACTOR),
    ("-m sin(θ)cos(θ)/(M + m sin^2 θ)", WEDGE_A, WEDGE, Reason.WRONG_DIMENSION),
    ("g r/(r^2 + k^2)", YOYO_A, YOYO, Reason.WRONG_DIMENSION),
    ("2 g/3", YOYO_A, YOYO, Reason.WRONG_VALUE),
    ("A sin(ωt - kx + φ)", WAVE, OSCILLATOR, Reason.WRONG_VALUE),
]


@pytest.mark.parametrize(("answer", "expected", "symbols", "reason"), WRONG)
def test_a_wrong_answer_is_diagnosed_on_its_tree_with_the_full_paths_reason(
    answer: str, expected: str, symbols: dict[str, object], reason: Reason, monkeypatch: pytest.MonkeyPatch
) -> None:
    asked = question(expected, symbols)
    found = quick(answer, asked)
    assert found is not None and found.reason is reason
    assert asked.grade(answer, DEFAULT_LIMITS) == in_full(answer, asked, monkeypatch)


# What the tree must leave to the full path, each for the reason in its id: the verdict is then the full
# path's alone (some are right answers, some wrong, some unreadable there).
DECLINED = {
    "wrong by one part in 10^12": ("(1 + 10^-12) g r^2/(r^2 + k^2)", YOYO_A, YOYO),
    "thirty digits of pi": ("3.14159265358979323846264338328 A cos(ωt - kx + φ)/pi", WAVE, OSCILLATOR),
    "a log of an exact zero": (f"{YOYO_A} + 0 log(sin(pi))", YOYO_A, YOYO),
    "a division by an exact zero": (f"{YOYO_A} + 1/sin(pi) - 1/sin(pi)", YOYO_A, YOYO),
    "a structural zero divided by": (f"({YOYO_A}) (1 + 0/(m - m))", YOYO_A, YOYO),
    "a merged exponent past the limit": (f"({YOYO_A}) (m^60)^2/(m^60)^2", YOYO_A, YOYO),
    "a product merging past the limit": (f"({YOYO_A}) m^60 m^50/(m^60 m^50)", YOYO_A, YOYO),
    "a factorial": (f"({YOYO_A}) 3!/6", YOYO_A, YOYO),
    "a percent sign": (f"({YOYO_A}) 100%", YOYO_A, YOYO),
    "roots nested": (f"({YOYO_A}) sqrt(sqrt(m^2))/sqrt(m)", YOYO_A, YOYO),
    "a cube root": (f"({YOYO_A}) (m^3)^(1/3)/m", YOYO_A, YOYO),
    "a constant with no real value": (f"{YOYO_A} + 0 acos(2)", YOYO_A, YOYO),
    "an exponent that is not a number": (f"({YOYO_A}) m^(r/k)/m^(r/k)", YOYO_A, YOYO),
    "numbers too large in all": (f"({YOYO_A}) (2^64 + 1)^4/(2^64 + 1)^4", YOYO_A, YOYO),
    "a value beyond 2^100 on the way": (f"{YOYO_A} + e^80 - e^80", YOYO_A, YOYO),
    "too many nodes": (f"{YOYO_A}" + " + m - m" * 70, YOYO_A, YOYO),
    "an angle sympy reduces exactly": (f"{YOYO_A} + sin(pi)", YOYO_A, YOYO),
    "terms whose dimensions clash": ("g + m", YOYO_A, YOYO),
    "a function of a length": ("g sin(r)", YOYO_A, YOYO),
    "zero, whose dimension goes unasked": ("m - m", YOYO_A, YOYO),
}


@pytest.mark.parametrize(("answer", "expected", "symbols"), DECLINED.values(), ids=DECLINED.keys())
def test_what_the_tree_cannot_vouch_for_takes_the_full_path(
    answer: str, expected: str, symbols: dict[str, object], monkeypatch: pytest.MonkeyPatch
) -> None:
    asked = question(expected, symbols)
    assert quick(answer, asked) is None
    assert asked.grade(answer, DEFAULT_LIMITS) == in_full(answer, asked, monkeypatch)


def test_the_first_right_answer_to_a_new_reference_is_judged_on_its_tree(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # It computes the reference's precise values (two points) rather than building the answer.
    asked = question("r**2*g/(k**2 + r**2)", YOYO, answered=False)  # a reference text no other test uses
    assert "precise_values" not in asked.reference.__dict__
    assert quick("g r^2/(r^2 + k^2)", asked) == EQUIVALENT
    assert "precise_values" in asked.reference.__dict__
    assert asked.grade("g r^2/(r^2 + k^2)", DEFAULT_LIMITS) == in_full(
        "g r^2/(r^2 + k^2)", asked, monkeypatch
    )


def test_a_wrong_answer_to_a_new_reference_is_judged_on_its_tree(monkeypatch: pytest.MonkeyPatch) -> None:
    # A reference that meets only wrong answers never computes its precise values: none is needed.
    asked = question("g*k**2/(k**2 + r**2)", YOYO, answered=False)  # a reference text no other test uses
    found = quick("g r^2/(r^2 + k^2)", asked)
    assert found is not None and found.reason is Reason.WRONG_VALUE
    assert asked.grade("g r^2/(r^2 + k^2)", DEFAULT_LIMITS) == in_full(
        "g r^2/(r^2 + k^2)", asked, monkeypatch
    )
    assert "precise_values" not in asked.reference.__dict__


def test_the_reading_note_leads_a_recognised_answer_as_it_leads_a_built_one(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    asked = question("m*g*sin(theta**2)", WEDGE)
    assert quick("m g sin θ^2", asked) == EQUIVALENT
    verdict = asked.grade("m g sin θ^2", DEFAULT_LIMITS)
    assert verdict.feedback.startswith("sin θ^2 is read as sin(θ²)")
    assert verdict == in_full("m g sin θ^2", asked, monkeypatch)


# Forms equal to 1 and small slips, combined at random with a reference: whatever the look decides,
# the verdict is the full path's (a few hundred answers, right and wrong, read both ways).
ONES = [
    "(m + 3 M)^2/(m^2 + 6 m M + 9 M^2)",
    "(sin(θ)^2 + cos(θ)^2)",
    "e^(ln(m))/m",
    "(1 - sin θ)(1 + sin θ)/cos(θ)^2",
    "sqrt(m^2)/m",
    "2 sin(θ/2) cos(θ/2)/sin(θ)",
    "tan(θ) cos(θ)/sin(θ)",
    "(M/m + 1) m/(M + m)",
    "cosh(θ)^2 - sinh(θ)^2",
    "10^3 m/(1000 m)",
    "abs(-m)/m",
    "log10(100)/2",
]
SLIPS = ["", "", "", "2 ", "-", "(M/m) ", "sin θ ", "(1 + 10^-9) "]


def test_random_rewritings_get_the_full_paths_verdict(monkeypatch: pytest.MonkeyPatch) -> None:
    rng = random.Random(20261126)
    asked = question(WEDGE_A, WEDGE)
    taken = 0
    for _ in range(150):
        factors = " ".join(f"({rng.choice(ONES)})" for _ in range(rng.randint(1, 3)))
        answer = f"{rng.choice(SLIPS)}({WEDGE_A}) {factors}"
        taken += quick(answer, asked) is not None
        assert asked.grade(answer, DEFAULT_LIMITS) == in_full(answer, asked, monkeypatch), answer
    assert taken > 75  # the tree decides most of them


def test_a_wrong_answer_with_a_bare_powered_argument_is_built_to_try_the_other_reading() -> None:
    asked = question("m*g*sin(theta)**2", WEDGE)
    found = quick("m g sin θ^2", asked)
    assert found is not None and not found.correct  # read as sin(θ²): wrong, and the tree says so
    feedback = asked.grade("m g sin θ^2", DEFAULT_LIMITS).feedback
    assert feedback.startswith("Read as sin(θ²); if you meant (sin θ)², write sin^2 θ.")


def test_a_function_is_evaluated_once_at_a_sample_point_for_every_answer_to_a_reference(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    asked = question("m*g*sin(theta)*cos(theta)", WEDGE)
    calls: list[tuple[object, int]] = []
    sine = numeric.UNARY[sympy.sin]
    monkeypatch.setitem(numeric.UNARY, sympy.sin, lambda x, prec: calls.append((x, prec)) or sine(x, prec))
    monkeypatch.setattr(quick_module, "_UNARY_VALUES", {})
    answers = ["m g sin θ cos θ", "g m cos(θ) sin(θ)", "m g sin(θ)/2", "m g sin(θ)/3", "-m g sin θ cos θ"]
    assert all(quick(answer, asked) is not None for answer in answers)
    # The tree's own precisions (the judge evaluates the reference at PREC itself).
    tree_precisions = {q + quick_module.EXTRA_BITS for q in (quick_module.PREC, quick_module.PRECISE_PREC)}
    mine = [call for call in calls if call[1] in tree_precisions]
    assert mine and len(mine) == len(set(mine))


def test_the_remembered_function_values_stay_bounded(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(quick_module, "_UNARY_VALUES", {})
    monkeypatch.setattr(quick_module, "UNARY_VALUES_KEPT", 8)
    for n in range(1, 30):
        quick_module._unary(sympy.sin, (0, n, 0, n.bit_length()), 53)
        assert len(quick_module._UNARY_VALUES) <= 8


def test_a_subtree_shared_by_answers_to_a_reference_is_evaluated_once_at_each_set_of_points(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    asked = question(WEDGE_A, WEDGE)
    grids: list[object] = []
    add = quick_module._VALUE_RULES[quick_module.Sum]
    monkeypatch.setitem(
        quick_module._VALUE_RULES,
        quick_module.Sum,
        lambda self, node: grids.append(self._grid) or add(self, node),
    )
    monkeypatch.setattr(quick_module, "_SUBTREES", {})
    # One sum each, the same one: evaluated at the precise points once, and once at each other set of
    # points the wrong answers' diagnoses look at.
    answers = [
        "-m g sin θ cos θ/(M + m sin^2 θ)",
        "-2 m g sin θ cos θ/(M + m sin^2 θ)",
        "m g/(M + m sin^2 θ)",
    ]
    assert [quick(answer, asked) for answer in answers] == [
        EQUIVALENT,
        Judgement(False, Reason.CONSTANT_FACTOR, FACTOR_FEEDBACK),
        quick(answers[2], asked),
    ]
    assert grids and len(grids) == len(set(grids))
    for answer in answers:
        assert asked.grade(answer, DEFAULT_LIMITS) == in_full(answer, asked, monkeypatch)


def test_the_remembered_subtree_values_stay_bounded(monkeypatch: pytest.MonkeyPatch) -> None:
    asked = question(WEDGE_A, WEDGE)
    monkeypatch.setattr(quick_module, "_SUBTREES", {})
    monkeypatch.setattr(quick_module, "SUBTREES_KEPT", 8)
    for n in range(2, 12):
        quick(f"(-m g sin θ cos θ/(M + m sin^2 θ)) (m + {n} M)/(m + {n} M)", asked)
        assert len(quick_module._SUBTREES) <= 8


def test_a_point_where_the_answer_is_undefined_leaves_the_other_points_their_values() -> None:
    # Several points are evaluated in one walk; where one of them declines, each is evaluated alone.
    asked = question(WEDGE_A, WEDGE)
    columns = asked.reference.sample.columns
    theta = asked.names["theta"]
    first, second = (float(sympy.Float(columns[theta][i])) for i in (0, 1))  # type: ignore[arg-type]
    middle = round((first + second) / 2, 6)
    assert min(first, second) < middle < max(first, second)
    reading = read_tree(f"m g log(θ - {middle})", asked.names)
    symbols = {name: reading.symbols[name] for name in ("m", "g", "theta")}
    shape = quick_module._Shape(100, reading.symbols)
    shape.check(reading.tree)
    keys = shape.keys
    together = quick_module._TreeAtPoints(reading.tree, symbols, asked.reference, keys)((0, 1))
    alone = [
        quick_module._TreeAtPoints(reading.tree, symbols, asked.reference, keys)((i,))[0] for i in (0, 1)
    ]
    assert together == alone and together.count(None) == 1
