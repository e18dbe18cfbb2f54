"""A surface's or a string's gap is a clearance: its force is the multiplier because the gap grows as fast
as the body moves away from the contact (a string's slack, as fast as each end moves along it).

Written as a square (`x^2 + y^2 - R^2` for the outside of a circle) or a multiple (`2*(d - R)`), the gap
still vanishes on the same surface, so every method agrees, the simulation too (it reads the same
multiplier), and the contact's sign checks pass; but the multiplier is the force divided by how fast the
gap grows, and a car's normal force over a hump verifies as m (g R - v^2)/(2 R^2). So each body the gap
places (its x and y) must move it at unit rate: |grad gap| = 1 for a surface, and a whole number for a
string (a body the string passes under, on a movable pulley, takes up twice its slack), at sampled
domain points with the coordinates at the state. Refused at the constraint otherwise, saying the rate.
"""

from __future__ import annotations

import sympy

from physics.answer_text import typed_text
from physics.engine.grips import state_points
from physics.engine.mechanics import Mechanics
from physics.engine.model import Constraint, ConstraintKind, Model
from physics.errors import DerivationError

_TOLERANCE = 1e-9


def check_clearances(model: Model, mech: Mechanics) -> None:
    """DerivationError at the first surface or string whose gap does not grow at unit rate (a string:
    a whole number of times) as each body it places moves off."""
    points = state_points(model, mech)
    planar = [b.name for b in model.bodies if len(b.position) > 1]  # in the x–y plane, or in space
    for constraint in model.constraints:
        if constraint.kind not in (ConstraintKind.SURFACE, ConstraintKind.STRING):
            continue
        rates = {body.name: _rate(mech, constraint, body.name) for body in model.bodies}
        placed = [name for name, rate in rates.items() if rate is not None]
        # a body placed on one axis only (a cart under a pendulum) feels the force's part along it: its
        # rate is no clearance's; judged by the bodies in the plane, where the gap places any
        judged = [name for name in placed if name in planar] or placed
        for body in judged:
            rate = rates[body]
            assert rate is not None
            values = [_value(rate, mech, point) for point in points]
            if all(_allowed(constraint.kind, v) for v in values if v is not None):
                continue
            raise DerivationError(
                _message(model, constraint, body, rate), path=("constraints", constraint.name)
            )


def _rate(mech: Mechanics, constraint: Constraint, body: str) -> sympy.Expr | None:
    """|grad gap| over the body's x and y, None where the gap does not place it."""
    axes = [d.symbol for d in mech.dofs if d.body == body and not d.name.startswith("phi_")]
    parts = [sympy.diff(constraint.gap, axis) for axis in axes if constraint.gap.has(axis)]
    if not parts:
        return None
    return sympy.sqrt(sympy.Add(*(p**2 for p in parts)))


def _value(rate: sympy.Expr, mech: Mechanics, point: dict[sympy.Symbol, sympy.Expr]) -> float | None:
    place = {d.symbol: d.mapping for d in mech.dofs}
    found = sympy.N(rate.subs(place).subs(point), 15)
    if not found.is_number:  # the time of a support moving as prescribed, left free
        return None
    value = complex(found)
    return value.real if abs(value.imag) < _TOLERANCE * max(1.0, abs(value.real)) else None


def _allowed(kind: ConstraintKind, rate: float) -> bool:
    if rate < _TOLERANCE:  # the body moves along the contact here: nothing to compare
        return True
    if kind is ConstraintKind.SURFACE:
        return abs(rate - 1) < 1e-6
    return abs(rate - round(rate)) < 1e-6 * rate  # a string: one per strand that pulls the body


def _message(model: Model, constraint: Constraint, body: str, rate: sympy.Expr) -> str:
    place = {d.symbol: d.mapping for d in Mechanics(model).dofs}
    shown = sympy.simplify(rate.subs(place).subs(dict(model.state)))
    what = (
        "a surface's gap is the clearance, the distance the body can move before it touches, so that its "
        "multiplier is the normal force"
        if constraint.kind is ConstraintKind.SURFACE
        else "a string's gap is its slack, which grows as fast as each end moves along it (a whole number of "
        "times for a body it passes under), so that its multiplier is the tension"
    )
    return (
        f"constraint {constraint.name!r}: its gap {typed_text(constraint.gap)} grows {typed_text(shown)} times as "
        f"fast as {body} moves off the contact: {what}, and here it would be the force divided by "
        f"{typed_text(shown)}. Write the distance itself (sqrt(x^2 + y^2) - R, not x^2 + y^2 - R^2)"
    )
