"""LaTeX words that both readers of pasted LaTeX know (the math reader, physics/mathinput/latex.py, and the
unit reader, physics/units/latex.py): one whitelist, in a module that imports nothing, so the unit
reader stays free of sympy. Commands are written without their backslash."""

from __future__ import annotations

from typing import Final

LATEX_FRACTIONS: Final = frozenset({"frac", "dfrac", "tfrac", "cfrac"})
# Spacing and style commands: read as a space.
LATEX_SPACES: Final = frozenset(
    {
        ",", ";", ":", "!", " ", ">", "quad", "qquad", "enspace", "thinspace", "medspace", "thickspace",
        "negthinspace", "displaystyle", "textstyle",
    }
)  # fmt: skip
# `\mathrm{max}`, `\text{v}`: a name in an upright or text font is still the name.
LATEX_TEXT_WRAPPERS: Final = frozenset({"mathrm", "text", "textrm", "mathit", "operatorname"})
