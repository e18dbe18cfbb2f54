"""`load_model`: a model section (parsed YAML/JSON data) validated into a `Model`, every fault at once."""

from __future__ import annotations

import dataclasses
import re
from collections.abc import Callable, Mapping
from functools import partial
from typing import Any, TypeVar

import sympy

from physics.answer_text import typed_text
from physics.dimensions import Dimension
from physics.engine import (
    amplitude,
    bounces,
    depth,
    embedding,
    evaluated_at,
    forcing,
    mode_shapes,
    reach_loading,
    released,
    scenarios,
    sticking,
)
from physics.engine.dimensional import check_dimensions
from physics.engine.distances import with_distance_sides
from physics.engine.elements import expand_elements
from physics.engine.loads import ForceEntryLoad
from physics.engine.loads import entries as force_kinds
from physics.engine.model import (
    AXES,
    EFFECTIVE_KINDS,
    EXTREMUM_KINDS,
    IMPACT_KINDS,
    SLIP_KINDS,
    STEADY_KINDS,
    Body,
    Collision,
    Constraint,
    ConstraintKind,
    Coordinate,
    Frame,
    Friction,
    Impact,
    Model,
    PairPotential,
    Quantity,
    QuantityKind,
    StatedLimit,
)
from physics.engine.notation import read_notation
from physics.engine.text import Path, read_expr
from physics.errors import SpecError, SpecErrors

_TIME = re.compile(r"(?<![A-Za-z0-9_])t(?![A-Za-z0-9_])")
_NAME = re.compile(r"^[A-Za-z][A-Za-z0-9]*$")
_SECTIONS = frozenset(
    {
        "coordinates",
        "bodies",
        "gravity",
        "constraints",
        "friction",
        "potentials",
        "collision",
        "state",
        "domain",
        "quantities",
        "limits",
        "forces",
        "impact",
        "frame",
        "notation",
        "unused",
        released.KEY,
    }
)
_QUANTITY_TARGET = {
    QuantityKind.ACCELERATION: "coordinate",
    QuantityKind.FORCE: "constraint",
    QuantityKind.EQUILIBRIUM: "coordinate",
    QuantityKind.POTENTIAL_FORCE: "coordinate",
    QuantityKind.STIFFNESS: "coordinate",
    QuantityKind.ANGULAR_FREQUENCY: "coordinate",
    QuantityKind.PERIOD: "coordinate",
    QuantityKind.TERMINAL_VELOCITY: "coordinate",
    QuantityKind.SLIP_TIME: "constraint",
    QuantityKind.SLIP_DISTANCE: "coordinate",
    QuantityKind.SLIP_END_VELOCITY: "coordinate",
    QuantityKind.DAMPED_FREQUENCY: "coordinate",
    QuantityKind.DECAY_TIME: "coordinate",
    QuantityKind.UNDAMPED_FREQUENCY: "coordinate",
    QuantityKind.TURNING_POINT: "coordinate",
    QuantityKind.VELOCITY_AFTER: "coordinate",
    **dict.fromkeys(STEADY_KINDS | EFFECTIVE_KINDS, "coordinate"),
}
_SLIPPING_KEYS = {"friction", "normal", "coefficient"}
# Sizes beyond any textbook model: the derivation's cost grows fast with them, and models are uploaded.
LIMITS = {
    "limits": 12,
    "coordinates": 8,
    "bodies": 12,
    "constraints": 16,
    "friction": 8,
    "potentials": 8,
    "quantities": 30,
}
T = TypeVar("T")


class _Collector:
    """Runs validation steps, keeping every SpecError instead of stopping at the first."""

    def __init__(self) -> None:
        self.errors: list[SpecError] = []

    def add(self, message: str, path: Path) -> None:
        self.errors.append(SpecError(message, path))

    def attempt(self, step: Callable[[], T]) -> T | None:
        try:
            return step()
        except SpecErrors as group:
            self.errors.extend(group.errors)
        except SpecError as error:
            self.errors.append(error)
        return None

    def read(self, text: Any, scope: Mapping[str, sympy.Symbol], path: Path) -> sympy.Expr | None:
        return self.attempt(lambda: read_expr(text, scope, path))


def load_model(
    data: Mapping[str, Any],
    symbols: Mapping[str, sympy.Symbol],
    dimensions: Mapping[str, Dimension] | None = None,
    ranges: Mapping[str, tuple[sympy.Expr, sympy.Expr]] | None = None,
) -> Model:
    """Validate a model section into a Model; raises SpecErrors listing every fault with its path.

    With the symbols' `dimensions` (name -> Dimension), every position, energy, mass, ... is also
    checked for dimensional consistency. `ranges`: the symbol table's own ranges (name -> (low, high)),
    which choose the root a `solve` keeps. `scenarios` are loaded each as a model of its own
    (scenarios.py)."""
    base, overrides = scenarios.split(data)
    model = _load_model(base, symbols, dimensions, ranges)
    if not overrides:
        return model
    again = partial(_load_model, symbols=symbols, dimensions=dimensions, ranges=ranges)
    return dataclasses.replace(model, scenarios=scenarios.load(base, overrides, again))


def _load_model(
    data: Mapping[str, Any],
    symbols: Mapping[str, sympy.Symbol],
    dimensions: Mapping[str, Dimension] | None,
    ranges: Mapping[str, tuple[sympy.Expr, sympy.Expr]] | None,
) -> Model:
    if isinstance(data, Mapping):
        depth.check_elements(data, data.get("elements"))
    expanded = expand_elements(data, symbols)  # composable elements -> the low-level sections
    if isinstance(data, Mapping):
        released.check_elements(data.get(released.KEY), expanded.elements)
    try:
        model = dataclasses.replace(_load_low_level(expanded.data, symbols), elements=expanded.elements)
        if ranges:
            bounds = tuple((symbols[n], low, high) for n, (low, high) in ranges.items() if n in symbols)
            # A symbol's own range is its domain too: sampling outside it checks physics nobody posed
            # (a restitution of 1.02). domain.ranges, when it narrows the symbol further, wins.
            ranged = {symbol for symbol, _, _ in model.ranges}
            finite = tuple(b for b in bounds if b[0] not in ranged and all(x.is_finite for x in b[1:]))
            model = dataclasses.replace(model, symbol_ranges=bounds, ranges=model.ranges + finite)
        faults = check_dimensions(model, dimensions) if dimensions else []
        if faults:
            raise SpecErrors(faults)
        if not dimensions:
            return model
        declared = tuple((s, dimensions[s.name]) for s in model.parameters if s.name in dimensions)
        return dataclasses.replace(model, dimensions_checked=True, dimensions=declared)
    except SpecErrors as group:
        raise expanded.relocate(group) from None


