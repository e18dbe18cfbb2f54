"""`parse_math`: untrusted text to a sympy expression plus how it was read, without evaluating text."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from functools import lru_cache

import sympy

from physics.errors import AmbiguousInput, ParseError, TooLarge
from physics.mathinput.build import Builder
from physics.mathinput.limits import DEFAULT_LIMITS, InputLimits
from physics.mathinput.names import NameTable
from physics.mathinput.parser import Parser
from physics.mathinput.powered import PoweredArgument, reading_note
from physics.mathinput.render import render_both
from physics.mathinput.tokens import Kind, Token, tokenize
from physics.mathinput.tree import Node
from physics.mathinput.words import resolve_words
from physics.verdict import ReadAs

# Values sympy gives to 1/0, 0/0, log(0): no checker can compare them, so they are refused here.
_UNDEFINED = frozenset((sympy.zoo, sympy.nan, sympy.oo, -sympy.oo))


def _has_undefined(expr: sympy.Basic) -> bool:
    """expr.has(*_UNDEFINED) in one walk rather than five (sympy's `has` walks once for all patterns,
    then once more per pattern asking `pattern == node`, for patterns that match unlike-hashed nodes).
    The same answer: each of the four is a singleton that equals only itself (sympy makes every
    infinite or nan Float into them), so a node equals one of them exactly when it is in the set."""
    stack = [expr]
    while stack:
        node = stack.pop()
        if node in _UNDEFINED:
            return True
        stack.extend(node.args)
    return False


def _refuse_exponent_letter_clash(text: str, tokens: list[Token], table: NameTable) -> None:
    """`2E-3` where `E` is a declared symbol: 2×10⁻³ or 2·E − 3? Refused with both readings."""
    for token in tokens:
        # A number's text has an `e` only when it was typed with a power of ten (`2E-3` reads 2e-3).
        if token.kind is not Kind.NUM or "e" not in token.text:
            continue
        typed = text[token.pos : token.end]
        if "e" not in typed and "E" not in typed:  # typed in another script (fullwidth)
            continue
        letter = next(c for c in typed if c in "eE")
        if not table.is_declared(letter):
            continue
        mantissa, _, exponent = typed.partition(letter)
        power = exponent.lstrip("+")
        readings = (
            f"{mantissa}*10^" + (f"({power})" if power.startswith("-") else power),
            f"{mantissa}*{letter}{exponent}",
        )
        raise AmbiguousInput(
            f'"{typed}" could be {mantissa}×10^{power} or {mantissa}·{letter}{exponent}, '
            f"because {letter} is a symbol here: write {readings[0]} or {readings[1]}.",
            token.pos,
            readings,
        )


@dataclass(frozen=True)
class ParsedMath:
    expr: sympy.Expr
    read_as: ReadAs  # rendered from the parse tree, so it shows how the input was grouped
    powered: tuple[PoweredArgument, ...] = ()  # bare function arguments with a power: `sin θ^2`
    long_words: tuple[tuple[int, int], ...] = ()  # bare function arguments of several factors: `cos ωt`


@dataclass(frozen=True)
class TreeReading:
    """An answer read as far as its parse tree and how it reads, before sympy builds anything."""

    tree: Node
    read_as: ReadAs
    powered: tuple[PoweredArgument, ...]
    symbols: Mapping[str, sympy.Symbol]  # what each name in the tree stands for
    long_words: tuple[tuple[int, int], ...] = ()  # (function's position, factors) of `cos ωt`, `sinθmgL`


@lru_cache(maxsize=256)
def _name_table(names: tuple[tuple[str, sympy.Symbol], ...]) -> NameTable:
    """One table per set of declared names (read-only once built): every answer to a part reuses it."""
    return NameTable(dict(names))


def parse_math(
    text: str,
    names: Mapping[str, sympy.Symbol],
    *,
    limits: InputLimits = DEFAULT_LIMITS,
    choices: Mapping[int, int] | None = None,
    powers_outside: bool = False,
    velocities: bool = False,
    word_ends: Mapping[int, int] | None = None,
) -> ParsedMath:
    """Read `text` using only the declared `names` (spelling -> Symbol to use).

    `choices` reads each ambiguous grouping (by the position of its `/` or `^`) one way: 0 as (a/b)·c
    or e^(−ω)·t, 1 as a/(b·c) or e^(−ωt), 2 and up as a/(b·c)·d (the divisor ending earlier); without a
    choice it is refused (AmbiguousGrouping). A bare function argument with a
    power (`sin θ^2`) reads as sin(θ²) and `read_as.note` says so; `powers_outside` reads it as
    (sin θ)², the other reading, for comparison. `velocities`: `x'`, `ẋ`, `\\dot{x}` and `dx/dt` are read
    as the name `x_dot` (a coordinate's velocity, which `names` then declares). `word_ends` ends a bare
    function's word argument after as many factors as it says (by the function's position):
    `sinθmgL` with {0: 1} is sin(θ)·m·g·L; `long_words` lists the words that could end so.

    Raises ParseError, AmbiguousInput, UnknownSymbol, UnknownFunction or TooLarge, each with a 0-based
    `position` into `text`; sizes are checked before any value is computed.
    """
    return build_reading(
        read_tree(
            text,
            names,
            limits=limits,
            choices=choices,
            powers_outside=powers_outside,
            velocities=velocities,
            word_ends=word_ends,
        ),
        limits,
    )


def read_tree(
    text: str,
    names: Mapping[str, sympy.Symbol],
    *,
    limits: InputLimits = DEFAULT_LIMITS,
    choices: Mapping[int, int] | None = None,
    powers_outside: bool = False,
    velocities: bool = False,
    word_ends: Mapping[int, int] | None = None,
) -> TreeReading:
    """`parse_math` up to the parse tree: raises what it raises before building, never a refusal of the
    builder's (`build_reading` makes those)."""
    tree, parser, table = _tree(text, names, limits, choices, powers_outside, velocities, word_ends)
    powered = tuple(parser.powered)
    try:
        text, latex = render_both(tree, symbol_e="e" in names)
        read_as = ReadAs(text, latex, reading_note(powered))
    except RecursionError:
        raise _too_deep() from None
    return TreeReading(tree, read_as, powered, table.symbols, tuple(parser.long_words))


