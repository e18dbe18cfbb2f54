"""Building the sympy expression from the parse tree through constructors, with size checks first.

Every power of exact numbers is sized (bits ~ |exponent| * log2|base|) before sympy computes it, integer
exponents on anything else are capped, and every exact number that comes out is measured, so `9^9^9`,
`(x+2)^10000` and `factorial(10^9)` are refused in microseconds instead of running for minutes.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from typing import cast

import sympy

from physics.errors import ParseError, TooLarge
from physics.mathinput.exact import exact_number
from physics.mathinput.limits import InputLimits
from physics.mathinput.tree import Call, Const, Group, Name, Neg, Node, Num, Power, Product, Sum
from physics.overflow import beyond_float

# sympy factors the number under a numeric root (seconds for a 2000-bit fraction; a q-th root of a
# fraction first raises its denominator to the power q-1) and merges roots in products, so all numeric
# roots of one answer share this budget of radicand bits times root degree.
_ROOT_BITS_BUDGET = 512
# Exact numbers above this size each cost sympy real work (trig of pi/big, logs, gcds); an answer may
# build distinct ones only up to twice max_int_bits in total.
_BIG_NUMBER_BITS = 256
# A root of an expression that may be negative may be complex, and sympy, building a root or abs() of
# such roots nested in one another, asks whether each is real through its argument, which asks the
# same of the roots inside it: the time grows five- to tenfold per level (abs of a sum of roots of
# negatives three deep took 0.6 s, a plain nest eight deep seconds). Two such levels are far more than
# physics needs (sqrt(2g(h - sqrt(R^2 - x^2)))); roots of what is surely nonnegative are not counted.
_MAX_ROOT_NESTING = 2
# A function asks whether its argument is real or positive, and sympy answers for an argument that may
# be complex by writing out its real and imaginary parts: a power (a + ib)^n as n + 1 terms, of the parts
# of a and b, a function's parts from its argument's. `_complex_weight` is about that size; past the
# budget the parts took from a third of a second (abs(cosh(cosh(acos(x)^5)^5)), weight 56) to minutes
# (cosh(cosh(θ acos(θ)^100)^100)), while what is surely real weighs 1 and physics answers a few.
_COMPLEX_WEIGHT_BUDGET = 40
# asin(sin(N)) and its kin reduce a constant N modulo 2π and compare the rest with π, at most to sympy's
# evalf precision: past about 10^105 the comparison cannot be decided and sympy raises (a grader crash,
# not a verdict). Such an angle has no meaning to check; below this size sympy reduces it exactly.
_MAX_REDUCED_ANGLE = 2.0**300
_INVERSE_TRIG = frozenset({"asin", "acos", "atan", "asec", "acsc", "acot"})
_TRIG = (sympy.sin, sympy.cos, sympy.tan, sympy.sec, sympy.csc, sympy.cot)

FUNCTIONS: dict[str, Callable[[sympy.Expr], sympy.Expr]] = {
    "exp": sympy.exp,
    "log": sympy.log,
    "log10": lambda x: sympy.log(x, 10),
    "abs": sympy.Abs,
    "sin": sympy.sin,
    "cos": sympy.cos,
    "tan": sympy.tan,
    "sec": sympy.sec,
    "csc": sympy.csc,
    "cot": sympy.cot,
    "asin": sympy.asin,
    "acos": sympy.acos,
    "atan": sympy.atan,
    "asec": sympy.asec,
    "acsc": sympy.acsc,
    "acot": sympy.acot,
    "sinh": sympy.sinh,
    "cosh": sympy.cosh,
    "tanh": sympy.tanh,
    "asinh": sympy.asinh,
    "acosh": sympy.acosh,
    "atanh": sympy.atanh,
}


class Builder:
    def __init__(self, symbols: Mapping[str, sympy.Symbol], limits: InputLimits) -> None:
        self._symbols = symbols
        self._limits = limits
        self._position = 0  # of the operator being built, for size errors
        self._root_bits = 0
        self._big_numbers: set[sympy.Rational] = set()
        self._big_bits = 0
        self._weights: dict[sympy.Basic, int] = {}

    def build(self, node: Node) -> sympy.Expr:
        return self._checked(self._build(node))

    def _too_large(self, message: str) -> TooLarge:
        return TooLarge(message, self._position)

    def _build(self, node: Node) -> sympy.Expr:
        if isinstance(node, Group):
            return self._build(node.inner)
        if isinstance(node, Num):
            return cast(sympy.Expr, exact_number(node.value.numerator, node.value.denominator))
        if isinstance(node, Name):
            return cast(sympy.Expr, self._symbols[node.name])
        if isinstance(node, Const):
            return cast(sympy.Expr, sympy.pi if node.which == "pi" else sympy.E)
        if isinstance(node, Neg):
            return self._checked(-self._build(node.operand))
        if isinstance(node, Sum):
            terms = [self._build(node.first)]
            for sign, term in node.rest:
                value = self._build(term)
                terms.append(value if sign == "+" else -value)
            return self._checked(sympy.Add(*terms))
        if isinstance(node, Product):
            return self._product(node)
        if isinstance(node, Power):
            base, exponent = self._build(node.base), self._build(node.exponent)
            self._position = node.pos
            return self._power(base, exponent)
        if isinstance(node, Call):
            arg = self._build(node.arg)
            self._position = node.pos
            if arg.is_number and not arg.is_Rational and beyond_float(arg):
                # sympy would reduce sec(e^(10^40)) modulo π with π to as many bits as the argument's
                # magnitude has, whenever it is asked whether the value is real (here, or building on it).
                raise self._too_large(f"The argument of {node.func}(…) is too large to compute with.")
            if self._complex_weight(arg) > _COMPLEX_WEIGHT_BUDGET:
                raise self._too_large(f"The argument of {node.func}(…) is too complicated to compute with.")
            if node.func in _INVERSE_TRIG and isinstance(arg, _TRIG) and _beyond_reduction(arg.args[0]):
                raise self._too_large(f"The angle inside {node.func}(…) is too large to compute with.")
            if node.func == "factorial":
                return self._factorial(arg)
            if node.func == "sqrt":
                return self._power(arg, sympy.Rational(1, 2))
            return self._real(self._checked(FUNCTIONS[node.func](arg)), node.func)
        operand = self._build(node.operand)
        self._position = node.pos
        if node.kind == "factorial":
            return self._factorial(operand)
        if node.kind == "percent":
            return self._checked(operand * sympy.Rational(1, 100))
        return self._checked(operand * sympy.pi / 180)

    def _product(self, node: Product) -> sympy.Expr:
        """The product as the left-to-right fold Mul(Mul(a, b), c)... builds it, each step size-checked;
        but a run of factors that `_Run` admits is multiplied in one Mul call, which gives the fold's
        very tree at a fraction of its cost (sympy sorts the arguments once, not once per factor)."""
        first = self._build(node.first)
        if len(node.rest) == 1:  # one Mul call either way
            operator, factor = node.rest[0]
            value = self._build(factor)
            return self._checked(sympy.Mul(first, _reciprocal(value) if operator == "/" else value))
        run = _Run(first, self._limits)
        for operator, factor in node.rest:
            value = self._build(factor)
            if operator == "/":
                value = _reciprocal(value)
            if not run.admits(value):
                run = _Run(self._checked(sympy.Mul(self._multiplied(run), value)), self._limits)
        return self._multiplied(run)

    def _multiplied(self, run: _Run) -> sympy.Expr:
        factors = run.factors
        return factors[0] if len(factors) == 1 else self._checked(sympy.Mul(*factors))

    def _power(self, base: sympy.Expr, exponent: sympy.Expr) -> sympy.Expr:
        limits = self._limits
        if exponent.is_Rational:
            p, q = int(exponent.p), int(exponent.q)
            if base.is_Rational:
                if base == 10 and q == 1 and abs(p) > limits.max_sci_exponent:
                    raise self._too_large(
                        f"A power of ten is too large (at most 10^{limits.max_sci_exponent})."
                    )
                size = max(abs(int(base.p)), int(base.q))
                if base != 0 and size > 1:
                    if q > limits.max_exponent:
                        raise self._too_large("A root of a number is too deep to compute exactly.")
                    if q > 1:
                        self._root_bits += (int(base.p).bit_length() + int(base.q).bit_length()) * q
                        if self._root_bits > _ROOT_BITS_BUDGET:
                            raise self._too_large("The numbers under roots in the answer are too large.")
                    budget = limits.max_int_bits * q  # the first test keeps a huge p out of float()
                    if abs(p) > budget or abs(p) * math.log2(size) > budget:
                        raise self._too_large("A power of numbers in the answer is too large to compute.")
            elif base is not sympy.E and (abs(p) > limits.max_exponent * q or q > limits.max_exponent):
                raise self._too_large(f"An exponent is too large (at most {limits.max_exponent}).")
        if not exponent.is_Integer and self._complex_weight(base) > _COMPLEX_WEIGHT_BUDGET:
            raise self._too_large("The base of this power is too complicated to compute with.")
        if not exponent.is_Integer and _root_nesting(base) >= _MAX_ROOT_NESTING:
            raise self._too_large(
                f"Roots of expressions that may be negative are nested too deeply (at most {_MAX_ROOT_NESTING} "
                "inside one another)."
            )
        return self._real(self._checked(sympy.Pow(base, exponent)), "power")

    def _complex_weight(self, expr: sympy.Basic) -> int:
        """The size sympy's real and imaginary parts of `expr` would have (`_COMPLEX_WEIGHT_BUDGET`)."""
        known = self._weights.get(expr)
        if known is not None:
            return known
        if _surely_real(expr):
            weight = 1
        elif expr.is_Add or expr.is_Mul:
            weight = sum(self._complex_weight(arg) for arg in expr.args)
        elif expr.is_Pow and expr.exp.is_Integer:
            weight = self._complex_weight(expr.base) * abs(int(expr.exp))
        else:  # a function or a root: its parts are functions of its argument's
            weight = 1 + sum(self._complex_weight(arg) for arg in expr.args)
        weight = min(weight, _COMPLEX_WEIGHT_BUDGET + 1)  # keeps the products small
        self._weights[expr] = weight
        return weight

    def _real(self, expr: sympy.Expr, what: str) -> sympy.Expr:
        """Refuse a constant with no real value (acos(2), sqrt(-1)): nothing physical is imaginary, and
        sympy's automatic simplification of powers of such constants can run for minutes."""
        # zoo and nan (1/0, log(0)) are refused elsewhere, as having no value at all.
        if expr.is_number and expr.is_finite is not False and expr.is_extended_real is False:
            message = (
                "This power has no real value; check its base and exponent."
                if what == "power"
                else f"{what}(…) has no real value here; check its argument."
            )
            raise ParseError(message, self._position)
        return expr

    def _factorial(self, arg: sympy.Expr) -> sympy.Expr:
        if arg.is_Rational and abs(arg) > self._limits.max_factorial:
            raise self._too_large(f"A factorial is too large (at most {self._limits.max_factorial}!).")
        return self._checked(sympy.factorial(arg))

    def _checked(self, expr: sympy.Expr) -> sympy.Expr:
        """Refuse an exact number that grew too large, or a power that sympy merged past the cap."""
        for part in (expr, *expr.args):
            if part.is_Rational:
                bits = max(abs(int(part.p)), int(part.q)).bit_length()
                if bits > self._limits.max_int_bits:
                    raise self._too_large("A number in the answer is too large to compute exactly.")
                if bits > _BIG_NUMBER_BITS and part not in self._big_numbers:
                    self._big_numbers.add(part)
                    self._big_bits += bits
                    if self._big_bits > 2 * self._limits.max_int_bits:
                        raise self._too_large("The answer computes with too many large numbers.")
            elif part.is_Pow and part.exp.is_Rational and not part.base.is_Rational:
                exp = part.exp
                if abs(int(exp.p)) > self._limits.max_exponent * int(exp.q):
                    raise self._too_large(f"An exponent is too large (at most {self._limits.max_exponent}).")
        return expr


