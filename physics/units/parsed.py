"""ParsedUnits: a product of units with integer powers, its dimension, display and exact conversion.

Temperature convention: `°C` on its own (power 1, nothing else) is an absolute temperature, so
25 °C converts to 298.15 K. Inside any compound unit (`J/(kg·°C)`, `°C/s`, `°C^2`) it is a temperature
difference, the same size as the kelvin, because an offset has no meaning in a product.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from dataclasses import dataclass
from fractions import Fraction
from functools import cached_property

from physics.dimensions import DIMENSIONLESS, Dimension
from physics.units.registry import UnitAtom


class IncompatibleUnits(ValueError):
    """A conversion between units of different dimensions was asked for."""

    def __init__(self, source: ParsedUnits, target: ParsedUnits) -> None:
        super().__init__(f"cannot convert {source.text} to {target.text}: the dimensions differ")
        self.source = source
        self.target = target


@dataclass(frozen=True)
class ParsedUnits:
    """Units as read from a unit string, merged: `m/s/s` is m·s⁻², with each unit once, in order."""

    factors: tuple[tuple[UnitAtom, int], ...]

    @staticmethod
    def of(factors: Iterable[tuple[UnitAtom, int]]) -> ParsedUnits:
        """Merge repeated units (first appearance keeps its place) and drop those whose powers cancel."""
        powers: dict[str, int] = {}
        atoms: dict[str, UnitAtom] = {}
        for atom, power in factors:
            atoms.setdefault(atom.name, atom)
            powers[atom.name] = powers.get(atom.name, 0) + power
        return ParsedUnits(tuple((atoms[name], p) for name, p in powers.items() if p != 0))

    def __mul__(self, other: ParsedUnits) -> ParsedUnits:
        return ParsedUnits.of([*self.factors, *other.factors])

    def __truediv__(self, other: ParsedUnits) -> ParsedUnits:
        return ParsedUnits.of([*self.factors, *((a, -p) for a, p in other.factors)])

    def __pow__(self, power: int) -> ParsedUnits:
        return ParsedUnits.of((a, p * power) for a, p in self.factors)

    @property
    def is_dimensionless_number(self) -> bool:
        """No units at all (`1`, or units that cancelled): a pure number."""
        return not self.factors

    @cached_property
    def dimension(self) -> Dimension:
        result = DIMENSIONLESS
        for atom, power in self.factors:
            result = result * atom.dimension**power
        return result

    @cached_property
    def scale(self) -> Fraction:
        """The SI value of one of these units (1 km/h → 5/18)."""
        result = Fraction(1)
        for atom, power in self.factors:
            result *= atom.scale**power
        return result

    @property
    def offset(self) -> Fraction:
        """SI value of this unit's zero: non-zero only for a lone offset unit (`°C`)."""
        if len(self.factors) == 1:
            atom, power = self.factors[0]
            if power == 1 and atom.offset is not None:
                return atom.offset
        return Fraction(0)

    def to_si(self, value: Fraction) -> Fraction:
        return value * self.scale + self.offset

    def from_si(self, value: Fraction) -> Fraction:
        return (value - self.offset) / self.scale

    def convert(self, value: Fraction, target: ParsedUnits) -> Fraction:
        """`value` in these units, expressed exactly in `target` units; IncompatibleUnits if they differ."""
        if self.dimension != target.dimension:
            raise IncompatibleUnits(self, target)
        return target.from_si(self.to_si(value))

    @cached_property
    def text(self) -> str:
        """Canonical plain text: `m/s^2`, `N·m`, `J/(kg·K)`, `1/s`, `1` for no units."""
        return _render(self.factors, _text_power, "·", "1")

    @cached_property
    def latex(self) -> str:
        """LaTeX: `\\mathrm{m}/\\mathrm{s}^{2}`, `\\mathrm{N}\\cdot\\mathrm{m}`."""
        return _render(self.factors, _latex_power, r"\cdot ", "1")

    def __str__(self) -> str:
        return self.text


def _text_power(atom: UnitAtom, power: int) -> str:
    return atom.symbol if power == 1 else f"{atom.symbol}^{power}"


def _latex_power(atom: UnitAtom, power: int) -> str:
    return atom.latex if power == 1 else f"{atom.latex}^{{{power}}}"


def _render(
    factors: tuple[tuple[UnitAtom, int], ...], show: Callable[[UnitAtom, int], str], times: str, one: str
) -> str:
    numerator = [show(a, p) for a, p in factors if p > 0]
    denominator = [show(a, -p) for a, p in factors if p < 0]
    top = times.join(numerator) if numerator else one
    if not denominator:
        return top
    bottom = times.join(denominator)
    return f"{top}/({bottom})" if len(denominator) > 1 else f"{top}/{bottom}"
