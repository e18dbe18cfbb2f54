"""The sample points: inside every range and constraint, reproducible, and refused when none exist."""

from __future__ import annotations

import dataclasses
import math

import pytest
import sympy
from mpmath import libmp

from physics.errors import SpecError
from physics.symbolic import SymbolicContext, SymbolSpec, make_symbol, prepare_reference, sampling
from physics.symbolic.bounded import BoundedEvaluator
from tests.symbolic.support import ACCELERATION, FORCE, M, context, g, m, mu, pi, sin, sqrt, tan, theta

HALF_PI = float(pi / 2)


def values(reference, symbol):
    return [libmp.to_float(value) for value in reference.sample.columns[symbol]]


def test_points_lie_strictly_inside_an_open_range():
    reference = prepare_reference(g * sin(theta), context(g * sin(theta)))
    thetas = values(reference, theta)
    assert all(0 < value < HALF_PI for value in thetas)


def test_latin_hypercube_visits_both_halves_of_a_range():
    reference = prepare_reference(g * sin(theta), context(g * sin(theta)))
    thetas = values(reference, theta)
    assert min(thetas) < HALF_PI / 4
    assert max(thetas) > 3 * HALF_PI / 4


def test_every_point_satisfies_the_constraints():
    friction = mu * tan(theta) < 1
    reference = prepare_reference(g * sin(theta) * mu, context(g * sin(theta) * mu, constraints=(friction,)))
    for mu_value, theta_value in zip(values(reference, mu), values(reference, theta), strict=True):
        assert mu_value * math.tan(theta_value) < 1
    assert reference.sample.size == 24


@pytest.mark.parametrize(
    ("spec", "check"),
    [
        pytest.param(SymbolSpec("q", negative=True), lambda v: v < 0, id="negative"),
        pytest.param(SymbolSpec("q", real=True), lambda v: v != 0, id="real"),
        pytest.param(SymbolSpec("q", integer=True), lambda v: v == int(v) and v >= 1, id="positive-integer"),
        pytest.param(
            SymbolSpec("q", low=sympy.Integer(-1), high=sympy.Integer(1)), lambda v: -1 < v < 1, id="range"
        ),
        pytest.param(SymbolSpec("q", low=sympy.Integer(3), high=sympy.oo), lambda v: v > 3, id="half-line"),
        pytest.param(
            SymbolSpec("q", integer=True, low=sympy.Integer(2), high=sympy.Integer(5)),
            lambda v: v in (3, 4),
            id="integer-range",
        ),
    ],
)
def test_points_respect_the_symbol_spec(spec, check):
    q = make_symbol(spec)
    reference = prepare_reference(q, SymbolicContext({q: spec}))
    assert all(check(value) for value in values(reference, q))


def test_real_symbols_take_both_signs():
    spec = SymbolSpec("q", real=True)
    q = make_symbol(spec)
    signs = {value > 0 for value in values(prepare_reference(q, SymbolicContext({q: spec})), q)}
    assert signs == {True, False}


def test_the_same_reference_gets_the_same_points():
    first = prepare_reference(m * g, context(m * g))
    second = prepare_reference(m * g, context(m * g))
    assert first.sample == second.sample


def test_different_references_get_different_points():
    assert prepare_reference(m * g, context(m * g)).sample != prepare_reference(M * g, context(M * g)).sample


