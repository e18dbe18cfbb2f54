"""Reading the expressions inside a model file: instructor text, so never evaluated.

Every model expression goes through `read_expr`. It uses the project's whitelist parser
`physics.mathinput.parse_math` when that is available, and otherwise a minimal whitelist parser of
its own (numbers, declared names, + - * / ^ **, parentheses and a few functions), which builds the
sympy tree with constructors only.
"""

from __future__ import annotations

import importlib
import re
from collections.abc import Callable, Mapping
from typing import Any

import sympy

from physics.errors import AnswerError, ParseError, SpecError, UnknownFunction, UnknownSymbol

Path = tuple[str | int, ...]

_FUNCTIONS: Mapping[str, Callable[[sympy.Expr], sympy.Expr]] = {
    "sin": sympy.sin,
    "cos": sympy.cos,
    "tan": sympy.tan,
    "sqrt": sympy.sqrt,
    "exp": sympy.exp,
    "ln": sympy.log,
    "log": sympy.log,
    "asin": sympy.asin,
    "acos": sympy.acos,
    "atan": sympy.atan,
}
_CONSTANTS: Mapping[str, sympy.Expr] = {"pi": sympy.pi, "π": sympy.pi}
_TOKEN = re.compile(r"\s*(?:(\d+(?:\.\d*)?(?:[eE][+-]?\d+)?)|([A-Za-z_π][A-Za-z_0-9]*)|(\*\*|[-+*/^(),]))")
MAX_TEXT = 2000


def read_expr(text: object, names: Mapping[str, sympy.Symbol], path: Path) -> sympy.Expr:
    """The expression written in `text`, over `names`; a SpecError at `path` if it cannot be read."""
    if isinstance(text, bool) or not isinstance(text, str | int | float):
        raise SpecError(f"expected an expression (text or number), got {type(text).__name__}", path)
    source = str(text)
    if len(source) > MAX_TEXT:
        raise SpecError(f"expression longer than {MAX_TEXT} characters", path)
    try:
        project = _project_parser()
        if project is not None:
            return _as_expr(project(source, names).expr, source, path)
        return _Parser(source, names).parse()
    except AnswerError as error:
        raise SpecError(f"cannot read {source!r}: {error.message}", path) from error


def _as_expr(value: Any, source: str, path: Path) -> sympy.Expr:
    if not isinstance(value, sympy.Expr):
        raise SpecError(f"{source!r} is not an expression", path)
    return value


def _project_parser() -> Callable[[str, Mapping[str, sympy.Symbol]], Any] | None:
    try:
        module = importlib.import_module("physics.mathinput")
    except ImportError:
        return None
    parser = getattr(module, "parse_math", None)
    return parser if callable(parser) else None


class _Parser:
    """expr := term (('+'|'-') term)*; term := unary (('*'|'/') unary)*; unary := '-' unary | power;
    power := atom (('^'|'**') unary)?; atom := number | name | name '(' expr ')' | '(' expr ')'."""

    def __init__(self, source: str, names: Mapping[str, sympy.Symbol]) -> None:
        self.source = source
        self.names = names
        self.tokens: list[tuple[str, str, int]] = []
        position = 0
        while position < len(source):
            match = _TOKEN.match(source, position)
            if match is None or match.end() == position:
                if source[position:].strip() == "":
                    break
                raise ParseError(f"unexpected character {source[position]!r}", position)
            kind = "num" if match.group(1) else "name" if match.group(2) else "op"
            self.tokens.append((kind, match.group(match.lastindex or 0), match.start(match.lastindex or 0)))
            position = match.end()
        self.index = 0

    def parse(self) -> sympy.Expr:
        if not self.tokens:
            raise ParseError("empty expression", 0)
        result = self._expr()
        if self.index < len(self.tokens):
            raise ParseError(f"unexpected {self.tokens[self.index][1]!r}", self.tokens[self.index][2])
        return result

    def _peek(self) -> str | None:
        return self.tokens[self.index][1] if self.index < len(self.tokens) else None

    def _take(self) -> tuple[str, str, int]:
        if self.index >= len(self.tokens):
            raise ParseError("unexpected end of expression", len(self.source))
        token = self.tokens[self.index]
        self.index += 1
        return token

    def _expect(self, op: str) -> None:
        kind, text, position = self._take()
        if kind != "op" or text != op:
            raise ParseError(f"expected {op!r}, found {text!r}", position)

    def _expr(self) -> sympy.Expr:
        result = self._term()
        while self._peek() in ("+", "-"):
            op = self._take()[1]
            right = self._term()
            result = sympy.Add(result, right) if op == "+" else sympy.Add(result, sympy.Mul(-1, right))
        return result

    def _term(self) -> sympy.Expr:
        result = self._unary()
        while self._peek() in ("*", "/"):
            op = self._take()[1]
            right = self._unary()
            result = sympy.Mul(result, right) if op == "*" else sympy.Mul(result, sympy.Pow(right, -1))
        return result

    def _unary(self) -> sympy.Expr:
        if self._peek() == "-":
            self._take()
            return sympy.Mul(-1, self._unary())
        if self._peek() == "+":
            self._take()
            return self._unary()
        return self._power()

    def _power(self) -> sympy.Expr:
        base = self._atom()
        if self._peek() in ("^", "**"):
            self._take()
            return sympy.Pow(base, self._unary())
        return base

    def _atom(self) -> sympy.Expr:
        kind, text, position = self._take()
        if kind == "num":
            return sympy.Rational(text)
        if kind == "name":
            if self._peek() == "(":
                function = _FUNCTIONS.get(text)
                if function is None:
                    raise UnknownFunction(f"unknown function {text!r}", position, text, sorted(_FUNCTIONS))
                self._take()
                argument = self._expr()
                self._expect(")")
                return function(argument)
            if text in self.names:
                return self.names[text]
            if text in _CONSTANTS:
                return _CONSTANTS[text]
            raise UnknownSymbol(f"unknown name {text!r}", position, text, sorted(self.names))
        if text == "(":
            inner = self._expr()
            self._expect(")")
            return inner
        raise ParseError(f"unexpected {text!r}", position)
