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

import sympy

from physics.engine.mechanics import Mechanics
from physics.engine.model import ConstraintKind, Model
from physics.engine.proof import domain_points
from physics.errors import DerivationError

POINTS = 6
SEED = 37


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
