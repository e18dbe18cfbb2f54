"""Which way an impact's impulse acts when the author does not give its normal.

Two free particles that stick together exchange the impulse mu (v1 - v2) (mu the reduced mass): along
their relative velocity. So sticking is a smooth impact with restitution 0 whose normal is that
relative velocity, and no more; a body held by a constraint also takes the constraint's impulse, which
turns the exchange away from the relative velocity, so sticking is refused there.

Without `stick` and without a `normal`, the normal is the x axis. That is only the author's meaning
when the bodies approach along x: bodies approaching across the plane would keep their sideways
velocities, which is no "perfectly inelastic" collision anyone posed, so a normal must then be given.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import sympy

from physics.engine import tidy
from physics.engine.model import Body, Constraint, Coordinate

Axes = tuple[tuple[str, sympy.Expr], ...]


def velocity(
    body: Body, coordinates: Sequence[Coordinate], state: Mapping[sympy.Symbol, sympy.Expr]
) -> dict[str, sympy.Expr]:
    """The body's Cartesian velocity at the state (velocities left out are 0)."""
    at = {s: v for s, v in state.items() if any(s == c.symbol for c in coordinates)}
    return {
        axis: tidy.simplify(
            sympy.Add(
                *(sympy.diff(expr, c.symbol) * state.get(c.velocity, sympy.Integer(0)) for c in coordinates)
            ).subs(at)
        )
        for axis, expr in body.position
    }


def relative_velocity(
    first: Body,
    second: Body | None,
    coordinates: Sequence[Coordinate],
    state: Mapping[sympy.Symbol, sympy.Expr],
) -> dict[str, sympy.Expr]:
    """v_first - v_second (a fixed partner does not move), on every axis either body moves along."""
    mine = velocity(first, coordinates, state)
    other = velocity(second, coordinates, state) if second is not None else {}
    axes = sorted({*mine, *other})
    return {a: tidy.simplify(mine.get(a, sympy.Integer(0)) - other.get(a, sympy.Integer(0))) for a in axes}


def stuck_normal(relative: Mapping[str, sympy.Expr]) -> Axes | None:
    """The relative velocity as the normal; None when the bodies do not approach at all."""
    if all(v == 0 for v in relative.values()):
        return None
    return tuple((axis, v) for axis, v in relative.items() if v != 0)


def across_x(relative: Mapping[str, sympy.Expr]) -> bool:
    """The approach has a component off the x axis (not proven zero): x is then no safe default normal."""
    return any(axis != "x" and v != 0 for axis, v in relative.items())


def held(body: str, constraints: Sequence[Constraint]) -> list[str]:
    """The constraints whose gap involves the body's Cartesian coordinates."""
    names = {f"{axis}_{body}" for axis in ("x", "y", "phi")}
    return [c.name for c in constraints if any(s.name in names for s in c.gap.free_symbols)]
