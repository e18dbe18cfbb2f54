"""Released contacts: a string gone slack, a surface the body has left, modelled as not acting.

    coordinates: [y1, y2]                  # each body its own coordinate: the string no longer ties them
    constraints:
      string: {kind: string, gap: "y_m1 + y_m2"}
    released: [string]                     # the thrust on m2 has made it go slack

A released constraint is kept out of `Model.constraints`, so every method (Newton, Lagrange, energy,
d'Alembert, the simulation) derives the motion without it; it lives on in `Model.released`, its gap
checked where the motion lets go and wherever a quantity is taken `at` (not negative there: the bodies
do not pass through it). Releasing it must be the physics, not a way round a refusal:

- the coordinates must let its gap change (`check_freed`): coordinates that build the constraint in
  (both masses on one `s`) give the freed bodies no way to move apart;
- at the state, where the contact lets go, it must not hold (`check_released`): held, its force would
  be negative on the whole domain (the string would push), the very sign `contacts.py` refuses on a
  held contact, and its gap must open (the bodies already apart or moving apart, or its second
  derivative in the free motion positive).
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

import sympy

from physics.answer_text import typed_text
from physics.engine import tidy
from physics.engine.mechanics import Mechanics, time_derivative
from physics.engine.method import Method, NotApplicable
from physics.engine.model import AuthoredElement, Constraint, ConstraintKind, Friction, Model, Quantity
from physics.engine.newton import NewtonMethod
from physics.engine.signs import Sign, point_text, sign_on_domain, where_negative
from physics.engine.text import Path
from physics.errors import DerivationError, PhyscheckError, SpecError, SpecErrors

KEY = "released"


@dataclass(frozen=True)
class _Words:
    thing: str  # the contact
    lets_go: str  # what releasing it means
    force: str  # its force's name
    holds: str  # what it does with its force positive
    then: str  # so it is not released


_WORDS = {
    ConstraintKind.STRING: _Words(
        "the string", "it goes slack", "tension", "the string is taut", "it pulls, it does not go slack"
    ),
    ConstraintKind.SURFACE: _Words(
        "the surface",
        "the body leaves it",
        "normal force",
        "the surface pushes",
        "the body stays on it, it does not leave it",
    ),
}


def read(
    value: Any, constraints: Sequence[Constraint], add: Callable[[str, Path], None]
) -> tuple[tuple[Constraint, ...], tuple[Constraint, ...]]:
    """(the constraints that hold, the released ones) from the `released:` list of constraint names."""
    if value is None:
        return tuple(constraints), ()
    if not isinstance(value, list) or not value:
        add("a list of the strings and surfaces that no longer act", (KEY,))
        return tuple(constraints), ()
    by_name = {c.name: c for c in constraints}
    names: list[str] = []
    for index, name in enumerate(value):
        constraint = by_name.get(name) if isinstance(name, str) else None
        if constraint is None:
            add(f"unknown constraint {name!r}", (KEY, index))
        elif constraint.kind not in _WORDS:
            add(
                f"constraint {name!r} is {constraint.kind.value}: it holds both ways and cannot be released "
                "(only a string goes slack and only a surface is left)",
                (KEY, index),
            )
        elif name in names:
            add(f"{name!r} is released twice", (KEY, index))
        else:
            names.append(name)
    return tuple(c for c in constraints if c.name not in names), tuple(by_name[n] for n in names)


def check_elements(value: Any, elements: Sequence[AuthoredElement]) -> None:
    """An element builds its constraints into its coordinates (a pulley's one `s`, a block's distance
    along its surface): one of them released is refused at `released`, asking for it by hand."""
    if not isinstance(value, list):
        return
    faults = [
        SpecError(
            f"constraint {name!r} comes from the {element.kind} element {element.name!r}, whose coordinates "
            "keep it shut: state it under `constraints:` by its gap, its bodies on coordinates of their own "
            "(positions in them, in which it can open), in place of the element",
            (KEY, index),
        )
        for index, name in enumerate(value)
        for element in elements
        if name in element.constraints
    ]
    if faults:
        raise SpecErrors(faults)


def check_uses(
    released: Sequence[Constraint],
    frictions: Sequence[Friction],
    quantities: Sequence[Quantity],
    add: Callable[[str, Path], None],
) -> None:
    """Nothing may rest on a released contact's force: it is zero."""
    names = {c.name for c in released}
    for index, friction in enumerate(frictions):
        if friction.constraint in names:
            add(
                f"constraint {friction.constraint!r} is released: with no normal force there is no friction "
                "(leave this entry out, `friction: null` in a scenario)",
                ("friction", index, "constraint"),
            )
    for quantity in (q for top in quantities for q in _nested(top)):
        if quantity.target in names or quantity.contact[1] in names:
            add(
                f"constraint {quantity.target or quantity.contact[1]!r} is released: it exerts no force "
                "(ask for its force in a model or scenario where it holds)",
                ("quantities", quantity.name.split(".")[0]),
            )