def _load_low_level(data: Mapping[str, Any], symbols: Mapping[str, sympy.Symbol]) -> Model:
    errors = _Collector()
    if not isinstance(data, Mapping):
        raise SpecErrors([SpecError("the model must be a mapping", ())])
    for key in data:
        if key not in _SECTIONS:
            errors.add(f"unknown section {key!r}; expected one of {sorted(_SECTIONS)}", (str(key),))
    for key, most in LIMITS.items():
        if isinstance(data.get(key), Mapping | list) and len(data[key]) > most:
            raise SpecErrors([SpecError(f"at most {most} entries", (key,))])
    coordinate_names = [c for c in data.get("coordinates") or [] if isinstance(c, str)]
    ranges, coordinate_ranges, positive = _domain(data.get("domain"), symbols, coordinate_names, errors)
    coordinates = _coordinates(data.get("coordinates"), symbols, coordinate_ranges, errors)
    coord_names = {c.name: c.symbol for c in coordinates}
    coord_scope = {**symbols, **coord_names}
    time = forcing.time_symbol(symbols)
    # a support moving as prescribed: positions (and gaps) may use the time (supports.py)
    bodies = _bodies(data.get("bodies"), symbols, {"t": time, **coord_scope}, errors)
    cartesian = tuple(
        (name, sympy.Symbol(name, real=True)) for body in bodies for name in body.cartesian_names()
    )
    clashes = sorted(set(dict(cartesian)) & (set(symbols) | set(coord_names)))
    for name in clashes:
        errors.add(f"Cartesian name {name!r} clashes with a symbol or coordinate", ("bodies",))
    gravity = None
    if data.get("gravity") is not None:
        gravity = errors.read(data["gravity"], symbols, ("gravity",))
    declared = _constraints(data.get("constraints"), {"t": time, **symbols, **dict(cartesian)}, errors)
    constraints, let_go = released.read(data.get(released.KEY), declared, errors.add)
    frictions = _frictions(data.get("friction"), symbols, bodies, declared, coordinates, errors)
    potentials = _potentials(data.get("potentials"), symbols, bodies, errors)
    collision = _collision(data.get("collision"), symbols, bodies, coordinates, errors)
    state = _state(data.get("state"), symbols, coordinates, errors, time)
    quantities = _quantities(data.get("quantities"), symbols, coordinates, declared, collision, errors)
    _check_collision_asks(quantities, collision, data.get("impact") is not None, errors)
    released.check_uses(let_go, frictions, quantities, errors.add)
    velocities = {f"{c.name}_dot": c.velocity for c in coordinates}
    forces = _forces(data.get("forces"), symbols, {"t": time, **coord_scope, **velocities}, bodies, errors)
    limits = _stated_limits(data.get("limits"), symbols, {q.name for q in quantities}, errors)
    unused = _unused(data.get("unused"), {q.name for q in quantities}, errors)
    impact = _impact(
        data.get("impact"), symbols, bodies, quantities, errors, (coordinates, state, constraints)
    )
    frame = _frame(data.get("frame"), symbols, bodies, errors)
    reach_loading.check_targets(quantities, bodies, state, coordinates, errors.add)
    bounces.check(quantities, impact, errors.add)
    _check_slip_quantities(quantities, frictions, errors)
    depth.check(data, bodies, declared, potentials, quantities, errors.add)
    named = [*coord_names, *(c.name for c in declared), *(b.name for b in bodies)]
    notation = errors.attempt(partial(read_notation, data.get("notation"), named)) or ()
    if errors.errors:
        raise SpecErrors(errors.errors)
    model = Model(
        coordinates=coordinates,
        bodies=bodies,
        constraints=constraints,
        frictions=frictions,
        potentials=potentials,
        gravity=gravity,
        collision=collision,
        state=state,
        ranges=ranges,
        coordinate_ranges=tuple((name, low, high) for name, (low, high) in coordinate_ranges.items()),
        positive=positive,
        quantities=quantities,
        parameters=tuple(symbols.values()),
        cartesian=cartesian,
        limits=limits,
        force_entries=forces,
        impact=impact,
        frame=frame,
        notation=notation,
        unused=unused,
        released=let_go,
    )
    return with_distance_sides(forcing.with_time(model, time))


def _frame(
    value: Any, symbols: Mapping[str, sympy.Symbol], bodies: tuple[Body, ...], errors: _Collector
) -> Frame | None:
    """`frame: {body: wedge}` (translating with a body) or `{rate: omega, axis: 0, bodies: [bead]}`."""
    if value is None:
        return None
    path: Path = ("frame",)
    spec = _mapping(value, path, errors)
    _check_keys(spec, {"body", "rate", "axis", "bodies"}, set(), path, errors)
    names = {b.name for b in bodies}
    if ("body" in spec) == ("rate" in spec):
        errors.add(
            "give exactly one of body (a frame moving with that body) and rate (a turning frame)", path
        )
        return None
    if "body" in spec:
        for key in ("axis", "bodies"):
            if key in spec:
                errors.add("only a turning frame (rate) has this", (*path, key))
        if spec["body"] not in names:
            errors.add(f"unknown body {spec['body']!r}", (*path, "body"))
            return None
        return Frame(body=str(spec["body"]))
    members = spec.get("bodies")
    if not isinstance(members, list) or not members:
        errors.add("a list of the bodies turning with the frame", (*path, "bodies"))
        return None
    for index, member in enumerate(members):
        if member not in names:
            errors.add(f"unknown body {member!r}", (*path, "bodies", index))
    rate = errors.read(spec["rate"], symbols, (*path, "rate"))
    axis = errors.read(spec.get("axis", 0), symbols, (*path, "axis"))
    if rate is None or axis is None or not all(m in names for m in members):
        return None
    return Frame(rate=rate, axis=axis, bodies=tuple(map(str, members)))


