"""A mechanical model as data: coordinates, bodies, loads, constraints, events and asked quantities.

The loads (gravity, pair potentials, the `forces:` entries, kinetic friction) are one list, `loads`,
which every method consumes through the protocol of `physics.engine.loads`; each constraint says how
it acts (`Action`: bilateral, unilateral, impulsive).

Two descriptions of the same system live side by side on purpose: each body's position (and angle)
in terms of the generalized coordinates, used by the Lagrangian methods, and the constraints written
as gap functions of the bodies' own Cartesian coordinates (`x_<body>`, `y_<body>`, `phi_<body>`), used
by Newton's method. A gap is kept at zero; its force on the bodies is lambda * grad(gap), so writing the
gap as "how far from violating the constraint" makes lambda the magnitude (normal force, tension).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from enum import StrEnum
from typing import Any

import sympy

from physics.dimensions import Dimension
from physics.engine.loads import ForceEntryLoad, Load, Traits
from physics.engine.loads.applied import AppliedForce, ForceKind
from physics.engine.loads.friction import Friction
from physics.engine.loads.gravity import Gravity
from physics.engine.loads.pair import PairPotential

__all__ = ["AppliedForce", "ForceKind", "Friction", "PairPotential"]  # re-exported: they are loads

AXES = ("x", "y")
ZERO = sympy.Integer(0)


@dataclass(frozen=True)
class Coordinate:
    """A generalized coordinate with its velocity and acceleration symbols."""

    name: str
    symbol: sympy.Symbol
    velocity: sympy.Symbol
    acceleration: sympy.Symbol


@dataclass(frozen=True)
class Body:
    """A particle (inertia 0, no angle) or a rigid body in the plane, placed by the coordinates."""

    name: str
    mass: sympy.Expr
    inertia: sympy.Expr
    position: tuple[tuple[str, sympy.Expr], ...]  # (axis, expression in the coordinates)
    angle: sympy.Expr | None = None

    def cartesian_names(self) -> tuple[str, ...]:
        names = tuple(f"{axis}_{self.name}" for axis, _ in self.position)
        return names + ((f"phi_{self.name}",) if self.angle is not None else ())


class Action(StrEnum):
    """How a constraint's force acts: the methods solve every held constraint as bilateral; a unilateral
    one's force must then keep its sign (contacts.py), an impulsive one acts for an instant (impact.py)."""

    BILATERAL = "bilateral"  # either sign: an axle, a rolling grip, a bead on a wire
    UNILATERAL = "unilateral"  # one sign: a surface only pushes, a string only pulls
    IMPULSIVE = "impulsive"  # an impulse at one instant: two bodies meeting


class ConstraintKind(StrEnum):
    SURFACE = "surface"
    STRING = "string"
    ROLLING = "rolling"
    OTHER = "other"


@dataclass(frozen=True)
class Constraint:
    name: str
    gap: sympy.Expr  # in the bodies' Cartesian symbols
    kind: ConstraintKind

    @property
    def action(self) -> Action:
        unilateral = self.kind in (ConstraintKind.SURFACE, ConstraintKind.STRING)
        return Action.UNILATERAL if unilateral else Action.BILATERAL


@dataclass(frozen=True)
class Frame:
    """The reference frame the fictitious-forces method works in: translating with a body (each other
    body feels -m A, A the body's acceleration), or turning at a constant `rate` about the vertical line
    x = `axis`, its `bodies` turning with it (centrifugal m rate^2 (x - axis) on each)."""

    body: str | None = None
    rate: sympy.Expr | None = None
    axis: sympy.Expr = ZERO
    bodies: tuple[str, ...] = ()


@dataclass(frozen=True)
class Collision:
    """A projectile particle hits `target` (at rest at `at`) along `direction` and sticks; the
    merged body then moves until the coordinates reach `reaches` with zero velocity (or, with the
    projectile's `speed` given, the velocities just after are asked). `point`: where on a
    rigid target it sticks, in the coordinates as a body's position is written (a rod's end); without
    it, the target's own position (its centre of mass)."""

    projectile: str
    projectile_mass: sympy.Expr
    direction: tuple[tuple[str, sympy.Expr], ...]
    target: str
    at: tuple[tuple[str, sympy.Expr], ...]
    reaches: tuple[tuple[str, sympy.Expr], ...]
    point: tuple[tuple[str, sympy.Expr], ...] = ()
    speed: sympy.Expr | None = None  # the projectile's speed, when given (then the motion after is asked)


