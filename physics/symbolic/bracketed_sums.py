"""A sum typed beside a division without its brackets: `mg/m+M` is (m·g/m) + M as typed, which adds a
mass to an acceleration and so can never be right; the student meant m·g/(m + M). Where the answer as
typed adds quantities of different dimensions and bracketing the sum a `/` touches (its divisor run on
to the end of the sum, `a/(b + c)`, or its numerator back to the start, `(a + b)/c`) gives the
dimension the answer must have, the answer is refused (`invalid`, no attempt used) asking whether that
was meant, as a teacher would ask, rather than graded wrong for a missing bracket. Never read as the
bracketed sum: precedence says otherwise, and the student's text must say what they mean."""

from __future__ import annotations

from collections.abc import Mapping

import sympy

from physics.dimensions import Dimension
from physics.errors import AmbiguousInput, AnswerError
from physics.mathinput import InputLimits, parse_math
from physics.mathinput.render import in_student_style
from physics.mathinput.tokens import Kind, Token, tokenize
from physics.symbolic.dimensional import (
    DimensionMismatch,
    UnknownDimension,
    expression_dimension,
    named_dimension,
)
from physics.symbolic.reading import read_symbolic_answer

# Divisions whose sums are bracketed, each one to three ways: a few parses at most, on a wrong answer.
_MAX_DIVISIONS = 3
# What a binary + or − follows: the end of an operand.
_OPERAND_ENDS = (Kind.NUM, Kind.WORD, Kind.CONST, Kind.RPAREN, Kind.POSTFIX, Kind.SUP)


def unbracketed_sum(
    text: str,
    names: Mapping[str, sympy.Symbol],
    limits: InputLimits,
    dimensions: Mapping[str, Dimension],
    expected: Dimension,
) -> AmbiguousInput | None:
    """The question to ask of `text` whose sum beside a `/` wants brackets, or None. For an answer
    graded wrong_dimension: the cheap tests first (a `/` and a sign in the text)."""
    if "/" not in text or not any(sign in text for sign in "+-−–"):
        return None
    try:
        literal = parse_math(text, names, limits=limits)
        tokens = tokenize(text, limits)
    except AnswerError:
        return None
    adds = _unlike_terms(literal.expr, dimensions)
    if adds is None:
        return None
    meant: dict[str, int] = {}
    for slash, bracketed in _bracketings(text, tokens):
        try:
            other = read_symbolic_answer(bracketed, names, limits, dimensions, expected)
        except AnswerError:
            continue
        if named_dimension(other.expr, dimensions) == expected:
            meant.setdefault(in_student_style(other.read_as.text), slash)
    if not meant:
        return None
    readings = list(meant)
    asked = readings[0] if len(readings) == 1 else f"{', '.join(readings[:-1])} or {readings[-1]}"
    typed = in_student_style(literal.read_as.text)
    return AmbiguousInput(
        f"Did you mean {asked}? As typed, {typed} {adds}, so it cannot be right: put the sum in brackets.",
        next(iter(meant.values())),
        [typed, *readings],
    )


def _unlike_terms(expr: sympy.Expr, dimensions: Mapping[str, Dimension]) -> str | None:
    """What the expression adds (`adds a mass to an acceleration`), where it adds unlike quantities."""
    known = {s: dimensions[s.name] for s in expr.free_symbols if s.name in dimensions}
    try:
        expression_dimension(expr, known)
    except DimensionMismatch as mismatch:
        return mismatch.message if mismatch.message.startswith("adds ") else None
    except UnknownDimension:
        return None
    return None


def _bracketings(text: str, tokens: list[Token]) -> list[tuple[int, str]]:
    """For each of the first `/`s with a binary + or − beside it in its bracket: where the `/` is, and the
    text with the divisor run on to the end of the sum, the numerator back to its start, or both."""
    if any(token.kind is Kind.BAR for token in tokens):
        return []  # |…| opens and closes with the same sign: its depth is not worth guessing here
    found: list[tuple[int, str]] = []
    slashes = [k for k, token in enumerate(tokens) if token.kind is Kind.OP and token.text == "/"]
    for k in slashes[:_MAX_DIVISIONS]:
        slash = tokens[k]
        end, after = _sum_after(text, tokens, k)
        start, before = _sum_before(tokens, k)
        # `a/(b) + c`, `a + (b)/c`: a bracket around the divisor or the whole numerator says where it
        # ends, as typed; only a bracket left out is asked about
        after = after and tokens[k + 1].kind is not Kind.LPAREN
        before = before and not _bracketed_numerator(tokens, k)
        ways = []
        if after:  # a/b + c → a/(b + c)
            ways.append(f"{text[: slash.end]}({text[slash.end : end]}){text[end:]}")
        if before:  # a + b/c → (a + b)/c
            ways.append(f"{text[:start]}({text[start : slash.pos]}){text[slash.pos :]}")
        if after and before:
            ways.append(f"{text[:start]}({text[start : slash.pos]})/({text[slash.end : end]}){text[end:]}")
        found.extend((slash.pos, way) for way in ways)
    return found


def _sum_after(text: str, tokens: list[Token], k: int) -> tuple[int, bool]:
    """Where the bracket holding the `/` at k closes (the text's end if none), and whether a binary + or
    − stands between them outside any inner bracket."""
    depth = 0
    signed = False
    for at in range(k + 1, len(tokens)):
        token = tokens[at]
        if token.kind is Kind.LPAREN:
            depth += 1
        elif token.kind is Kind.RPAREN:
            if depth == 0:
                return token.pos, signed
            depth -= 1
        elif depth == 0 and _binary_sign(tokens, at):
            signed = True
    return len(text), signed


def _sum_before(tokens: list[Token], k: int) -> tuple[int, bool]:
    """Where the bracket holding the `/` at k opens (0 if none: after its bracket), and whether a binary
    + or − stands between them outside any inner bracket."""
    depth = 0
    signed = False
    for at in range(k - 1, -1, -1):
        token = tokens[at]
        if token.kind is Kind.RPAREN:
            depth += 1
        elif token.kind is Kind.LPAREN:
            if depth == 0:
                return token.end, signed
            depth -= 1
        elif depth == 0 and _binary_sign(tokens, at):
            signed = True
    return 0, signed


def _bracketed_numerator(tokens: list[Token], k: int) -> bool:
    """Whether the numerator of the `/` at k is one bracket, begun after a sign or at the start."""
    if tokens[k - 1].kind is not Kind.RPAREN:
        return False
    depth = 0
    for at in range(k - 1, -1, -1):
        depth += {Kind.RPAREN: 1, Kind.LPAREN: -1}.get(tokens[at].kind, 0)
        if depth == 0:
            return at == 0 or tokens[at - 1].kind is Kind.LPAREN or tokens[at - 1].text in ("+", "-")
    return False


def _binary_sign(tokens: list[Token], at: int) -> bool:
    token = tokens[at]
    return token.kind is Kind.OP and token.text in "+-" and at > 0 and tokens[at - 1].kind in _OPERAND_ENDS
