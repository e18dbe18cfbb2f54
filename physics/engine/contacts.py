"""Unilateral contacts: a string only pulls, a surface only pushes.

The methods treat every constraint as bilateral (its multiplier may take either sign), which is right
for an axle, a bead on a wire or a rolling grip, but not for a string or a body resting on a surface:
there a negative multiplier means the string would push or the surface pull, so the string goes slack
or the body leaves the surface, and the motion the model describes is not what happens. Every string's
and surface's force at the model's state is found on the whole domain; a wrong sign anywhere refuses
the model at that constraint, saying where.
"""

from __future__ import annotations

from collections.abc import Mapping

import sympy

from physics.answer_text import typed_text
from physics.engine import collision, impact
from physics.engine.method import Method
from physics.engine.model import Action, Constraint, ConstraintKind, Model, QuantityKind
from physics.engine.signs import Sign, point_text, sign_on_domain, where_negative
from physics.errors import DerivationError, PhyscheckError

# a unilateral kind -> (the force's name, what it would do with the wrong sign, what then happens)
UNILATERAL = {
    ConstraintKind.STRING: ("tension", "the string would push", "it goes slack"),
    ConstraintKind.SURFACE: ("normal force", "the surface would pull", "the body leaves it"),
}


def check_contact_signs(
    model: Model, method: Method, quantities: Mapping[str, sympy.Expr] | None = None
) -> dict[str, str]:
    """Each string's and surface's force keeps its physical sign over the domain, at the state and
    wherever an asked force is taken (`at`): a check's name -> what was shown; DerivationError at
    `constraints.<name>` (or the asked force's quantity) where it does not."""
    shown: list[str] = []
    unilateral = {c.name: c.kind for c in model.acting(Action.UNILATERAL) if isinstance(c, Constraint)}
    for constraint in model.constraints:
        if constraint.name not in unilateral:
            continue
        force = _force(method, constraint.name)
        if force is None:  # this method cannot give it here: left unchecked
            continue
        if _holds(model, constraint.kind, constraint.name, force, ("constraints", constraint.name), ""):
            shown.append(constraint.name)
    for quantity in model.quantities:
        if quantity.kind is not QuantityKind.FORCE or not quantity.at or quantities is None:
            continue
        kind = unilateral.get(quantity.target)
        if kind is not None:
            ((coordinate, value),) = quantity.at
            there = f" at {coordinate} = {typed_text(value)}"
            path = ("quantities", quantity.name)
            _holds(model, kind, quantity.target, quantities[quantity.name], path, there)
    _check_impulses(model, unilateral)
    if not shown:
        return {}
    return {"contact signs": f"{', '.join(shown)}: a string pulls, a surface pushes, on the whole domain"}


def _check_impulses(model: Model, unilateral: Mapping[str, ConstraintKind]) -> None:
    """An impact (or a projectile's collision) holds every constraint through the blow, which a string and
    a surface do only with an impulse of their force's sign: a ball flying up into a bob hanging on a
    string would need the string to push, and bounces off it as off a wall (a bullet rising into it would
    swing with it), while the string goes slack and the bob flies up."""
    if (model.impact is None and model.collision is None) or not unilateral:
        return
    try:
        if model.impact is not None:
            impulses = impact.constraint_impulses(model)
        else:
            impulses = collision.constraint_impulses(model)
    except PhyscheckError:
        return  # the methods said why already
    except Exception:  # sympy's failures on an uploaded model: the quantities were derived already
        return
    for name, kind in unilateral.items():
        if name not in impulses:
            continue
        found = sign_on_domain(impulses[name].subs(collision.SPEED, 1), model)  # linear in an asked speed
        if found.sign not in (Sign.NEGATIVE, Sign.MIXED):
            continue
        _, wrong, then = UNILATERAL[kind]
        where = (
            "on the whole domain"
            if found.sign is Sign.NEGATIVE
            else f"at {point_text(found.negative_at or {})}"
        )
        if model.impact is not None:
            raise DerivationError(
                f"constraint {name!r}: {wrong} during the impact {where}: {then} at the blow, which the "
                f"impact holds (its impulse {typed_text(impulses[name])} must not be negative). Model the blow "
                f"with the contact released (`released: [{name}]`, its bodies free to part)",
                path=("impact",),
            )
        raise DerivationError(
            f"constraint {name!r}: {wrong} as the projectile strikes {where}: {then} at the blow, which the "
            f"collision holds (its impulse {typed_text(impulses[name])} must not be negative). Check the "
            "projectile's direction",
            path=("collision", "direction"),
        )


def _holds(
    model: Model, kind: ConstraintKind, name: str, force: sympy.Expr, path: tuple[str, ...], there: str
) -> bool:
    """True when the force keeps its sign; DerivationError at `path` when it is wrong somewhere; False when
    its sign could not be found."""
    loads = [s for f in model.force_entries for e in f.expressions() for s in sorted(e.free_symbols, key=str)]
    found = sign_on_domain(force, model)
    if found.sign is Sign.POSITIVE:
        return True
    if found.sign in (Sign.NEGATIVE, Sign.MIXED):
        named, wrong, then = UNILATERAL[kind]
        condition = where_negative(force, model, loads)
        if found.sign is Sign.NEGATIVE:
            where = f"wherever {condition}, which is the whole domain" if condition else "on the whole domain"
        else:
            where = f"where {condition}" if condition else f"at {point_text(found.negative_at or {})}"
        raise DerivationError(
            f"constraint {name!r}: {wrong}{there} {where}: {then}{' before it gets there' if there else ''} "
            f"(its {named} {typed_text(force)} "
            f"must not be negative). Keep the domain where it holds (domain.positive), or model the "
            f"motion without it{'' if there else f' (`released: [{name}]`, its bodies free to part)'}",
            path=path,
        )
    return False


def _force(method: Method, constraint: str) -> sympy.Expr | None:
    try:
        return method.force(constraint)
    except PhyscheckError:
        raise
    except Exception:  # sympy's failures on an uploaded model: its asked quantities were derived already
        return None
