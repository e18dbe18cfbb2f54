"""Checks of the model itself, beside the methods' agreement (which only proves the algebra: every
method reads the same model, so a wrong model is derived "consistently").

- dimensions: done when the model is loaded with its symbols' dimensions (`load_model`);
- energy bookkeeping: the integrated motion's change of T + V equals the work of the non-conservative
  forces, and kinetic friction only takes energy out;
- limiting cases the author states (`limits:`), taken on the derived expressions;
- friction to zero: the derived expression tends to what the frictionless model derives.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable, Mapping
from functools import partial

import sympy

from physics.answer_text import typed_text
from physics.engine import damping, tidy
from physics.engine.mechanics import Mechanics
from physics.engine.method import Method, NotApplicable
from physics.engine.model import Model, Quantity, QuantityKind
from physics.engine.proof import domain_points, prove_equal
from physics.engine.simulation import Simulator
from physics.errors import DerivationError

ENERGY_POINTS = 3
MethodFactory = Callable[[Model, Mechanics], Method]


def physical_checks(
    model: Model, quantities: Mapping[str, sympy.Expr], simulator: Simulator, factory: MethodFactory
) -> dict[str, str]:
    """name -> what was shown; DerivationError (with the model path) when a check fails."""
    checks: dict[str, str] = {}
    if model.dimensions_checked:
        checks["dimensions"] = (
            "every position is a length; every mass, inertia, energy, gravity, gap and state consistent"
        )
    try:
        balance = simulator.energy_balance(domain_points(model, ENERGY_POINTS, seed=9))
    except ArithmeticError as error:  # an integration that overflows or divides by zero: the model's fault
        raise DerivationError(
            f"energy balance: the simulation failed: {type(error).__name__}: {error}", path=()
        ) from error
    if balance is not None:
        checks["energy balance"] = (
            f"{balance.compared}: worst relative gap {balance.max_relative_error:.1e} at {balance.points} points"
        )
    for index, stated in enumerate(model.limits):
        where = ", ".join(f"{s} → {typed_text(v)}" for s, v in stated.where)
        for name, expected in stated.expect:
            _check_limit(
                model, quantities[name], stated.where, expected, ("limits", index, "expect", name), name
            )
            checks[f"limit {name} ({where})"] = stated.description or f"{name} → {typed_text(expected)}"
    checks.update(_frictionless(model, quantities, factory))
    checks.update(damping.undamped_checks(model, quantities, partial(_frequency, factory)))
    return checks


def _frequency(factory: MethodFactory, model: Model, coordinate: str) -> sympy.Expr:
    method = factory(model, Mechanics(model))
    return method.answer(Quantity("undamped", QuantityKind.ANGULAR_FREQUENCY, coordinate))


def _limit_of(expr: sympy.Expr, where: tuple[tuple[sympy.Symbol, sympy.Expr], ...]) -> sympy.Expr:
    for symbol, value in where:
        expr = sympy.limit(expr, symbol, value) if value.is_infinite or expr.has(symbol) else expr
    return tidy.simplify(expr)


def _check_limit(
    model: Model,
    reference: sympy.Expr,
    where: tuple[tuple[sympy.Symbol, sympy.Expr], ...],
    expected: sympy.Expr,
    path: tuple[str | int, ...],
    name: str,
) -> None:
    found = _limit_of(reference, where)
    if tidy.simplify(found - expected) == 0:
        return
    shown = ", ".join(f"{s} → {typed_text(v)}" for s, v in where)
    if found.has(sympy.oo, -sympy.oo, sympy.zoo, sympy.nan, sympy.AccumBounds):
        raise DerivationError(
            f"{name} = {typed_text(reference)} tends to {typed_text(found)} as {shown}, not {typed_text(expected)}",
            path=path,
        )
    try:
        prove_equal(found, expected, model, name, ("the derived limit", "the stated limit"))
    except DerivationError:
        raise DerivationError(
            f"{name} = {typed_text(reference)} tends to {typed_text(found)} as {shown}; the stated limit is {typed_text(expected)}",
            path=path,
        ) from None


def _frictionless(
    model: Model, quantities: Mapping[str, sympy.Expr], factory: MethodFactory
) -> dict[str, str]:
    """Each answer with friction tends, as every coefficient goes to zero, to the frictionless model's."""
    coefficients = [f.coefficient for f in model.frictions if isinstance(f.coefficient, sympy.Symbol)]
    if not coefficients or len(coefficients) != len(model.frictions):
        return {}
    smooth = dataclasses.replace(model, frictions=())
    method = factory(smooth, Mechanics(smooth))
    checks: dict[str, str] = {}
    for quantity in model.quantities:
        reference = quantities[quantity.name]
        if quantity.kind is QuantityKind.SOLVE or not reference.has(*coefficients):
            continue
        try:
            expected = method.answer(quantity)
        except (NotApplicable, DerivationError):
            continue
        where = tuple((c, sympy.Integer(0)) for c in coefficients)
        # the coefficient may stand in the author's own formula too (friction's work, -mu*N*d): it goes
        # to zero there as well
        expected = _limit_of(expected, where)
        _check_limit(model, reference, where, expected, ("friction",), quantity.name)
        checks[f"limit {quantity.name} (no friction)"] = (
            f"tends to the frictionless model's {typed_text(expected)}"
        )
    return checks
