"""A hand-written precedence parser from tokens to the parse tree; it never evaluates text.

Grammar (loosest first):
    sum      := term (("+" | "-") term)*
    term     := ("-" | "+") term | product
    product  := power (("*" | "/") signed | juxtaposed power)*     juxtaposition binds like *
    signed   := ("-" | "+") signed | power
    power    := postfixed ("^" exponent | superscript)*            ^ is right-associative
    exponent := ("-" | "+") exponent | power
    postfixed:= atom ("!" | "%" | "°" | deg)*
    atom     := number | name | constant | function call | ("√" | "∛" | "∜") argument | bracketed
              | "|" sum "|"
Recursion is bounded by `max_depth`, so deep nesting is a TooLarge, never a RecursionError.
"""

from __future__ import annotations

from collections.abc import Mapping
from fractions import Fraction
from typing import Literal, NoReturn

from physics import separators
from physics.errors import (
    AmbiguousDivision,
    AmbiguousGrouping,
    AmbiguousInput,
    LikelySlip,
    ParseError,
    TooLarge,
)
from physics.mathinput.limits import InputLimits
from physics.mathinput.mixed_numbers import mixed_number_slip
from physics.mathinput.powered import PoweredArgument
from physics.mathinput.render import AS_TYPED_STYLE, STUDENT_STYLE, render_text
from physics.mathinput.tokens import Kind, Token, script_fraction
from physics.mathinput.tree import (
    Call,
    Const,
    Group,
    Name,
    Neg,
    Node,
    Num,
    Postfix,
    PostfixKind,
    Power,
    Product,
    Sum,
    ungroup,
)
from physics.mathinput.vocabulary import INVERSES, OPENERS, ROOT_SIGNS, VULGAR_FRACTIONS

_POSTFIX_KINDS: dict[str, PostfixKind] = {"!": "factorial", "%": "percent", "°": "degrees"}
# Functions of an angle: a bare number as their argument is in radians, which no one types spaced from
# a word after it (`sin 2 θ`).
_TRIGONOMETRIC = frozenset({"sin", "cos", "tan", "sec", "csc", "cot"})
# The tokens of `\\frac{n}{d}` (or `\\frac12`) after the number of a mixed number, `3\\frac{1}{2}`.
_LATEX_FRACTION_OF_NUMBERS = (
    Kind.LPAREN, Kind.LPAREN, Kind.NUM, Kind.RPAREN, Kind.OP, Kind.LPAREN, Kind.NUM, Kind.RPAREN, Kind.RPAREN,
)  # fmt: skip
# A tuple, not a set: membership by identity, without Enum's hash (a Python call) for every token.
_FACTOR_STARTS = (Kind.NUM, Kind.NAME, Kind.CONST, Kind.FUNC, Kind.LPAREN, Kind.SQRT)


class _Item:
    """One step of a product while it is being read: operator, operand, and the token that began it."""

    __slots__ = ("juxtaposed", "node", "op", "token")

    def __init__(self, op: Literal["*", "/"], node: Node, token: Token, juxtaposed: bool) -> None:
        self.op: Literal["*", "/"] = op
        self.node = node
        self.token = token
        self.juxtaposed = juxtaposed


# A division followed by more factors than this has too many readings to list (each place its divisor
# may end): it is refused with two, and its readings are not tried to settle other groupings.
_MAX_DIVISOR_READINGS = 4


