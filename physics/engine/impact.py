"""Two bodies meeting in an impact (1-D or 2-D, both moving) or parting in an explosion, worked two ways.

Conservation: momentum is conserved on every axis and the contact is smooth (the first body keeps its
velocity across the normal); the normal relative velocity after is Newton's restitution law, or, when
the collision is elastic or an explosion, comes from the kinetic energy balance instead. Newton:
each body's impulse-momentum law with an unknown normal impulse J; J is Poisson's compression impulse
(the one that stops the normal approach) times 1 + e, or, for an explosion, the impulse whose work
(J times the mean normal velocity before and after) is the energy released.
"""

from __future__ import annotations

from collections.abc import Callable

import sympy

from physics.answer_text import typed_text
from physics.engine import tidy
from physics.engine.model import Model, Quantity, QuantityKind
from physics.engine.proof import domain_points
from physics.errors import DerivationError

Step = Callable[[str, str], None]
Velocities = dict[str, dict[str, sympy.Expr]]  # body -> axis -> velocity component


def axes(model: Model) -> tuple[str, ...]:
    hit = model.impact
    assert hit is not None
    used = {axis for name in hit.bodies for axis, _ in model.body(name).position}
    return tuple(a for a in ("x", "y") if a in used)


def unit_normal(model: Model) -> dict[str, sympy.Expr]:
    hit = model.impact
    assert hit is not None
    given = dict(hit.normal)
    norm = sympy.sqrt(sympy.Add(*(given.get(a, 0) ** 2 for a in axes(model))))
    return {a: tidy.simplify(given.get(a, sympy.Integer(0)) / norm) for a in axes(model)}


def velocities_before(model: Model) -> Velocities:
    """Each body's Cartesian velocity at the model's state (positions differentiated in time)."""
    hit = model.impact
    assert hit is not None
    state = dict(model.state)
    result: Velocities = {}
    for name in hit.bodies:
        position = dict(model.body(name).position)
        result[name] = {
            a: tidy.simplify(
                sympy.Add(
                    *(sympy.diff(position.get(a, 0), c.symbol) * c.velocity for c in model.coordinates)
                ).subs(state)
            )
            for a in axes(model)
        }
    return result


def _masses(model: Model) -> tuple[sympy.Expr, sympy.Expr]:
    hit = model.impact
    assert hit is not None
    return model.body(hit.bodies[0]).mass, model.body(hit.bodies[1]).mass


def _dot(u: dict[str, sympy.Expr], n: dict[str, sympy.Expr]) -> sympy.Expr:
    return sympy.Add(*(u[a] * n[a] for a in n))


def kinetic(model: Model, velocities: Velocities) -> sympy.Expr:
    masses = dict(zip(velocities, _masses(model), strict=True))
    return sympy.Add(*(masses[b] * _dot(v, v) / 2 for b, v in velocities.items()))


def _parting_root(model: Model, roots: list[sympy.Expr], unchanged: sympy.Expr, what: str) -> sympy.Expr:
    """The root of an energy balance with which the bodies part: not the one that leaves the motion as it
    was (`unchanged`, the bodies passing through each other), real, and positive at a domain point."""
    real = [r for r in roots if r.is_real is not False and tidy.simplify(r - unchanged) != 0]
    if len(real) > 1:
        point = domain_points(model, 1, seed=11)[0]
        real = [r for r in real if r.is_positive or (r.is_positive is None and float(r.subs(point)) > 0)]
    if len(real) != 1:
        raise DerivationError(f"expected one {what} with which the bodies part, found {typed_text(roots)}")
    return real[0]


Worked = tuple[tuple[tuple[str, str], ...], Velocities, Velocities]  # (steps, before, after)


def answer(worked: Worked, model: Model, quantity: Quantity, step: Step) -> sympy.Expr:
    """One quantity from a method's worked impact (its steps written once per method)."""
    steps, before, after = worked
    for title, latex in steps:
        step(title, latex)
    return _quantity(model, quantity, before, after, step)


