"""The value of a parameter at which a quantity is largest (`maximize`) or smallest (`minimize`): the
rope angle that gives a block pulled over a rough floor its largest acceleration (tan α = μ), the launch
angle of the longest range on level ground (π/4).

Each method differentiates its own expression of the inner quantity, dQ/dp = 0. The root kept is the
one the parameter's declared sign and range allow (roots.py); the second derivative there must have the
kind's sign (negative for a maximum) at every sampled point of the domain, and where the parameter has
a declared range the quantity, sampled across it, must nowhere beat the extremum (an end of the range
can be larger than a local maximum). The simulation measures the inner quantity on runs at three values
about the derived one and compares the vertex of the parabola through them.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import sympy

from physics.answer_text import typed_text
from physics.engine import tidy
from physics.engine.model import EXTREMUM_KINDS, Model, Quantity, QuantityKind
from physics.engine.proof import domain_points
from physics.engine.quantity_table import derives
from physics.engine.roots import admissible, declared_range
from physics.errors import DerivationError

if TYPE_CHECKING:
    from physics.engine.method import Method
    from physics.engine.simulation import Measured, Point, Simulator

POINTS = 8  # domain points at which the curvature's sign and the sweep across the range are checked
SWEEP = 41  # parameter values across its declared range
SPREAD = 0.01  # the simulated runs take the parameter at (1 ± SPREAD) times the derived value
_ROUNDING = 1e-9
# quantities that are themselves a parameter's value: their simulations start from the derived value
PARAMETER_VALUED = EXTREMUM_KINDS | {QuantityKind.SOLVE, QuantityKind.SLIPPING}


@derives(*EXTREMUM_KINDS)
def extremum(method: Method, quantity: Quantity) -> sympy.Expr:
    """The parameter value where this method's inner quantity is stationary, of the asked kind."""
    inner, parameter = quantity.inner, quantity.parameter
    assert inner is not None and parameter is not None
    model, name, largest = method.model, quantity.name, quantity.kind is QuantityKind.MAXIMIZE
    what = described(inner)
    value = _without_abs(method.answer(inner), model)
    if not value.has(parameter):
        raise DerivationError(
            f"{name}: {what} = {typed_text(value)} does not depend on {parameter}", quantity=name
        )
    slope = tidy.simplify(sympy.diff(value, parameter))
    found = _other_turns(tidy.solve(slope, parameter), slope, parameter, model)
    bend = sympy.diff(value, parameter, 2)
    # the stationary values the parameter's sign and range allow, and of those the maxima (minima)
    stationary = [
        (root, tidy.simplify(bend.subs(parameter, root))) for root in admissible(found, parameter, model)
    ]
    extreme = [(root, c) for root, c in stationary if _of_sign(-c if largest else c, model)]
    if len(extreme) != 1:
        raise DerivationError(
            f"{name}: expected one {'maximum' if largest else 'minimum'} of {what} in {parameter}'s declared "
            f"sign and range, found {typed_text([r for r, _ in extreme])} among the stationary values "
            f"{typed_text([r for r, _ in stationary])} (second derivatives {typed_text([c for _, c in stationary])}; "
            f"all the roots of the derivative in {parameter}: {typed_text(found)})",
            quantity=name,
        )
    ((root, curvature),) = extreme
    root = _simplest(tidy.simplify(root), model)
    _check_range(value, parameter, root, largest, model, (name, what))
    symbol = method.tex(parameter)
    method.step(
        f"{'Largest' if largest else 'Smallest'} {what}: its derivative in ${symbol}$ vanishes",
        rf"\frac{{\partial}}{{\partial {symbol}}}\left({method.tex(value)}\right) = {method.tex(slope)} = 0"
        rf"\Rightarrow {symbol} = {method.tex(root)},\ \frac{{\partial^2}}{{\partial {symbol}^2}} = "
        + method.tex(curvature)
        + (r" < 0" if largest else r" > 0"),
    )
    return root


def _other_turns(
    found: list[sympy.Expr], slope: sympy.Expr, parameter: sympy.Symbol, model: Model
) -> list[sympy.Expr]:
    """The roots with those an arctangent's branch leaves out: solve gives tan(2α − θ) = −cot θ one α,
    θ/2 − π/4, where the launch angle of the longest range up an incline is π/4 + θ/2, a half-turn of
    2α on. Each shift of a quarter or a half turn that also makes the derivative vanish (at the domain's
    points) is a root too; the declared range then chooses."""
    points = domain_points(model, POINTS, seed=41)
    shifted = []
    for root in found:
        if not root.has(sympy.atan):
            continue
        for turn in (sympy.pi / 2, -sympy.pi / 2, sympy.pi, -sympy.pi):
            other = root + turn
            if all(abs(complex(sympy.N(slope.subs(parameter, other).subs(p), 30))) < 1e-20 for p in points):
                shifted.append(other)
    return found + shifted


def described(quantity: Quantity) -> str:
    """ "the acceleration of x", for messages and titles."""
    words = quantity.kind.value.replace("_", " ")
    return f"the {words} of {quantity.target}" if quantity.target else f"the {words}"


