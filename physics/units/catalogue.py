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
    si: bool = True  # an SI unit or one accepted for use with it (SI brochure, table 8)
    # pint spellings left out: `a` (year) and `G` (gauss) would turn glued names into surprises.
    skip_spellings: tuple[str, ...] = ()
    # Whether a glued name may be split into it: `c` is the speed of light alone (`0.8 c`, `MeV/c^2`),
    # never a piece of `mc` (the millicoulomb in lower case).
    in_products: bool = True


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
    CatalogueEntry("steradian", True),
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
    CatalogueEntry("watt_hour", True, si=False),
    CatalogueEntry("minute", False, extra_spellings=("mins",)),
    CatalogueEntry("hour", False, extra_spellings=("hrs",)),
    CatalogueEntry("day", False, extra_spellings=("days",)),
    CatalogueEntry("degree", False, symbol="°", latex="{}^{\\circ}", extra_spellings=("°",)),
    CatalogueEntry("turn", False, symbol="rev", extra_spellings=("rev",), si=False),
    CatalogueEntry("revolutions_per_minute", False, si=False),
    CatalogueEntry("degree_Celsius", False, latex="{}^{\\circ}\\mathrm{C}"),
    # Without it `°F` would be read as degree·farad, a capacitance.
    CatalogueEntry("degree_Fahrenheit", False, latex="{}^{\\circ}\\mathrm{F}", si=False),
    CatalogueEntry("angstrom", False, latex=r"\text{Å}", si=False),
    CatalogueEntry("unified_atomic_mass_unit", False),
    CatalogueEntry("dalton", True),  # kDa, as biophysics writes a protein's mass
    CatalogueEntry("astronomical_unit", False),
    CatalogueEntry("katal", True),
    # Units beyond SI that courses use; each from pint's definitions (factor and dimension).
    CatalogueEntry("standard_atmosphere", False, si=False),
    CatalogueEntry("bar", True, si=False),
    CatalogueEntry("foot", False, si=False),
    CatalogueEntry("inch", False, si=False),
    CatalogueEntry("mile", False, si=False),
    CatalogueEntry("yard", False, si=False),
    CatalogueEntry("mile_per_hour", False, si=False),
    CatalogueEntry("knot", False, si=False),
    CatalogueEntry("pound", False, si=False),
    CatalogueEntry("force_pound", False, si=False),
    CatalogueEntry("slug", False, si=False),
    CatalogueEntry("pound_force_per_square_inch", False, si=False),
    CatalogueEntry("torr", False, si=False),
    CatalogueEntry("meter_Hg", True, si=False, skip_spellings=("m_Hg",)),  # mmHg is milli + mHg
    CatalogueEntry("calorie", True, si=False),
    CatalogueEntry("british_thermal_unit", False, si=False),
    CatalogueEntry("horsepower", False, si=False),
    CatalogueEntry("dyne", False, si=False),
    CatalogueEntry("erg", False, si=False),
    # pint's `gauss` is the Gaussian-system unit, not commensurable with the tesla; courses mean 1e-4 T.
    CatalogueEntry("gauss_tesla", False, symbol="G", extra_spellings=("gauss", "G"), si=False),
    CatalogueEntry("light_year", False, si=False),
    CatalogueEntry("parsec", True, si=False),  # kpc, Mpc
    CatalogueEntry(
        "year", True, symbol="yr", si=False, skip_spellings=("a", "julian_year"), extra_spellings=("yrs",)
    ),  # Myr, Gyr
    # Volumes, masses and forces of US courses (pint's US customary definitions).
    CatalogueEntry("gallon", False, si=False, extra_spellings=("gals",)),
    CatalogueEntry("quart", False, si=False),
    CatalogueEntry("pint", False, si=False),
    # pint's `cp` is left out: it is the centipoise to a chemist.
    CatalogueEntry("cup", False, symbol="cup", si=False, extra_spellings=("cups",), skip_spellings=("cp",)),
    CatalogueEntry("fluid_ounce", False, symbol="fl oz", latex=r"\mathrm{fl\,oz}", si=False),
    CatalogueEntry("ounce", False, si=False),
    CatalogueEntry("force_ounce", False, si=False),
    CatalogueEntry("kip", False, si=False, extra_spellings=("kips",)),
    CatalogueEntry("kip_per_square_inch", False, si=False),
    CatalogueEntry("force_kilogram", False, si=False),
    CatalogueEntry("force_gram", False, si=False, skip_spellings=("pond",)),
    CatalogueEntry("inch_Hg", False, si=False),
    # pint's `th` is left out: no one types it, and it would split glued names.
    CatalogueEntry("thou", False, symbol="thou", skip_spellings=("th",), si=False),
    CatalogueEntry("mil", False, si=False),  # pint's: the angular mil (a length in mil is `thou`)
    CatalogueEntry("nautical_mile", False, si=False),
    # Shown as `tonne`: pint's `t` is left out, being the tesla in lower case.
    CatalogueEntry("metric_ton", False, symbol="tonne", skip_spellings=("t",), si=False),
    CatalogueEntry("hectare", False, si=False),
    CatalogueEntry("acre", False, si=False),
    # Shown as the micrometre it is; pint's `µ` alone is left out, being a prefix everywhere else.
    CatalogueEntry(
        "micron", False, symbol="µm", latex=r"\mathrm{\mu m}", skip_spellings=("µ", "μ", "µm"), si=False
    ),
    CatalogueEntry("arcminute", False, si=False),
    CatalogueEntry("arcsecond", False, si=False),
    CatalogueEntry("revolutions_per_second", False, si=False),
    CatalogueEntry("counts_per_second", False, si=False),
    CatalogueEntry("galileo", True, si=False),  # Gal, mGal: gravimetry's cm/s²
    CatalogueEntry("curie", True, si=False),
    CatalogueEntry("rem", True, si=False),
    CatalogueEntry("ampere_hour", True, si=False),  # Ah, mAh: a battery's charge
    CatalogueEntry("speed_of_light", False, symbol="c", si=False, in_products=False),  # 0.8 c, MeV/c^2
    # An acceleration in gees (`3.2 g0`, and `3.2 g` where an acceleration is expected, MEANINGS).
    CatalogueEntry(
        "standard_gravity",
        False,
        symbol="g0",
        latex="g_{0}",
        si=False,
        skip_spellings=("gravity",),
        extra_spellings=("gn", "gee", "gees"),  # gn as g_n is written, without its underscore
    ),
)

