"""An impact measured on a contact model: a stiff spring and dashpot along the normal, integrated with RK4
in the model's coordinates, so every constraint holds throughout (a block held on an incline moves
only along it, however hard it is hit, and the incline takes the rest of the blow).

The coordinates' velocities change under the contact force P = k delta + c delta' (delta the overlap
along the normal) while the bodies overlap: M q'' = P a, a the normal separation's rate per unit
velocity of each coordinate, M the mass matrix, both frozen at the state (the contact is over before
the configuration changes). With k the effective mass 1 / (a . M^-1 a), a linear spring-dashpot that
lets go when the overlap returns to zero rebounds with exactly e = exp(-zeta pi / sqrt(1 - zeta^2)), so
the damping ratio is chosen from the model's restitution; an explosion is a spring compressed to hold
the energy released, let go. Nothing here reads the derived formulas: the velocities after come from
the integrated forces alone.
"""

from __future__ import annotations

import math
from functools import cached_property

import sympy

from physics.answer_text import typed_text
from physics.engine.impact import Contact, contact
from physics.engine.model import Model, Quantity, QuantityKind
from physics.errors import DerivationError

STEP = 1e-3  # of the contact's undamped period 2 pi (stiffness k = effective mass: omega0 = 1)
LONGEST = 40.0  # a critically damped contact (e = 0) never lets go: by then the bodies move together


def _value(expr: sympy.Expr, point: dict[sympy.Symbol, float]) -> float:
    value = sympy.N(expr.subs(point), 20)
    if not value.is_real:
        raise DerivationError(f"{typed_text(expr)} is not real at {typed_text(point)}")
    return float(value)


# (each body's Cartesian velocities before and after: body -> [(axis, value)]; the speed scale of the
# motion; the kinetic energy before and after; the coordinates' velocities after)
Run = tuple[
    dict[str, list[tuple[str, float]]], dict[str, list[tuple[str, float]]], float, float, float, list[float]
]


def _by_body(found: Contact, cartesian: list[float]) -> dict[str, list[tuple[str, float]]]:
    result: dict[str, list[tuple[str, float]]] = {}
    for d, value in zip(found.mech.dofs, cartesian, strict=True):
        result.setdefault(d.body, []).append((d.name.split("_", 1)[0], value))
    return result