def build_reading(reading: TreeReading, limits: InputLimits = DEFAULT_LIMITS) -> ParsedMath:
    """The reading's sympy expression: what `parse_math` returns for the text `reading` was read from."""
    expr = _built(reading.tree, reading.symbols, limits)
    return ParsedMath(expr, reading.read_as, reading.powered, reading.long_words)


def parse_expression(
    text: str,
    names: Mapping[str, sympy.Symbol],
    *,
    limits: InputLimits = DEFAULT_LIMITS,
    velocities: bool = False,
) -> sympy.Expr:
    """`parse_math(...).expr`, without rendering how the text reads (a sixth of the work): for texts
    whose reading is never shown, such as a reference answer. Raises what parse_math raises."""
    tree, _, table = _tree(text, names, limits, None, False, velocities)
    return _built(tree, table.symbols, limits)


def parse_tree(
    text: str, names: Mapping[str, sympy.Symbol], *, limits: InputLimits = DEFAULT_LIMITS
) -> tuple[Node, Mapping[str, sympy.Symbol]]:
    """`parse_expression` up to the parse tree, with what each name in it stands for: for a reference
    valued from its tree before sympy builds it (`build_tree`), whose reading is never shown."""
    tree, _, table = _tree(text, names, limits, None, False)
    return tree, table.symbols


def build_tree(
    tree: Node, symbols: Mapping[str, sympy.Symbol], limits: InputLimits = DEFAULT_LIMITS
) -> sympy.Expr:
    """sympy's expression of a tree from `parse_tree`: `parse_expression` of the text it was read from."""
    return _built(tree, symbols, limits)


def _tree(
    text: str,
    names: Mapping[str, sympy.Symbol],
    limits: InputLimits,
    choices: Mapping[int, int] | None,
    powers_outside: bool,
    velocities: bool = False,
    word_ends: Mapping[int, int] | None = None,
) -> tuple[Node, Parser, NameTable]:
    table = _name_table(tuple(names.items()))
    tokens = tokenize(text, limits, velocities=velocities)
    _refuse_exponent_letter_clash(text, tokens, table)
    tokens = resolve_words(tokens, table, text)
    try:
        parser = Parser(text, tokens, limits, choices, powers_outside=powers_outside, word_ends=word_ends)
        tree = parser.parse()
    except RecursionError:
        raise _too_deep() from None
    return tree, parser, table


def _built(tree: Node, symbols: Mapping[str, sympy.Symbol], limits: InputLimits) -> sympy.Expr:
    try:
        expr = Builder(symbols, limits).build(tree)
    except RecursionError:
        raise _too_deep() from None
    if _has_undefined(expr):
        raise ParseError("The answer has no value: it divides by zero or takes the log of zero.", 0)
    return expr


def _too_deep() -> TooLarge:
    # Only reachable when a caller raises max_depth far above the default.
    return TooLarge("The answer is nested too deeply.", 0)
