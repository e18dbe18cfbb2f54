"""A perfectly inelastic collision followed by motion, worked two ways.

Conservation: the generalized momentum the projectile brings (its momentum projected on the target's
motion) is the merged system's momentum just after, the constraint impulses doing no virtual work;
then energy is conserved up to the turning point. Newton: impulse balance in Cartesian coordinates
with the constraint impulses as unknowns; then the work-energy theorem, integrating the work of the
forces along the path.
"""

from __future__ import annotations

import dataclasses
from typing import TYPE_CHECKING

import sympy

from physics import typeset
from physics.answer_text import typed_text
from physics.engine import embedding, tidy
from physics.engine.mechanics import Mechanics, cartesian_subscript, rates_giving, solve_linear
from physics.engine.model import Model, Quantity, QuantityKind
from physics.engine.quantity_table import derives
from physics.engine.roots import admissible
from physics.engine.signs import Sign, sign_on_domain
from physics.errors import DerivationError

if TYPE_CHECKING:
    from physics.engine.method import Method

SPEED = sympy.Symbol("v", positive=True)


def merged(model: Model) -> Model:
    """The model after the projectile has embedded itself in the target: in a rigid target's `point`,
    a particle held there (embedding.py); else part of the target's mass."""
    hit = model.collision
    assert hit is not None
    if hit.point and model.body(hit.target).angle is not None:
        return embedding.joined(model)
    bodies = tuple(
        dataclasses.replace(b, mass=b.mass + hit.projectile_mass) if b.name == hit.target else b
        for b in model.bodies
    )
    return dataclasses.replace(model, bodies=bodies)


def event_points(model: Model) -> tuple[dict[sympy.Symbol, sympy.Expr], dict[sympy.Symbol, sympy.Expr]]:
    hit = model.collision
    assert hit is not None
    at = {model.coordinate(n).symbol: v for n, v in hit.at}
    reaches = {model.coordinate(n).symbol: v for n, v in hit.reaches}
    for c in model.coordinates:
        at.setdefault(c.symbol, sympy.Integer(0))
        reaches.setdefault(c.symbol, at[c.symbol])
    return at, reaches


def _momentum(model: Model) -> dict[str, sympy.Expr]:
    """The projectile's momentum on each axis."""
    hit = model.collision
    assert hit is not None
    direction = dict(hit.direction)
    norm = sympy.sqrt(sympy.Add(*(v**2 for v in direction.values())))
    return {axis: hit.projectile_mass * _speed(model) * value / norm for axis, value in direction.items()}


def _projectile_momentum(model: Model, mech: Mechanics) -> list[sympy.Expr]:
    """The projectile's momentum on each Cartesian dof of the body that carries it after the impact:
    itself where it sticks in a rigid target's point, else the target (zero elsewhere)."""
    hit = model.collision
    assert hit is not None
    carrier = hit.projectile if any(d.body == hit.projectile for d in mech.dofs) else hit.target
    momentum = _momentum(model)
    return [
        momentum.get(d.name.split("_", 1)[0], sympy.Integer(0))
        if d.body == carrier and not d.name.startswith("phi_")
        else sympy.Integer(0)
        for d in mech.dofs
    ]


def _speed(model: Model) -> sympy.Expr:
    """The projectile's speed: given (`speed`), or the unknown v that `reaches` settles."""
    assert model.collision is not None
    return SPEED if model.collision.speed is None else model.collision.speed


def _fraction_lost(kinetic_after: sympy.Expr, model: Model, steps: list[tuple[str, str]]) -> sympy.Expr:
    assert model.collision is not None
    before = model.collision.projectile_mass * _speed(model) ** 2 / 2
    fraction = tidy.simplify((before - kinetic_after) / before)
    steps.append(
        ("Fraction of the kinetic energy lost", r"\frac{K_0 - K_1}{K_0} = " + typeset.latex(fraction))
    )
    return fraction


def _velocity_after(
    rates: dict[sympy.Symbol, sympy.Expr], mech: Mechanics, quantity: Quantity, steps: list[tuple[str, str]]
) -> sympy.Expr:
    velocity = mech.model.coordinate(quantity.target).velocity
    value = tidy.simplify(rates[velocity])
    steps.append(
        ("Velocity just after", typeset.latex(sympy.Eq(velocity, value), symbol_names=mech.latex_names))
    )
    return value