def _nested(quantity: Quantity) -> list[Quantity]:
    return [quantity, *(_nested(quantity.inner) if quantity.inner is not None else [])]


def check_freed(model: Model, mech: Mechanics) -> None:
    """Each released constraint's gap, with the bodies placed by the coordinates, must depend on them:
    coordinates that keep it at a constant leave the released bodies no freedom to part."""
    place = {d.symbol: d.mapping for d in mech.dofs}
    moving = set(mech.q)
    for index, constraint in enumerate(model.released):
        gap = tidy.simplify(constraint.gap.subs(place))
        if gap.free_symbols & moving:
            continue
        words = _WORDS[constraint.kind]
        bodies = sorted({d.body for d in mech.dofs if d.symbol in constraint.gap.free_symbols})
        raise DerivationError(
            f"constraint {constraint.name!r} is released ({words.lets_go}), but the coordinates build it in: "
            f"its gap is {typed_text(gap)} wherever they are, so its bodies cannot part. Give "
            f"{_listed(bodies)} coordinates of their own (in which {words.thing} can open) and state "
            f"{words.thing} under `constraints:` by its gap",
            path=(KEY, index),
        )


def check_released(model: Model, free: Method) -> dict[str, str]:
    """Each released contact lets go at the state: a check's name -> what was shown; DerivationError at
    `released.<index>` where it would hold (its force, held, positive somewhere) or its gap would close.
    `free` is a method of the released model, for its accelerations."""
    shown = [_lets_go(model, constraint, free, (KEY, i)) for i, constraint in enumerate(model.released)]
    for constraint in model.released:
        _check_stays_open(model, constraint)
    return {"released contacts": "; ".join(shown)} if shown else {}


def _check_stays_open(model: Model, constraint: Constraint) -> None:
    """Where a quantity is taken `at` a place, a released contact's gap must not be negative there: the
    motion would have carried the bodies through it (a ball asked about below the floor it left)."""
    place = {d.symbol: d.mapping for d in Mechanics(model).dofs}
    state = dict(model.state)
    for quantity in model.quantities:
        if not quantity.at:
            continue
        there = {model.coordinate(name).symbol: value for name, value in quantity.at}
        gap = tidy.simplify(constraint.gap.subs(place).subs(there).subs(state))
        if gap.free_symbols - set(model.parameters):
            continue
        if sign_on_domain(gap, model).sign in (Sign.NEGATIVE, Sign.MIXED):
            raise DerivationError(
                f"{quantity.name}: the released constraint {constraint.name!r} has the gap {typed_text(gap)} "
                "there, negative: the bodies would have passed through the contact to get there",
                quantity=quantity.name,
                path=("quantities", quantity.name, "at"),
            )


def _lets_go(model: Model, constraint: Constraint, free: Method, path: Path) -> str:
    """What shows that the contact lets go at the state; DerivationError where it does not."""
    words = _WORDS[constraint.kind]
    name = constraint.name
    gap, rate, growth = _gap_at_state(model, constraint, free)
    gap_sign = sign_on_domain(gap, model).sign if gap is not None else Sign.UNKNOWN
    if gap_sign is Sign.POSITIVE and gap != 0:
        return f"{name} is open at the state (gap {typed_text(gap)})"
    if gap_sign in (Sign.NEGATIVE, Sign.MIXED):
        raise DerivationError(
            f"constraint {name!r} is released, but its gap {typed_text(gap)} is negative at the state: the "
            "bodies would overlap (a string longer than it is)",
            path=path,
        )
    opening = sign_on_domain(rate, model).sign if rate is not None else Sign.UNKNOWN
    if opening is Sign.POSITIVE and rate != 0:
        return f"{name} opens at the rate {typed_text(rate)}"
    if opening in (Sign.NEGATIVE, Sign.MIXED):
        raise DerivationError(
            f"constraint {name!r} is released, but its gap closes at the rate {typed_text(rate)}: the "
            "bodies move into the contact, which then acts",
            path=path,
        )
    # touching, and not moving apart: it lets go only if, held, it would have to pull (or push)
    force = _held_force(model, constraint)
    if force is not None:
        _refuse_if_held(model, constraint, force, path)
    held = "" if force is None else f"held, its {words.force} {typed_text(force)} would be negative"
    if growth is None:
        return f"{name}: {held or 'its letting go could not be decided'}"
    if growth == 0 and force is not None and force == 0:  # at the threshold itself (the top of the dome)
        return f"{name}: lets go at its threshold (held, its {words.force} would be 0)"
    if growth == 0 or sign_on_domain(growth, model).sign is not Sign.POSITIVE:
        raise DerivationError(
            f"constraint {name!r} is released ({words.lets_go}), but its gap does not grow: its second "
            f"derivative in the free motion is {typed_text(growth)}, not positive on the whole domain, so "
            "the bodies do not part there. Keep the domain where they do (domain.positive), or hold the "
            "contact",
            path=path,
        )
    return f"{name}: {held + '; ' if held else ''}free, its gap grows as {typed_text(growth)} > 0"


