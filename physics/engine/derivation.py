"""`derive`: every quantity by every method that reaches it, proved equal, checked by simulation."""

from __future__ import annotations

import dataclasses
from collections.abc import Callable
from functools import lru_cache

import sympy

from physics.answer_text import typed_text
from physics.engine import bounces, evaluated_at, released, scenarios, tidy
from physics.engine.along_the_way import check_along_the_way
from physics.engine.amplitude import check_amplitudes
from physics.engine.buffers import check_buffers, check_buffers_placed
from physics.engine.checks import physical_checks
from physics.engine.clearances import check_clearances
from physics.engine.collision import check_heading
from physics.engine.conservation import ConservationMethod
from physics.engine.contact_friction import check_contact_sides, check_state_slips
from physics.engine.contacts import check_contact_signs
from physics.engine.dalembert import DAlembertMethod
from physics.engine.degrees import check_angles_in_radians
from physics.engine.frames import FramesMethod
from physics.engine.grips import check_rolling_grips
from physics.engine.lagrange import LagrangeMethod
from physics.engine.mechanics import Mechanics
from physics.engine.method import Method, NotApplicable
from physics.engine.mistakes import generate_limits, generate_mistakes
from physics.engine.model import Model, Quantity
from physics.engine.newton import NewtonMethod
from physics.engine.parting import check_parting, check_release
from physics.engine.pivot_inertia import check_pivot_inertias
from physics.engine.proof import clear_domain_points, domain_points, prove_equal
from physics.engine.results import Derivation, KnownMistake, LimitCase, MethodReport, SimulationCheck
from physics.engine.settle import settle
from physics.engine.simulation import Simulator
from physics.engine.sizes import check_friction_reactions, check_sizes
from physics.engine.soundness import (
    check_gravity,
    check_magnitudes,
    check_state_in_range,
    check_weight_as_force,
)
from physics.engine.trajectory import check_slopes
from physics.errors import DerivationError, PhyscheckError
from physics.wording import counted

SIMULATION_POINTS = 3
MIN_METHODS = 2
_CORE_METHODS = frozenset({"lagrange", "newton", "conservation"})


def _methods() -> tuple[type[Method], ...]:
    return (LagrangeMethod, NewtonMethod, ConservationMethod, FramesMethod, DAlembertMethod)


def derive(model: Model) -> Derivation:
    """Derive every quantity of the model; DerivationError if fewer than two methods reach one, if they
    disagree, or if the simulation disagrees. Cached per model (models are immutable and hashable).
    Each of the model's scenarios is derived as a model of its own (scenarios.py)."""
    return _failing_plainly(_derive, model)


def _failing_plainly(step: Callable[[Model], Derivation], model: Model) -> Derivation:
    try:
        return step(model)
    except PhyscheckError:
        raise
    except Exception as error:  # whatever sympy raises on an uploaded model is the model's failure to derive
        raise DerivationError(f"the derivation failed: {type(error).__name__}: {error}") from error


@lru_cache(maxsize=64)
def _derive(model: Model) -> Derivation:
    if not model.scenarios:
        return _derive_model(model)
    base = _failing_plainly(_derive_model, dataclasses.replace(model, scenarios=()))
    derived: list[tuple[str, Derivation]] = []
    failed: list[DerivationError] = []
    for name, own in model.scenarios:
        try:
            derived.append((name, _failing_plainly(_derive_model, own)))
        except DerivationError as error:
            failed.append(scenarios.relocated(error, name))
    if failed:
        findings = [item for error in failed for item in error.items()]
        raise DerivationError(
            "; ".join(m for _, m in findings),
            quantity=failed[0].quantity,
            path=findings[0][0],
            findings=findings,
        )
    return scenarios.combined(base, derived)


