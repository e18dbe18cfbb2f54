"""Grade a symbolic answer against a prepared reference, and say why a wrong one is wrong.

Deciding equivalence (the rule):
1. Sampling refutes: a domain point where both sides are defined and differ beyond the tolerance
   (physics.symbolic.compare) makes the answer wrong. Final; no symbolic step is started.
2. Sampling accepts: agreement at every sample point, confirmed at two points with twice the precision,
   makes the answer right. sympy's simplify is not consulted: it is incomplete on restricted domains
   (θ ∈ (0, π/2)), so its failure to reach 0 is no evidence against an answer.
3. Inconclusive: the answer agrees wherever it has a real value, but the real evaluator finds none at
   some point where the reference is defined, and nudging the point does not help (not a removable
   singularity). There sympy evaluates it in complex arithmetic: not real or different is wrong; real
   and equal (complex intermediates, e.g. (e^{iθ} + e^{-iθ})) counts as agreement. Only where even that
   gives no number does a bounded symbolic proof (physics.symbolic.proof) decide: proved or wrong.

Why a wrong answer is wrong, first match wins: known_mistake, wrong_dimension, sign_error,
constant_factor, wrong_value (with hints on limiting cases). Each is first looked for in float64 at every
point and confirmed in multiprecision at one or two points; wherever float64 cannot tell (a value out of
its range, a difference below its resolution, an undefined point) every point is evaluated in
multiprecision, so the reason is always the one multiprecision gives. Feedback never shows the reference, and
a constant factor is not named: with it the answer would give the reference away.
"""

from __future__ import annotations

import threading
import weakref
from collections import OrderedDict
from collections.abc import Callable

import numpy as np
import sympy
from mpmath import libmp

from physics.dimensions import Dimension, describe
from physics.errors import ParseError, UnknownSymbol
from physics.symbolic.compare import (
    PREC,
    PRECISE_TOLERANCE_BITS,
    TOLERANCE_BITS,
    agreement,
    close,
    constant_ratio,
    negated,
)
from physics.symbolic.dimensional import DimensionMismatch, UnknownDimension, expression_dimension
from physics.symbolic.floats import AGREE, DIFFER, Floats, agrees, differs, in_range
from physics.symbolic.limits import breaks_limit
from physics.symbolic.numeric import ONE, RND, Column, Evaluator, Mpf, complex_value
from physics.symbolic.proof import proves_equal
from physics.symbolic.reference import PreparedReference, exact_numbers, over_context, rename_symbols
from physics.verdict import Judgement, Reason

CORRECT = "Correct."
EQUIVALENT = Judgement(True, Reason.EQUIVALENT, CORRECT)
SIGN_FEEDBACK = "Check the sign of your answer."
FACTOR_FEEDBACK = (
    "Your answer is off by a constant factor: check the numerical factors (such as 2, π or a square root)."
)
WRONG_VALUE_FEEDBACK = "Your answer is not equivalent to the expected one."
UNDEFINED_FEEDBACK = "Your expression is not defined (or not real) for some allowed values of the symbols."
# The sample points where a float64 finding is confirmed in multiprecision (the precise points).
_CHECK_POINTS = (0, 1)
_NUDGE_BITS = 60
_NUDGE_TOLERANCE_BITS = 40


def _require_expression(answer: sympy.Basic) -> sympy.Expr:
    # Not `Boolean`: sympy's Symbol is a Boolean too, and a bare `m` is a fine answer.
    relation = (
        sympy.core.relational.Relational,
        sympy.logic.boolalg.BooleanFunction,
        sympy.logic.boolalg.BooleanAtom,
    )
    if not isinstance(answer, sympy.Expr) or isinstance(answer, relation):
        raise ParseError("the answer must be an expression, not an equation or a relation")
    return answer


def _normalize_answer(answer: sympy.Basic, reference: PreparedReference) -> sympy.Expr:
    answer = _require_expression(answer)
    if over_context(answer, reference.context):  # a parsed answer: nothing to rename or make exact
        return answer
    try:
        renamed = rename_symbols(exact_numbers(answer), reference.context)
    except KeyError as missing:
        name = str(missing.args[0])
        allowed = sorted(reference.context.by_name)
        raise UnknownSymbol(f"unknown symbol {name}", None, name, allowed) from None
    return renamed