def _forces(
    value: Any,
    symbols: Mapping[str, sympy.Symbol],
    scope: Mapping[str, sympy.Symbol],
    bodies: tuple[Body, ...],
    errors: _Collector,
) -> tuple[ForceEntryLoad, ...]:
    """Each entry names its body and one kind of load by its key, read by that load's module."""
    result: list[ForceEntryLoad] = []
    by_name = {b.name: b for b in bodies}
    kinds = list(force_kinds.READERS)
    for index, entry in enumerate(_sequence(value, ("forces",), errors)):
        path: Path = ("forces", index)
        spec = _mapping(entry, path, errors)
        given = [k for k in kinds if k in spec]
        _check_keys(spec, {"body", *kinds}, {"body"}, path, errors)
        if len(given) != 1:
            errors.add(f"give exactly one of {kinds}", path)
            continue
        body = by_name.get(spec.get("body"))  # type: ignore[arg-type]
        if body is None:
            errors.add(f"unknown body {spec.get('body')!r}", (*path, "body"))
            continue
        key = given[0]
        read = force_kinds.Entry(
            body,
            spec[key],
            (*path, key),
            expression=lambda text, where: errors.read(text, scope, where),
            parameter=lambda text, where: errors.read(text, symbols, where),
            axes=lambda text, where: _axes(text, scope, where, errors, depth.SPACE),
            error=errors.add,
        )
        load = force_kinds.READERS[key](key, read)
        if load is not None:
            result.append(load)
    return tuple(result)


def _stated_limits(
    value: Any, symbols: Mapping[str, sympy.Symbol], quantities: set[str], errors: _Collector
) -> tuple[StatedLimit, ...]:
    result: list[StatedLimit] = []
    for index, entry in enumerate(_sequence(value, ("limits",), errors)):
        path: Path = ("limits", index)
        spec = _mapping(entry, path, errors)
        _check_keys(spec, {"where", "expect", "description"}, {"where", "expect"}, path, errors)
        where: list[tuple[sympy.Symbol, sympy.Expr]] = []
        for name, text in _mapping(spec.get("where"), (*path, "where"), errors).items():
            if name not in symbols:
                errors.add(f"unknown symbol {name!r}", (*path, "where", str(name)))
                continue
            bound = errors.attempt(partial(_bound, text, symbols, (*path, "where", str(name))))
            if bound is not None:
                where.append((symbols[name], bound))
        expect: list[tuple[str, sympy.Expr]] = []
        for name, text in _mapping(spec.get("expect"), (*path, "expect"), errors).items():
            if name not in quantities:
                errors.add(f"unknown quantity {name!r}", (*path, "expect", str(name)))
                continue
            expr = errors.read(text, symbols, (*path, "expect", str(name)))
            if expr is not None:
                expect.append((str(name), expr))
        description = spec.get("description", "")
        if where and expect:
            result.append(StatedLimit(tuple(where), tuple(expect), str(description)))
    return tuple(result)


def _unused(value: Any, quantities: set[str], errors: _Collector) -> tuple[str, ...]:
    """`unused: [name, ...]`: quantities no part asks for, on purpose (the problem checks the rest)."""
    names: list[str] = []
    for index, name in enumerate(_sequence(value, ("unused",), errors)):
        if name not in quantities:
            errors.add(f"unknown quantity {name!r}; the model's are {sorted(quantities)}", ("unused", index))
        else:
            names.append(str(name))
    return tuple(names)


def _mapping(value: Any, path: Path, errors: _Collector, required: bool = True) -> Mapping[str, Any]:
    if value is None and not required:
        return {}
    if not isinstance(value, Mapping):
        errors.add("expected a mapping" if value is not None else "required", path)
        return {}
    return value


def _sequence(value: Any, path: Path, errors: _Collector, required: bool = False) -> list[Any]:
    if value is None and not required:
        return []
    if not isinstance(value, list):
        errors.add("expected a list" if value is not None else "required", path)
        return []
    return value


def _check_keys(
    entry: Mapping[str, Any], allowed: set[str], required: set[str], path: Path, errors: _Collector
) -> None:
    for key in entry:
        if key not in allowed:
            errors.add(f"unknown key {key!r}; expected one of {sorted(allowed)}", (*path, str(key)))
    for key in sorted(required - set(entry)):
        errors.add("required", (*path, key))


def _coordinates(
    value: Any,
    symbols: Mapping[str, sympy.Symbol],
    ranges: Mapping[str, tuple[sympy.Expr, sympy.Expr]],
    errors: _Collector,
) -> tuple[Coordinate, ...]:
    result: list[Coordinate] = []
    for index, name in enumerate(_sequence(value, ("coordinates",), errors, required=True)):
        if not isinstance(name, str) or not _NAME.match(name):
            errors.add("a coordinate is a plain name (letters and digits)", ("coordinates", index))
            continue
        if any(c.name == name for c in result):
            errors.add(f"coordinate {name!r} declared twice", ("coordinates", index))
            continue
        symbol = symbols.get(name) or _coordinate_symbol(name, ranges.get(name))
        result.append(
            Coordinate(
                name, symbol, sympy.Symbol(f"{name}_dot", real=True), sympy.Symbol(f"{name}_ddot", real=True)
            )
        )
    return tuple(result)


def _coordinate_symbol(name: str, bounds: tuple[sympy.Expr, sympy.Expr] | None) -> sympy.Symbol:
    """A coordinate's symbol carries the sign its declared range gives it (sympy then keeps roots,
    distances and square roots on that side)."""
    if bounds is not None and bool(bounds[0] >= 0):
        return sympy.Symbol(name, positive=True)
    if bounds is not None and bool(bounds[1] <= 0):
        return sympy.Symbol(name, negative=True)
    return sympy.Symbol(name, real=True)


def _bodies(
    value: Any, symbols: Mapping[str, sympy.Symbol], scope: Mapping[str, sympy.Symbol], errors: _Collector
) -> tuple[Body, ...]:
    result: list[Body] = []
    for name, entry in _mapping(value, ("bodies",), errors).items():
        path: Path = ("bodies", str(name))
        if not isinstance(name, str) or not _NAME.match(name):
            errors.add("a body name is a plain name (letters and digits)", path)
            continue
        spec = _mapping(entry, path, errors)
        _check_keys(spec, {"mass", "inertia", "position", "angle"}, {"mass", "position"}, path, errors)
        mass = errors.read(spec.get("mass"), symbols, (*path, "mass"))
        inertia: sympy.Expr | None = sympy.Integer(0)
        if "inertia" in spec:
            inertia = errors.read(spec["inertia"], symbols, (*path, "inertia"))
        angle = None
        if "angle" in spec:
            angle = errors.read(spec["angle"], scope, (*path, "angle"))
        elif "inertia" in spec:
            errors.add("a body with a moment of inertia needs an angle", (*path, "angle"))
        position = _axes(spec.get("position"), scope, (*path, "position"), errors, depth.SPACE)
        if mass is not None and inertia is not None and position:
            result.append(Body(name, mass, inertia, position, angle))
    return tuple(result)


