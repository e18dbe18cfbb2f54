"""Reading a unit string into ParsedUnits, by a small recursive-descent grammar over `lexer` tokens.

    units    := product ('/' product)*
    product  := factor (('*' | '·' | '⋅' | '×' | juxtaposition) factor)*
    factor   := atom (('^' | '**') exponent | SUPERSCRIPT)?
    atom     := NAME | '1' | '(' units ')'
    exponent := ('-' | '−' | '+')? INTEGER | '(' ('-' | '−' | '+')? INTEGER ')'

With one `/`, the whole product after it is the denominator (`J/kg K` is J/(kg·K)); with several, each
divides by the single factor after it (`m/s/s`). Several `/` with a product after one of them
(`J/kg K/s`) is refused as ambiguous. A NAME is a unit spelling (`ms`, `kN`, `meters`); a glued name
that is not one but splits one way into spellings is their product (`Nm`).
"""

from __future__ import annotations

from functools import lru_cache

from physics.errors import AmbiguousInput, ParseError, TooLarge, UnknownUnit
from physics.units.lexer import Kind, Token, tokenize
from physics.units.parsed import ParsedUnits
from physics.units.registry import UnitAtom, lookup, suggestion

MAX_UNIT_TEXT_LENGTH = 100
MAX_UNIT_POWER = 12
_MAX_SPLIT_LENGTH = 24
_FACTOR_STARTS = (Kind.NAME, Kind.INTEGER, Kind.LPAREN)


def _splits(name: str) -> list[list[UnitAtom]]:
    """Up to two ways to write `name` as a product of two or more unit spellings."""
    if len(name) > _MAX_SPLIT_LENGTH:
        return []
    # ways[i]: up to two segmentations of name[i:]
    ways: list[list[list[UnitAtom]]] = [[] for _ in range(len(name) + 1)]
    ways[len(name)] = [[]]
    for start in range(len(name) - 1, -1, -1):
        found: list[list[UnitAtom]] = []
        for end in range(start + 1, len(name) + 1):
            if not ways[end]:
                continue
            atom = lookup(name[start:end])
            if atom is None:
                continue
            for rest in ways[end]:
                found.append([atom, *rest])
                if len(found) == 2:
                    break
            if len(found) == 2:
                break
        ways[start] = found
    return [w for w in ways[0] if len(w) >= 2]


def _name_units(token: Token) -> ParsedUnits:
    atom = lookup(token.text)
    if atom is not None:
        return ParsedUnits(((atom, 1),))
    splits = _splits(token.text)
    if len(splits) == 1:
        return ParsedUnits.of((a, 1) for a in splits[0])
    if len(splits) > 1:
        readings = ["·".join(a.symbol for a in split) for split in splits]
        raise AmbiguousInput(
            f"{token.text!r} can be read as {readings[0]} or as {readings[1]}; separate the units with "
            "a space or ·",
            token.position,
            readings,
        )
    hint = suggestion(token.text)
    advice = f" (units are case-sensitive: did you mean {hint!r}?)" if hint else ""
    raise UnknownUnit(f"Unknown unit {token.text!r}{advice}", token.position, token.text)


class _Parser:
    def __init__(self, text: str) -> None:
        self.tokens = tokenize(text)
        self.index = 0

    @property
    def token(self) -> Token:
        return self.tokens[self.index]

    def at(self, kind: Kind) -> bool:
        return self.tokens[self.index].kind is kind

    def advance(self) -> Token:
        token = self.tokens[self.index]
        self.index += 1
        return token

    def parse(self) -> ParsedUnits:
        if self.at(Kind.END):
            raise ParseError("No units were given", 0)
        result = self.units()
        if not self.at(Kind.END):
            raise ParseError(f"Unexpected {self.token.text!r} in the units", self.token.position)
        return result

    def units(self) -> ParsedUnits:
        numerator, _ = self.product()
        denominators: list[tuple[ParsedUnits, int, Token]] = []
        while self.at(Kind.DIVIDE):
            slash = self.advance()
            denominator, count = self.product()
            denominators.append((denominator, count, slash))
        if len(denominators) > 1:
            for _, count, slash in denominators:
                if count > 1:
                    self._refuse_several_slashes(numerator, denominators, slash)
        result = numerator
        for denominator, _, _ in denominators:
            result = result / denominator
        return result

    @staticmethod
    def _refuse_several_slashes(
        numerator: ParsedUnits, denominators: list[tuple[ParsedUnits, int, Token]], slash: Token
    ) -> None:
        together = numerator
        for denominator, _, _ in denominators:
            together = together / denominator
        raise AmbiguousInput(
            "With several / in the units, write each denominator of more than one unit in parentheses, "
            f"for example {together.text}",
            slash.position,
            [together.text],
        )

    def product(self) -> tuple[ParsedUnits, int]:
        """A product of factors and how many factors it had (the several-`/` rule needs the count)."""
        result = self.factor()
        count = 1
        while True:
            if self.at(Kind.TIMES):
                self.advance()
            elif self.token.kind not in _FACTOR_STARTS:
                return result, count
            result = result * self.factor()
            count += 1

    def factor(self) -> ParsedUnits:
        base = self.atom()
        if self.at(Kind.POWER):
            self.advance()
            return base ** self.exponent()
        if self.at(Kind.SUPERSCRIPT):
            return base ** self._checked_power(self.advance())
        return base

    def atom(self) -> ParsedUnits:
        token = self.advance()
        if token.kind is Kind.NAME:
            return _name_units(token)
        if token.kind is Kind.INTEGER:
            if token.value != 1:
                raise ParseError(
                    "A unit string holds no numbers except 1 (as in 1/s) and powers (as in m^2)",
                    token.position,
                )
            return ParsedUnits(())
        if token.kind is Kind.LPAREN:
            inner = self.units()
            if not self.at(Kind.RPAREN):
                raise ParseError("Missing ) in the units", self.token.position)
            self.advance()
            return inner
        if token.kind is Kind.END:
            raise ParseError("The units end too early", token.position)
        raise ParseError(f"Expected a unit at {token.text!r}", token.position)

    def exponent(self) -> int:
        parenthesised = self.at(Kind.LPAREN)
        if parenthesised:
            self.advance()
        sign = 1
        if self.token.kind in (Kind.MINUS, Kind.PLUS):
            sign = -1 if self.advance().kind is Kind.MINUS else 1
        token = self.advance()
        if token.kind is not Kind.INTEGER:
            raise ParseError("A power of a unit must be a whole number, as in s^-2", token.position)
        if parenthesised:
            if not self.at(Kind.RPAREN):
                raise ParseError("A power of a unit must be a whole number: s^(-2)", self.token.position)
            self.advance()
        return self._checked_power(token, sign)

    @staticmethod
    def _checked_power(token: Token, sign: int = 1) -> int:
        if abs(token.value) > MAX_UNIT_POWER:
            raise TooLarge(f"The power {token.text} is too large for a unit", token.position)
        return sign * token.value


@lru_cache(maxsize=2048)
def _parse_cached(text: str) -> ParsedUnits:
    return _Parser(text).parse()


def parse_units(text: str) -> ParsedUnits:
    """Read a unit string (`m/s^2`, `kg·m²/s²`, `J/kg K`, `km/h`, `°C`, `1`).

    Raises UnknownUnit, AmbiguousInput, ParseError or TooLarge, with 0-based positions into `text`.
    """
    if len(text) > MAX_UNIT_TEXT_LENGTH:
        limit = MAX_UNIT_TEXT_LENGTH
        raise TooLarge(f"A unit string may be at most {limit} characters", limit)
    return _parse_cached(text)
