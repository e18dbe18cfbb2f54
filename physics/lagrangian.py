"""Grading a Lagrangian, a kinetic energy or a potential energy typed in a model's coordinates and their
velocities (`x'`, `ẋ`, `\\dot{x}`, `dx/dt`, `xdot`).

A Lagrangian is right when its Euler–Lagrange equations are the model's up to one nonzero constant factor
(so c·L and L plus a total time derivative are right too); an energy when its derivatives with respect
to every coordinate and velocity are the model's (so it is right up to an additive constant). Both are
decided at the domain's sample points (`physics.proportional`): the student's expression is
differentiated by sympy (it was read by the whitelist parser, never evaluated as text), the equations
evaluated, compared. A wrong answer is compared with the model's own wrong versions (V added, a body's
kinetic energy left out, velocities treated as independent), each with what to tell the student, and
otherwise told which equation of motion (or which dependence) differs.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from enum import StrEnum
from fractions import Fraction
from functools import cached_property

import sympy

from physics import typeset
from physics.dimensions import DIMENSIONLESS, Dimension
from physics.errors import AnswerError
from physics.mathinput import InputLimits, parse_math
from physics.proportional import Sample, factor_text, matched
from physics.symbolic import SymbolicContext
from physics.symbolic.dimensional import DimensionMismatch, UnknownDimension, expression_dimension
from physics.symbolic.floats import Floats
from physics.verdict import InputProblem, Judgement, Preview, Reason, Verdict


class Asked(StrEnum):
    LAGRANGIAN = "lagrangian"
    KINETIC = "kinetic_energy"
    POTENTIAL = "potential_energy"


ASKED_WORDS = {
    Asked.LAGRANGIAN: "Lagrangian",
    Asked.KINETIC: "kinetic energy",
    Asked.POTENTIAL: "potential energy",
}


@dataclass(frozen=True)
class Coordinate:
    """A generalized coordinate as a student types it: `name`, and `name_dot` (or x', ẋ …) its velocity."""

    name: str
    symbol: sympy.Symbol
    velocity: sympy.Symbol
    acceleration: sympy.Symbol
    words: str = ""  # what it measures, e.g. "the wedge's position along the floor"

    @property
    def velocity_name(self) -> str:
        return f"{self.name}_dot"

    def named(self) -> str:
        """`X` (the wedge's position …), for feedback."""
        return f"${typeset.latex(self.symbol)}$" + (f" ({self.words})" if self.words else "")


@dataclass(frozen=True)
class Alternative:
    """A wrong answer the model knows of (in the coordinates), and what to tell a student who gives it."""

    expr: sympy.Expr
    feedback: str


def time_derivative(expr: sympy.Expr, coordinates: Sequence[Coordinate]) -> sympy.Expr:
    """d/dt of an expression in the coordinates and their velocities (the chain rule over them)."""
    return sympy.Add(
        *(
            sympy.diff(expr, c.symbol) * c.velocity + sympy.diff(expr, c.velocity) * c.acceleration
            for c in coordinates
        )
    )


def euler_lagrange(lagrangian: sympy.Expr, coordinates: Sequence[Coordinate]) -> tuple[sympy.Expr, ...]:
    """d/dt ∂L/∂q' − ∂L/∂q for each coordinate q (each = 0 is its equation of motion)."""
    return tuple(
        time_derivative(sympy.diff(lagrangian, c.velocity), coordinates) - sympy.diff(lagrangian, c.symbol)
        for c in coordinates
    )


def gradient(energy: sympy.Expr, coordinates: Sequence[Coordinate]) -> tuple[sympy.Expr, ...]:
    """∂E/∂q for each coordinate, then ∂E/∂q' for each velocity."""
    return tuple(sympy.diff(energy, c.symbol) for c in coordinates) + tuple(
        sympy.diff(energy, c.velocity) for c in coordinates
    )


def state_symbols(coordinates: Sequence[Coordinate]) -> tuple[sympy.Symbol, ...]:
    return tuple(s for c in coordinates for s in (c.symbol, c.velocity, c.acceleration))


ENERGY = Dimension({"mass": 1, "length": 2, "time": -2})
_TIME = Dimension({"time": 1})
# Functions whose argument is a pure number: a coordinate inside one (cos θ) is an angle or a ratio.
_PURE_ARGUMENT = (sympy.sin, sympy.cos, sympy.tan, sympy.cot, sympy.sec, sympy.csc, sympy.exp, sympy.log)


def state_dimensions(
    expected: sympy.Expr, coordinates: Sequence[Coordinate], known: Mapping[sympy.Symbol, Dimension]
) -> dict[sympy.Symbol, Dimension] | None:
    """The dimensions of the parameters (`known`), and of each coordinate and its velocity as the model's
    energy `expected` implies them (a term ½ (M+m) Ẋ² makes X a length; a coordinate inside cos is a
    pure number); None where a coordinate's cannot be told."""
    found = dict(known)
    pending = list(coordinates)
    terms = sympy.Add.make_args(sympy.expand(expected))
    while pending:
        solved = next(
            ((c, d) for c in pending for t in terms if (d := _coordinate_dimension(t, c, found)) is not None),
            None,
        )
        if solved is None:
            return None
        coordinate, dimension = solved
        found[coordinate.symbol] = dimension
        found[coordinate.velocity] = dimension / _TIME
        pending.remove(coordinate)
    try:  # what the model's energy itself must satisfy, or no answer is held to it
        consistent = expression_dimension(expected, found) == ENERGY
    except (UnknownDimension, DimensionMismatch):
        consistent = False
    return found if consistent else None


def _coordinate_dimension(
    term: sympy.Expr, coordinate: Coordinate, found: Mapping[sympy.Symbol, Dimension]
) -> Dimension | None:
    """What `coordinate`'s dimension must be for `term` to be an energy, if the term tells."""
    power = 0  # of the coordinate and its velocity together, as factors
    rate = 0  # of the velocity: each brings 1/time
    rest = sympy.Integer(1)
    inside = False  # the coordinate inside a function, whose argument is a pure number
    for factor, exponent in term.as_powers_dict().items():
        if factor in (coordinate.symbol, coordinate.velocity) and exponent.is_Integer:
            power += int(exponent)
            rate += int(exponent) if factor == coordinate.velocity else 0
        elif factor.has(coordinate.symbol, coordinate.velocity):
            if not isinstance(factor, _PURE_ARGUMENT):  # √(x² + L²), |x|: the term does not tell
                return None
            inside = True
        else:
            rest *= factor**exponent
    try:
        others = expression_dimension(rest, found)
    except (UnknownDimension, DimensionMismatch):
        return None
    if inside and power == 0:
        return DIMENSIONLESS
    if power == 0:
        return None
    return (ENERGY / others * _TIME**rate) ** Fraction(1, power)


def velocity_names(coordinates: Sequence[Coordinate]) -> dict[str, sympy.Symbol]:
    """What a student may type for the coordinates and their velocities."""
    names: dict[str, sympy.Symbol] = {}
    for c in coordinates:
        names[c.name] = c.symbol
        names[c.velocity_name] = c.velocity
    return names


def dotted_latex(expr: sympy.Expr, coordinates: Sequence[Coordinate]) -> str:
    """TeX with each velocity written with its dot."""
    names = {c.velocity: rf"\dot{{{typeset.latex(c.symbol)}}}" for c in coordinates}
    return str(typeset.latex(expr, symbol_names=names))


@dataclass(frozen=True)
class _Values:
    base: tuple[Floats, ...]
    rolled: tuple[Floats, ...]


@dataclass(frozen=True)
class EnergyQuestion:
    """A Lagrangian or an energy to grade against the model's."""

    asked: Asked
    names: Mapping[str, sympy.Symbol]  # what the answer may use: parameters, coordinates, velocities
    coordinates: tuple[Coordinate, ...]
    expected: sympy.Expr  # T − V, T or V
    context: SymbolicContext  # the parameters' and the state's domain
    alternatives: tuple[Alternative, ...] = ()
    # Every parameter's, coordinate's and velocity's dimension, where all are known: a wrong answer whose
    # terms differ in dimension is told so.
    dimensions: Mapping[sympy.Symbol, Dimension] | None = None

    @property
    def _lagrangian(self) -> bool:
        return self.asked is Asked.LAGRANGIAN

    def components(self, expr: sympy.Expr) -> tuple[sympy.Expr, ...]:
        return (
            euler_lagrange(expr, self.coordinates) if self._lagrangian else gradient(expr, self.coordinates)
        )

    @cached_property
    def sample(self) -> Sample:
        return Sample(self.context, state_symbols(self.coordinates), self.expected)

    def _values(self, expr: sympy.Expr) -> _Values:
        parts = self.components(expr)
        return _Values(
            tuple(self.sample.values(p) for p in parts),
            tuple(self.sample.values(p, rolled=True) for p in parts),
        )

    @cached_property
    def _target(self) -> _Values:
        return self._values(self.expected)

    @cached_property
    def _wrong(self) -> tuple[tuple[_Values, str], ...]:
        return tuple((self._values(alt.expr), alt.feedback) for alt in self.alternatives)

    def prepare(self) -> EnergyQuestion:
        """Everything computed now (before the question is pickled for workers)."""
        self._target  # noqa: B018
        self._wrong  # noqa: B018
        return self

    def _matches(self, found: _Values, target: _Values, fixed: bool) -> tuple[bool, float | None]:
        m = matched(found.base, target.base, found.rolled, target.rolled, fixed=fixed)
        return m.proportional, m.factor

    def _mixed_dimensions(self, expr: sympy.Expr) -> str | None:
        """Why an answer is no energy at all, where its terms have different dimensions (`g s sin θ`
        beside `½ m ṡ²`: a mass left out; `m g` added to a right one, a force); None where they agree or
        cannot be told. (A right answer may be scaled, `L/m`, as the equations of motion allow.)"""
        if self.dimensions is None:
            return None
        try:
            expression_dimension(expr, self.dimensions)
        except DimensionMismatch as mismatch:
            return f"{mismatch.message}: each of its terms must be an energy."
        except UnknownDimension:
            pass
        return None

    def judge(self, expr: sympy.Expr) -> Judgement:
        found = self._values(expr)
        words = ASKED_WORDS[self.asked]
        right, factor = self._matches(found, self._target, fixed=not self._lagrangian)
        mixed = self._mixed_dimensions(expr)
        if right and mixed is not None:  # `L + m g`: a force added, which no derivative sees
            return Judgement(
                False,
                Reason.WRONG_DIMENSION,
                f"Your {words} has the model's derivatives, but it {mixed}",
            )
        if right:
            if factor is not None and abs(factor - 1) <= 1e-9:
                return Judgement(True, Reason.EQUIVALENT, "Correct.")
            return Judgement(
                True,
                Reason.EQUIVALENT,
                f"Correct: your Lagrangian is {factor_text(factor)} times $T - V$ (up to a total time "
                "derivative), which gives the same equations of motion.",
            )
        for values, feedback in self._wrong:
            if self._matches(found, values, fixed=not self._lagrangian)[0]:
                return Judgement(False, Reason.KNOWN_MISTAKE, feedback)
        if not self._lagrangian:
            scaled, factor = self._matches(found, self._target, fixed=False)
            if scaled and factor is not None and abs(factor + 1) <= 1e-9:
                return Judgement(
                    False, Reason.SIGN_ERROR, f"Your {words} has the opposite sign of the model's."
                )
            if scaled and factor is not None:  # a number: a factor that varies with θ is a different energy
                return Judgement(
                    False,
                    Reason.CONSTANT_FACTOR,
                    f"Your {words} is {factor_text(factor)} times the model's: check its factors"
                    + (" (½ m v², ½ I ω²)." if self.asked is Asked.KINETIC else "."),
                )
        if mixed is not None:
            return Judgement(False, Reason.WRONG_DIMENSION, f"Your {words} {mixed}")
        return Judgement(False, Reason.WRONG_VALUE, self._what_differs(found))

    def _what_differs(self, found: _Values) -> str:
        coordinates = self.coordinates
        failing = [
            k
            for k in range(len(found.base))
            if not matched(
                [found.base[k]],
                [self._target.base[k]],
                [found.rolled[k]],
                [self._target.rolled[k]],
                fixed=not self._lagrangian,
            ).proportional
        ]
        if self._lagrangian:
            if matched(found.base, self._target.base).factor == 0.0:
                return (
                    "Your Lagrangian gives no equation of motion at all (it is a constant or a total time "
                    "derivative): $L = T - V$, with $T$ the kinetic energy of every moving body."
                )
            if len(failing) == len(coordinates) and len(coordinates) > 1:
                return (
                    "None of the equations of motion your Lagrangian gives is the model's: $L = T - V$, with "
                    "$T$ the kinetic energy of every moving body (its velocity measured in an inertial "
                    "frame) and $V$ the potential energy."
                )
            which = " and ".join(coordinates[k].named() for k in failing) or "the coordinates"
            if len(failing) < len(coordinates):
                return (
                    f"Lagrange's equation for {which} from your Lagrangian is not the model's (the other "
                    "equations agree up to the same factor): look again at the terms with that coordinate "
                    "and its velocity."
                )
            return f"Lagrange's equation for {which} from your Lagrangian is not the model's."
        n = len(coordinates)
        names = [f"${typeset.latex(c.symbol)}$" for c in coordinates] + [
            rf"$\dot{{{typeset.latex(c.symbol)}}}$" for c in coordinates
        ]
        differ = ", ".join(names[k] for k in failing if k < 2 * n) or "the coordinates"
        return f"Your {ASKED_WORDS[self.asked]} depends on {differ} differently from the model's."

    def grade(self, answer: str, limits: InputLimits) -> Verdict:
        try:
            parsed = parse_math(answer, self.names, limits=limits, velocities=True)
        except AnswerError as error:
            return Verdict.invalid(error)
        return Verdict.graded(self.judge(parsed.expr), parsed.read_as)

    def read(self, answer: str, limits: InputLimits) -> Preview:
        try:
            parsed = parse_math(answer, self.names, limits=limits, velocities=True)
        except AnswerError as error:
            return Preview(None, InputProblem(error.message, error.position))
        return Preview(parsed.read_as, None)


def standard_alternatives(
    asked: Asked,
    kinetic: sympy.Expr,
    potential: sympy.Expr,
    coordinates: Sequence[Coordinate],
    terms: Sequence[tuple[str, sympy.Expr]] = (),
) -> tuple[Alternative, ...]:
    """The wrong answers a model implies: for a Lagrangian V added, V or T left out; for a Lagrangian or
    a kinetic energy, a body's kinetic energy (`terms`: words, term) left out, a body's velocity taken
    along one coordinate alone, the cross terms of velocities dropped."""
    found: list[Alternative] = []
    lagrangian = asked is Asked.LAGRANGIAN
    base = kinetic - potential if lagrangian else kinetic
    if asked is Asked.POTENTIAL:
        return ()
    if lagrangian and potential != 0:
        found.append(Alternative(kinetic + potential, "$V$ is added instead of subtracted: $L = T - V$."))
        found.append(Alternative(kinetic, "The potential energy is missing: $L = T - V$."))
    if lagrangian:
        found.append(Alternative(-potential, "The kinetic energy is missing: $L = T - V$."))
    if len(terms) > 1:
        for words, term in terms:
            found.append(
                Alternative(
                    base - term,
                    f"The kinetic energy of {words} is missing: ${dotted_latex(term, coordinates)}$.",
                )
            )
    velocities = [c.velocity for c in coordinates]
    for words, term in terms:
        moving = [c for c in coordinates if term.has(c.velocity)]
        if len(moving) < 2:
            continue
        for alone in moving:
            kept = term.subs({c.velocity: 0 for c in moving if c is not alone})
            if kept != 0:
                found.append(
                    Alternative(
                        base - term + kept,
                        f"The kinetic energy of {words} uses $\\dot{{{typeset.latex(alone.symbol)}}}$ alone: "
                        "its velocity depends on "
                        + " and ".join(
                            f"$\\dot{{{typeset.latex(c.symbol)}}}$" for c in moving if c is not alone
                        )
                        + " too (add the velocities as vectors, then square).",
                    )
                )
    expanded = sympy.expand(kinetic)
    cross = sympy.Add(
        *(t for t in sympy.Add.make_args(expanded) if sum(1 for v in velocities if t.has(v)) > 1)
    )
    if cross != 0:
        found.append(
            Alternative(
                base - cross,
                "The velocities are treated as independent: the cross term "
                f"${dotted_latex(cross, coordinates)}$ of the kinetic energy is missing (a body's velocity is "
                "the vector sum of its velocity relative to another body and that body's velocity).",
            )
        )
    return tuple(found)
