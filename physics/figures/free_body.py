"""Free-body diagrams drawn from a model: the forces on one body, as arrows from its centre.

The weight comes from gravity; each constraint the body takes part in pushes or pulls along the gradient
of its gap (a surface's normal force, a string's tension, rolling friction), as the engine's multipliers
do; kinetic friction opposes the sliding. Directions are those in the configuration the scene draws
(configuration.py: the model's state, or where the scene places a body) with the given or typical
values. A contact keeps one label in every diagram of the problem (the incline's N on the block is the N
on the wedge, opposite; a pendulum's T on the bob pulls its cart at the pivot); friction against a
moving surface is drawn on both bodies. A body under gravity that the model moves only along x (a cart)
stands on a floor that the model leaves out, pushing it up: N. Springs, other potentials, given forces and drag come from loads.py (a
spring's direction is taken where the body rests); constraints of kind "other" (a wire, a hoop, a pivot
or axle, a floor's grip) from held.py, which reads what they are from their gaps.
"""

from __future__ import annotations

import math
from collections import Counter
from collections.abc import Mapping
from dataclasses import dataclass
from functools import lru_cache

import sympy

from physics.engine import depth
from physics.engine.model import AppliedForce, Constraint, ConstraintKind, ForceKind, Model
from physics.engine.notation import notation_of, split_subscript
from physics.figures.configuration import drawn_configuration
from physics.figures.figure import BLOCK, Values, body_label
from physics.figures.geometry import is_linear
from physics.figures.held import held_forces
from physics.figures.loads import applied_forces, potential_forces
from physics.figures.svg import FILLS, Canvas
from physics.wording import symbol_label

_LABELS = {ConstraintKind.SURFACE: "N", ConstraintKind.STRING: "T", ConstraintKind.ROLLING: "f"}
ARROW = 2.2
RIGID = 0.8  # drawn radius of a rigid body
FORCE_LABEL = 0.55  # force labels read at the size of the page's text, the diagram scaled to a column
SIDE_BY_SIDE = 0.5  # how far apart arrows along one line are drawn
# pixels to the model's unit: a page shows every body's diagram at this one size, so the arrows of one
# compare with another's (each scaled to its box, a lone weight's arrow was drawn the longest)
SCALE = 36.0


@dataclass(frozen=True)
class Force:
    label: str
    direction: tuple[float, float]  # unit vector, y up
    # on a rigid body: the signed lever arm of its line of action about the centre (torque / force,
    # anticlockwise positive), in the model's lengths, and the symbol that writes it (r)
    lever: float = 0.0
    lever_label: str = ""
    at_rim: bool = False  # a rolling contact: it acts where the body touches the surface
    # on a round rigid body: where on its rim the force acts, as a unit vector from the centre (a
    # surface's push and kinetic friction act where the body touches the surface, as textbooks draw them)
    contact: tuple[float, float] | None = None


def _unit(x: float, y: float) -> tuple[float, float] | None:
    norm = math.hypot(x, y)
    return None if not math.isfinite(norm) or norm < 1e-12 else (x / norm, y / norm)


def body_forces(model: Model, body_name: str, given: Mapping[str, float]) -> list[Force]:
    """The forces on `body_name`: weight, constraint forces, kinetic friction, springs and other
    potentials, given forces and drag, with directions. A contact has one label in every body's
    diagram: numbered across the model when two contacts of one kind (two strings, two surfaces) would
    otherwise share it."""
    body = model.body(body_name)
    forces: list[Force] = []
    if model.gravity is not None:
        mass = body.mass.name if isinstance(body.mass, sympy.Symbol) else "m"
        gravity = model.gravity.name if isinstance(model.gravity, sympy.Symbol) else "g"
        forces.append(Force(f"{symbol_label(mass)}{symbol_label(gravity)}", (0.0, -1.0)))
    forces += _contact_forces(model, tuple(sorted(given.items())))[body_name]
    # Springs are named by their constants, as the scene labels them: two springs k are both Fₖ there
    # too, so they are not numbered (Fₖ₁ would read as the spring k₁).
    values = Values(model, given)
    loads = potential_forces(model, body_name, values) + applied_forces(model, body_name, values)
    return forces + [Force(label, direction) for label, direction in loads]


