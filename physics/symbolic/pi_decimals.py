"""A decimal typed for π (`2*3.14*sqrt(L/g)`): the answer is graded as typed, a decimal being exactly the
number it shows, but the feedback says that π in its place would be right, which the plain "off by a
constant factor" leaves the student to guess."""

from __future__ import annotations

import math
import re
from collections.abc import Callable

_DECIMAL = re.compile(r"(?<![\w.])(\d+\.\d+)(?![\w.])")
_MULTIPLES = ((1, 4), (1, 2), (1, 1), (2, 1), (3, 1), (4, 1))  # π/4, π/2, π, 2π, 3π, 4π
_MIN_DIGITS = 3  # 3.14, 6.28, 1.57: a decimal of fewer significant digits is not meant as π
_CLOSE = 2e-3  # 3.14 is 5e-4 from π


def _as_pi(decimal: str) -> tuple[str, str] | None:
    """The multiple of π that `decimal` rounds, as text the reader takes (`(2*pi/1)`) and as shown
    (`2π`), or None."""
    if len(decimal.replace(".", "").lstrip("0")) < _MIN_DIGITS:
        return None
    value = float(decimal)
    for top, bottom in _MULTIPLES:
        if abs(value / (math.pi * top / bottom) - 1) < _CLOSE:
            shown = ("" if top == 1 else str(top)) + "π" + ("" if bottom == 1 else f"/{bottom}")
            return f"({top}*pi/{bottom})", shown
    return None


def pi_decimal_hint(read_as_text: str, right_with: Callable[[str], bool]) -> str | None:
    """Feedback for an answer whose decimals for multiples of π make it off by a factor: when the
    answer with π in their place is right (`right_with` grades a text), what to write instead."""
    found = [(match, _as_pi(match.group(1))) for match in _DECIMAL.finditer(read_as_text)]
    found = [(match, pi) for match, pi in found if pi is not None]
    if not found:
        return None
    text = read_as_text
    for match, pi in reversed(found):
        assert pi is not None
        text = text[: match.start()] + pi[0] + text[match.end() :]
    if not right_with(text):
        return None
    swaps = ", ".join(dict.fromkeys(f"{pi[1]} for {match.group(1)}" for match, pi in found if pi))
    return (
        f"Your answer would be right with {swaps}: a decimal is taken as exactly the number it shows, "
        "so write pi (or π) where you mean π."
    )
