"""Reading a symbolic answer, with an ambiguous grouping settled by dimension where only one reading
fits.

`mv/qB` is (m·v/q)·B or m·v/(q·B), and `A e^-ωt` is A·e^(−ω)·t or A·e^(−ωt). The math reader refuses
them; here, when every symbol of the answer has a declared dimension and exactly one reading has the
dimension the answer must have (a radius: m·v/(q·B); a displacement: A·e^(−ωt), since exp of a rate
has none), that reading is taken and `read_as.note` says so. Where both readings of a division fit, spacing
decides as it does for a function's argument: a space before the next factor ends the divisor
(`12 U0/r ((r0/r)^12 - (r0/r)^6)` is (12·U0/r)·(…)), and the note says so; a divisor glued to what
follows (`a/bc`) is refused. Where neither fits, or a dimension is unknown, the refusal stands: the
student must add parentheses.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Mapping, Sequence

import sympy

from physics.dimensions import Dimension, describe
from physics.errors import AmbiguousGrouping, AnswerError
from physics.mathinput import InputLimits, ParsedMath, parse_math
from physics.mathinput.render import in_student_style
from physics.symbolic.dimensional import DimensionMismatch, UnknownDimension, expression_dimension

# Ambiguous groupings one answer may have settled: 2^3 readings at most are parsed.
MAX_SETTLED = 3


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
            raise
        chosen_readings = _readings(text, names, limits, {}, refused, powers_outside)
        fitting_choices = [(c, r) for c, r in chosen_readings if _fits(r.expr, dimensions, expected, refused)]
        fitting = [r for _, r in fitting_choices]
        if len(fitting) > 1:
            spaced = _spaced_reading(text, names, limits, powers_outside, fitting, expected)
            if spaced is not None:
                return spaced
            refused = _open_question(text, names, limits, powers_outside, fitting_choices, refused)
            raise AmbiguousGrouping(
                f"{_asked(refused, fitting_choices)} {'Both readings' if len(fitting) == 2 else 'Each of these'} are "
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
    `√2gh/(1+I/mr²)` asks about the root's reach, not about I/(m·r²), the only pure number to add to 1."""
    open_positions = {p for choices, _ in fitting for p in choices if len({c.get(p) for c, _ in fitting}) > 1}
    if not open_positions or refused.position in open_positions:
        return refused
    settled = {p: choice for p, choice in fitting[0][0].items() if p not in open_positions}
    try:
        parse_math(text, names, limits=limits, choices=settled, powers_outside=powers_outside)
    except AmbiguousGrouping as question:
        return question
    return refused


def _asked(refused: AmbiguousGrouping, fitting: Sequence[tuple[Mapping[int, int], ParsedMath]]) -> str:
    """The refusal's question, asking only of the readings that fit where the division had more than
    two (`1/2π √(k/m)`: not 1/(2π·√(k/m)), which is not a frequency)."""
    if len(refused.readings) <= 2 or refused.position is None:
        return refused.message
    taken = sorted({choices[refused.position] for choices, _ in fitting if refused.position in choices})
    if len(taken) < 2:
        return refused.message
    texts = [refused.readings[choice] for choice in taken]
    return f"Did you mean {', '.join(texts[:-1])} or {texts[-1]}? Add parentheses."


def _spaced_reading(
    text: str,
    names: Mapping[str, sympy.Symbol],
    limits: InputLimits,
    powers_outside: bool,
    fitting: list[ParsedMath],
    expected: Dimension,
) -> ParsedMath | None:
    """The one `fitting` reading left when each division with a space after its divisor is read as
    spacing reads it (`a/b c` as (a/b)·c), with a note saying so; None if none or several are left."""
    fits = {r.read_as.text for r in fitting}
    found = [
        (parsed, pairs)
        for parsed, pairs in _by_spacing(text, names, limits, {}, (), powers_outside)
        if parsed.read_as.text in fits
    ]
    if len(found) != 1 or not found[0][1]:
        return None
    chosen, pairs = found[0]
    taken, other = (" and ".join(dict.fromkeys(side)) for side in zip(*pairs, strict=True))
    several = len(set(pairs)) > 1
    note = (
        f"Read as {in_student_style(chosen.read_as.text)}: {'every reading is' if several else 'both readings are'} "
        f"{describe(expected)}, and a space ends the divisor, so it is {taken}; write {other} for the "
        f"other reading{'s' if several else ''}"
    )
    if chosen.read_as.note is not None:
        note = f"{note}. {chosen.read_as.note}"
    return dataclasses.replace(chosen, read_as=dataclasses.replace(chosen.read_as, note=note))


def _by_spacing(
    text: str,
    names: Mapping[str, sympy.Symbol],
    limits: InputLimits,
    choices: dict[int, int],
    pairs: tuple[tuple[str, str], ...],
    powers_outside: bool,
) -> list[tuple[ParsedMath, tuple[tuple[str, str], ...]]]:
    """Every reading with each spaced division read as (a/b)·c, and the (taken, other) readings of those
    divisions; the other groupings both ways, as `_readings` does."""
    try:
        parsed = parse_math(text, names, limits=limits, choices=choices, powers_outside=powers_outside)
        return [(parsed, pairs)]
    except AmbiguousGrouping as grouping:
        position = grouping.position
        if len(choices) >= MAX_SETTLED or position is None or position in choices or grouping.partial:
            return []
        if grouping.spaced:
            taken = ((grouping.readings[0], grouping.readings[1]),)
            return _by_spacing(text, names, limits, {**choices, position: 0}, pairs + taken, powers_outside)
        return [
            reading
            for choice in range(len(grouping.readings))  # a choice for each reading
            for reading in _by_spacing(
                text, names, limits, {**choices, position: choice}, pairs, powers_outside
            )
        ]


def _readings(
    text: str,
    names: Mapping[str, sympy.Symbol],
    limits: InputLimits,
    choices: dict[int, int],
    refused: AmbiguousGrouping,
    powers_outside: bool,
) -> list[tuple[dict[int, int], ParsedMath]]:
    """Every reading, with the choices that make it."""
    try:
        return [
            (choices, parse_math(text, names, limits=limits, choices=choices, powers_outside=powers_outside))
        ]
    except AmbiguousGrouping as another:
        if (
            len(choices) >= MAX_SETTLED
            or another.position is None
            or another.position in choices
            or another.partial
        ):
            raise refused from None
        position = another.position
        return [
            reading
            for choice in range(len(another.readings))  # a choice for each reading
            for reading in _readings(
                text, names, limits, {**choices, position: choice}, refused, powers_outside
            )
        ]


def _fits(
    expr: sympy.Expr, dimensions: Mapping[str, Dimension], expected: Dimension, refused: AmbiguousGrouping
) -> bool:
    known = {s: dimensions[s.name] for s in expr.free_symbols if s.name in dimensions}
    try:
        return expression_dimension(expr, known) == expected
    except DimensionMismatch:
        return False
    except UnknownDimension:
        raise refused from None  # a symbol without a dimension: nothing can be decided