def _nudged(reference: PreparedReference, index: int) -> dict[sympy.Symbol, Column]:
    """The sample point moved by a relative 2^-60, to step off an isolated singular point."""
    return {
        s: [libmp.mpf_add(v, libmp.mpf_shift(v, -_NUDGE_BITS), PREC, RND)]
        for s in reference.sample.symbols
        for v in (reference.sample.columns[s][index],)
    }


def _removable(answer: sympy.Expr, reference: PreparedReference, indexes: tuple[int, ...]) -> bool:
    """True when at each point the answer is undefined, it is defined right next to it and agrees."""
    for index in indexes:
        columns = _nudged(reference, index)
        mine = Evaluator(columns, 1, PREC)(answer)[0]
        theirs = Evaluator(columns, 1, PREC)(reference.expected)[0]
        if mine is None or theirs is None or not close(mine, theirs, reference.scale, _NUDGE_TOLERANCE_BITS):
            return False
    return True


def _precisely_equal(answer: sympy.Expr, reference: PreparedReference) -> bool:
    """Agreement at twice the precision wherever the answer has a real value among the check points."""
    values = reference.precise_evaluator()(answer)
    return all(
        a is None or (b is not None and close(a, b, reference.scale, PRECISE_TOLERANCE_BITS))
        for a, b in zip(values, reference.precise_values, strict=True)
    )


def _confirmed(answer: sympy.Expr, reference: PreparedReference) -> bool:
    """Defined and equal at twice the precision at every one of the check points (no point skipped)."""
    values = reference.precise_evaluator()(answer)
    return len(values) > 0 and all(
        a is not None and b is not None and close(a, b, reference.scale, PRECISE_TOLERANCE_BITS)
        for a, b in zip(values, reference.precise_values, strict=True)
    )


def _complex_agrees(
    answer: sympy.Expr, reference: PreparedReference, indexes: tuple[int, ...]
) -> bool | None:
    """Where the real evaluator found no value: True if the answer is real there and equal to the reference
    (it went through complex intermediates), False if it is not real or differs, None if it cannot tell."""
    zero = libmp.fzero
    for index in indexes:
        found = complex_value(answer, reference.sample.point(index), PREC)
        expected = reference.values[index]
        if found is None or expected is None:
            return None
        real, imaginary = found
        if not close(imaginary, zero, reference.scale, TOLERANCE_BITS) or not close(
            real, expected, reference.scale, TOLERANCE_BITS
        ):
            return False
    return True


def _equivalent(answer: sympy.Expr, values: Column, reference: PreparedReference) -> bool:
    """The rule in the module docstring."""
    found = agreement(values, reference.values, reference.scale)
    if found.differs:
        return False
    if found.answer_missing and not _removable(answer, reference, found.answer_missing):
        complex_check = _complex_agrees(answer, reference, found.answer_missing)
        if complex_check is None:
            return proves_equal(answer, reference.expected)
        if not complex_check:
            return False
    return _precisely_equal(answer, reference)


def _dimension_problem(answer: sympy.Expr, reference: PreparedReference) -> str | None:
    if answer == 0:
        return None  # zero is a value of every dimension
    try:
        found = expression_dimension(answer, reference.dims)
    except UnknownDimension:
        return None
    except DimensionMismatch as error:
        return f"Your expression {error.message}."
    return dimension_difference(found, reference)


def dimension_difference(found: Dimension, reference: PreparedReference) -> str | None:
    """What to say of an answer of a consistent dimension `found`: None when it is the one expected."""
    expected = reference.dimension
    if expected is None or found == expected:
        return None
    return f"Your expression has the dimension of {describe(found)}; {describe(expected)} is expected."


def _limit_hints(answer: sympy.Expr, reference: PreparedReference) -> list[str]:
    """One sentence naming every limiting case the answer fails, or none (a sentence each read as
    separate faults, repeating the same advice)."""
    failed = [
        limit.description.rstrip(".")
        for limit in reference.limits
        if breaks_limit(answer, limit, reference.scale)
    ]
    if not failed:
        return []
    if len(failed) == 1:
        return [f"Your answer fails a limiting case, {failed[0]}: check it there."]
    return [f"Your answer fails {len(failed)} limiting cases; check it in each: {'; '.join(failed)}."]