@dataclass(frozen=True)
class Impact:
    """Bodies meet at the model's state, moving with its velocities: an impulse along `normal` (pointing
    from the first body to the second, or to the `fixed` partner) with Newton's coefficient of
    `restitution` (1 elastic, 0 perfectly inelastic), or, for an explosion, one that `release`s that
    much kinetic energy as they part. Exactly one of restitution and release is given. `bodies` are the
    moving ones: two, or one against a `fixed` partner (a floor, a wall) that does not move."""

    bodies: tuple[str, ...]
    normal: tuple[tuple[str, sympy.Expr], ...]
    restitution: sympy.Expr | None
    release: sympy.Expr | None
    fixed: str | None = None
    # where a rigid body is struck (body -> its point's position in the coordinates): the impulse's
    # moment turns it; without, the contact is at its centre of mass
    points: tuple[tuple[str, tuple[tuple[str, sympy.Expr], ...]], ...] = ()
    action = Action.IMPULSIVE


class QuantityKind(StrEnum):
    ACCELERATION = "acceleration"  # second derivative of a coordinate
    FORCE = "force"  # the multiplier of a constraint
    EQUILIBRIUM = "equilibrium"  # stable equilibrium value of a coordinate
    POTENTIAL_FORCE = "potential_force"  # generalized force of the potentials on a coordinate
    STIFFNESS = "stiffness"  # second derivative of the potential at the equilibrium
    ANGULAR_FREQUENCY = "angular_frequency"  # of small oscillations about the equilibrium
    PERIOD = "period"
    SOLVE = "solve"  # the parameter value that makes another quantity vanish
    PROJECTILE_SPEED = "projectile_speed"
    ENERGY_FRACTION_LOST = "energy_fraction_lost"
    VELOCITY_AFTER = "velocity_after"  # a coordinate's velocity just after a collision of given speed
    NORMAL_FREQUENCY = (
        "normal_frequency"  # the n-th lowest (1, 2, ...) non-zero normal-mode angular frequency
    )
    TERMINAL_VELOCITY = "terminal_velocity"
    EXPRESSION = "expression"  # a formula in the parameters and earlier quantities  # the velocity of a coordinate at which it stops accelerating
    FINAL_VELOCITY = "final_velocity"  # a body's velocity after an impact, along its one axis
    FINAL_SPEED = "final_speed"  # a body's speed after an impact
    KINETIC_ENERGY_LOST = "kinetic_energy_lost"  # by the bodies of an impact (negative: released)
    SPEED = "speed"  # a body's speed when the coordinates reach `at`, moving from the state
    VELOCITY = "velocity"  # a coordinate's velocity when the coordinates reach `at`
    TIME_OF_FLIGHT = "time_of_flight"  # of a body launched at the state, until it lands at `level`
    RANGE = "range"  # the body's horizontal displacement when it lands at `level`
    MAX_HEIGHT = "max_height"  # the body's highest point above where it was launched
    SLIP_TIME = "slip_time"  # until a contact with kinetic friction stops slipping (a ball starts rolling)
    SLIP_DISTANCE = "slip_distance"  # how far a coordinate moves until then
    SLIP_END_VELOCITY = "slip_end_velocity"  # a coordinate's velocity when the slipping stops
    SLIPPING = "slipping"  # the parameter value at which a holding contact's |f| reaches mu_s N
    DAMPED_FREQUENCY = "damped_frequency"  # of an underdamped oscillation about the equilibrium
    DECAY_TIME = "decay_time"  # the amplitude's e-folding time of that oscillation
    TURNING_POINT = "turning_point"  # where the coordinate first stops, moving from the state
    UNDAMPED_FREQUENCY = "undamped_frequency"  # of that oscillation with the damping left out: sqrt(k/m)
    MODE_SHAPE = "mode_shape"  # amplitude ratio of two coordinates in the n-th normal mode
    # steady circular motion: the angle coordinate turns uniformly, the others stay at the state (orbits.py)
    CIRCULAR_SPEED = "circular_speed"
    REVOLUTION_PERIOD = "revolution_period"
    CIRCULAR_ENERGY = "circular_energy"
    MECHANICAL_ENERGY = "mechanical_energy"  # T + V at the model's state
    # with the cyclic coordinates' momenta held at their state values (the effective potential)
    CIRCULAR_RADIUS = "circular_radius"
    EPICYCLIC_FREQUENCY = "epicyclic_frequency"
    # the value of a parameter at which another quantity is largest or smallest (extremum.py)
    MAXIMIZE = "maximize"
    MINIMIZE = "minimize"


REACH_KINDS = frozenset({QuantityKind.SPEED, QuantityKind.VELOCITY})
TRAJECTORY_KINDS = frozenset({QuantityKind.TIME_OF_FLIGHT, QuantityKind.RANGE, QuantityKind.MAX_HEIGHT})
IMPACT_KINDS = frozenset(
    {QuantityKind.FINAL_VELOCITY, QuantityKind.FINAL_SPEED, QuantityKind.KINETIC_ENERGY_LOST}
)
SLIP_KINDS = frozenset({QuantityKind.SLIP_TIME, QuantityKind.SLIP_DISTANCE, QuantityKind.SLIP_END_VELOCITY})


