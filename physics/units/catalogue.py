"""Which of pint's units a unit string may name, and how each is shown.

Data only: the conversion factors and dimensions come from pint (`physics.units.registry`). pint knows
thousands of units, some of which collide with the contract's reading of short strings (`Nm` would be
pint's "number_meter", `min` could be a milli-inch, `a` a year); accepting only these keeps `Nm` the
newton-metre, `ms` the millisecond, and rules out surprises.
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class CatalogueEntry:
    """One accepted pint unit (by its canonical pint name), whether SI prefixes apply, and its display."""

    name: str
    prefixable: bool
    symbol: str | None = None  # display symbol when pint's own is not the one students use
    latex: str | None = None  # LaTeX body when `\mathrm{symbol}` would be wrong
    # Spellings pint lacks: the contract promises `rev` and `°`; `mins`, `hrs` and `secs` would
    # otherwise be split into products (`min·s`), which no one means.
    extra_spellings: tuple[str, ...] = ()


CATALOGUE: tuple[CatalogueEntry, ...] = (
    # SI base units (pint's base for mass is the gram; kg is kilo + gram).
    CatalogueEntry("meter", True),
    CatalogueEntry("gram", True),
    CatalogueEntry("second", True, extra_spellings=("secs",)),
    CatalogueEntry("ampere", True),
    CatalogueEntry("kelvin", True),
    CatalogueEntry("mole", True),
    CatalogueEntry("candela", True),
    # SI derived units with special names.
    CatalogueEntry("radian", True),
    CatalogueEntry("hertz", True),
    CatalogueEntry("newton", True),
    CatalogueEntry("pascal", True),
    CatalogueEntry("joule", True),
    CatalogueEntry("watt", True),
    CatalogueEntry("coulomb", True),
    CatalogueEntry("volt", True),
    CatalogueEntry("farad", True),
    CatalogueEntry("ohm", True, latex=r"\Omega"),
    CatalogueEntry("siemens", True),
    CatalogueEntry("weber", True),
    CatalogueEntry("tesla", True),
    CatalogueEntry("henry", True),
    CatalogueEntry("lumen", True),
    CatalogueEntry("lux", True),
    CatalogueEntry("becquerel", True),
    CatalogueEntry("gray", True),
    CatalogueEntry("sievert", True),
    # Units accepted for use with the SI.
    CatalogueEntry("liter", True, symbol="L"),
    CatalogueEntry("electron_volt", True),
    CatalogueEntry("watt_hour", True),
    CatalogueEntry("bar", True),
    CatalogueEntry("minute", False, extra_spellings=("mins",)),
    CatalogueEntry("hour", False, extra_spellings=("hrs",)),
    CatalogueEntry("day", False),
    CatalogueEntry("degree", False, symbol="°", latex="{}^{\\circ}", extra_spellings=("°",)),
    CatalogueEntry("turn", False, symbol="rev", extra_spellings=("rev",)),
    CatalogueEntry("revolutions_per_minute", False),
    CatalogueEntry("degree_Celsius", False, latex="{}^{\\circ}\\mathrm{C}"),
    # Without it `°F` would be read as degree·farad, a capacitance.
    CatalogueEntry("degree_Fahrenheit", False, latex="{}^{\\circ}\\mathrm{F}"),
    CatalogueEntry("angstrom", False, latex=r"\text{Å}"),
    CatalogueEntry("unified_atomic_mass_unit", False),
    CatalogueEntry("dalton", False),
    CatalogueEntry("standard_atmosphere", False),
)

# The decimal SI prefixes, by pint name. Binary prefixes, and the 2022 ones (ronto r, quecto q,
# ronna R, quetta Q), are left out: no homework uses them, and they would make glued names such as
# `hrs` split in surprising ways.
SI_PREFIXES: tuple[str, ...] = (
    "yocto", "zepto", "atto", "femto", "pico", "nano", "micro", "milli", "centi", "deci",
    "deca", "hecto", "kilo", "mega", "giga", "tera", "peta", "exa", "zetta", "yotta",
)  # fmt: skip

# LaTeX for prefix symbols that are not plain Latin letters.
PREFIX_LATEX: dict[str, str] = {"µ": r"\mu "}

# Dimension names pint uses, mapped to `physics.dimensions.BASE_DIMENSIONS`.
PINT_DIMENSIONS: dict[str, str] = {
    "[mass]": "mass",
    "[length]": "length",
    "[time]": "time",
    "[current]": "current",
    "[temperature]": "temperature",
    "[substance]": "amount",
    "[luminosity]": "luminosity",
}