# ("constraint", its name), ("friction", its index in the model) or ("floor", the body's name)
_Source = tuple[str, str | int]


@lru_cache(maxsize=16)
def _contact_forces(model: Model, given: tuple[tuple[str, float], ...]) -> dict[str, tuple[Force, ...]]:
    """Every body's contact forces, labelled together: a problem's diagrams are drawn one body at a
    time, and each needs the others' contacts to number its own."""
    values = Values(model, dict(given))
    drawn = drawn_configuration(model, dict(given))
    contacts = {body.name: _contacts(model, body.name, values, drawn) for body in model.bodies}
    labels = _named(
        model,
        _contact_labels(model, {source: base for found in contacts.values() for source, base, _ in found}),
    )
    return {
        name: tuple(
            Force(
                labels[source],
                direction,
                *_lever(model, name, source, values, drawn),
                at_rim=source[0] == "constraint"
                and model.constraint(str(source[1])).kind is ConstraintKind.ROLLING,
                contact=_contact_point(model, name, source, direction, found),
            )
            for source, _, direction in found
        )
        for name, found in contacts.items()
    }


def _round_surface(model: Model, body_name: str, source: _Source) -> bool:
    """Whether `source` is a surface a rigid body touches with its rim: a surface's gap that does not
    turn with the body (a wheel's, a ball's) pushes along the line through its centre, from the point
    where the body touches it. A ladder's floor turns with it (the gap holds its angle): its foot, not
    its rim, touches; it keeps its lever arm."""
    body = model.body(body_name)
    if body.angle is None or source[0] != "constraint":
        return False
    constraint = model.constraint(str(source[1]))
    if constraint.kind is not ConstraintKind.SURFACE:
        return False
    turn = dict(model.cartesian).get(f"phi_{body_name}")
    return turn is None or turn not in constraint.gap.free_symbols


def _contact_point(
    model: Model,
    body_name: str,
    source: _Source,
    direction: tuple[float, float],
    found: list[tuple[_Source, str, tuple[float, float]]],
) -> tuple[float, float] | None:
    """Where on a round rigid body's rim a force acts: a surface's push where the body touches it
    (opposite the push, from the centre); friction, kinetic or rolling, at the same point when the body
    touches one surface (a rolling friction with a lever arm is drawn at its arm's end, the same point).
    None for every other force (drawn from the body's edge along its line of action)."""
    if _round_surface(model, body_name, source):
        return (-direction[0], -direction[1])
    rolls = source[0] == "constraint" and model.constraint(str(source[1])).kind is ConstraintKind.ROLLING
    if source[0] != "friction" and not rolls:
        return None
    touching = [d for s, _, d in found if _round_surface(model, body_name, s)]
    return (-touching[0][0], -touching[0][1]) if len(touching) == 1 else None


def _named(model: Model, labels: dict[_Source, str]) -> dict[_Source, str]:
    """The worked solutions' names for the contacts (N₁ from the wedge on the block, T, f), where they
    have a plain form; a pin's one arrow (the resultant of R_x and R_y) takes the letter, R."""
    notation = notation_of(model)
    named = dict(labels)
    for source, label in labels.items():
        kind, key = source
        if kind == "constraint" and str(key) in notation.forces:
            name = notation.forces[str(key)]
            base, _ = split_subscript(name.tex)
            if label.startswith("F") and len(base) == 1:  # the pin's resultant
                named[source] = base
            elif name.text:
                named[source] = name.text
        elif kind == "friction" and isinstance(key, int) and key < len(notation.frictions):
            named[source] = notation.frictions[key].text or label
    return named


