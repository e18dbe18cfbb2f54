"""An angle coordinate's value typed in degrees, where every angle is read in radians.

A pendulum's or a conical pendulum's state written `phi: 30` (30° meant) is 30 radians: cos(30) is
0.154, not 0.866, and every method reads the same number, agrees, and verifies the cone's rate as
sqrt(g/(L cos(30))). An angle coordinate (one a position turns: inside a sine or cosine with a plain
number for its factor, never a length over a radius) given a plain number past a full turn at the state
or at a quantity's `at` is refused where it was written, saying how the degrees are written. Past a
full turn, and not a right angle as for an incline's slope: a coordinate may legitimately swing past
the horizontal or over the top.
"""

from __future__ import annotations

import math
from collections.abc import Iterator

import sympy

from physics.engine.model import Model
from physics.engine.text import Path
from physics.errors import DerivationError

_TRIGONOMETRIC = (sympy.sin, sympy.cos, sympy.tan)


def check_angles_in_radians(model: Model) -> None:
    """DerivationError at the first plain number past a full turn given to an angle coordinate."""
    angles = angle_coordinates(model)
    for path, symbol, value in _placed(model):
        if symbol not in angles or not isinstance(value, sympy.Number):  # 3*pi is radians already
            continue
        number = float(value)
        if abs(number) <= 2 * math.pi:
            continue
        text = str(value)
        raise DerivationError(
            f"{text} radians is {math.degrees(number):.0f}°, past a full turn: angles are in radians, so "
            f"{text}° is written {text}*pi/180",
            path=path,
        )


def angle_coordinates(model: Model) -> set[sympy.Symbol]:
    """The coordinates a body's position turns by: inside a sine, cosine or tangent with a plain number
    for its factor (theta, 2*theta, theta + alpha; not x/R, a length rolled)."""
    coordinates = {c.symbol for c in model.coordinates}
    found: set[sympy.Symbol] = set()
    for body in model.bodies:
        for _, expr in body.position:
            for call in expr.atoms(*_TRIGONOMETRIC):
                argument = call.args[0]
                for symbol in argument.free_symbols & coordinates:
                    factor = sympy.diff(argument, symbol)
                    if factor.is_number and factor != 0:
                        found.add(symbol)
    return found


def _placed(model: Model) -> Iterator[tuple[Path, sympy.Symbol, sympy.Expr]]:
    """Each coordinate's value at the state and at each quantity's `at`, with where it was written."""
    symbols = {c.symbol: c.name for c in model.coordinates}
    for symbol, value in model.state:
        if symbol in symbols:
            yield ("state", symbols[symbol]), symbol, value
    for quantity in model.quantities:
        for name, value in quantity.at:
            yield ("quantities", quantity.name, "at", name), model.coordinate(name).symbol, value
    if model.collision is not None:
        for field, values in (("at", model.collision.at), ("reaches", model.collision.reaches)):
            for name, value in values:
                yield ("collision", field, name), model.coordinate(name).symbol, value