# Common spellings that are not pint's, each read as the unit expression it stands for. They win over
# splitting a glued name into units: `ohms` is the ohm, never ohm·second; `mcg` a microgram, never
# milli·centigram. Plurals of long names (`volts`, `newtons`) need no entry: they are made for every
# name; these are the short ones.
ALIASES: dict[str, str] = {
    "ohms": "ohm", "Ohm": "ohm", "Ohms": "ohm", "rads": "rad", "degs": "°", "revs": "rev",
    "amps": "A", "gm": "g", "gms": "g", "kgs": "kg", "mcg": "µg", "kilo": "kg", "kilos": "kg",
    "lbm": "lb", "ftlb": "ft·lbf", "ftlbs": "ft·lbf",
    "kph": "km/h", "kmh": "km/h", "kmph": "km/h", "kmhr": "km/h", "mps": "m/s", "kmps": "km/s", "cc": "cm^3", "AU": "au",
    # The SI brochure's elided forms; `Cal` is the dietary calorie, the kilocalorie.
    "kilohm": "kΩ", "kilohms": "kΩ", "megohm": "MΩ", "megohms": "MΩ", "Cal": "kcal", "Cals": "kcal",
    # `ms-1` is how many textbooks print m·s⁻¹; no one writes a reciprocal millisecond that way.
    "ms-1": "m/s", "ms-2": "m/s^2",
    # The one-character degree Celsius and Fahrenheit signs, and the degree typed as a letter o
    "℃": "°C", "℉": "°F", "oC": "°C", "oF": "°F",
    # and the degree sign typed after the scale's letter (`25 C°`): never a coulomb times a degree
    "C°": "°C", "F°": "°F",
    # The raised c that British texts mark a radian with (`1.2ᶜ`): compatibility folding made it a c,
    # the speed of light
    "ᶜ": "rad",
}  # fmt: skip

