"""Per-student given values, drawn deterministically, and the student's view of a problem.

A variant is a pure function of (server secret, problem id, version, student): HMAC-SHA256 of the
three, per given symbol, picks a point uniformly in [min, max], rounded to the given's sigfigs or
step. The same student therefore always sees the same numbers, students see different ones, and
nobody can predict another student's numbers without the secret.
"""

from __future__ import annotations

import hashlib
import hmac
import re
from collections.abc import Mapping
from dataclasses import dataclass, field
from decimal import ROUND_CEILING, ROUND_FLOOR, ROUND_HALF_EVEN, Decimal, localcontext
from typing import TYPE_CHECKING

import sympy

from physics.errors import SpecError
from physics.numeric.rounding import round_sigfigs
from physics.units import parse_units
from problems.fields import DEFAULT_SIGFIGS, GivenDecl

if TYPE_CHECKING:
    from problems.schema import ProblemDocument

REFERENCE_DIGITS = 30  # working precision of the numeric reference
REFERENCE_SIGNIFICANT = 12  # digits kept in the reference value
_HASH_SPAN = 2**64
_DEGREE_SPELLINGS = frozenset({"deg", "°", "degree", "degrees"})


@dataclass(frozen=True)
class Variant:
    """One student's given values, each a Decimal in its given's unit (as shown to the student)."""

    problem: str
    version: int
    student: str
    values: Mapping[str, Decimal] = field(default_factory=dict)


def draw_variant(doc: ProblemDocument, version: int, student: str, secret: str | bytes) -> Variant:
    """The student's given values: deterministic in (secret, id, version, student), per symbol."""
    key = secret.encode("utf-8") if isinstance(secret, str) else secret
    values = {
        name: draw_value(given, _uniform(key, doc.id, version, student, name))
        for name, given in doc.given.items()
    }
    return Variant(doc.id, version, student, values)


def fixed_variant(
    doc: ProblemDocument, values: Mapping[str, Decimal | int | str], version: int = 0
) -> Variant:
    """A variant with chosen values (tests, worked examples); unlisted givens take their midpoint."""
    chosen = {name: draw_value(given, Decimal("0.5")) for name, given in doc.given.items()}
    chosen.update({name: Decimal(str(value)) for name, value in values.items()})
    return Variant(doc.id, version, "", chosen)


def _uniform(key: bytes, problem: str, version: int, student: str, name: str) -> Decimal:
    # Unit-separator joins keep ("ab", "c") and ("a", "bc") apart.
    message = "\x1f".join((problem, str(version), student, name)).encode("utf-8")
    digest = hmac.new(key, message, hashlib.sha256).digest()
    with localcontext() as ctx:
        ctx.prec = 40
        return Decimal(int.from_bytes(digest[:8], "big")) / Decimal(_HASH_SPAN)


def draw_value(given: GivenDecl, u: Decimal) -> Decimal:
    """The value at fraction u ∈ [0, 1) of the given's range, on its step grid or to its sigfigs."""
    low, high = given.min, given.max
    if low == high:
        return low
    with localcontext() as ctx:
        ctx.prec = 40
        if given.step is not None:
            count = int((high - low) / given.step) + 1  # grid points low, low + step, ... <= high
            index = min(int(u * count), count - 1)
            return low + given.step * index
        raw = low + (high - low) * u
        sigfigs = given.sigfigs or DEFAULT_SIGFIGS
        # Half-even, not the grading rule: changing it would change every student's drawn values.
        value = round_sigfigs(raw, sigfigs, ROUND_HALF_EVEN)
        # Rounding may step outside the range; round towards it instead.
        if value < low:
            value = round_sigfigs(raw, sigfigs, ROUND_CEILING)
        elif value > high:
            value = round_sigfigs(raw, sigfigs, ROUND_FLOOR)
        return value


def valid_range_errors(given: GivenDecl) -> list[str]:
    """Faults of a given's range that the schema cannot see: empty range, no rounded value inside."""
    if given.min > given.max:
        return ["min must be <= max"]
    if given.min == given.max:
        return []
    if given.step is not None:
        return []
    sigfigs = given.sigfigs or DEFAULT_SIGFIGS
    if given.min != 0 and round_sigfigs(given.min, sigfigs, ROUND_CEILING) > given.max:
        return [f"no value with {sigfigs} significant figures lies in [{given.min}, {given.max}]"]
    return []


# ---- units and SI values ----------------------------------------------------------------------


def unit_scale(unit: str) -> sympy.Expr:
    """SI value of one `unit`, exact: degrees are pi/180 (not a float), `1` is 1."""
    text = unit.strip()
    if text in {"1", ""}:
        return sympy.Integer(1)
    if text in _DEGREE_SPELLINGS:
        return sympy.pi / 180
    parsed = parse_units(text)
    if parsed.offset:
        raise SpecError(f"{text} has an offset zero; give temperatures in K", ("unit",))
    scale = parsed.scale
    return sympy.Rational(scale.numerator, scale.denominator)


