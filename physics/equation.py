"""Grading an equation a student writes (`m a = m g sin θ − μ N`): right when the difference of its
sides is a nonzero multiple of the asked equation's, on the domain, with the unknowns (N, T, a …) free.

The unknowns are sampled as free values (`physics.proportional`'s state): `m a − m g sin θ + μ N` and
`2 m g sin θ − 2 μ N − 2 m a` are the same equation, `m a = m g sin θ` is not. Where the model gives
each unknown's value, an equation that is not the one asked but holds once they are put in is told so
(a different body or component, a combination of equations), and so is the asked equation with one
unknown replaced by its value; a wrong one is compared with the asked equation's own wrong versions:
each term left out, each term's sign flipped, sine and cosine swapped. An answer that is none of those
and whose sides or terms differ in dimension is told that before anything else (the unknowns'
dimensions are those of their values).
"""

from __future__ import annotations

import contextlib
from collections.abc import Mapping
from dataclasses import dataclass
from functools import cached_property

import numpy as np
import sympy

from physics import typeset
from physics.characters import without_math_delimiters
from physics.dimensions import Dimension, describe
from physics.errors import AnswerError, ParseError
from physics.mathinput import InputLimits, parse_math
from physics.proportional import Sample, close, factor_text, matched
from physics.symbolic import SymbolicContext
from physics.symbolic.dimensional import DimensionMismatch, UnknownDimension, expression_dimension
from physics.symbolic.floats import Floats
from physics.verdict import InputProblem, Judgement, Preview, ReadAs, Reason, Verdict


@dataclass(frozen=True)
class Unknown:
    """A name the student may use beyond the problem's symbols, what it means, and (where the model
    gives it) its value in the problem's symbols."""

    name: str
    symbol: sympy.Symbol
    meaning: str = ""
    value: sympy.Expr | None = None


@dataclass(frozen=True)
class WrongEquation:
    difference: sympy.Expr  # lhs − rhs of the wrong equation
    feedback: str


@dataclass(frozen=True)
class ReadEquation:
    lhs: sympy.Expr
    rhs: sympy.Expr
    read_as: ReadAs


def read_equation(
    text: str, names: Mapping[str, sympy.Symbol], limits: InputLimits | None = None
) -> ReadEquation:
    """`lhs = rhs`, each side read by the whitelist parser; AnswerError with a position in `text`."""
    limits = limits or InputLimits()
    if len(text) > limits.max_length:
        parse_math(text, names, limits=limits)  # raises the reader's own TooLarge
    text = without_math_delimiters(text)  # `$ma = mg\sin\theta$`, before the sides are split apart
    sign = text.find("=")
    if sign < 0:
        raise ParseError(
            "Write an equation, with '=' between its two sides (as in m a = m g sin θ).", len(text)
        )
    if "=" in text[sign + 1 :]:
        raise ParseError("Write one equation, with one '='.", text.find("=", sign + 1))
    left, right = text[:sign], text[sign + 1 :]
    if not left.strip():
        raise ParseError("The left side of the equation is empty.", sign)
    if not right.strip():
        raise ParseError("The right side of the equation is empty.", sign)
    lhs = parse_math(left, names, limits=limits)
    try:
        rhs = parse_math(right, names, limits=limits)
    except AnswerError as error:
        if error.position is not None:
            error.position += sign + 1
        raise
    read_as = ReadAs(
        f"{lhs.read_as.text} = {rhs.read_as.text}",
        f"{lhs.read_as.latex} = {rhs.read_as.latex}",
        "; ".join(n for n in (lhs.read_as.note, rhs.read_as.note) if n) or None,
    )
    return ReadEquation(lhs.expr, rhs.expr, read_as)


def _terms(expr: sympy.Expr) -> tuple[sympy.Expr, ...]:
    return tuple(sympy.Add.make_args(sympy.expand(expr)))


def standard_wrong(
    lhs: sympy.Expr, rhs: sympy.Expr, unknowns: tuple[Unknown, ...]
) -> tuple[WrongEquation, ...]:
    """The asked equation's own wrong versions: a term left out, a term's sign flipped, sin and cos
    swapped (the wrong component)."""
    difference = sympy.expand(lhs - rhs)
    found: list[WrongEquation] = []
    for term in _terms(difference):
        found.append(WrongEquation(difference - term, f"A term is missing: {_named(term, unknowns)}."))
        found.append(WrongEquation(difference - 2 * term, f"The sign of {_named(term, unknowns)} is wrong."))
    for term in _terms(difference):
        turned = _swapped(term)
        if turned != term:
            found.append(
                WrongEquation(
                    difference - term + turned,
                    f"{_named(term, unknowns)} is the wrong component: sine and cosine swapped.",
                )
            )
    swapped = _swapped(difference)
    if swapped != difference:
        found.append(
            WrongEquation(
                swapped,
                "Sine and cosine are swapped: that is the other component. Along an incline of angle θ "
                "gravity's component is $m g \\sin\\theta$, across it $m g \\cos\\theta$.",
            )
        )
    return tuple(found)