def _lever(
    model: Model, body_name: str, source: _Source, values: Values, drawn: dict[sympy.Symbol, float]
) -> tuple[float, str]:
    """A constraint force's lever arm about a rigid body's centre: its torque over its force, from the
    gap's gradient (d gap/d phi over the length of d gap/d(x, y)), and the symbol it is (the yo-yo's r)."""
    body = model.body(body_name)
    names = dict(model.cartesian)
    if body.angle is None or source[0] != "constraint" or f"phi_{body_name}" not in names:
        return 0.0, ""
    gap = model.constraint(str(source[1])).gap
    turn = sympy.diff(gap, names[f"phi_{body_name}"])
    pushes = [sympy.diff(gap, names[f"{a}_{body_name}"]) if f"{a}_{body_name}" in names else 0 for a in "xy"]
    size = sympy.sqrt(sum(p**2 for p in pushes))
    if turn == 0 or size == 0:
        return 0.0, ""
    arm = sympy.simplify(turn / size)
    try:
        number = values.number(arm, drawn)
    except (TypeError, ValueError, ZeroDivisionError):
        return 0.0, ""
    named = [s for s in arm.free_symbols if s in set(model.parameters)]
    label = symbol_label(named[0].name) if len(named) == 1 and abs(arm) == named[0] else ""
    return number, label


def _contact_labels(model: Model, drawn: dict[_Source, str]) -> dict[_Source, str]:
    """One label per contact force drawn on any body (`drawn` gives each its letter), in the model's
    order."""
    order: list[_Source] = [("constraint", c.name) for c in model.constraints]
    order += [("floor", body.name) for body in model.bodies]
    order += [("friction", i) for i in range(len(model.frictions))]
    sources = [(source, drawn[source]) for source in order if source in drawn]
    shared = Counter(base for _, base in sources)
    counts: Counter[str] = Counter()
    labels: dict[_Source, str] = {}
    for source, base in sources:
        if shared[base] > 1:
            counts[base] += 1
            labels[source] = base + str(counts[base]).translate(_SUB)
        else:
            labels[source] = base
    return labels


def across_the_page(model: Model, body_name: str, given: Mapping[str, float]) -> str:
    """Why the diagram, of the x–y plane, would leave out part of a force on a body on z ("" where it
    would not): the body is off the page (z ≠ 0) where the scene draws it, a constraint or a potential
    (a spring to a point off the page) pulls it along z there, or a given force or drag may push it
    along z."""
    body = model.body(body_name)
    if not any(axis == depth.DEPTH for axis, _ in body.position):
        return ""
    for force in model.forces:
        if force.body == body_name and _along_z(force):
            given_force = force.kind is ForceKind.APPLIED
            return "a given force on it has a part along z" if given_force else "drag on it may act along z"
    values = Values(model, given)
    place = _place(model, values, drawn_configuration(model, dict(given)))
    z = model.cartesian_symbol(f"{depth.DEPTH}_{body_name}")
    lengths = [p.length(model, dict(model.cartesian)) for p in model.potentials if body_name in p.bodies]
    pulls = [c.gap for c in model.constraints if z in c.gap.free_symbols] + lengths
    try:
        if abs(place[z]) > 1e-9:
            return f"it is off the page where the problem is drawn (z = {place[z]:.3g})"
        # not "> 1e-9": a slope that is no number (a spring of length 0) leaves the force's way unknown
        if any(not abs(values.number(sympy.diff(pull, z), place)) <= 1e-9 for pull in pulls):
            return "a constraint or a spring pulls it along z where the problem is drawn"
    except (KeyError, TypeError, ValueError, ZeroDivisionError):
        return "its place where the problem is drawn is not defined"
    return ""


def _along_z(force: AppliedForce) -> bool:
    """A given force with a z component, or drag, which opposes a velocity that may run along z."""
    return force.kind is not ForceKind.APPLIED or any(axis == depth.DEPTH for axis, _ in force.components)


def _place(model: Model, values: Values, drawn: dict[sympy.Symbol, float]) -> dict[sympy.Symbol, float]:
    """Every body's Cartesian coordinates (and the time) where the configuration `drawn` puts them."""
    place = dict(drawn)  # the time too: a gap that moves with it is taken where the scene draws it
    for other in model.bodies:
        for name, expr in [
            *((f"{axis}_{other.name}", e) for axis, e in other.position),
            *([(f"phi_{other.name}", other.angle)] if other.angle is not None else []),
        ]:
            try:
                place[model.cartesian_symbol(name)] = values.number(expr, drawn)
            except (TypeError, ValueError, ZeroDivisionError):
                continue
    return place


