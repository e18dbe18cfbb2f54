"""Bank self-test: does each problem grade its own reference answers the way a student's would be?

For every symbolic part, equivalent rewritings of the reference (expanded, factored, trig-rewritten,
`together`, `cancel`), written as a student would type them (physics.answer_text) and read back by the
student parser, must be ACCEPTED (a form no student could type, such as `Piecewise`, is judged as a
tree), and every known mistake REJECTED with its feedback. For every numeric part, across many
students' variants, the reference value (also in other unit prefixes) must be accepted and a value
10 % off rejected. The engine's methods must agree. Nothing stops at the first failure.
"""

from __future__ import annotations

import sys
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field
from decimal import ROUND_HALF_UP, Decimal
from pathlib import Path

import sympy

from physics.answer_text import student_text
from physics.checking import SymbolicQuestion, check_answer
from physics.errors import DerivationError, PhyscheckError
from physics.symbolic import judge_symbolic
from physics.verdict import Outcome, Reason, Verdict
from problems.compiled import CompiledNumericPart, CompiledProblem, CompiledSymbolicPart, compile_problem
from problems.errors import ProblemInvalid
from problems.loader import load_bank
from problems.modelinfo import MIN_AGREEING_METHODS
from problems.schema import ProblemDocument, format_path
from problems.variants import Variant, draw_variant, format_number, round_sigfigs, si_values, unit_scale

# Not a credential: self-test variants only need to be reproducible.
SELFTEST_SECRET = "physcheck-bank-selftest"  # noqa: S105
DEFAULT_VARIANTS = 20
OFF_BY = Decimal("1.10")  # a value this far off must be rejected

# (label, done, total): one call per finished part within a problem, or per problem within the bank.
Progress = Callable[[str, int, int], None]

# Other spellings of common units whose conversion factors are not powers of ten as well as those that are.
_UNIT_ALTERNATIVES: dict[str, tuple[str, ...]] = {
    "m/s": ("km/h", "cm/s"),
    "m/s^2": ("cm/s^2", "mm/s^2"),
    "s": ("ms", "min"),
    "rad/s": ("rad/ms", "rev/min"),
    "N": ("kN", "mN"),
    "J": ("kJ", "mJ"),
    "kg": ("g",),
    "m": ("cm", "mm"),
    "Hz": ("kHz",),
}


@dataclass(frozen=True)
class CheckResult:
    problem: str
    part: str | None
    check: str  # e.g. "rewrite factor", "mistake 1", "variant 7 in km/h", "methods agree"
    ok: bool
    detail: str = ""


@dataclass
class ProblemReport:
    problem: str
    results: list[CheckResult] = field(default_factory=list)
    not_derived: tuple[str, ...] = ()  # parts graded against a typed answer only

    @property
    def ok(self) -> bool:
        return all(r.ok for r in self.results)

    @property
    def failures(self) -> list[CheckResult]:
        return [r for r in self.results if not r.ok]


@dataclass
class Report:
    problems: list[ProblemReport] = field(default_factory=list)

    @property
    def ok(self) -> bool:
        return all(p.ok for p in self.problems)

    @property
    def failures(self) -> list[CheckResult]:
        return [r for p in self.problems for r in p.failures]

    def summary(self) -> str:
        """One line per problem, then one line per failed check."""
        lines = []
        for p in self.problems:
            passed = sum(r.ok for r in p.results)
            mark = "ok  " if p.ok else "FAIL"
            typed = f"; not derived (typed answer only): {', '.join(p.not_derived)}" if p.not_derived else ""
            lines.append(f"{mark} {p.problem}: {passed}/{len(p.results)} checks passed{typed}")
        for r in self.failures:
            where = f"{r.problem}/{r.part}" if r.part else r.problem
            lines.append(f"  {where}: {r.check}: {r.detail}")
        total = sum(len(p.results) for p in self.problems)
        lines.append(f"{len(self.problems)} problem(s), {total} checks, {len(self.failures)} failure(s)")
        return "\n".join(lines)


