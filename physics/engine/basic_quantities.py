"""The quantities every method gives from its own basics: accelerations, constraint forces, the
equilibrium and small oscillations about it, terminal velocities, formulas of other quantities, and
the value of a parameter that makes a quantity vanish."""

from __future__ import annotations

from typing import TYPE_CHECKING

import sympy

from physics.engine import modes, tidy
from physics.engine.model import Quantity, QuantityKind
from physics.engine.quantity_table import derives

if TYPE_CHECKING:
    from physics.engine.method import Method


@derives(QuantityKind.ACCELERATION)
def acceleration(method: Method, quantity: Quantity) -> sympy.Expr:
    return method.acceleration(quantity.target)


@derives(QuantityKind.FORCE)
def force(method: Method, quantity: Quantity) -> sympy.Expr:
    return method.force(quantity.target)


@derives(QuantityKind.POTENTIAL_FORCE)
def potential_force(method: Method, quantity: Quantity) -> sympy.Expr:
    return method.potential_force(quantity.target)


@derives(QuantityKind.EQUILIBRIUM)
def equilibrium(method: Method, quantity: Quantity) -> sympy.Expr:
    return method.equilibrium(quantity.target)


@derives(QuantityKind.STIFFNESS)
def stiffness(method: Method, quantity: Quantity) -> sympy.Expr:
    """-dQ/dq at the equilibrium (the other coordinates where they rest with it)."""
    q = method.model.coordinate(quantity.target).symbol
    rest = method.rest(quantity.target)
    value = tidy.simplify(-sympy.diff(method.potential_force(quantity.target), q).subs(rest))
    generalized = method.mech.notation.letters.generalized
    method.step(
        f"Stiffness at the equilibrium of {method.named(quantity.target)}",
        rf"-\left.\frac{{\partial {generalized}_{{{method.tex(q)}}}}}{{\partial {method.tex(q)}}}"
        rf"\right|_{{{method.tex(q)}_{{\mathrm{{eq}}}}}} = " + method.tex(value),
    )
    return value


@derives(QuantityKind.ANGULAR_FREQUENCY)
def angular_frequency(method: Method, quantity: Quantity) -> sympy.Expr:
    return method.frequency(quantity.target, method.equilibrium(quantity.target))


@derives(QuantityKind.PERIOD)
def period(method: Method, quantity: Quantity) -> sympy.Expr:
    return tidy.simplify(2 * sympy.pi / angular_frequency(method, quantity))


@derives(QuantityKind.NORMAL_FREQUENCY)
def normal_frequency(method: Method, quantity: Quantity) -> sympy.Expr:
    return modes.pick(method.mode_frequencies, quantity)


@derives(QuantityKind.TERMINAL_VELOCITY)
def terminal_velocity(method: Method, quantity: Quantity) -> sympy.Expr:
    return method.terminal_velocity(quantity.target)


@derives(QuantityKind.EXPRESSION)
def expression(method: Method, quantity: Quantity) -> sympy.Expr:
    """The author's formula, each quantity it uses derived by this same method."""
    assert quantity.expression is not None
    values = {symbol: method.answer(method.model.quantity(name)) for symbol, name in quantity.uses}
    return tidy.simplify(quantity.expression.subs(values))


@derives(QuantityKind.SOLVE)
def solve(method: Method, quantity: Quantity) -> sympy.Expr:
    """The parameter value that makes the inner quantity vanish, by this method's inner quantity."""
    assert quantity.inner is not None and quantity.parameter is not None
    inner = quantity.inner
    what = f"the {inner.kind.value.replace('_', ' ')} of {inner.target}" if inner.target else inner.name
    return method.solve_for(quantity.parameter, method.answer(inner), quantity.name, what)
