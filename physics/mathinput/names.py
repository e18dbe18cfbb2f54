"""Resolving words to declared names, constants and functions, including glued runs like `mgh`.

Spellings of one declared name: as declared, with its Greek name or letter swapped (`theta` and `θ`)
and, as aliases, with or without a subscript underscore (`v_0` and `v0`, `U0` and `U_0`). An alias
or a glued run is accepted only when it reads exactly one way.
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Literal

import sympy

from physics.mathinput.vocabulary import (
    EULER_SPELLING,
    FUNCTIONS,
    GREEK_LETTERS,
    GREEK_NAMES,
    LETTER_NAMES,
    PI_SPELLINGS,
)

PartKind = Literal["name", "const", "func"]

_TRAILING_DIGITS = re.compile(r"^([^\W\d_]+)(\d+)$")
# Words whose resolution a table keeps (each at most vocabulary.MAX_WORD_LENGTH letters).
_MAX_RESOLVED = 256


@dataclass(frozen=True, slots=True)
class Part:
    """One piece of a word: `canonical` is the declared spelling, `pi`/`e`, or a canonical function."""

    kind: PartKind
    canonical: str
    start: int  # offsets inside the word
    end: int


@dataclass(frozen=True, slots=True)
class Resolution:
    readings: tuple[tuple[Part, ...], ...]  # none, one, or two (the first two found) readings

    @property
    def unique(self) -> tuple[Part, ...] | None:
        return self.readings[0] if len(self.readings) == 1 else None


def _greek_swapped(name: str) -> str | None:
    """`theta_0` -> `θ_0` and `θ0` -> `theta0`: the same name in the other script."""
    if name and name[0] in GREEK_NAMES:
        return GREEK_NAMES[name[0]] + name[1:]
    for greek, letter in GREEK_LETTERS.items():
        if name.startswith(greek):
            rest = name[len(greek) :]
            if not rest or rest[0] == "_" or rest[0].isdigit():
                return letter + rest
    return None


def _subscript_aliases(name: str) -> list[str]:
    """`v_0` -> `v0`; `U0` -> `U_0`."""
    aliases = []
    if name.count("_") == 1 and not name.startswith("_") and not name.endswith("_"):
        aliases.append(name.replace("_", ""))
    match = _TRAILING_DIGITS.match(name)
    if match:
        aliases.append(f"{match.group(1)}_{match.group(2)}")
    return aliases


class NameTable:
    """The names one parse may use: the declared ones plus constants and functions."""

    def __init__(self, names: Mapping[str, sympy.Symbol]) -> None:
        self.symbols: dict[str, sympy.Symbol] = dict(names)
        self.declared: tuple[str, ...] = tuple(names)
        self._exact: dict[str, str] = {}
        pieces: dict[str, list[tuple[PartKind, str]]] = {}
        for name in self.declared:
            spellings = [name]
            swapped = _greek_swapped(name)
            if swapped is not None:
                spellings.append(swapped)
            spellings.extend(letter for letter, named in LETTER_NAMES.items() if named == name)
            for spelling in spellings:
                self._exact.setdefault(spelling, name)
            for spelling in spellings + [a for s in spellings for a in _subscript_aliases(s)]:
                entry = pieces.setdefault(spelling, [])
                if ("name", name) not in entry:
                    entry.append(("name", name))
        self.euler_available = EULER_SPELLING not in self._exact
        self._constants = {s: "pi" for s in PI_SPELLINGS if s not in self._exact}
        if self.euler_available:
            self._constants[EULER_SPELLING] = "e"
        self._functions = {typed: canon for typed, canon in FUNCTIONS.items() if typed not in self._exact}
        for spelling, const in self._constants.items():
            pieces.setdefault(spelling, []).append(("const", const))
        for typed, canon in self._functions.items():
            pieces.setdefault(typed, []).append(("func", canon))
        self._pieces = pieces
        self._longest_piece = max((len(p) for p in pieces), default=1)
        self._resolved: dict[str, Resolution] = {}

    def is_declared(self, word: str) -> bool:
        return word in self._exact

    def resolve(self, word: str) -> Resolution:
        """The readings of `word`: the same object for the same word (a table serves every answer to its
        part, whose words repeat: resolved once each, up to _MAX_RESOLVED words)."""
        found = self._resolved.get(word)
        if found is None:
            found = self._resolve(word)
            if len(self._resolved) < _MAX_RESOLVED:
                self._resolved[word] = found
        return found

    def _resolve(self, word: str) -> Resolution:
        if word in self._exact:
            return Resolution(((Part("name", self._exact[word], 0, len(word)),),))
        if word in self._functions:
            return Resolution(((Part("func", self._functions[word], 0, len(word)),),))
        if word in self._constants:
            return Resolution(((Part("const", self._constants[word], 0, len(word)),),))
        return Resolution(self._split(word))

    def _split(self, word: str) -> tuple[tuple[Part, ...], ...]:
        """Every way (up to two) to write `word` as consecutive known pieces, found right to left."""
        n = len(word)
        readings: list[list[tuple[Part, ...]]] = [[] for _ in range(n + 1)]
        readings[n] = [()]
        for i in range(n - 1, -1, -1):
            found = readings[i]
            for j in range(i + 1, min(n, i + self._longest_piece) + 1):
                for kind, canonical in self._pieces.get(word[i:j], ()):
                    for rest in readings[j]:
                        found.append((Part(kind, canonical, i, j), *rest))
                        if len(found) == 2:
                            break
                    if len(found) == 2:
                        break
                if len(found) == 2:
                    break
        return tuple(readings[0])
