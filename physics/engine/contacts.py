"""Unilateral contacts: a string only pulls, a surface only pushes.

The methods treat every constraint as bilateral (its multiplier may take either sign), which is right
for an axle, a bead on a wire or a rolling grip, but not for a string or a body resting on a surface:
there a negative multiplier means the string would push or the surface pull, so the string goes slack
or the body leaves the surface, and the motion the model describes is not what happens. Every string's
and surface's force at the model's state is found on the whole domain; a wrong sign anywhere refuses
the model at that constraint, saying where.
"""

from __future__ import annotations

import sympy

from physics.answer_text import typed_text
from physics.engine.method import Method
from physics.engine.model import ConstraintKind, Model
from physics.engine.signs import Sign, point_text, sign_on_domain, where_negative
from physics.errors import DerivationError, PhyscheckError

# kind -> (the force's name, what it would do with the wrong sign, what then happens)
_UNILATERAL = {
    ConstraintKind.STRING: ("tension", "the string would push", "it goes slack"),
    ConstraintKind.SURFACE: ("normal force", "the surface would pull", "the body leaves it"),
}


def check_contact_signs(model: Model, method: Method) -> dict[str, str]:
    """Each string's and surface's force keeps its physical sign over the domain (a check's name -> what
    was shown); DerivationError at `constraints.<name>` where it does not."""
    shown: list[str] = []
    loads = [s for f in model.forces for _, c in f.components for s in sorted(c.free_symbols, key=str)]
    for constraint in model.constraints:
        if constraint.kind not in _UNILATERAL:
            continue
        force = _force(method, constraint.name)
        if force is None:  # this method cannot give it here: left unchecked
            continue
        found = sign_on_domain(force, model)
        if found.sign is Sign.POSITIVE:
            shown.append(constraint.name)
            continue
        if found.sign not in (Sign.NEGATIVE, Sign.MIXED):
            continue
        named, wrong, then = _UNILATERAL[constraint.kind]
        condition = where_negative(force, model, loads)
        if found.sign is Sign.NEGATIVE:
            where = f"wherever {condition}, which is the whole domain" if condition else "on the whole domain"
        else:
            where = f"where {condition}" if condition else f"at {point_text(found.negative_at or {})}"
        raise DerivationError(
            f"constraint {constraint.name!r}: {wrong} {where}: {then} (its {named} {typed_text(force)} "
            f"must not be negative). Keep the domain where it holds (domain.positive), or model the "
            "motion without it",
            path=("constraints", constraint.name),
        )
    if not shown:
        return {}
    return {"contact signs": f"{', '.join(shown)}: a string pulls, a surface pushes, on the whole domain"}


def _force(method: Method, constraint: str) -> sympy.Expr | None:
    try:
        return method.force(constraint)
    except PhyscheckError:
        raise
    except Exception:  # sympy's failures on an uploaded model: its asked quantities were derived already
        return None