def diagnose(answer: sympy.Expr, values: Column, reference: PreparedReference, undefined: bool) -> Judgement:
    """Why an answer that is not equivalent is wrong (order in the module docstring)."""
    # A known mistake first: its author's feedback is more specific than any general reason, even
    # when the mistake has another dimension (a frequency given for a period).
    for mistake in reference.mistakes:
        if agreement(values, mistake.values, reference.scale).agrees:
            return Judgement(False, Reason.KNOWN_MISTAKE, mistake.feedback)
    dimension = _dimension_problem(answer, reference)
    if dimension is not None:
        return Judgement(False, Reason.WRONG_DIMENSION, dimension)
    if agreement(values, negated(reference.values), reference.scale).agrees:
        return Judgement(False, Reason.SIGN_ERROR, SIGN_FEEDBACK)
    # Between two plain numbers every ratio is constant: the reason would say nothing.
    ratio = constant_ratio(values, reference.values, reference.scale) if reference.has_symbols else None
    if ratio is not None and not close(libmp.mpf_abs(ratio), ONE, ONE, 40) and ratio != libmp.fzero:
        return Judgement(False, Reason.CONSTANT_FACTOR, FACTOR_FEEDBACK)
    sentences = [WRONG_VALUE_FEEDBACK]
    if undefined:
        sentences.append(UNDEFINED_FEEDBACK)
    sentences.extend(_limit_hints(answer, reference))
    return Judgement(False, Reason.WRONG_VALUE, " ".join(sentences))


# The answer in multiprecision (PREC) at the given sample points.
AnswerAt = Callable[[tuple[int, ...]], Column]


class _AtPoints:
    """The answer in multiprecision (PREC) at sample points, each point evaluated once per judgement:
    the refutation, the sign check and the factor check look at overlapping points (the first suspect
    is often point 0, a check point). The evaluator computes point by point, so a point's value is the
    same whichever points it is evaluated with: the one each check would compute on its own."""

    def __init__(self, answer: sympy.Expr, reference: PreparedReference) -> None:
        self._answer = answer
        self._reference = reference
        self._values: dict[int, Mpf | None] = {}

    def __call__(self, indexes: tuple[int, ...]) -> Column:
        values = self._values
        missing = tuple(index for index in dict.fromkeys(indexes) if index not in values)
        if missing:
            found = self._reference.point_evaluator(missing)(self._answer)
            values.update(zip(missing, found, strict=True))
        return [values[index] for index in indexes]


def _refuted_at(answer_at: AnswerAt, reference: PreparedReference, index: int) -> bool:
    """The answer, in multiprecision at one sample point, is defined there and differs (rule 1)."""
    (value,) = answer_at((index,))
    (expected,) = reference.values_at((index,))
    return (
        value is not None
        and expected is not None
        and not close(value, expected, reference.scale, TOLERANCE_BITS)
    )


def _first_look(
    values: Floats | None, reference: PreparedReference, answer_at: AnswerAt, confirmed: Callable[[], bool]
) -> tuple[bool | None, Floats | None]:
    """The rule decided from the answer's float64 `values` at every point and multiprecision at a few:
    True (equal, when `confirmed` at the precise points), False (refuted), None (float64 cannot tell:
    the full multiprecision path decides); with the values when they are usable."""
    floats = reference.floats
    if not floats.usable or values is None or not in_range(values):
        return None, None
    if agrees(values, floats.values, floats.scale):
        # Equal to 1e-9 everywhere; the precise points catch what float64 cannot see (30 digits of pi).
        return (True if confirmed() else None), values
    suspects = np.flatnonzero(differs(values, floats.values, floats.scale))
    if suspects.size and _refuted_at(answer_at, reference, int(suspects[0])):
        return False, values
    return None, values