def _contacts(
    model: Model, body_name: str, values: Values, drawn: dict[sympy.Symbol, float]
) -> list[tuple[_Source, str, tuple[float, float]]]:
    """The constraint and friction forces on one body in the configuration `drawn`, each with its
    source, its letter and direction."""
    place = _place(model, values, drawn)
    found: list[tuple[_Source, str, tuple[float, float]]] = []
    held: list[tuple[Constraint, tuple[float, float]]] = []  # kind "other": a wire, a pivot, a grip
    names = dict(model.cartesian)
    x, y = names.get(f"x_{body_name}"), names.get(f"y_{body_name}")
    for constraint in model.constraints:
        if not {s for s in (x, y) if s is not None} & constraint.gap.free_symbols:
            continue
        # A body the model moves along one axis only (a cart) would feel only that component of a
        # pull along the line to another body (a pendulum's rod): it feels the whole of the other
        # body's, reversed. A string over a pulley (a linear gap) pulls each body its own way.
        joined = None in (x, y) and not is_linear(constraint.gap, model)
        partner = _partner(model, body_name, constraint) if joined else None
        try:
            if partner is None:
                gradient = [_slope(constraint, s, place, values) for s in (x, y)]
            else:
                gradient = [-_slope(constraint, names[f"{axis}_{partner}"], place, values) for axis in "xy"]
        except (TypeError, ValueError, ZeroDivisionError):  # not defined in the drawn configuration
            continue
        direction = _unit(gradient[0], gradient[1])
        if direction is None:
            continue
        if constraint.kind is ConstraintKind.OTHER:
            held.append((constraint, direction))
            continue
        found.append((("constraint", constraint.name), _LABELS[constraint.kind], direction))
    found = _along_surfaces(model, found)
    if model.gravity is not None and x is not None and y is None:
        found.append((("floor", body_name), "N", (0.0, 1.0)))
    for index, friction in enumerate(model.frictions):
        if body_name not in (friction.body, friction.against):
            continue
        slider = model.body(friction.body)
        coordinate = model.coordinate(friction.sliding).symbol
        try:
            along = [values.number(sympy.diff(expr, coordinate), drawn) for _, expr in slider.position]
        except (TypeError, ValueError, ZeroDivisionError):
            continue
        axes = [axis for axis, _ in slider.position]
        vx = along[axes.index("x")] if "x" in axes else 0.0
        vy = along[axes.index("y")] if "y" in axes else 0.0
        reaction = -1.0 if body_name == friction.against else 1.0  # the surface body feels -f
        direction = _unit(-vx * reaction, -vy * reaction)
        if direction is not None:
            found.append((("friction", index), "f", direction))
    return found + held_forces(model, body_name, values, held, found)


def _along_surfaces(
    model: Model, found: list[tuple[_Source, str, tuple[float, float]]]
) -> list[tuple[_Source, str, tuple[float, float]]]:
    """Rolling friction turned along the surface it rolls on: a rolling constraint's gap (the arc
    rolled against the turn) may follow only the body's x, which is along the surface only where that is
    level (a ball off the bottom of a bowl)."""
    normals = [
        d
        for (kind, name), _, d in found
        if kind == "constraint" and model.constraint(str(name)).kind is ConstraintKind.SURFACE
    ]
    if len(normals) != 1:
        return found
    nx, ny = normals[0]
    turned = []
    for (kind, name), label, (dx, dy) in found:
        if kind == "constraint" and model.constraint(str(name)).kind is ConstraintKind.ROLLING:
            across = dx * nx + dy * ny
            along = _unit(dx - across * nx, dy - across * ny)
            if along is not None:
                (dx, dy) = along
        turned.append(((kind, name), label, (dx, dy)))
    return turned


