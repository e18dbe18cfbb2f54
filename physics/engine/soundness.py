"""Checks that the model says what physics allows, beside the methods' agreement: gravity points down,
and a quantity that is a magnitude (a length, a time, a speed, a frequency) is not negative or complex.

Every method reads the same model, so a weight pointing up or a spring "stretch" of −m g/k is derived,
proved and simulated consistently; only a check of the model's own sense refuses it.
"""

from __future__ import annotations

import re
from collections.abc import Mapping

import sympy

from physics.answer_text import typed_text
from physics.dimensions import Dimension
from physics.engine.dimensional import LENGTH, TIME
from physics.engine.model import MAGNITUDE_KINDS, Model, Quantity, QuantityKind
from physics.engine.proof import domain_points
from physics.engine.signs import Sign, point_text, sign_on_domain, where_negative
from physics.errors import DerivationError
from physics.symbolic.dimensional import DimensionMismatch, UnknownDimension, expression_dimension

# what a quantity of that dimension is, to say so in a refusal
_MAGNITUDES = {LENGTH: "a length", TIME: "a time", LENGTH / TIME: "a speed", TIME**-1: "a frequency"}
# magnitudes by their kind; a range and a slip distance are displacements, signed by the axis
_NEVER_NEGATIVE = MAGNITUDE_KINDS - {QuantityKind.RANGE, QuantityKind.SLIP_DISTANCE}


def check_gravity(model: Model) -> None:
    """`gravity: g` is the weight's magnitude along the model's down (−y): it must not be negative."""
    if model.gravity is None:
        return
    found = sign_on_domain(model.gravity, model)
    if found.sign is Sign.POSITIVE or found.sign is Sign.UNKNOWN:
        return
    shown = typed_text(model.gravity)
    if found.sign is Sign.NOT_REAL:
        raise DerivationError(f"gravity {shown} is not real on the domain", path=("gravity",))
    where = (
        "on the whole domain"
        if found.sign is Sign.NEGATIVE
        else f"where {where_negative(model.gravity, model) or point_text(found.negative_at or {})}"
    )
    raise DerivationError(
        f"gravity {shown} is negative {where}: the weight would point up (+y), against the model's own "
        "down (gravity pulls along −y, y is up). Write gravity as its magnitude (g), and the positions "
        "with y up",
        path=("gravity",),
    )


_GRAVITY_NAME = re.compile(r"g(_\w+)?")


def check_weight_as_force(model: Model) -> None:
    """Without `gravity:`, a given force of a body's mass times g (an acceleration: `g`, `g_0`, `g_moon`)
    along +y is its weight typed with the sign of "up": every method and the simulation would lift the
    body with it."""
    if model.gravity is not None:
        return
    dims = dict(model.dimensions)
    for force in model.forces:
        components = dict(force.components)
        up = components.get("y")
        if up is None or set(components) - {"y"} or not force.constant(model.moving_symbols):
            continue
        mass = model.body(force.body).mass
        ratio = sympy.simplify(up / mass)
        if not isinstance(ratio, sympy.Symbol) or ratio not in model.parameters:
            continue
        # gravity's own letter: a lift's or a rocket's m*A up, in a model without gravity, is a push
        if not _GRAVITY_NAME.fullmatch(ratio.name) or dims.get(ratio, LENGTH / TIME**2) != LENGTH / TIME**2:
            continue
        shown = typed_text(up)
        raise DerivationError(
            f"the force {shown} on {force.body} points up (+y) and the model has no gravity: if it is "
            f"{force.body}'s weight, it points down. Write `gravity: {ratio}` (it acts along −y on every "
            f"body) and leave this force out, or write it as {{y: {typed_text(-up)}}}",
            path=("forces", model.force_entries.index(force)),
        )


def check_state_in_range(model: Model) -> None:
    """Where the state puts a coordinate lies inside the range the model declares for it: the range says
    which side of an anchor a body is on (a spring's length is |d|, and -d on the negative side), so a
    state on the other side is derived as a body on the declared side, somewhere else. Cart 2 placed at
    d = L0 ahead of cart 1 with d declared negative gives a spring squeezed by 2 L0, and an acceleration
    for a state nobody posed."""
    state = dict(model.state)
    for name, low, high in model.coordinate_ranges:
        value = state.get(model.coordinate(name).symbol)
        if value is None or value.free_symbols - set(model.parameters):
            continue
        for point in domain_points(model, 12, seed=7):
            try:
                at, lowest, highest = (float(sympy.N(e.subs(point))) for e in (value, low, high))
            except (TypeError, ValueError):
                break
            slack = 1e-9 * max(1.0, abs(at))
            if lowest - slack <= at <= highest + slack:  # its ends included: a body resting at a stop
                continue
            raise DerivationError(
                f"the state puts {name} at {typed_text(value)}, outside its declared range "
                f"[{typed_text(low)}, {typed_text(high)}] at {point_text(point)} ({name} = {at:.4g}): the "
                "range says which side the body is on (of a spring's anchor, of a surface), so the model "
                "would be derived for a body on the other side. Check the range's side, or the state",
                path=("state", name),
            )


def check_magnitudes(model: Model, quantities: Mapping[str, sympy.Expr]) -> None:
    """A length, time, speed or frequency proved negative, or not real, on the whole domain is refused at
    the quantity (any quantity that is nowhere real is)."""
    dims = dict(model.dimensions)
    for quantity in model.quantities:
        value = quantities[quantity.name]
        found = sign_on_domain(value, model)
        path = ("quantities", quantity.name)
        if found.sign is Sign.NOT_REAL:
            raise DerivationError(
                f"{quantity.name} = {typed_text(value)} is not real anywhere on the domain: check the model's "
                "signs (a square root of a negative)",
                path=path,
            )
        if found.sign is not Sign.NEGATIVE:
            continue
        what = _magnitude(quantity, value, dims)
        if what is not None:
            raise DerivationError(
                f"{quantity.name} = {typed_text(value)} is {what}, yet negative on the whole domain: check "
                "the model's signs (a position's direction, a coordinate's sense, a spring's side)",
                path=path,
            )


def _magnitude(quantity: Quantity, value: sympy.Expr, dims: Mapping[sympy.Symbol, Dimension]) -> str | None:
    """What makes the quantity a magnitude ("a length"), or None when it may be signed."""
    if quantity.kind in _NEVER_NEGATIVE:
        words = quantity.kind.value.replace("_", " ")
        return f"{'an' if words[0] in 'aeiou' else 'a'} {words}, never negative"
    if quantity.kind is not QuantityKind.EXPRESSION or not dims:
        return None
    try:
        dimension = expression_dimension(value, dims)
    except (DimensionMismatch, UnknownDimension):
        return None
    return _MAGNITUDES.get(dimension)
