"""An answer typed as a sentence (`The period is 2π√(L/g)`): refused saying to type the expression alone,
rather than naming its first word as an unknown symbol. Words that are declared symbols are never part
of the sentence, so `m g` stays an answer however it is surrounded.
"""

from __future__ import annotations

import re

from physics.errors import ParseError
from physics.mathinput.names import NameTable
from physics.mathinput.tokentypes import Kind, SpelledWord, Token

# Words that a sentence about an answer holds and an answer does not: one of them must be among the
# opening words, so that two undeclared names (`Delta x`, `vx vy`) are still asked about as names.
_SENTENCE_WORDS = frozenset(
    {
        "the", "is", "are", "was", "equals", "equal", "answer", "of", "so", "then", "thus", "hence",
        "therefore", "it", "this", "that", "we", "get", "gives", "given", "by", "will", "be", "my", "final",
    }
)  # fmt: skip


def refuse_leading_sentence(tokens: list[Token], table: NameTable, text: str) -> None:
    """Raise where the answer opens with two or more plain words that are no names (one of them a
    sentence's), followed by an expression; the refusal shows the expression without the words around it."""
    leading = _leading_words(tokens)
    unknown = [_plain_unknown(tok, table) for tok in leading]
    opening = len(unknown) if all(unknown) else unknown.index(False)
    if opening < 2 or not any(tok.text.lower() in _SENTENCE_WORDS for tok in leading[:opening]):
        return
    # The sentence ends after a run of its words: the last run with an expression after it
    # (`The period T is 2π√(L/g)`: after `is`; `the answer is m g newtons`: after `is`, not `newtons`).
    ends = [
        k + 1 for k in range(len(leading)) if unknown[k] and (k + 1 == len(leading) or not unknown[k + 1])
    ]
    for end in reversed(ends):
        expression = _expression_after(tokens, end, table, text)
        if expression:
            sentence = text[tokens[0].pos : tokens[end - 1].end]
            raise ParseError(
                f'"{sentence}" is a sentence, which is not read: type only the expression, as in {expression}.',
                tokens[0].pos,
            )


# The verbs of `T is 2π√(L/g)`, the answer's name before it.
_NAMING_VERBS = frozenset({"is", "equals", "was", "are"})


def refuse_a_named_answer(tokens: list[Token], table: NameTable, text: str) -> None:
    """Raise where the answer opens with a declared name and a verb (`T is 2π√(L/g)`, T declared),
    followed by an expression: a sentence, as `The period is 2π√(L/g)` is, not an unknown symbol `is`."""
    name, verb = tokens[0], tokens[1]
    if name.kind is not Kind.WORD or verb.text.lower() not in _NAMING_VERBS or not verb.space_before:
        return
    expression = _expression_after(tokens, 2, table, text)
    if not expression:
        return
    raise ParseError(
        f'"{text[name.pos : verb.end]}" is a sentence, which is not read: type only the expression, as in '
        f"{expression}.",
        name.pos,
    )


def refuse_a_remark(tokens: list[Token], at: int, table: NameTable, text: str) -> None:
    """Raise where the unknown word at tokens[at] is in a remark in brackets that ends the answer, of
    plain words only (`2π√(L/g) (small angles)`, `m g (approx)`): the refusal shows the expression to type."""
    if tokens[-2].kind is not Kind.RPAREN or tokens[-2].text != ")":
        return
    opening = next((k for k in range(at - 1, -1, -1) if tokens[k].kind in (Kind.LPAREN, Kind.RPAREN)), None)
    if opening is None or tokens[opening].text != "(" or not tokens[opening].space_before or opening == 0:
        return
    words = tokens[opening + 1 : -2]
    if not all(_plain_unknown(tok, table) for tok in words) or (len(words) < 2 and len(words[0].text) < 4):
        return  # `m (mu)`, `m g (x)`: a name the problem lacks, more likely than a remark
    remark = text[tokens[opening].pos : tokens[-2].end]
    raise ParseError(
        f"Give the expression alone: leave out {remark}, and type only {text[: tokens[opening].pos].strip()}.",
        tokens[opening].pos,
    )