class Parser:
    """`choices` settles ambiguous groupings by the position of their operator: 0 reads `a/b c` as
    (a/b)·c and `e^-ωt` as e^(−ω)·t, 1 as a/(b·c) and e^(−ωt); a division followed by more factors has
    a choice for each other place its divisor may end (2: `a/b c d` as a/(b·c)·d). One without a choice
    is refused (AmbiguousGrouping, with a reading for each choice; AmbiguousDivision for a division,
    which a choice only reads one way to try how other groupings read: the contract refuses it).

    A function without brackets takes the next factor with its power (`sin θ^2` is sin(θ²)), or the
    whole word typed without a space (`cos ωt` is cos(ωt), as physics writes it); each such
    argument is listed in `powered`, so the reading can be shown. `powers_outside` reads the power as
    the function's instead ((sin θ)²): the reading a student may have meant, to compare, never to grade.
    """

    def __init__(
        self,
        source: str,
        tokens: list[Token],
        limits: InputLimits,
        choices: Mapping[int, int] | None = None,
        *,
        powers_outside: bool = False,
        word_ends: Mapping[int, int] | None = None,
    ) -> None:
        self._source = source
        self._tokens = tokens
        self._limits = limits
        self._choices = choices or {}
        self._powers_outside = powers_outside
        self._word_ends = word_ends or {}
        self.powered: list[PoweredArgument] = []
        self.long_words: list[tuple[int, int]] = []  # (function's position, factors): `sinθmgL`'s θmgL
        self._i = 0
        self._depth = 0
        self._abs_depth = 0  # open |...| in the current bracket level; a | there closes instead of opening

    # -- helpers -------------------------------------------------------------------------------
    @property
    def _prev(self) -> Token | None:
        return self._tokens[self._i - 1] if self._i > 0 else None

    def _advance(self) -> Token:
        tok = self._tokens[self._i]
        if tok.kind is not Kind.END:
            self._i += 1
        return tok

    def _typed(self, tok: Token) -> str:
        return self._source[tok.pos : tok.end] or tok.text

    def _typed_since(self, start: int) -> str:
        """The text typed from `start` to the end of the last token read."""
        return self._source[start : self._tokens[self._i - 1].end]

    def _enter(self, tok: Token) -> None:
        self._depth += 1
        if self._depth > self._limits.max_depth:
            raise TooLarge(
                f"The answer is nested too deeply (at most {self._limits.max_depth} levels).", tok.pos
            )

    def _leave(self) -> None:
        self._depth -= 1

    # -- grammar -------------------------------------------------------------------------------
    def parse(self) -> Node:
        if self._tokens[self._i].kind is Kind.END:
            raise ParseError("The answer is empty.", 0)
        node = self._sum()
        tok = self._tokens[self._i]
        if tok.kind is not Kind.END:
            self._fail_after_expression(tok)
        return node

    def _sum(self) -> Node:
        self._enter(self._tokens[self._i])
        term_at = self._tokens[self._i].pos
        first = self._term()
        rest: list[tuple[Literal["+", "-"], Node]] = []
        while (tok := self._tokens[self._i]).kind is Kind.OP and tok.text in "+-":
            if tok.text == "-" and _after_times_ten(self._tokens, self._i):
                self._refuse_a_calculator_exponent()
            elif tok.text == "-" and _after_a_factor_and_ten(self._tokens, self._i):
                self._refuse_a_calculator_exponent(term_at)
            op = self._advance()
            term_at = self._tokens[self._i].pos
            rest.append(("+" if op.text == "+" else "-", self._term()))
        self._leave()
        return Sum(first, tuple(rest)) if rest else first

    def _term(self) -> Node:
        tok = self._tokens[self._i]
        if tok.kind is Kind.OP and tok.text in "+-":
            self._advance()
            self._enter(tok)
            operand = self._term()
            self._leave()
            return Neg(operand) if tok.text == "-" else operand
        return self._product()

    def _signed(self) -> Node:
        tok = self._tokens[self._i]
        if tok.kind is Kind.OP and tok.text in "+-":
            self._advance()
            self._enter(tok)
            operand = self._signed()
            self._leave()
            return Neg(operand) if tok.text == "-" else operand
        return self._power()

    def _product(self) -> Node:
        tokens = self._tokens
        product_at = factor_at = tokens[self._i].pos  # where the last factor read was typed
        first = self._power()
        items: list[_Item] = []
        while True:
            tok = tokens[self._i]
            kind = tok.kind
            if kind is Kind.OP and tok.text in "*/":
                self._i += 1
                after = tokens[self._i]
                factor_at = after.pos
                signed = after.kind is Kind.OP and after.text in "+-"
                factor = self._signed() if signed else self._power()
                items.append(_Item("*" if tok.text == "*" else "/", factor, tok, False))
            elif kind in _FACTOR_STARTS or (kind is Kind.BAR and self._abs_depth == 0):
                prev = tokens[self._i - 1]  # the factor before this one
                if (
                    kind is Kind.LPAREN
                    and prev.kind is Kind.NUM
                    and self._source[tok.pos : tok.pos + 1] == "\\"
                ):
                    self._refuse_a_latex_mixed_number(prev)
                if kind is Kind.NUM and prev.kind is Kind.NUM:
                    if _times_a_power_of_ten(tokens, self._i):
                        self._power()
                        end = self._tokens[self._i - 1].end
                        raise separators.power_of_ten_apart(self._source, prev.pos, tok.pos, end)
                    if _number_after_an_exponent(tokens, self._i):
                        raise self._number_after_a_power(factor_at, prev, tok)
                    self._refuse_a_mixed_number(prev, tok)
                    if len(tok.text) <= 2 and _after_a_factor_and_ten(tokens, self._i):
                        mantissa = self._source[product_at : prev.pos].rstrip(" *×·⋅")
                        raise separators.calculator_exponent_slip(mantissa, tok.text, tok.pos, negative=False)
                    raise separators.side_by_side(self._source, prev.pos, tok.pos, product=True)
                factor_at = tok.pos
                items.append(_Item("*", self._power(), tok, True))
            else:
                break
        if not items:
            return first
        if any(item.op == "/" for item in items):  # only a division can be ambiguous
            first, items = self._settle_ambiguous_divisions(first, items)
            if not items:
                return first
        return Product(first, tuple((item.op, item.node) for item in items))

    def _refuse_a_calculator_exponent(self, term_at: int | None = None) -> None:
        """`3.0×10-3`, a calculator's display of 3.0×10^-3 with its ^ left out: 3.0·10 − 3 as typed, which
        no one means; refused as in a numeric answer (a minus spaced on both sides is a subtraction).
        `term_at`: where the term starts whose factors are the mantissa, `g sin α 10 -3`."""
        ten = self._tokens[self._i - 1]
        found = separators.calculator_exponent(self._source, ten.end)
        if found is None:
            return
        if term_at is None:
            mantissa = self._typed(self._tokens[self._i - 3])
        else:
            mantissa = self._source[term_at : ten.pos].rstrip(" *×·⋅")
        raise separators.calculator_exponent_slip(mantissa, found[1], found[0])

    def _number_after_a_power(self, factor_at: int, exponent: Token, number: Token) -> ParseError:
        """The refusal of `x^2 3`: the power typed from `factor_at` to its `exponent`, then a `number`
        (with the fraction typed on it, `x^2 1/2`, or its own power, `x^2 10^3`)."""
        tokens, at = self._tokens, self._i
        end = number.end
        if _is_raised(tokens[at + 1]):  # `x^2 10^3`: the number with its own power
            self._power()
            end = tokens[self._i - 1].end
        elif (
            tokens[at + 1].kind is Kind.OP and tokens[at + 1].text == "/" and tokens[at + 2].kind is Kind.NUM
        ):
            end = tokens[at + 2].end
        caret = next(t for t in reversed(tokens[: at - 1]) if t.kind is Kind.OP and t.text == "^")
        return separators.number_after_a_power(
            self._source[factor_at : caret.pos],
            self._source[tokens[tokens.index(caret) + 1].pos : exponent.end],
            self._source[number.pos : end],
            number.pos,
        )

    def _refuse_a_mixed_number(self, whole: Token, top: Token) -> None:
        """`1 1/2`, a whole number then a fraction of whole numbers: one and a half, as a recipe writes
        it. Only where the first number is no exponent (`x^2 1/2` is a number after a power)."""
        at = self._i
        tokens = self._tokens
        slash, bottom = tokens[at + 1], tokens[at + 2] if at + 2 < len(tokens) else tokens[-1]
        if not (
            whole.text.isdigit()
            and top.text.isdigit()
            and slash.kind is Kind.OP
            and slash.text == "/"
            and bottom.kind is Kind.NUM
            and bottom.text.isdigit()
            and bottom.value
            and top.value is not None
            # `12 500/2`: a group of three digits over less is no mixed number, but digits grouped
            and not (len(top.text) == 3 and top.value >= bottom.value)
            and not (at >= 2 and tokens[at - 2].kind is Kind.OP and tokens[at - 2].text == "^")
        ):
            return
        typed = self._source[whole.pos : bottom.end]
        raise mixed_number_slip(int(whole.text), top.value / bottom.value, typed, top.pos)

    def _refuse_a_latex_mixed_number(self, whole: Token) -> None:
        """`3\\frac{1}{2}`: a mixed number as LaTeX prints it, 3½, refused as `1 1/2` is. The tokens of a
        `\\frac` of two whole numbers are `( ( n ) / ( d ) )`, each bracket a brace or zero-width."""
        at = self._i
        shape = self._tokens[at : at + 9]
        kinds = [t.kind for t in shape]
        if kinds != [*_LATEX_FRACTION_OF_NUMBERS] or not (
            whole.text.isdigit()
            and shape[2].text.isdigit()
            and shape[4].text == "/"
            and shape[6].text.isdigit()
            and shape[6].value
        ):
            return
        if at >= 2 and self._tokens[at - 2].kind is Kind.OP and self._tokens[at - 2].text == "^":
            return
        assert shape[2].value is not None
        typed = self._source[whole.pos : shape[-1].end]
        raise mixed_number_slip(int(whole.text), shape[2].value / shape[6].value, typed, shape[0].pos)

    def _settle_ambiguous_divisions(self, first: Node, items: list[_Item]) -> tuple[Node, list[_Item]]:
        """`a/b c` could be (a/b)·c or a/(b·c); only an integer fraction opening a term is a coefficient.
        Each ambiguous `/` is read as `choices` says, or refused."""
        k = 0
        while k < len(items):
            item = items[k]
            if item.op != "/" or k + 1 >= len(items) or not items[k + 1].juxtaposed:
                k += 1
                continue
            if (
                k == 0
                and isinstance(first, Num)
                and first.integer_literal
                and isinstance(item.node, Num)
                and item.node.integer_literal
                and items[k + 1].token.space_before
            ):
                k += 1
                continue
            run_end = k + 1
            while run_end < len(items) and items[run_end].juxtaposed:
                run_end += 1
            # The divisor may end after any factor of the run: `1/2π √(k/m)` is (1/2)·π·√(k/m) (choice 0),
            # 1/(2π·√(k/m)) (choice 1), or 1/(2π)·√(k/m) (choice 2: the divisor ends after the run's
            # first factor; choice 3 after its second, and so on).
            ends = (k + 1, run_end, *range(k + 2, run_end))
            choice = self._choices.get(item.token.pos)
            if choice == 0:  # (a/b)·c
                first = Group(Product(first, tuple((i.op, i.node) for i in items[: k + 1])))
                items = items[k + 1 :]
                k = run_end - (k + 1)
                continue
            if choice is not None and 0 < choice < len(ends):
                divisor_end = ends[choice]
                run = [i.node for i in items[k + 1 : divisor_end]]
                grouped = Group(Product(item.node, tuple(("*", n) for n in run)))
                items = [*items[:k], _Item("/", grouped, item.token, False), *items[divisor_end:]]
                k += 1
                continue
            raise self._ambiguous_division(first, items, k, ends)
        return first, items

    def _ambiguous_division(
        self, first: Node, items: list[_Item], k: int, ends: tuple[int, ...]
    ) -> AmbiguousDivision:
        """The refusal of the division at items[k], with a reading for each place its divisor may end
        (`ends`, by choice); a run too long to list each is refused with two, as `partial`."""
        item = items[k]
        numerator = render_text(Product(first, tuple((i.op, i.node) for i in items[:k])), AS_TYPED_STYLE)
        partial = len(ends) > _MAX_DIVISOR_READINGS
        readings: list[str] = []
        for divisor_end in ends[:2] if partial else ends:
            divisor = Product(item.node, tuple(("*", i.node) for i in items[k + 1 : divisor_end]))
            rest = [i.node for i in items[divisor_end : ends[1]]]
            after = (
                "·" + render_text(Product(rest[0], tuple(("*", n) for n in rest[1:])), AS_TYPED_STYLE)
                if rest
                else ""
            )
            if divisor_end == k + 1:  # (a/b)·c
                numerator_product = Product(first, tuple((i.op, i.node) for i in items[: k + 1]))
                readings.append(f"({render_text(numerator_product, AS_TYPED_STYLE)}){after}")
            else:
                readings.append(f"{numerator}/({render_text(divisor, AS_TYPED_STYLE)}){after}")
        # Asked in the order the divisor grows: (a/b)·c·d, a/(b·c)·d, a/(b·c·d)
        asked = [readings[0], *readings[2:], readings[1]]
        return AmbiguousDivision(
            f"Did you mean {', '.join(asked[:-1])} or {asked[-1]}? Add parentheses.",
            item.token.pos,
            readings,
            partial=partial,
        )

    def _power(self) -> Node:
        # A name or a number (most factors) made here, and the powers and postfixes looked for only
        # where a token can start one: a factor is then one call deep, not four.
        tok = self._tokens[self._i]
        kind = tok.kind
        if kind is Kind.NAME:
            self._i += 1
            node: Node = Name(tok.text)
        elif kind is Kind.NUM:
            self._i += 1
            assert tok.value is not None
            node = Num(tok.text, tok.value, tok.is_integer_literal)
        else:
            node = self._atom()
        after = self._tokens[self._i]
        if after.kind is Kind.POSTFIX:
            node = self._postfixes(node)
            after = self._tokens[self._i]
        if (after.kind is Kind.OP and after.text == "^") or after.kind is Kind.SUP:
            return self._raised(node, tok.pos)
        return node

    def _raised(self, node: Node, start: int) -> Node:
        """`node`, typed from `start`, with the powers written after it (`^2`, `**2`, `²`)."""
        while True:
            tok = self._tokens[self._i]
            if tok.kind is Kind.OP and tok.text in "^":
                self._advance()
                self._enter(tok)
                exponent = self._exponent()
                whole_word = node == Const("e") and self._word_glued_to(exponent)
                if whole_word or self._fraction_glued_to(exponent):
                    exponent = self._settle_exponent(node, exponent, tok, whole_word=whole_word)
                    node = Power(node, exponent, tok.pos, self._typed_since(start))
                else:
                    node = Power(node, exponent, tok.pos)
                self._leave()
            elif tok.kind is Kind.SUP:
                self._advance()
                node = Power(node, _superscript_node(tok), tok.pos)
            else:
                return node

    def _word_glued_to(self, exponent: Node) -> bool:
        """Whether a name, or a `/` and a factor, follows an unbracketed exponent without a space:
        `e^-ωt`, `e^2x`, `e^-t/τ`."""
        core = exponent.operand if isinstance(exponent, Neg) else exponent
        return not isinstance(core, Group) and self._glued_factor() is not None

    def _fraction_glued_to(self, exponent: Node) -> bool:
        """Whether `/n` follows an exponent of 1 without a space: `x^1/2`, `x^-1/2`, a root as students
        type it (no one types x^1 for x). `R^2/5` stays R²/5, as in `2mR^2/5`."""
        core = exponent.operand if isinstance(exponent, Neg) else exponent
        return isinstance(core, Num) and core.literal == "1" and self._glued_fraction() is not None

    def _glued_fraction(self) -> Literal["/"] | None:
        """A `/` and a whole number typed on without a space (taken once: `x^1/2`), else None."""
        slash, after = self._tokens[self._i], self._tokens[min(self._i + 1, len(self._tokens) - 1)]
        if (
            slash.kind is Kind.OP
            and slash.text == "/"
            and not slash.space_before
            and after.kind is Kind.NUM
            and after.is_integer_literal
            and not after.space_before
        ):
            return "/"
        return None

    def _glued_factor(self) -> Literal["*", "/"] | None:
        """How the word typed on without a space goes on here: a name (`*`), a `/` before a name or a
        number (`/`), or not at all (None)."""
        follower = self._tokens[self._i]
        if follower.space_before:
            return None
        if follower.kind in (Kind.NAME, Kind.CONST):
            return "*"
        after = self._tokens[self._i + 1] if follower.kind is not Kind.END else follower
        if (
            follower.kind is Kind.OP
            and follower.text == "/"
            and after.kind in (Kind.NAME, Kind.CONST, Kind.NUM)
            and not after.space_before
        ):
            return "/"
        return None

    def _settle_exponent(self, base: Node, exponent: Node, caret: Token, *, whole_word: bool) -> Node:
        """`e^-ωt` is e^(−ω)·t to the grammar, but physics writes e^(−ωt) so (and `e^-t/τ` e^(−t/τ)),
        and `(2gh)^1/2` √(2gh): `choices` reads it (by the position of its `^`) one way, 0 as e^(−ω)·t
        (the rest left to the product), 1 as e^(−ωt) (what is typed on without a space is the exponent:
        the `whole_word` as with `cos ωt`, else a root's one fraction); without a choice it is refused.
        A division in that word may be ambiguous in turn (`e^-bt/2m`)."""
        choice = self._choices.get(caret.pos)
        if choice == 0:
            return exponent
        items: list[_Item] = []
        op = self._glued_factor() if whole_word else self._glued_fraction()
        while op is not None:
            tok = self._advance() if op == "/" else self._tokens[self._i]
            items.append(_Item(op, self._raised(self._postfixed(), tok.pos), tok, op == "*"))
            op = self._glued_factor() if whole_word else None
        negative = isinstance(exponent, Neg)
        first = exponent.operand if isinstance(exponent, Neg) else exponent
        if choice == 1:
            first, items = self._settle_ambiguous_divisions(first, items)
            whole = Product(first, tuple((i.op, i.node) for i in items)) if items else first
            return Neg(whole) if negative else whole
        rest = tuple((i.op, i.node) for i in items)
        whole = Product(first, rest)
        readings = (
            render_text(Product(Power(base, exponent), rest), STUDENT_STYLE),
            render_text(Power(base, Neg(whole) if negative else whole), STUDENT_STYLE),
        )
        raise AmbiguousGrouping(
            f"Did you mean {readings[0]} or {readings[1]}? Add parentheses.", caret.pos, readings
        )

    def _divisor_glued_to(self, argument: Node, *, root: bool = False) -> bool:
        """Whether a `/` and a factor follow a function's bare argument without a space (`sin θ/2`,
        `√m/k`), or a bracket follows a root's (`√2gL(1 - cos θ)`), so that they may be the argument's,
        as physics often means them. A bracketed argument says where it ends (`sin(θ)/2`), and so does a
        space (`sin θ /2`); `√2/2` is (√2)/2, √(2/2) being 1, which no one writes so, and `√2(1 + x)` is
        √2·(1 + x), as printed. An argument ending with a power (`sin θ^2/2`) keeps the reading the note
        on its power explains."""
        tokens = self._tokens
        follower = tokens[self._i]
        if follower.space_before or isinstance(argument, Group) or tokens[self._i - 1].kind is Kind.RPAREN:
            return False
        last = argument.rest[-1][1] if isinstance(argument, Product) else argument
        if isinstance(last, Power):
            return False  # `sin θ^2/2`: its power is the question, asked by the powered argument's note
        if root and (self._glued_bracket() or self._divided_by_bracket() or self._glued_function()):
            return not isinstance(argument, Num)  # `√2(1 + x)` is √2·(1 + x), as printed, `√3cosθ` √3·cos θ
        if self._glued_factor() != "/":
            return False
        divisor, after = tokens[self._i + 1], tokens[self._i + 2]
        return not (
            isinstance(argument, Num)
            and divisor.kind is Kind.NUM
            and divisor.value == argument.value
            and (after.space_before or after.kind not in (Kind.NAME, Kind.CONST, Kind.NUM))
        )

    def _glued_bracket(self) -> bool:
        """Whether a bracket (not a vulgar fraction's) opens here, typed on without a space."""
        tok = self._tokens[self._i]
        return (
            tok.kind is Kind.LPAREN
            and not tok.space_before
            and self._source[tok.pos : tok.pos + 1] in OPENERS
        )

    def _glued_function(self) -> bool:
        """Whether a function is typed on here without a space: `√gRtanθ`, √(gR)·tan θ or √(gR·tan θ)?"""
        tok = self._tokens[self._i]
        return tok.kind is Kind.FUNC and not tok.space_before

    def _divided_by_bracket(self) -> bool:
        """Whether a `/` and a bracket follow here, typed on without a space: `√2gh/(1 + k)`."""
        slash = self._tokens[self._i]
        if slash.kind is not Kind.OP or slash.text != "/" or slash.space_before:
            return False
        self._i += 1
        try:
            return self._glued_bracket()
        finally:
            self._i -= 1

    def _argument_follower(self, root: bool) -> Literal["*", "/"] | None:
        """How the word typed on after a bare argument goes on: `_glued_factor`'s, or for a root a
        bracket or a function (`*`) or a `/` before a bracket (`√2gh/(1 + I/mr²)`; a function's `sin θ/(1 + k)` is
        sin θ divided, as physics writes it)."""
        op = self._glued_factor()
        if op is not None or not root:
            return op
        if self._glued_bracket() or self._glued_function():
            return "*"
        return "/" if self._divided_by_bracket() else None

    def _settle_argument(
        self, func_tok: Token, func: str, argument: Node, power: Node | None, *, root: bool = False
    ) -> Node:
        """`sin θ/2` is sin(θ)/2 to the grammar, but is often meant sin(θ/2) (`2π√m/k` as 2π√(m/k)):
        `choices` reads it (by the position of the function or root sign) one way, 0 as the grammar does
        (the `/` left to the product), 1 with the `/` and the word typed on after it in the argument;
        without a choice it is refused. A division in that word may be ambiguous in turn."""
        choice = self._choices.get(func_tok.pos)
        if choice == 0:
            return argument
        items: list[_Item] = []
        op = self._argument_follower(root)
        while op is not None:
            tok = self._advance() if op == "/" else self._tokens[self._i]
            items.append(_Item(op, self._raised(self._postfixed(), tok.pos), tok, op == "*"))
            op = self._argument_follower(root)
        if choice == 1:
            first, items = self._settle_ambiguous_divisions(argument, items)
            return Product(first, tuple((i.op, i.node) for i in items)) if items else first
        rest = tuple((i.op, i.node) for i in items)
        shown = "sqrt" if func in ROOT_SIGNS else func

        def applied(inner: Node) -> Node:
            if func in ROOT_SIGNS and ROOT_SIGNS[func] != 2:
                index = Num(str(ROOT_SIGNS[func]), Fraction(ROOT_SIGNS[func]), True)
                return Power(Group(inner), Group(Product(Num("1", Fraction(1), True), (("/", index),))))
            call: Node = Call(shown, inner, func_tok.pos)
            return call if power is None else Power(call, power)

        readings = (
            render_text(Product(applied(argument), rest), STUDENT_STYLE),
            render_text(applied(Product(argument, rest)), STUDENT_STYLE),
        )
        raise AmbiguousGrouping(
            f"Did you mean {readings[0]} or {readings[1]}? Add parentheses.", func_tok.pos, readings
        )

    def _exponent(self) -> Node:
        tok = self._tokens[self._i]
        if tok.kind is Kind.OP and tok.text in "+-":
            self._advance()
            self._enter(tok)
            operand = self._exponent()
            self._leave()
            return Neg(operand) if tok.text == "-" else operand
        return self._power()

    def _postfixed(self) -> Node:
        return self._postfixes(self._atom())

    def _postfixes(self, node: Node) -> Node:
        while self._tokens[self._i].kind is Kind.POSTFIX:
            tok = self._advance()
            kind = _POSTFIX_KINDS[tok.text]
            if kind == "degrees":
                self._refuse_degrees_of_symbols(node, tok)
                self._refuse_degrees_of_a_value(node, tok)
            elif kind == "percent" and (name := _first_name(node)) is not None:
                # `0.5 m g %`: a percentage is of a number; after a symbol it would divide it by 100
                raise ParseError(
                    f"A % goes after a number, as in 50 % {name}: after {name} it would divide it by 100.",
                    tok.pos,
                )
            node = Postfix(kind, node, tok.pos)
        return node

    def _refuse_degrees_of_symbols(self, node: Node, sign: Token) -> None:
        """`cos(θ°)`, `sin (90-θ)°`: a symbol is an angle already (a problem's θ given as 30° is π/6), so
        θ° would be θ·π/180, which no one means by it; refused, saying where the ° goes."""
        name = _first_name(node)
        if name is None:
            return
        if isinstance(node, Name):
            raise ParseError(
                f"{self._source[self._tokens[self._i - 2].pos : sign.pos].strip()} is an angle already: "
                f"leave out the {self._typed(sign)} after it (a ° goes after a number, as in 30°).",
                sign.pos,
            )
        raise ParseError(
            f"The {self._typed(sign)} applies to all that comes before it, and {name} in it is an angle already: "
            "put the ° after the numbers alone, as in (90° - θ).",
            sign.pos,
        )

    def _refuse_degrees_of_a_value(self, node: Node, sign: Token) -> None:
        """`sin(30)°`, as a calculator's key order has it: as typed the ° turns sin(30), of 30 radians,
        into degrees, which no one means by it; refused, asking about the angle in degrees."""
        if not (isinstance(node, Call) and node.func in _TRIGONOMETRIC):
            return
        typed = self._source[node.pos : sign.pos].strip()
        number = ungroup(node.arg)
        meant = f"{node.func}({number.literal}°)" if isinstance(number, Num) else f"{node.func}(30°)"
        ask = f"Did you mean {meant}? " if isinstance(number, Num) else ""
        raise LikelySlip(
            f"{ask}The {self._typed(sign)} after {typed} would turn its value into degrees: put the ° inside "
            f"the brackets, after the angle's number, as in {meant}.",
            sign.pos,
        )

    def _atom(self) -> Node:
        tok = self._tokens[self._i]
        if tok.kind is Kind.NUM:
            self._advance()
            assert tok.value is not None
            return Num(tok.text, tok.value, tok.is_integer_literal)
        if tok.kind is Kind.NAME:
            self._advance()
            return Name(tok.text)
        if tok.kind is Kind.CONST:
            self._advance()
            return Const("pi" if tok.text == "pi" else "e")
        if tok.kind is Kind.FUNC:
            self._advance()
            return self._call(tok)
        if tok.kind is Kind.SQRT:
            self._advance()
            radicand = self._argument(tok, tok.text, bare_function=False)[0]
            settled: str | None = None
            if self._divisor_glued_to(radicand, root=True):  # `√m/k`: √m/k or √(m/k)?
                radicand = self._settle_argument(tok, tok.text, radicand, None, root=True)
                settled = self._typed_since(tok.pos)
            index = ROOT_SIGNS[tok.text]
            if index == 2:
                return Call("sqrt", radicand, tok.pos, settled)
            # `∛x` is x^(1/3), as `\sqrt[3]{x}` reads
            reciprocal = Product(
                Num("1", Fraction(1), True), (("/", Num(str(index), Fraction(index), True)),)
            )
            return Power(Group(radicand), Group(reciprocal), tok.pos, settled)
        if tok.kind is Kind.LPAREN:
            return Group(self._bracketed())
        if tok.kind is Kind.BAR:
            return self._bars()
        self._fail_atom(tok)

    def _bracketed(self) -> Node:
        opening = self._advance()
        if self._tokens[self._i].kind is Kind.RPAREN:
            before = self._tokens[self._i - 2] if self._i >= 2 else None
            if before is not None and before.kind is Kind.CONST and before.text == "pi":
                # `2*pi()`, as a spreadsheet writes π (`PI()`): a number, with no brackets
                raise ParseError(
                    f"π is a number, not a function: type {self._typed(before)} without the brackets.",
                    opening.pos,
                )
            raise ParseError("Empty brackets: write something inside them.", opening.pos)
        saved, self._abs_depth = self._abs_depth, 0
        inner = self._sum()
        self._abs_depth = saved
        closing = self._tokens[self._i]
        if closing.kind is Kind.RPAREN:
            if closing.text != OPENERS[opening.text]:
                raise ParseError(
                    f"'{closing.text}' does not match the '{opening.text}' at position {opening.pos}.",
                    closing.pos,
                )
            self._advance()
            return inner
        if closing.kind is Kind.END:
            raise ParseError(f"Unbalanced bracket: this '{opening.text}' is never closed.", opening.pos)
        self._fail_after_expression(closing)

    def _bars(self) -> Node:
        opening = self._advance()  # a | right after it opens a nested |...|, as in ||x| - 1|
        self._abs_depth += 1
        inner = self._sum()
        self._abs_depth -= 1
        closing = self._tokens[self._i]
        if closing.kind is Kind.BAR:
            self._advance()
            return Call("abs", inner, opening.pos)
        if closing.kind is Kind.END:
            raise ParseError("Unbalanced '|': this one is never closed.", opening.pos)
        self._fail_after_expression(closing)

    def _call(self, func_tok: Token) -> Node:
        func = func_tok.text
        typed = self._typed(func_tok)
        power: Node | None = None
        tok = self._tokens[self._i]
        if tok.kind is Kind.OP and tok.text in "^":
            if func == "exp" and self._tokens[self._i + 1].kind is Kind.LPAREN:
                self._refuse_exp_raised(tok)
            self._advance()
            power = self._function_power(typed)
        elif tok.kind is Kind.SUP:
            self._advance()
            power = _superscript_node(tok)
        # `sin^2 θ^2` (or `sin^-1 x^2`) already says where a power goes: its argument's power is no
        # slip to point out.
        bare_function = power is None
        if power is not None and _is_minus_one(power) and func in INVERSES:
            func, power = INVERSES[func], None
        argument, outside = self._argument(func_tok, typed, bare_function=bare_function)
        root = func == "sqrt"
        settled: str | None = None
        if outside is None and self._divisor_glued_to(
            argument, root=root
        ):  # `sin θ/2`: sin(θ)/2 or sin(θ/2)?
            argument = self._settle_argument(func_tok, func, argument, power, root=root)
            settled = self._typed_since(func_tok.pos)
        if power is not None:
            return Power(Call(func, argument, func_tok.pos), power, func_tok.pos, settled)
        node: Node = Call(func, argument, func_tok.pos, settled)
        return Power(node, outside.exponent, outside.pos) if outside is not None else node

    def _refuse_exp_raised(self, caret: Token) -> None:
        """`exp^(-t/τ)`, e's power written with exp's name, as WeBWorK and calculators write e^x: as typed
        a power of exp waiting for its argument. Refused with the two ways to write it, unless an argument
        follows the power (`exp^2(x)`, a power of exp)."""
        depth, at = 0, self._i + 1
        while True:
            kind = self._tokens[at].kind
            depth += {Kind.LPAREN: 1, Kind.RPAREN: -1}.get(kind, 0)
            if kind is Kind.END:
                return  # an unclosed bracket: its own refusal says where
            if depth == 0:
                break
            at += 1
        following = self._tokens[at + 1]
        if following.kind in (Kind.LPAREN, Kind.NUM, Kind.NAME, Kind.CONST) and not following.space_before:
            return
        power = self._source[self._tokens[self._i + 1].pos : self._tokens[at].end]
        raise ParseError(
            f"Did you mean e^{power}? Write e's power as e^{power} or exp{power}, not both.", caret.pos
        )

    def _function_power(self, typed: str) -> Node:
        tok = self._tokens[self._i]
        if (tok.kind is Kind.OP and tok.text in "+-") and self._tokens[self._i + 1].kind is Kind.NUM:
            self._advance()
            number = self._advance()
            assert number.value is not None
            node = Num(number.text, number.value, number.is_integer_literal)
            return Neg(node) if tok.text == "-" else node
        if tok.kind is Kind.NUM:
            self._advance()
            assert tok.value is not None
            return Num(tok.text, tok.value, tok.is_integer_literal)
        if tok.kind is Kind.LPAREN:
            return Group(self._bracketed())
        raise ParseError(f"Write a power of {typed} as {typed}^2(x) or {typed}(x)^2.", tok.pos)

    def _argument(self, func_tok: Token, typed: str, *, bare_function: bool) -> tuple[Node, Power | None]:
        """A function written without brackets takes the next factor, or the word typed without a space
        that starts with it: `sin 2θ`, `sin θ^2`, `√x`, `cos ωt`, `√2gh` (but `sin θ m` is sin(θ)·m).

        Returns the argument, and, for a `bare_function` (no power of its own, not `√`: `√x^2` is
        plainly √(x²)) whose argument ends with a power, the power to raise the function to instead
        when `powers_outside` (`sin θ^2` as (sin θ)²), else None."""
        tok = self._tokens[self._i]
        # `½` is read as the bracket `(1/2)`, but is typed as a number is: `sin ½θ` is sin(½θ), as `sin 2θ`
        vulgar = tok.kind is Kind.LPAREN and (
            self._source[tok.pos : tok.pos + 1] in VULGAR_FRACTIONS
            or script_fraction(self._source, tok.pos) is not None  # `sin ¹⁄₂θ`, as `sin ½θ`
        )
        if tok.kind is Kind.LPAREN and not vulgar:
            return Group(self._bracketed()), None
        if tok.kind is Kind.BAR:
            return self._bars(), None
        if vulgar or tok.kind in (Kind.NUM, Kind.NAME, Kind.CONST, Kind.FUNC, Kind.SQRT):
            self._enter(tok)
            start = self._i
            base = self._postfixed()
            factors = [self._raised(base, tok.pos)]
            # The word typed without a space is the argument: `cos ωt`, `sin kx`, `√2gh`, `sin 2πft`
            # (`word_ends` may end it earlier: `sinθmgL` as sin(θ)·m·g·L, where only that has a dimension).
            ends = self._word_ends.get(func_tok.pos) if self._word_ends else None
            while tok.kind is not Kind.FUNC and tok.kind is not Kind.SQRT:
                follower = self._tokens[self._i]
                if follower.kind not in (Kind.NAME, Kind.CONST) or follower.space_before:
                    break
                if ends is not None and len(factors) >= ends:
                    break
                base = self._postfixed()
                factors.append(self._raised(base, follower.pos))
            self._leave()
            if len(factors) > 1 and ends is None and func_tok.kind is Kind.FUNC and func_tok.text != "sqrt":
                self.long_words.append((func_tok.pos, len(factors)))
            if len(factors) == 1 and func_tok.text in _TRIGONOMETRIC:
                self._refuse_number_spaced_from_its_word(func_tok, typed, factors[0])
            last = factors[-1]
            node = _product_of(factors)
            if last is base or not isinstance(last, Power) or not bare_function:
                return node, None
            typed_as = self._powered_argument(func_tok, start, last)
            if typed_as is None:
                return node, None
            self.powered.append(typed_as)
            if not self._powers_outside:
                return node, None
            return _product_of([*factors[:-1], last.base]), last
        if tok.kind is Kind.OP and tok.text in "+-":
            after = self._tokens[self._i + 1]
            inverse = INVERSES.get(func_tok.text)
            if inverse is not None and tok.text == "-" and after.kind is Kind.NUM and after.text == "1":
                # `tan-1(y/x)`, a calculator's key label for the inverse
                raise ParseError(
                    f"Did you mean the inverse, {typed}^-1(…) (also written {inverse}(…))? Write {typed}^-1 "
                    f"with its ^; for {typed} of a negative number, put it in brackets: {typed}(-x).",
                    tok.pos,
                )
            raise ParseError(f"Put the argument of {typed} in brackets, as in {typed}(-x).", tok.pos)
        raise ParseError(f"{typed} needs an argument, as in {typed}(x).", func_tok.pos)

    def _refuse_number_spaced_from_its_word(self, func_tok: Token, typed: str, argument: Node) -> None:
        """`sin 2 θ`, `cos ½ ωt`: a number, then a space, then a word: sin(2)·θ as the space reads it, which
        no one means (a trigonometric function of a bare number is an angle in radians, 2 rad), or sin(2θ)?
        Refused with both; `sin 30° x` (the degree sign says the number is the angle) stays."""
        tokens = self._tokens
        follower = tokens[self._i]
        if follower.kind not in (Kind.NAME, Kind.CONST) or not follower.space_before:
            return
        number = ungroup(argument)
        if not isinstance(number, Num) and not (
            isinstance(number, Product) and isinstance(number.first, Num) and len(number.rest) == 1
        ):
            return  # a number, or `½` (the bracket (1/2))
        end = self._i
        while tokens[end + 1].kind in (Kind.NAME, Kind.CONST) and not tokens[end + 1].space_before:
            end += 1
        number_text = self._source[func_tok.end : follower.pos].strip()
        word = self._source[follower.pos : tokens[end].end]
        readings = (f"{typed}({number_text}{word})", f"{typed}({number_text})·{word}")
        raise AmbiguousInput(
            f"Did you mean {readings[0]} or {readings[1]}? A space ends the argument of {typed}: write "
            f"{readings[0]} (or {number_text}{word} without the space), or {readings[1]}.",
            follower.pos,
            readings,
        )

    def _powered_argument(self, func_tok: Token, start: int, power: Power) -> PoweredArgument | None:
        """How `sin θ^2` was typed, from the tokens of its argument (from `start`) and its final power;
        None if the power's sign cannot be found among them (then nothing is said about it)."""
        caret = next((t for t in self._tokens[start : self._i] if t.pos == power.pos), None)
        if caret is None or caret.kind not in (Kind.OP, Kind.SUP):
            return None
        end = self._tokens[self._i - 1].end
        exponent = ungroup(power.exponent)
        whole = (
            int(exponent.value)
            if isinstance(exponent, Num) and exponent.integer_literal and exponent.value > 0
            else None
        )
        source = self._source
        return PoweredArgument(
            typed=source[func_tok.pos : end],
            function=self._typed(func_tok),
            base=source[self._tokens[start].pos : caret.pos].rstrip(),
            exponent=source[caret.end : end] if caret.kind is Kind.OP else str(caret.value),
            whole_power=whole,
        )

    # -- errors --------------------------------------------------------------------------------
    def _fail_atom(self, tok: Token) -> NoReturn:
        prev = self._prev
        if tok.kind is Kind.END:
            if prev is not None and prev.kind is Kind.OP:
                raise ParseError(f"Nothing after '{self._typed(prev)}'.", prev.pos)
            if prev is not None and prev.kind in (Kind.LPAREN, Kind.BAR):
                raise ParseError(f"Unbalanced bracket: this '{prev.text}' is never closed.", prev.pos)
            raise ParseError("The answer ends too early.", tok.pos)
        if tok.kind is Kind.OP:
            if prev is not None and prev.kind is Kind.OP:
                raise ParseError(f"Nothing between '{self._typed(prev)}' and '{self._typed(tok)}'.", tok.pos)
            raise ParseError(f"Nothing before '{self._typed(tok)}'.", tok.pos)
        if tok.kind is Kind.RPAREN:
            if prev is not None and prev.kind is Kind.OP:
                raise ParseError(f"Nothing after '{self._typed(prev)}'.", prev.pos)
            raise ParseError(f"Unexpected '{tok.text}'.", tok.pos)
        raise ParseError(f"Unexpected '{self._typed(tok)}'.", tok.pos)

    def _fail_after_expression(self, tok: Token) -> NoReturn:
        if tok.kind is Kind.RPAREN:
            raise ParseError(f"Unmatched '{tok.text}': no bracket opens it.", tok.pos)
        if tok.kind is Kind.BAR:
            raise ParseError("Unexpected '|'.", tok.pos)
        raise ParseError(f"Unexpected '{self._typed(tok)}'.", tok.pos)


