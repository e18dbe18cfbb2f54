"""Free-body diagrams drawn from a model: the forces on one body, as arrows from its centre.

The weight comes from gravity; each constraint the body takes part in pushes or pulls along the gradient
of its gap (a surface's normal force, a string's tension, rolling friction), as the engine's multipliers
do; kinetic friction opposes the sliding. Directions are those at the model's reference configuration
(every coordinate 0) with the given or typical values. Springs, other potentials, given forces and drag
come from loads.py (a spring's direction is taken where the body rests).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass

import sympy

from physics.engine.model import ConstraintKind, Model
from physics.figures.loads import applied_forces, potential_forces
from physics.figures.scene import BLOCK, Values, body_label, symbol_label
from physics.figures.svg import FILLS, Canvas

_LABELS = {ConstraintKind.SURFACE: "N", ConstraintKind.STRING: "T", ConstraintKind.ROLLING: "f"}
ARROW = 2.2
SIDE_BY_SIDE = 0.5  # how far apart arrows along one line are drawn


@dataclass(frozen=True)
class Force:
    label: str
    direction: tuple[float, float]  # unit vector, y up


def _unit(x: float, y: float) -> tuple[float, float] | None:
    norm = math.hypot(x, y)
    return None if not math.isfinite(norm) or norm < 1e-12 else (x / norm, y / norm)


def body_forces(model: Model, body_name: str, given: Mapping[str, float]) -> list[Force]:
    """The forces on `body_name`: weight, constraint forces, kinetic friction, springs and other
    potentials, given forces and drag, with directions."""
    values = Values(model, given)
    body = model.body(body_name)
    at_rest = {c.symbol: 0.0 for c in model.coordinates}
    place: dict[sympy.Symbol, float] = {}
    for other in model.bodies:
        for name, expr in [
            *((f"{axis}_{other.name}", e) for axis, e in other.position),
            *([(f"phi_{other.name}", other.angle)] if other.angle is not None else []),
        ]:
            try:
                place[model.cartesian_symbol(name)] = values.number(expr, at_rest)
            except (TypeError, ValueError, ZeroDivisionError):
                continue
    forces: list[Force] = []
    if model.gravity is not None:
        mass = body.mass.name if isinstance(body.mass, sympy.Symbol) else "m"
        gravity = model.gravity.name if isinstance(model.gravity, sympy.Symbol) else "g"
        forces.append(Force(f"{symbol_label(mass)}{symbol_label(gravity)}", (0.0, -1.0)))
    names = dict(model.cartesian)
    for constraint in model.constraints:
        x, y = names.get(f"x_{body_name}"), names.get(f"y_{body_name}")
        if not {s for s in (x, y) if s is not None} & constraint.gap.free_symbols:
            continue
        try:
            gradient = [
                values.number(sympy.diff(constraint.gap, s), place) if s is not None else 0.0 for s in (x, y)
            ]
        except (TypeError, ValueError, ZeroDivisionError):  # not defined at the reference configuration
            continue
        direction = _unit(gradient[0], gradient[1])
        if direction is None or constraint.kind is ConstraintKind.OTHER:
            continue
        label = _LABELS.get(constraint.kind, constraint.name)
        forces.append(Force(label, direction))
    for friction in model.frictions:
        if friction.body != body_name:
            continue
        coordinate = model.coordinate(friction.sliding).symbol
        try:
            along = [values.number(sympy.diff(expr, coordinate), at_rest) for _, expr in body.position]
        except (TypeError, ValueError, ZeroDivisionError):
            continue
        axes = [axis for axis, _ in body.position]
        vx = along[axes.index("x")] if "x" in axes else 0.0
        vy = along[axes.index("y")] if "y" in axes else 0.0
        direction = _unit(-vx, -vy)
        if direction is not None:
            forces.append(Force("f", direction))
    # Two forces of one kind (two strings, two surfaces) are told apart by number.
    seen: dict[str, int] = {}
    for force in forces:
        seen[force.label] = seen.get(force.label, 0) + 1
    counts: dict[str, int] = {}
    numbered = []
    for force in forces:
        if seen[force.label] > 1:
            counts[force.label] = counts.get(force.label, 0) + 1
            numbered.append(Force(force.label + str(counts[force.label]).translate(_SUB), force.direction))
        else:
            numbered.append(force)
    # Springs are named by their constants, as the scene labels them: two springs k are both Fₖ there
    # too, so they are not numbered (Fₖ₁ would read as the spring k₁).
    loads = potential_forces(model, body_name, values) + applied_forces(model, body_name, values)
    return numbered + [Force(label, direction) for label, direction in loads]


_SUB = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")


def free_body_figure(model: Model, body_name: str, given: Mapping[str, float], *, title: str) -> str:
    """SVG of the forces on one body (role img, <title>, <desc> listing the forces and directions)."""
    canvas = Canvas()
    body = model.body(body_name)
    label = body_label(body, model)
    half = BLOCK / 2
    canvas.polygon([(-half, -half), (half, -half), (half, half), (-half, half)], fill=FILLS[0])
    if len(label) <= 3:
        canvas.text((0.0, 0.0), label)
    else:  # a body's name does not fit inside it: beside it, clear of the forces along the axes
        canvas.text((half + 0.15, half + 0.3), label, size=0.36, anchor="start")
    said = []
    drawn: list[tuple[float, float]] = []
    for force in body_forces(model, body_name, given):
        dx, dy = force.direction
        # Forces along one line (a spring and drag, two tensions) are drawn side by side, not on top.
        beside = sum(1 for ex, ey in drawn if ex * dx + ey * dy > math.cos(math.radians(8)))
        drawn.append(force.direction)
        shift = ((-dy, dx) if beside % 2 else (dy, -dx)) if beside else (0.0, 0.0)
        offset = SIDE_BY_SIDE * ((beside + 1) // 2)
        ox, oy = shift[0] * offset, shift[1] * offset
        tip = (dx * ARROW + ox, dy * ARROW + oy)
        canvas.arrow((dx * half + ox, dy * half + oy), tip, width=0.07, color="#a11111")
        away = 0.5 + 0.45 * beside  # labels of arrows side by side stagger along them, clear of each other
        canvas.text((tip[0] + dx * away, tip[1] + dy * away), force.label)
        degrees = round(math.degrees(math.atan2(dy, dx)))
        said.append(f"{force.label} at {degrees}° from the +x axis")
    description = f"Forces on {label}: " + ("; ".join(said) if said else "none") + "."
    return canvas.svg(f"Free-body diagram: {title}, {label}", description)