def _gap_at_state(
    model: Model, constraint: Constraint, free: Method
) -> tuple[sympy.Expr | None, sympy.Expr | None, sympy.Expr | None]:
    """The gap, its rate and its second derivative in the free motion at the state, each None where the
    state leaves it open (a coordinate whose value the model does not give)."""
    place = {d.symbol: d.mapping for d in Mechanics(model).dofs}
    gap = constraint.gap.subs(place)
    rate = time_derivative(gap, model)
    second = time_derivative(rate, model)
    try:
        accelerations = {c.acceleration: free.acceleration(c.name) for c in model.coordinates}
    except (NotApplicable, DerivationError):
        accelerations = {}  # the growth is then left open: the held force decides
    except PhyscheckError:
        raise
    except Exception:  # sympy's failures on an uploaded model: the growth left open too
        accelerations = {}
    state = dict(model.state)

    def known(expr: sympy.Expr) -> sympy.Expr | None:
        value = tidy.simplify(expr.subs(accelerations).subs(state))
        return None if value.free_symbols - set(model.parameters) else value

    return known(gap), known(rate), known(second)


def _held_force(model: Model, constraint: Constraint) -> sympy.Expr | None:
    """The contact's force at the state were it held: Newton's, in the bodies' Cartesian coordinates
    (which need no coordinate to build it in)."""
    held = dataclasses.replace(
        model,
        constraints=(*model.constraints, constraint),
        released=tuple(c for c in model.released if c != constraint),
        quantities=(),
        limits=(),
        scenarios=(),
    )
    try:
        force = NewtonMethod(held, Mechanics(held)).force(constraint.name)
    except Exception:  # the equations not determined, or sympy's failures: the gap's growth still decides
        return None
    return None if force.free_symbols - set(model.parameters) else force


def _refuse_if_held(model: Model, constraint: Constraint, force: sympy.Expr, path: Path) -> None:
    """Refused where the held contact's force is positive: there it holds, it does not let go."""
    found = sign_on_domain(-force, model)
    if found.sign not in (Sign.NEGATIVE, Sign.MIXED):
        return
    words = _WORDS[constraint.kind]
    loads = [s for f in model.force_entries for e in f.expressions() for s in sorted(e.free_symbols, key=str)]
    # the factor that decides shows once the domain's own bounds are off
    unbounded = dataclasses.replace(model, positive=())
    if found.sign is Sign.NEGATIVE and sign_on_domain(-force, unbounded).sign is Sign.NEGATIVE:
        where = "on the whole domain"  # whatever the symbols: no condition to say
    elif found.sign is Sign.NEGATIVE:
        condition = where_negative(-force, unbounded, loads)
        where = f"wherever {condition}, which is the whole domain" if condition else "on the whole domain"
    else:
        condition = where_negative(-force, model, loads)
        where = f"where {condition}" if condition else f"at {point_text(found.negative_at or {})}"
    raise DerivationError(
        f"constraint {constraint.name!r} is released, but {words.holds} {where}: {words.then} (held, its "
        f"{words.force} {typed_text(force)} is positive there). Keep the domain where "
        f"{words.lets_go} (domain.positive), or hold it",
        path=path,
    )


def _listed(names: Sequence[str]) -> str:
    return names[0] if len(names) == 1 else ", ".join(names[:-1]) + " and " + names[-1]