def _decimal_to_rational(value: Decimal) -> sympy.Rational:
    numerator, denominator = value.as_integer_ratio()
    return sympy.Rational(numerator, denominator)


def si_values(
    doc: ProblemDocument, variant: Variant, table: Mapping[str, sympy.Symbol]
) -> dict[sympy.Symbol, sympy.Expr]:
    """The variant's values in SI (radians for angles), exact, keyed by the problem's symbols."""
    values: dict[sympy.Symbol, sympy.Expr] = {}
    for name, value in variant.values.items():
        given = doc.given.get(name)
        if given is None or name not in table:
            continue
        values[table[name]] = _decimal_to_rational(value) * unit_scale(given.unit)
    return values


def evaluate_reference(
    expr: sympy.Expr, substitutions: Mapping[sympy.Symbol, sympy.Expr], units: str, *, where: str = ""
) -> Decimal:
    """`expr` at the SI values, expressed in `units`, to REFERENCE_SIGNIFICANT digits.

    Evaluated at REFERENCE_DIGITS so that the kept digits are exact; a symbol without a value,
    or a non-real or infinite result, is the problem author's fault (SpecError).
    """
    value = (expr.xreplace(dict(substitutions)) / unit_scale(units)).evalf(REFERENCE_DIGITS)
    missing = sorted(str(s) for s in value.free_symbols)
    if missing:
        raise SpecError(f"no given value for {', '.join(missing)}", (where, "of") if where else ())
    if not value.is_number or value.has(sympy.zoo, sympy.oo, -sympy.oo, sympy.nan) or not value.is_real:
        raise SpecError(
            f"the reference value is not a finite real number ({value})", (where,) if where else ()
        )
    with localcontext() as ctx:
        ctx.prec = REFERENCE_SIGNIFICANT
        return +Decimal(str(sympy.Float(value, REFERENCE_DIGITS)))


# ---- what a student sees ----------------------------------------------------------------------

_MATH = re.compile(r"(\$\$.*?\$\$|\$[^$]*\$)", re.DOTALL)
PLACEHOLDER = re.compile(r"\{([A-Za-z_][A-Za-z0-9_]*)\}")
_SUPERSCRIPTS = {"^-1": "⁻¹", "^-2": "⁻²", "^-3": "⁻³", "^2": "²", "^3": "³"}


def placeholders(statement: str) -> list[str]:
    """Names written as `{m}` outside `$...$` math (braces inside LaTeX are LaTeX's)."""
    names: list[str] = []
    for index, segment in enumerate(_MATH.split(statement)):
        if index % 2 == 0:
            names.extend(PLACEHOLDER.findall(segment))
    return names


def format_number(value: Decimal) -> str:
    """Plain decimal for everyday magnitudes, `a × 10^n` otherwise; trailing zeros are kept."""
    if value != 0 and not Decimal("1e-4") <= abs(value) < Decimal("1e7"):
        mantissa = value.scaleb(-value.adjusted())
        return f"{mantissa} × 10^{value.adjusted()}"
    return format(value, "f")


def format_quantity(value: Decimal, unit: str) -> str:
    """`2.5 kg`, `35°`, `0.031` (dimensionless), `9.81 m/s²`: text that is also read back (an API's
    value, a CSV's cell), so a negative one keeps the hyphen-minus a keyboard types."""
    return _with_unit(format_number(value), unit)


def shown_quantity(value: Decimal, unit: str) -> str:
    """`format_quantity` as a typeset page shows it, with a true minus: `−3.044 m/s²`."""
    return _with_unit(format_number(value).replace("-", "\u2212"), unit)


def _with_unit(number: str, unit: str) -> str:
    if unit in _DEGREE_SPELLINGS:
        return f"{number}°"
    if unit in {"1", ""}:
        return number
    pretty = unit
    for plain, superscript in _SUPERSCRIPTS.items():
        pretty = pretty.replace(plain, superscript)
    return f"{number} {pretty}"


def fill_statement(statement: str, doc: ProblemDocument, variant: Variant) -> str:
    """Replace `{name}` outside math by the student's value with its unit."""

    def fill(match: re.Match[str]) -> str:
        name = match.group(1)
        if name in variant.values and name in doc.given:
            return format_quantity(variant.values[name], doc.given[name].unit)
        return match.group(0)

    segments = _MATH.split(statement)
    return "".join(PLACEHOLDER.sub(fill, s) if i % 2 == 0 else s for i, s in enumerate(segments))