def _derive_model(model: Model) -> Derivation:
    clear_domain_points()  # shared within this derivation only, so vetting times stay honest
    tidy.forget()
    mech = Mechanics(model)
    released.check_freed(model, mech)  # before the count of freedoms, which it explains
    check_sizes(model)  # before the consistency: a pendulum of length -L violates its own string
    check_consistency(model, mech)
    check_gravity(model)
    check_weight_as_force(model)
    check_angles_in_radians(model)  # before the range: 30 (degrees meant) is outside [0, pi/2] for that cause
    check_slopes(model)
    check_state_in_range(model)
    check_friction_reactions(model)
    check_state_slips(model, mech)
    check_rolling_grips(model, mech)
    check_pivot_inertias(model)
    check_clearances(model, mech)
    check_contact_sides(model, mech)  # after the clearances: a unit normal mirrors the contact
    check_heading(model)
    check_parting(model)
    check_release(model)
    check_buffers_placed(model, mech)
    methods = [cls(model, mech) for cls in _methods()]
    answers: dict[str, dict[str, sympy.Expr]] = {q.name: {} for q in model.quantities}
    stopped: dict[str, dict[str, str]] = {q.name: {} for q in model.quantities}  # why a method gave none
    # a stop placed inside the quantity's own spec (its `at`): the refusal is reported there
    places: dict[str, tuple[str | int, ...]] = {}
    reports: list[MethodReport] = []
    for method in methods:
        method.derive()
        results: dict[str, sympy.Expr] = {}
        notes: list[str] = []
        for quantity in model.quantities:
            try:
                value = method.answer(quantity)
                _check_free_symbols(model, quantity, method, value)
            except NotApplicable as why:
                notes.append(f"{quantity.name}: {why}")
                stopped[quantity.name][method.name] = f"does not apply ({why})"
                continue
            except DerivationError as error:
                said = error.message.removeprefix(f"{quantity.name}: ")  # the name is said once, here
                notes.append(f"{quantity.name}: stopped: {said}")
                stopped[quantity.name][method.name] = f"stopped: {said}"
                if error.path[:2] == ("quantities", quantity.name):
                    places[quantity.name] = error.path
                continue
            except PhyscheckError:
                raise
            except Exception as error:  # sympy and arithmetic failures on an uploaded model
                reason = f"failed: {type(error).__name__}: {error}"
                notes.append(f"{quantity.name}: {reason}")
                stopped[quantity.name][method.name] = reason
                continue
            results[quantity.name] = value
            answers[quantity.name][method.name] = value
        if results or method.steps or method.name in _CORE_METHODS:  # a method that never applied is noise
            reports.append(method.report(results, notes))
    quantities: dict[str, sympy.Expr] = {}
    agreement: dict[str, tuple[str, ...]] = {}
    proofs: dict[str, str] = {}
    findings: list[tuple[tuple[str | int, ...], str]] = []
    for quantity in model.quantities:
        derived = answers[quantity.name]
        path: tuple[str | int, ...] = ("quantities", quantity.name)
        if len(derived) < MIN_METHODS:
            findings.append(
                (
                    places.get(quantity.name, path),
                    _too_few(quantity.name, derived, stopped[quantity.name], methods),
                )
            )
            continue
        frame_failed = _frame_failed(model, quantity.name, derived, stopped[quantity.name], methods)
        if frame_failed:
            findings.append((path, frame_failed))
            continue
        names = list(derived)
        how = []
        try:
            for other in names[1:]:
                how.append(
                    f"{names[0]} = {typed_text(other)}: "
                    + prove_equal(derived[names[0]], derived[other], model, quantity.name, (names[0], other))
                )
        except DerivationError as error:
            found = "; ".join(f"{name} gives {typed_text(value)}" for name, value in derived.items())
            findings.append((path, f"{error.message} (all methods: {found})"))
            continue
        quantities[quantity.name] = _simplest([settle(v, model) for v in derived.values()])
        agreement[quantity.name] = tuple(names)
        proofs[quantity.name] = "; ".join(how)
    if findings:
        raise DerivationError(
            "; ".join(f"{'.'.join(map(str, p))}: {m}" for p, m in findings),
            quantity=str(findings[0][0][1]),
            path=findings[0][0],
            findings=findings,
        )
    check_magnitudes(model, quantities)
    lagrange = methods[0]
    assert isinstance(lagrange, LagrangeMethod)  # the first of _methods()
    check_amplitudes(lagrange)
    contact_signs = check_contact_signs(model, lagrange, quantities)
    contact_signs |= check_along_the_way(model, lagrange, quantities)
    contact_signs |= check_buffers(model, lagrange, quantities)
    contact_signs |= released.check_released(model, lagrange)
    # one compiled motion for every measure, from the equations Lagrange's method has formed
    simulator = Simulator(model, lagrange.equilibrium, quantities, lagrange, rest_of=lagrange.rest)
    simulation = _simulate(model, quantities, simulator)
    variants: dict[tuple[Model, type[Method]], Method] = {(model, LagrangeMethod): lagrange}

    def rederive(changed: Model, quantity: Quantity) -> sympy.Expr | None:
        # Lagrange's equations, or conservation where they do not apply (a collision)
        for kind in (LagrangeMethod, ConservationMethod):
            method = variants.setdefault((changed, kind), kind(changed, Mechanics(changed)))
            try:
                return method.answer(quantity)
            except NotApplicable:
                continue
            except DerivationError:
                return None
        return None

    mistakes: dict[str, tuple[KnownMistake, ...]] = {}
    limits: dict[str, tuple[LimitCase, ...]] = {}
    for quantity in model.quantities:
        reference = quantities[quantity.name]
        # mistakes and limits are extras: a model whose slips cannot be derived still has its answers
        try:
            mistakes[quantity.name] = generate_mistakes(model, quantity, reference, rederive)
        except Exception:
            mistakes[quantity.name] = ()
        try:
            limits[quantity.name] = generate_limits(model, reference)
        except Exception:
            limits[quantity.name] = ()
    checks = {**contact_signs, **physical_checks(model, quantities, simulator, LagrangeMethod)}
    return Derivation(
        quantities, tuple(reports), agreement, simulation, mistakes, limits, proofs, checks, mech.notation
    )