def _first_name(node: Node) -> str | None:
    """The first symbol in the tree, or None: whether a degree sign is put on a symbol."""
    stack = [node]
    while stack:
        current = stack.pop()
        if isinstance(current, Name):
            return current.name
        if isinstance(current, (Group, Neg, Postfix)):
            stack.append(current.inner if isinstance(current, Group) else current.operand)
        elif isinstance(current, Sum):
            stack.extend(term for _, term in reversed(current.rest))
            stack.append(current.first)
        elif isinstance(current, Product):
            stack.extend(factor for _, factor in reversed(current.rest))
            stack.append(current.first)
        elif isinstance(current, Power):
            stack.extend((current.exponent, current.base))
        elif isinstance(current, Call):
            stack.append(current.arg)
    return None


def _superscript_node(tok: Token) -> Node:
    assert tok.value is not None
    magnitude = abs(tok.value)
    node = Num(str(magnitude), magnitude, True)
    return Neg(node) if tok.value < 0 else node


def _is_minus_one(node: Node) -> bool:
    node = ungroup(node)
    if isinstance(node, Neg):
        inner = ungroup(node.operand)
        return isinstance(inner, Num) and inner.value == 1
    return isinstance(node, Num) and node.value == -1


def _product_of(factors: list[Node]) -> Node:
    return factors[0] if len(factors) == 1 else Product(factors[0], tuple(("*", f) for f in factors[1:]))