def _moving_anchor(value: Any, symbols: Mapping[str, sympy.Symbol]) -> bool:
    """An anchor written in the time `t` (not a symbol of the table): a support meant to move."""
    return (
        "t" not in symbols
        and isinstance(value, Mapping)
        and any(isinstance(text, str) and _TIME.search(text) for text in value.values())
    )


def _axes(
    value: Any,
    scope: Mapping[str, sympy.Symbol],
    path: Path,
    errors: _Collector,
    axes: tuple[str, ...] = AXES,
) -> tuple[tuple[str, sympy.Expr], ...]:
    """A point or direction in the x–y plane; a body's position or an anchor (`axes`: depth.SPACE) may also take z."""
    spec = _mapping(value, path, errors)
    result: list[tuple[str, sympy.Expr]] = []
    for axis in spec:
        if axis == depth.DEPTH and axis not in axes:
            errors.add(
                "z is for a body's position or a potential's anchor only: every other point or direction is "
                "in the x–y plane",
                (*path, str(axis)),
            )
        elif axis not in axes:
            errors.add(
                f"unknown axis {axis!r}; expected {', '.join(axes[:-1])} and/or {axes[-1]}",
                (*path, str(axis)),
            )
    for axis in axes:
        if axis in spec:
            expr = errors.read(spec[axis], scope, (*path, axis))
            if expr is not None:
                result.append((axis, expr))
    if value is not None and not spec:
        errors.add(f"give at least one of {', '.join(axes)}", path)
    return tuple(result)


def _constraints(value: Any, scope: Mapping[str, sympy.Symbol], errors: _Collector) -> tuple[Constraint, ...]:
    result: list[Constraint] = []
    for name, entry in _mapping(value, ("constraints",), errors, required=False).items():
        path: Path = ("constraints", str(name))
        spec = _mapping(entry, path, errors)
        _check_keys(spec, {"gap", "kind"}, {"gap"}, path, errors)
        kind_text = spec.get("kind", "other")
        if kind_text not in set(ConstraintKind):
            errors.add(
                f"unknown kind {kind_text!r}; expected one of {[k.value for k in ConstraintKind]}",
                (*path, "kind"),
            )
            continue
        gap = errors.read(spec.get("gap"), scope, (*path, "gap"))
        if gap is not None:
            result.append(Constraint(str(name), gap, ConstraintKind(kind_text)))
    return tuple(result)


def _frictions(
    value: Any,
    symbols: Mapping[str, sympy.Symbol],
    bodies: tuple[Body, ...],
    constraints: tuple[Constraint, ...],
    coordinates: tuple[Coordinate, ...],
    errors: _Collector,
) -> tuple[Friction, ...]:
    result: list[Friction] = []
    for index, entry in enumerate(_sequence(value, ("friction",), errors)):
        path: Path = ("friction", index)
        spec = _mapping(entry, path, errors)
        keys = {"constraint", "body", "coefficient", "sliding"}
        _check_keys(spec, keys | {"contact", "against"}, keys, path, errors)
        body = next((b for b in bodies if b.name == spec.get("body")), None)
        contact: tuple[tuple[str, sympy.Expr], ...] = ()
        if body is None:
            errors.add(f"unknown body {spec.get('body')!r}", (*path, "body"))
        elif body.angle is not None and "contact" not in spec:
            errors.add(
                "friction on a rigid body acts at its contact point: give `contact: {x, y}`, the point "
                "relative to the body's centre",
                (*path, "contact"),
            )
        elif body.angle is None and "contact" in spec:
            errors.add(
                "a particle has no size: friction acts at its centre (leave out `contact`)",
                (*path, "contact"),
            )
        elif "contact" in spec:
            contact = _axes(spec["contact"], symbols, (*path, "contact"), errors)
        against = spec.get("against")
        if against is not None and (
            against == spec.get("body") or not any(b.name == against for b in bodies)
        ):
            errors.add(f"expected another body, the one {spec.get('body')!r} slides on", (*path, "against"))
        if not any(c.name == spec.get("constraint") for c in constraints):
            errors.add(f"unknown constraint {spec.get('constraint')!r}", (*path, "constraint"))
        if not any(c.name == spec.get("sliding") for c in coordinates):
            errors.add(f"unknown coordinate {spec.get('sliding')!r}", (*path, "sliding"))
        mu = errors.read(spec.get("coefficient"), symbols, (*path, "coefficient"))
        if mu is not None and body is not None:
            result.append(
                Friction(
                    str(spec["constraint"]),
                    body.name,
                    mu,
                    str(spec["sliding"]),
                    contact,
                    str(against) if against is not None else None,
                )
            )
    return tuple(result)


def _potentials(
    value: Any, symbols: Mapping[str, sympy.Symbol], bodies: tuple[Body, ...], errors: _Collector
) -> tuple[PairPotential, ...]:
    result: list[PairPotential] = []
    names = {b.name for b in bodies}
    for index, entry in enumerate(_sequence(value, ("potentials",), errors)):
        path: Path = ("potentials", index)
        spec = _mapping(entry, path, errors)
        _check_keys(
            spec,
            {"bodies", "anchor", "energy", "distance", "reach"},
            {"bodies", "energy", "distance"},
            path,
            errors,
        )
        members = spec.get("bodies")
        if not isinstance(members, list) or not 1 <= len(members) <= 2:
            errors.add("one or two body names", (*path, "bodies"))
            continue
        for position, member in enumerate(members):
            if member not in names:
                errors.add(f"unknown body {member!r}", (*path, "bodies", position))
        anchor: tuple[tuple[str, sympy.Expr], ...] = ()
        if len(members) == 1 and _moving_anchor(spec.get("anchor"), symbols):
            errors.add(
                "a fixed point cannot move with the time t: for a support that moves as prescribed, make it "
                "a body whose position uses t, held there by a constraint (`gap: y_cab - A*t^2/2`), and join "
                "the spring or potential to that body",
                (*path, "anchor"),
            )
        elif len(members) == 1:
            anchor = _axes(spec.get("anchor"), symbols, (*path, "anchor"), errors, depth.SPACE)
        elif "anchor" in spec:
            errors.add("an anchor is only for a potential on one body", (*path, "anchor"))
        distance_name = spec.get("distance")
        if not isinstance(distance_name, str) or not _NAME.match(distance_name):
            errors.add("the name of the distance variable", (*path, "distance"))
            continue
        distance = symbols.get(distance_name, sympy.Symbol(distance_name, positive=True))
        energy = errors.read(spec.get("energy"), {**symbols, distance_name: distance}, (*path, "energy"))
        reach = errors.read(spec["reach"], symbols, (*path, "reach")) if "reach" in spec else None
        if energy is not None and all(m in names for m in members):
            result.append(
                PairPotential(f"potential{index}", tuple(members), anchor, energy, distance, reach=reach)
            )
    return tuple(result)


