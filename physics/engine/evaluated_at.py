"""A quantity evaluated at another quantity's solved value: `with: {symbol: quantity}`.

    rate: {solve: Omega, zero: {acceleration: phi}}        # the rate at which the bob circles
    tension: {force: string, with: {Omega: rate}}          # the string's tension at that rate

Each method derives the quantity with the symbol left free, then puts in its own value of the named
quantity (so the two steps are each that method's, and the methods are compared on the result). The
simulation measures the quantity with the symbol set to the derived value at each sampled point, so a
wrong rate or a wrong tension each make it disagree. The pairs are kept as the quantity's `uses` (the
same meaning as an expression's: a symbol that stands for another quantity's value), so a part that
asks for the tension asks for the rate too, and two quantities evaluated at each other are a circle.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable, Mapping, Sequence
from typing import TYPE_CHECKING, Any

import sympy

from physics import typeset
from physics.answer_text import typed_text
from physics.engine import tidy
from physics.engine.model import Quantity, QuantityKind
from physics.errors import DerivationError

if TYPE_CHECKING:
    from physics.engine.method import Method

KEY = "with"
Path = tuple[str | int, ...]
Uses = tuple[tuple[sympy.Symbol, str], ...]


def split(
    name: str,
    entry: Any,
    symbols: Mapping[str, sympy.Symbol],
    quantities: Sequence[str],
    add: Callable[[str, Path], None],
) -> tuple[Any, Uses]:
    """(the quantity's entry without `with`, the (symbol, quantity) pairs it is evaluated at)."""
    if not isinstance(entry, Mapping) or KEY not in entry:
        return entry, ()
    path: Path = ("quantities", name, KEY)
    rest = {k: v for k, v in entry.items() if k != KEY}
    given = entry[KEY]
    if not isinstance(given, Mapping) or not given:
        add("a mapping of symbols to the quantities whose values they take: {Omega: rate}", path)
        return rest, ()
    uses: list[tuple[sympy.Symbol, str]] = []
    for symbol, other in given.items():
        if symbol not in symbols:
            add(f"unknown symbol {symbol!r}: `with` sets a symbol of the table", (*path, str(symbol)))
        elif other == name or other not in quantities:
            others = sorted(q for q in quantities if q != name)
            add(
                f"expected another quantity of the model, one of {others}, not {other!r}",
                (*path, str(symbol)),
            )
        else:
            uses.append((symbols[symbol], str(other)))
    return rest, tuple(uses)


def applies(quantity: Quantity) -> bool:
    return bool(quantity.uses) and quantity.kind is not QuantityKind.EXPRESSION


def answer(method: Method, quantity: Quantity) -> sympy.Expr:
    """The quantity with each symbol at this method's own value of the quantity it stands for."""
    free = method.answer(dataclasses.replace(quantity, uses=()))
    values: dict[sympy.Symbol, sympy.Expr] = {}
    for symbol, name in quantity.uses:
        if not free.has(symbol):
            raise DerivationError(
                f"{quantity.name} = {typed_text(free)} does not depend on {symbol}: `with: {{{symbol}: {name}}}` "
                "changes nothing (is it the symbol the other quantity solves for?)",
                quantity=quantity.name,
            )
        used = method.model.quantity(name)
        if used.parameter is not None and used.parameter != symbol:
            raise DerivationError(
                f"{quantity.name}: {name} is the value of {used.parameter}, not of {symbol}: "
                f"write `with: {{{used.parameter}: {name}}}`",
                quantity=quantity.name,
            )
        values[symbol] = method.answer(used)
    result = tidy.simplify(free.subs(values))
    method.step(
        f"The {quantity.kind.value.replace('_', ' ')}{_of(method, quantity.target)} at the value found for "
        + ", ".join(f"${typeset.latex(s)}$" for s in values),
        method.tex(free)
        + r"\Big|_{"
        + r",\ ".join(method.tex(sympy.Eq(s, v)) for s, v in values.items())
        + "} = "
        + method.tex(result),
    )
    return result


def _of(method: Method, target: str) -> str:
    """What the quantity is of, as the worked solution names it: ` ($T$)`, ` ($X$)` or ` of «ball»`."""
    model = method.model
    if any(c.name == target for c in model.constraints):
        return f" ({method.force_named(target)})"
    if any(c.name == target for c in model.coordinates):
        return f" ({method.named(target)})"
    return f" of «{target}»" if any(b.name == target for b in model.bodies) else ""


def simulated(
    quantity: Quantity, points: Sequence[dict[sympy.Symbol, float]], derived: Mapping[str, sympy.Expr]
) -> tuple[Quantity, list[dict[sympy.Symbol, float]]]:
    """The quantity the simulation measures (the symbol free) and the points it measures it at: each
    symbol at the derived value of its quantity there."""
    if not applies(quantity):
        return quantity, list(points)
    moved = [
        {**point, **{symbol: float(derived[name].subs(point)) for symbol, name in quantity.uses}}
        for point in points
    ]
    return dataclasses.replace(quantity, uses=()), moved