class _Run:
    """Factors whose product in one Mul call is the tree the pairwise fold builds, with no size check
    failing on the way: every factor's parts (a Mul's arguments, or the factor itself) are distinct
    powers of distinct non-numeric bases, after at most one exact coefficient per factor; or a factor
    is a nonzero exact number, opening the run or joining parts that are not one sum alone.

    Why that suffices: sympy's Mul.flatten then merges nothing (no two parts share a base, and it
    merges numeric powers only, which are kept out), so each step only multiplies the coefficients
    and sorts the parts into its canonical order; a product of the same parts and coefficients sorts
    the same in one call. The two cases where flatten distributes a number over a sum (its 2-argument
    rule, and a result that is a number times one sum) need a step that multiplies a number and one
    sum (with or without a coefficient), or a step whose result is a coefficient and one sum: a run
    has neither. A number joins only parts that are not one sum alone; after a number that opens the
    run, the next factor may not be one sum; and every other step brings parts to parts (two at
    least, none cancelling). The coefficients' bits are budgeted below every size check, and every
    part was size-checked when its factor was built (a reciprocal's exponents only change sign), so
    the fold's per-step checks would refuse nothing either.
    """

    def __init__(self, first: sympy.Expr, limits: InputLimits) -> None:
        self.factors: list[sympy.Expr] = []
        self._bases: set[sympy.Basic] = set()
        self._budget = min(_BIG_NUMBER_BITS, limits.max_int_bits)
        self._parts = 0  # non-numeric parts taken
        self._one_sum = False  # the parts taken are one sum alone
        self._open = self._take(first)
        self.factors.append(first)

    def admits(self, value: sympy.Expr) -> bool:
        """Take `value` into the run if one Mul call over the run stays the fold's tree."""
        if not self._open or not self._take(value):
            return False
        self.factors.append(value)
        return True

    def _take(self, value: sympy.Expr) -> bool:
        if value.is_Rational:
            # Opening the run, or joining parts: the step multiplies it into their coefficient.
            if value == 0 or self._one_sum or (self.factors and not self._parts):
                return False
            return self._spend(_bits(value))
        parts = value.args if value.is_Mul else (value,)
        bits = 0
        if parts[0].is_Number and value.is_Mul:
            coefficient = parts[0]
            if not coefficient.is_Rational:
                return False
            bits = _bits(coefficient)
            parts = parts[1:]
        bases = []
        for part in parts:
            if part is sympy.I or not part.is_commutative:
                return False
            base = part.as_base_exp()[0]
            if base.is_Number:
                return False
            bases.append(base)
        one_sum = len(parts) == 1 and parts[0].is_Add
        if (
            not bases
            or (one_sum and self.factors and not self._parts)  # a number times one sum
            or len(set(bases)) < len(bases)
            or self._bases.intersection(bases)
            or not self._spend(bits)
        ):
            return False
        self._bases.update(bases)
        self._one_sum = one_sum and not self._parts
        self._parts += len(parts)
        return True

    def _spend(self, bits: int) -> bool:
        if bits > self._budget:
            return False
        self._budget -= bits
        return True


