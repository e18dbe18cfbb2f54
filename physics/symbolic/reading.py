"""Reading a symbolic answer, with an ambiguous grouping settled by dimension where only one reading
fits.

`A e^-ωt` is A·e^(−ω)·t or A·e^(−ωt), and `2π√m/k` 2π·√m/k or 2π·√(m/k). The math reader refuses
them; here, when every symbol of the answer has a declared dimension and exactly one reading has the
dimension the answer must have (a displacement: A·e^(−ωt), since exp of a rate has none), that reading
is taken and `read_as.note` says so. Where several or none fit, or a dimension is unknown, the refusal
stands: the student must add parentheses. A `/` followed by an unparenthesised product (`p^2/2m`,
`m v/q B`) is never settled: the contract (API.md) refuses it whatever the dimensions. Its readings are
tried only to settle another grouping: `A e^-t/τ cos ωt` is A·e^(−t/τ)·cos(ωt), since with e^(−t) it
has no dimension however τ cos ωt is grouped; a reading that fits only with the division read one way
is refused with the division's question. Wherever the dimensions cannot decide, a division's question is
asked before any other grouping's.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Mapping, Sequence

import sympy

from physics.dimensions import Dimension, describe
from physics.errors import AmbiguousDivision, AmbiguousGrouping, AnswerError
from physics.mathinput import InputLimits, ParsedMath, parse_math
from physics.mathinput.render import in_student_style
from physics.symbolic.dimensional import DimensionMismatch, UnknownDimension, expression_dimension

# Ambiguous groupings one answer may have settled (a division's choices are not counted: it is never
# settled, and each reading tries one division's readings at most): 2^3 · 4 readings at most are parsed.
MAX_SETTLED = 3
# Parses spent looking past other groupings for a division to ask about, where dimensions cannot decide.
_MAX_LOOKED_PAST = 2**MAX_SETTLED


class _Undecidable(Exception):
    """The dimensions cannot settle the answer's groupings: a symbol has none, or there are too many."""


def read_symbolic_answer(
    text: str,
    names: Mapping[str, sympy.Symbol],
    limits: InputLimits,
    dimensions: Mapping[str, Dimension],
    expected: Dimension | None,
    *,
    powers_outside: bool = False,
) -> ParsedMath:
    """`parse_math`, except that an ambiguous grouping is settled by `expected` when exactly one
    reading has it (`dimensions`: each symbol's dimension, by name). Raises what parse_math raises.
    `powers_outside` reads `sin θ^2` as (sin θ)², as parse_math does."""
    try:
        parsed = parse_math(text, names, limits=limits, powers_outside=powers_outside)
        if parsed.long_words and expected is not None and not _has(parsed.expr, dimensions, expected):
            return shorter_arguments(text, names, limits, dimensions, expected, parsed)
        return parsed
    except AmbiguousGrouping as refused:
        if expected is None:
            raise _question(text, names, limits, powers_outside, refused) from None
        try:
            chosen_readings = _readings(text, names, limits, {}, None, powers_outside)
            fitting_readings = [t for t in chosen_readings if _fits(t[1].expr, dimensions, expected)]
        except _Undecidable:
            raise _question(text, names, limits, powers_outside, refused) from None
        divisions = [d for _, _, d in fitting_readings or chosen_readings if d is not None]
        if divisions:  # it fits (or may) only with a division read one way: the contract refuses it
            raise divisions[0] from None
        fitting_choices = [(c, r) for c, r, _ in fitting_readings]
        fitting = [r for _, r in fitting_choices]
        if len(fitting) > 1:
            refused = _open_question(text, names, limits, powers_outside, fitting_choices, refused)
            raise AmbiguousGrouping(
                f"{refused.message} {'Both readings' if len(fitting) == 2 else 'Each of these'} are "
                f"{describe(expected)}, so the dimensions cannot decide.",
                refused.position,
                refused.readings,
            ) from None
        if not fitting:
            raise refused from None
        chosen = fitting[0]
        note = (
            f"Read as {in_student_style(chosen.read_as.text)}: the only reading that is {describe(expected)}"
        )
        if chosen.read_as.note is not None:  # how a bare function argument with a power was read
            note = f"{note}. {chosen.read_as.note}"
        return dataclasses.replace(chosen, read_as=dataclasses.replace(chosen.read_as, note=note))


# Readings of glued function arguments tried for one answer (each a parse).
_MAX_SHORTER = 6


