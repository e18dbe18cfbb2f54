"""A compiled problem as an instructor reads it: every part's reference (TeX), its known mistakes and
limiting cases, the worked solution by each method, and one variant's expected numbers.

Plain, picklable data: the upload vetting worker builds it for a preview before anything is stored,
and the problem pages build it from the catalog's compiled problem. No FastAPI here.
"""

from __future__ import annotations

from dataclasses import dataclass

from app.instructor.worked import Comparison, MethodInfo, worked_solutions
from problems.compiled import CompiledProblem
from problems.kinds import Part, kind_of
from problems.kinds.base import LimitInfo, MistakeInfo, PartInfo
from problems.kinds.numeric import SHOWN_FIGURES, tolerance_text
from problems.variants import Variant, shown_quantity

__all__ = [
    "SHOWN_FIGURES",
    "Described",
    "LimitInfo",
    "MistakeInfo",
    "PartInfo",
    "describe",
    "tolerance_text",
]


@dataclass(frozen=True)
class Described:
    parts: tuple[PartInfo, ...]
    methods: tuple[MethodInfo, ...]  # the worked solutions, in the seed's order (worked.py)
    agreement: tuple[tuple[str, tuple[str, ...]], ...]  # quantity -> methods that agree on it
    methods_agree: bool
    given: tuple[tuple[str, str], ...]  # the variant's values: (symbol, "2.5 kg")
    # checks of the model beside method agreement (energy bookkeeping, limits): name -> what was shown
    checks: tuple[tuple[str, str], ...] = ()
    # quantity -> what a numerical simulation compared, and its largest relative error
    simulation: tuple[tuple[str, str, float], ...] = ()
    comparison: Comparison | None = None  # the methods compared, where two or more answer


def _part(spec: Part, compiled: CompiledProblem, variant: Variant | None) -> PartInfo:
    """The part as its kind describes it."""
    info = PartInfo(id=spec.id, kind=spec.kind, prompt=spec.prompt, latex="")
    return kind_of(spec).describe(compiled.parts[spec.id], info, compiled, variant)


def describe(compiled: CompiledProblem, variant: Variant | None = None) -> Described:
    """Everything an instructor checks a problem by; numeric values for `variant` when given."""
    doc = compiled.document
    parts = tuple(_part(spec, compiled, variant) for spec in doc.parts)
    derived = compiled.derived
    derivation = derived.raw if derived is not None else None
    methods: tuple[MethodInfo, ...] = ()
    comparison: Comparison | None = None
    if derivation is not None:
        methods, comparison = worked_solutions(compiled, derivation, variant)
    agreement = () if derived is None else tuple((q, tuple(m)) for q, m in derived.agreement.items())
    given: tuple[tuple[str, str], ...] = ()
    if variant is not None:
        given = tuple(
            (name, shown_quantity(value, doc.given[name].unit))
            for name, value in variant.values.items()
            if name in doc.given
        )
    checks: tuple[tuple[str, str], ...] = ()
    simulation: tuple[tuple[str, str, float], ...] = ()
    if derivation is not None:
        checks = tuple((str(k), str(v)) for k, v in dict(getattr(derivation, "checks", {})).items())
        simulation = tuple(
            (str(name), str(check.compared), float(check.max_relative_error))
            for name, check in dict(getattr(derivation, "simulation", {})).items()
        )
    return Described(
        parts=tuple(parts),
        methods=methods,
        agreement=agreement,
        methods_agree=derived is not None and not derived.disagreements,
        given=given,
        checks=checks,
        simulation=simulation,
        comparison=comparison,
    )