# Spellings with more than one meaning, each meaning a unit spelling. The first is pint's, taken where no
# dimension is expected (an author's units); where one is, the meaning with that dimension is taken and
# said, and a spelling that no meaning fits is refused with all of them.
MEANINGS: dict[str, tuple[str, ...]] = {
    "lb": ("lb", "lbf"),  # the pound, or the pound-force as US courses write a weight (50 lb, ft·lb)
    "lbs": ("lb", "lbf"),
    "oz": ("oz", "floz", "ozf"),  # mass, volume (a fluid ounce) or force
    "Gal": ("Gal", "gal"),  # the galileo (cm/s²), or the gallon in capitals
    "mil": ("mil", "thou"),  # the angular mil, or a thousandth of an inch
    "c": ("c", "C", "°C"),  # the speed of light, or the coulomb or degrees Celsius in lower case
    "g": ("g", "g0"),  # the gram, or an acceleration in gees (`0.47 g`)
    # Gees as `5 gs` (and `5 g's`) are said, or grams; never the gram-second its letters would split into.
    "gs": ("g0", "g"),
    "C": ("C", "°C"),  # the coulomb, or degrees Celsius as typed without the degree sign (`27 C`)
    "F": ("F", "°F"),  # the farad, or degrees Fahrenheit (`80 F`)
}

# Spellings that are an angle unit to some students and another to others, refused with both (and never
# split, nor read by a prefix): `30 Grad` is 30° in German, 30 gradians (0.9° each) in French and Polish
# use; its letters would otherwise read as a gigaradian (G·rad), and `grad` as a gram-radian.
TWO_ANGLE_SPELLINGS: dict[str, tuple[str, str]] = dict.fromkeys(
    ("grad", "Grad", "grads", "Grads"), ("degrees (°)", "gradians (0.9° each)")
)

# Spellings that end in digits, which the lexer would otherwise read as a power (`g0` as g^0).
SPELLINGS_WITH_DIGITS = frozenset({"g0", "g_0"})

# Spellings of MEANINGS whose first meaning is what nearly everyone means: where no meaning has the
# expected dimension, the answer is graded in that one (a wrong dimension) instead of refused.
FIRST_WHERE_NONE_FITS = frozenset({"g", "gs", "C", "F"})

# The decimal SI prefixes, by pint name. Binary prefixes, and the 2022 ones (ronto r, quecto q,
# ronna R, quetta Q), are left out: no homework uses them, and they would make glued names such as
# `hrs` split in surprising ways.
SI_PREFIXES: tuple[str, ...] = (
    "yocto", "zepto", "atto", "femto", "pico", "nano", "micro", "milli", "centi", "deci",
    "deca", "hecto", "kilo", "mega", "giga", "tera", "peta", "exa", "zetta", "yotta",
)  # fmt: skip

_PREFIX_SYMBOL_LIST = (
    "y", "z", "a", "f", "p", "n", "µ", "m", "c", "d", "da", "h", "k", "M", "G", "T", "P", "E", "Z", "Y",
)  # fmt: skip

# Each prefix's symbol, for a prefix said apart from a unit's symbol (`micro s`, `kilo m`); the Greek
# letter's name and the letter typed apart (`mu s`, `µ s`) are the micro sign too.
PREFIX_SYMBOLS: dict[str, str] = {
    **dict(zip(SI_PREFIXES, _PREFIX_SYMBOL_LIST, strict=True)),
    "mu": "µ",
    "µ": "µ",
    "μ": "µ",
}

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
