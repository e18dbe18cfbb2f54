"""Reading a unit string into ParsedUnits, by a small recursive-descent grammar over `lexer` tokens.

    units    := product ('/' product)*
    product  := factor (('*' | '·' | '⋅' | '×' | juxtaposition) factor)*
    factor   := atom (('^' | '**') exponent | SUPERSCRIPT)?
    atom     := NAME | '1' | '(' units ')'
    exponent := ('-' | '−' | '+')? INTEGER | '(' ('-' | '−' | '+')? INTEGER ')'

With one `/`, the whole product after it is the denominator (`J/kg K` is J/(kg·K)); with several, each
divides by the single factor after it (`m/s/s`). Several `/` with a product after one of them
(`J/kg K/s`) is refused as ambiguous. A NAME is a unit spelling (`ms`, `kN`, `meters`) or an alias
from `catalogue.ALIASES` (`ohms`, `mps`); a glued name that is neither but splits one way into
spellings is their product (`Nm`), with a power on its last unit (`kgm^2` is kg·m²). A glued name that
another single unit also fits (`Kg`, `kgs`) has no safe reading: `read_units` lets the expected
dimension choose, or refuses it.
"""

from __future__ import annotations

import itertools
import math
import re
from collections.abc import Mapping
from dataclasses import dataclass
from functools import lru_cache

from physics.dimensions import Dimension, describe
from physics.errors import AmbiguousInput, AnswerError, LikelySlip, ParseError, TooLarge, UnknownUnit
from physics.units.catalogue import (
    ALIASES,
    FIRST_WHERE_NONE_FITS,
    MEANINGS,
    PREFIX_SYMBOLS,
    SI_PREFIXES,
    TWO_ANGLE_SPELLINGS,
)
from physics.units.lexer import Kind, Token, second_quantity, tokenize
from physics.units.parsed import ParsedUnits
from physics.units.registry import (
    UnitAtom,
    case_variants,
    lookup,
    lookup_piece,
    pint_unit,
    prefixed_name,
    suggestion,
)
from physics.wording import DIRECTION_BY_SIGN, DIRECTION_WORDS

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
            atom = lookup_piece(name[start:end])
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


Factors = tuple[tuple[UnitAtom, int], ...]


@dataclass(frozen=True)
class _Option:
    """One reading of a name: its units, and whether it is a glued product (a power then applies to
    its last unit only: `kgm^2` is kg·m²)."""

    factors: Factors
    split: bool = False

    def powered(self, power: int) -> ParsedUnits:
        if not self.split:
            return ParsedUnits(self.factors) ** power
        *head, (last, one) = self.factors
        return ParsedUnits.of([*head, (last, one * power)])

    @property
    def text(self) -> str:
        return ParsedUnits(self.factors).text


@dataclass(frozen=True)
class _NameReadings:
    """The ways one name can be read; `safe`: the first may be taken without a dimension to confirm it;
    `default`: the first (pint's meaning of a spelling with several, `lb`) is taken where no dimension
    is expected, and said nothing about where it is the one that fits."""

    options: tuple[_Option, ...]
    safe: bool
    default: bool = False
    case_only: bool = False  # every reading is a unit the letters spell in another case (`mc`, `pa`)
    first_where_none_fits: bool = False  # graded as the first reading where none has the dimension

    @property
    def plain(self) -> bool:
        """Its first reading may stand without a note: safe, or pint's own meaning of the spelling."""
        return self.safe or self.default


