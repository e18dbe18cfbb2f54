"""Mistakes and limits generated from the models: the slips the brief names, with feedback that does
not give the answer away, and limits in which the answer stays finite."""

from __future__ import annotations

from typing import Any

import pytest
import sympy
from sympy import cos, sin, sqrt

from physics.engine import derive, load_model
from physics.engine.mistakes import SWAPPED_TRIG
from physics.engine.proof import proven_sign
from physics.engine.results import KnownMistake, LimitCase
from physics.mathinput import parse_math
from physics.wording import symbol_label
from problems.modelinfo import load_doc_model
from problems.symbols import symbol_table
from tests.bank import bank_documents
from tests.engine.conftest import SLOW_PROBLEMS, bank_derivation, bank_model, s


def _mistakes() -> list[tuple[str, str, sympy.Expr, str]]:
    m, big, th, g = (s("moving-wedge", n) for n in ("m", "M", "theta", "g"))
    u0, r0, mass = (s("lennard-jones", n) for n in ("U0", "r0", "m"))
    bm, bbig, length, bth, bg = (s("ballistic-pendulum", n) for n in ("m", "M", "L", "theta", "g"))
    al, mu, sg = (s("skier-friction", n) for n in ("alpha", "mu", "g"))
    rth, rg = s("rolling-incline", "theta"), s("rolling-incline", "g")
    yg = s("yo-yo", "g")
    return [
        ("moving-wedge", "block_relative_acceleration", g * sin(th), "fixed"),
        ("moving-wedge", "normal_force", m * g * cos(th), "fixed"),
        ("moving-wedge", "wedge_acceleration", -m * g * sin(th) * cos(th) / big, "fixed"),
        (
            "moving-wedge",
            "normal_force",
            big * m * g * sin(th) / (big + m * cos(th) ** 2),
            "sine and a cosine",
        ),
        ("lennard-jones", "oscillation_frequency", sqrt(72 * u0 / r0**2 / mass), "reduced mass"),
        (
            "ballistic-pendulum",
            "bullet_speed",
            sqrt(2 * bg * length * (1 - cos(bth)) * (bm + bbig) / bm),
            "not conserved",
        ),
        ("ballistic-pendulum", "energy_fraction_lost", bm / (bm + bbig), "remains"),
        ("skier-friction", "acceleration", sg * (sin(al) + mu * cos(al)), "opposes"),
        ("rolling-incline", "acceleration_cylinder", rg * sin(rth), "moment of inertia"),
        ("yo-yo", "acceleration", yg, "moment of inertia"),
    ]


@pytest.mark.parametrize(
    ("problem", "quantity", "expr", "hint"),
    [
        pytest.param(
            *row,
            id=f"{row[0]}:{row[1]}:{row[3]}",
            marks=[pytest.mark.slow] if row[0] in SLOW_PROBLEMS else [],
        )
        for row in _mistakes()
    ],
)
def test_the_slip_is_generated_with_targeted_feedback(
    problem: str, quantity: str, expr: sympy.Expr, hint: str
) -> None:
    derivation = bank_derivation(problem)
    matches = [k for k in derivation.mistakes[quantity] if sympy.simplify(k.expr - expr) == 0]
    assert matches, [k.expr for k in derivation.mistakes[quantity]]
    assert hint in matches[0].feedback
    assert str(derivation.quantities[quantity]) not in matches[0].feedback


@pytest.mark.slow
def test_no_mistake_equals_the_answer() -> None:
    for problem in ("moving-wedge", "rolling-incline", "lennard-jones", "ballistic-pendulum"):
        derivation = bank_derivation(problem)
        for name, mistakes in derivation.mistakes.items():
            for mistake in mistakes:
                assert sympy.simplify(mistake.expr - derivation.quantities[name]) != 0, (problem, name)