STEADY_KINDS = frozenset(
    {QuantityKind.CIRCULAR_SPEED, QuantityKind.REVOLUTION_PERIOD, QuantityKind.CIRCULAR_ENERGY}
)
EXTREMUM_KINDS = frozenset({QuantityKind.MAXIMIZE, QuantityKind.MINIMIZE})
EFFECTIVE_KINDS = frozenset({QuantityKind.CIRCULAR_RADIUS, QuantityKind.EPICYCLIC_FREQUENCY})
ORBIT_KINDS = STEADY_KINDS | EFFECTIVE_KINDS | {QuantityKind.MECHANICAL_ENERGY}
# Times, lengths, speeds and frequencies: where the answer is positive, a negative value is no slip
# a student makes (a force, an acceleration or an energy of the wrong sign is one).
MAGNITUDE_KINDS = frozenset(
    {
        QuantityKind.ANGULAR_FREQUENCY,
        QuantityKind.PERIOD,
        QuantityKind.NORMAL_FREQUENCY,
        QuantityKind.DAMPED_FREQUENCY,
        QuantityKind.UNDAMPED_FREQUENCY,
        QuantityKind.DECAY_TIME,
        QuantityKind.PROJECTILE_SPEED,
        QuantityKind.SPEED,
        QuantityKind.FINAL_SPEED,
        QuantityKind.TIME_OF_FLIGHT,
        QuantityKind.RANGE,
        QuantityKind.MAX_HEIGHT,
        QuantityKind.SLIP_TIME,
        QuantityKind.SLIP_DISTANCE,
        QuantityKind.CIRCULAR_SPEED,
        QuantityKind.REVOLUTION_PERIOD,
        QuantityKind.CIRCULAR_RADIUS,
        QuantityKind.EPICYCLIC_FREQUENCY,
    }
)


@dataclass(frozen=True)
class Quantity:
    name: str
    kind: QuantityKind
    target: str = ""  # coordinate or constraint name
    parameter: sympy.Symbol | None = None  # for SOLVE, MAXIMIZE, MINIMIZE
    inner: Quantity | None = None  # for SOLVE: the quantity set to zero; MAXIMIZE, MINIMIZE: made extreme
    # for EXPRESSION: the formula, and the stand-in symbol of each earlier quantity it uses
    expression: sympy.Expr | None = None
    uses: tuple[tuple[sympy.Symbol, str], ...] = ()
    # where the coordinates are when the quantity is taken (speed, velocity; force and acceleration
    # there too), reached by the motion from the model's state: ((coordinate, value),)
    at: tuple[tuple[str, sympy.Expr], ...] = ()
    level: sympy.Expr | None = None  # TIME_OF_FLIGHT, RANGE: the landing height (y); None: the launch's
    # TIME_OF_FLIGHT, RANGE: lands instead on the line through the launch point rising at this angle (an
    # incline's surface), the range taken along it
    slope: sympy.Expr | None = None
    # for SLIPPING: the holding contact's friction and normal constraints, and mu_s
    contact: tuple[str, str] = ("", "")
    coefficient: sympy.Expr | None = None
    ratio: tuple[str, ...] = ()  # for MODE_SHAPE: (numerator, denominator) coordinates; target = mode
    after: str = ""  # "impact": taken in the motion that starts just after the model's impact
    bounces: sympy.Expr | None = (
        None  # with `after`: after this many bounces off the fixed partner (bounces.py)
    )
    total: bool = False  # KINETIC_ENERGY_LOST with `bounces`: over the first n together, not the n-th alone
    small: bool = (
        False  # PERIOD, ANGULAR_FREQUENCY: `amplitude: small`, whatever the state's swing (amplitude.py)
    )


@dataclass(frozen=True)
class StatedLimit:
    """A limiting case the author states: with `where` taken to its values, each quantity in `expect`
    must tend to the given expression (e.g. the wedge held fixed: M -> oo, its acceleration -> 0)."""

    where: tuple[tuple[sympy.Symbol, sympy.Expr], ...]
    expect: tuple[tuple[str, sympy.Expr], ...]
    description: str


@dataclass(frozen=True)
class AuthoredElement:
    """An element as the author wrote it under `elements:` (its fields as read), with the names of what
    it generated: figures draw the picture the author described from these, not from the low-level model."""

    kind: str
    name: str
    fields: Mapping[str, Any] = field(compare=False)  # YAML data, not hashable
    bodies: tuple[str, ...] = ()
    constraints: tuple[str, ...] = ()
    potentials: tuple[str, ...] = ()  # PairPotential names
    coordinates: tuple[str, ...] = ()