def _readings(name: str, power: int = 1) -> _NameReadings:
    """Every reading of a glued name, most literal first.

    A known spelling or alias is taken as it is; a glued name that splits one way only is that product
    (`Nm`). Where another single unit fits the same letters (`Kg` for kg, `kgs` as a plural of kg) the
    name has no safe reading: only the expected dimension can choose. A known spelling with a negative
    power (`ms^-1`) keeps its split as a second reading, for the same choice; so does an alias of a
    rate with a power (`mps2`: metres per second squared, or (m/s)²).
    """
    negative_power = power < 0
    meanings = MEANINGS.get(name)
    if meanings is not None:
        return _NameReadings(tuple(_Option(((_meaning(m), 1),)) for m in meanings), safe=False, default=True)
    alias = ALIASES.get(name)
    if alias is not None and power > 1 and _alias_factors(alias)[-1][1] < 0:
        # `mps2`, `mps²`: said "metres per second squared", the power on the second; or (m/s)² as typed
        per = _alias_factors(alias)
        return _NameReadings((_Option(per, split=True), _Option(per)), safe=False, first_where_none_fits=True)
    if alias is not None and not negative_power:
        return _NameReadings((_Option(_alias_factors(alias)),), safe=True)
    splits = tuple(_Option(tuple((a, 1) for a in split), split=True) for split in _splits(name))
    if alias is not None:  # `rads^-1`: per radian, or rad·s⁻¹ as a student means it (not `mps` as m·ps)
        plain_splits = tuple(split for split in splits if _unprefixed(split.factors))
        return _NameReadings((_Option(_alias_factors(alias)), *plain_splits), safe=True)
    atom = lookup(name)
    if atom is not None:
        return _NameReadings((_Option(((atom, 1),)), *(splits if negative_power else ())), safe=True)
    options = list(splits)
    plural = _plural_of(name)
    if plural is not None:
        options.insert(0, _Option(((plural, 1),)))
    # A case slip counts as a reading where no split does, or where the split starts with a kelvin:
    # `Kg`, `KJ` are the kilo prefix in capitals; `Nm` stays the newton-metre, never a nanometre.
    # So does a unit's name in capitals, at the start of a sentence or by a phone: `Amps`, `Pascals` (not
    # A·m·ps, Pa·s·cal·s).
    slip = not splits or splits[0].factors[0][0].name == "kelvin" or (len(name) > 3 and not name.islower())
    alias_variant = _ALIASES_BY_FOLDED_CASE.get(name.casefold()) if slip else None  # `Kilos`, `Kgs`
    # Every unit the letters spell in another case: `Ks` is ks or kS (a time or a conductance), and the
    # expected dimension may choose.
    variants = () if alias_variant is not None or not slip else case_variants(name)
    if alias_variant is not None:
        options.append(_Option(_alias_factors(ALIASES[alias_variant])))
    for variant in variants:
        options.append(_Option(((_meaning(variant), 1),)))
    if slip and name.isupper() and name.isascii() and len(name) <= _MAX_RECASED_LENGTH:
        options.extend(_glued_in_capitals(name))  # `NM` for a torque: N·m, as well as nm
    unique = list({option.text: option for option in options}.values())
    if not unique:
        # `sqft`, `cuin`; then the long tail by pint's own names (`furlongs`, `fortnight`).
        pint_only = pint_unit(name)
        other = _squared_or_cubed(name) or (None if pint_only is None else (pint_only, 1))
        if other is not None:
            return _NameReadings((_Option((other,)),), safe=True)
    case_slip = alias_variant is not None or bool(variants)
    return _NameReadings(
        tuple(unique),
        safe=len(unique) == 1 and not case_slip,
        case_only=case_slip and not splits and not plural,
    )


# How near the value is, said after it as in a sentence (`4.58 m/s^2 approx`): no unit, and never read as one.
_REMARK_WORDS = frozenset({"approx", "approximately", "about", "roughly", "exactly", "circa"})

# Prefix symbols that are no unit alone, typed apart from the unit they scale (`1.5k N`, `2 M J`).
_PREFIX_SYMBOLS_ALONE = frozenset({"k", "M"})


