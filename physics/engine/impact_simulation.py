"""An impact measured on a contact model: a stiff spring and dashpot along the normal, integrated with RK4.

The two bodies move freely except for the contact force P = k delta + c delta' (delta the overlap along
the normal) while they overlap. A linear spring-dashpot that lets go when the overlap returns to zero
rebounds with exactly e = exp(-zeta pi / sqrt(1 - zeta^2)), so the damping ratio is chosen from the
model's restitution; an explosion is a spring compressed to hold the energy released, let go. Nothing
here reads the derived formulas: the velocities after come from the integrated forces alone.
"""

from __future__ import annotations

import math

import sympy

from physics.answer_text import typed_text
from physics.engine.impact import axes, unit_normal, velocities_before
from physics.engine.model import Model, Quantity, QuantityKind
from physics.errors import DerivationError

STEP = 1e-3  # of the contact's undamped period 2 pi (stiffness k = reduced mass: omega0 = 1)
LONGEST = 40.0  # a critically damped contact (e = 0) never lets go: by then the bodies move together


def _value(expr: sympy.Expr, point: dict[sympy.Symbol, float]) -> float:
    value = sympy.N(expr.subs(point), 20)
    if not value.is_real:
        raise DerivationError(f"{typed_text(expr)} is not real at {typed_text(point)}")
    return float(value)


Run = tuple[list[list[float]], list[list[float]], float]


def _integrate(model: Model, point: tuple[tuple[sympy.Symbol, float], ...]) -> Run:
    """(velocities before, velocities after: [body][axis]; the speed scale of the motion)."""
    hit = model.impact
    assert hit is not None
    at = dict(point)
    names = axes(model)
    d = len(names)
    normal = [_value(v, at) for v in unit_normal(model).values()]
    before_exprs = velocities_before(model)
    before = [[_value(before_exprs[b][a], at) for a in names] for b in hit.bodies]
    ma, mb = (_value(model.body(b).mass, at) for b in hit.bodies)
    reduced = ma * mb / (ma + mb)
    approach = sum((before[0][i] - before[1][i]) * normal[i] for i in range(d))
    overlap = 0.0
    damping = 0.0
    if hit.release is not None:
        overlap = math.sqrt(2 * _value(hit.release, at) / reduced)  # k = reduced mass
    else:
        assert hit.restitution is not None
        if approach <= 0:
            raise DerivationError(
                "the bodies do not approach along the normal at "
                + ", ".join(f"{s}={v:.4g}" for s, v in point)
                + ": declare the approach positive (domain.positive)",
                path=("impact",),
            )
        e = _value(hit.restitution, at)
        if not 0 <= e <= 1:
            raise DerivationError(
                f"a coefficient of restitution lies in [0, 1], not {e:.4g}", path=("impact",)
            )
        zeta = 1.0 if e == 0 else -math.log(e) / math.hypot(math.pi, math.log(e))
        damping = 2 * zeta * reduced

    def derivative(y: list[float]) -> list[float]:
        # y: overlap, then velocities of the first and second body
        va, vb = y[1 : 1 + d], y[1 + d :]
        rate = sum((va[i] - vb[i]) * normal[i] for i in range(d))
        push = reduced * y[0] + damping * rate  # tensile near the end: that is the model e(zeta) describes
        return [rate, *(-push * n / ma for n in normal), *(push * n / mb for n in normal)]

    y = [overlap, *before[0], *before[1]]
    previous, t = y, 0.0
    while t < LONGEST:
        k1 = derivative(y)
        k2 = derivative([a + STEP / 2 * b for a, b in zip(y, k1, strict=True)])
        k3 = derivative([a + STEP / 2 * b for a, b in zip(y, k2, strict=True)])
        k4 = derivative([a + STEP * b for a, b in zip(y, k3, strict=True)])
        previous, y = (
            y,
            [
                a + STEP / 6 * (b + 2 * c + 2 * e_ + f)
                for a, b, c, e_, f in zip(y, k1, k2, k3, k4, strict=True)
            ],
        )
        t += STEP
        if y[0] <= 0 and t > STEP:
            # the contact lets go between the two states: interpolate to the instant the overlap is zero
            share = previous[0] / (previous[0] - y[0])
            y = [p + share * (c - p) for p, c in zip(previous, y, strict=True)]
            break
    after = [y[1 : 1 + d], y[1 + d :]]
    scale = max(math.hypot(*v) for v in before + after)
    return before, after, max(scale, 1e-300)


class ImpactMeasure:
    """Measures an impact's quantities; integrates each parameter point once for all of them."""

    def __init__(self, model: Model) -> None:
        self.model = model
        self.runs: dict[tuple[tuple[sympy.Symbol, float], ...], Run] = {}

    def __call__(
        self, quantity: Quantity, point: dict[sympy.Symbol, float], expected: float
    ) -> tuple[str, float, float]:
        key = tuple(sorted(point.items(), key=lambda kv: kv[0].name))
        if key not in self.runs:
            self.runs[key] = _integrate(self.model, key)
        return _measure(self.model, self.runs[key], quantity, point, expected)


def _measure(
    model: Model, run: Run, quantity: Quantity, point: dict[sympy.Symbol, float], expected: float
) -> tuple[str, float, float]:
    hit = model.impact
    assert hit is not None
    before, after, scale = run
    what = (
        "an integrated spring-dashpot contact"
        if hit.restitution is not None
        else "an integrated spring let go"
    )
    if quantity.kind is QuantityKind.KINETIC_ENERGY_LOST:
        masses = [_value(model.body(b).mass, point) for b in hit.bodies]
        energy = [
            sum(m * sum(c * c for c in v) / 2 for m, v in zip(masses, vs, strict=True))
            for vs in (before, after)
        ]
        lost = energy[0] - energy[1]
        return f"kinetic energy lost in {what}", lost, abs(lost - expected) / max(energy)
    velocity = after[hit.bodies.index(quantity.target)]
    if quantity.kind is QuantityKind.FINAL_SPEED:
        measured = math.hypot(*velocity)
        return f"speed after {what}", measured, abs(measured - expected) / scale
    (component,) = velocity
    return f"velocity after {what}", component, abs(component - expected) / scale
