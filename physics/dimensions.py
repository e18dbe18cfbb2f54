"""Physical dimensions as exponent vectors over the SI base dimensions.

A Dimension is immutable and hashable; products and powers combine exponents (as Fractions, so
sqrt(length) is representable). Unit strings are turned into Dimensions by `physics.units`.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from fractions import Fraction

BASE_DIMENSIONS = ("mass", "length", "time", "current", "temperature", "amount", "luminosity")


class Dimension:
    __slots__ = ("_exponents",)

    def __init__(self, exponents: Mapping[str, Fraction | int] | Iterable[tuple[str, Fraction | int]] = ()):
        items = exponents.items() if isinstance(exponents, Mapping) else exponents
        clean: dict[str, Fraction] = {}
        for base, power in items:
            if base not in BASE_DIMENSIONS:
                raise ValueError(f"unknown base dimension {base!r}")
            clean[base] = clean.get(base, Fraction(0)) + Fraction(power)
        self._exponents = tuple(sorted((b, p) for b, p in clean.items() if p != 0))

    @property
    def exponents(self) -> dict[str, Fraction]:
        return dict(self._exponents)

    @property
    def is_dimensionless(self) -> bool:
        return not self._exponents

    @classmethod
    def _of(cls, exponents: dict[str, Fraction]) -> Dimension:
        """From exponents already checked and made Fractions (those of Dimensions): what __init__ would
        build of them, without checking and converting each again (dimensions are combined per node of
        every wrong answer's tree)."""
        made = cls.__new__(cls)
        made._exponents = tuple(sorted((b, p) for b, p in exponents.items() if p != 0))
        return made

    def __mul__(self, other: Dimension) -> Dimension:
        # Most factors of a physics expression are pure numbers: no new Dimension to build.
        if not other._exponents:
            return self
        if not self._exponents:
            return other
        exponents = dict(self._exponents)
        for base, power in other._exponents:
            exponents[base] = exponents.get(base, 0) + power
        return Dimension._of(exponents)

    def __truediv__(self, other: Dimension) -> Dimension:
        exponents = dict(self._exponents)
        for base, power in other._exponents:
            exponents[base] = exponents.get(base, 0) - power
        return Dimension._of(exponents)

    def __pow__(self, power: Fraction | int) -> Dimension:
        power = Fraction(power)
        return Dimension._of({b: p * power for b, p in self._exponents})

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Dimension) and self._exponents == other._exponents

    def __hash__(self) -> int:
        return hash(self._exponents)

    def __repr__(self) -> str:
        if not self._exponents:
            return "Dimension(dimensionless)"
        return "Dimension(" + ", ".join(f"{b}^{p}" for b, p in self._exponents) + ")"


DIMENSIONLESS = Dimension()


def _dim(**exponents: int) -> Dimension:
    return Dimension(exponents)


# Common dimensions named for feedback. Where two quantities share a dimension, the one a mechanics
# student most often means comes first (a torque reads as "an energy": N·m and J are the same).
_NAMED: dict[Dimension, str] = {
    DIMENSIONLESS: "a pure number",
    _dim(mass=1): "a mass",
    _dim(length=1): "a length",
    _dim(time=1): "a time",
    _dim(current=1): "a current",
    _dim(temperature=1): "a temperature",
    _dim(amount=1): "an amount of substance",
    _dim(luminosity=1): "a luminous intensity",
    _dim(length=2): "an area",
    _dim(length=3): "a volume",
    _dim(length=1, time=-1): "a speed",
    _dim(length=1, time=-2): "an acceleration",
    _dim(time=-1): "an angular frequency or rate",
    _dim(time=-2): "an angular acceleration",
    _dim(mass=1, length=1, time=-2): "a force",
    _dim(mass=1, length=2, time=-2): "an energy",
    _dim(mass=1, length=2, time=-3): "a power",
    _dim(mass=1, length=-1, time=-2): "a pressure",
    _dim(mass=1, length=1, time=-1): "a momentum",
    _dim(mass=1, length=2, time=-1): "an angular momentum",
    _dim(mass=1, length=2): "a moment of inertia",
    _dim(mass=1, time=-2): "a spring constant",
    _dim(mass=1, length=-3): "a density",
    _dim(mass=1, time=-1): "a mass flow rate",
    _dim(length=3, time=-1): "a volume flow rate",
    _dim(length=2, time=-2, temperature=-1): "a specific heat capacity",
    _dim(mass=1, length=2, time=-2, temperature=-1): "a heat capacity",
    _dim(current=1, time=1): "an electric charge",
    _dim(mass=1, length=2, time=-3, current=-1): "a voltage",
    _dim(mass=1, length=2, time=-3, current=-2): "a resistance",
    _dim(mass=-1, length=-2, time=4, current=2): "a capacitance",
    _dim(mass=1, length=2, time=-2, current=-2): "an inductance",
    _dim(mass=1, time=-2, current=-1): "a magnetic field",
    _dim(mass=1, length=1, time=-3, current=-1): "an electric field",
    _dim(mass=-1, length=3, time=-2): "a gravitational constant",
}

_SI_SYMBOLS = {
    "mass": "kg",
    "length": "m",
    "time": "s",
    "current": "A",
    "temperature": "K",
    "amount": "mol",
    "luminosity": "cd",
}
_SI_ORDER = ("mass", "length", "time", "current", "temperature", "amount", "luminosity")
_SUPERSCRIPTS = str.maketrans("0123456789", "⁰¹²³⁴⁵⁶⁷⁸⁹")


def _si_power(base: str, power: Fraction) -> str:
    symbol = _SI_SYMBOLS[base]
    if power == 1:
        return symbol
    if power.denominator == 1:
        return symbol + str(power.numerator).translate(_SUPERSCRIPTS)
    return f"{symbol}^({power})"


def si_form(dim: Dimension) -> str:
    """The dimension as SI base units: `kg·m²/s³`, `1/s`, `kg/(m·s²)`, `1` for a pure number."""
    exponents = dim.exponents
    top = [_si_power(b, exponents[b]) for b in _SI_ORDER if exponents.get(b, 0) > 0]
    bottom = [_si_power(b, -exponents[b]) for b in _SI_ORDER if exponents.get(b, 0) < 0]
    numerator = "·".join(top) if top else "1"
    if not bottom:
        return numerator
    denominator = "·".join(bottom)
    return f"{numerator}/({denominator})" if len(bottom) > 1 else f"{numerator}/{denominator}"


def describe(dim: Dimension) -> str:
    """A phrase naming the quantity, for feedback: "a force", "an acceleration", "a pure number".

    Falls back to the SI form ("a quantity in kg·m²/s³") for dimensions without a common name.
    """
    named = _NAMED.get(dim)
    if named is not None:
        return named
    return f"a quantity in {si_form(dim)}"
