"""A standard body's moment of inertia taken for another's: the slip students make most with rolling and
spinning bodies (a disk's ½MR² for a hoop's MR², a solid sphere's 2/5 for a shell's 2/3, a rod's 1/3
ML² about its end for its 1/12 ML² about its centre).

A body's inertia (about its centre of mass) is recognised as a shape's when it is a number from the
table below times the body's own mass times the square of one of the body's lengths: a length the
model's positions, constraints or friction's contact points use too, such as the radius a wheel rolls
or skids on or the length a rod hangs by. A radius of gyration (`m k²`, k nowhere else) names no shape,
and is left alone."""

from __future__ import annotations

import dataclasses
from collections.abc import Iterator

import sympy

from physics import typeset
from physics.engine.model import Body, Model

_HALF, _THIRD, _TWELFTH = sympy.Rational(1, 2), sympy.Rational(1, 3), sympy.Rational(1, 12)
_ONE, _SOLID, _SHELL = sympy.Integer(1), sympy.Rational(2, 5), sympy.Rational(2, 3)
SHAPES: dict[sympy.Rational, str] = {
    _ONE: "a thin hoop's",
    _HALF: "a uniform disk's",
    _SOLID: "a solid sphere's",
    _SHELL: "a thin spherical shell's",
    _TWELFTH: "a rod's about its centre",
    _THIRD: "a rod's about its end",
}
# A shape's inertia about a point on its edge (a rod's end, a round body's rim), the parallel-axis sum
# of its own about the centre and m times the edge's distance squared: factor -> (centre's factor, the
# edge's distance over the length, what it is).
ABOUT_AN_EDGE: dict[sympy.Rational, tuple[sympy.Rational, sympy.Rational, str]] = {
    _THIRD: (_TWELFTH, _HALF, "a rod's about its end"),
    sympy.Integer(2): (_ONE, _ONE, "a thin hoop's about a point on its rim"),
    sympy.Rational(3, 2): (_HALF, _ONE, "a uniform disk's about a point on its rim"),
    sympy.Rational(7, 5): (_SOLID, _ONE, "a solid sphere's about a point on its surface"),
    sympy.Rational(5, 3): (_SHELL, _ONE, "a thin spherical shell's about a point on its surface"),
}
# What each is taken for: the shapes a student confuses it with, most often first.
CONFUSED: dict[sympy.Rational, tuple[sympy.Rational, ...]] = {
    _ONE: (_HALF,),
    _HALF: (_ONE, _SOLID),
    _SOLID: (_SHELL, _HALF),
    _SHELL: (_SOLID,),
    _TWELFTH: (_THIRD,),
    _THIRD: (_TWELFTH,),
}
WRONG_SHAPE = (
    "Check the moment of inertia of {body}: this answer uses {wrong}, ${used}$; about its centre of mass "
    "it is ${right}$ here."
)


def confused_inertias(model: Model) -> Iterator[tuple[Model, str]]:
    """The model with one body's inertia replaced by a shape's it is taken for, and what to tell a
    student whose answer is that model's."""
    lengths = geometric_symbols(model)
    for index, body in enumerate(model.bodies):
        factor = shape_factor(body.inertia, body.mass, lengths)
        if factor is None:
            continue
        for wrong in CONFUSED[factor]:
            used = wrong * body.inertia / factor
            bodies = list(model.bodies)
            bodies[index] = dataclasses.replace(body, inertia=used)
            feedback = WRONG_SHAPE.format(
                body=_called(body),
                wrong=SHAPES[wrong],
                used=typeset.latex(used),
                right=typeset.latex(body.inertia),
            )
            yield dataclasses.replace(model, bodies=tuple(bodies)), feedback


def geometric_symbols(model: Model) -> set[sympy.Symbol]:
    """The symbols the bodies' positions, the constraints and friction's contact points are written in
    (a skidding ball's radius is only where it touches the floor)."""
    found: set[sympy.Symbol] = set()
    for body in model.bodies:
        for _, expr in body.position:
            found |= expr.free_symbols
    for constraint in model.constraints:
        found |= constraint.gap.free_symbols
    for friction in model.frictions:
        for _, offset in friction.contact:
            found |= offset.free_symbols
    return {symbol for symbol in found if isinstance(symbol, sympy.Symbol)}


def shape_factor(inertia: sympy.Expr, mass: sympy.Expr, lengths: set[sympy.Symbol]) -> sympy.Rational | None:
    """The number a standard shape's inertia is made of (½ in M R²/2), when the inertia is that number
    times the body's own mass times the square of one of its lengths; else None."""
    found = _factor_and_length(inertia, mass, lengths)
    return found[0] if found is not None and found[0] in SHAPES else None


def edge_shape(
    inertia: sympy.Expr, mass: sympy.Expr, lengths: set[sympy.Symbol]
) -> tuple[sympy.Rational, sympy.Symbol] | None:
    """The factor (in ABOUT_AN_EDGE) and the length of an inertia that is a shape's about its edge."""
    found = _factor_and_length(inertia, mass, lengths)
    return found if found is not None and found[0] in ABOUT_AN_EDGE else None


def _factor_and_length(
    inertia: sympy.Expr, mass: sympy.Expr, lengths: set[sympy.Symbol]
) -> tuple[sympy.Rational, sympy.Symbol] | None:
    """The inertia as a number times the body's own mass times the square of one of its lengths."""
    if not isinstance(mass, sympy.Symbol) or inertia == 0:
        return None
    factor, rest = inertia.as_coeff_Mul()
    base, power = (rest / mass).as_base_exp()
    if (
        isinstance(factor, sympy.Rational)
        and power == 2
        and isinstance(base, sympy.Symbol)
        and base in lengths
    ):
        return factor, base
    return None


def _called(body: Body) -> str:
    """`the wheel` where the author named it in words; else by its mass (a name an element made, such
    as `stringWheel`, is no word a student reads)."""
    if body.name.isalpha() and body.name.islower():
        return f"the {body.name}"
    return f"the body of mass ${typeset.latex(body.mass)}$"