def judged_in_floats(
    values: Floats | None,
    reference: PreparedReference,
    answer_at: AnswerAt,
    confirmed: Callable[[], bool],
    dimension_problem: Callable[[], str | None],
    limit_hints: Callable[[], list[str]],
) -> Judgement | None:
    """The judgement decided from the answer's values alone, as `_judge` first tries: float64 at every
    point (`values`), multiprecision where a finding needs confirming (`answer_at`, `confirmed`), and
    what its dimension and the limiting cases say; None wherever that cannot tell. quick.py gives it the
    values of the parse tree, `_judge` those of sympy's."""
    decided, floats = _first_look(values, reference, answer_at, confirmed)
    if decided is True:
        return EQUIVALENT
    if decided is False and floats is not None:
        return _diagnose_in_floats(floats, reference, answer_at, dimension_problem, limit_hints)
    return None


def _expression_at(reference: PreparedReference, target: sympy.Expr) -> AnswerAt:
    """A reference-side expression (a known mistake) in multiprecision at sample points."""
    return lambda indexes: reference.point_evaluator(indexes, (target,))(target)


def _negation_at(reference: PreparedReference) -> AnswerAt:
    """The reference's negation in multiprecision at sample points: for a reference read from its parse
    tree, its values there negated (exactly), so sympy need not build it to look for a sign error."""
    if reference.source is None:
        return _expression_at(reference, -reference.expected)
    return lambda indexes: [None if v is None else libmp.mpf_neg(v) for v in reference.values_at(indexes)]


def _same_as(
    answer_at: AnswerAt,
    values: Floats,
    target_at: AnswerAt,
    targets: Floats | None,
    reference: PreparedReference,
) -> bool | None:
    """Would multiprecision find the answer equal to a reference-side target (`target_at` its values at
    sample points, `targets` in float64) at every sample point? Decided from float64 and confirmed in
    multiprecision: equal at the check points, or different at a point where float64 sees a clear
    difference; None when float64 cannot tell."""
    if targets is None:
        return None
    scale = reference.floats.scale
    if agrees(values, targets, scale):
        mine, theirs = answer_at(_CHECK_POINTS), target_at(_CHECK_POINTS)
        same = all(
            a is not None and b is not None and close(a, b, reference.scale, TOLERANCE_BITS)
            for a, b in zip(mine, theirs, strict=True)
        )
        return True if same else None
    suspects = np.flatnonzero(differs(values, targets, scale))
    if suspects.size:
        index = (int(suspects[0]),)
        (a,), (b,) = answer_at(index), target_at(index)
        if a is not None and b is not None and not close(a, b, reference.scale, TOLERANCE_BITS):
            return False
    return None


def _constant_factor(answer_at: AnswerAt, values: Floats, reference: PreparedReference) -> bool | None:
    """Is the answer a constant multiple (not ±1, not 0) of the reference, as constant_ratio would find
    in multiprecision? From float64 ratios, confirmed at two points; None when float64 cannot tell."""
    floats = reference.floats
    tiny = floats.scale * 2.0**-40
    if (np.abs(floats.values) <= tiny).any():
        return None  # a point where constant_ratio skips or refuses: left to multiprecision
    with np.errstate(all="ignore"):
        ratios = values / floats.values
    if not np.isfinite(ratios).all():
        return None
    spread = np.abs(ratios - ratios[0])
    far = int(np.argmax(spread))
    if spread[far] <= AGREE * abs(ratios[0]):
        indexes = _CHECK_POINTS
    elif spread[far] > DIFFER * (abs(ratios[0]) + abs(ratios[far])):
        indexes = (0, far)
    else:
        return None
    mine = answer_at(indexes)
    theirs = reference.values_at(indexes)
    if any(v is None for v in (*mine, *theirs)):
        return None
    first, second = (
        libmp.mpf_div(a, b, PREC, RND)
        for a, b in zip(mine, theirs, strict=True)
        if a is not None and b is not None
    )
    constant = close(first, second, libmp.fzero, TOLERANCE_BITS)
    if indexes is _CHECK_POINTS:
        if not constant:
            return None
        return not close(libmp.mpf_abs(first), ONE, ONE, 40) and first != libmp.fzero
    return False if not constant else None