def _collision(
    value: Any,
    symbols: Mapping[str, sympy.Symbol],
    bodies: tuple[Body, ...],
    coordinates: tuple[Coordinate, ...],
    errors: _Collector,
) -> Collision | None:
    if value is None:
        return None
    path: Path = ("collision",)
    spec = _mapping(value, path, errors)
    keys = {"projectile", "mass", "direction", "target", "at"}
    _check_keys(spec, keys | {"point", "reaches", "speed"}, keys, path, errors)
    projectile = spec.get("projectile")
    if not isinstance(projectile, str) or not _NAME.match(projectile):
        errors.add("the projectile's name", (*path, "projectile"))
    target = spec.get("target")
    if not any(b.name == target for b in bodies):
        errors.add(f"unknown body {target!r}", (*path, "target"))
    mass = errors.read(spec.get("mass"), symbols, (*path, "mass"))
    direction = _axes(spec.get("direction"), symbols, (*path, "direction"), errors)
    at = _coordinate_values(spec.get("at"), symbols, coordinates, (*path, "at"), errors)
    reaches: tuple[tuple[str, sympy.Expr], ...] = ()
    if "reaches" in spec:
        reaches = _coordinate_values(spec["reaches"], symbols, coordinates, (*path, "reaches"), errors)
    scope = {**symbols, **{c.name: c.symbol for c in coordinates}}
    point = _axes(spec["point"], scope, (*path, "point"), errors) if "point" in spec else ()
    if any(b.name == projectile for b in bodies):
        errors.add(
            f"{projectile!r} names a body already; the projectile needs a name of its own",
            (*path, "projectile"),
        )
    if mass is None or not direction or not isinstance(projectile, str) or not isinstance(target, str):
        return None
    speed = errors.read(spec["speed"], symbols, (*path, "speed")) if "speed" in spec else None
    if ("speed" in spec) == ("reaches" in spec):
        errors.add(
            "give exactly one of reaches (where the merged body stops: the projectile's speed is asked) and "
            "speed (the projectile's: the velocities just after are asked)",
            path,
        )
    hit = Collision(projectile, mass, direction, target, at, reaches, point, speed)
    struck = next((b for b in bodies if b.name == target), None)
    moving = {c.symbol for c in coordinates}
    if point and struck is not None:
        fault = embedding.point_fault(dict(point), struck, moving)
        if fault is not None:
            errors.add(fault, (*path, "point"))  # the quantities that use the collision stay found
    elif struck is not None and (fault := embedding.unplaced_fault(struck, moving, "`point: {x, y}`")):
        errors.add(fault, (*path, "point"))
    return hit


def _check_collision_asks(
    quantities: tuple[Quantity, ...], collision: Collision | None, impact: bool, errors: _Collector
) -> None:
    """A collision's speed is asked where the merged body stops (`reaches`), or given (`speed`) when the
    velocities just after are asked: never both. An impact's velocities just after need nothing more."""
    for q in quantities:
        where: Path = ("quantities", q.name, q.kind.value)
        given = collision is not None and collision.speed is not None
        after_impact = collision is None and impact
        if q.kind is QuantityKind.VELOCITY_AFTER and not (given or after_impact):
            errors.add(
                "the velocity just after a collision needs the collision's speed (`speed:`), or an impact",
                where,
            )
        if q.kind is QuantityKind.PROJECTILE_SPEED and collision is not None and collision.speed is not None:
            errors.add("the collision gives the projectile's speed; ask it with `reaches:` instead", where)