@dataclass(frozen=True)
class Model:
    coordinates: tuple[Coordinate, ...]
    bodies: tuple[Body, ...]
    constraints: tuple[Constraint, ...]
    frictions: tuple[Friction, ...]
    potentials: tuple[PairPotential, ...]
    gravity: sympy.Expr | None
    collision: Collision | None
    state: tuple[tuple[sympy.Symbol, sympy.Expr], ...]  # coordinate/velocity symbol -> value
    ranges: tuple[tuple[sympy.Symbol, sympy.Expr, sympy.Expr], ...]
    coordinate_ranges: tuple[tuple[str, sympy.Expr, sympy.Expr], ...]  # a coordinate's declared range
    positive: tuple[sympy.Expr, ...]  # expressions the domain keeps positive
    quantities: tuple[Quantity, ...]
    parameters: tuple[sympy.Symbol, ...]  # the problem's symbols, in table order
    cartesian: tuple[tuple[str, sympy.Symbol], ...]  # Cartesian symbol names of every body
    limits: tuple[StatedLimit, ...] = ()
    # the `forces:` section's entries, of any kind (loads/entries.py); `forces` are its given forces and drag
    force_entries: tuple[ForceEntryLoad, ...] = ()
    dimensions_checked: bool = False
    impact: Impact | None = None  # every term was found dimensionally consistent when loaded
    frame: Frame | None = None  # declared (`frame:`) or implied by an element (a wedge, a rotating frame)
    time: sympy.Symbol | None = None  # the time `t`, when a given force depends on it
    # the author's names for worked solutions: (coordinate, constraint or body, symbol, words); notation.py
    notation: tuple[tuple[str, str | None, str | None], ...] = ()
    # the declared dimensions of the problem's symbols (when given): what kind of thing a quantity is
    dimensions: tuple[tuple[sympy.Symbol, Dimension], ...] = ()
    unused: tuple[str, ...] = ()
    # the symbol table's own ranges (`range:` of a symbol): which root a solve keeps (roots.py)
    symbol_ranges: tuple[
        tuple[sympy.Symbol, sympy.Expr, sympy.Expr], ...
    ] = ()  # quantities the author derives on purpose without a part asking for them
    # other configurations of the same system, each a whole model with its own quantities (scenarios.py)
    scenarios: tuple[tuple[str, Model], ...] = ()
    # strings gone slack, surfaces left: declared, they act in no method (released.py)
    released: tuple[Constraint, ...] = ()

    # the elements the author wrote, in the order they were expanded (empty for a low-level model)
    elements: tuple[AuthoredElement, ...] = ()

    def body(self, name: str) -> Body:
        return next(b for b in self.bodies if b.name == name)

    def coordinate(self, name: str) -> Coordinate:
        return next(c for c in self.coordinates if c.name == name)

    def constraint(self, name: str) -> Constraint:
        return next(c for c in self.constraints if c.name == name)

    def acting(self, action: Action) -> tuple[Constraint | Impact, ...]:
        """The constraints that act so, the impact among them: one list for every kind of constraint."""
        held: tuple[Constraint | Impact, ...] = self.constraints
        every = (*held, self.impact) if self.impact is not None else held
        return tuple(c for c in every if c.action is action)

    @property
    def moving_symbols(self) -> set[sympy.Symbol]:
        moving = {c.symbol for c in self.coordinates} | {c.velocity for c in self.coordinates}
        return moving | ({self.time} if self.time is not None else set())

    @property
    def loads(self) -> tuple[Load, ...]:
        """Every load on the bodies, whichever section gave it: what the methods consume (loads/)."""
        gravity = (Gravity(self.gravity),) if self.gravity is not None else ()
        return (*gravity, *self.potentials, *self.force_entries, *self.frictions)

    @property
    def forces(self) -> tuple[AppliedForce, ...]:
        """The given forces and drag of the `forces:` section (what its figures draw)."""
        return tuple(f for f in self.force_entries if isinstance(f, AppliedForce))

    def loads_where(self, which: Callable[[Traits], bool]) -> tuple[Load, ...]:
        """The loads whose traits `which` selects (e.g. those that work through a constraint force)."""
        return tuple(load for load in self.loads if which(load.traits(self)))

    @property
    def nonconservative_loads(self) -> tuple[Load, ...]:
        """Loads without a potential: friction, drag, forces in the coordinates, velocities or time."""
        return self.loads_where(lambda traits: not traits.conservative)

    @property
    def contact_loads(self) -> tuple[Load, ...]:
        """Loads whose size is a constraint's force (kinetic friction, mu N): they do work through it."""
        return self.loads_where(lambda traits: bool(traits.constraints))

    def quantity(self, name: str) -> Quantity:
        return next(q for q in self.quantities if q.name == name)

    def cartesian_symbol(self, name: str) -> sympy.Symbol:
        return dict(self.cartesian)[name]
