"""Resolving words to declared names, constants and functions, including glued runs like `mgh`.

Spellings of one declared name: as declared, with its Greek name or letter swapped (`theta` and `θ`)
and, as aliases, with or without a subscript underscore (`v_0` and `v0`, `U0` and `U_0`). An alias
or a glued run is accepted only when it reads exactly one way.
"""

from __future__ import annotations

import re
from collections.abc import Mapping, Sequence
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
    for greek, letter in _GREEK_BY_INITIAL.get(name[:1], ()):
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


# GREEK_LETTERS' items by the initial of the name, in their order: a name is compared only with those.
_GREEK_BY_INITIAL: dict[str, list[tuple[str, str]]] = {}
for _greek, _letter in GREEK_LETTERS.items():
    _GREEK_BY_INITIAL.setdefault(_greek[:1], []).append((_greek, _letter))
_ALL_FUNCTIONS = dict(FUNCTIONS)
# The constants' and functions' pieces, as every table has them unless a declared name takes the spelling.
_BASE_CONSTANTS = {**{s: "pi" for s in PI_SPELLINGS}, EULER_SPELLING: "e"}
_BASE_PIECES: dict[str, tuple[tuple[PartKind, str], ...]] = {}
for _spelling, _const in _BASE_CONSTANTS.items():
    _BASE_PIECES[_spelling] = (*_BASE_PIECES.get(_spelling, ()), ("const", _const))
for _typed, _canon in FUNCTIONS.items():
    _BASE_PIECES[_typed] = (*_BASE_PIECES.get(_typed, ()), ("func", _canon))
_BASE_LONGEST = max(len(p) for p in _BASE_PIECES)
# The letters that stand for each name (`ħ` for `hbar`).
_LETTERS_OF: dict[str, list[str]] = {}
for _letter, _named in LETTER_NAMES.items():
    _LETTERS_OF.setdefault(_named, []).append(_letter)


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
            spellings.extend(_LETTERS_OF.get(name, ()))
            for spelling in spellings:
                self._exact.setdefault(spelling, name)
            for spelling in spellings + [a for s in spellings for a in _subscript_aliases(s)]:
                entry = pieces.setdefault(spelling, [])
                if ("name", name) not in entry:
                    entry.append(("name", name))
        exact = self._exact
        self.euler_available = EULER_SPELLING not in exact
        self._constants = {s: c for s, c in _BASE_CONSTANTS.items() if s not in exact}
        # Shared by the tables whose names take no function's spelling (the usual case): only read.
        self._functions = (
            _ALL_FUNCTIONS
            if exact.keys().isdisjoint(_ALL_FUNCTIONS)
            else {typed: canon for typed, canon in FUNCTIONS.items() if typed not in exact}
        )
        # The constants' and functions' pieces but those a declared name takes; a declared name's pieces
        # first, then the constant's or function's of the same spelling.
        merged: dict[str, Sequence[tuple[PartKind, str]]] = dict(_BASE_PIECES)
        longest = _BASE_LONGEST
        if not exact.keys().isdisjoint(_BASE_PIECES):
            for spelling in exact:
                merged.pop(spelling, None)
            longest = max((len(p) for p in merged), default=1)
        for spelling, entries in pieces.items():
            found = merged.get(spelling)
            merged[spelling] = entries if found is None else (*entries, *found)
            longest = max(longest, len(spelling))
        self._pieces = merged
        self._longest_piece = longest
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
