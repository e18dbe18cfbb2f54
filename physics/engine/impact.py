"""Bodies meeting in an impact (1-D or 2-D, both moving, or one against a fixed floor or wall) or parting
in an explosion, worked two ways, with the constraints of every body in it.

The contact is smooth: its impulse J acts along the normal. A body held by a constraint (a block on a
fixed incline, a bob on its string) also receives that constraint's impulse during the impact, which
changes where its momentum goes. Conservation: generalized momentum M q' changes only along the
contact's row a in the coordinates (the constraints are built into the coordinates, so their impulses
never enter): u . M q' is conserved for every u with a . u = 0; the normal separation's rate after,
a . q', is Newton's restitution law, or, for an elastic impact or an explosion, comes from the kinetic
energy balance. Newton: each Cartesian degree of freedom's impulse-momentum law with J and every
constraint's impulse unknown, the constraints holding after; J is Poisson's compression impulse (the one
that stops the normal approach) times 1 + e, or, for an explosion, the impulse whose work (J times the
mean normal velocity before and after) is the energy released.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

import sympy

from physics import typeset
from physics.answer_text import typed_text
from physics.engine import tidy
from physics.engine.mechanics import Mechanics, cartesian_subscript, rates_giving, solve_linear
from physics.engine.model import AXES, IMPACT_KINDS, Model, Quantity, QuantityKind
from physics.engine.proof import domain_points
from physics.engine.quantity_table import derives
from physics.errors import DerivationError

if TYPE_CHECKING:
    from physics.engine.method import Method

Step = Callable[[str, str], None]
Velocities = dict[str, dict[str, sympy.Expr]]  # body -> axis (x, y, phi) -> velocity component


@dataclass(frozen=True)
class Contact:
    """The impact seen on every Cartesian degree of freedom of the model at its state: how each moves
    the contact's normal separation, each one's velocity just before, and how each follows the
    coordinates (the constraints are in that map: a block held on an incline moves along it)."""

    mech: Mechanics
    normal_row: tuple[sympy.Expr, ...]  # d(n . (r_second - r_first)) / d(x_d)
    before: tuple[sympy.Expr, ...]
    jacobian: sympy.Matrix  # d(x_d)/d(q_j) at the state
    place: dict[sympy.Symbol, sympy.Expr]  # Cartesian positions at the state

    @property
    def generalized(self) -> list[sympy.Expr]:
        """a: the normal separation's rate is a . q' (the contact's row in the coordinates)."""
        return [
            tidy.simplify(sympy.Add(*(c * self.jacobian[i, j] for i, c in enumerate(self.normal_row))))
            for j in range(self.jacobian.shape[1])
        ]


def unit_normal(model: Model) -> dict[str, sympy.Expr]:
    hit = model.impact
    assert hit is not None
    given = dict(hit.normal)
    norm = sympy.sqrt(sympy.Add(*(given.get(a, 0) ** 2 for a in AXES)))
    return {a: tidy.simplify(given.get(a, sympy.Integer(0)) / norm) for a in AXES}


def contact(model: Model, mech: Mechanics | None = None) -> Contact:
    hit = model.impact
    assert hit is not None
    mech = mech or Mechanics(model)
    state = dict(model.state)
    n = unit_normal(model)
    side = {hit.bodies[0]: -1, **({hit.bodies[1]: 1} if len(hit.bodies) > 1 else {})}
    row = tuple(
        side.get(d.body, 0) * n[d.name.split("_", 1)[0]]
        if not d.name.startswith("phi_")
        else side.get(d.body, 0) * _moment_arm(model, d.body, n, state)
        for d in mech.dofs
    )
    jacobian = sympy.Matrix(
        [[tidy.simplify(sympy.diff(d.mapping, q).subs(state)) for q in mech.q] for d in mech.dofs]
    )
    velocities = [state.get(c.velocity, sympy.Integer(0)) for c in model.coordinates]
    before = tuple(
        tidy.simplify(sympy.Add(*(jacobian[i, j] * v for j, v in enumerate(velocities))))
        for i in range(len(mech.dofs))
    )
    place = {d.symbol: d.mapping.subs(state) for d in mech.dofs}
    return Contact(mech, row, before, jacobian, place)


def _moment_arm(
    model: Model, body: str, n: dict[str, sympy.Expr], state: dict[sympy.Symbol, sympy.Expr]
) -> sympy.Expr:
    """How the body's turning moves its struck point along the normal: (r x n) for r from its centre
    of mass to the point (`points`), zero where it is struck at its centre."""
    assert model.impact is not None
    point = dict(dict(model.impact.points).get(body, ()))
    if not point:
        return sympy.Integer(0)
    position = dict(model.body(body).position)
    rx, ry = (tidy.simplify((point.get(a, 0) - position.get(a, 0)).subs(state)) for a in AXES)
    return tidy.simplify(rx * n["y"] - ry * n["x"])


def by_body(mech: Mechanics, values: Sequence[sympy.Expr]) -> Velocities:
    """Per-dof values as body -> axis -> value."""
    result: Velocities = {}
    for d, value in zip(mech.dofs, values, strict=True):
        result.setdefault(d.body, {})[d.name.split("_", 1)[0]] = value
    return result


def velocities_before(model: Model) -> Velocities:
    """Each body's Cartesian velocity at the model's state (positions differentiated in time)."""
    found = contact(model)
    return by_body(found.mech, found.before)


def _masses(model: Model) -> tuple[sympy.Expr, ...]:
    hit = model.impact
    assert hit is not None
    return tuple(model.body(name).mass for name in hit.bodies)


def _dot(u: dict[str, sympy.Expr], n: dict[str, sympy.Expr]) -> sympy.Expr:
    return sympy.Add(*(u.get(a, 0) * n[a] for a in n))


def kinetic(model: Model, velocities: Velocities) -> sympy.Expr:
    """The kinetic energy of every body: 1/2 m v^2, and 1/2 I omega^2 of a rigid body's turning."""
    total = sympy.Integer(0)
    for name, velocity in velocities.items():
        body = model.body(name)
        for axis, v in velocity.items():
            total += (body.inertia if axis == "phi" else body.mass) * v**2 / 2
    return total


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
    """Generalized momentum p = M q' changes only along the contact's row a (the impulse's generalized
    direction; a constraint's impulse does no work on the coordinates, so it never enters): u . p is
    conserved for every u with a . u = 0. Then Newton's restitution law on a . q', or for an elastic
    impact or an explosion the kinetic energy balance."""
    steps: list[tuple[str, str]] = []
    step = _recorder(steps)
    hit = model.impact
    assert hit is not None
    found = contact(model)
    mech = found.mech
    state = dict(model.state)
    mass = mech.mass_matrix.subs(state).applyfunc(tidy.simplify)
    a = sympy.Matrix(found.generalized)
    before = sympy.Matrix([state.get(c.velocity, sympy.Integer(0)) for c in model.coordinates])
    after = sympy.Matrix([sympy.Symbol(f"{c.name}_after", real=True) for c in model.coordinates])
    parting = sympy.Symbol("w", real=True)  # the normal separation's rate after: a . q'
    # each coordinate's velocity after primed, as textbooks write it: \dot{x}'
    names = {
        v: mech.latex_names.get(c.velocity, typeset.latex(c.velocity)) + "'"
        for v, c in zip(after, model.coordinates, strict=True)
    }
    conserved = [(u.T * mass * (after - before))[0] for u in sympy.Matrix([list(a)]).nullspace()]
    equations = [*conserved, (a.T * after)[0] - parting]
    solved = solve_linear(equations, list(after), "momentum conservation", tidy=_tidy)
    step(
        "Momentum conserved in every direction the contact's impulse has no part in "
        "(the constraints' impulses included: they do no work on the coordinates); the normal "
        "separation's rate after is w",
        r",\quad ".join(typeset.latex(sympy.Eq(e, 0), symbol_names=names) for e in equations),
    )
    approach = -(a.T * before)[0]
    in_w = sympy.Matrix([solved[v] for v in after])
    elastic = hit.restitution is not None and hit.restitution == 1
    if hit.release is not None or elastic:
        gain = hit.release if hit.release is not None else sympy.Integer(0)
        balance = sympy.expand(((in_w.T * mass * in_w)[0] - (before.T * mass * before)[0]) / 2 - gain)
        w = _parting_root(model, sympy.solve(balance, parting), -approach, "normal velocity")
        step(
            "Kinetic energy balance" + (" (elastic)" if elastic else " (energy released)"),
            typeset.latex(sympy.Eq(balance, 0)) + r"\Rightarrow w = " + typeset.latex(w),
        )
    else:
        assert hit.restitution is not None
        w = hit.restitution * approach
        step("Newton's restitution law", r"w = e\,(u_1 - u_2)\cdot n = " + typeset.latex(w))
    rates = [_tidy(v.subs(parting, w)) for v in in_w]
    cartesian = [
        _tidy(sympy.Add(*(found.jacobian[i, j] * r for j, r in enumerate(rates))))
        for i in range(len(mech.dofs))
    ]
    return tuple(steps), by_body(mech, found.before), by_body(mech, cartesian)


def by_impulse(model: Model) -> Worked:
    """Each Cartesian degree of freedom's impulse-momentum law, with the contact's normal impulse J and
    each constraint's impulse as unknowns (a block held on an incline is pushed by the incline during
    the impact), the constraints holding after; J is Poisson's compression impulse (the one that stops
    the normal approach) times 1 + e, or, for an explosion, the impulse whose work is the energy."""
    blow = _blow(model)
    mech = blow.found.mech
    return blow.steps, by_body(mech, blow.found.before), by_body(mech, blow.after)


def constraint_impulses(model: Model) -> dict[str, sympy.Expr]:
    """Each constraint's impulse during the model's impact (Newton's route), positive as its force is:
    a string's pulls, a surface's pushes (contacts.py checks that they do)."""
    return _blow(model).impulses


@dataclass(frozen=True)
class _Blow:
    steps: tuple[tuple[str, str], ...]
    found: Contact
    after: list[sympy.Expr]  # each Cartesian degree of freedom's velocity just after
    impulses: dict[str, sympy.Expr]  # each constraint's impulse


def _blow(model: Model) -> _Blow:
    steps: list[tuple[str, str]] = []
    step = _recorder(steps)
    hit = model.impact
    assert hit is not None
    found = contact(model)
    mech = found.mech
    impulse = sympy.Symbol("J", real=True)
    held = [sympy.Symbol(f"Lambda_{c.name}", real=True) for c in model.constraints]
    gradients = [[g.subs(found.place) for g in mech.gap_gradient(k)] for k in range(len(held))]
    after = [sympy.Symbol(f"v_{d.name}_after", real=True) for d in mech.dofs]
    laws = [
        d.inertia * (after[i] - found.before[i])
        - impulse * found.normal_row[i]
        - sympy.Add(*(lam * grad[i] for lam, grad in zip(held, gradients, strict=True)))
        for i, d in enumerate(mech.dofs)
    ]
    holding = [sympy.Add(*(g * v for g, v in zip(grad, after, strict=True))) for grad in gradients]
    solved = solve_linear([*laws, *holding], [*after, *held], "the impulse-momentum laws", tidy=_tidy)
    names = {  # v'_{x,ball} just after; \Lambda_{axle} a constraint's impulse
        **mech.latex_names,
        **{v: rf"v'_{{{cartesian_subscript(d.name)}}}" for v, d in zip(after, mech.dofs, strict=True)},
        **{lam: rf"\Lambda_{{\mathrm{{{c.name}}}}}" for lam, c in zip(held, model.constraints, strict=True)},
    }
    in_j = [solved[v] for v in after]
    step(
        "Impulse-momentum law for each body, normal impulse J"
        + (", and each constraint's impulse, the constraint holding after" if held else ""),
        r",\quad ".join(typeset.latex(sympy.Eq(e, 0), symbol_names=names) for e in [*laws, *holding]),
    )
    rate_after = sympy.Add(*(c * v for c, v in zip(found.normal_row, in_j, strict=True)))
    rate_before = sympy.Add(*(c * v for c, v in zip(found.normal_row, found.before, strict=True)))
    if hit.release is not None:
        work = impulse * (rate_before + rate_after) / 2
        j = _parting_root(
            model, sympy.solve(sympy.expand(work - hit.release), impulse), sympy.Integer(0), "impulse"
        )
        step(
            "Work of the impulse equals the energy released",
            r"J\,\frac{(u_2 + v_2 - u_1 - v_1)\cdot n}{2} = "
            + typeset.latex(hit.release)
            + r"\Rightarrow J = "
            + typeset.latex(j),
        )
    else:
        assert hit.restitution is not None
        # linear in J; solved by hand since sympy's solve can lose the root behind cos^2 + sin^2
        compression = tidy.simplify(-rate_after.subs(impulse, 0) / sympy.diff(rate_after, impulse))
        j = (1 + hit.restitution) * compression
        step(
            "Poisson: the compression impulse stops the approach; restitution returns e times it",
            r"J_c = " + typeset.latex(compression) + r",\ J = (1 + e) J_c = " + typeset.latex(j),
        )
    final = [_tidy(v.subs(impulse, j)) for v in in_j]
    impulses = {
        c.name: _tidy(solved[lam].subs(impulse, j)) for c, lam in zip(model.constraints, held, strict=True)
    }
    return _Blow(tuple(steps), found, final, impulses)


def coordinate_rates(model: Model, after: Velocities) -> list[sympy.Expr]:
    """The coordinates' velocities that give the bodies' velocities `after` (the constraints hold, so
    the Cartesian velocities determine them)."""
    found = contact(model)
    cartesian = [after[d.body][d.name.split("_", 1)[0]] for d in found.mech.dofs]
    return rates_giving(found.jacobian, cartesian, "the velocities after the impact", tidy=_tidy)


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
        step("Kinetic energy lost", r"K_0 - K_1 = " + typeset.latex(lost))
        return lost
    if quantity.kind is QuantityKind.VELOCITY_AFTER:  # a coordinate's: a struck rod's rate of turning
        index = [c.name for c in model.coordinates].index(quantity.target)
        rate = sympy.factor(coordinate_rates(model, after)[index])
        coordinate = model.coordinates[index]
        names = Mechanics(model).latex_names  # the coordinate's rate as a worked solution writes it
        step("Velocity just after", typeset.latex(sympy.Eq(coordinate.velocity, rate), symbol_names=names))
        return rate
    velocity = {a: v for a, v in after[quantity.target].items() if a != "phi"}
    if quantity.kind is QuantityKind.FINAL_SPEED:
        speed = _signs_by_domain(model, sympy.sqrt(sympy.factor(sympy.expand(_dot(velocity, velocity)))))
        step(f"Speed of «{quantity.target}» after", typeset.latex(speed))
        return speed
    (component,) = velocity.values()
    step(f"Velocity of «{quantity.target}» after", typeset.latex(component))
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
    masses = _masses(model)
    if len(masses) == 2 and all(isinstance(m, sympy.Symbol) for m in masses):
        ma, mb = masses
        found.append((reference.subs({ma: mb, mb: ma}, simultaneous=True), SWAPPED_MASSES))
    # e = 0 in the n-th bounce's e^(2n - 2): no student's answer (there is no second bounce to slip on)
    return [(wrong, why) for wrong, why in found if wrong is None or not _zero_to_a_symbol(wrong)]


def _zero_to_a_symbol(expression: sympy.Expr) -> bool:
    return any(power.base == 0 and not power.exp.is_number for power in expression.atoms(sympy.Pow))


# The derivation methods that work an impact, by method name.
METHODS: dict[str, Callable[[Model], Worked]] = {
    "conservation": by_conservation,
    "newton": by_impulse,
}


@derives(*IMPACT_KINDS)
def derived(method: Method, quantity: Quantity) -> sympy.Expr:
    return method.impact(quantity)
