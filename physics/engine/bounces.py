"""The motion after the n-th bounce off a fixed partner: `{max_height: ball, after: impact, bounces: n}`.

A body that bounces off a floor flies back to it and bounces again. Each method works one cycle with
its own laws, on velocities w left free: the flight back to the contact (Newton: the body's constant
acceleration brings the normal separation back to zero after t = -2 (a . w)/(a . A), with velocities
w + A t; conservation: energy at the same place, so the same speed, turned back along the one
coordinate), then the impact (impact.METHODS: impulses, or momentum and restitution). The cycle must
be linear and diagonal in the coordinates' velocities, w -> P w, so that n bounces are P^(n-1) applied
to the velocities after the first: e^(n-1) for a ball on a floor, whatever n is, a symbol or a number.
The simulation bounces the body n times: flights integrated until the contact closes, each contact
integrated through its spring-dashpot (bounce_simulation.py).
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING

import sympy

from physics.answer_text import typed_text
from physics.engine import impact, tidy
from physics.engine.model import Impact, Model, Quantity, QuantityKind
from physics.engine.proof import domain_points
from physics.errors import DerivationError

if TYPE_CHECKING:
    from physics.engine.method import Method

Report = Callable[[str, tuple[str | int, ...]], None]
Rederive = Callable[[Model, Quantity], sympy.Expr | None]
# a body's velocity or speed just after the n-th bounce (`{final_speed: ball, bounces: n}`), or the
# kinetic energy the n-th bounce takes (`{kinetic_energy_lost: impact, bounces: n}`)
FINAL_KINDS = frozenset(
    {QuantityKind.FINAL_SPEED, QuantityKind.FINAL_VELOCITY, QuantityKind.KINETIC_ENERGY_LOST}
)
TOTAL = (
    "`total: true` with `bounces: n` takes the kinetic energy the first n bounces take together (the ball "
    "arrives at each with the energy it left the one before with); without it, the n-th bounce's alone"
)


def check(quantities: Sequence[Quantity], model_impact: Impact | None, report: Report) -> None:
    """Bounces need an impact against a fixed partner (a floor, a wall), a count of at least one, and no
    slope to land on."""
    for quantity in quantities:
        if quantity.bounces is None:
            continue
        path = ("quantities", quantity.name, "bounces")
        if model_impact is not None and model_impact.fixed is None:
            report("a body bounces again only off a fixed partner: the impact's other body moves on", path)
        if quantity.bounces.is_number and not (quantity.bounces.is_integer and quantity.bounces >= 1):
            report(f"the number of bounces is a whole number, 1 or more, not {quantity.bounces}", path)
        if quantity.slope is not None:  # the slope runs through the launch: earlier flights would cross it
            report(
                "a landing on a slope through the launch point ends the first flight after the impact, "
                "so there are no later bounces to count: ask for the slope without bounces",
                path,
            )


NTH_ALONE = (
    "That is what the last of those bounces takes alone; the question asks for the energy all of them take "
    "together, from the first bounce on."
)
ALL_TOGETHER = (
    "That is what all the bounces up to this one take together; the question asks for what this bounce "
    "alone takes, from the energy the body arrives with."
)


def mistakes(model: Model, quantity: Quantity, rederive: Rederive) -> list[tuple[sympy.Expr | None, str]]:
    """The energy lost in the n-th bounce alone taken for the first n together, and the other way round."""
    if quantity.kind is not QuantityKind.KINETIC_ENERGY_LOST or quantity.bounces is None:
        return []
    other = rederive(model, dataclasses.replace(quantity, total=not quantity.total))
    return [(other, NTH_ALONE if quantity.total else ALL_TOGETHER)]


def velocities_after(method: Method, quantity: Quantity, first: list[sympy.Expr]) -> list[sympy.Expr]:
    """The coordinates' velocities just after bounce number `quantity.bounces`, from those after the
    first, by one cycle (back to the contact, then the impact) worked with this method's own laws."""
    from physics.engine.method import NotApplicable  # here: method builds on this module

    back = _RETURNS.get(method.name)
    work = impact.METHODS.get(method.name)
    if back is None or work is None:
        raise NotApplicable(f"{method.title} does not follow a body back to the contact")
    assert quantity.bounces is not None
    model = method.model
    free = [sympy.Dummy(f"w_{c.name}", real=True) for c in model.coordinates]
    arriving = back(method, free, quantity.name)
    positions = [(s, v) for s, v in model.state if s not in {c.velocity for c in model.coordinates}]
    trial = dataclasses.replace(
        model,
        state=(*positions, *((c.velocity, v) for c, v in zip(model.coordinates, arriving, strict=True))),
    )
    _, _, after = work(trial)
    cycle = [sympy.expand(r) for r in impact.coordinate_rates(trial, after)]
    jacobian = sympy.Matrix(cycle).jacobian(free)
    linear = all(
        tidy.simplify(sympy.expand(c - (jacobian.row(i) * sympy.Matrix(free))[0])) == 0
        for i, c in enumerate(cycle)
    )
    diagonal = all(
        tidy.simplify(jacobian[i, j]) == 0 for i in range(len(free)) for j in range(len(free)) if i != j
    )
    if not (linear and diagonal and not jacobian.has(*free)):
        raise DerivationError(
            f"{quantity.name}: one bounce does not repeat the last (the velocities after a cycle are "
            f"{typed_text(cycle)} of those before): the n-th bounce needs a cycle that scales each velocity",
            quantity=quantity.name,
        )
    count = quantity.bounces
    factors = [tidy.simplify(jacobian[i, i]) for i in range(len(free))]
    result = [tidy.simplify(f ** (count - 1) * v) for f, v in zip(factors, first, strict=True)]
    method.step(
        "Each bounce repeats the last: back at the contact and bounced again, each velocity is multiplied by",
        r",\ ".join(method.tex(f) for f in factors)
        + r";\ \text{after bounce } "
        + method.tex(count)
        + r":\ "
        + r",\ ".join(
            method.tex(sympy.Eq(c.velocity, v)) for c, v in zip(model.coordinates, result, strict=True)
        ),
    )
    return result