def _projectile_speed(
    kinetic_after: sympy.Expr, rise: sympy.Expr, model: Model, steps: list[tuple[str, str]]
) -> sympy.Expr:
    hit = model.collision
    assert hit is not None
    found = tidy.solve(kinetic_after - rise, SPEED)
    roots = admissible(found, SPEED, model)
    if not roots and tidy.simplify(rise).is_nonpositive:
        raise DerivationError(
            f"the merged body cannot come to rest at {typed_text(dict(hit.reaches))}: its kinetic energy just "
            f"after the blow would have to be {typed_text(tidy.simplify(rise))}, which is not positive (is "
            "`reaches` on the side the projectile drives it?)"
        )
    if len(roots) != 1:
        raise DerivationError(f"expected one positive projectile speed, found {typed_text(found)}")
    steps.append(("Projectile speed", typeset.latex(sympy.Eq(SPEED, roots[0]))))
    return tidy.simplify(roots[0])


def check_heading(model: Model) -> None:
    """The blow drives the merged body towards where `reaches` says it stops: a coordinate that must
    grow (or fall) to get there moves that way just after. A projectile fired the other way had been
    taken to stop at `reaches` all the same (the speed squared, every method agreeing), refused only by
    a simulation that "never turned back"."""
    hit = model.collision
    if hit is None or not hit.reaches:
        return
    after = merged(model)
    mech = Mechanics(after)
    at, reaches = event_points(model)
    equations, _ = _momentum_equations(model, mech, at)
    velocities = solve_linear(equations, list(mech.qd), "momentum across the collision")
    for c in model.coordinates:
        ahead = sign_on_domain(tidy.simplify(reaches[c.symbol] - at[c.symbol]), model).sign
        heading = sign_on_domain(tidy.simplify(velocities[c.velocity].subs(SPEED, 1)), model).sign
        if {ahead, heading} == {Sign.POSITIVE, Sign.NEGATIVE}:
            way = "decreasing" if heading is Sign.NEGATIVE else "increasing"
            raise DerivationError(
                f"the projectile drives {c.name} towards {way} values (just after the blow "
                f"{c.name}_dot = {typed_text(tidy.simplify(velocities[c.velocity]))}, v the projectile's speed), but `reaches` puts "
                f"{c.name} at {typed_text(reaches[c.symbol])}, the other way from {typed_text(at[c.symbol])}: "
                "check the projectile's direction, or which side `reaches` is on",
                path=("collision", "direction"),
            )


def _momentum_equations(
    model: Model, mech: Mechanics, at: dict[sympy.Symbol, sympy.Expr]
) -> tuple[list[sympy.Expr], list[sympy.Expr]]:
    """M q' = p for the merged body just after the blow, p the projectile's momentum projected on each
    coordinate's motion of the point it strikes; (the equations, p)."""
    momentum, point = _momentum(model), embedding.struck(model)
    brought = [
        sympy.Add(
            *(p * sympy.diff(point.get(axis, sympy.Integer(0)), q) for axis, p in momentum.items())
        ).subs(at)
        for q in mech.q
    ]
    mass = mech.mass_matrix.subs(at)
    equations = [
        sympy.Add(*(mass[i, j] * mech.qd[j] for j in range(len(mech.q)))) - brought[i]
        for i in range(len(mech.q))
    ]
    return equations, brought


