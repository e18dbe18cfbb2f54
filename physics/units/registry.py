"""The pint registry (built once, lazily) and the table of unit spellings a unit string may use.

pint supplies every conversion factor and dimension, as exact Fractions (`non_int_type=Fraction`).
pint's own string parser is never given outside text: a spelling is looked up in a table built from
the definitions of the units in `catalogue.CATALOGUE`, with SI prefixes, so that the lookup is a
dictionary access and nothing else.
"""

from __future__ import annotations

import unicodedata
from dataclasses import dataclass
from fractions import Fraction
from functools import cache
from typing import TYPE_CHECKING, Any

from physics.dimensions import Dimension
from physics.units.catalogue import (
    CATALOGUE,
    PINT_DIMENSIONS,
    PREFIX_LATEX,
    SI_PREFIXES,
    CatalogueEntry,
)

if TYPE_CHECKING:
    import pint

# A symbol-style spelling takes prefix symbols (`km`); a name-style one takes prefix names
# (`kilometer`) and a plural `s`. pint's short aliases (`sec`, `hr`) count as symbols.
_MAX_SYMBOL_LENGTH = 3


@dataclass(frozen=True)
class UnitAtom:
    """One unit with its prefix, e.g. the kilometre: how to show it and how it relates to SI."""

    name: str  # pint's name, e.g. "kilometer"; identifies the atom
    symbol: str  # canonical display, e.g. "km"
    latex: str  # e.g. r"\mathrm{km}"
    scale: Fraction  # value in coherent SI units (kg, m, s, A, K, mol, cd) of one of this unit
    dimension: Dimension
    offset: Fraction | None = None  # for an offset unit (°C): SI value of its zero
    si: bool = True  # SI, or accepted for use with it; False for ft, lb, atm, rev, …
    angle: bool = False  # an angle unit, or one with an angle in it (rad, °, rev, rpm): pint's radian


@dataclass(frozen=True)
class _Spelling:
    prefix: str  # pint prefix name, "" for none
    entry: CatalogueEntry


@cache
def registry() -> pint.UnitRegistry[Fraction]:
    """The one pint registry, with exact (Fraction) arithmetic."""
    import pint  # a twentieth of a CPU-second, paid with the registry (after /ready, in the server)

    ureg: pint.UnitRegistry[Fraction] = pint.UnitRegistry(non_int_type=Fraction)
    # The gauss of SI-based courses (pint's own `gauss` belongs to the Gaussian system).
    ureg.define("gauss_tesla = tesla / 10000")
    return ureg


def _unit_definition(ureg: pint.UnitRegistry[Fraction], name: str) -> Any:
    # pint has no public accessor for a unit's symbol and aliases together.
    return ureg._units[name]


def _spellings_of_unit(
    ureg: pint.UnitRegistry[Fraction], entry: CatalogueEntry
) -> tuple[list[str], list[str]]:
    definition = _unit_definition(ureg, entry.name)
    symbols: list[str] = []
    names: list[str] = []
    candidates = [entry.name, *definition.aliases, *entry.extra_spellings]
    if definition.symbol and definition.symbol != "_":
        candidates.append(definition.symbol)
    if entry.symbol:
        candidates.append(entry.symbol)
    for spelling in candidates:
        if spelling in entry.skip_spellings or " " in spelling:  # `fl oz` is a display, not a token
            continue
        is_name = len(spelling) > _MAX_SYMBOL_LENGTH and spelling.isascii()
        (names if is_name else symbols).append(spelling)
    return symbols, names


def _plural(name: str) -> str | None:
    if name.islower() and name.isascii() and name[-1] not in "sxz":
        return name + "s"
    return None