def _diagnose_in_floats(
    values: Floats,
    reference: PreparedReference,
    answer_at: AnswerAt,
    dimension_problem: Callable[[], str | None],
    limit_hints: Callable[[], list[str]],
) -> Judgement | None:
    """`diagnose` decided from float64 values with multiprecision confirmations (same order, same
    answers); None wherever float64 cannot tell, and the multiprecision diagnosis decides."""
    if not np.isfinite(values).all():
        return None  # undefined somewhere: the full path says so in the feedback
    for (expr, feedback), targets in zip(reference.mistake_exprs, reference.float_mistakes, strict=True):
        same = _same_as(answer_at, values, _expression_at(reference, expr), targets, reference)
        if same is None:
            return None
        if same:
            return Judgement(False, Reason.KNOWN_MISTAKE, feedback)
    dimension = dimension_problem()
    if dimension is not None:
        return Judgement(False, Reason.WRONG_DIMENSION, dimension)
    floats = reference.floats
    same = _same_as(answer_at, values, _negation_at(reference), -floats.values, reference)
    if same is None:
        return None
    if same:
        return Judgement(False, Reason.SIGN_ERROR, SIGN_FEEDBACK)
    if reference.has_symbols:
        factor = _constant_factor(answer_at, values, reference)
        if factor is None:
            return None
        if factor:
            return Judgement(False, Reason.CONSTANT_FACTOR, FACTOR_FEEDBACK)
    return Judgement(False, Reason.WRONG_VALUE, " ".join([WRONG_VALUE_FEEDBACK, *limit_hints()]))


class Remembered:
    """Judgements by (reference, answer expression), the least recently used forgotten first.

    Many texts read as one expression (`m g sin θ`, `mg*sin(theta)`), and the judge is a pure function of
    the expression and the reference; only answers over_context are kept, whose equality as sympy trees
    is equality of everything the judge reads. One bound for the whole process (an answer's tree is up
    to ~40 KB); a reference is held weakly, so one that is dropped is never matched by a new one at
    its address.
    """

    def __init__(self, size: int) -> None:
        self._size = size
        self._kept: OrderedDict[tuple[int, sympy.Expr], tuple[weakref.ref[PreparedReference], Judgement]] = (
            OrderedDict()
        )
        self._lock = threading.Lock()

    def get(self, reference: PreparedReference, answer: sympy.Expr) -> Judgement | None:
        key = (id(reference), answer)
        with self._lock:
            found = self._kept.get(key)
            if found is None or found[0]() is not reference:
                return None
            self._kept.move_to_end(key)
            return found[1]

    def put(self, reference: PreparedReference, answer: sympy.Expr, judgement: Judgement) -> None:
        key = (id(reference), answer)
        with self._lock:
            self._kept[key] = (weakref.ref(reference), judgement)
            self._kept.move_to_end(key)
            while len(self._kept) > self._size:
                self._kept.popitem(last=False)

    def __len__(self) -> int:
        return len(self._kept)

    def clear(self) -> None:
        with self._lock:
            self._kept.clear()


REMEMBERED = Remembered(1024)


def judge_symbolic(answer: sympy.Expr, reference: PreparedReference) -> Judgement:
    """Correct when the answer equals the reference on the whole domain; else the first reason found.

    Raises UnknownSymbol (an AnswerError) for a name the context does not declare.
    """
    expr = _require_expression(answer)
    if not over_context(expr, reference.context):
        return _judge(_normalize_answer(expr, reference), reference)
    # A parsed answer: judged once per expression and reference (the judge is deterministic).
    known = REMEMBERED.get(reference, expr)
    if known is None:
        known = _judge(expr, reference)
        REMEMBERED.put(reference, expr, known)
    return known


def _judge(expr: sympy.Expr, reference: PreparedReference) -> Judgement:
    """judge_symbolic of an answer already over the context's symbols, with exact numbers."""
    if expr == reference.expected:
        return EQUIVALENT
    quick = judged_in_floats(
        reference.float_evaluator()(expr) if reference.floats.usable else None,
        reference,
        _AtPoints(expr, reference),
        lambda: _confirmed(expr, reference),
        lambda: _dimension_problem(expr, reference),
        lambda: _limit_hints(expr, reference),
    )
    if quick is not None:
        return quick
    # Where float64 refuted the answer, the point it refuted at differs here too: not equivalent.
    values = Evaluator(reference.sample.columns, reference.sample.size, PREC)(expr)
    if _equivalent(expr, values, reference):
        return EQUIVALENT
    # The reference is defined at every sample point, so a missing value is the answer's own gap.
    return diagnose(expr, values, reference, undefined=any(v is None for v in values))
