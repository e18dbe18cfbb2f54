"""Errors of the physics core, each carrying fields rather than a bare string.

    PhyscheckError
     ├── AnswerError        an answer could not be read: an `invalid` verdict, no attempt used
     │    ├── ParseError          reason parse_error
     │    ├── AmbiguousInput      reason ambiguous (carries both readings)
     │    │    └── AmbiguousGrouping   `e^-ωt`, `sin θ/2`: the expected dimension may settle it
     │    │         └── AmbiguousDivision   `p^2/2m`, `a/b c`: never settled (API.md)
     │    ├── UnknownSymbol       reason unknown_symbol (carries the allowed names)
     │    ├── UnknownFunction     reason unknown_function (carries the allowed functions)
     │    ├── TooLarge            reason too_large (a size limit checked before evaluation)
     │    ├── CheckTimeout        reason timeout (the worker ran out of time)
     │    ├── MissingUnits        reason missing_units
     │    ├── UnexpectedUnits     reason unexpected_units
     │    ├── UnknownUnit         reason unknown_unit
     │    └── SigfigsError        reason sigfigs (not a literal with the asked significant figures)
     ├── SpecError          the reference side (expected, symbols, units, a problem file) is unusable;
     │                      the author's fault, reported as 422 with a path
     │    └── SpecErrors      several SpecErrors of one document, all at once (`.errors`)
     └── DerivationError    the engine could not derive an answer, or its methods disagree

The web layer maps these to HTTP in one place (`app/errors.py`); AnswerError never becomes an HTTP
error, it becomes an `invalid` verdict.
"""

from __future__ import annotations

from collections.abc import Sequence

from physics.wording import counted


class PhyscheckError(Exception):
    """Base of every error the physics core raises on purpose."""


class AnswerError(PhyscheckError):
    """An answer that could not be read; `position` is a 0-based character offset into the text."""

    reason: str = "parse_error"

    def __init__(self, message: str, position: int | None = None) -> None:
        super().__init__(message)
        self.message = message
        self.position = position


class ParseError(AnswerError):
    reason = "parse_error"


class LikelySlip(ParseError):
    """Text a student types for something other than what it literally says (`3.0 x 10-3` for ×10⁻³,
    `30^0` for 30°), refused asking which was meant: the refusal stands whatever another reader (the
    arithmetic of a numeric answer) could make of the text."""


class AmbiguousInput(AnswerError):
    reason = "ambiguous"

    def __init__(self, message: str, position: int | None, readings: Sequence[str]) -> None:
        super().__init__(message, position)
        self.readings = tuple(readings)


class AmbiguousGrouping(AmbiguousInput):
    """One operator that groups two ways where physics usually means one: `e^-ωt`, e^(−ω)·t or
    e^(−ωt); `sin θ/2`, sin(θ)/2 or sin(θ/2). `position` is the operator's (the `^`, the function), by
    which a reader may settle it by dimension. `readings` holds one reading per choice."""


class AmbiguousDivision(AmbiguousGrouping):
    """A `/` followed by an unparenthesised juxtaposed product: `p^2/2m`, (p²/2)·m or p²/(2m). The
    contract (API.md) refuses it whatever the dimensions: a reader may try its readings to settle another
    grouping (`e^-t/τ cos ωt`), never to take one. A divisor followed by several factors has a reading for
    each place it may end (`a/b c d`: (a/b)·c·d, a/(b·c·d), a/(b·c)·d); `partial`: too many to list, so
    not all are there, and none is tried."""

    def __init__(self, message: str, position: int | None, readings: Sequence[str], *, partial: bool) -> None:
        super().__init__(message, position, readings)
        self.partial = partial


class UnknownSymbol(AnswerError):
    reason = "unknown_symbol"

    def __init__(self, message: str, position: int | None, symbol: str, allowed: Sequence[str]) -> None:
        super().__init__(message, position)
        self.symbol = symbol
        self.allowed = tuple(allowed)


class UnknownFunction(AnswerError):
    reason = "unknown_function"

    def __init__(self, message: str, position: int | None, function: str, allowed: Sequence[str]) -> None:
        super().__init__(message, position)
        self.function = function
        self.allowed = tuple(allowed)


class TooLarge(AnswerError):
    reason = "too_large"


class CheckTimeout(AnswerError):
    reason = "timeout"


class MissingUnits(AnswerError):
    reason = "missing_units"


class UnexpectedUnits(AnswerError):
    reason = "unexpected_units"


class UnknownUnit(AnswerError):
    reason = "unknown_unit"

    def __init__(self, message: str, position: int | None, unit: str) -> None:
        super().__init__(message, position)
        self.unit = unit


class SigfigsError(AnswerError):
    reason = "sigfigs"


class SpecError(PhyscheckError):
    """A reference, symbol table, unit or problem file that cannot be used.

    `path` locates the fault in the author's document, e.g. ("symbols", "theta", "range").
    """

    def __init__(self, message: str, path: Sequence[str | int] = ()) -> None:
        super().__init__(message)
        self.message = message
        self.path = tuple(path)

    @classmethod
    def unreadable(cls, error: AnswerError, path: Sequence[str | int], text: str | None = None) -> SpecError:
        """The one place where an author's text that does not read (a parse error) becomes a SpecError:
        the parser's message, where it stopped, and the text itself when it is not shown elsewhere."""
        where = f" at character {error.position}" if error.position is not None else ""
        if text is None:
            return cls(f"{error.message}{where}", path)
        return cls(f"cannot read {text!r}{where}: {error.message}", path)

    def at(self, path: Sequence[str | int]) -> SpecError:
        """The same fault, located at `path` in the author's document."""
        return SpecError(self.message, path)


class DerivationError(PhyscheckError):
    """The engine failed to derive a quantity, or two methods gave different answers.

    `path` locates the fault inside the model section (("constraints", "contact"), ("quantities",
    "tension")); `findings` lists several faults found at once, each (path, message).
    """

    def __init__(
        self,
        message: str,
        problem: str | None = None,
        quantity: str | None = None,
        path: Sequence[str | int] | None = None,
        findings: Sequence[tuple[tuple[str | int, ...], str]] = (),
    ) -> None:
        super().__init__(message)
        self.message = message
        self.problem = problem
        self.quantity = quantity
        self.path = tuple(path) if path is not None else (("quantities", quantity) if quantity else ())
        self.findings = tuple(findings)

    def items(self) -> list[tuple[tuple[str | int, ...], str]]:
        """(path inside the model, message) for every fault found."""
        return list(self.findings) or [(self.path, self.message)]


class SpecErrors(SpecError):
    """Several SpecErrors found in one document, reported together (each keeps its own path)."""

    def __init__(self, errors: Sequence[SpecError]) -> None:
        self.errors = tuple(errors)
        lines = [f"{'/'.join(str(p) for p in e.path) or '(document)'}: {e.message}" for e in self.errors]
        first_path = self.errors[0].path if self.errors else ()
        super().__init__(f"{counted(len(self.errors), 'error')}:\n" + "\n".join(lines), first_path)