@cache
def spelling_table() -> dict[str, _Spelling]:
    """Every accepted spelling (`km`, `kilometres`, `µs`, `°C`, `micromol`) mapped to its prefix and unit."""
    ureg = registry()
    table: dict[str, _Spelling] = {}

    def add(spelling: str, prefix: str, entry: CatalogueEntry) -> None:
        new = _Spelling(prefix, entry)
        old = table.get(spelling)
        # An unprefixed unit wins a clash with a prefixed one (the `ms` / `m·s` rule, one level down).
        if old is None or (old.prefix and not prefix):
            table[spelling] = new

    prefix_symbols: list[tuple[str, str]] = []
    prefix_names: list[tuple[str, str]] = []
    for prefix in SI_PREFIXES:
        definition = ureg._prefixes[prefix]
        prefix_names.append((prefix, prefix))
        prefix_symbols.append((prefix, definition.symbol))
        for alias in definition.aliases:
            (prefix_symbols if len(alias) == 1 else prefix_names).append((prefix, alias))

    for entry in CATALOGUE:
        symbols, names = _spellings_of_unit(ureg, entry)
        for symbol in symbols:
            add(symbol, "", entry)
        for name in names:
            plural = _plural(name)
            for form in (name, plural) if plural else (name,):
                add(form, "", entry)
    for entry in CATALOGUE:
        if not entry.prefixable:
            continue
        symbols, names = _spellings_of_unit(ureg, entry)
        for symbol in symbols:
            for prefix, prefix_symbol in prefix_symbols:
                add(prefix_symbol + symbol, prefix, entry)
            # A prefix spelled out before a symbol, as WeBWorK and chemists write it: `micromol`,
            # `nanomol`, `microN`, `millisec` (pint's names only: its `mc` and `mu` would make `mcd` a
            # microcandela; and not before `m`, `g`, `s`, `l`, making `kilos` a kilosecond).
            if len(symbol) == 1 and symbol.islower():
                continue
            for prefix in SI_PREFIXES:
                plural = _plural(prefix + symbol)
                for form in (prefix + symbol, plural) if plural else (prefix + symbol,):
                    add(form, prefix, entry)
        for name in names:
            plural = _plural(name)
            for prefix, prefix_name in prefix_names:
                for form in (name, plural) if plural else (name,):
                    add(prefix_name + form, prefix, entry)
    return table


def _dimension_of(ureg: pint.UnitRegistry[Fraction], name: str) -> Dimension:
    exponents: dict[str, Fraction] = {}
    for pint_dimension, power in ureg.get_dimensionality(name).items():
        exponents[PINT_DIMENSIONS[pint_dimension]] = _exact(power)
    return Dimension(exponents)


def _exact(number: object) -> Fraction:
    # The registry is built with non_int_type=Fraction, so factors are Fractions or ints, except where
    # pint's definition file writes a decimal in e-notation (`gauss = 1e-4 tesla`): that float's
    # shortest repr is the decimal written.
    if isinstance(number, float):
        return Fraction(repr(number))
    if not isinstance(number, Fraction | int):
        raise TypeError(f"pint gave an inexact factor {number!r}")
    return Fraction(number)


@cache
def _atom(prefix: str, entry: CatalogueEntry) -> UnitAtom:
    ureg = registry()
    definition = _unit_definition(ureg, entry.name)
    dimension = _dimension_of(ureg, entry.name)
    factor, root_units = ureg.get_root_units(entry.name)
    root_factor = _exact(factor)
    prefix_scale = _exact(ureg._prefixes[prefix].converter.scale) if prefix else Fraction(1)
    # pint's root unit of mass is the gram; SI's is the kilogram.
    mass_power = dimension.exponents.get("mass", Fraction(0))
    scale = prefix_scale * root_factor / Fraction(1000) ** int(mass_power)
    offset: Fraction | None = None
    converter_offset = getattr(definition.converter, "offset", 0)
    if converter_offset:
        # pint's converter: root value = value * scale + offset, so the offset is already in kelvin.
        offset = Fraction(converter_offset)
    unit_symbol = entry.symbol or definition.symbol or entry.name
    prefix_symbol = ureg._prefixes[prefix].symbol if prefix else ""
    prefix_latex = PREFIX_LATEX.get(prefix_symbol, prefix_symbol)
    if entry.latex is not None:
        latex = (rf"\mathrm{{{prefix_latex}}}" if prefix else "") + entry.latex
    else:
        latex = rf"\mathrm{{{prefix_latex}{unit_symbol}}}"
    return UnitAtom(
        name=prefix + entry.name,
        symbol=prefix_symbol + unit_symbol,
        latex=latex,
        scale=scale,
        dimension=dimension,
        offset=offset,
        si=entry.si,
        angle="radian" in root_units._units,
    )


def _found(spelling: str) -> _Spelling | None:
    table = spelling_table()
    found = table.get(spelling)
    if found is None:
        # Compatibility forms: the micro sign and the Greek mu, the ohm sign and capital omega, `ℓ`.
        found = table.get(unicodedata.normalize("NFKC", spelling))
    return found


def lookup(spelling: str) -> UnitAtom | None:
    """The unit a single spelling names (`ms`, `kN`, `µm`, `um`, `Ω`, `°C`), or None."""
    found = _found(spelling)
    return None if found is None else _atom(found.prefix, found.entry)