def test_a_new_reference_over_a_known_domain_bounds_only_its_new_subtrees(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    wedge = m * g * sin(theta) / (M + m * sin(theta) ** 2)
    first = prepare_reference(wedge, context(wedge))
    evaluated: list[sympy.Basic] = []
    evaluate = BoundedEvaluator._evaluate
    monkeypatch.setattr(
        BoundedEvaluator, "_evaluate", lambda self, expr: evaluated.append(expr) or evaluate(self, expr)
    )
    scaled = sympy.Rational(3, 4) * wedge
    second = prepare_reference(scaled, context(scaled))
    assert second.sample.columns == first.sample.columns
    # The product itself and its new factor: sin θ, the denominator and the rest were bounded before.
    assert set(evaluated) <= {scaled, sympy.Rational(3, 4)}
    monkeypatch.undo()
    afresh = BoundedEvaluator(second.sample.float_columns, second.sample.size)(scaled)
    assert afresh.values.tolist() == second.floats.values.tolist()


def test_a_domain_under_new_names_is_drawn_as_the_same_points_without_drawing_again(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """The points depend on the symbols' specs, not their names: `m_7` in kg is sampled as `m` was."""
    wedge = m * g * sin(theta) / (M + m * sin(theta) ** 2)
    first = prepare_reference(wedge, context(wedge))
    renamed_specs = {
        s: dataclasses.replace(spec, name=f"{s.name}_7") for s, spec in context(wedge).symbols.items()
    }
    renamed = {s: make_symbol(spec) for s, spec in renamed_specs.items()}
    monkeypatch.setattr(sampling, "_draw", lambda *args: pytest.fail("a known shape was drawn again"))
    second = prepare_reference(
        wedge.xreplace(renamed), SymbolicContext({renamed[s]: spec for s, spec in renamed_specs.items()})
    )
    for symbol, column in first.sample.columns.items():
        assert second.sample.columns[renamed[symbol]] == column
    assert second.values == first.values


def test_a_constrained_domain_under_new_names_is_drawn_anew() -> None:
    friction = mu * tan(theta) < 1
    expr = g * sin(theta) * mu
    first = prepare_reference(expr, context(expr, constraints=(friction,)))
    specs = context(expr).symbols
    renamed = {s: make_symbol(dataclasses.replace(spec, name=f"{s.name}_8")) for s, spec in specs.items()}
    constrained = SymbolicContext(
        {renamed[s]: dataclasses.replace(spec, name=f"{s.name}_8") for s, spec in specs.items()},
        constraints=(friction.xreplace(renamed),),
    )
    second = prepare_reference(expr.xreplace(renamed), constrained)
    for mu_value, theta_value in zip(
        values(second, renamed[mu]), values(second, renamed[theta]), strict=True
    ):
        assert mu_value * math.tan(theta_value) < 1
    assert values(second, renamed[mu]) != values(first, mu)  # constraints are named: not shared


SPEC_ERRORS = [
    ("empty-constraint", g * mu, (mu < 0,), ("constraints",)),
    ("equation-as-constraint", g * mu, (sympy.Eq(mu, 1),), ("constraints",)),
    ("reference-never-real", sqrt(-g), (), ("expected",)),
    ("undeclared-symbol", g * sympy.Symbol("zeta"), (), ("expected",)),
]


@pytest.mark.parametrize(
    ("expected", "constraints", "path"), [e[1:] for e in SPEC_ERRORS], ids=[e[0] for e in SPEC_ERRORS]
)
def test_an_unusable_reference_side_is_a_spec_error(expected, constraints, path):
    ctx = context(g * mu, constraints=constraints)
    with pytest.raises(SpecError) as raised:
        prepare_reference(expected, ctx)
    assert raised.value.path[: len(path)] == path


def test_an_empty_range_is_a_spec_error():
    spec = SymbolSpec("q", low=sympy.Integer(2), high=sympy.Integer(1))
    q = make_symbol(spec)
    with pytest.raises(SpecError) as raised:
        prepare_reference(q, SymbolicContext({q: spec}))
    assert raised.value.path == ("symbols", "q", "range")


def test_a_dimensionally_inconsistent_reference_is_a_spec_error():
    with pytest.raises(SpecError) as raised:
        prepare_reference(m + g, context(m + g))
    assert "adds" in raised.value.message


def test_the_declared_expected_dimension_must_match_the_reference():
    base = context(m * g)
    with pytest.raises(SpecError) as raised:
        prepare_reference(m * g, SymbolicContext(base.symbols, expected_dimension=ACCELERATION))
    assert raised.value.path == ("expected",)
    assert (
        prepare_reference(m * g, SymbolicContext(base.symbols, expected_dimension=FORCE)).dimension == FORCE
    )


def test_a_thin_constrained_domain_is_still_sampled():
    thin = (mu * tan(theta) > 8,)
    reference = prepare_reference(mu * g, context(mu * g * theta, constraints=thin))
    assert reference.sample.size == 24
