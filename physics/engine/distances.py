"""Distances in potentials are lengths: never a signed coordinate difference passed off as a distance.

With two or more shared axes the distance is the Euclidean length. On one shared axis it is |b - a|,
and the absolute value is resolved once, here, from what the model declares: the sign of b - a that
the symbols' assumptions or the coordinates' ranges fix. A potential even in the distance (k d^2/2)
needs no side. Anything else is refused with the reason: a hanging spring k (d - L0)^2/2 whose side
is not declared would otherwise derive an equilibrium on the wrong side of the anchor.
"""

from __future__ import annotations

import dataclasses
import itertools
import random

import sympy

from physics.answer_text import typed_text
from physics.engine import tidy
from physics.engine.model import Model, PairPotential
from physics.engine.proof import domain_points
from physics.errors import DerivationError, SpecError, SpecErrors

SIDE_SAMPLES = 24


def separations(model: Model, pair: PairPotential) -> list[tuple[sympy.Expr, sympy.Expr]]:
    """(start, end) positions along each axis the pair shares, in the generalized coordinates."""
    first = model.body(pair.bodies[0])
    if len(pair.bodies) == 2:
        second = dict(model.body(pair.bodies[1]).position)
        return [(expr, second[axis]) for axis, expr in first.position if axis in second]
    anchor = dict(pair.anchor)
    return [(anchor[axis], expr) for axis, expr in first.position if axis in anchor]


def with_distance_sides(model: Model) -> Model:
    """The model with each one-axis potential's side resolved; SpecErrors (with paths) where it cannot be."""
    errors: list[SpecError] = []
    potentials: list[PairPotential] = []
    for index, pair in enumerate(model.potentials):
        path = ("potentials", index)
        ends = separations(model, pair)
        if not ends:
            errors.append(SpecError(f"the bodies of {list(pair.bodies)} share no axis", (*path, "bodies")))
            continue
        if len(ends) > 1:
            potentials.append(pair)
            continue
        start, end = ends[0]
        separation = tidy.simplify(end - start)
        side = _side(separation, model)
        if side is None:
            if tidy.simplify(pair.energy.subs(pair.distance, -pair.distance) - pair.energy) == 0:
                side = 0
            else:
                errors.append(SpecError(_undecided(model, pair, separation), (*path, "distance")))
                continue
        potentials.append(dataclasses.replace(pair, side=side))
    if errors:
        raise SpecErrors(errors)
    return dataclasses.replace(model, potentials=tuple(potentials))


def _side(separation: sympy.Expr, model: Model) -> int | None:
    """+1 or -1 when the model fixes the sign of the separation, else None."""
    if separation.is_nonnegative:
        return 1
    if separation.is_nonpositive:
        return -1
    names = {c.symbol: c.name for c in model.coordinates}
    ranges = {name: (low, high) for name, low, high in model.coordinate_ranges}
    moving = [names[s] for s in separation.free_symbols if s in names]
    if (bounded := _side_from_bounds(separation, model, ranges)) is not None:
        return bounded
    if any(name not in ranges or not all(b.is_finite for b in ranges[name]) for name in moving):
        return None
    rng = random.Random(5)  # noqa: S311 - reproducible sampling, not security
    signs: set[bool] = set()
    try:
        for point in domain_points(model, SIDE_SAMPLES, seed=17):
            at: dict[sympy.Symbol, float] = dict(point)
            for c in model.coordinates:
                if c.name in moving:
                    low, high = (float(b.subs(point)) for b in ranges[c.name])
                    at[c.symbol] = low + (high - low) * (0.01 + 0.98 * rng.random())
            signs.add(float(separation.subs(at)) > 0)
    except (DerivationError, TypeError, ValueError):
        return None
    return (1 if signs == {True} else -1) if len(signs) == 1 else None


def _side_from_bounds(
    separation: sympy.Expr, model: Model, ranges: dict[str, tuple[sympy.Expr, sympy.Expr]]
) -> int | None:
    """The sign proved from the coordinates' declared bounds alone (a spring's foot at -L0 with y >= -L0
    gives L0 + y >= 0, also on a range open above): each coordinate is one of its bounds plus or minus a
    nonnegative amount, and sympy's assumptions must settle the sign for every such amount. The bounds may
    differ by coordinate: a molecule's middle atom in [0, L0] and the next in [L0, oo] keep x3 - x2 >= 0."""
    moved = [c for c in model.coordinates if c.symbol in separation.free_symbols]
    if not moved or any(c.name not in ranges for c in moved):
        return None
    for ends in itertools.product((0, 1), repeat=len(moved)):  # 0: from the lower bound up
        if not all(ranges[c.name][end].is_finite for c, end in zip(moved, ends, strict=True)):
            continue
        shifted = separation.subs(
            {
                c.symbol: ranges[c.name][end]
                + (1 - 2 * end) * sympy.Symbol(f"shift_{c.name}", nonnegative=True)
                for c, end in zip(moved, ends, strict=True)
            }
        )
        shifted = tidy.simplify(shifted)
        if shifted.is_nonnegative:
            return 1
        if shifted.is_nonpositive:
            return -1
    return None


def _undecided(model: Model, pair: PairPotential, separation: sympy.Expr) -> str:
    names = {c.symbol: c.name for c in model.coordinates}
    moving = sorted(names[s] for s in separation.free_symbols if s in names)
    what = (
        f"between {pair.bodies[0]} and {pair.bodies[1]}"
        if len(pair.bodies) == 2
        else f"of {pair.bodies[0]} from its anchor"
    )
    hint = (
        f"declare the side: a range for {', '.join(moving)} under domain.ranges (e.g. {moving[0]}: [0, oo]), "
        "or a coordinate declared positive in the symbol table"
        if moving
        else "declare the parameters' signs so that it is fixed"
    )
    return (
        f"the distance {pair.distance} {what} is the length |{typed_text(separation)}|, and the model does not "
        f"say which sign {typed_text(separation)} has; the energy {typed_text(pair.energy)} is not even in "
        f"{pair.distance}, so a signed "
        f"distance would put the equilibrium on the wrong side of the anchor: {hint}"
    )