@pytest.mark.parametrize(
    ("problem", "quantity", "symbol", "value", "word"),
    [
        pytest.param(
            "moving-wedge",
            "block_relative_acceleration",
            "M",
            sympy.oo,
            "fixed",
            marks=pytest.mark.slow,
            id="heavy-wedge",
        ),
        pytest.param(
            "moving-wedge", "wedge_acceleration", "theta", 0, "θ → 0", marks=pytest.mark.slow, id="flat-wedge"
        ),
        pytest.param(
            "moving-wedge", "wedge_acceleration", "m", 0, "lighter", marks=pytest.mark.slow, id="light-block"
        ),
        pytest.param("yo-yo", "acceleration", "k", 0, "rotational inertia", id="yo-yo-without-inertia"),
        pytest.param(
            "skier-friction",
            "acceleration",
            "mu",
            0,
            "friction",
            marks=pytest.mark.slow,
            id="frictionless-slope",
        ),
        pytest.param("atwood", "acceleration", "m1", 0, "lighter", id="light-counterweight"),
    ],
)
def test_physical_limit_is_listed(
    problem: str, quantity: str, symbol: str, value: sympy.Expr, word: str
) -> None:
    limits = bank_derivation(problem).limits[quantity]
    target = s(problem, symbol)
    found = [c for c in limits if c.substitutions.get(target) == value]
    assert found and word in found[0].description


def test_limits_are_finite() -> None:
    derivation = bank_derivation("atwood")
    for name, cases in derivation.limits.items():
        for case in cases:
            ((symbol, value),) = case.substitutions.items()
            assert sympy.limit(derivation.quantities[name], symbol, value).is_finite


TRIG_NAMES = ("m", "F0", "w", "t", "theta", "g")


def driven_up_a_slope() -> dict[str, Any]:
    """A cart pushed up a smooth incline theta by F0 cos(w t), the time t a symbol of the problem."""
    return {
        "elements": {
            "incline": {
                "kind": "incline",
                "body": "cart",
                "mass": "m",
                "angle": "theta",
                "coordinate": "s",
                "direction": "up",
            }
        },
        "gravity": "g",
        "forces": [{"body": "cart", "force": {"x": "F0*cos(w*t)*cos(theta)", "y": "F0*cos(w*t)*sin(theta)"}}],
        "domain": {"ranges": {"theta": ["0", "pi/2"]}},
        "quantities": {"a": {"acceleration": "s"}, "drive": {"expression": "m*a + m*g*sin(theta)"}},
    }


def _feedback_for(mistakes: tuple[KnownMistake, ...], expr: sympy.Expr) -> list[str]:
    return [k.feedback for k in mistakes if sympy.simplify(k.expr - expr) == 0]


def test_a_swapped_drive_phase_is_not_called_a_component_along_the_surface() -> None:
    m, f0, w, t, th, g = (sympy.Symbol(n, positive=True) for n in TRIG_NAMES)
    model = load_model(driven_up_a_slope(), {n: sympy.Symbol(n, positive=True) for n in TRIG_NAMES})
    derivation = derive(model)
    assert sympy.simplify(derivation.quantities["a"] - (f0 * cos(w * t) / m - g * sin(th))) == 0
    mistakes = derivation.mistakes["a"]
    drive_swapped = _feedback_for(mistakes, f0 * sin(w * t) / m - g * sin(th))
    slope_swapped = _feedback_for(mistakes, f0 * cos(w * t) / m - g * cos(th))
    assert drive_swapped and "driving force" in drive_swapped[0] and "surface" not in drive_swapped[0]
    assert slope_swapped and "along the surface" in slope_swapped[0]
    amplitude = _feedback_for(derivation.mistakes["drive"], f0)  # F0 cos(w t) taken as F0
    assert amplitude and "amplitude" in amplitude[0] and "projection" not in amplitude[0]
    assert all("along the surface" not in k.feedback for k in derivation.mistakes["drive"])


@pytest.mark.slow
def test_a_swing_angle_is_not_called_a_component_along_the_surface() -> None:
    bm, bbig, length, bth, bg = (s("ballistic-pendulum", n) for n in ("m", "M", "L", "theta", "g"))
    swapped = sqrt(2 * bg * length * (1 - sin(bth))) * (bm + bbig) / bm
    feedback = _feedback_for(bank_derivation("ballistic-pendulum").mistakes["bullet_speed"], swapped)
    assert feedback and "sine and a cosine" in feedback[0] and "surface" not in feedback[0]


def test_an_incline_angle_keeps_the_along_the_surface_feedback() -> None:
    g, th, m = (sympy.Symbol(n, positive=True) for n in ("g", "theta", "m"))
    data = driven_up_a_slope()
    data.pop("forces")
    data["quantities"] = {"normal_force": {"force": "incline"}}
    derivation = derive(load_model(data, {n: sympy.Symbol(n, positive=True) for n in ("m", "theta", "g")}))
    assert _feedback_for(derivation.mistakes["normal_force"], m * g * sin(th)) == [SWAPPED_TRIG]