def _impact(
    value: Any,
    symbols: Mapping[str, sympy.Symbol],
    bodies: tuple[Body, ...],
    quantities: tuple[Quantity, ...],
    errors: _Collector,
    motion: tuple[
        tuple[Coordinate, ...], tuple[tuple[sympy.Symbol, sympy.Expr], ...], tuple[Constraint, ...]
    ],
) -> Impact | None:
    asked = [q for q in quantities if q.kind in IMPACT_KINDS]
    if value is None:
        for q in asked:
            errors.add("this quantity needs an impact section", ("quantities", q.name, q.kind.value))
        for q in quantities:
            if q.after:
                errors.add(
                    "the motion after an impact needs an impact section", ("quantities", q.name, "after")
                )
        return None
    path: Path = ("impact",)
    spec = _mapping(value, path, errors)
    _check_keys(
        spec, {"bodies", "normal", "restitution", "release", "stick", "points"}, {"bodies"}, path, errors
    )
    entries = spec.get("bodies")
    known = {b.name: b for b in bodies}
    if not isinstance(entries, list) or len(entries) != 2:
        errors.add(
            "two different bodies: [first, second], the normal pointing from the first; a floor or wall "
            "that does not move is {fixed: floor}",
            (*path, "bodies"),
        )
        return None
    names: list[str] = []
    fixed: str | None = None
    flip = False
    for index, entry in enumerate(entries):
        where: Path = (*path, "bodies", index)
        if isinstance(entry, Mapping):
            partner = entry.get("fixed")
            if set(entry) != {"fixed"} or not isinstance(partner, str) or not _NAME.match(partner):
                errors.add(
                    "a fixed partner is {fixed: <its name>}, a floor or wall that does not move", where
                )
            elif partner in known:
                errors.add(
                    f"{partner!r} is a body of the model, which moves: name the fixed partner apart", where
                )
            elif fixed is not None:
                errors.add("one of the two may be fixed, not both", where)
            else:
                fixed, flip = partner, index == 0
            continue
        if entry not in known:
            errors.add(f"unknown body {entry!r}", where)
        elif known[entry].angle is not None and spec.get("stick", False):
            errors.add("sticking is modelled for particles; a rigid body needs restitution: 0", where)
        names.append(str(entry))
    if len(set(names)) != len(names):
        errors.add(
            "two different bodies: [first, second], the normal pointing from the first", (*path, "bodies")
        )
    stick = spec.get("stick", False)
    if not isinstance(stick, bool):
        errors.add("stick is true (the bodies move on together) or false", (*path, "stick"))
        stick = False
    if stick and {"restitution", "release", "normal"} & set(spec):
        errors.add(
            "bodies that stick together need no restitution, release or normal: their impulse is along "
            "their relative velocity, and they part at none",
            (*path, "stick"),
        )
    elif not stick and ("restitution" in spec) == ("release" in spec):
        errors.add(
            "give exactly one of restitution (a collision) and release (an explosion), or stick: true",
            path,
        )
    if fixed is not None and "release" in spec:
        errors.add("an explosion parts two bodies: a fixed partner cannot take a share", (*path, "release"))
    restitution_stuck: sympy.Expr | None = None
    restitution = (
        errors.read(spec["restitution"], symbols, (*path, "restitution")) if "restitution" in spec else None
    )
    release = errors.read(spec["release"], symbols, (*path, "release")) if "release" in spec else None
    normal = (
        _axes(spec["normal"], symbols, (*path, "normal"), errors)
        if "normal" in spec
        else (("x", sympy.Integer(1)),)
    )
    if "normal" not in spec and len(names) + (fixed is not None) == 2 and all(n in known for n in names):
        coordinates, state, constraints = motion
        partner = known[names[1]] if len(names) > 1 else None
        relative = sticking.relative_velocity(known[names[0]], partner, coordinates, dict(state))
        if flip:  # the partner is first in the author's order; the approach is the same line
            relative = {a: -v for a, v in relative.items()}
        if stick:
            holding = [c for n in names for c in sticking.held(n, constraints)]
            found = sticking.stuck_normal(relative)
            if holding:
                errors.add(
                    f"sticking is modelled for free bodies; {', '.join(holding)} also pushes during the "
                    "impact: give the contact's normal and restitution: 0",
                    (*path, "stick"),
                )
            elif found is None:
                errors.add("the bodies do not move towards each other at the state", (*path, "stick"))
            else:
                normal, restitution_stuck = found, sympy.Integer(0)
        elif sticking.across_x(relative):
            errors.add(
                "the bodies approach across the plane (relative velocity "
                + ", ".join(f"{a}: {typed_text(v)}" for a, v in relative.items())
                + "): give the contact's normal (the line of centres, from the first body), or stick: true "
                "for bodies that move on together",
                path,
            )
    if flip:  # written from the fixed partner to the body: kept from the moving body to the partner
        normal = tuple((axis, -component) for axis, component in normal)
    points = _impact_points(spec.get("points"), symbols, known, names, motion[0], errors)
    written = spec.get("points")
    placed = set(written) if isinstance(written, Mapping) else set()
    moving = {c.symbol for c in motion[0]}
    for name in names:
        if name in known and name not in placed:
            fault = embedding.unplaced_fault(known[name], moving, f"`points: {{{name}: {{x, y}}}}`")
            if fault is not None:
                errors.add(fault, (*path, "points"))
    for q in asked:
        where = ("quantities", q.name, q.kind.value)
        if q.kind is QuantityKind.KINETIC_ENERGY_LOST:
            if q.target != "impact":
                errors.add("the energy lost is the impact's: write `kinetic_energy_lost: impact`", where)
        elif q.target not in names:
            errors.add(f"the impact's moving bodies are {names}, not {q.target!r}", where)
        elif q.kind is QuantityKind.FINAL_VELOCITY and len(known[q.target].position) > 1:
            errors.add(f"{q.target!r} moves in the plane: ask for the final_speed", where)
    if len(names) + (fixed is not None) != 2 or not all(n in known for n in names):
        return None
    restitution = restitution if restitution_stuck is None else restitution_stuck
    if restitution is None and release is None:
        return None
    return Impact(tuple(names), normal, restitution, release, fixed, points)


def _impact_points(
    value: Any,
    symbols: Mapping[str, sympy.Symbol],
    known: Mapping[str, Body],
    names: list[str],
    coordinates: tuple[Coordinate, ...],
    errors: _Collector,
) -> tuple[tuple[str, tuple[tuple[str, sympy.Expr], ...]], ...]:
    """`points: {rod: {x: ..., y: ...}}`: where each rigid body of the impact is struck."""
    if value is None:
        return ()
    path: Path = ("impact", "points")
    scope = {**symbols, **{c.name: c.symbol for c in coordinates}}
    found: list[tuple[str, tuple[tuple[str, sympy.Expr], ...]]] = []
    for name, entry in _mapping(value, path, errors).items():
        if name not in names or name not in known:
            errors.add(f"the impact's moving bodies are {names}, not {name!r}", (*path, str(name)))
            continue
        point = _axes(entry, scope, (*path, str(name)), errors)
        fault = embedding.point_fault(
            dict(point), known[name], {c.symbol for c in coordinates}, "the contact is"
        )
        if fault is not None:
            errors.add(fault, (*path, str(name)))
            continue
        found.append((str(name), point))
    return tuple(found)


def _coordinate_values(
    value: Any,
    symbols: Mapping[str, sympy.Symbol],
    coordinates: tuple[Coordinate, ...],
    path: Path,
    errors: _Collector,
) -> tuple[tuple[str, sympy.Expr], ...]:
    result: list[tuple[str, sympy.Expr]] = []
    names = {c.name for c in coordinates}
    for name, text in _mapping(value, path, errors).items():
        if name not in names:
            errors.add(f"unknown coordinate {name!r}", (*path, str(name)))
            continue
        expr = errors.read(text, symbols, (*path, str(name)))
        if expr is not None:
            result.append((str(name), expr))
    return tuple(result)


def _state(
    value: Any,
    symbols: Mapping[str, sympy.Symbol],
    coordinates: tuple[Coordinate, ...],
    errors: _Collector,
    time: sympy.Symbol,
) -> tuple[tuple[sympy.Symbol, sympy.Expr], ...]:
    known = {c.name: c.symbol for c in coordinates} | {f"{c.name}_dot": c.velocity for c in coordinates}
    known.setdefault(forcing.NAME, time)  # the time, for forces that depend on it
    given: dict[sympy.Symbol, sympy.Expr] = {c.velocity: sympy.Integer(0) for c in coordinates}
    for name, text in _mapping(value, ("state",), errors, required=False).items():
        if name not in known:
            errors.add(f"unknown coordinate, velocity or time {name!r}", ("state", str(name)))
            continue
        expr = errors.read(text, symbols, ("state", str(name)))
        if expr is not None:
            given[known[name]] = expr
    return tuple(given.items())