def final(method: Method, quantity: Quantity, worked: impact.Worked) -> sympy.Expr:
    """A body's velocity or speed just after the n-th bounce, from this method's worked first impact."""
    steps, before, after = worked
    for title, latex in steps:
        method.step(title, latex)
    model = method.model
    first = impact.coordinate_rates(model, after)
    rates = velocities_after(method, quantity, first)
    if quantity.kind is QuantityKind.KINETIC_ENERGY_LOST and not quantity.total:
        # into the n-th bounce the body arrives with the kinetic energy it left the one before with: the
        # flight back to the same place keeps T + V (the cycle's return: by energy, or at constant
        # acceleration); the first bounce's own factor undone, n = 1 gives the first impact's loss. With
        # `total`, the same return makes the first n bounces' losses telescope: the energy before the
        # first less that after the n-th
        assert quantity.bounces is not None
        earlier = velocities_after(method, dataclasses.replace(quantity, bounces=quantity.bounces - 1), first)
        before = _by_body(model, earlier)
    return impact.answer(((), before, _by_body(model, rates)), model, quantity, method.step)


def _by_body(model: Model, rates: list[sympy.Expr]) -> impact.Velocities:
    """The bodies' velocities from the coordinates' rates at the contact."""
    found = impact.contact(model)
    cartesian = [
        sympy.Add(*(found.jacobian[i, j] * r for j, r in enumerate(rates)))
        for i in range(len(found.mech.dofs))
    ]
    return impact.by_body(found.mech, cartesian)


def _contact_row(model: Model) -> list[sympy.Expr]:
    """a: the normal separation's rate is a . q' (at the state, where the contact is)."""
    return impact.contact(model).generalized


def _pulled_back(model: Model, rate: sympy.Expr, name: str) -> None:
    """The separation's acceleration must bring the body back: negative on the whole domain."""
    negative = rate.is_negative
    if negative is None:
        try:
            negative = all(float(rate.subs(p)) < 0 for p in domain_points(model, 12, seed=13))
        except (TypeError, ValueError):
            negative = False
    if not negative:
        raise DerivationError(
            f"{name}: after the bounce nothing brings the body back to the contact (the separation's acceleration is "
            f"{typed_text(rate)}): it bounces once",
            quantity=name,
        )


