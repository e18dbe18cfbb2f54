"""Reading the expressions inside a model file: instructor text, so never evaluated.

Every model expression goes through the project's whitelist parser, exactly as answers do.
"""

from __future__ import annotations

from collections.abc import Mapping

import sympy

from physics.errors import AnswerError, SpecError
from physics.mathinput import parse_math

Path = tuple[str | int, ...]


def read_expr(text: object, names: Mapping[str, sympy.Symbol], path: Path) -> sympy.Expr:
    """The expression written in `text` (YAML may give a number), over `names`; SpecError at `path`."""
    if isinstance(text, bool) or not isinstance(text, str | int | float):
        raise SpecError(f"expected an expression (text or number), got {type(text).__name__}", path)
    source = text if isinstance(text, str) else repr(text)
    try:
        return parse_math(source, names).expr
    except AnswerError as error:
        raise SpecError(f"cannot read {source!r}: {error.message}", path) from None