def _too_few(
    name: str, derived: dict[str, sympy.Expr], stopped: dict[str, str], methods: list[Method]
) -> str:
    """What each method found and why the others stopped, for a quantity fewer than two methods reached:
    a reason several methods share is said once, naming them all (each method's own title taken out: the
    name before it says which). A method that does not apply to the model (frames, without a frame) is
    named only when no method tried: beside a cause, it is noise."""
    found = [f"{m.name} gives {typed_text(derived[m.name])}" for m in methods if m.name in derived]
    reasons: dict[str, list[str]] = {}
    for method in methods:
        if method.name not in derived:
            reason = stopped[method.name].replace(f"{method.title}: ", "", 1)
            reasons.setdefault(reason, []).append(method.name)
    if any(not why.startswith("does not apply") for why in reasons):  # a method that tried says why
        reasons = {why: names for why, names in reasons.items() if not why.startswith("does not apply")}
    found += [_who(names) + " " + (_plural(why) if len(names) > 1 else why) for why, names in reasons.items()]
    reached = (
        "no method could derive it"
        if not derived
        else f"only {len(derived)} method could derive it ({', '.join(derived)})"
    )
    return f"{name}: {reached}; at least {MIN_METHODS} are required. " + "; ".join(found)


def _who(names: list[str]) -> str:
    return names[0] if len(names) == 1 else ", ".join(names[:-1]) + " and " + names[-1]


def _plural(reason: str) -> str:
    return (
        "do not apply" + reason.removeprefix("does not apply")
        if reason.startswith("does not apply")
        else reason
    )


def _frame_failed(
    model: Model, name: str, derived: dict[str, sympy.Expr], stopped: dict[str, str], methods: list[Method]
) -> str | None:
    """A frame the model declares must work: the fictitious-forces method stopping where the others
    derive the quantity means the frame does not fit the model (a wrong rate, axis or body)."""
    reason = stopped.get(FramesMethod.name, "")
    if model.frame is None or not reason.startswith("stopped"):
        return None
    found = "; ".join(f"{m.name} gives {typed_text(derived[m.name])}" for m in methods if m.name in derived)
    return (
        f"{name}: in the model's frame the fictitious forces {reason}, while the other methods derive it "
        f"({found}): check the frame's rate, axis and bodies against the model"
    )