def _as_velocities(model: Model, leaving: list[sympy.Expr], expr: sympy.Expr) -> sympy.Expr:
    """A formula in the velocities just after a bounce, written with the coordinates' velocities."""
    return expr.xreplace({w: c.velocity for w, c in zip(leaving, model.coordinates, strict=True)})


def _back_at_constant_acceleration(method: Method, leaving: list[sympy.Expr], name: str) -> list[sympy.Expr]:
    """Newton: the body's own constant accelerations A bring the separation a . q back to zero."""
    model = method.model
    moving = {c.symbol for c in model.coordinates} | {c.velocity for c in model.coordinates}
    accelerations = [tidy.simplify(method.free.acceleration(c.name)) for c in model.coordinates]
    if any(a.free_symbols & moving for a in accelerations):
        raise DerivationError(
            f"between bounces the accelerations {typed_text(accelerations)} are not constant: the flight back "
            "to the contact has no closed form here"
        )
    row = _contact_row(model)
    towards = tidy.simplify(sum((r * a for r, a in zip(row, accelerations, strict=True)), sympy.Integer(0)))
    _pulled_back(model, towards, name)
    parting = sum((r * w for r, w in zip(row, leaving, strict=True)), sympy.Integer(0))
    time = -2 * parting / towards
    arriving = [w + a * time for w, a in zip(leaving, accelerations, strict=True)]
    method.step(
        "Between bounces the acceleration is constant: the separation from the contact returns to zero after",
        "t = " + method.tex(_as_velocities(model, leaving, tidy.simplify(time))),
    )
    return arriving


def _back_by_energy(method: Method, leaving: list[sympy.Expr], name: str) -> list[sympy.Expr]:
    """Conservation: the momentum of every coordinate the contact does not move (cyclic, with a constant
    mass matrix) is conserved, so its velocity is unchanged; back at the same place with the same
    energy, the one coordinate along the normal has the same speed, turned back."""
    model, mech = method.model, method.mech
    row = _contact_row(model)
    along = [i for i, a in enumerate(row) if a != 0]
    mass = mech.mass_matrix
    moving = {c.symbol for c in model.coordinates} | {c.velocity for c in model.coordinates}
    others = [i for i in range(len(row)) if i not in along]
    if (
        len(along) != 1
        or mass.free_symbols & moving
        or not mass.is_diagonal()
        or any(mech.potential.has(model.coordinates[i].symbol) for i in others)
    ):
        raise DerivationError(
            "the energy gives the return to the contact when one coordinate moves along the normal and the "
            "others are free (cyclic, with a constant mass matrix)"
        )
    (k,) = along
    normal = model.coordinates[k]
    force = -sympy.diff(mech.potential, normal.symbol).subs(dict(model.state))
    _pulled_back(model, tidy.simplify(row[k] * force), name)
    kept = [model.coordinates[i] for i in others]
    method.step(
        "Between bounces the energy is conserved: back at the contact at the same speed along the normal, "
        "moving the other way" + (", the free coordinates' momenta unchanged" if kept else ""),
        method.tex(normal.velocity)
        + r"\to "
        + method.tex(-normal.velocity)
        + "".join(r",\ " + method.tex(c.velocity) + r"\to " + method.tex(c.velocity) for c in kept),
    )
    return [-w if i == k else w for i, w in enumerate(leaving)]


_RETURNS: dict[str, Callable[[Method, list[sympy.Expr], str], list[sympy.Expr]]] = {
    "newton": _back_at_constant_acceleration,
    "conservation": _back_by_energy,
}


def counted(
    quantity: Quantity, points: Sequence[dict[sympy.Symbol, float]]
) -> list[dict[sympy.Symbol, float]]:
    """Points at which the simulation bounces a whole number of times: a symbolic count takes 1, 2, 3."""
    if quantity.bounces is None:
        return list(points)
    free = sorted(quantity.bounces.free_symbols, key=str)
    return [{**point, **{s: float(1 + i % 3) for s in free}} for i, point in enumerate(points)]