def _root_nesting(expr: sympy.Basic) -> int:
    """How deep roots (non-integer powers) of what may be negative nest in `expr`, one inside another's base."""
    inner = max((_root_nesting(arg) for arg in expr.args), default=0)
    if expr.is_Pow and not expr.exp.is_Integer and not _surely_nonnegative(expr.base):
        return inner + 1
    return inner


def _surely_nonnegative(expr: sympy.Basic) -> bool:
    """Nonnegative by its form alone (sympy's own answer is the costly question): unknown is False."""
    if expr.is_Number or expr.is_NumberSymbol or expr.is_Symbol:
        return bool(expr.is_nonnegative)  # a stored assumption, or a number's sign
    if expr.is_Add or expr.is_Mul:
        return all(_surely_nonnegative(arg) for arg in expr.args)
    if expr.is_Pow:
        even = expr.exp.is_Integer and expr.exp.is_even
        return _surely_nonnegative(expr.base) or bool(even and expr.base.is_Symbol and expr.base.is_real)
    return isinstance(expr, sympy.Abs)


# Real for every real argument (or infinite: tan at a pole is not complex).
_REAL_OF_REAL = (
    *(sympy.sin, sympy.cos, sympy.tan, sympy.sec, sympy.csc, sympy.cot),
    *(sympy.exp, sympy.sinh, sympy.cosh, sympy.tanh, sympy.atan, sympy.acot),
)