def _integrate(model: Model, found: Contact, point: tuple[tuple[sympy.Symbol, float], ...]) -> Run:
    from physics.engine.simulation import solve_numeric  # here: simulation imports this module

    hit = model.impact
    assert hit is not None
    at = dict(point)
    state = dict(model.state)
    n = len(model.coordinates)
    mass = [[_value(found.mech.mass_matrix[i, j].subs(state), at) for j in range(n)] for i in range(n)]
    a = [_value(v, at) for v in found.generalized]
    before = [_value(state.get(c.velocity, sympy.Integer(0)), at) for c in model.coordinates]
    jacobian = [[_value(found.jacobian[i, j], at) for j in range(n)] for i in range(len(found.mech.dofs))]
    response = solve_numeric(mass, a)  # M^-1 a: how the coordinates' accelerations follow P
    effective = 1 / sum(x * y for x, y in zip(a, response, strict=True))
    approach = -sum(x * y for x, y in zip(a, before, strict=True))
    overlap = 0.0
    damping = 0.0
    if hit.release is not None:
        overlap = math.sqrt(2 * _value(hit.release, at) / effective)  # k = effective mass
    else:
        assert hit.restitution is not None
        if approach <= 0:
            second = hit.fixed if hit.fixed is not None else hit.bodies[-1]
            apart = (  # moving apart, not merely side by side: most often the normal is reversed
                f", they move apart along it: the normal points from the first body ({hit.bodies[0]}) to the "
                f"second ({second}); check its direction, or"
                if approach < 0
                else ":"
            )
            raise DerivationError(
                "the bodies do not approach along the normal at "
                + ", ".join(f"{s}={v:.4g}" for s, v in point)
                + f"{apart} declare the approach positive (domain.positive)",
                path=("impact",),
            )
        e = _value(hit.restitution, at)
        if not 0 <= e <= 1:
            raise DerivationError(
                f"a coefficient of restitution lies in [0, 1], not {e:.4g}", path=("impact",)
            )
        zeta = 1.0 if e == 0 else -math.log(e) / math.hypot(math.pi, math.log(e))
        damping = 2 * zeta * effective

    def derivative(y: list[float]) -> list[float]:
        # y: overlap, then the coordinates' velocities
        rate = -sum(x * v for x, v in zip(a, y[1:], strict=True))
        push = effective * y[0] + damping * rate  # tensile near the end: that is the model e(zeta) describes
        return [rate, *(push * r for r in response)]

    y = [overlap, *before]
    previous, t = y, 0.0
    while t < LONGEST:
        k1 = derivative(y)
        k2 = derivative([a_ + STEP / 2 * b for a_, b in zip(y, k1, strict=True)])
        k3 = derivative([a_ + STEP / 2 * b for a_, b in zip(y, k2, strict=True)])
        k4 = derivative([a_ + STEP * b for a_, b in zip(y, k3, strict=True)])
        previous, y = (
            y,
            [
                a_ + STEP / 6 * (b + 2 * c + 2 * e_ + f)
                for a_, b, c, e_, f in zip(y, k1, k2, k3, k4, strict=True)
            ],
        )
        t += STEP
        if y[0] <= 0 and t > STEP:
            # the contact lets go between the two states: interpolate to the instant the overlap is zero
            share = previous[0] / (previous[0] - y[0])
            y = [p + share * (c - p) for p, c in zip(previous, y, strict=True)]
            break
    rates = y[1:]

    def cartesian(velocities: list[float]) -> list[float]:
        return [sum(j * v for j, v in zip(row, velocities, strict=True)) for row in jacobian]

    def kinetic(velocities: list[float]) -> float:
        return sum(velocities[i] * mass[i][j] * velocities[j] for i in range(n) for j in range(n)) / 2

    first, last = cartesian(before), cartesian(rates)
    scale = max([abs(v) for v in first + last] + [1e-300])
    return _by_body(found, first), _by_body(found, last), scale, kinetic(before), kinetic(rates), rates


class ImpactMeasure:
    """Measures an impact's quantities; integrates each parameter point once for all of them."""

    def __init__(self, model: Model) -> None:
        self.model = model
        self.runs: dict[tuple[tuple[sympy.Symbol, float], ...], Run] = {}

    @cached_property
    def contact(self) -> Contact:
        return contact(self.model)

    def __call__(
        self, quantity: Quantity, point: dict[sympy.Symbol, float], expected: float
    ) -> tuple[str, float, float]:
        return _measure(self.model, self._run(point), quantity, expected)

    def rates(self, point: dict[sympy.Symbol, float]) -> list[float]:
        """The coordinates' velocities just after the integrated contact."""
        return self._run(point)[5]

    def _run(self, point: dict[sympy.Symbol, float]) -> Run:
        key = tuple(sorted(point.items(), key=lambda kv: kv[0].name))
        if key not in self.runs:
            self.runs[key] = _integrate(self.model, self.contact, key)
        return self.runs[key]


def _measure(model: Model, run: Run, quantity: Quantity, expected: float) -> tuple[str, float, float]:
    hit = model.impact
    assert hit is not None
    _, after, scale, before_energy, after_energy, _ = run
    what = (
        "an integrated spring-dashpot contact, the constraints holding"
        if hit.restitution is not None
        else "an integrated spring let go"
    )
    if quantity.kind is QuantityKind.KINETIC_ENERGY_LOST:
        lost = before_energy - after_energy
        return f"kinetic energy lost in {what}", lost, abs(lost - expected) / max(before_energy, after_energy)
    velocity = [v for axis, v in after[quantity.target] if axis != "phi"]
    if quantity.kind is QuantityKind.FINAL_SPEED:
        measured = math.hypot(*velocity)
        return f"speed after {what}", measured, abs(measured - expected) / scale
    (component,) = velocity
    return f"velocity after {what}", component, abs(component - expected) / scale
