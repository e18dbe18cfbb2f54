"""The words and characters the math reader knows: functions, constants, Greek letters, Unicode operators.

Data only; the tokenizer, name table and renderers look things up here.
"""

from __future__ import annotations

from types import MappingProxyType
from typing import Final

from physics.characters import (
    ARABIC_DIGITS,
    CARET_LOOKALIKES,
    DEGREE_LOOKALIKES,
    FULLWIDTH,
    INVISIBLE_GAPS,
    MATH_LETTERS,
)

GREEK_LETTERS: Final = MappingProxyType(
    {
        "alpha": "α", "beta": "β", "gamma": "γ", "delta": "δ", "epsilon": "ε", "zeta": "ζ",
        "eta": "η", "theta": "θ", "iota": "ι", "kappa": "κ", "lambda": "λ", "mu": "μ",
        "nu": "ν", "xi": "ξ", "omicron": "ο", "pi": "π", "rho": "ρ", "sigma": "σ",
        "tau": "τ", "upsilon": "υ", "phi": "φ", "chi": "χ", "psi": "ψ", "omega": "ω",
        "Alpha": "Α", "Beta": "Β", "Gamma": "Γ", "Delta": "Δ", "Epsilon": "Ε", "Zeta": "Ζ",
        "Eta": "Η", "Theta": "Θ", "Iota": "Ι", "Kappa": "Κ", "Lambda": "Λ", "Mu": "Μ",
        "Nu": "Ν", "Xi": "Ξ", "Omicron": "Ο", "Pi": "Π", "Rho": "Ρ", "Sigma": "Σ",
        "Tau": "Τ", "Upsilon": "Υ", "Phi": "Φ", "Chi": "Χ", "Psi": "Ψ", "Omega": "Ω",
    }
)  # fmt: skip
GREEK_NAMES: Final = MappingProxyType({letter: name for name, letter in GREEK_LETTERS.items()})

# Capital Greek letters that LaTeX writes as the Latin letter (there is no \Alpha).
LATIN_LOOKING_CAPITALS: Final = frozenset(
    {"Alpha", "Beta", "Epsilon", "Zeta", "Eta", "Iota", "Kappa", "Mu", "Nu", "Omicron", "Rho", "Tau", "Chi"}
)

# Characters read as another one; every mapping is one character to one, so positions stay exact.
CHARACTER_VARIANTS: Final = MappingProxyType(
    {
        "ϑ": "θ", "ϕ": "φ", "ϵ": "ε", "ϱ": "ρ", "ς": "σ", "µ": "μ",
        "−": "-", "–": "-", "‐": "-", "‑": "-", "﹣": "-",
        "×": "*", "·": "*", "⋅": "*", "∙": "*", "•": "*", "∗": "*", "∣": "|", "÷": "/", "⁄": "/", "∕": "/",  # fraction and division slashes
        # Subscript digits, as in v₀, ε₀, r₁: the same names as v0 (an alias of v_0), ε0, r1.
        "₀": "0", "₁": "1", "₂": "2", "₃": "3", "₄": "4", "₅": "5", "₆": "6", "₇": "7", "₈": "8", "₉": "9",
        "ℏ": "ħ",  # the Planck constant sign, as the letter ħ
        **FULLWIDTH,  # from East Asian input methods
        **ARABIC_DIGITS,  # ٤٫٥ from an Arabic or Persian keyboard
        **DEGREE_LOOKALIKES,  # 30º, 30˚
        **MATH_LETTERS,  # 𝑚𝑔ℎ, 𝜃: an equation copied from Word or a PDF
        **INVISIBLE_GAPS,  # sin⁡θ as Word copies it: function application, invisible times
        **CARET_LOOKALIKES,  # vˆ2, a Mac's option-i
    }
)  # fmt: skip

# Vulgar fractions: each reads as a bracketed fraction, `½ m v²` as (1/2)·m·v².
VULGAR_FRACTIONS: Final = MappingProxyType(
    {
        "½": (1, 2), "⅓": (1, 3), "⅔": (2, 3), "¼": (1, 4), "¾": (3, 4), "⅕": (1, 5), "⅖": (2, 5),
        "⅗": (3, 5), "⅘": (4, 5), "⅙": (1, 6), "⅚": (5, 6), "⅛": (1, 8), "⅜": (3, 8), "⅝": (5, 8),
        "⅞": (7, 8),
    }
)  # fmt: skip

# Letters that stand for a declared name, like a Greek letter for its name: `ħ` for a declared `hbar`.
LETTER_NAMES: Final = MappingProxyType({"ħ": "hbar"})