def _slope(
    constraint: Constraint, symbol: sympy.Symbol | None, place: dict[sympy.Symbol, float], values: Values
) -> float:
    """The constraint's gap's rate of change with one of a body's Cartesian coordinates (0 if it has none)."""
    return 0.0 if symbol is None else values.number(sympy.diff(constraint.gap, symbol), place)


def _partner(model: Model, body_name: str, constraint: Constraint) -> str | None:
    """The one other body the constraint joins to `body_name`, if that body moves in both x and y."""
    names = dict(model.cartesian)
    free = constraint.gap.free_symbols
    others = [
        b.name
        for b in model.bodies
        if b.name != body_name and {names.get(f"x_{b.name}"), names.get(f"y_{b.name}")} & free
    ]
    if len(others) != 1 or not {f"x_{others[0]}", f"y_{others[0]}"} <= set(names):
        return None
    return others[0]


_SUB = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")


def _drawn_arms(forces: list[Force]) -> list[float]:
    """Each force's lever arm as drawn on a wheel of radius RIGID: the longest at the rim, the others in
    proportion; a lone lever arm (a string on an axle) at half the radius, inside the body, unless it is
    a rolling contact's, which acts at the rim."""
    longest = max((abs(f.lever) for f in forces), default=0.0)
    if longest == 0:
        return [0.0 for _ in forces]
    alone = sum(1 for f in forces if f.lever) == 1 and not any(f.at_rim for f in forces if f.lever)
    return [
        0.0 if not f.lever else math.copysign(RIGID * (0.5 if alone else abs(f.lever) / longest), f.lever)
        for f in forces
    ]


def _clear_of_labels(
    at: tuple[float, float], direction: tuple[float, float], labelled: list[tuple[float, float]]
) -> tuple[float, float]:
    """`at`, or farther along the force's direction until it is clear of the labels already placed: two
    arrows close and parallel (a weight and a string on a wheel's axle) would have their labels meet."""
    for _ in range(4):
        if all(abs(at[0] - x) > 0.75 or abs(at[1] - y) > 0.5 for x, y in labelled):
            break
        at = (at[0] + direction[0] * 0.5, at[1] + direction[1] * 0.5)
    return at


def _arm_label_at(start: tuple[float, float], direction: tuple[float, float]) -> tuple[float, float]:
    """Beside a lever arm's middle, on the side its force points to: two arms' labels would meet in the
    corner between them on the other side."""
    return (start[0] / 2 + direction[0] * 0.3, start[1] / 2 + direction[1] * 0.3)


def _clear_of_arms(forces: list[Force], arms: list[float]) -> tuple[float, float]:
    """Where a wheel's name goes: the quarter of the wheel farthest from its lever arms and their labels,
    and from the arrows drawn across it from a contact point."""
    taken = []
    for force, arm in zip(forces, arms, strict=True):
        dx, dy = force.direction
        if arm:
            start = (arm * dy, -arm * dx)
            taken += [(start[0] / 2, start[1] / 2), _arm_label_at(start, force.direction)]
        elif force.contact is not None:
            cx, cy = force.contact[0] * RIGID, force.contact[1] * RIGID
            taken += [(cx + dx * t, cy + dy * t) for t in (0.0, 0.4, 0.8, 1.2, 1.6)]
    quarters = [(RIGID * 0.45 * sx, RIGID * 0.5 * sy) for sx, sy in ((1, -1), (-1, -1), (-1, 1), (1, 1))]
    return max(quarters, key=lambda q: min(math.dist(q, point) for point in taken))


def _arrow_from(
    canvas: Canvas, start: tuple[float, float], force: Force, labelled: list[tuple[float, float]]
) -> None:
    """The force's arrow from `start` along its direction, labelled clear of the labels already placed."""
    dx, dy = force.direction
    tip = (start[0] + dx * ARROW, start[1] + dy * ARROW)
    canvas.arrow(start, tip, width=0.07, color="#a11111")
    at = _clear_of_labels((tip[0] + dx * 0.5, tip[1] + dy * 0.5), force.direction, labelled)
    canvas.text(at, force.label, size=FORCE_LABEL)
    labelled.append(at)