def _prefixes_joined(tokens: list[Token]) -> list[Token]:
    """The tokens with a prefix said as a word apart from its unit joined to it (`kilo newtons`,
    `kilo-newtons`, `micro seconds`, and before a symbol `micro s`, `kilo m`, `mu s`), where the two make
    one unit's spelling: never `kilo` (kg) times a newton or a metre, nor `mu` the metre times the
    atomic mass unit."""
    joined: list[Token] = []
    i = 0
    while i < len(tokens):
        token = tokens[i]
        after = tokens[i + 1] if i + 1 < len(tokens) else None
        gap = 2 if after is not None and after.kind is Kind.TIMES and after.text == "-" else 1
        unit = tokens[i + gap] if i + gap < len(tokens) else None
        word = token.text.lower() if token.kind is Kind.NAME else ""
        if word in PREFIX_SYMBOLS and unit and unit.kind is Kind.NAME:
            spelling = next((s for s in _prefixed_spellings(word, unit.text) if _one_unit(s)), None)
            if spelling is not None:
                joined.append(Token(Kind.NAME, spelling, token.position))
                i += gap + 1
                continue
        joined.append(token)
        i += 1
    return joined


def _prefixed_spellings(prefix: str, unit: str) -> tuple[str, ...]:
    """The ways a prefix said apart joins its unit: the word to a name (`kilonewtons`), the symbol to a
    symbol (`µs`)."""
    by_symbol = PREFIX_SYMBOLS[prefix] + unit
    return (prefix + unit, by_symbol) if prefix in SI_PREFIXES else (by_symbol,)


def _one_unit(spelling: str) -> bool:
    """Whether a spelling reads as one unit and one way only."""
    readings = _readings(spelling)
    return len(readings.options) == 1 and readings.safe and not readings.options[0].split


# Aliases by their letters in lower case, where only one alias has them: a case slip's reading.
_ALIASES_BY_FOLDED_CASE = {
    folded: alias
    for alias in ALIASES
    if sum(other.casefold() == (folded := alias.casefold()) for other in ALIASES) == 1
}


def _meaning(spelling: str) -> UnitAtom:
    atom = lookup(spelling)
    assert atom is not None, f"catalogue.MEANINGS names {spelling!r}, which is no unit spelling"
    return atom


_AREA_OR_VOLUME = {"sq": 2, "cu": 3}


def _squared_or_cubed(name: str) -> tuple[UnitAtom, int] | None:
    """`sqft`, `sqm`, `cuin`: a unit glued after `sq` or `cu`, squared or cubed (the spaced `sq ft` is
    the lexer's), else None."""
    power = _AREA_OR_VOLUME.get(name[:2])
    atom = lookup(name[2:]) if power is not None and len(name) > 2 else None
    if atom is None or power is None:
        return None
    return atom, power


def _plural_of(name: str) -> UnitAtom | None:
    """`lbs` is the pound: a lowercase plural of a unit spelling of two letters or more."""
    if len(name) > 2 and name.endswith("s") and name.isascii() and name.islower():
        return lookup(name[:-1])
    return None


_SPACED_POWER = re.compile(r"(?<=[^\W\d_])\s+[-−–](\d+)")


@lru_cache(maxsize=64)
def _alias_factors(alias: str) -> Factors:
    return _Parser(alias, {}).parse().factors