def _bank_limits(problem_id: str, quantity: str) -> tuple[LimitCase, ...]:
    doc = bank_documents()[problem_id]
    return derive(load_doc_model(doc, symbol_table(doc))).limits[quantity]


def test_a_friction_limit_names_its_coefficient_and_is_listed_once_per_coefficient() -> None:
    two = [
        c.description
        for c in _bank_limits("blocks-in-contact", "acceleration")
        if "friction" in c.description
    ]
    assert len(two) == 2 and len(set(two)) == 2  # mu1 and mu2 each, told apart
    assert all(  # as the statement writes it: μ₁, not mu1
        symbol_label(next(iter(c.substitutions)).name) in c.description
        for c in _bank_limits("blocks-in-contact", "acceleration")
    )
    shared = [c for c in _bank_limits("pushed-blocks", "acceleration") if "friction" in c.description]
    assert len(shared) == 1  # two contacts with one coefficient: one limit


def test_a_light_body_is_compared_with_the_other_body_by_name() -> None:
    m1, m2 = s("atwood", "m1"), s("atwood", "m2")
    cases = {
        next(iter(c.substitutions)): c.description for c in bank_derivation("atwood").limits["acceleration"]
    }
    assert cases[m1] == "m₁ much lighter than m₂" and cases[m2] == "m₂ much lighter than m₁"


def test_a_bare_tangent_is_not_offered_as_a_dropped_projection() -> None:
    doc = bank_documents()["skier-friction"]
    derivation = derive(load_doc_model(doc, symbol_table(doc)))
    assert derivation.quantities["friction_coefficient"].has(sympy.tan)
    # mu = 1 (tan(alpha) dropped) is no slip anyone makes
    assert all("projection" not in slip.feedback for slip in derivation.mistakes["friction_coefficient"])


# (problem, quantity, slip whose mistake must stay): a time, length or speed the answer proves positive
# gets no mistake proven negative (friction's sign flipped gives -2 v0/(7 g mu) for a skid's time); a
# force keeps one, since a force of the wrong sign is a slip students make.
NEGATIVE_MISTAKES = [
    ("bowling-ball-skid", "skid_time", None),
    ("bowling-ball-skid", "skid_distance", None),
    ("bowling-ball-skid", "rolling_speed", None),
    ("quarter-circle-slide", "normal_force_at_bottom", "centripetal acceleration points towards"),
]


@pytest.mark.parametrize(("problem", "quantity", "kept"), NEGATIVE_MISTAKES)
def test_no_negative_mistake_for_a_positive_magnitude(problem: str, quantity: str, kept: str | None) -> None:
    derivation = bank_derivation(problem)
    model = bank_model(problem)
    assert proven_sign(derivation.quantities[quantity], model) == 1
    negative = [m for m in derivation.mistakes[quantity] if proven_sign(m.expr, model) in (-1, 0)]
    if kept is None:
        assert negative == []
        assert derivation.mistakes[quantity] or quantity == "rolling_speed"  # the other slips stay
    else:
        assert any(kept in m.feedback for m in negative), derivation.mistakes[quantity]


def test_friction_sign_flip_of_a_skid_time_is_not_offered() -> None:
    v0, g, mu = (s("bowling-ball-skid", n) for n in ("v0", "g", "mu"))
    offered = [m.expr for m in bank_derivation("bowling-ball-skid").mistakes["skid_time"]]
    assert all(sympy.simplify(e + 2 * v0 / (7 * g * mu)) != 0 for e in offered), offered


@pytest.mark.parametrize(
    ("text", "sign"),
    [
        ("2*v0/(7*g*mu)", 1),
        ("-2*v0/(7*g*mu)", -1),
        ("sqrt(-g*mu)", 0),
        ("v0 - g", None),  # positive or negative depending on the values
    ],
)
def test_proven_sign_uses_the_symbols_declared_signs(text: str, sign: int | None) -> None:
    names = {n: s("bowling-ball-skid", n) for n in ("v0", "g", "mu")}
    assert proven_sign(parse_math(text, names).expr, bank_model("bowling-ball-skid")) == sign


def test_proven_sign_uses_an_angles_range() -> None:
    theta, g = s("skier-friction", "alpha"), s("skier-friction", "g")
    model = bank_model("skier-friction")
    assert proven_sign(g * sin(theta) * cos(theta), model) == 1
    assert proven_sign(-g * cos(theta), model) == -1
