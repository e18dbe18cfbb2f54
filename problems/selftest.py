"""Bank self-test: does each problem grade its own reference answers the way a student's would be?

Each part is graded by the cases its kind states (`problems.kinds`): for a symbolic part, equivalent
rewritings of the reference typed as a student would must be ACCEPTED and every known mistake REJECTED
with its feedback; for a numeric part, across many students' variants, the reference value (also in
other units) accepted and a value 10 % off rejected; for a choice, the right one accepted and the
others rejected. Every student's values must satisfy the problem's constraints and the engine's
methods must agree. Nothing stops at the first failure.
"""

from __future__ import annotations

import sys
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field
from pathlib import Path

import sympy

from physics.answer_text import typed_text
from physics.engine.notation import audit
from physics.errors import DerivationError, PhyscheckError
from physics.wording import counted
from problems.compiled import CompiledProblem, CompiledSymbolicPart, compile_problem
from problems.errors import ProblemInvalid, format_path
from problems.kinds import kind_of
from problems.kinds.base import CheckResult
from problems.kinds.numeric import answer_text, unit_alternatives
from problems.kinds.symbolic import equivalent_forms, rewritings
from problems.loader import load_bank
from problems.modelinfo import MIN_AGREEING_METHODS, load_doc_model
from problems.schema import ProblemDocument
from problems.variants import Variant, draw_variant, si_values

__all__ = [
    "CheckResult",
    "ProblemReport",
    "Report",
    "answer_text",
    "equivalent_forms",
    "rewritings",
    "unit_alternatives",
    "verify_bank",
    "verify_problem",
]

# Not a credential: self-test variants only need to be reproducible.
SELFTEST_SECRET = "physcheck-bank-selftest"  # noqa: S105
DEFAULT_VARIANTS = 20
# (label, done, total): one call per finished part within a problem, or per problem within the bank.
Progress = Callable[[str, int, int], None]


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
        lines.append(
            f"{counted(len(self.problems), 'problem')}, {counted(total, 'check')}, {counted(len(self.failures), 'failure')}"
        )
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
        report.results.extend(_notation_checks(doc, compiled))
    total = len(compiled.parts)
    students = [draw_variant(doc, version, f"selftest-{i}", secret) for i in range(variants)]
    report.results.extend(_domain_checks(doc.id, compiled, students))
    for done, (part_id, part) in enumerate(compiled.parts.items(), start=1):
        try:
            report.results.extend(kind_of(doc.part(part_id)).selftest(doc.id, part, students))
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
            continue  # only a symbolic part names a model quantity
        methods = compiled.derived.agreement.get(part.quantity, ())
        proof = compiled.derived.proofs.get(part.quantity, "")
        ok = len(methods) >= MIN_AGREEING_METHODS
        detail = proof if ok else f"derived by {', '.join(methods) or 'no method'} only"
        results.append(CheckResult(problem, part.id, "methods agree", ok, detail))
    return results


def _notation_checks(doc: ProblemDocument, compiled: CompiledProblem) -> list[CheckResult]:
    """The worked solutions read cleanly: every constraint force has a physical name, no two things are
    written alike, every symbol a step prints is defined (physics/engine/notation.py)."""
    assert compiled.derived is not None
    derivation = compiled.derived.raw
    if getattr(derivation, "notation", None) is None:
        return []
    faults = audit(load_doc_model(doc, compiled.table), derivation.notation, derivation.methods)
    return [CheckResult(doc.id, None, "solution notation", not faults, "; ".join(faults[:5]))]


def _domain_checks(problem: str, compiled: CompiledProblem, students: list[Variant]) -> list[CheckResult]:
    """Every student's given values satisfy the problem's constraints (the skier does slide)."""
    results = []
    for index, variant in enumerate(students):
        values = si_values(compiled.document, variant, compiled.table)
        broken = []
        for relation in compiled.constraints:
            at = relation.xreplace(values)
            if not at.free_symbols and at is not sympy.true:
                broken.append(f"{typed_text(relation)} fails at {_shown(variant)}")
        if compiled.constraints:
            results.append(
                CheckResult(problem, None, f"variant {index} in domain", not broken, "; ".join(broken))
            )
    return results


def _shown(variant: Variant) -> str:
    return ", ".join(f"{name} = {value}" for name, value in variant.values.items())


def main(argv: list[str] | None = None) -> int:
    """`python -m problems.selftest`: the same as `physcheck bank verify`, without the progress bar."""
    report = verify_bank()
    print(report.summary())
    return 0 if report.ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