def free_body_figure(model: Model, body_name: str, given: Mapping[str, float], *, title: str) -> str:
    """SVG of the forces on one body (role img, <title>, <desc> listing the forces and directions)."""
    canvas = Canvas()
    body = model.body(body_name)
    label = body_label(body, model)
    half = BLOCK / 2
    across = bool(across_the_page(model, body_name, given))
    forces = [] if across else body_forces(model, body_name, given)
    arms = _drawn_arms(forces)
    if body.angle is not None:  # a rigid body: a wheel, each force drawn where its line of action passes
        canvas.circle((0.0, 0.0), RIGID, fill=FILLS[0])
        for arm in sorted({abs(a) for a in arms if a} - {RIGID}):
            canvas.circle((0.0, 0.0), arm, fill=FILLS[3])  # the axle a string is wound on
    else:
        canvas.polygon([(-half, -half), (half, -half), (half, half), (-half, half)], fill=FILLS[0])
    # the centre is where the lever arms start, and a contact's push crosses it
    if body.angle is not None and (any(arms) or any(f.contact for f in forces)):
        canvas.text(_clear_of_arms(forces, arms), label, size=0.36)
    elif len(label) <= 3:
        canvas.text((0.0, 0.0), label)
    else:  # a body's name does not fit inside it: beside it, clear of the forces along the axes
        canvas.text((half + 0.15, half + 0.3), label, size=0.36, anchor="start")
    said = []
    drawn: list[tuple[float, float]] = []
    labelled: list[tuple[float, float]] = []  # where the forces' labels are
    for force, arm in zip(forces, arms, strict=True):
        dx, dy = force.direction
        if arm:  # from the point where the lever arm meets the line of action, the arm drawn dashed
            start = (arm * dy, -arm * dx)
            canvas.line((0.0, 0.0), start, width=0.03, dashed=True)
            if force.lever_label:
                canvas.text(_arm_label_at(start, force.direction), force.lever_label, size=0.42)
            _arrow_from(canvas, start, force, labelled)
            said.append(
                f"{force.label} at {round(math.degrees(math.atan2(dy, dx)))}° from the +x axis, acting "
                f"{'left' if start[0] < 0 else 'right' if start[0] > 0 else 'off'} of the centre"
                + (f" at lever arm {force.lever_label}" if force.lever_label else "")
            )
            continue
        if force.contact is not None and body.angle is not None:  # from where the body touches
            _arrow_from(canvas, (force.contact[0] * RIGID, force.contact[1] * RIGID), force, labelled)
            said.append(
                f"{force.label} at {round(math.degrees(math.atan2(dy, dx)))}° from the +x axis, at the contact"
            )
            continue
        # Forces along one line (a spring and drag, two tensions) are drawn side by side, not on top.
        beside = sum(1 for ex, ey in drawn if ex * dx + ey * dy > math.cos(math.radians(8)))
        drawn.append(force.direction)
        shift = ((-dy, dx) if beside % 2 else (dy, -dx)) if beside else (0.0, 0.0)
        offset = SIDE_BY_SIDE * ((beside + 1) // 2)
        ox, oy = shift[0] * offset, shift[1] * offset
        tip = (dx * ARROW + ox, dy * ARROW + oy)
        edge = RIGID if body.angle is not None else half
        canvas.arrow((dx * edge + ox, dy * edge + oy), tip, width=0.07, color="#a11111")
        away = 0.5 + 0.45 * beside  # labels of arrows side by side stagger along them, clear of each other
        at = _clear_of_labels((tip[0] + dx * away, tip[1] + dy * away), force.direction, labelled)
        canvas.text(at, force.label, size=FORCE_LABEL)
        labelled.append(at)
        degrees = round(math.degrees(math.atan2(dy, dx)))
        said.append(f"{force.label} at {degrees}° from the +x axis")
    description = f"Forces on {label}: " + ("; ".join(said) if said else "none") + "."
    if across:
        description = f"Forces on {label}: not drawn, as where the problem is drawn {label} is off the page or pulled across it (along z)."
    return canvas.svg(f"Free-body diagram: {title}, {label}", description, unit=SCALE)