def _domain(
    value: Any, symbols: Mapping[str, sympy.Symbol], coordinates: list[str], errors: _Collector
) -> tuple[
    tuple[tuple[sympy.Symbol, sympy.Expr, sympy.Expr], ...],
    dict[str, tuple[sympy.Expr, sympy.Expr]],
    tuple[sympy.Expr, ...],
]:
    spec = _mapping(value, ("domain",), errors, required=False)
    _check_keys(spec, {"ranges", "positive"}, set(), ("domain",), errors)
    ranges: list[tuple[sympy.Symbol, sympy.Expr, sympy.Expr]] = []
    coordinate_ranges: dict[str, tuple[sympy.Expr, sympy.Expr]] = {}
    for name, bounds in _mapping(spec.get("ranges"), ("domain", "ranges"), errors, required=False).items():
        path: Path = ("domain", "ranges", str(name))
        if name not in symbols and name not in coordinates:
            errors.add(f"unknown symbol or coordinate {name!r}", path)
            continue
        if not isinstance(bounds, list) or len(bounds) != 2:
            errors.add("a range is [low, high]", path)
            continue
        low = errors.attempt(partial(_bound, bounds[0], symbols, (*path, 0)))
        high = errors.attempt(partial(_bound, bounds[1], symbols, (*path, 1)))
        if low is None or high is None:
            continue
        if name in coordinates:
            coordinate_ranges[str(name)] = (low, high)
        elif low.free_symbols or high.free_symbols:  # sampled first, each symbol on its own
            kept = [f"{name} - {typed_text(low)}"] if low.free_symbols else []
            kept += [f"{typed_text(high)} - {name}"] if high.free_symbols else []
            errors.add(
                f"a parameter's range is two numbers; to keep {name} within other symbols, write what "
                f"stays positive (`positive: [{', '.join(kept)}]`)",
                path,
            )
        elif low.is_finite and high.is_finite:
            ranges.append((symbols[name], low, high))
        else:
            errors.add("a parameter's range is finite (its sign is declared in the symbol table)", path)
    positive: list[sympy.Expr] = []
    for index, text in enumerate(_sequence(spec.get("positive"), ("domain", "positive"), errors)):
        expr = errors.read(text, symbols, ("domain", "positive", index))
        if expr is not None:
            positive.append(expr)
    return tuple(ranges), coordinate_ranges, tuple(positive)


def _bound(text: Any, symbols: Mapping[str, sympy.Symbol], path: Path) -> sympy.Expr:
    """A range bound; `oo` and `-oo` leave the range open on that side."""
    if isinstance(text, str) and text.strip() in _INFINITE:
        return _INFINITE[text.strip()]
    return read_expr(text, symbols, path)


_INFINITE: dict[str, sympy.Expr] = {"oo": sympy.oo, "+oo": sympy.oo, "-oo": -sympy.oo}


def _quantities(
    value: Any,
    symbols: Mapping[str, sympy.Symbol],
    coordinates: tuple[Coordinate, ...],
    constraints: tuple[Constraint, ...],
    collision: Collision | None,
    errors: _Collector,
) -> tuple[Quantity, ...]:
    result: list[Quantity] = []
    entries = _mapping(value, ("quantities",), errors)
    # every quantity may be used by an expression, wherever it stands: a mapping has no order
    stand_ins = {str(n): sympy.Symbol(f"quantity_{n}", real=True) for n in entries if str(n) not in symbols}
    for name, entry in entries.items():
        if isinstance(entry, Mapping) and "expression" in entry:
            others = {n: s for n, s in stand_ins.items() if n != name}
            result += _expression_quantity(str(name), entry, symbols, others, errors)
            continue
        entry, at_values = evaluated_at.split(str(name), entry, symbols, list(map(str, entries)), errors.add)
        quantity = _quantity(
            str(name),
            entry,
            ("quantities", str(name)),
            symbols,
            coordinates,
            constraints,
            collision,
            errors,
            {n: s for n, s in stand_ins.items() if n != name},
        )
        if quantity is not None:
            result.append(dataclasses.replace(quantity, uses=at_values))
    _check_cycles(result, errors)
    return tuple(result)


def _check_cycles(quantities: list[Quantity], errors: _Collector) -> None:
    """Expressions (or quantities evaluated `with` each other's values) that use each other in a circle
    define nothing."""
    uses = {q.name: [name for _, name in q.uses] for q in quantities}
    reported: set[str] = set()

    def visit(name: str, path: list[str]) -> None:
        if name in path:
            circle = [*path[path.index(name) :], name]
            if not reported & set(circle):
                reported.update(circle)
                errors.add(
                    f"the expressions use each other in a circle: {' -> '.join(circle)}",
                    ("quantities", circle[0], "expression"),
                )
            return
        for used in uses.get(name, []):
            visit(used, [*path, name])

    for quantity in quantities:
        visit(quantity.name, [])


def _expression_quantity(
    name: str,
    entry: Mapping[str, Any],
    symbols: Mapping[str, sympy.Symbol],
    stand_ins: Mapping[str, sympy.Symbol],
    errors: _Collector,
) -> list[Quantity]:
    """`T: {expression: "2*pi*R/v"}`: a formula in the parameters and the model's other quantities."""
    path: Path = ("quantities", name)
    _check_keys(entry, {"expression"}, {"expression"}, path, errors)
    expr = errors.read(entry["expression"], {**symbols, **stand_ins}, (*path, "expression"))
    if expr is None:
        return []
    uses = tuple((symbol, quantity) for quantity, symbol in stand_ins.items() if expr.has(symbol))
    return [Quantity(name, QuantityKind.EXPRESSION, expression=expr, uses=uses)]


