"""A new ad-hoc reference prepared from its parse tree (physics.symbolic.tree_reference) grades every
answer as the compiled reference does, and whatever the tree cannot vouch for is compiled as before."""

from __future__ import annotations

import pickle

import pytest

from physics.checking import SymbolDecl
from physics.errors import SpecError
from physics.mathinput import DEFAULT_LIMITS
from problems.kinds.symbolic import AdhocTreeQuestion, SymbolicJob, adhoc_part, adhoc_tree_question

ANGLE = ("1", ("0", "pi/2"))
WEDGE = {"m": "kg", "M": "kg", "g": "m/s^2", "theta": ANGLE}
LJ = {"U0": "J", "r0": "m", "r": "m", "m": "kg"}
SPRING = {"k": "N/m", "m": "kg", "x": "m", "t": "s"}
OPEN = {"x": ("1", ("0", "2")), "a": "1"}

WEDGE_A = "-m*g*sin(theta)*cos(theta)/(M + m*sin(theta)**2)"
LJ_F = "12*U0/r0*((r0/r)**13 - (r0/r)**7)"

# Answers of every verdict and reason: right, a sign, a factor, a dimension, a value, undefined.
CASES = [
    (
        WEDGE_A,
        WEDGE,
        [
            "-m g sin(θ)cos(θ)/(M + m sin^2 θ)",
            "m g sin(θ)cos(θ)/(M + m sin^2 θ)",
            "-2 m g sin(θ)cos(θ)/(M + m sin^2 θ)",
            "-m sin(θ)cos(θ)/(M + m sin^2 θ)",
            "-m g sin(θ)/(M + m sin^2 θ)",
            "-m g sin(θ)cos(θ)/(M - m sin^2 θ)",
            "g",
            "0",
        ],
    ),
    (LJ_F, LJ, ["12 U0 r0^12/r^13 - 12 U0 r0^6/r^7", "-12 U0 r0^12/r^13 + 12 U0 r0^6/r^7", "U0/r", "U0"]),
    ("sqrt(k/m)*x*cos(sqrt(k/m)*t)", SPRING, ["x sqrt(k/m) cos(t sqrt(k/m))", "x cos(t sqrt(k/m))", "-x"]),
    ("2*pi", {"a": "1"}, ["2π", "π", "-2 pi", "2*pi*a"]),
]


def decls(symbols: dict[str, object]) -> tuple[SymbolDecl, ...]:
    return tuple(
        SymbolDecl(name, spec) if isinstance(spec, str) else SymbolDecl(name, spec[0], range=spec[1])  # type: ignore[index]
        for name, spec in symbols.items()
    )


@pytest.mark.parametrize(("expected", "symbols", "answers"), CASES)
def test_a_reference_prepared_from_its_tree_grades_as_the_compiled_one(
    expected: str, symbols: dict[str, object], answers: list[str]
) -> None:
    declared = decls(symbols)
    tree = adhoc_tree_question(expected, declared)
    assert isinstance(tree, AdhocTreeQuestion)
    assert tree.question.reference.built is None  # not built by sympy yet
    compiled = adhoc_part(expected, declared).compiled
    for answer in answers:
        assert tree.grade(answer, DEFAULT_LIMITS) == compiled.grade(answer, DEFAULT_LIMITS), answer
        assert tree.read(answer, DEFAULT_LIMITS) == compiled.read(answer, DEFAULT_LIMITS), answer
    assert tree.question.reference.expected == compiled.expected


@pytest.mark.parametrize(
    ("expected", "symbols"),
    [
        ("m/m", {"m": "kg"}),  # names a symbol, yet sympy's tree is a constant
        ("log10(x)", OPEN),  # a function float64 does not vouch for here
        ("sqrt(x - 1)", OPEN),  # undefined at some points: sampling draws more
        ("a", {"a": "1", "b": "1"}),  # the control
        ("x!", OPEN),  # a postfix
        ("x^a", OPEN),  # an exponent that is not a constant
        ("m + x", {"m": "kg", "x": "m"}),  # its dimension is not consistent
    ],
)
def test_what_the_tree_cannot_vouch_for_is_compiled_as_before(
    expected: str, symbols: dict[str, object]
) -> None:
    declared = decls(symbols)
    if expected == "a":  # the control: a plain reference is prepared from its tree
        assert adhoc_tree_question(expected, declared) is not None
        return
    assert adhoc_tree_question(expected, declared) is None
    assert SymbolicJob("1", expected, declared).question() == adhoc_part(expected, declared).compiled


def test_a_reference_that_cannot_be_read_raises_as_before() -> None:
    declared = decls({"m": "kg"})
    for expected in ("m +", "q"):
        with pytest.raises(SpecError) as compiled:
            adhoc_part(expected, declared)
        with pytest.raises(SpecError) as asked:
            SymbolicJob("m", expected, declared).question()
        assert (asked.value.message, asked.value.path) == (compiled.value.message, compiled.value.path)


def test_a_reference_from_its_tree_is_pickled_with_sympys_tree() -> None:
    tree = adhoc_tree_question(WEDGE_A, decls(WEDGE))
    assert tree is not None
    reference = tree.question.reference
    reference.complete()
    copied = pickle.loads(pickle.dumps(reference))
    assert copied.source is None
    assert copied.expected == adhoc_part(WEDGE_A, decls(WEDGE)).compiled.expected
    assert copied.precise_values == reference.precise_values