class _Parser:
    """One reading of a unit string; `choices` picks a reading (by index) for names at given positions."""

    def __init__(self, text: str, choices: Mapping[int, int]) -> None:
        self.text = text
        self.tokens = _prefixes_joined(tokenize(text))
        self.index = 0
        self.choices = choices
        self.open_names: list[tuple[Token, _NameReadings]] = []  # names read more than one way
        self.names: list[Token] = []  # every name read, for the case slips of a reading that does not fit
        self.in_denominator = False
        self.divided_twice: list[int] = []  # where a minus divides again what a `/` divides (`m/s^-2`)

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
            raise ParseError(
                f"Unexpected {self.token.text!r} in the units{self._spaced_power_hint()}", self.token.position
            )
        return result

    def _spaced_power_hint(self) -> str:
        """`. Did you mean m s^-2? …` for `m s -2`, a textbook's power with a space before its minus; or ""
        (after a `/`, `m/s -2`, the power meant is anyone's guess)."""
        minus, following = self.token, self.tokens[self.index + 1]
        if not (
            "/" not in self.text
            and minus.kind is Kind.MINUS
            and self.tokens[self.index - 1].kind is Kind.NAME
            and following.kind is Kind.INTEGER
            and following.position == minus.position + 1
        ):
            return ""
        meant = _SPACED_POWER.sub(r"^-\1", self.text)
        return f". Did you mean {meant}? Write a power with ^"

    def units(self) -> ParsedUnits:
        numerator, _ = self.product()
        denominators: list[tuple[ParsedUnits, int, Token]] = []
        while self.at(Kind.DIVIDE):
            slash = self.advance()
            outer, self.in_denominator = self.in_denominator, True
            denominator, count = self.product()
            self.in_denominator = outer
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
        if self.at(Kind.NAME):
            return self.name_factor()
        base = self.atom()
        if self.at(Kind.POWER):
            self.advance()
            return base ** self.exponent()
        if self.at(Kind.SUPERSCRIPT):
            return base ** self._superscript_power()
        return base

    def _superscript_power(self) -> int:
        token = self.advance()
        if self.in_denominator and token.text.startswith("⁻"):
            self.divided_twice.append(token.position)
        return self._checked_power(token)

    def name_factor(self) -> ParsedUnits:
        token = self.advance()
        power = 1
        if self.at(Kind.POWER):
            self.advance()
            power = self.exponent()
        elif self.at(Kind.SUPERSCRIPT):
            power = self._superscript_power()
        angles = TWO_ANGLE_SPELLINGS.get(token.text)
        if angles is not None:
            raise AmbiguousInput(
                f"{token.text!r} can mean {angles[0]} or {angles[1]}: for degrees write ° or deg, as in 30°",
                token.position,
                angles,
            )
        if token.text in _PREFIX_SYMBOLS_ALONE and power == 1 and self.at(Kind.NAME):
            # `1.5k N`: a thousand, as a price is written; not a kelvin (k) or a metre (M) in capitals
            raise UnknownUnit(
                f"Unknown unit {token.text!r}: {token.text!r} is a prefix, not a unit; join it to its unit, "
                f"as in {token.text}{self.token.text}",
                token.position,
                token.text,
            )
        self.names.append(token)
        readings = _readings(token.text, power)
        if not readings.options:
            if token.text.lower() in DIRECTION_WORDS:  # `-6.17 m/s^2 downward`, as said in a sentence
                raise UnknownUnit(
                    f"Unknown unit {token.text!r}: {DIRECTION_BY_SIGN}",
                    token.position,
                    token.text,
                )
            if token.text.lower() in _REMARK_WORDS:
                raise UnknownUnit(
                    f"Unknown unit {token.text!r}: give the value and its units alone, and leave out {token.text}",
                    token.position,
                    token.text,
                )
            hint = suggestion(token.text)
            advice = f" (units are case-sensitive: did you mean {hint!r}?)" if hint else ""
            if not hint and (spelled := prefixed_name(token.text)) is not None:  # `kJoules`
                advice = (
                    f": did you mean {spelled[0]}? Write the symbols together, {spelled[0]}, or the names together, "
                    f"{spelled[1]}"
                )
            if token.text in _DEGREE_LOOKALIKES:  # `30o`: the letter typed for a degree sign
                advice = ": for degrees write ° or deg, as in 30°"
            raise UnknownUnit(f"Unknown unit {token.text!r}{advice}", token.position, token.text)
        if len(readings.options) > 1 or not readings.safe:
            self.open_names.append((token, readings))
        return readings.options[self.choices.get(token.position, 0)].powered(power)

    def atom(self) -> ParsedUnits:
        token = self.advance()
        if token.kind is Kind.INTEGER:
            if token.value != 1 and self.at(Kind.NAME):  # `5 ft 10 in`, `2 h 30 min`
                raise second_quantity(token.text, self.token.text, token.position)
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
            signed = self.advance()
            sign = -1 if signed.kind is Kind.MINUS else 1
            if sign < 0 and self.in_denominator:
                self.divided_twice.append(signed.position)
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