def _leading_words(tokens: list[Token]) -> list[Token]:
    """The words the answer opens with, each spaced from the one before."""
    words: list[Token] = []
    for tok in tokens:
        if tok.kind is not Kind.WORD or (words and not tok.space_before):
            break
        words.append(tok)
    return words


def _plain_unknown(tok: Token, table: NameTable) -> bool:
    """Whether a word is typed in plain letters and reads as no name, function or constant."""
    return (
        tok.kind is Kind.WORD
        and not isinstance(tok, SpelledWord)
        and tok.text.isascii()
        and tok.text.isalpha()
        and not table.resolve(tok.text).readings
    )


def _expression_after(tokens: list[Token], start: int, table: NameTable, text: str) -> str:
    """The text from tokens[start] on, without the plain words that end it (`2π√(L/g) seconds`)."""
    stop = len(tokens) - 1  # the END token
    while stop > start and _plain_unknown(tokens[stop - 1], table) and tokens[stop - 1].space_before:
        stop -= 1
    if stop == start:
        return ""
    return text[tokens[start].pos : tokens[stop - 1].end].strip()


# A name on one side of an `=`: `T`, `ω`, `v_0`, `a_{max}`, `F_N`.
_NAME_SIDE = re.compile(r"\s*[^\W\d]\w*(?:_\{?\w+\}?)?\s*")
# Words typed after the expression, as its units in words: `seconds`, `newtons`.
_TRAILING_WORDS = re.compile(r"(?:\s+[A-Za-z]{4,})+\s*$")


def equals_sign(text: str, at: int) -> ParseError:
    """The refusal of the `=` (or `≈`) at `at`: the answer is the expression alone. Where a name stands on
    one side and an expression on the other (`T = 2π√(L/g)`, `g sin α = a`), it shows the expression to
    type, as a sentence's refusal does."""
    sign = text[at]
    if not text[:at].strip() and sign == "=":  # `=m*g*h`: a spreadsheet's formula
        return ParseError("Leave out the '=' at the start: type the expression alone.", at)
    named = named_side(text, at)
    if named is None:
        return ParseError(f"Give the expression alone, without '{sign}' (nor the name before it).", at)
    name, expression = named
    if text[:at].strip() == name:
        without, expression = f"{name} {sign}", _TRAILING_WORDS.sub("", expression)  # `… seconds`
    else:
        without = f"{sign} {name}"
    return ParseError(f"Give the expression alone, without '{without}': type only {expression}.", at)


# Words before the name, as a sentence introduces it: `the period T`, `so T`.
_WORDS_THEN_NAME = re.compile(r"\s*((?:[A-Za-z]+\s+)+)" + _NAME_SIDE.pattern.removeprefix(r"\s*"))


def _introduced_name(side: str) -> bool:
    """Whether `side` is a name after words of a sentence, one of them a sentence's (`the period T`)."""
    found = _WORDS_THEN_NAME.fullmatch(side)
    return found is not None and any(word.lower() in _SENTENCE_WORDS for word in found.group(1).split())


def named_side(text: str, at: int) -> tuple[str, str] | None:
    """The name and the expression of `T = 2π√(L/g)` (or `2π√(L/g) = T`, `the period T = 2π√(L/g)`, the
    name with the words before it), the sign at `at`; None where neither side is a name alone (or after a
    sentence's words), or the answer has another sign."""
    left, right = text[:at], text[at + 1 :]
    if any(sign in right for sign in "=≈") or not left.strip() or not right.strip():
        return None
    if _NAME_SIDE.fullmatch(left) or _introduced_name(left):
        return left.strip(), right.strip()
    if _NAME_SIDE.fullmatch(right):
        return right.strip(), left.strip()
    return None