def verify_problem(
    doc: ProblemDocument,
    variants: int = DEFAULT_VARIANTS,
    progress: Progress | None = None,
    *,
    version: int = 0,
    secret: str = SELFTEST_SECRET,
    use_model: bool = True,
) -> Report:
    """Self-test one problem; a compile failure is reported as failed checks, not raised."""
    report = ProblemReport(doc.id)
    try:
        compiled = compile_problem(doc, version, use_model=use_model)
    except ProblemInvalid as error:
        report.results.extend(
            CheckResult(doc.id, None, f"compile {path}", False, msg) for path, msg in error.errors
        )
        return Report([report])
    except DerivationError as error:  # every finding, each at its place in the model
        report.results.extend(
            CheckResult(doc.id, None, f"derive {format_path(('model', *path))}", False, message)
            for path, message in error.items()
        )
        return Report([report])
    except PhyscheckError as error:
        report.results.append(CheckResult(doc.id, None, "derive", False, str(error)))
        return Report([report])
    except Exception as error:  # a fault in the engine must not hide the other problems' results
        report.results.append(CheckResult(doc.id, None, "derive", False, f"{type(error).__name__}: {error}"))
        return Report([report])

    report.not_derived = compiled.not_derived
    if compiled.derived is not None:
        report.results.extend(_agreement_checks(doc.id, compiled))
    total = len(compiled.parts)
    students = [draw_variant(doc, version, f"selftest-{i}", secret) for i in range(variants)]
    report.results.extend(_domain_checks(doc.id, compiled, students))
    for done, (part_id, part) in enumerate(compiled.parts.items(), start=1):
        try:
            if isinstance(part, CompiledSymbolicPart):
                report.results.extend(_symbolic_checks(doc.id, part))
            else:
                report.results.extend(_numeric_checks(doc.id, compiled, part, students))
        except PhyscheckError as error:
            report.results.append(CheckResult(doc.id, part_id, "prepare", False, str(error)))
        except Exception as error:  # a grader fault on one part must not stop the rest
            report.results.append(
                CheckResult(doc.id, part_id, "grader fault", False, f"{type(error).__name__}: {error}")
            )
        if progress is not None:
            progress(f"{doc.id}:{part_id}", done, total)
    return Report([report])


def verify_bank(
    documents: Iterable[ProblemDocument] | None = None,
    variants: int = DEFAULT_VARIANTS,
    progress: Progress | None = None,
    *,
    bank_dir: Path | None = None,
    secret: str = SELFTEST_SECRET,
    use_model: bool = True,
) -> Report:
    """Self-test every problem (default: the built-in bank); a bank that does not load is one failure."""
    if documents is None:
        try:
            documents = load_bank(bank_dir)
        except ProblemInvalid as error:
            return Report(
                [
                    ProblemReport(
                        "bank", [CheckResult("bank", None, f"load {p}", False, m) for p, m in error.errors]
                    )
                ]
            )
    docs = list(documents)
    report = Report()
    for done, doc in enumerate(docs, start=1):
        report.problems.extend(verify_problem(doc, variants, secret=secret, use_model=use_model).problems)
        if progress is not None:
            progress(doc.id, done, len(docs))
    return report


def _agreement_checks(problem: str, compiled: CompiledProblem) -> list[CheckResult]:
    """Each derived quantity a part asks for was found by at least two methods that agree."""
    assert compiled.derived is not None
    results = []
    for part in compiled.parts.values():
        if not isinstance(part, CompiledSymbolicPart) or part.quantity not in compiled.derived.quantities:
            continue
        methods = compiled.derived.agreement.get(part.quantity, ())
        proof = compiled.derived.proofs.get(part.quantity, "")
        ok = len(methods) >= MIN_AGREEING_METHODS
        detail = proof if ok else f"derived by {', '.join(methods) or 'no method'} only"
        results.append(CheckResult(problem, part.id, "methods agree", ok, detail))
    return results


def _domain_checks(problem: str, compiled: CompiledProblem, students: list[Variant]) -> list[CheckResult]:
    """Every student's given values satisfy the problem's constraints (the skier does slide)."""
    results = []
    for index, variant in enumerate(students):
        values = si_values(compiled.document, variant, compiled.table)
        broken = []
        for relation in compiled.constraints:
            at = relation.xreplace(values)
            if not at.free_symbols and at is not sympy.true:
                broken.append(f"{sympy.sstr(relation)} fails at {_shown(variant)}")
        if compiled.constraints:
            results.append(
                CheckResult(problem, None, f"variant {index} in domain", not broken, "; ".join(broken))
            )
    return results


def _shown(variant: Variant) -> str:
    return ", ".join(f"{name} = {value}" for name, value in variant.values.items())


# ---- symbolic parts ---------------------------------------------------------------------------


def equivalent_forms(expr: sympy.Expr) -> dict[str, sympy.Expr]:
    """Equivalent forms of `expr` (label -> form), without repeats."""
    forms: dict[str, sympy.Expr] = {"as derived": expr}
    transforms: dict[str, Callable[[sympy.Expr], sympy.Expr]] = {
        "expand": sympy.expand,
        "factor": sympy.factor,
        "trigsimp": sympy.trigsimp,
        "fu": sympy.fu,
        "together": sympy.together,
        "cancel": sympy.cancel,
        "expand_trig": sympy.expand_trig,
    }
    for label, transform in transforms.items():
        try:
            form = transform(expr)
        except (TypeError, ValueError, NotImplementedError, sympy.PolynomialError):
            continue
        if all(form != other for other in forms.values()):
            forms[label] = form
    return forms