def _swapped(expr: sympy.Expr) -> sympy.Expr:
    """sin ↔ cos throughout: the other component."""
    return expr.xreplace(
        {
            f: (sympy.cos(f.args[0]) if f.func is sympy.sin else sympy.sin(f.args[0]))
            for f in expr.atoms(sympy.sin, sympy.cos)
        }
    )


def _named(term: sympy.Expr, unknowns: tuple[Unknown, ...]) -> str:
    """`$\\mu N$` (the normal force …)."""
    said = [u.meaning for u in unknowns if term.has(u.symbol) and u.meaning]
    tex = typeset.latex(-term if term.could_extract_minus_sign() else term)
    return f"${tex}$" + (f" ({'; '.join(said)})" if said else "")


@dataclass(frozen=True)
class EquationQuestion:
    names: Mapping[str, sympy.Symbol]  # the problem's symbols and the unknowns
    unknowns: tuple[Unknown, ...]
    lhs: sympy.Expr  # the asked equation, as the author states it
    rhs: sympy.Expr
    context: SymbolicContext  # the parameters' and the unknowns' domain
    wrong: tuple[WrongEquation, ...] = ()
    asked: str = ""  # what the part asks for, in words, for "holds but is not the one asked"

    @property
    def difference(self) -> sympy.Expr:
        return self.lhs - self.rhs

    @cached_property
    def sample(self) -> Sample:
        return Sample(self.context, tuple(u.symbol for u in self.unknowns), self.difference)

    def _both(self, expr: sympy.Expr) -> tuple[Floats, Floats]:
        return self.sample.values(expr), self.sample.values(expr, rolled=True)

    @cached_property
    def _target(self) -> tuple[Floats, Floats]:
        return self._both(self.difference)

    @cached_property
    def _wrong(self) -> tuple[tuple[tuple[Floats, Floats], str], ...]:
        return tuple((self._both(w.difference), w.feedback) for w in self.wrong)

    @cached_property
    def _values(self) -> dict[sympy.Symbol, sympy.Expr]:
        return {u.symbol: u.value for u in self.unknowns if u.value is not None}

    @cached_property
    def _values_put_in(self) -> tuple[tuple[tuple[Floats, Floats], Unknown], ...]:
        """The asked equation with one unknown replaced by the value the model gives it (T by m g k²/(k²
        + r²)), where another unknown is left: a student who solved for it first writes that."""
        found = []
        for unknown in self.unknowns:
            if unknown.value is None or unknown.symbol not in self.difference.free_symbols:
                continue
            put_in = self.difference.xreplace({unknown.symbol: unknown.value})
            if not put_in.free_symbols & {u.symbol for u in self.unknowns}:
                continue  # nothing asked is left: it would hold for every answer that holds
            found.append((self._both(put_in), unknown))
        return tuple(found)

    @cached_property
    def _dimensions(self) -> dict[sympy.Symbol, Dimension]:
        """The problem's symbols' dimensions, and each unknown's where the model gives its value."""
        found = {symbol: spec.dimension for symbol, spec in self.context.symbols.items() if spec.dimension}
        for unknown in self.unknowns:
            # a value without symbols (0 where nothing accelerates) says nothing of its dimension
            if unknown.value is not None and unknown.value.free_symbols:
                with contextlib.suppress(DimensionMismatch, UnknownDimension):
                    found[unknown.symbol] = expression_dimension(unknown.value, found)
        return found

    def _dimension_fault(self, lhs: sympy.Expr, rhs: sympy.Expr) -> str | None:
        """Why the equation cannot hold whatever the values: its sides differ in dimension, or one adds
        unlike quantities (m a = m g - T/m). None where it is consistent, or a name's dimension unknown."""
        dims = self._dimensions
        sides = []
        for side, expr in (("left", lhs), ("right", rhs)):
            try:
                sides.append(expression_dimension(expr, dims))
            except UnknownDimension:
                return None
            except DimensionMismatch as mismatch:
                return (
                    f"The {side} side of your equation {mismatch.message}: each of its terms must be the "
                    "same kind of quantity."
                )
        left, right = sides
        if left == right:
            return None
        return (
            f"The two sides of your equation differ in dimension: the left is {describe(left)}, the right "
            f"{describe(right)}, so it cannot hold."
        )

    def prepare(self) -> EquationQuestion:
        self._target  # noqa: B018
        self._wrong  # noqa: B018
        self._values_put_in  # noqa: B018
        self._dimensions  # noqa: B018
        return self

    def _proportional(
        self, found: tuple[Floats, Floats], target: tuple[Floats, Floats]
    ) -> tuple[bool, float | None]:
        m = matched([found[0]], [target[0]], [found[1]], [target[1]])
        return m.proportional, m.factor

    def _holds(self, lhs: sympy.Expr, rhs: sympy.Expr) -> bool:
        """With every unknown the model gives put in (and only then), whether the equation holds."""
        values = self._values
        if not values or any(s in (lhs - rhs).free_symbols for s in self._free_unknowns):
            return False
        left = self.sample.values(lhs.xreplace(values))
        right = self.sample.values(rhs.xreplace(values))
        scale = float(np.nanmedian(np.abs(left))) if np.isfinite(left).any() else 1.0
        return bool(np.all(close(left, right, scale)))

    @cached_property
    def _free_unknowns(self) -> tuple[sympy.Symbol, ...]:
        return tuple(u.symbol for u in self.unknowns if u.value is None)

    def judge(self, lhs: sympy.Expr, rhs: sympy.Expr) -> Judgement:
        found = self._both(lhs - rhs)
        right, factor = self._proportional(found, self._target)
        if right:
            if factor is not None and abs(factor - 1) <= 1e-9:
                return Judgement(True, Reason.EQUIVALENT, "Correct.")
            return Judgement(
                True,
                Reason.EQUIVALENT,
                f"Correct (the same equation, multiplied by {factor_text(factor)} or with its terms moved).",
            )
        for values, feedback in self._wrong:
            if self._proportional(found, values)[0]:
                return Judgement(False, Reason.KNOWN_MISTAKE, feedback)
        fault = self._dimension_fault(lhs, rhs)
        if fault is not None:
            return Judgement(False, Reason.WRONG_DIMENSION, fault)
        for values, unknown in self._values_put_in:
            if self._proportional(found, values)[0]:
                said = f" ({unknown.meaning})" if unknown.meaning else ""
                return Judgement(
                    False,
                    Reason.WRONG_VALUE,
                    f"This is the equation asked with ${typeset.latex(unknown.symbol)}${said} replaced by its "
                    f"value: write ${typeset.latex(unknown.symbol)}$ itself, as the question asks.",
                )
        if self._holds(lhs, rhs):
            return Judgement(
                False,
                Reason.WRONG_VALUE,
                "This equation holds, but it is not the one asked"
                + (f" ({self.asked})" if self.asked else "")
                + ": it is for a different body or direction, or a combination of equations.",
            )
        return Judgement(
            False,
            Reason.WRONG_VALUE,
            self._terms_differ(lhs - rhs)
            or "This is not the equation asked"
            + (f" ({self.asked})" if self.asked else "")
            + ": check that every force on the body is there, each with its component along the direction "
            "asked and its sign.",
        )

    def _terms_differ(self, difference: sympy.Expr) -> str | None:
        """ "m a = m g sin θ − N" for "m a = m g sin θ − m A cos θ": the terms missing, extra or of the
        wrong sign, when a few terms are all that differ (comparing as typed, or with the sides swapped)."""
        asked = sympy.expand(self.difference)
        theirs = sympy.expand(difference)
        residual = min(
            (sympy.expand(theirs - asked), sympy.expand(theirs + asked)),
            key=lambda r: len(sympy.Add.make_args(r)),
        )
        terms = sympy.Add.make_args(residual)
        if residual == 0 or len(terms) > 3:
            return None
        own = set(_terms(asked)) | {-t for t in _terms(asked)}
        said = []
        for term in terms:
            if term in own:
                said.append(f"{_named(term, self.unknowns)} is missing")
            elif term / 2 in own:
                said.append(f"the sign of {_named(term / 2, self.unknowns)} is wrong")
            else:
                said.append(f"{_named(term, self.unknowns)} does not belong in it")
        return "Compared with the equation asked, " + "; ".join(said) + "."

    def grade(self, answer: str, limits: InputLimits) -> Verdict:
        try:
            read = read_equation(answer, self.names, limits)
        except AnswerError as error:
            return Verdict.invalid(error)
        return Verdict.graded(self.judge(read.lhs, read.rhs), read.read_as)

    def read(self, answer: str, limits: InputLimits) -> Preview:
        try:
            read = read_equation(answer, self.names, limits)
        except AnswerError as error:
            return Preview(None, InputProblem(error.message, error.position))
        return Preview(read.read_as, None)
