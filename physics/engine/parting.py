"""After a perfectly inelastic impact the bodies touch, at one velocity along the normal; the motion the
model asks about next (`after: impact`) is taken without the contact, so it holds only where the free
motion then parts them, or keeps them just touching.

A cart that runs into one at rest on a spring, and does not bounce, is pushed along by the first while
the spring slows it: the two move on pressed together, one body. Free of each other, the first would
pass through the second, and the spring's greatest squeeze was verified as m1 u sqrt(m2/k)/(m1 + m2),
the second cart's alone, not m1 u/sqrt(k (m1 + m2)). So the separation along the normal, s, which
starts at zero with zero rate, must not start to shrink: its first time derivative along the free motion
(Lagrange's accelerations, the state left free) that is not zero must be positive on the domain, else
the model is refused at the impact. A ball that does not bounce off a floor is refused the same way
(gravity would take it through the floor).
"""

from __future__ import annotations

import dataclasses

import sympy

from physics.answer_text import typed_text
from physics.engine import impact, tidy
from physics.engine.lagrange import LagrangeMethod
from physics.engine.mechanics import Mechanics
from physics.engine.model import AXES, Model
from physics.engine.signs import Sign, sign_on_domain
from physics.errors import DerivationError

_ORDERS = 4  # s, s', s'' ... up to s'''': the spring's push grows only with the squeeze (s''' here)


def check_parting(model: Model) -> None:
    """DerivationError at the impact where, after a perfectly inelastic one, the motion the model asks
    about would take the bodies into each other (or one into its fixed partner)."""
    hit = model.impact
    if hit is None or hit.restitution != 0 or model.time is not None:
        return
    if not any(q.after for q in model.quantities):
        return
    _, _, after = impact.by_conservation(model)
    rates = impact.coordinate_rates(model, after)
    state = dict(model.state)
    at = {c.symbol: state.get(c.symbol, c.symbol) for c in model.coordinates}
    at |= {c.velocity: rate for c, rate in zip(model.coordinates, rates, strict=True)}
    free = dataclasses.replace(model, state=(), impact=None)
    lagrange = LagrangeMethod(free, Mechanics(free))
    flow = {c.symbol: c.velocity for c in model.coordinates}
    flow |= {c.velocity: lagrange.acceleration(c.name) for c in model.coordinates}
    derivative = _separation(model)
    for order in range(1, _ORDERS + 1):
        derivative = sympy.Add(*(sympy.diff(derivative, s) * rate for s, rate in flow.items()))
        value = tidy.simplify(derivative.subs(at))
        if value == 0:
            continue
        found = sign_on_domain(value, model)
        if found.sign in (Sign.NEGATIVE, Sign.MIXED):
            parts = " and ".join(hit.bodies) if hit.fixed is None else f"{hit.bodies[0]} and {hit.fixed}"
            raise DerivationError(
                f"after the perfectly inelastic impact {parts} would close on each other: their separation "
                f"along the normal starts to shrink (its derivative of order {order} is {typed_text(value)}), "
                "so in the motion the model asks about they pass through each other. They move on pressed "
                "together, as one body: ask about that motion in a model of its own, the pair one body with the "
                "velocity just after in its state",
                path=("impact",),
            )
        return


def _separation(model: Model) -> sympy.Expr:
    """n . (r_second - r_first) in the coordinates (the struck point of a rigid body, its `points`): the
    partner fixed, n . (r_state - r_first)."""
    hit = model.impact
    assert hit is not None
    n = impact.unit_normal(model)
    points = dict(hit.points)

    def where(body: str) -> dict[str, sympy.Expr]:
        return dict(points.get(body, ())) or dict(model.body(body).position)

    first = where(hit.bodies[0])
    if hit.fixed is None:
        second = where(hit.bodies[1])
    else:
        state = dict(model.state)
        second = {axis: expr.subs(state) for axis, expr in first.items()}
    zero = sympy.Integer(0)
    return sympy.Add(*(n[a] * (second.get(a, zero) - first.get(a, zero)) for a in AXES))


def check_release(model: Model) -> None:
    """An explosion (`release: Q`) parts bodies that are together before, at rest relative to each other
    along the normal: it adds Q of kinetic energy. Bodies that meet at a speed and `release` the energy
    a sticking collision loses would gain it twice over, and every method and the simulation agree on
    those velocities; refused at the impact."""
    hit = model.impact
    if hit is None or hit.release is None:
        return
    found = impact.contact(model)
    closing = tidy.simplify(-sympy.Add(*(c * v for c, v in zip(found.normal_row, found.before, strict=True))))
    if closing == 0:
        return
    raise DerivationError(
        f"`release: {typed_text(hit.release)}` is an explosion: it adds that kinetic energy to bodies "
        f"that are together before, but here they close along the normal at {typed_text(closing)} at the "
        "state. Bodies that collide and stick lose energy: write `restitution: 0` (or `stick: true`) and "
        "ask the energy lost as {kinetic_energy_lost: impact}",
        path=("impact", "release"),
    )