def rewritings(expr: sympy.Expr) -> dict[str, str]:
    """The equivalent forms a student could type, as text the student parser reads (label -> text)."""
    texts: dict[str, str] = {}
    for label, form in equivalent_forms(expr).items():
        text = student_text(form)
        if text is not None and text not in texts.values():
            texts[label] = text
    return texts


def _grade(form: sympy.Expr, question: SymbolicQuestion) -> tuple[str, Verdict]:
    """Grade a form as a student's typed text when one could type it (sympy prints forms such as
    `Piecewise` or `Min` that no student can), else as the tree itself."""
    text = student_text(form)
    if text is not None:
        return text, check_answer(text, question)
    return sympy.sstr(form), Verdict.graded(judge_symbolic(form, question.reference), None)


def _symbolic_checks(problem: str, part: CompiledSymbolicPart) -> list[CheckResult]:
    results: list[CheckResult] = []
    question = part.question
    for label, form in equivalent_forms(part.expected).items():
        text, verdict = _grade(form, question)
        ok = verdict.outcome is Outcome.CORRECT
        results.append(
            CheckResult(problem, part.id, f"rewrite {label}", ok, "" if ok else _explain(text, verdict))
        )
    for index, mistake in enumerate(part.context.mistakes, start=1):
        text, verdict = _grade(mistake.expr, question)
        ok = (
            verdict.outcome is Outcome.INCORRECT
            and verdict.reason is Reason.KNOWN_MISTAKE
            and mistake.feedback in verdict.feedback
        )
        results.append(
            CheckResult(problem, part.id, f"mistake {index}", ok, "" if ok else _explain(text, verdict))
        )
    return results


def _explain(text: str, verdict: Verdict) -> str:
    return f"{text!r} was {verdict.outcome.value} ({verdict.reason.value}): {verdict.feedback}"


# ---- numeric parts ----------------------------------------------------------------------------


def answer_text(value: Decimal, sigfigs: int | None) -> str:
    """A student's way of writing `value`: to the asked sigfigs, else 6 significant figures."""
    if sigfigs is not None:
        return format_number(round_sigfigs(value, sigfigs, ROUND_HALF_UP)).replace(" × 10^", "e")
    return format_number(round_sigfigs(value, 6, ROUND_HALF_UP)).replace(" × 10^", "e")


def unit_alternatives(units: str) -> list[str]:
    """Other units of the same dimension a student might answer in (km/h for m/s, cm/s^2, ...)."""
    return list(_UNIT_ALTERNATIVES.get(units.strip(), ()))


def _numeric_checks(
    problem: str, compiled: CompiledProblem, part: CompiledNumericPart, students: list[Variant]
) -> list[CheckResult]:
    results: list[CheckResult] = []
    sigfigs = part.tolerance.sigfigs
    dimensionless = part.units.strip() == "1"
    for index, variant in enumerate(students):
        spec = part.spec(variant)
        reference = spec.expected
        attempts: list[tuple[str, str, bool]] = []
        suffix = "" if dimensionless else f" {part.units}"
        attempts.append((f"variant {index}", answer_text(reference, sigfigs) + suffix, True))
        if reference != 0:
            attempts.append(
                (f"variant {index} 10% off", answer_text(reference * OFF_BY, sigfigs) + suffix, False)
            )
        for alternative in unit_alternatives(part.units):
            factor = unit_scale(part.units) / unit_scale(alternative)
            if sigfigs is not None and not _power_of_ten(factor):
                continue  # rounding to n figures in another unit is a different number
            converted = Decimal(str(sympy.Float(sympy.Rational(*reference.as_integer_ratio()) * factor, 30)))
            attempts.append(
                (
                    f"variant {index} in {alternative}",
                    f"{answer_text(converted, sigfigs)} {alternative}",
                    True,
                )
            )
        for label, text, should_pass in attempts:
            verdict = check_answer(text, spec)
            ok = (
                verdict.outcome is Outcome.CORRECT
            ) == should_pass and verdict.outcome is not Outcome.INVALID
            detail = "" if ok else f"expected {reference}: " + _explain(text, verdict)
            results.append(CheckResult(problem, part.id, label, ok, detail))
    return results


def _power_of_ten(factor: sympy.Expr) -> bool:
    if not factor.is_Rational or factor <= 0:
        return False
    p, q = int(factor.p), int(factor.q)
    return (p == 1 or str(p).rstrip("0") == "1") and (q == 1 or str(q).rstrip("0") == "1")


def main(argv: list[str] | None = None) -> int:
    """`python -m problems.selftest`: the same as `physcheck bank verify`, without the progress bar."""
    report = verify_bank()
    print(report.summary())
    return 0 if report.ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