def _without_abs(expr: sympy.Expr, model: Model) -> sympy.Expr:
    """|e| replaced by e or -e where e keeps one sign at the domain's points: a derivative of |e| cannot
    be solved (an energy's sqrt(v^2) leaves |sin(alpha)| in a range)."""
    for term in expr.atoms(sympy.Abs):
        (argument,) = term.args
        values = [_number(argument.subs(point)) for point in domain_points(model, POINTS, seed=37)]
        if all(v > 0 for v in values):
            expr = expr.subs(term, argument)
        elif all(v < 0 for v in values):
            expr = expr.subs(term, -argument)
    return tidy.simplify(expr)


def _simplest(root: sympy.Expr, model: Model) -> sympy.Expr:
    """An angle root in its simplest equal form: solve writes tan(a) = mu as 2*atan((sqrt(mu^2 + 1) - 1)/mu),
    which is atan(mu) on the domain, and atan(1/tan(theta)) for pi/2 - theta (each checked at its points:
    the inverse functions' branches differ)."""
    if not root.has(sympy.atan, sympy.asin, sympy.acos):
        return root
    candidates = [
        inverse(tidy.simplify(sympy.expand_trig(function(root))))
        for function, inverse in ((sympy.tan, sympy.atan), (sympy.sin, sympy.asin), (sympy.cos, sympy.acos))
    ]
    candidates += [  # atan(cot u) is pi/2 - u where u is within a right angle
        tidy.simplify(root.subs(term, sympy.pi / 2 - term.args[0].base.args[0]))
        for term in root.atoms(sympy.atan)
        if term.args[0].is_Pow and term.args[0].exp == -1 and isinstance(term.args[0].base, sympy.tan)
    ]
    equal = [
        c
        for c in candidates
        if all(
            abs(_number(c.subs(point)) - _number(root.subs(point))) < _ROUNDING
            for point in domain_points(model, POINTS, seed=41)
        )
    ]
    return min([root, *equal], key=sympy.count_ops)


def _of_sign(expr: sympy.Expr, model: Model) -> bool:
    """expr > 0 under the symbols' assumptions, or else at every one of a set of domain points."""
    if expr.is_positive is not None:
        return bool(expr.is_positive)
    try:
        return all(float(expr.subs(point)) > 0 for point in domain_points(model, POINTS, seed=29))
    except (TypeError, ValueError):
        return False


def _check_range(
    value: sympy.Expr,
    parameter: sympy.Symbol,
    root: sympy.Expr,
    largest: bool,
    model: Model,
    names: tuple[str, str],
) -> None:
    """No value of the parameter across its declared range (where the domain holds) beats the root's."""
    bounds = declared_range(parameter, model)
    if bounds is None or not all(math.isfinite(b) for b in bounds):
        return
    low, high = bounds
    name, inner = names
    sign = 1.0 if largest else -1.0
    for sampled in domain_points(model, POINTS, seed=31):
        point = {s: v for s, v in sampled.items() if s != parameter}
        best = sign * _number(value.subs(point).subs(parameter, root.subs(point)))
        for k in range(SWEEP):
            at = {**point, parameter: sympy.Float(low + (high - low) * k / (SWEEP - 1))}
            if not all(_number(p.subs(at)) > 0 for p in model.positive):
                continue
            there = sign * _number(value.subs(at))
            if math.isfinite(there) and there > best + _ROUNDING * max(1.0, abs(best)):
                raise DerivationError(
                    f"{name}: {parameter} = {typed_text(root)} is a local "
                    f"{'maximum' if largest else 'minimum'} only: at {parameter} = {float(at[parameter]):.4g} "
                    f"{inner} is {'larger' if largest else 'smaller'} ({sign * there:.6g} against "
                    f"{sign * best:.6g}, at "
                    + ", ".join(f"{s}={float(v):.4g}" for s, v in point.items() if s != parameter)
                    + ")",
                    quantity=name,
                )


def _number(expr: sympy.Expr) -> float:
    try:
        return float(expr)
    except (TypeError, ValueError):
        return math.nan


def measure(simulator: Simulator, quantity: Quantity, point: Point, expected: float) -> Measured:
    """The vertex of the parabola through the inner quantity measured on runs at three parameter values
    about the derived one; it must open the asked way."""
    inner, parameter = quantity.inner, quantity.parameter
    assert inner is not None and parameter is not None
    measure_inner = simulator.measure_for(inner)
    if measure_inner is None or inner.kind in PARAMETER_VALUED:  # those measures steer by the value
        raise DerivationError(f"{quantity.name}: no simulation measures {inner.name}", quantity=quantity.name)
    step = SPREAD * (abs(expected) or 1.0)
    below, at, above = (
        measure_inner(inner, {**point, parameter: expected + shift}, 0.0)[1] for shift in (-step, 0.0, step)
    )
    bend = above - 2 * at + below
    largest = quantity.kind is QuantityKind.MAXIMIZE
    if not (bend < 0 if largest else bend > 0):
        raise DerivationError(
            f"{quantity.name}: the integrated {inner.kind.value.replace('_', ' ')} is not "
            f"{'largest' if largest else 'smallest'} near {parameter} = {expected:.6g}: {below:.8g}, {at:.8g}, "
            f"{above:.8g} at {expected - step:.6g}, {expected:.6g}, {expected + step:.6g}",
            quantity=quantity.name,
        )
    vertex = expected + step * (below - above) / (2 * bend)
    return (
        f"vertex of the parabola through the integrated {inner.kind.value.replace('_', ' ')} at three values of "
        f"{parameter} about the derived one",
        vertex,
        None,
    )