def check_consistency(model: Model, mech: Mechanics) -> None:
    """The two descriptions must describe one system: the positions satisfy every constraint, and the
    constraints leave exactly as many degrees of freedom as there are coordinates."""
    place = {d.symbol: d.mapping for d in mech.dofs}
    for constraint in model.constraints:
        residue = tidy.simplify(constraint.gap.subs(place))
        if residue != 0:  # |R - r| where R > r is declared, atan(tan(theta)) with theta in range
            residue = tidy.simplify(settle(residue, model))
        if residue != 0:
            moving = (
                model.time is not None and model.time in residue.free_symbols - constraint.gap.free_symbols
            )
            raise DerivationError(
                f"constraint {constraint.name!r}: the positions in terms of the coordinates violate it "
                f"(gap = {typed_text(residue)} instead of 0)"
                + (
                    "; the positions move with the time t but the gap does not: write it relative to the "
                    "moving support"
                    if moving
                    else ""
                ),
                path=("constraints", constraint.name),
            )
    if not model.constraints:
        free = len(mech.dofs)
    else:
        point = domain_points(model, 1)[0]
        at = {
            **point,
            **{
                q: sympy.Rational(3, 10) + sympy.Rational(i, 7)
                for i, q in enumerate(mech.q)
                if q not in point
            },
        }
        if model.time is not None and model.time not in at:
            # a gap that turns with the time (a rod spun at w) has a normal in t: the count is taken at an
            # instant, as at a domain point (a symbolic t leaves sympy unable to choose a pivot)
            at[model.time] = sympy.Rational(2, 7)
        jacobian = sympy.Matrix([[sympy.diff(c.gap, d.symbol) for d in mech.dofs] for c in model.constraints])
        numeric = jacobian.subs(place).subs(at).evalf(20)
        free = len(mech.dofs) - numeric.rank(iszerofunc=lambda x: abs(x) < 1e-12)
    if free != len(mech.q):
        raise DerivationError(
            f"the constraints leave {counted(free, 'degree of freedom', 'degrees of freedom')} but the model has "
            f"{counted(len(mech.q), 'coordinate')}{_unheld(model, mech) if free > len(mech.q) else ''}",
            path=("coordinates",),
        )


def _unheld(model: Model, mech: Mechanics) -> str:
    """The Cartesian components no constraint involves, those the coordinates do not move first: a body
    placed at `x: 1` beside a pulley is free along x (nothing holds it there), which is easy to miss."""
    unheld = [d for d in mech.dofs if not any(c.gap.has(d.symbol) for c in model.constraints)]
    still = [d for d in unheld if not d.mapping.free_symbols & set(mech.q)]
    listed = ", ".join(f"{d.name} = {typed_text(d.mapping)}" for d in still or unheld)
    if still:
        return (
            f": no constraint holds {listed}, which no coordinate moves (leave that component out of the "
            "body's position, or add the constraint that holds it there)"
        )
    return f": no constraint involves {listed}" if listed else ""


def _check_free_symbols(model: Model, quantity: Quantity, method: Method, value: sympy.Expr) -> None:
    extra = value.free_symbols - set(model.parameters)
    if extra:
        raise DerivationError(
            f"{quantity.name}: {method.title} leaves {sorted(map(str, extra))} in the answer {typed_text(value)}; give their "
            "values in the model's state",
            quantity=quantity.name,
        )


def _simplest(candidates: list[sympy.Expr]) -> sympy.Expr:
    forms: list[sympy.Expr] = []
    for expr in candidates:
        forms += [tidy.simplify(expr), sympy.factor(sympy.expand_trig(expr))]
    return min(forms, key=lambda e: (sympy.count_ops(e), len(str(e))))


def _simulate(
    model: Model, quantities: dict[str, sympy.Expr], simulator: Simulator
) -> dict[str, SimulationCheck]:
    points = domain_points(model, SIMULATION_POINTS, seed=7)
    result: dict[str, SimulationCheck] = {}
    findings: list[tuple[tuple[str | int, ...], str]] = []
    for quantity in model.quantities:
        path: tuple[str | int, ...] = ("quantities", quantity.name)
        measured, at = evaluated_at.simulated(quantity, bounces.counted(quantity, points), quantities)
        try:
            check = simulator.check(measured, quantities[quantity.name], at)
        except DerivationError as error:
            findings.append((path, error.message))
            continue
        except PhyscheckError:
            raise
        except Exception as error:  # a singular or overflowing integration
            findings.append(
                (path, f"{quantity.name}: the simulation failed: {type(error).__name__}: {error}")
            )
            continue
        if check is not None:
            result[quantity.name] = check
    if findings:
        raise DerivationError(  # one fault of the model, found by every quantity, said once
            "; ".join(dict.fromkeys(m for _, m in findings)),
            quantity=str(findings[0][0][-1]),
            findings=findings,
        )
    return result