SUPERSCRIPT_DIGITS: Final = MappingProxyType(
    {"⁰": 0, "¹": 1, "²": 2, "³": 3, "⁴": 4, "⁵": 5, "⁶": 6, "⁷": 7, "⁸": 8, "⁹": 9}
)
SUPERSCRIPT_SIGNS: Final = MappingProxyType({"⁻": -1, "⁺": 1})
# Superscript letters, brackets and a slash, as a phone's keyboard or a "superscript generator" types an
# exponent (`e⁻ʷᵗ`, `e⁻ᵗᐟᵗᵃᵘ`): each the plain character it raises (the turned m, ᵚ, for the ω it
# looks like and stands for there).
SUPERSCRIPT_PLAIN: Final = MappingProxyType(
    dict(
        zip(
            "ᵃᵇᶜᵈᵉᶠᵍʰⁱʲᵏˡᵐⁿᵒᵖʳˢᵗᵘᵛʷˣʸᶻᴬᴮᴰᴱᴳᴴᴵᴶᴷᴸᴹᴺᴼᴾᴿᵀᵁⱽᵂᵅᵝᵞᵟᵋᶿᶥᶲᵠᵡᵚ⁽⁾ᐟ⁰¹²³⁴⁵⁶⁷⁸⁹⁻⁺",
            "abcdefghijklmnoprstuvwxyzABDEGHIJKLMNOPRTUVWαβγδεθιφφχω()/0123456789-+",
            strict=True,
        )
    )
)
# Subscript letters (`vₘₐₓ`, `Fₙ`): each the plain letter it lowers. Subscript digits are digits already
# (CHARACTER_VARIANTS).
SUBSCRIPT_LETTERS: Final = MappingProxyType(
    dict(zip("ₐₑₒₓₕₖₗₘₙₚₛₜᵢᵣᵤᵥⱼᵦᵧᵨᵩᵪ", "aeoxhklmnpstiruvjβγρφχ", strict=True))
)

# The root signs, and the index of each: `√x`, `∛x` (x^(1/3)), `∜x` (x^(1/4)).
ROOT_SIGNS: Final = MappingProxyType({"√": 2, "∛": 3, "∜": 4})

OPENERS: Final = MappingProxyType({"(": ")", "[": "]", "{": "}"})
CLOSERS: Final = frozenset(OPENERS.values())

# Function names a student may type, mapped to the canonical name the tree and renderers use.
FUNCTIONS: Final = MappingProxyType(
    {
        "sqrt": "sqrt", "exp": "exp", "ln": "log", "log": "log", "log10": "log10", "abs": "abs",
        "sin": "sin", "cos": "cos", "tan": "tan", "sec": "sec", "csc": "csc", "cot": "cot",
        "asin": "asin", "acos": "acos", "atan": "atan", "arcsin": "asin", "arccos": "acos",
        "arctan": "atan", "asec": "asec", "acsc": "acsc", "acot": "acot", "arcsec": "asec",
        "arccsc": "acsc", "arccot": "acot", "sinh": "sinh", "cosh": "cosh", "tanh": "tanh",
        "asinh": "asinh", "acosh": "acosh", "atanh": "atanh", "arsinh": "asinh", "arcosh": "acosh",
        "artanh": "atanh", "factorial": "factorial", "cosec": "csc", "arccosec": "acsc", "Abs": "abs",
        "log_10": "log10", "log_e": "log",  # `log_10(x)`, `log_{10}(x)` typed as LaTeX writes the base
    }
)  # fmt: skip

# What `f^-1` means for each function that has a named inverse (sin^-1(x) is asin(x)).
INVERSES: Final = MappingProxyType(
    {
        "sin": "asin", "cos": "acos", "tan": "atan", "sec": "asec", "csc": "acsc", "cot": "acot",
        "sinh": "asinh", "cosh": "acosh", "tanh": "atanh",
    }
)  # fmt: skip

# The functions listed to a student in an unknown-function message (the common spellings only).
LISTED_FUNCTIONS: Final = (
    "sqrt", "exp", "ln", "log", "log10", "abs", "sin", "cos", "tan", "sec", "csc", "cot",
    "asin", "acos", "atan", "sinh", "cosh", "tanh", "factorial",
)  # fmt: skip

PI_SPELLINGS: Final = ("pi", "π")
EULER_SPELLING: Final = "e"
DEGREE_WORD: Final = "deg"
TIMES_WORD: Final = "x"
MAX_WORD_LENGTH: Final = 64