def by_conservation(model: Model) -> Worked:
    steps: list[tuple[str, str]] = []
    step = _recorder(steps)
    hit = model.impact
    assert hit is not None
    first, second = hit.bodies
    n = unit_normal(model)
    before = velocities_before(model)
    ma, mb = _masses(model)
    after = {b: {a: sympy.Symbol(f"v_{b}_{a}", real=True) for a in n} for b in hit.bodies}
    parting = sympy.Symbol("w", real=True)  # normal velocity of the second body relative to the first
    equations = [
        ma * after[first][a] + mb * after[second][a] - ma * before[first][a] - mb * before[second][a]
        for a in n
    ]
    if len(n) == 2:  # smooth contact: the first body's velocity across the normal does not change
        equations.append(
            (after[first]["x"] - before[first]["x"]) * n["y"]
            - (after[first]["y"] - before[first]["y"]) * n["x"]
        )
    equations.append(_dot(after[second], n) - _dot(after[first], n) - parting)
    unknowns = [after[b][a] for b in hit.bodies for a in n]
    solved = sympy.solve(equations, unknowns, dict=True)
    if len(solved) != 1:
        raise DerivationError("momentum conservation did not fix the velocities after the impact")
    step(
        "Momentum conserved; the normal relative velocity after is w",
        r",\ ".join(sympy.latex(sympy.Eq(e, 0)) for e in equations),
    )
    in_w = {b: {a: solved[0][after[b][a]] for a in n} for b in hit.bodies}
    approach = _dot(before[first], n) - _dot(before[second], n)
    elastic = hit.restitution is not None and hit.restitution == 1
    if hit.release is not None or elastic:
        gain = hit.release if hit.release is not None else sympy.Integer(0)
        balance = sympy.expand(kinetic(model, in_w) - kinetic(model, before) - gain)
        w = _parting_root(model, sympy.solve(balance, parting), -approach, "normal velocity")
        step(
            "Kinetic energy balance" + (" (elastic)" if elastic else " (energy released)"),
            sympy.latex(sympy.Eq(balance, 0)) + r"\Rightarrow w = " + sympy.latex(w),
        )
    else:
        assert hit.restitution is not None
        w = hit.restitution * approach
        step("Newton's restitution law", r"w = e\,(u_1 - u_2)\cdot n = " + sympy.latex(w))
    final = {b: {a: _tidy(v.subs(parting, w)) for a, v in in_w[b].items()} for b in hit.bodies}
    return tuple(steps), before, final


def by_impulse(model: Model) -> Worked:
    steps: list[tuple[str, str]] = []
    step = _recorder(steps)
    hit = model.impact
    assert hit is not None
    first, second = hit.bodies
    n = unit_normal(model)
    before = velocities_before(model)
    ma, mb = _masses(model)
    impulse = sympy.Symbol("J", real=True)
    in_j = {
        first: {a: before[first][a] - impulse * n[a] / ma for a in n},
        second: {a: before[second][a] + impulse * n[a] / mb for a in n},
    }
    step(
        "Impulse-momentum law for each body, normal impulse J",
        r",\ ".join(
            rf"\vec v_{{{b}}} = " + sympy.latex(sympy.Matrix([in_j[b][a] for a in n]).T) for b in hit.bodies
        ),
    )
    if hit.release is not None:
        mean = {b: {a: (before[b][a] + in_j[b][a]) / 2 for a in n} for b in hit.bodies}
        work = impulse * (_dot(mean[second], n) - _dot(mean[first], n))
        j = _parting_root(
            model, sympy.solve(sympy.expand(work - hit.release), impulse), sympy.Integer(0), "impulse"
        )
        step(
            "Work of the impulse equals the energy released",
            r"J\,\frac{(u_2 + v_2 - u_1 - v_1)\cdot n}{2} = "
            + sympy.latex(hit.release)
            + r"\Rightarrow J = "
            + sympy.latex(j),
        )
    else:
        assert hit.restitution is not None
        closing = _dot(in_j[first], n) - _dot(in_j[second], n)
        # linear in J; solved by hand since sympy's solve can lose the root behind cos^2 + sin^2
        compression = tidy.simplify(-closing.subs(impulse, 0) / sympy.diff(closing, impulse))
        j = (1 + hit.restitution) * compression
        step(
            "Poisson: the compression impulse stops the approach; restitution returns e times it",
            r"J_c = " + sympy.latex(compression) + r",\ J = (1 + e) J_c = " + sympy.latex(j),
        )
    final = {b: {a: _tidy(v.subs(impulse, j)) for a, v in in_j[b].items()} for b in hit.bodies}
    return tuple(steps), before, final