@dataclass(frozen=True)
class UnitReading:
    """Units as read, and, when the expected dimension chose between readings, a note saying so."""

    units: ParsedUnits
    note: str | None = None


# Letters typed where a degree sign was meant (`30o`), which no unit spells.
_DEGREE_LOOKALIKES = frozenset({"o", "O", "ᵒ"})

_MAX_READINGS = 64  # combinations of readings of glued names tried against the expected dimension


def _read(text: str, expected: Dimension | None, *, case_slips: bool = True) -> UnitReading:
    parser = _Parser(text, {})
    literal = parser.parse()
    if parser.divided_twice and expected is not None and literal.dimension != expected:
        _refuse_dividing_twice(text, parser.divided_twice, literal, expected)
    open_names = parser.open_names
    safe = all(readings.safe for _, readings in open_names)
    plain = all(readings.plain for _, readings in open_names)
    if (safe and literal.dimension == expected) or (plain and expected is None):
        return UnitReading(literal)
    if safe and case_slips and expected is not None:
        _refuse_case_slip(text, parser.names, literal, expected)
    fits: list[ParsedUnits] = []
    if expected is not None:
        fits = _fitting(text, open_names, expected)
        if len(fits) == 1:
            if plain and fits[0] == literal:  # `50 lb` for a mass: pint's pound, as typed
                return UnitReading(literal)
            typed = " ".join(text.split())
            return UnitReading(
                fits[0], f"Read {typed} as {fits[0].text}: the only reading that is {describe(expected)}"
            )
    if all(
        readings.safe or readings.first_where_none_fits or token.text in FIRST_WHERE_NONE_FITS
        for token, readings in open_names
    ):
        return UnitReading(literal)  # graded: the dimension is wrong
    token, readings = next((t, r) for t, r in open_names if not r.safe)
    shown = [option.text for option in readings.options]
    if readings.default and expected is not None:
        typed = " ".join(text.split())
        which = "more than one reading" if fits else "no reading"
        raise AmbiguousInput(
            f"{token.text!r} can mean {' or '.join(shown)}, and {which} of {typed} is {describe(expected)}: "
            "write the units you mean",
            token.position,
            shown,
        )
    if readings.case_only and len(shown) > 1:
        # `mc` for a charge: mC or MC; `pa` with nothing to choose: Pa first, not pA or PA
        offered = [fit.text for fit in fits] if len(fits) > 1 else [suggestion(token.text) or shown[0]]
        quoted = [repr(text) for text in offered]
        either = quoted[0] if len(quoted) == 1 else f"{', '.join(quoted[:-1])} or {quoted[-1]}"
        raise UnknownUnit(
            f"Unknown unit {token.text!r} (units are case-sensitive: did you mean {either}?)",
            token.position,
            token.text,
        )
    if len(shown) == 1:
        raise UnknownUnit(
            f"Unknown unit {token.text!r} (units are case-sensitive: did you mean {shown[0]!r}?)",
            token.position,
            token.text,
        )
    raise AmbiguousInput(
        f"{token.text!r} can be read as {' or as '.join(shown)}; write the unit you mean, "
        "separating units with a space or ·",
        token.position,
        shown,
    )


# Names this short are tried in every case (`nm` as Nm, a glued N·m); longer ones as the units they spell.
_MAX_RECASED_LENGTH = 3


def _recased(name: str) -> list[str]:
    """The name's letters in other cases that are units: `PA` → `Pa`, `pA`; `nm` → `Nm` (N·m), but not
    `mps` → `mPs`: a glued name in another case only where its units have no prefix."""
    variants = list(case_variants(name))
    if len(name) <= _MAX_RECASED_LENGTH and name.isascii() and name.isalpha():
        for cases in itertools.product(*((c.lower(), c.upper()) for c in name)):
            spelled = "".join(cases)
            if spelled == name or spelled in variants:
                continue
            readings = _readings(spelled)
            if len(readings.options) == 1 and readings.safe and _unprefixed(readings.options[0].factors):
                variants.append(spelled)
    return variants