def shorter_arguments(
    text: str,
    names: Mapping[str, sympy.Symbol],
    limits: InputLimits,
    dimensions: Mapping[str, Dimension],
    expected: Dimension,
    parsed: ParsedMath,
) -> ParsedMath:
    """`sinθmgL` is sin(θ·m·g·L) by the rule that a function takes the word typed on after it (`cos ωt`),
    and so has no dimension: where ending a word earlier (sin(θ)·m·g·L) gives the only reading with the
    expected dimension, that one is taken and said, as a grouping settled by dimension is. `parsed` as it
    is otherwise. A shorter word can have another dimension only where the longer one had none."""
    found: dict[str, ParsedMath] = {}
    tries = 0
    for position, factors in parsed.long_words:
        for ends in range(factors - 1, 0, -1):
            tries += 1
            if tries > _MAX_SHORTER:
                break
            try:
                other = parse_math(text, names, limits=limits, word_ends={position: ends})
            except AnswerError:
                continue
            if _has(other.expr, dimensions, expected):
                found.setdefault(other.read_as.text, other)
    if len(found) != 1:
        return parsed
    chosen = next(iter(found.values()))
    note = f"Read as {in_student_style(chosen.read_as.text)}: the only reading that is {describe(expected)}"
    return dataclasses.replace(chosen, read_as=dataclasses.replace(chosen.read_as, note=note))


def _has(expr: sympy.Expr, dimensions: Mapping[str, Dimension], expected: Dimension) -> bool:
    """Whether `expr` has the expected dimension (False where it has none, or a symbol has none)."""
    known = {s: dimensions[s.name] for s in expr.free_symbols if s.name in dimensions}
    try:
        return expression_dimension(expr, known) == expected
    except (DimensionMismatch, UnknownDimension):
        return False


def _open_question(
    text: str,
    names: Mapping[str, sympy.Symbol],
    limits: InputLimits,
    powers_outside: bool,
    fitting: Sequence[tuple[Mapping[int, int], ParsedMath]],
    refused: AmbiguousGrouping,
) -> AmbiguousGrouping:
    """The refusal of a grouping the dimensions left open, where the first refused was settled by them:
    `A e^-ωt sin x/2` asks about sin's reach, not about e's exponent, which only ω·t fits."""
    open_positions = {p for choices, _ in fitting for p in choices if len({c.get(p) for c, _ in fitting}) > 1}
    if not open_positions or refused.position in open_positions:
        return refused
    settled = {p: choice for p, choice in fitting[0][0].items() if p not in open_positions}
    try:
        parse_math(text, names, limits=limits, choices=settled, powers_outside=powers_outside)
    except AmbiguousGrouping as question:
        return question
    return refused


def _question(
    text: str,
    names: Mapping[str, sympy.Symbol],
    limits: InputLimits,
    powers_outside: bool,
    refused: AmbiguousGrouping,
) -> AmbiguousGrouping:
    """The question to ask where the dimensions cannot settle `refused`: a division's, if reading the
    groupings before it as physics means them finds one (`e^2x p^2/2m` asks about p^2/2m, which the
    contract refuses whatever else is settled), else `refused` itself."""
    choices: dict[int, int] = {}
    for _ in range(_MAX_LOOKED_PAST):
        try:
            parse_math(text, names, limits=limits, choices=choices, powers_outside=powers_outside)
        except AmbiguousDivision as division:
            return division
        except AmbiguousGrouping as another:
            if another.position is not None and another.position not in choices:
                choices[another.position] = len(another.readings) - 1
                continue
        except AnswerError:
            pass
        return refused
    return refused


def _readings(
    text: str,
    names: Mapping[str, sympy.Symbol],
    limits: InputLimits,
    choices: dict[int, int],
    division: AmbiguousDivision | None,
    powers_outside: bool,
) -> list[tuple[dict[int, int], ParsedMath, AmbiguousDivision | None]]:
    """Every reading, with the choices that make it and the refusal of the division it reads one way
    (None if it reads none). A reading that meets a second division is refused with the first: it can
    only be asked about. _Undecidable where more groupings than MAX_SETTLED would have to be settled."""
    try:
        parsed = parse_math(text, names, limits=limits, choices=choices, powers_outside=powers_outside)
        return [(choices, parsed, division)]
    except AmbiguousGrouping as another:
        if isinstance(another, AmbiguousDivision):
            if division is not None:
                raise division from None
            if another.partial:
                raise another from None
            division = another
        elif len(choices) - (division is not None) >= MAX_SETTLED:
            raise _Undecidable from None
        if another.position is None or another.position in choices:
            raise _Undecidable from None
        position = another.position
        # The last choice first: it takes the word typed on into the grouping, as physics means it
        # (e^(−bt/2m)), so a division refused in it is asked about in the student's terms.
        return [
            reading
            for choice in reversed(range(len(another.readings)))
            for reading in _readings(
                text, names, limits, {**choices, position: choice}, division, powers_outside
            )
        ]


def _fits(expr: sympy.Expr, dimensions: Mapping[str, Dimension], expected: Dimension) -> bool:
    """Whether `expr` has the expected dimension; _Undecidable where a symbol has none."""
    known = {s: dimensions[s.name] for s in expr.free_symbols if s.name in dimensions}
    try:
        return expression_dimension(expr, known) == expected
    except DimensionMismatch:
        return False
    except UnknownDimension:
        raise _Undecidable from None
