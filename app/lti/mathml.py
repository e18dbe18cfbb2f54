"""Text with `$...$` TeX math to HTML with MathML, made on the server (no CDN, no scripts).

Only the TeX that problem statements use is understood: letters, digits, operators, Greek letters,
named functions, `^`, `_`, `\\frac`, `\\sqrt`, groups, `\\left`/`\\right` and a few symbols. Anything else
is shown literally. Nothing is evaluated; every character that reaches the page is escaped.
"""

from __future__ import annotations

import re
from html import escape, unescape

GREEK = {
    "alpha": "α", "beta": "β", "gamma": "γ", "delta": "δ", "epsilon": "ε", "varepsilon": "ε",
    "zeta": "ζ", "eta": "η", "theta": "θ", "vartheta": "ϑ", "iota": "ι", "kappa": "κ",
    "lambda": "λ", "mu": "μ", "nu": "ν", "xi": "ξ", "pi": "π", "rho": "ρ", "sigma": "σ",
    "tau": "τ", "upsilon": "υ", "phi": "φ", "varphi": "φ", "chi": "χ", "psi": "ψ", "omega": "ω",
    "Gamma": "Γ", "Delta": "Δ", "Theta": "Θ", "Lambda": "Λ", "Xi": "Ξ", "Pi": "Π", "Sigma": "Σ",
    "Phi": "Φ", "Psi": "Ψ", "Omega": "Ω",
}  # fmt: skip
FUNCTIONS = frozenset({"sin", "cos", "tan", "cot", "sec", "csc", "arcsin", "arccos", "arctan",
                       "sinh", "cosh", "tanh", "ln", "log", "exp", "max", "min"})  # fmt: skip
OPERATORS = {
    "cdot": "·", "times": "×", "pm": "±", "mp": "∓", "le": "≤", "leq": "≤", "ge": "≥", "geq": "≥",
    "neq": "≠", "ne": "≠", "approx": "≈", "sim": "∼", "to": "→", "rightarrow": "→", "infty": "∞",
    "propto": "∝", "partial": "∂", "nabla": "∇", "degree": "°", "circ": "∘", "ll": "≪", "gg": "≫",
}  # fmt: skip
SPACES = frozenset({",", ";", ":", "!", "quad", "qquad", " "})
_TOKEN = re.compile(r"\\([A-Za-z]+|.)|(\d+(?:\.\d+)?)|(\s+)|(.)", re.DOTALL)
_MATH = re.compile(r"(?<!\\)\$(.+?)(?<!\\)\$", re.DOTALL)
MAX_MATH_CHARS = 2000


class _Parser:
    def __init__(self, tex: str) -> None:
        self.tokens = [m for m in _TOKEN.finditer(tex) if not m.group(3)]
        self.at = 0

    def peek(self) -> re.Match[str] | None:
        return self.tokens[self.at] if self.at < len(self.tokens) else None

    def row(self, until: str | None = None) -> str:
        items: list[str] = []
        while (token := self.peek()) is not None:
            if until is not None and token.group(4) == until:
                self.at += 1
                break
            if token.group(1) == "right":
                break
            items.append(self._scripts(self._atom()))
        return items[0] if len(items) == 1 else f"<mrow>{''.join(items)}</mrow>"

    def _argument(self) -> str:
        token = self.peek()
        if token is None:
            return "<mrow></mrow>"
        if token.group(4) == "{":
            self.at += 1
            return self.row(until="}")
        return self._atom()

    def _scripts(self, base: str) -> str:
        sub = sup = None
        while (token := self.peek()) is not None and token.group(4) in ("^", "_"):
            self.at += 1
            if token.group(4) == "^":
                sup = self._argument()
            else:
                sub = self._argument()
        if sub is not None and sup is not None:
            return f"<msubsup>{base}{sub}{sup}</msubsup>"
        if sup is not None:
            return f"<msup>{base}{sup}</msup>"
        if sub is not None:
            return f"<msub>{base}{sub}</msub>"
        return base

    def _atom(self) -> str:
        token = self.tokens[self.at]
        self.at += 1
        command, number, _, char = token.groups()
        if number is not None:
            return f"<mn>{escape(number)}</mn>"
        if command is not None:
            return self._command(command)
        if char == "{":
            return self.row(until="}")
        if char.isalpha():
            return f"<mi>{escape(char)}</mi>"
        return f"<mo>{escape(char)}</mo>"

    def _command(self, name: str) -> str:
        if name in GREEK:
            return f"<mi>{GREEK[name]}</mi>"
        if name in FUNCTIONS:
            return f"<mi>{name}</mi>"  # several letters: upright by default
        if name in OPERATORS:
            return f"<mo>{OPERATORS[name]}</mo>"
        if name in SPACES:
            return '<mspace width="0.2em"></mspace>'
        if name == "frac":
            return f"<mfrac>{self._argument()}{self._argument()}</mfrac>"
        if name == "sqrt":
            return f"<msqrt>{self._argument()}</msqrt>"
        if name in ("left", "right"):
            token = self.peek()
            if token is None:
                return ""
            self.at += 1
            text = token.group(0).lstrip("\\")
            return "" if text == "." else f"<mo>{escape(text)}</mo>"
        if name in ("mathrm", "text", "operatorname"):
            return f'<mi mathvariant="normal">{escape(_plain(self._argument()))}</mi>'
        if name in ("{", "}", "$", "%", "_", "&", "#"):
            return f"<mo>{escape(name)}</mo>"
        return f"<mtext>{escape(chr(92) + name)}</mtext>"


def _plain(markup: str) -> str:
    """The text inside MathML we just made (for \\mathrm{...}): tags dropped, entities kept escaped."""
    return unescape(re.sub(r"<[^>]+>", "", markup))


def tex_to_mathml(tex: str, *, display: bool = False) -> str:
    """One formula as a `<math>` element; the TeX is kept in `alttext` for assistive technology."""
    if len(tex) > MAX_MATH_CHARS:
        return f"<code>{escape(tex)}</code>"
    parser = _Parser(tex)
    body = ""
    while parser.peek() is not None:  # a stray \right or } ends a row; keep going past it
        body += parser.row()
        if parser.peek() is not None:
            parser.at += 1
    mode = "block" if display else "inline"
    return f'<math display="{mode}" alttext="{escape(tex)}">{body}</math>'


def text_to_html(text: str) -> str:
    """Paragraphs (blank-line separated) of escaped text, `$...$` made MathML."""
    paragraphs = [p.strip() for p in re.split(r"\n\s*\n", text) if p.strip()]
    return "".join(f"<p>{_inline(p)}</p>" for p in paragraphs)


def inline_html(text: str) -> str:
    """One line of escaped text with its math, no paragraph."""
    return _inline(text.strip())


def _inline(text: str) -> str:
    out: list[str] = []
    last = 0
    for match in _MATH.finditer(text):
        out.append(escape(text[last : match.start()]))
        out.append(tex_to_mathml(match.group(1)))
        last = match.end()
    out.append(escape(text[last:]))
    return "".join(out)
