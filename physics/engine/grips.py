"""A rolling grip is friction at the contact point: it turns the body the way a force there does.

A `rolling` constraint's force acts on the body's centre along the gap's gradient (a_x, a_y) and on its
angle with the torque a_phi. Written by hand, the angle's sign is easy to get wrong (`angle: s/R` for a
ball rolling down towards +x, which turns clockwise): the positions and the gap then agree with each
other, every method and the simulation agree, and the answers are those of a body whose centre is
geared to its spin the wrong way round, its contact point sliding at twice the centre's speed while the
"grip" does no work. A force F at the contact point, which lies at the radius on the far side of the
centre from the surface's normal n (the gap's gradient, pointing away from the surface), has the torque
-r n x F about the centre, r > 0: so a_phi must have the sign of -(n x a). Checked for each body that a
rolling grip turns and that exactly one surface holds (which it then rolls on), at sampled domain points;
refused at the grip where the sign is wrong at every one.
"""

from __future__ import annotations

import math

import sympy

from physics.answer_text import typed_text
from physics.engine.mechanics import Mechanics
from physics.engine.model import Body, Constraint, ConstraintKind, Model
from physics.engine.proof import domain_points
from physics.engine.shape_inertia import SHAPES, geometric_symbols, shape_factor
from physics.errors import DerivationError

POINTS = 6
SEED = 37
# hoop, disk, solid sphere, shell: shapes whose length is the radius they roll on
ROUND = frozenset({sympy.Integer(1), sympy.Rational(1, 2), sympy.Rational(2, 5), sympy.Rational(2, 3)})


def check_rolling_grips(model: Model, mech: Mechanics) -> None:
    surfaces = [c for c in model.constraints if c.kind is ConstraintKind.SURFACE]
    symbols = {d.name: d.symbol for d in mech.dofs}
    for grip in (c for c in model.constraints if c.kind is ConstraintKind.ROLLING):
        for body in model.bodies:
            x, y, phi = (symbols.get(f"{axis}_{body.name}") for axis in ("x", "y", "phi"))
            if phi is None or x is None or y is None or not grip.gap.has(phi):
                continue
            under = [s for s in surfaces if s.gap.has(x) or s.gap.has(y)]
            if len(under) != 1:  # no surface, or several: which one it rolls on is not said
                continue
            signs = {_sign(mech, grip.gap, under[0].gap, (x, y, phi), p) for p in state_points(model, mech)}
            if signs == {-1}:
                raise DerivationError(
                    f"constraint {grip.name!r}: the grip turns {body.name} the wrong way for rolling on "
                    f"{under[0].name!r}: a friction force at the contact point cannot give the torque its gap "
                    f"gives, and {body.name}'s contact point would slide at twice its centre's speed. Flip the "
                    f"sign of the angle (phi_{body.name}) in the grip's gap and in {body.name}'s `angle` (a "
                    "body rolling towards +x on a floor beneath it turns clockwise)",
                    path=("constraints", grip.name),
                )
            _check_radius(model, mech, grip, under[0], body, (x, y, phi))


def _check_radius(
    model: Model,
    mech: Mechanics,
    grip: Constraint,
    surface: Constraint,
    body: Body,
    axes: tuple[sympy.Symbol, sympy.Symbol, sympy.Symbol],
) -> None:
    """A grip puts the contact point at a_phi / |n x a| from the centre (its torque over its push); a round
    body of a standard shape has that point at its radius. A ball in a bowl geared by R/r instead of
    (R - r)/r grips it at r (R - r)/R: its contact point slides, the grip doing no work."""
    factor = shape_factor(body.inertia, body.mass, geometric_symbols(model))
    if factor is None or factor not in ROUND:
        return
    radius = sympy.sqrt(body.inertia / (factor * body.mass))
    found = [_reach(mech, grip.gap, surface.gap, axes, p) for p in state_points(model, mech)]
    sizes = [
        (r, float(sympy.N(radius.subs(p)))) for r, p in zip(found, state_points(model, mech), strict=True)
    ]
    if not sizes or any(r is None or abs(r - size) <= 1e-6 * size for r, size in sizes):
        return
    raise DerivationError(
        f"constraint {grip.name!r}: the grip turns {body.name} as if its contact point with {surface.name!r} "
        f"were {sizes[0][0]:.4g} from its centre (at a sampled point), but its inertia is {SHAPES[factor]} of "
        f"radius {typed_text(radius)} ({sizes[0][1]:.4g}): rolling, the point that touches is at rest, and "
        "here it would slide. A rolling body turns through the arc its centre travels over its radius: in a "
        "bowl of radius R a ball of radius r turns (R - r)/r times the centre's angle, not R/r",
        path=("constraints", grip.name),
    )


def _reach(
    mech: Mechanics,
    grip: sympy.Expr,
    surface: sympy.Expr,
    axes: tuple[sympy.Symbol, sympy.Symbol, sympy.Symbol],
    point: dict[sympy.Symbol, sympy.Expr],
) -> float | None:
    """How far from the centre the grip acts, a_phi over the lever of its push about the normal."""
    place = {d.symbol: d.mapping for d in mech.dofs}
    x, y, phi = axes
    try:
        ax, ay, aphi, nx, ny = (
            complex(sympy.N(sympy.diff(e, v).subs(place).subs(point), 15))
            for e, v in ((grip, x), (grip, y), (grip, phi), (surface, x), (surface, y))
        )
    except (TypeError, ValueError):
        return None
    if any(abs(v.imag) > 1e-12 for v in (ax, ay, aphi, nx, ny)):
        return None
    norm = math.hypot(nx.real, ny.real)
    lever = abs(nx.real * ay.real - ny.real * ax.real) / norm if norm else 0.0
    return abs(aphi.real) / lever if lever > 1e-12 else None


def state_points(model: Model, mech: Mechanics) -> list[dict[sympy.Symbol, sympy.Expr]]:
    """Domain points with the coordinates at the state (else at generic values)."""
    state = dict(model.state)
    generic = {q: state.get(q, sympy.Rational(3, 10) + sympy.Rational(i, 7)) for i, q in enumerate(mech.q)}
    if model.time is not None:
        generic.setdefault(model.time, state.get(model.time, sympy.Rational(2, 7)))
    return [{**generic, **point} for point in domain_points(model, POINTS, seed=SEED)]


def _sign(
    mech: Mechanics,
    grip: sympy.Expr,
    surface: sympy.Expr,
    axes: tuple[sympy.Symbol, sympy.Symbol, sympy.Symbol],
    point: dict[sympy.Symbol, sympy.Expr],
) -> int:
    """+1 where the grip's torque is a contact force's, -1 where it is the opposite, 0 where undecided."""
    place = {d.symbol: d.mapping for d in mech.dofs}
    x, y, phi = axes

    def at(expr: sympy.Expr) -> float:
        value = complex(sympy.N(expr.subs(place).subs(point), 15))
        return value.real if abs(value.imag) < 1e-12 else float("nan")

    ax, ay, aphi = (at(sympy.diff(grip, s)) for s in (x, y, phi))
    nx, ny = (at(sympy.diff(surface, s)) for s in (x, y))
    lever = -(nx * ay - ny * ax)  # the torque per unit force of a contact point at unit distance
    scale = max(abs(ax), abs(ay), 1e-300) * max(abs(nx), abs(ny), 1e-300)
    if not (abs(lever) > 1e-9 * scale and abs(aphi) > 0):  # nan, or a grip without a push on the centre
        return 0
    return 1 if lever * aphi > 0 else -1
