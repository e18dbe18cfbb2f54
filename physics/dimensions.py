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

    def __mul__(self, other: Dimension) -> Dimension:
        return Dimension([*self._exponents, *other._exponents])

    def __truediv__(self, other: Dimension) -> Dimension:
        return Dimension([*self._exponents, *((b, -p) for b, p in other._exponents)])

    def __pow__(self, power: Fraction | int) -> Dimension:
        return Dimension((b, p * Fraction(power)) for b, p in self._exponents)

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Dimension) and self._exponents == other._exponents

    def __hash__(self) -> int:
        return hash(self._exponents)

    def __repr__(self) -> str:
        if not self._exponents:
            return "Dimension(dimensionless)"
        return "Dimension(" + ", ".join(f"{b}^{p}" for b, p in self._exponents) + ")"


DIMENSIONLESS = Dimension()
