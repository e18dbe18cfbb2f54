"""Small pieces of English shared by every message the core, the bank tools and the web layer print."""

from __future__ import annotations

# A `;` ending an answer, as Maxima and MATLAB end a command: refused, as STACK refuses it, in symbolic and
# numeric answers alike.
TRAILING_SEMICOLON = "Leave out the ';' at the end: an answer is not a command, so type it without one."
# Arrows a phone's symbol keyboard offers, typed for a direction beside a value (`4.58 m/s^2 ↓`).
ARROWS = "↓↑←→⇓⇑⇐⇒↙↘↖↗"
# Directions said after a value, as in a sentence: no unit, and never read as one.
DIRECTION_WORDS = frozenset(
    {
        "up", "upward", "upwards", "down", "downward", "downwards", "left", "right", "leftward",
        "rightward", "north", "south", "east", "west", "forward", "forwards", "backward", "backwards",
        "clockwise", "anticlockwise", "counterclockwise", "uphill", "downhill", "inward", "inwards",
        "outward", "outwards",
    }
)  # fmt: skip
# Why a direction said beside a value is not read: the sign carries it.
DIRECTION_BY_SIGN = (
    "a direction is not read here; give it by the sign of the value (negative for the other way), as the "
    "problem sets its axes"
)


def counted(count: int, noun: str, plural: str | None = None) -> str:
    """`1 problem`, `2 problems`, `0 problems`: the count with the noun agreeing, never `problem(s)`."""
    return f"{count} {noun if count == 1 else plural or noun + 's'}"


def the_counted(count: int, noun: str, plural: str | None = None) -> str:
    """`the equation`, `the 2 equations`: a definite count, the number left out where it is one."""
    return f"the {noun}" if count == 1 else f"the {counted(count, noun, plural)}"


GREEK = [
    "alpha",
    "beta",
    "gamma",
    "delta",
    "epsilon",
    "zeta",
    "eta",
    "theta",
    "iota",
    "kappa",
    "lambda",
    "mu",
    "nu",
    "xi",
    "omicron",
    "pi",
    "rho",
    "sigma",
    "tau",
    "upsilon",
    "phi",
    "chi",
    "psi",
    "omega",
]
_SUBSCRIPT = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")


def symbol_label(name: str) -> str:
    """`theta` -> θ, `m1` -> m₁, `Omega` -> Ω, `v_0` -> v₀: how the statement typesets the name."""
    base, _, sub = name.partition("_")
    digits = ""
    while base and base[-1].isdigit() and len(base) > 1:
        digits, base = base[-1] + digits, base[:-1]
    if base.lower() in GREEK:
        letter = chr(0x3B1 + GREEK.index(base.lower()) + (base.lower() in GREEK[17:]))
        base = letter.upper() if base[0].isupper() else letter
    return base + (digits + sub).translate(_SUBSCRIPT)