def _number_after_an_exponent(tokens: list[Token], at: int) -> bool:
    """Whether the number at `at` follows an exponent: `x^2 3`, `x^-2 3`, `x^2 10^3`."""
    before = [t.text if t.kind is Kind.OP else "" for t in tokens[max(at - 3, 0) : at - 1]]
    return before[-1:] == ["^"] or (before[-2:-1] == ["^"] and before[-1] in ("+", "-"))


def _is_raised(token: Token) -> bool:
    return token.kind is Kind.SUP or (token.kind is Kind.OP and token.text == "^")


def _after_times_ten(tokens: list[Token], at: int) -> bool:
    """Whether the minus at `at` follows a number times 10, `3.0×10-3`, the number no exponent."""
    return (
        at >= 3
        and tokens[at - 1].text == "10"
        and tokens[at - 1].kind is Kind.NUM
        and tokens[at - 2].kind is Kind.OP
        and tokens[at - 2].text == "*"
        and tokens[at - 3].kind is Kind.NUM
        and not (at >= 4 and _is_raised(tokens[at - 4]))
        and tokens[at + 1].is_integer_literal
    )


_ENDS_A_FACTOR = (Kind.NAME, Kind.CONST, Kind.RPAREN, Kind.POSTFIX, Kind.SUP)


def _after_a_factor_and_ten(tokens: list[Token], at: int) -> bool:
    """Whether the minus (or the exponent's digits, `g sin α 10 3`) at `at` follows a 10 after a factor
    that is no number, `g sin α 10 -3` or `m g*10-3`: the 10 no one writes there but as a power of ten."""
    if at < 2 or tokens[at - 1].text != "10" or tokens[at - 1].kind is not Kind.NUM:
        return False
    before = tokens[at - 2]
    if before.kind is Kind.OP and before.text == "*":
        before = tokens[at - 3] if at >= 3 else before
    elif not tokens[at - 1].space_before:
        return False
    exponent = tokens[at] if tokens[at].kind is Kind.NUM else tokens[at + 1]
    return before.kind in _ENDS_A_FACTOR and exponent.is_integer_literal


def _times_a_power_of_ten(tokens: list[Token], at: int) -> bool:
    """`4.58 10^3`: scientific notation with its × left out, as a calculator shows it, refused saying
    where the × goes. The number before is no exponent (`x^2 10^3` may be x^(2·10^3))."""
    return (
        tokens[at].text == "10" and _is_raised(tokens[at + 1]) and not _number_after_an_exponent(tokens, at)
    )
