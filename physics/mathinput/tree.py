"""The parse tree: how the student's text was grouped, before sympy reorders anything.

Both the sympy builder and the read-back renderers walk this tree, so what the student is shown is
exactly what was computed.

Nodes are never changed once made, but are not declared frozen: a frozen dataclass's __init__ sets each
field through object.__setattr__, four times the cost of a plain one, and an answer makes dozens of
nodes. unsafe_hash keeps the hash (and eq keeps the equality) that frozen gave.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from fractions import Fraction
from typing import Literal

PostfixKind = Literal["factorial", "percent", "degrees"]


@dataclass(slots=True, unsafe_hash=True)
class Num:
    literal: str  # as typed, normalized (4.58E-3 -> 4.58e-3)
    value: Fraction
    integer_literal: bool


@dataclass(slots=True, unsafe_hash=True)
class Name:
    name: str  # the declared spelling


@dataclass(slots=True, unsafe_hash=True)
class Const:
    which: Literal["pi", "e"]


@dataclass(slots=True, unsafe_hash=True)
class Neg:
    operand: Node


@dataclass(slots=True, unsafe_hash=True)
class Sum:
    first: Node
    rest: tuple[tuple[Literal["+", "-"], Node], ...]


@dataclass(slots=True, unsafe_hash=True)
class Product:
    """Left to right: `a/b*c` is (a/b)*c. Juxtaposition is stored as `*`."""

    first: Node
    rest: tuple[tuple[Literal["*", "/"], Node], ...]


@dataclass(slots=True, unsafe_hash=True)
class Power:
    base: Node
    exponent: Node
    pos: int = field(default=0, compare=False)  # of the ^ (for size errors)
    typed: str | None = field(default=None, compare=False)  # as Call.typed: `e^2x`, `(2gh)^1/2`


@dataclass(slots=True, unsafe_hash=True)
class Call:
    func: str  # canonical function name (vocabulary.FUNCTIONS values)
    arg: Node
    pos: int = field(default=0, compare=False)
    # As typed (`sin x/2`), where how far the argument reaches was a choice, not typed: a division's
    # question shows it so, not as the reading tried.
    typed: str | None = field(default=None, compare=False)


@dataclass(slots=True, unsafe_hash=True)
class Postfix:
    kind: PostfixKind
    operand: Node
    pos: int = field(default=0, compare=False)


@dataclass(slots=True, unsafe_hash=True)
class Group:
    """Brackets the student typed; kept so grouping rules can see them, invisible when rendered."""

    inner: Node


Node = Num | Name | Const | Neg | Sum | Product | Power | Call | Postfix | Group


def ungroup(node: Node) -> Node:
    while isinstance(node, Group):
        node = node.inner
    return node
