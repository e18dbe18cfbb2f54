"""What a numeric answer is checked against: the exact reference value, its units and the tolerance."""

from __future__ import annotations

from dataclasses import dataclass
from decimal import Decimal
from fractions import Fraction

from physics.errors import AnswerError, SpecError
from physics.numeric.decimals import as_decimal
from physics.numeric.tolerance import DEFAULT_TOLERANCE, Tolerance
from physics.units import ParsedUnits, parse_units
from physics.verdict import Preview, Verdict

UNITS_SYSTEMS = (None, "SI")
# "strict": a hertz counts cycles (1 Hz = 2π rad/s), so Hz for an angular frequency is the 2π mistake;
# absent, Hz and rad/s are both s⁻¹ (the radian a pure number) and either is graded, with a remark.
ANGULAR_UNITS = (None, "strict")


@dataclass(frozen=True)
class MistakenValue:
    """The value a known mistake gives for this student (in the spec's units), and what to tell them."""

    value: Decimal
    feedback: str


@dataclass(frozen=True)
class NumericSpec:
    expected: Decimal  # exact decimal of the reference value, in `units`
    units: str | None = None  # None: the answer is a pure number
    units_required: bool = True
    tolerance: Tolerance = DEFAULT_TOLERANCE
    arithmetic: bool = True  # the number may be an expression (`229/50`); False: a plain decimal
    units_system: str | None = None  # "SI": answers must use SI units (or those accepted with them)
    angular_units: str | None = None  # "strict": Hz is 2π rad/s where the other side has an angle unit
    # A wrong answer within the tolerance of one of these is that mistake (the first listed wins).
    mistakes: tuple[MistakenValue, ...] = ()

    def __post_init__(self) -> None:
        # frozen: normalising what the author passed (a JSON float 4.5807 means the decimal 4.5807)
        object.__setattr__(self, "expected", as_decimal(self.expected, ("expected",)))
        if self.units is not None and not isinstance(self.units, str):
            raise SpecError(f"units must be text, not {self.units!r}", ("units",))
        if self.units_system not in UNITS_SYSTEMS:
            raise SpecError(
                f'units_system must be "SI" or absent, not {self.units_system!r}', ("units_system",)
            )
        if self.angular_units not in ANGULAR_UNITS:
            raise SpecError(
                f'angular_units must be "strict" or absent, not {self.angular_units!r}', ("angular_units",)
            )
        target = (
            self.target_units()
        )  # refuse unusable units when the spec is made, not when a student answers
        if self.units_system == "SI" and target is not None:
            foreign = [atom.symbol for atom, _ in target.factors if not atom.si]
            if foreign:
                raise SpecError(f"units {self.units!r} are not SI, but units_system is SI", ("units",))

    def grade(self, answer: str, limits: object = None) -> Verdict:
        """The verdict on `answer` (physics.checking.Question; a numeric answer has its own limits)."""
        from physics.numeric.check import check_numeric  # check.py imports this module

        return check_numeric(answer, self)

    def read(self, answer: str, limits: object = None) -> Preview:
        """How `answer` reads: the numeric check is cheap, so reading is grading without the verdict."""
        verdict = self.grade(answer)
        return Preview(verdict.read_as, verdict.error)

    @property
    def expected_value(self) -> Fraction:
        return Fraction(self.expected)

    def target_units(self) -> ParsedUnits | None:
        """The parsed `units`, or None when the answer is a pure number (`units` None or `1`)."""
        if self.units is None:
            return None
        try:
            parsed = parse_units(self.units)
        except AnswerError as error:
            raise SpecError.unreadable(error, ("units",), self.units) from error
        return None if parsed.is_dimensionless_number else parsed
