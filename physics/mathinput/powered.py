"""A function written without brackets whose argument ends with a power: `sin θ^2`, `cos x^2`, `sin 2θ^2`.

By the usual convention the function takes the next factor with its power, so `sin θ^2` is sin(θ²). A
student who meant (sin θ)² is told how the answer was read (`read_as.note`) and, when that other reading
would have been right, how to write it. The wording quotes the student's own text (`θ` or `theta`,
`^2` or `²`, LaTeX as typed), so the advice is in their notation.
"""

from __future__ import annotations

from dataclasses import dataclass

_SUPERSCRIPTS = str.maketrans("0123456789", "⁰¹²³⁴⁵⁶⁷⁸⁹")


@dataclass(frozen=True)
class PoweredArgument:
    """One bare argument ending with a power, as typed."""

    typed: str  # the function and its argument: `sin θ^2`
    function: str  # `sin`, `\\sin`
    base: str  # the argument without its final power: `θ`, `2θ`
    exponent: str  # the power as typed after the caret: `2`, `(n+1)`, `{2}`
    whole_power: int | None  # the power, when it is a positive whole number (written `²` or `^2`)

    def _shown(self) -> str:
        """The power as read, for the student's eye: `²`, or `^(n+1)`."""
        if self.whole_power is not None:
            return str(self.whole_power).translate(_SUPERSCRIPTS)
        return f"^{self.exponent}"

    def _outside(self) -> str:
        """The other reading: `(sin θ)²`."""
        return f"({self.function} {self.base}){self._shown()}"

    def _writings(self) -> list[str]:
        """How to write the other reading: `sin^2 θ` (only for a whole power: `sin^-1` is arcsin), then
        the bracketed form."""
        power = str(self.whole_power) if self.whole_power is not None else self.exponent
        bracketed = f"({self.function} {self.base})^{power}"
        if self.whole_power is None:
            return [bracketed]
        return [f"{self.function}^{power} {self.base}", bracketed]

    def _inside(self) -> str:
        """The reading taken: `sin(θ²)`."""
        return f"{self.function}({self.base}{self._shown()})"

    @property
    def note(self) -> str:
        """`sin θ^2 is read as sin(θ²); for (sin θ)² write sin^2 θ or (sin θ)^2`."""
        return f"{self.typed} is read as {self._inside()}; for {self._outside()} write {' or '.join(self._writings())}"

    @property
    def reread_hint(self) -> tuple[str, str, str]:
        """The pieces of the hint given when the other reading would have been right."""
        return self._inside(), self._outside(), self._writings()[0]


def reading_note(found: tuple[PoweredArgument, ...]) -> str | None:
    """The note for `read_as`: one sentence per distinct bare powered argument, or None."""
    notes = dict.fromkeys(argument.note for argument in found)
    return ". ".join(notes) if notes else None


def other_reading_hint(found: tuple[PoweredArgument, ...]) -> str:
    """`Read as sin(θ²); if you meant (sin θ)², write sin^2 θ`, for feedback when the other reading of
    every bare powered argument would have been right."""
    hints = list(dict.fromkeys(argument.reread_hint for argument in found))
    inside, outside, writing = (" and ".join(piece[k] for piece in hints) for k in range(3))
    return f"Read as {inside}; if you meant {outside}, write {writing}"