LATEX_FUNCTIONS: Final = MappingProxyType(
    {
        "sin": r"\sin", "cos": r"\cos", "tan": r"\tan", "sec": r"\sec", "csc": r"\csc", "cot": r"\cot",
        "asin": r"\arcsin", "acos": r"\arccos", "atan": r"\arctan", "asec": r"\operatorname{arcsec}",
        "acsc": r"\operatorname{arccsc}", "acot": r"\operatorname{arccot}", "sinh": r"\sinh",
        "cosh": r"\cosh", "tanh": r"\tanh", "asinh": r"\operatorname{arsinh}",
        "acosh": r"\operatorname{arcosh}", "atanh": r"\operatorname{artanh}", "log": r"\ln",
        "log10": r"\log_{10}",
    }
)  # fmt: skip

# -- LaTeX as equation editors paste it (read by latex.py); commands without their backslash ----------
# Each is also a key of FUNCTIONS.
LATEX_FUNCTION_COMMANDS: Final = frozenset(
    {
        "sin", "cos", "tan", "sec", "csc", "cot", "arcsin", "arccos", "arctan", "sinh", "cosh", "tanh",
        "exp", "ln", "log",
    }
)  # fmt: skip
# Commands that are a letter, as the word the name table knows (`\theta` is theta, `\varphi` is phi).
LATEX_LETTERS: Final = MappingProxyType(
    {
        **{name: name for name in GREEK_LETTERS if name[0].islower() and name != "omicron"},
        **{name: name for name in GREEK_LETTERS if name[0].isupper() and name not in LATIN_LOOKING_CAPITALS},
        "varepsilon": "epsilon", "vartheta": "theta", "varphi": "phi", "varrho": "rho", "varsigma": "sigma",
        "hbar": "hbar",
    }
)  # fmt: skip
LATEX_OPERATORS: Final = MappingProxyType({"cdot": "*", "times": "*", "ast": "*", "div": "/"})
# `\left(`, `\bigl[`: a size before a delimiter; the delimiter is what counts.
LATEX_SIZES: Final = frozenset(
    {
        "left", "right", "big", "Big", "bigg", "Bigg", "bigl", "bigr", "Bigl", "Bigr", "biggl", "biggr",
        "Biggl", "Biggr",
    }
)  # fmt: skip
# Commands that are a bracket or a bar, standing alone or after a size (`\{`, `\left\lvert`).
LATEX_BRACKETS: Final = MappingProxyType(
    {
        "{": "{", "}": "}", "lbrace": "{", "rbrace": "}", "lbrack": "[", "rbrack": "]",
        "vert": "|", "lvert": "|", "rvert": "|",
    }
)  # fmt: skip

# How to type what an unknown command was for; the default hint serves every other one.
LATEX_PLAIN_TEXT_HINT: Final = (
    "type that part in plain text, as in sqrt(x), sin(theta), x^2 or a*b (the LaTeX read here is "
    "\\frac, \\sqrt, functions such as \\sin, Greek letters, \\cdot, \\times, \\left( \\right), "
    "^{…} and _{…})"
)
_NAME_AS_LISTED = "type the symbol as the problem lists it (v, v_x, F_net): a plain name has no accents"
_NAME_NOT_BOLD = "type the symbol as the problem lists it (v, v_x, F_net), in plain letters: bold is not read"
_ONE_EXPRESSION = "type only the expression, without =, relations or a second line"
_WORK_IT_OUT = "an answer is an expression in the problem's symbols: work the operation out first"
LATEX_HINTS: Final = MappingProxyType(
    {
        **dict.fromkeys(
            ("vec", "hat", "bar", "dot", "ddot", "tilde", "overline", "overrightarrow"),
            _NAME_AS_LISTED,
        ),
        **dict.fromkeys(("mathbf", "boldsymbol", "bm"), _NAME_NOT_BOLD),
        **dict.fromkeys(
            ("\\", "newline", "approx", "ne", "neq", "le", "leq", "ge", "geq", "lt", "gt", "equiv",
             "to", "rightarrow", "Rightarrow", "implies", "sim", "propto", "begin", "end"),
            _ONE_EXPRESSION,
        ),
        **dict.fromkeys(
            ("int", "iint", "oint", "sum", "prod", "lim", "partial", "nabla", "infty"),
            _WORK_IT_OUT,
        ),
        **dict.fromkeys(  # siunitx's quantities, `\SI{4.58}{m/s^2}`, as a LaTeX-writing student sets them
            ("SI", "qty", "num", "si", "unit"),
            "type the value and its units in plain text, as in 4.58 m/s^2 (siunitx's commands are not read)",
        ),
        "pm": "give one answer, with its sign", "mp": "give one answer, with its sign",
        "circ": "write degrees as 30^\\circ or 30°",
        "ell": "type the name the problem uses for it (l or L)",
        **{capital: f"type the letter {capital[0]} (LaTeX has no \\{capital})" for capital in LATIN_LOOKING_CAPITALS},
    }
)  # fmt: skip