def by_conservation(model: Model, quantity: Quantity, steps: list[tuple[str, str]]) -> sympy.Expr:
    after = merged(model)
    mech = Mechanics(after)
    at, reaches = event_points(model)
    equations, brought = _momentum_equations(model, mech, at)
    steps.append(
        (
            "Generalized momentum across the impulse",
            r",\quad ".join(
                typeset.latex(sympy.Eq(e + b, b), symbol_names=mech.latex_names)
                for e, b in zip(equations, brought, strict=True)
            ),
        )
    )
    velocities = solve_linear(equations, list(mech.qd), "momentum across the collision")
    if quantity.kind is QuantityKind.VELOCITY_AFTER:
        return _velocity_after(velocities, mech, quantity, steps)
    kinetic = tidy.simplify(mech.kinetic.subs(at).subs(velocities))
    if quantity.kind is QuantityKind.ENERGY_FRACTION_LOST:
        return _fraction_lost(kinetic, model, steps)
    rise = tidy.simplify(mech.potential.subs(reaches) - mech.potential.subs(at))
    work = _nonconservative_work(after, mech, at, reaches, steps)
    title = (
        "Energy conserved after the collision"
        if work == 0
        else "Energy after the collision, less friction's work"
    )
    steps.append(
        (title, typeset.latex(sympy.Eq(kinetic, tidy.simplify(rise - work)), symbol_names=mech.latex_names))
    )
    return _projectile_speed(kinetic, tidy.simplify(rise - work), model, steps)


def _nonconservative_work(
    after: Model,
    mech: Mechanics,
    at: dict[sympy.Symbol, sympy.Expr],
    reaches: dict[sympy.Symbol, sympy.Expr],
    steps: list[tuple[str, str]],
) -> sympy.Expr:
    """The work of kinetic friction (and forces in the coordinates) from the impact to where the merged
    body stops: a bullet in a block that skids on a rough floor. The normal forces come from Newton's law
    across each surface; on a curve they change with the speed, and the work needs the motion itself."""
    if not after.nonconservative_loads:
        return sympy.Integer(0)
    from physics.engine.newton import NewtonMethod  # it builds on the methods, which load this module

    if len(mech.q) != 1:
        raise DerivationError("the work of friction after a collision is done for one coordinate only")
    multipliers: list[sympy.Expr] = list(mech.multipliers)
    if after.contact_loads:
        free = dataclasses.replace(after, state=())
        across = NewtonMethod(free, Mechanics(free)).solution
        multipliers = [across[lam] for lam in mech.multipliers]
    (q,), (qd,) = mech.q, mech.qd
    generalized = tidy.simplify(mech.generalized(mech.load_forces(False, multipliers))[0])
    if generalized.has(qd):
        raise DerivationError(
            f"the force along {q} after the collision ({typed_text(generalized)}) depends on the speed: "
            "its work needs the motion itself"
        )
    work = tidy.simplify(tidy.integrate(generalized, (q, at[q], reaches[q])))
    steps.append(
        (
            "Work of friction and the other non-conservative forces until it stops",
            rf"W = \int Q_{{\mathrm{{nc}}}}\,d{typeset.latex(q, symbol_names=mech.latex_names)} = "
            + typeset.latex(work, symbol_names=mech.latex_names),
        )
    )
    return work


@dataclasses.dataclass(frozen=True)
class _Balance:
    """The impulse balance of the merged body: each Cartesian dof's law, the constraints allowing the
    velocities after, and the unknowns (velocities just after, constraint impulses)."""

    after: Model
    mech: Mechanics
    balances: list[sympy.Expr]
    allowed: list[sympy.Expr]
    velocity: list[sympy.Symbol]
    impulses: list[sympy.Symbol]


def _balance(model: Model) -> _Balance:
    after = merged(model)
    mech = Mechanics(after)
    at, _ = event_points(model)
    place = {d.symbol: d.mapping.subs(at) for d in mech.dofs}
    momentum = _projectile_momentum(model, mech)
    impulses = [sympy.Symbol(f"J_{c.name}", real=True) for c in after.constraints]
    velocity = [sympy.Symbol(f"u_{d.name}", real=True) for d in mech.dofs]
    gradients = [[sympy.diff(c.gap, d.symbol).subs(place) for d in mech.dofs] for c in after.constraints]
    balances = [
        d.inertia * u - p - sympy.Add(*(j * g[i] for j, g in zip(impulses, gradients, strict=True)))
        for i, (d, u, p) in enumerate(zip(mech.dofs, velocity, momentum, strict=True))
    ]
    allowed = [sympy.Add(*(g_i * u for g_i, u in zip(g, velocity, strict=True))) for g in gradients]
    return _Balance(after, mech, balances, allowed, velocity, impulses)


