"""Reading the quantities taken where the motion from the state gets to: `speed`/`velocity` (and `force`,
`acceleration`) `at` a configuration, and a trajectory's `time_of_flight`, `range` and `max_height`.

    speed_bottom: {speed: block, at: {theta: 0}}        # a body's speed when theta reaches 0
    rate: {velocity: theta, at: {theta: 0}}             # the coordinate's velocity there
    normal_bottom: {force: track, at: {theta: 0}}       # the constraint force there, with that velocity
    flight: {time_of_flight: ball, level: "-h"}         # until the body's y is -h (default: launch height)
    up: {range: ball, slope: theta}                     # along an incline through the launch point
    rebound: {max_height: ball, after: impact}          # in the motion just after the model's impact
    later: {max_height: ball, after: impact, bounces: n}   # after the n-th bounce off a fixed floor
"""

from __future__ import annotations

from collections.abc import Callable, Collection, Mapping, Sequence
from typing import Any

import sympy

from physics.engine.model import (
    REACH_KINDS,
    TRAJECTORY_KINDS,
    Body,
    Constraint,
    Coordinate,
    Quantity,
    QuantityKind,
)
from physics.engine.text import Path, read_expr
from physics.errors import SpecError

AT_KINDS = REACH_KINDS | {QuantityKind.FORCE, QuantityKind.ACCELERATION}
LEVEL_KINDS = frozenset({QuantityKind.TIME_OF_FLIGHT, QuantityKind.RANGE})
Report = Callable[[str, Path], None]


def handles(kind: QuantityKind, spec: Mapping[str, Any]) -> bool:
    """Whether this module reads the quantity (its kind is one of ours, or it is taken `at` a place)."""
    return kind in REACH_KINDS | TRAJECTORY_KINDS or (kind in AT_KINDS and "at" in spec)


def load_quantity(
    name: str,
    kind: QuantityKind,
    spec: Mapping[str, Any],
    path: Path,
    symbols: Mapping[str, sympy.Symbol],
    coordinates: Sequence[Coordinate],
    constraints: Sequence[Constraint],
    report: Report,
    others: Collection[str] = (),
) -> Quantity | None:
    """The quantity, or None with every fault reported at its path; `others` are the model's other
    quantities, named in the refusal of an `at` that names one. Body targets are checked later
    (`check_targets`), once the bodies are known."""
    allowed = (
        {kind.value, "after"}
        | ({"bounces"} if "after" in spec else set())
        | ({"at"} if kind in AT_KINDS else set())
        | ({"level", "slope"} if kind in LEVEL_KINDS else set())
    )
    faults = len([None for key in spec if key not in allowed])
    for key in spec:
        if key not in allowed:
            report(f"unknown key {key!r}; expected one of {sorted(allowed)}", (*path, str(key)))
    target = spec[kind.value]
    where: Path = (*path, kind.value)
    pools = {
        QuantityKind.VELOCITY: ("coordinate", {c.name for c in coordinates}),
        QuantityKind.ACCELERATION: ("coordinate", {c.name for c in coordinates}),
        QuantityKind.FORCE: ("constraint", {c.name for c in constraints}),
    }
    if kind in pools and target not in pools[kind][1]:
        report(f"unknown {pools[kind][0]} {target!r}", where)
        faults += 1
    elif kind not in pools and not isinstance(target, str):
        report("the name of a body", where)
        faults += 1
    at: tuple[tuple[str, sympy.Expr], ...] = ()
    if kind in REACH_KINDS and "at" not in spec:
        report(
            "required: where the coordinate gets to, e.g. {theta: 0} (the speed is taken when the motion from "
            "the state reaches it)",
            (*path, "at"),
        )
        faults += 1
    elif "at" in spec:
        at, bad = _read_at(spec["at"], symbols, coordinates, (*path, "at"), report, others)
        faults += bad
    if "level" in spec and "slope" in spec:
        report(
            "the body lands at a height (`level`) or on a slope through the launch point (`slope`), not both",
            (*path, "slope"),
        )
        faults += 1
    landing: dict[str, sympy.Expr] = {}
    for key in ("level", "slope"):
        if key in spec:
            try:
                landing[key] = read_expr(spec[key], symbols, (*path, key))
            except SpecError as error:
                report(error.message, error.path)
                faults += 1
    after = spec.get("after", "")
    if after not in ("", "impact"):
        report(
            "`after: impact` takes the quantity in the motion just after the model's impact", (*path, "after")
        )
        faults += 1
    bounces = None
    if "bounces" in spec:
        try:
            bounces = read_expr(spec["bounces"], symbols, (*path, "bounces"))
        except SpecError as error:
            report(error.message, error.path)
            faults += 1
    if faults:
        return None
    return Quantity(
        name,
        kind,
        str(target),
        at=at,
        level=landing.get("level"),
        slope=landing.get("slope"),
        after=str(after),
        bounces=bounces,
    )