def _quantity(
    name: str,
    entry: Any,
    path: Path,
    symbols: Mapping[str, sympy.Symbol],
    coordinates: tuple[Coordinate, ...],
    constraints: tuple[Constraint, ...],
    collision: Collision | None,
    errors: _Collector,
    others: Mapping[str, sympy.Symbol] | None = None,
) -> Quantity | None:
    """One quantity's entry; `others` are the model's other quantities, which a `solve`'s `zero:` or an
    extremum's `of:` may name instead of writing its quantity in place."""
    spec = _mapping(entry, path, errors)
    kinds = [k for k in spec if k in set(QuantityKind)]
    if len(kinds) != 1:
        errors.add(f"give exactly one of {[k.value for k in QuantityKind]}", path)
        return None
    kind = QuantityKind(kinds[0])
    if reach_loading.handles(kind, spec):
        return reach_loading.load_quantity(
            name, kind, spec, path, symbols, coordinates, constraints, errors.add, list(others or ())
        )
    allowed = (
        {kind.value}
        | ({"zero"} if kind is QuantityKind.SOLVE else set())
        | ({"of"} if kind in EXTREMUM_KINDS else set())
        | (_SLIPPING_KEYS if kind is QuantityKind.SLIPPING else set())
    )
    optional = {"bounces"} if kind in bounces.FINAL_KINDS else set()
    if kind is QuantityKind.KINETIC_ENERGY_LOST:
        optional |= {"total"}
    if kind is QuantityKind.TURNING_POINT:  # how far the motion just after an impact goes (a squeeze)
        optional = {"after"}
    if kind in amplitude.KINDS:
        optional = {"amplitude"}
    _check_keys(spec, allowed | optional, allowed, path, errors)
    target = spec[kind.value]
    where: Path = (*path, kind.value)
    if kind is QuantityKind.REVOLUTION_PERIOD and target == "frame":  # the rotating frame's turn
        return Quantity(name, kind, "frame")
    if kind in _QUANTITY_TARGET:
        pool = (
            {c.name for c in coordinates}
            if _QUANTITY_TARGET[kind] == "coordinate"
            else {c.name for c in constraints}
        )
        if target not in pool:
            errors.add(f"unknown {_QUANTITY_TARGET[kind]} {target!r}", where)
            return None
        after = spec.get("after", "")
        if after not in ("", "impact"):
            errors.add(
                "`after: impact` takes the quantity in the motion just after the model's impact",
                (*path, "after"),
            )
            return None
        small = spec.get("amplitude") == "small"
        if "amplitude" in spec and not small:
            errors.add(
                "`amplitude: small` says the problem asks for small oscillations", (*path, "amplitude")
            )
            return None
        return Quantity(name, kind, str(target), after=after, small=small)
    if kind is QuantityKind.MECHANICAL_ENERGY:
        if target != "state":
            errors.add("the energy is the model's state's: write `mechanical_energy: state`", where)
            return None
        return Quantity(name, kind, "state")
    if kind in IMPACT_KINDS:  # checked against the impact section by `_impact`
        count = errors.read(spec["bounces"], symbols, (*path, "bounces")) if "bounces" in spec else None
        total = spec.get("total", False)
        if total is not False and (total is not True or "bounces" not in spec):
            errors.add(bounces.TOTAL, (*path, "total"))
            return None
        return Quantity(name, kind, str(target), bounces=count, total=total)
    if kind is QuantityKind.MODE_SHAPE:
        return errors.attempt(lambda: mode_shapes.read(name, target, where, coordinates))
    if kind is QuantityKind.NORMAL_FREQUENCY:
        if isinstance(target, bool) or not isinstance(target, int) or not 1 <= target <= len(coordinates):
            errors.add(f"the mode's number, 1 (lowest) to {len(coordinates)}", where)
            return None
        return Quantity(name, kind, str(target))
    if kind is QuantityKind.SLIPPING:
        return _slipping_quantity(name, spec, path, symbols, constraints, errors)
    if kind is QuantityKind.SOLVE or kind in EXTREMUM_KINDS:  # a parameter's value, set by an inner quantity
        if target not in symbols:
            errors.add(f"unknown symbol {target!r}", where)
            return None
        inner_key = "zero" if kind is QuantityKind.SOLVE else "of"
        named = spec.get(inner_key)
        if isinstance(named, str):  # another quantity of the model, by its name (an expression, say)
            stand_in = (others or {}).get(named)
            if stand_in is None:
                errors.add(
                    f"unknown quantity {named!r}: name another quantity of the model, one of "
                    f"{sorted(others or {})}, or write the quantity in place",
                    (*path, inner_key),
                )
                return None
            inner_quantity = Quantity(
                f"{name}.{inner_key}", QuantityKind.EXPRESSION, expression=stand_in, uses=((stand_in, named),)
            )
            return Quantity(name, kind, parameter=symbols[target], inner=inner_quantity)
        if isinstance(named, Mapping) and "expression" in named:
            errors.add(
                f"write the expression as a quantity of its own and name it here (`{inner_key}: <its name>`)",
                (*path, inner_key),
            )
            return None
        inner = _quantity(
            f"{name}.{inner_key}",
            spec.get(inner_key),
            (*path, inner_key),
            symbols,
            coordinates,
            constraints,
            collision,
            errors,
        )
        return Quantity(name, kind, parameter=symbols[target], inner=inner) if inner is not None else None
    if collision is None:
        errors.add("this quantity needs a collision section", where)
        return None
    if target != collision.projectile:
        errors.add(f"the collision's projectile is {collision.projectile!r}, not {target!r}", where)
        return None
    return Quantity(name, kind, str(target))


def _slipping_quantity(
    name: str,
    spec: Mapping[str, Any],
    path: Path,
    symbols: Mapping[str, sympy.Symbol],
    constraints: tuple[Constraint, ...],
    errors: _Collector,
) -> Quantity | None:
    """`{slipping: theta, friction: hold, normal: slope, coefficient: mu_s}`: the value of a parameter at
    which the holding contact's friction force reaches mu_s times its normal force."""
    parameter = spec.get("slipping")
    found = True
    if parameter not in symbols:
        errors.add(f"unknown symbol {parameter!r}", (*path, "slipping"))
        found = False
    names = {c.name for c in constraints}
    for key in ("friction", "normal"):
        if spec.get(key) not in names:
            errors.add(f"unknown constraint {spec.get(key)!r}", (*path, key))
            found = False
    coefficient = errors.read(spec.get("coefficient"), symbols, (*path, "coefficient"))
    if not found or coefficient is None:
        return None
    return Quantity(
        name,
        QuantityKind.SLIPPING,
        parameter=symbols[str(parameter)],
        contact=(str(spec["friction"]), str(spec["normal"])),
        coefficient=coefficient,
    )


def _check_slip_quantities(
    quantities: tuple[Quantity, ...], frictions: tuple[Friction, ...], errors: _Collector
) -> None:
    """A sliding-phase quantity needs the kinetic friction whose slipping it follows."""
    for quantity in quantities:
        path: Path = ("quantities", quantity.name, quantity.kind.value)
        if quantity.kind is QuantityKind.SLIP_TIME and not any(
            f.constraint == quantity.target for f in frictions
        ):
            errors.add(f"no kinetic friction acts at the constraint {quantity.target!r}", path)
        elif quantity.kind in SLIP_KINDS - {QuantityKind.SLIP_TIME} and len(frictions) != 1:
            errors.add(
                f"the model has {len(frictions)} kinetic frictions; this quantity follows the slipping of "
                "exactly one (ask for `slip_time: <constraint>` instead)",
                path,
            )