def _surely_real(expr: sympy.Basic) -> bool:
    """Real by its form alone (sympy's own answer is the costly question): unknown is False."""
    if expr.is_Rational or expr.is_Float or expr.is_NumberSymbol or expr.is_Symbol:
        return bool(expr.is_real)  # a stored assumption
    if expr.is_Add or expr.is_Mul:
        return all(_surely_real(arg) for arg in expr.args)
    if expr.is_Pow:
        return (expr.exp.is_Integer and _surely_real(expr.base)) or (
            _surely_nonnegative(expr.base) and _surely_real(expr.exp)
        )
    if isinstance(expr, sympy.Abs) or (isinstance(expr, sympy.log) and _surely_nonnegative(expr.args[0])):
        return True  # log(0) has no value at all, and is refused as such
    return isinstance(expr, _REAL_OF_REAL) and _surely_real(expr.args[0])


def _beyond_reduction(angle: sympy.Basic) -> bool:
    """Whether a constant angle is too large for sympy to reduce modulo 2π (`_MAX_REDUCED_ANGLE`)."""
    if not angle.is_number:
        return False
    try:
        return abs(complex(angle)) > _MAX_REDUCED_ANGLE
    except (TypeError, OverflowError):
        return True


def _bits(number: sympy.Rational) -> int:
    return int(number.p).bit_length() + int(number.q).bit_length()


def _reciprocal(value: sympy.Expr) -> sympy.Expr:
    """1/value. A nonzero exact number is inverted directly: the object `Pow(value, -1)` would return,
    without the sign queries that sympy's Pow makes of it first (over a tenth of a millisecond for each
    number not met before, such as the 7 of `x/7`)."""
    if value.is_Rational and value.p != 0:
        return cast(sympy.Expr, exact_number(int(value.q), int(value.p)))
    # S.NegativeOne, not the int -1: the same power, under the key sympy's cache gives the one Mul.flatten
    # asks for when it rebuilds each factor of a product (Pow(base, S.NegativeOne)); with the int it
    # missed, and every denominator was computed a second time.
    return cast(sympy.Expr, sympy.Pow(value, sympy.S.NegativeOne))