def _read_at(
    value: Any,
    symbols: Mapping[str, sympy.Symbol],
    coordinates: Sequence[Coordinate],
    path: Path,
    report: Report,
    others: Collection[str],
) -> tuple[tuple[tuple[str, sympy.Expr], ...], int]:
    names = {c.name for c in coordinates}
    if not isinstance(value, Mapping) or len(value) != 1:
        report("one coordinate and the value it reaches, e.g. {theta: 0}", path)
        return (), 1
    ((name, text),) = value.items()
    if name not in names:
        report(f"unknown coordinate {name!r}; expected one of {sorted(names)}", (*path, str(name)))
        return (), 1
    try:
        return ((str(name), read_expr(text, symbols, (*path, str(name)))),), 0
    except SpecError as error:
        report(error.message + _at_hint(text, name, symbols, others), error.path)
        return (), 1


def _at_hint(
    text: object, coordinate: str, symbols: Mapping[str, sympy.Symbol], others: Collection[str]
) -> str:
    """How to write an `at` that names a word no symbol has: often another quantity (`{y: top}`)."""
    word = text.strip() if isinstance(text, str) else ""
    if not word.isidentifier() or word in symbols:
        return ""
    said = (
        f" `at` takes the value {coordinate} reaches as an expression in the problem's symbols, not the name "
        "of another quantity"
    )
    if word in others:
        said += (
            f": {word} is a quantity of this model, so write in its place the expression it comes to, in "
            f'those symbols, as {{{coordinate}: "..."}}'
        )
    return said + "."


def check_targets(
    quantities: Sequence[Quantity],
    bodies: Sequence[Body],
    state: Sequence[tuple[sympy.Symbol, sympy.Expr]],
    coordinates: Sequence[Coordinate],
    report: Report,
) -> None:
    """A body target names a body; the motion starts at a configuration the state gives."""
    names = {b.name for b in bodies}
    given = {s for s, _ in state}
    unplaced = [c.name for c in coordinates if c.symbol not in given]
    starting = False
    for q in quantities:
        path: Path = ("quantities", q.name, q.kind.value)
        if q.kind in TRAJECTORY_KINDS | {QuantityKind.SPEED} and q.target not in names:
            report(f"unknown body {q.target!r}; expected one of {sorted(names)}", path)
        elif q.kind in TRAJECTORY_KINDS and not any(a == "y" for a, _ in _body(bodies, q.target).position):
            report("the body has no height (y position) to fly in", path)
        starting = starting or bool(q.at) or q.kind in TRAJECTORY_KINDS
    if starting and unplaced:
        report(
            f"the motion starts at the model's state: give where {', '.join(unplaced)} "
            f"{'starts' if len(unplaced) == 1 else 'start'} under `state`",
            ("state",),
        )


def _body(bodies: Sequence[Body], name: str) -> Body:
    return next(b for b in bodies if b.name == name)
