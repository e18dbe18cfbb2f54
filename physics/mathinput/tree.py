"""The parse tree: how the student's text was grouped, before sympy reorders anything.

Both the sympy builder and the read-back renderers walk this tree, so what the student is shown is
exactly what was computed.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from fractions import Fraction
from typing import Literal

PostfixKind = Literal["factorial", "percent", "degrees"]


@dataclass(frozen=True, slots=True)
class Num:
    literal: str  # as typed, normalized (4.58E-3 -> 4.58e-3)
    value: Fraction
    integer_literal: bool


@dataclass(frozen=True, slots=True)
class Name:
    name: str  # the declared spelling


@dataclass(frozen=True, slots=True)
class Const:
    which: Literal["pi", "e"]


@dataclass(frozen=True, slots=True)
class Neg:
    operand: Node


@dataclass(frozen=True, slots=True)
class Sum:
    first: Node
    rest: tuple[tuple[Literal["+", "-"], Node], ...]


@dataclass(frozen=True, slots=True)
class Product:
    """Left to right: `a/b*c` is (a/b)*c. Juxtaposition is stored as `*`."""

    first: Node
    rest: tuple[tuple[Literal["*", "/"], Node], ...]


@dataclass(frozen=True, slots=True)
class Power:
    base: Node
    exponent: Node
    pos: int = field(default=0, compare=False)  # of the ^ (for size errors)


@dataclass(frozen=True, slots=True)
class Call:
    func: str  # canonical function name (vocabulary.FUNCTIONS values)
    arg: Node
    pos: int = field(default=0, compare=False)


@dataclass(frozen=True, slots=True)
class Postfix:
    kind: PostfixKind
    operand: Node
    pos: int = field(default=0, compare=False)


@dataclass(frozen=True, slots=True)
class Group:
    """Brackets the student typed; kept so grouping rules can see them, invisible when rendered."""

    inner: Node


Node = Num | Name | Const | Neg | Sum | Product | Power | Call | Postfix | Group


def ungroup(node: Node) -> Node:
    while isinstance(node, Group):
        node = node.inner
    return node