def constraint_impulses(model: Model) -> dict[str, sympy.Expr]:
    """Each constraint's impulse as the projectile embeds itself (Newton's route), positive as its force
    is (a string's pulls); in the projectile's speed, SPEED where that is what is asked."""
    found = _balance(model)
    solution = solve_linear(
        found.balances + found.allowed, found.velocity + found.impulses, "impulse balance"
    )
    return {
        c.name: tidy.simplify(solution[j])
        for c, j in zip(found.after.constraints, found.impulses, strict=True)
    }


def by_newton(model: Model, quantity: Quantity, steps: list[tuple[str, str]]) -> sympy.Expr:
    hit = model.collision
    assert hit is not None
    found = _balance(model)
    after, mech, balances, allowed = found.after, found.mech, found.balances, found.allowed
    velocity, impulses = found.velocity, found.impulses
    at, reaches = event_points(model)
    # just after the impact: v'_{x,block} for the block's x velocity (primed as textbooks write a velocity
    # after; u may be the given speed), J_{string} for the string's impulse
    names = {
        **mech.latex_names,
        **{u: rf"v'_{{{cartesian_subscript(d.name)}}}" for u, d in zip(velocity, mech.dofs, strict=True)},
        **{j: rf"J_{{\mathrm{{{c.name}}}}}" for j, c in zip(impulses, after.constraints, strict=True)},
    }

    def listed(equations: list[sympy.Expr]) -> str:  # `,\quad`: a worked solution's line each
        return r",\quad ".join(typeset.latex(sympy.Eq(e, 0), symbol_names=names) for e in equations)

    # one line per body (a rod struck at its end, and the bullet in it, are two), then the velocities
    for body in after.bodies:
        own = [e for e, d in zip(balances, mech.dofs, strict=True) if d.body == body.name]
        named = f"the {body.name}" if body.name == hit.projectile else f"«{body.name}»"  # not a model body
        steps.append((f"Impulse balance on {named}, constraint impulses unknown", listed(own)))
    if allowed:
        steps.append(("Velocities just after, as the constraints allow", listed(allowed)))
    solution = solve_linear(balances + allowed, velocity + impulses, "impulse balance")
    if quantity.kind is QuantityKind.VELOCITY_AFTER:
        jacobian = sympy.Matrix([[sympy.diff(d.mapping, q).subs(at) for q in mech.q] for d in mech.dofs])
        rates = rates_giving(jacobian, [solution[u] for u in velocity], "the velocities just after")
        return _velocity_after(dict(zip(mech.qd, rates, strict=True)), mech, quantity, steps)
    kinetic = tidy.simplify(
        sympy.Add(*(d.inertia * solution[u] ** 2 / 2 for d, u in zip(mech.dofs, velocity, strict=True)))
    )
    if quantity.kind is QuantityKind.ENERGY_FRACTION_LOST:
        return _fraction_lost(kinetic, model, steps)
    if len(mech.q) != 1:
        raise DerivationError("the work integral is done for one coordinate only")
    q = mech.q[0]
    cart_state = mech.cartesian_state()
    force = sympy.Add(
        *(
            (-sympy.diff(mech.cartesian_potential, d.symbol)).subs(cart_state) * sympy.diff(d.mapping, q)
            for d in mech.dofs
        )
    )
    work = tidy.simplify(
        tidy.integrate(force, (q, at[q], reaches[q])) + _nonconservative_work(after, mech, at, reaches, steps)
    )
    steps.append(
        (
            "Work-energy theorem up to the turning point",
            rf"0 - K_1 = \int Q\,d{typeset.latex(q, symbol_names=names)} = "
            + typeset.latex(work, symbol_names=names),
        )
    )
    return _projectile_speed(kinetic, -work, model, steps)


@derives(QuantityKind.PROJECTILE_SPEED, QuantityKind.ENERGY_FRACTION_LOST, QuantityKind.VELOCITY_AFTER)
def derived(method: Method, quantity: Quantity) -> sympy.Expr:
    """Each method works the collision its own way (`collision` of Newton and of conservation); a
    velocity just after an `impact` (bodies that bounce) is the impact's."""
    if quantity.kind is QuantityKind.VELOCITY_AFTER and method.model.collision is None:
        return method.impact(quantity)
    return method.collision(quantity)
