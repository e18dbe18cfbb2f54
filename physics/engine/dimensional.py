"""Dimensional consistency of a model: every position a length, every energy an energy, and so on.

A check independent of the methods: they all work from the same model, so a potential written with a
force where an energy belongs would be derived, proved and simulated "consistently" and still be
wrong. Runs when the problem declares its symbols' dimensions; a coordinate without one is a length
or a pure number (an angle), whichever makes the positions lengths.
"""

from __future__ import annotations

import itertools
from collections.abc import Mapping

import sympy

from physics.answer_text import typed_text
from physics.dimensions import DIMENSIONLESS, Dimension, describe
from physics.engine.model import Model
from physics.engine.text import Path
from physics.errors import SpecError
from physics.symbolic.dimensional import DimensionMismatch, UnknownDimension, expression_dimension

MASS = Dimension({"mass": 1})
LENGTH = Dimension({"length": 1})
TIME = Dimension({"time": 1})
ENERGY = MASS * LENGTH**2 / TIME**2
FORCE = MASS * LENGTH / TIME**2
ACCELERATION = LENGTH / TIME**2
SPEED = LENGTH / TIME
INERTIA = MASS * LENGTH**2
MAX_UNKNOWN_COORDINATES = 8  # 2^8 assignments at most, each a handful of cheap checks

Dims = Mapping[sympy.Symbol, Dimension]
Expected = Dimension | None  # None: any dimension, as long as the expression is consistent
Check = tuple[Path, sympy.Expr, Expected]


def check_dimensions(model: Model, declared: Mapping[str, Dimension]) -> list[SpecError]:
    """Every dimensional fault of the model, with its path (empty when consistent)."""
    dims: dict[sympy.Symbol, Dimension] = {
        s: declared[s.name] for s in model.parameters if s.name in declared
    }
    unknown = [c for c in model.coordinates if c.symbol not in dims]
    best: list[SpecError] | None = None
    for choice in itertools.product((LENGTH, DIMENSIONLESS), repeat=len(unknown[:MAX_UNKNOWN_COORDINATES])):
        trial = {**dims, **{c.symbol: d for c, d in zip(unknown, choice, strict=False)}}
        faults = _faults(_placement(model), trial)
        if best is None or len(faults) < len(best):
            best = faults
        if not faults:
            break
    assert best is not None
    if best:
        return best
    coordinate_dims = {**dims, **{c.symbol: d for c, d in zip(unknown, choice, strict=False)}}
    return _faults(_physics(model, coordinate_dims), _with_model_symbols(model, coordinate_dims))


def _placement(model: Model) -> list[Check]:
    checks: list[Check] = []
    for body in model.bodies:
        for axis, expr in body.position:
            checks.append((("bodies", body.name, "position", axis), expr, LENGTH))
        if body.angle is not None:
            checks.append((("bodies", body.name, "angle"), body.angle, DIMENSIONLESS))
    return checks


def _with_model_symbols(model: Model, dims: Dims) -> dict[sympy.Symbol, Dimension]:
    """Add the Cartesian symbols (x_, y_ lengths; phi_ angles), velocities and the distances."""
    result = dict(dims)
    for name, symbol in model.cartesian:
        result[symbol] = DIMENSIONLESS if name.startswith("phi_") else LENGTH
    for c in model.coordinates:
        if c.symbol in dims:
            result[c.velocity] = dims[c.symbol] / TIME
    for pair in model.potentials:
        result[pair.distance] = LENGTH
    if model.time is not None:
        result.setdefault(model.time, TIME)
    return result


def _physics(model: Model, dims: Dims) -> list[Check]:
    checks: list[Check] = []
    for body in model.bodies:
        checks.append((("bodies", body.name, "mass"), body.mass, MASS))
        if body.inertia != 0:
            checks.append((("bodies", body.name, "inertia"), body.inertia, INERTIA))
    if model.gravity is not None:
        checks.append((("gravity",), model.gravity, ACCELERATION))
    for constraint in (*model.constraints, *model.released):
        checks.append((("constraints", constraint.name, "gap"), constraint.gap, None))
    for index, friction in enumerate(model.frictions):
        checks.append((("friction", index, "coefficient"), friction.coefficient, DIMENSIONLESS))
    if model.frame is not None and model.frame.rate is not None:  # before the centrifugal energy it makes
        checks.append((("frame", "rate"), model.frame.rate, TIME**-1))
    for index, pair in enumerate(model.potentials):
        checks.append((("potentials", index, "energy"), pair.energy, ENERGY))
    names = {c.symbol: c.name for c in model.coordinates} | {
        c.velocity: f"{c.name}_dot" for c in model.coordinates
    }
    if model.time is not None:
        names[model.time] = "t"
    for symbol, value in model.state:
        if symbol in names and value != 0:
            own = dims.get(symbol) if symbol in dims else _velocity_dim(model, symbol, dims)
            own = TIME if symbol == model.time else own
            checks.append((("state", names[symbol]), value, own))
    for index, force in enumerate(model.force_entries):
        checks += force.dimensions(("forces", index))
    if model.collision is not None:
        checks.append((("collision", "mass"), model.collision.projectile_mass, MASS))
        if model.collision.speed is not None:
            checks.append((("collision", "speed"), model.collision.speed, SPEED))
    if model.impact is not None:
        for axis, component in model.impact.normal:
            checks.append((("impact", "normal", axis), component, None))
        if model.impact.restitution is not None:
            checks.append((("impact", "restitution"), model.impact.restitution, DIMENSIONLESS))
        if model.impact.release is not None:
            checks.append((("impact", "release"), model.impact.release, ENERGY))
    coordinates = {c.name: c.symbol for c in model.coordinates}
    for quantity in model.quantities:  # where the motion gets to: a coordinate's value, a height
        for name, value in quantity.at:
            checks.append((("quantities", quantity.name, "at", name), value, dims.get(coordinates[name])))
        if quantity.level is not None:
            checks.append((("quantities", quantity.name, "level"), quantity.level, LENGTH))
        if quantity.slope is not None:
            checks.append((("quantities", quantity.name, "slope"), quantity.slope, DIMENSIONLESS))
    return checks


def _velocity_dim(model: Model, symbol: sympy.Symbol, dims: Dims) -> Dimension | None:
    for c in model.coordinates:
        if c.velocity == symbol and c.symbol in dims:
            return dims[c.symbol] / TIME
    return None


def _faults(checks: list[Check], dims: Dims) -> list[SpecError]:
    faults: list[SpecError] = []
    for path, expr, expected in checks:
        fault = _fault(expr, expected, dims)
        if fault is not None:
            faults.append(SpecError(fault, path))
    return faults


def _fault(expr: sympy.Expr, expected: Expected, dims: Dims) -> str | None:
    if not expr.free_symbols:
        return None  # a bare number (an anchor at 0) is read in SI units
    try:
        found = expression_dimension(expr, dims)
    except UnknownDimension:
        return None  # a symbol without a declared dimension: nothing to compare against
    except DimensionMismatch as error:
        return f"dimensionally inconsistent: {typed_text(expr)} {error.message}"
    if expected is not None and found != expected:
        return f"{typed_text(expr)} is {describe(found)}; expected {describe(expected)}"
    return None
