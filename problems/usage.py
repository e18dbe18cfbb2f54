"""Every model quantity is asked for: one that no part uses is a fault, unless listed under `unused:`.

A quantity the author misspells (`acceleraton`) is derived and then silently ignored, while the part
meant to use it (`acceleration`) falls back to its typed answer, which students are graded against:
the engine's derivation protects nothing. So an unasked quantity must be listed on purpose, and a part
whose id is a near miss of an unasked quantity is refused naming both.
"""

from __future__ import annotations

from difflib import get_close_matches

from physics.engine.scenarios import quantity_path
from problems.errors import ErrorItem
from problems.kinds import kind_of
from problems.kinds.symbolic import SymbolicPart
from problems.modelinfo import ModelQuantities
from problems.schema import ProblemDocument, format_path

NEAR = 0.8  # difflib's ratio: one slip in a name of eight letters or more, or two in ten
UNASKED = "no part asks for the quantity"


def is_usage_fault(message: str) -> bool:
    """A fault of which quantities parts ask for: the model still loads and derives."""
    return message.startswith(UNASKED)


def usage_errors(doc: ProblemDocument, model: ModelQuantities) -> list[ErrorItem]:
    """The unasked quantities not listed `unused`, and the parts whose ids nearly name one."""
    asked = {
        name for part in doc.parts for name in kind_of(part).asked_quantities(part) if name in model.names
    }
    used = set(asked)
    pending = list(asked)
    while pending:  # an expression asked for uses its quantities
        for name in model.uses.get(pending.pop(), ()):
            if name not in used:
                used.add(name)
                pending.append(name)
    unasked = sorted(model.names - used)
    errors: list[ErrorItem] = []
    for index, part in enumerate(doc.parts):
        if not isinstance(part, SymbolicPart) or part.quantity is not None or part.id in model.names:
            continue  # only a symbolic part's id names its quantity
        near = get_close_matches(part.id, unasked, n=1, cutoff=NEAR)
        if near:
            errors.append(
                (
                    format_path(("parts", index, "id")),
                    f"part {part.id!r} asks for no model quantity, but the model derives {near[0]!r}, which "
                    f"no part asks for: a near miss? The part would be graded against its typed answer, not "
                    f"the derivation; make the names match",
                )
            )
    if any(isinstance(p, SymbolicPart) and p.quantity and p.quantity not in model.names for p in doc.parts):
        return errors  # a part names a quantity the model lacks: that fault (listing them all) comes first
    for name in unasked:
        if name not in model.unused:
            errors.append(
                (
                    format_path(("model", *quantity_path(name))),
                    f"{UNASKED} {name!r}: ask for it in a part (its id, `quantity:` or "
                    "`of:`), remove it, or list it under the model's `unused:` if it is derived on purpose",
                )
            )
    return errors