def _glued_in_capitals(name: str) -> list[_Option]:
    """The products of unprefixed units that the letters of a short name typed in capitals spell in
    other cases, one way each: `NM` is N·m (never a kelvin first, `KM` being km, not K·m)."""
    glued: list[_Option] = []
    for cases in itertools.product(*((c.lower(), c.upper()) for c in name)):
        spelled = "".join(cases)
        if spelled == name or lookup(spelled) is not None or spelled in ALIASES:
            continue
        splits = _splits(spelled)
        if (
            len(splits) == 1
            and _unprefixed(tuple((a, 1) for a in splits[0]))
            and splits[0][0].name != "kelvin"
        ):
            glued.append(_Option(tuple((a, 1) for a in splits[0]), split=True))
    return glued


def _unprefixed(factors: Factors) -> bool:
    """Whether no unit of `factors` has a prefix: a glued name read as `rad·s`, `N·m`, not `m·ps`."""
    return not any(atom.name.startswith(SI_PREFIXES) for atom, _ in factors)


def _refuse_dividing_twice(text: str, minuses: list[int], literal: ParsedUnits, expected: Dimension) -> None:
    """`m/s^-2`: a `/` and a negative power each divide, so as typed the two multiply (m·s²). Where the
    units without that minus (m/s^2) have the expected dimension, refused asking whether they were meant,
    rather than graded as a wrong dimension."""
    tries = [(at, text[:at] + text[at + 1 :]) for at in minuses]
    if len(minuses) > 1:  # `J/kg^-1 K^-1`: every power of the denominator typed negative
        tries.append((minuses[0], "".join(c for k, c in enumerate(text) if k not in minuses)))
    for at, meant in tries:
        try:
            reading = _read(meant, expected, case_slips=False)
        except AnswerError:
            continue
        if reading.units.dimension == expected:
            typed = " ".join(text.split())
            raise AmbiguousInput(
                f"Did you mean {reading.units.text}? As typed, {typed} is {literal.text}: a / and a "
                "negative power each divide, so together they multiply",
                at,
                [literal.text, reading.units.text],
            )


def _refuse_case_slip(text: str, names: list[Token], literal: ParsedUnits, expected: Dimension) -> None:
    """A unit that is not the expected dimension but is in another case (`101325 PA`, the petaampere,
    for a pressure; `4.58 Ms^-2`, per megasecond squared, for an acceleration): refused asking whether
    the unit in that case was meant, rather than graded as a wrong dimension; nothing is said where no
    other case fits. A reading with the expected dimension is never questioned (`3 Mm` for mm)."""
    offered: dict[str, None] = {}
    slipped: Token | None = None
    for token in names:
        at = token.position
        if text[at : at + len(token.text)] != token.text:
            continue  # joined from words (`kilo newtons`) or read from LaTeX: not retyped here
        for variant in _recased(token.text):
            retyped = text[:at] + variant + text[at + len(token.text) :]
            try:
                reading = _read(retyped, expected, case_slips=False)
            except AnswerError:
                continue
            if reading.units.dimension == expected:
                offered[reading.units.text] = None
                slipped = slipped or token
    if slipped is None:
        return
    typed = " ".join(text.split())
    atom = lookup(slipped.text)
    name = atom.name if atom is not None and "_" not in atom.name else None  # not pint's `gauss_tesla`
    what = f"{typed} measures {describe(literal.dimension)}"
    if name is not None and typed == slipped.text:
        what = f"{typed} is the {name}, {describe(literal.dimension)}"  # PA is the petaampere, a current
    elif name is not None:
        what = f"{slipped.text} is the {name}, so {typed} is {describe(literal.dimension)}"
    shown = list(offered)
    either = shown[0] if len(shown) == 1 else f"{', '.join(shown[:-1])} or {shown[-1]}"
    raise AmbiguousInput(
        f"Units are case-sensitive: {what}, but {describe(expected)} is expected. Did you mean {either}?",
        slipped.position,
        [literal.text, *shown],
    )