def lookup_piece(spelling: str) -> UnitAtom | None:
    """`lookup`, for a piece of a glued name: None for a unit that is never glued to others (`c`)."""
    found = _found(spelling)
    if found is None or not found.entry.in_products:
        return None
    return _atom(found.prefix, found.entry)


_MIN_NAME_LENGTH = 4


@cache
def pint_unit(name: str) -> UnitAtom | None:
    """A unit pint defines by this full name or long alias (`furlong`, `fortnight`, `barn`, plural
    `furlongs`) that the catalogue leaves out, or None: pint's definitions rather than a list of our
    own. Symbols (`gr` is pint's grain, to a student a gram) and prefixes stay the catalogue's; so do
    angles (pint's `cycle` is 2π rad, not the hertz's cycle) and units that are not a plain factor (dB).
    """
    if len(name) < _MIN_NAME_LENGTH or not name.isascii() or not name.replace("_", "").isalpha():
        return None
    ureg = registry()
    candidates = [name, name[:-1]] if name.endswith("s") and name.islower() else [name]
    for candidate in candidates:
        definition = ureg._units.get(candidate)
        if definition is None or candidate not in (definition.name, *definition.aliases):
            continue
        if not definition.is_multiplicative or definition.is_logarithmic:
            return None
        root = ureg.get_root_units(definition.name)[1]._units
        if "radian" in root or any(d not in PINT_DIMENSIONS for d in ureg.get_dimensionality(candidate)):
            return None
        shown = definition.name.replace("_", " ")
        entry = CatalogueEntry(
            definition.name, False, symbol=definition.name, latex=rf"\text{{{shown}}}", si=False
        )
        try:
            return _atom("", entry)
        except TypeError:  # an inexact factor: not a unit to grade with
            return None
    return None


@cache
def _by_folded_case() -> dict[str, str]:
    # Where several spellings share their letters, an unprefixed unit first: `ev` suggests eV, not EV
    # (the exavolt), `pa` Pa, not PA (the petaampere).
    table = spelling_table()
    index: dict[str, str] = {}
    for spelling in sorted(table, key=lambda spelling: (bool(table[spelling].prefix), spelling)):
        index.setdefault(spelling.casefold(), spelling)
    return index


@cache
def _folded_counts() -> dict[str, int]:
    counts: dict[str, int] = {}
    for spelling in spelling_table():
        counts[spelling.casefold()] = counts.get(spelling.casefold(), 0) + 1
    return counts


@cache
def _spellings_by_folded_case() -> dict[str, tuple[str, ...]]:
    table = spelling_table()
    index: dict[str, list[str]] = {}
    for spelling in sorted(table):
        index.setdefault(spelling.casefold(), []).append(spelling)
    return {folded: tuple(spellings) for folded, spellings in index.items()}


def case_variants(spelling: str) -> tuple[str, ...]:
    """Every accepted spelling that differs from `spelling` only in case: `Ks` → `kS`, `ks`; `PA` → `Pa`,
    `pA`. Where several fit, the dimension an answer must have may choose among them."""
    return tuple(s for s in _spellings_by_folded_case().get(spelling.casefold(), ()) if s != spelling)


def case_variant(spelling: str) -> str | None:
    """The one accepted spelling that differs from `spelling` only in case (`Kg` → `kg`), if exactly one
    does: `MM` has two (`mm`, `Mm`), so it has none."""
    folded = spelling.casefold()
    if _folded_counts().get(folded) != 1:
        return None
    match = _by_folded_case()[folded]
    return match if match != spelling else None


def suggestion(spelling: str) -> str | None:
    """A spelling that differs only in letter case (`KG` → `kg`), to help with an unknown unit."""
    match = _by_folded_case().get(spelling.casefold())
    return match if match != spelling else None


def prefixed_name(spelling: str) -> tuple[str, str] | None:
    """The symbol and the name of a unit typed as a prefix's symbol glued to the unit's name (`kJoules`,
    `mSeconds`): (`kJ`, `kilojoules`), to say what to type; None for other spellings. Never a reading:
    `mNewtons` may be m·N as well as mN."""
    ureg = registry()
    for prefix in SI_PREFIXES:
        symbol = ureg._prefixes[prefix].symbol
        rest = spelling[len(symbol) :]
        if not spelling.startswith(symbol) or len(rest) < 3 or not rest.isalpha():
            continue
        named = prefix + rest.lower()
        atom = lookup(named)
        if atom is not None and atom.symbol != named:
            return atom.symbol, named
    return None