def _recorder(steps: list[tuple[str, str]]) -> Step:
    return lambda title, latex: steps.append((title, latex))


def _tidy(expr: sympy.Expr) -> sympy.Expr:
    return sympy.factor(sympy.expand(expr))


def _signs_by_domain(model: Model, expr: sympy.Expr) -> sympy.Expr:
    """|a| written as a or -a where a keeps one sign over the domain (u |cos(phi)| with phi in (0, pi/2))."""
    points = domain_points(model, 12, seed=5)
    expr = tidy.simplify(expr)  # sqrt(cos(phi)^2) -> Abs(cos(phi))
    for part in expr.atoms(sympy.Abs):
        inner = part.args[0]
        values = [float(inner.subs(point)) for point in points]
        if all(v > 0 for v in values):
            expr = expr.subs(part, inner)
        elif all(v < 0 for v in values):
            expr = expr.subs(part, -inner)
    return expr


def _quantity(
    model: Model, quantity: Quantity, before: Velocities, after: Velocities, step: Step
) -> sympy.Expr:
    if quantity.kind is QuantityKind.KINETIC_ENERGY_LOST:
        lost = sympy.factor(tidy.simplify(kinetic(model, before) - kinetic(model, after)))
        step("Kinetic energy lost", r"K_0 - K_1 = " + sympy.latex(lost))
        return lost
    velocity = after[quantity.target]
    if quantity.kind is QuantityKind.FINAL_SPEED:
        speed = _signs_by_domain(model, sympy.sqrt(sympy.factor(sympy.expand(_dot(velocity, velocity)))))
        step(f"Speed of «{quantity.target}» after", sympy.latex(speed))
        return speed
    (component,) = velocity.values()
    step(f"Velocity of «{quantity.target}» after", sympy.latex(component))
    return sympy.factor(component)


INELASTIC = (
    "That is the perfectly inelastic answer ($e = 0$), with the bodies moving together afterwards. With a "
    "coefficient of restitution $e$ they separate: Newton's law gives the separating speed as $e$ times the "
    "approach speed."
)
ELASTIC = (
    "That assumes an elastic collision, conserving kinetic energy; it is conserved only when $e = 1$. Use "
    "momentum conservation with Newton's restitution law."
)
RESTITUTION_SIGN = (
    "The restitution law reverses the relative velocity: the second body leaves the first at $e$ times the "
    "speed at which they approached ($v_2 - v_1 = e\\,(u_1 - u_2)$), not towards it."
)
SWAPPED_MASSES = "Check which mass goes where: the two bodies' masses are swapped."


def mistakes(model: Model, reference: sympy.Expr) -> list[tuple[sympy.Expr | None, str]]:
    """The answers the common slips give: e taken as 0 or 1, the restitution law's sign, masses swapped."""
    hit = model.impact
    assert hit is not None
    found: list[tuple[sympy.Expr | None, str]] = []
    restitution = hit.restitution
    if restitution is not None and isinstance(restitution, sympy.Symbol) and reference.has(restitution):
        found += [
            (reference.subs(restitution, 0), INELASTIC),
            (reference.subs(restitution, 1), ELASTIC),
            (reference.subs(restitution, -restitution), RESTITUTION_SIGN),
        ]
    ma, mb = _masses(model)
    if isinstance(ma, sympy.Symbol) and isinstance(mb, sympy.Symbol):
        found.append((reference.subs({ma: mb, mb: ma}, simultaneous=True), SWAPPED_MASSES))
    return found


# The derivation methods that work an impact, by method name.
METHODS: dict[str, Callable[[Model], Worked]] = {
    "conservation": by_conservation,
    "newton": by_impulse,
}