def _fitting(
    text: str, open_names: list[tuple[Token, _NameReadings]], expected: Dimension
) -> list[ParsedUnits]:
    """The distinct readings of `text` with the expected dimension (none if there are too many to try)."""
    counts = [len(readings.options) for _, readings in open_names]
    if math.prod(counts) > _MAX_READINGS:
        return []
    fits: list[ParsedUnits] = []
    for combination in itertools.product(*(range(count) for count in counts)):
        choices = {token.position: k for (token, _), k in zip(open_names, combination, strict=True)}
        units = _Parser(text, choices).parse()
        if units.dimension == expected and units not in fits:
            fits.append(units)
    return fits


@lru_cache(maxsize=2048)
def _read_cached(text: str, expected: Dimension | None) -> UnitReading:
    if expected is None or not text.isupper():
        return _read(text, expected)
    # `9.8 M/S^2`, caps lock on: where the units as typed are unknown or do not fit, in small letters
    # they may be the ones meant (a single name's other cases are read in `_readings`)
    try:
        typed = _read(text, expected)
    except UnknownUnit:
        typed = None
    except AmbiguousInput:
        if text.isalpha():
            raise  # one name: its other cases were asked about (`101325 PA`: Pa?)
        typed = None  # `KG M/S^2`: K·G or kg, in a product that in small letters is a force
    if typed is not None and typed.units.dimension == expected:
        return typed
    try:
        small = _read(text.lower(), expected)
    except AnswerError:
        small = None
    if small is None or small.units.dimension != expected:
        return typed or _read(text, expected)
    shown = " ".join(text.split())
    return UnitReading(
        small.units,
        f"Read {shown} as {small.units.text}: units are case-sensitive, and in small letters these are "
        f"{describe(expected)}",
    )


def _check_length(text: str) -> None:
    if len(text) > MAX_UNIT_TEXT_LENGTH:
        limit = MAX_UNIT_TEXT_LENGTH
        raise TooLarge(f"A unit string may be at most {limit} characters", limit)


def read_units(text: str, expected: Dimension | None = None) -> UnitReading:
    """Read a unit string as `parse_units` does; where glued names read several ways (`Kg`: kg or
    K·g; `ms^-1`: ms⁻¹ or m·s⁻¹) and exactly one reading has the `expected` dimension, take it and
    say so in `note`. Without one that decides, a name with no safe reading is refused.
    """
    _check_length(text)
    reading = _read_cached(text, expected)
    if expected is not None and reading.units.dimension != expected:
        if text.startswith("in "):
            _refuse_the_word_in(text, expected)
        if text.strip() == "dg" and expected == Dimension():  # `35 dg` for an angle: never 35 decigrams
            raise LikelySlip(
                "Did you mean degrees? dg is the decigram, a mass: for degrees write ° or deg, as in 30°", 0
            )
    return reading


def _refuse_the_word_in(text: str, expected: Dimension) -> None:
    """`9.8 in m/s^2`, the answer said as a sentence: the inch times m/s² as typed. Refused where the
    units after the word are the dimension asked, rather than graded as a quantity in m²/s²."""
    rest = text[3:].strip()
    try:
        meant = _read_cached(rest, expected)
    except AnswerError:
        return
    if meant.units.dimension == expected:
        raise ParseError(
            f"'in' here is the inch, so these units are in·{rest}: write the units alone, as in {rest}", 0
        )


def parse_units(text: str) -> ParsedUnits:
    """Read a unit string (`m/s^2`, `kg·m²/s²`, `J/kg K`, `km/h`, `°C`, `1`).

    Raises UnknownUnit, AmbiguousInput, ParseError or TooLarge, with 0-based positions into `text`.
    """
    return read_units(text).units
