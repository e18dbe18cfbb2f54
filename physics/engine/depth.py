"""Positions along z, the second horizontal axis (y is up, gravity along −y; x and z are horizontal).

A body may be placed on z so that a conical pendulum or a puck on a table can be written as it moves.
The mechanics that reads positions only through generic sums over their axes handles z: energies,
Lagrange, Newton's constraint forces (a gap's gradient in x_, y_ and z_), the simulation, steady
circular motion, pair potentials (the distance over every axis), supports moving in the time (the
chain rule in t), the `forces:` entries (a load's force on each Cartesian dof, z among them). Everything
written for the x–y plane (impacts, friction, frames, flights, elements) would ignore z and could verify a wrong model, so a model with z refuses each
of them where it is written, and a body on z is a particle (its angle would turn in the x–y plane).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping
from typing import Any

from physics.engine.model import AXES, Body, Constraint, ConstraintKind, PairPotential, Quantity, QuantityKind
from physics.engine.text import Path
from physics.errors import SpecError, SpecErrors

DEPTH = "z"
SPACE = (*AXES, DEPTH)  # a body's position or a potential's anchor; directions stay in the x–y plane

# read through generic sums over a body's axes (mechanics.py, newton.py, lagrange.py, simulation.py,
# orbits.py, modes.py); every other kind reads x and y by name
KINDS = frozenset(
    {
        QuantityKind.ACCELERATION,
        QuantityKind.FORCE,
        QuantityKind.EQUILIBRIUM,
        QuantityKind.POTENTIAL_FORCE,
        QuantityKind.STIFFNESS,
        QuantityKind.ANGULAR_FREQUENCY,
        QuantityKind.PERIOD,
        QuantityKind.SOLVE,
        QuantityKind.NORMAL_FREQUENCY,
        QuantityKind.EXPRESSION,
        QuantityKind.SPEED,
        QuantityKind.VELOCITY,
        QuantityKind.TURNING_POINT,
        QuantityKind.MODE_SHAPE,
        QuantityKind.CIRCULAR_SPEED,
        QuantityKind.REVOLUTION_PERIOD,
        QuantityKind.CIRCULAR_ENERGY,
        QuantityKind.MECHANICAL_ENERGY,
        QuantityKind.CIRCULAR_RADIUS,
        QuantityKind.EPICYCLIC_FREQUENCY,
        QuantityKind.MAXIMIZE,
        QuantityKind.MINIMIZE,
    }
)
# the sections a model with z may use; the others are written for the x–y plane
SECTIONS = frozenset(
    {
        "coordinates",
        "bodies",
        "gravity",
        "constraints",
        "potentials",
        "forces",
        "state",
        "domain",
        "quantities",
        "limits",
        "notation",
        "unused",
    }
)

PLANE_ONLY = "written for the x–y plane; a model with a body on z (the second horizontal axis) cannot use it"
SPRING_ON_Z = ": write a spring as a potential of the distance (`potentials:`), which runs over x, y and z"


def uses_depth(bodies: Iterable[Body]) -> bool:
    return any(axis == DEPTH for body in bodies for axis, _ in body.position)


def check(
    data: Mapping[str, Any],
    bodies: tuple[Body, ...],
    constraints: tuple[Constraint, ...],
    potentials: Iterable[PairPotential],
    quantities: Iterable[Quantity],
    add: Callable[[str, Path], None],
) -> None:
    """Refuse, where written, each part of a model with z that is handled in the x–y plane only."""
    for index, pair in enumerate(potentials):
        _check_pair_axes(pair, {b.name: b for b in bodies}, ("potentials", index), add)
    if not uses_depth(bodies):
        return
    for key in data:
        if key not in SECTIONS:
            add(f"the {key!r} section is {PLANE_ONLY}", (str(key),))
    for body in bodies:
        if body.angle is not None and any(axis == DEPTH for axis, _ in body.position):
            add(f"an angle is {PLANE_ONLY}: a body on z is a particle", ("bodies", body.name, "angle"))
    for constraint in constraints:
        if constraint.kind is ConstraintKind.ROLLING:  # a wheel's grip turns it in the x–y plane (grips.py)
            add(f"a rolling grip is {PLANE_ONLY}", ("constraints", constraint.name, "kind"))
    for quantity in quantities:
        for kind in _kinds(quantity):
            if kind not in KINDS:
                add(f"{kind.value} is {PLANE_ONLY}", ("quantities", quantity.name, quantity.kind.value))


def _check_pair_axes(
    pair: PairPotential, bodies: Mapping[str, Body], path: Path, add: Callable[[str, Path], None]
) -> None:
    """The distance runs over the axes both ends give: where one end gives z and the other does not (a
    fixed point written without its z), that distance would silently leave z out."""
    if not all(name in bodies for name in pair.bodies):
        return  # an unknown body, refused where it is named
    ends = [(name, {axis for axis, _ in bodies[name].position}) for name in pair.bodies]
    if len(ends) == 1:
        ends.append(("the anchor", {axis for axis, _ in pair.anchor}))
    (first, first_axes), (second, second_axes) = ends
    if (DEPTH in first_axes) == (DEPTH in second_axes):
        return
    on_z, without = (first, second) if DEPTH in first_axes else (second, first)
    add(
        f"{on_z} is on z but {without} gives no z, so the distance {pair.distance} would leave z out: "
        f"give {without}'s z too (z: 0 where it stays at z = 0)",
        (*path, "anchor" if len(pair.bodies) == 1 else "bodies"),
    )


def check_elements(data: Any, elements: object) -> None:
    """SpecErrors at `elements:` beside a body written on z: an element places its bodies, points and
    directions in the x–y plane (read before the elements are expanded, so the fault is where written)."""
    if not elements or not isinstance(data, Mapping) or not isinstance(data.get("bodies"), Mapping):
        return
    written = [b.get("position") for b in data["bodies"].values() if isinstance(b, Mapping)]
    if any(isinstance(position, Mapping) and DEPTH in position for position in written):
        raise SpecErrors([SpecError(f"the elements are {PLANE_ONLY}{SPRING_ON_Z}", ("elements",))])


def _kinds(quantity: Quantity) -> Iterable[QuantityKind]:
    """The quantity's kind and those it is built on (`maximize: alpha, of: {range: ball}`)."""
    while quantity is not None:
        yield quantity.kind
        quantity = quantity.inner  # type: ignore[assignment]
