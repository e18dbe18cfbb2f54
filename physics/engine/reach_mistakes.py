"""Known slips for the speed at a position and for trajectories, generated from the model (listed before
the generic ones, so that their feedback, which names the slip in the problem's own terms, wins)."""

from __future__ import annotations

import dataclasses
from collections.abc import Callable

import sympy

from physics.engine import tidy
from physics.engine.model import TRAJECTORY_KINDS, Model, Quantity, QuantityKind

Rederive = Callable[[Model, Quantity], sympy.Expr | None]
Candidates = list[tuple[sympy.Expr | None, str]]

HALF_KINETIC = (
    "Kinetic energy is $\\tfrac12 m v^2$: setting it equal to the energy gained gives $v^2 = 2(\\ldots)/m$. "
    "Check the factor 2."
)
AT_REST = (
    "That is the force if the body were at rest there. It is moving along a curve, so the net force "
    "towards the centre must also supply $m v^2/R$."
)
CENTRIPETAL_SIGN = "The centripetal acceleration points towards the centre of the curve: check the sign of the $m v^2/R$ term."
LAUNCH_COMPONENTS = (
    "The launch angle is measured from the horizontal: the vertical component of the launch velocity is "
    "$v_0 \\sin\\alpha$ and the horizontal one $v_0 \\cos\\alpha$, $\\alpha$ the launch angle. A sine and a "
    "cosine are swapped."
)
TIME_TO_APEX = (
    "That is the time to the top of the flight. The body keeps flying until it comes back down to the "
    "landing level."
)
HALF_G_TWICE = (
    "In $y = v_{y0} t - \\tfrac12 g t^2$ the factor $\\tfrac12$ belongs once: here it is used twice "
    "($g/2$ for $g$)."
)
APEX_RANGE = "That is the horizontal distance to the top of the flight, not to the landing point."
LAUNCH_LEVEL = (
    "This lands the body at the height it was launched from; it comes down to the landing level stated."
)
LEVEL_GROUND = (
    "This lands the body on level ground at the height it was launched from; it lands on the slope, "
    "which rises (or falls away) under its flight."
)
HORIZONTAL = (
    "That is the horizontal distance to the landing point; the range is measured along the slope: "
    "divide by the cosine of its angle."
)
HEIGHT_FACTOR = (
    "At the top the vertical kinetic energy $\\tfrac12 m v_{y0}^2$ has become $m g H$: check the factor 2."
)
WHOLE_SPEED = (
    "At the top the body still moves horizontally: only the vertical part of its kinetic energy, "
    "$\\tfrac12 m v_{y0}^2$, becomes potential energy."
)


def candidates(model: Model, quantity: Quantity, reference: sympy.Expr, rederive: Rederive) -> Candidates:
    if quantity.kind in TRAJECTORY_KINDS:
        return _trajectory(model, quantity, reference, rederive)
    if not quantity.at:
        return []
    if quantity.kind in (QuantityKind.SPEED, QuantityKind.VELOCITY):
        return [(reference / sympy.sqrt(2), HALF_KINETIC)]
    if quantity.kind is QuantityKind.FORCE:
        return _force(model, quantity, reference, rederive)
    return []


def _swapped(reference: sympy.Expr, slope: sympy.Expr | None) -> sympy.Expr | None:
    """The launch angle's sine and cosine swapped (a slope's own are no launch component)."""
    kept = slope.free_symbols if slope is not None else set()
    trig = {t for t in reference.atoms(sympy.sin, sympy.cos) if not t.free_symbols & kept}
    if not trig:
        return None
    swap = {t: (sympy.cos if isinstance(t, sympy.sin) else sympy.sin)(t.args[0]) for t in trig}
    return reference.subs(swap, simultaneous=True)


def _trajectory(model: Model, quantity: Quantity, reference: sympy.Expr, rederive: Rederive) -> Candidates:
    found: Candidates = [(_swapped(reference, quantity.slope), LAUNCH_COMPONENTS)]
    if quantity.kind is QuantityKind.MAX_HEIGHT:
        from physics.engine.trajectory import launch

        start = launch(model, quantity)
        vx, vy = start.velocity["x"], start.velocity["y"]
        found += [(2 * reference, HEIGHT_FACTOR)]
        if vx != 0:
            found += [(tidy.simplify(reference * (vx**2 + vy**2) / vy**2), WHOLE_SPEED)]
        return found
    launch_level = rederive(model, dataclasses.replace(quantity, level=None, slope=None))
    if quantity.level is not None:
        found += [(launch_level, LAUNCH_LEVEL)]
    if quantity.slope is not None:
        found += [(launch_level, LEVEL_GROUND)]
        if quantity.kind is QuantityKind.RANGE:
            found += [(tidy.simplify(reference * sympy.cos(quantity.slope)), HORIZONTAL)]
    if launch_level is not None and quantity.kind is QuantityKind.TIME_OF_FLIGHT:
        found += [(launch_level / 2, TIME_TO_APEX)]
        if quantity.level is None:
            found += [(2 * reference, HALF_G_TWICE)]
    if launch_level is not None and quantity.kind is QuantityKind.RANGE:
        found += [(launch_level / 2, APEX_RANGE)]
    return found


def _force(model: Model, quantity: Quantity, reference: sympy.Expr, rederive: Rederive) -> Candidates:
    """The force with the body at rest where it arrives (no centripetal term), and with that term's sign
    flipped."""
    ((name, end),) = quantity.at
    c = model.coordinate(name)
    resting = dataclasses.replace(model, state=((c.symbol, end), (c.velocity, sympy.Integer(0))))
    static = rederive(resting, dataclasses.replace(quantity, at=()))
    if static is None:
        return []
    return [(static, AT_REST), (tidy.simplify(2 * static - reference), CENTRIPETAL_SIGN)]
