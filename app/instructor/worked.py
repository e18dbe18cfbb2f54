"""A problem's worked solutions as a textbook sets them out, and the methods compared as the seed
document compares them for the moving wedge.

Each method's solution opens with its set-up (the coordinates it uses, in words; the forces it has to
name, on which body; its own letters), then its equations, numbered (2.1), (2.2), …, the count of
equations against unknowns, the solution, and a check of each result against the student's values.
The comparison says, per method, how many equations and unknowns it needed, which constraint forces it
had to name, how many steps it took, and which method suits this problem and why.

Plain, picklable data built from the compiled problem (no FastAPI): the instructor's problem page, the
printable solution and the student's released solution all render it with one template macro.
"""

from __future__ import annotations

import re
from collections import Counter
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from decimal import Decimal

import sympy

from physics import typeset
from physics.engine.model import Model
from physics.engine.notation import Notation, fill_bodies, notation_of
from physics.engine.results import Derivation, MethodReport, StepKind
from physics.errors import PhyscheckError
from problems.compiled import CompiledNumericPart, CompiledProblem
from problems.schema import ProblemDocument
from problems.variants import Variant, evaluate_reference, shown_quantity, si_values

# The seed's order: vectorial methods first, then the scalar ones, Lagrange's last.
ORDER = ("newton", "frames", "dalembert", "conservation", "lagrange")
SHORT = {
    "newton": "Newton's laws",
    "frames": "Newton's laws with fictitious forces",
    "dalembert": "d'Alembert's principle",
    "conservation": "Conservation laws",
    "lagrange": "Lagrange's equations",
}
_MASS_OF = re.compile(r"^(?:the )?mass of (?:the |a |an )?(.+)$", re.IGNORECASE)
_VECTORIAL = frozenset({"newton", "frames"})
_SINGULAR = frozenset({"dalembert"})  # its title names one principle: "d'Alembert's principle reaches"


@dataclass(frozen=True)
class Term:
    """One line of a set-up: a symbol and what it means (Markdown with TeX)."""

    tex: str
    words: str


@dataclass(frozen=True)
class StepInfo:
    title: str  # Markdown with TeX
    latex: str
    number: str | None = None  # "2.3" for a numbered equation

    @property
    def lines(self) -> tuple[str, ...]:
        """The formula as display lines: results listed with `,\\quad` and a general form followed by
        `:\\quad` go one to a line, so that none is wider than a phone or a printed page needs."""
        return tuple(line for line in _split_top_level(self.latex, (r",\quad ", r":\quad ")) if line.strip())


@dataclass(frozen=True)
class CheckInfo:
    """A result of the method at the student's values beside what their numeric part expects."""

    part: int  # its number in the answers' list: a hand-out's reader never sees part ids
    latex: str  # the method's result
    value: str  # e.g. "−1.83 m/s²"
    expected: str
    agrees: bool


@dataclass(frozen=True)
class MethodInfo:
    name: str
    title: str
    number: int  # its place on the page: equations are numbered (number.k)
    coordinates: tuple[Term, ...]
    forces: tuple[Term, ...]  # the forces it names, weights included
    letters: tuple[Term, ...]  # the method's own letters
    steps: tuple[StepInfo, ...]
    count: str  # "6 equations, (1.1)–(1.6), for 6 unknowns: …" (Markdown)
    checks: tuple[CheckInfo, ...]
    notes: tuple[str, ...]
    answers: tuple[str, ...]  # the quantities it derived
    equations: int
    unknowns: int
    constraint_forces: tuple[str, ...]  # TeX of the constraint forces it had to name


@dataclass(frozen=True)
class ComparisonRow:
    method: str
    equations: int | None  # None where its worked solution does not count them (shown "—", said why)
    unknowns: int | None
    forces: str  # Markdown: "$N_{1}$, $N_{2}$" or "none"
    steps: int
    answers: str  # the numbers of the parts it answers, "1, 2, 3"


@dataclass(frozen=True)
class Comparison:
    rows: tuple[ComparisonRow, ...]
    advice: str  # Markdown: which method and why, for this problem
    # Markdown, under the table: each worked method it leaves out, as it answers no part, and why; and
    # those whose worked solutions do not count their equations and unknowns (an impact's, an energy's)
    notes: tuple[str, ...] = ()


def _split_top_level(tex: str, separators: tuple[str, ...]) -> list[str]:
    """`tex` cut at each separator outside braces."""
    pieces, depth, start, index = [], 0, 0, 0
    while index < len(tex):
        char = tex[index]
        if char == "{":
            depth += 1
        elif char == "}":
            depth -= 1
        elif depth == 0 and (found := next((s for s in separators if tex.startswith(s, index)), None)):
            pieces.append(tex[start:index])
            index += len(found)
            start = index
            continue
        index += 1
    pieces.append(tex[start:])
    return pieces


def body_words(doc: ProblemDocument, notation: Notation, masses: Mapping[str, str]) -> dict[str, str]:
    """Each body's words: the author's, else from its mass symbol's meaning ("mass of the yo-yo" is "the
    yo-yo"), else the notation's default ("the block"). A mass several bodies share names none of them
    ("mass of each object" is not "the each object")."""
    words = dict(notation.bodies)
    held = Counter(masses.values())
    for body, mass in masses.items():
        symbol = doc.symbols.get(mass) if held[mass] == 1 else None
        match = _MASS_OF.match(symbol.meaning.strip()) if symbol is not None else None
        if match and words.get(body, "").startswith("the ") and not _authored(notation, body):
            words[body] = "the " + match.group(1).rstrip(".")
    return words


def body_captions(doc: ProblemDocument, model: Model) -> dict[str, str]:
    """Each body's caption under its free-body diagram: its words, with the letter the figures name it
    by (its own mass, or the notation's) where the words do not already write one ("the wedge $M$"),
    so a reader knows which body each one shows."""
    notation = notation_of(model)
    words = body_words(doc, notation, notation.masses)
    author = {key: symbol for key, symbol, _ in model.notation if symbol}
    masses = [b.mass for b in model.bodies]
    captions = {}
    for body in model.bodies:
        letter = author.get(body.name) or (
            body.mass.name if isinstance(body.mass, sympy.Symbol) and masses.count(body.mass) == 1 else None
        )
        said = words[body.name]
        captions[body.name] = (
            said if letter is None or "$" in said else f"{said} ${typeset.latex(sympy.Symbol(letter))}$"
        )
    return captions


def _authored(notation: Notation, body: str) -> bool:
    default = "the " + re.sub(r"(?<=[a-z])(?=[A-Z])", " ", body).lower()
    return notation.bodies.get(body) not in (default, None) and not notation.bodies[body].startswith(
        "the mass $"
    )


def _coordinates(method: str, notation: Notation, fill: Mapping[str, str]) -> tuple[Term, ...]:
    if method in _VECTORIAL:
        terms = [Term(name.tex, fill_bodies(name.words, fill)) for name in notation.cartesian.values()]
        if method == "frames":
            terms.append(
                Term(
                    "x', y'", "the same positions measured in the moving frame, from its body's own position"
                )
            )
        return tuple(terms)
    return tuple(Term(name.tex, fill_bodies(name.words, fill)) for name in notation.coordinates.values())


def _weights(
    doc: ProblemDocument, masses: Mapping[str, str], fill: Mapping[str, str], gravity: str
) -> list[Term]:
    return [
        Term(f"{typeset.latex(sympy.Symbol(mass))} {gravity}", f"the weight of {fill[body]}, downwards")
        for body, mass in masses.items()
    ]


def _letters(method: str, notation: Notation, report: MethodReport) -> tuple[Term, ...]:
    letters = notation.letters
    written = " ".join(step.latex for step in report.steps)
    if method == "lagrange":
        wanted = [letters.kinetic, letters.potential, letters.lagrangian, letters.generalized]
        return tuple(Term(t, w) for t, w in letters.legend() if t in wanted and t in written)
    if method == "conservation":
        return tuple(Term(t, w) for t, w in letters.legend() if t == letters.energy and t in written)
    if method == "dalembert":
        return (
            Term(
                r"\mathbf{r}_i",
                "the position of body $i$; $\\delta\\mathbf{r}_i$ a virtual displacement "
                "the constraints allow",
            ),
            Term(
                r"\mathbf{F}_i",
                "the applied force on body $i$ (weight, springs, given forces); the "
                "constraint forces do no virtual work and are left out",
            ),
            Term(r"-m_i\mathbf{a}_i", "the inertial force on body $i$"),
        )
    if method == "frames":
        return (
            Term(
                r"\mathbf{A}",
                "the acceleration of the frame's body; every other body feels "
                r"$-m\mathbf{A}$, the translational fictitious force",
            ),
        )
    return ()


def _checks(
    report: MethodReport, compiled: CompiledProblem, variant: Variant | None
) -> tuple[CheckInfo, ...]:
    """The method's result for each numeric part it answers, at the student's values."""
    if variant is None:
        return ()
    doc = compiled.document
    found = []
    for number, spec in enumerate(doc.parts, 1):
        part = compiled.parts.get(spec.id)
        of = getattr(spec, "of", None)
        if not isinstance(part, CompiledNumericPart) or of is None:
            continue
        try:
            quantity = getattr(doc.part(of), "quantity_name", of)
        except KeyError:
            quantity = of
        result = report.results.get(quantity)
        if result is None:
            continue
        try:
            values = si_values(doc, variant, compiled.table)
            mine = evaluate_reference(result, values, part.units)
            expected = part.reference(variant)
        except (PhyscheckError, ValueError, TypeError, ArithmeticError):
            continue
        agrees = _close(mine, expected)
        found.append(
            CheckInfo(
                number,
                typeset.latex(result),
                shown_quantity(_round(mine), part.units),
                shown_quantity(_round(expected), part.units),
                agrees,
            )
        )
    return tuple(found)


def _notes(notes: Sequence[str], compiled: CompiledProblem) -> tuple[str, ...]:
    """Why the method gives no answer to some parts, each reason once, naming the parts by their
    numbers in the answers' list ("Parts 1, 2 and 3: …"): the engine names its quantities, which a
    hand-out's reader never sees."""
    doc = compiled.document
    numbers: dict[str, list[str]] = {}
    for number, spec in enumerate(doc.parts, 1):
        of = getattr(spec, "of", None)
        try:
            asked = (
                getattr(doc.part(of), "quantity_name", of) if of else getattr(spec, "quantity_name", spec.id)
            )
        except KeyError:
            asked = of
        numbers.setdefault(asked, []).append(str(number))
    said: dict[str, list[str]] = {}
    for note in notes:
        quantity, colon, why = note.partition(": ")
        parts = numbers.get(quantity) if colon else None
        if parts is None:
            said.setdefault(note, [])
        else:
            said.setdefault(why, []).extend(parts)
    return tuple(
        why
        if not parts
        else f"{'Part' if len(parts) == 1 else 'Parts'} {_join(sorted(set(parts), key=int))}: {why}"
        for why, parts in said.items()
    )


def _round(value: Decimal) -> Decimal:
    return Decimal(f"{value:.4g}")


def _close(a: Decimal, b: Decimal) -> bool:
    scale = max(abs(a), abs(b), Decimal("1e-300"))
    return abs(a - b) <= scale * Decimal("1e-9")


def method_info(
    report: MethodReport,
    number: int,
    notation: Notation,
    fill: Mapping[str, str],
    doc: ProblemDocument,
    masses: Mapping[str, str],
    gravity: str | None,
    compiled: CompiledProblem,
    variant: Variant | None,
) -> MethodInfo:
    steps: list[StepInfo] = []
    count = 0
    unknowns: list[str] = []
    for step in report.steps:
        title = fill_bodies(step.title, fill)
        if step.kind is StepKind.EQUATION:
            count += 1
            steps.append(StepInfo(title, step.latex, f"{number}.{count}"))
        else:
            steps.append(StepInfo(title, step.latex))
        unknowns += [u for u in step.unknowns if u not in unknowns]
    named = sorted((notation.forces[c] for c in report.forces), key=lambda n: n.tex)
    forces: list[Term] = []
    if gravity is not None and report.name in _VECTORIAL:
        forces += _weights(doc, masses, fill, gravity)
    forces += [Term(n.tex, fill_bodies(n.words, fill)) for n in named]
    if report.name in _VECTORIAL:
        forces += [Term(f.tex, fill_bodies(f.words, fill)) for f in notation.frictions]
    span = f"({number}.1)–({number}.{count})" if count > 1 else f"({number}.1)"
    said = ", ".join(f"${u}$" for u in unknowns)
    if count and unknowns:
        text = f"{count} equation{'s' if count != 1 else ''}, {span}, for {len(unknowns)} unknown" + (
            f"{'s' if len(unknowns) != 1 else ''}: {said}."
        )
    elif count:
        text = f"{count} equation{'s' if count != 1 else ''}, {span}."
    else:
        text = ""
    return MethodInfo(
        name=report.name,
        title=SHORT.get(report.name, report.title),
        number=number,
        coordinates=_coordinates(report.name, notation, fill),
        forces=tuple(forces),
        letters=_letters(report.name, notation, report),
        steps=tuple(steps),
        count=text,
        checks=_checks(report, compiled, variant),
        notes=_notes([fill_bodies(n, fill) for n in report.notes], compiled),
        answers=tuple(report.results),
        equations=count,
        unknowns=len(unknowns),
        constraint_forces=tuple(n.tex for n in named),
    )


def ordered(reports: Sequence[MethodReport]) -> list[MethodReport]:
    rank = {name: i for i, name in enumerate(ORDER)}
    return sorted(reports, key=lambda r: rank.get(r.name, len(ORDER)))


def worked_solutions(
    compiled: CompiledProblem, derivation: Derivation, variant: Variant | None
) -> tuple[tuple[MethodInfo, ...], Comparison | None]:
    """Every method's worked solution, in the seed's order, and their comparison (two or more)."""
    notation = derivation.notation
    if notation is None:
        return (), None
    doc = compiled.document
    masses = notation.masses
    fill = body_words(doc, notation, masses)
    gravity = notation.gravity or None
    infos = tuple(
        method_info(report, i, notation, fill, doc, masses, gravity, compiled, variant)
        for i, report in enumerate(ordered([r for r in derivation.methods if r.steps]), start=1)
    )
    useful = [m for m in infos if m.answers]
    idle = [m for m in infos if not m.answers]
    return infos, (compare(useful, compiled, idle) if len(useful) >= 2 else None)


def compare(
    methods: Sequence[MethodInfo], compiled: CompiledProblem, idle: Sequence[MethodInfo] = ()
) -> Comparison:
    """The table of `methods`; `idle`, worked methods that answer no part, are left out of it, saying why."""
    parts = compiled.document.parts
    rows = []
    for m in methods:
        # by the number the answers' list gives each part: a hand-out's reader never sees part ids
        answered = [str(n) for n, p in enumerate(parts, 1) if getattr(p, "quantity_name", p.id) in m.answers]
        rows.append(
            ComparisonRow(
                method=m.title,
                equations=m.equations if _counted(m) else None,
                unknowns=m.unknowns if _counted(m) else None,
                forces=", ".join(f"${f}$" for f in m.constraint_forces) or "none",
                steps=len(m.steps),
                answers=", ".join(answered) or "—",
            )
        )
    notes = [
        f"{m.title} {_verb([m], 'answer', 'answers')} no part here"
        + (f" ({'; '.join(n.rstrip('.') for n in m.notes)})" if m.notes else "")
        + f", so the table leaves {'it' if m.name in _SINGULAR else 'them'} out."
        for m in idle
    ]
    uncounted = [m for m in methods if not _counted(m)]
    if uncounted:
        several = len(uncounted) > 1
        its = "their" if several else "its"
        notes.append(
            f"—: the worked solution{'s' if several else ''} by {_join([m.title for m in uncounted])} "
            f"{'do' if several else 'does'} not number {its} equations against {its} unknowns here; {its} "
            "steps are set out below."
        )
    return Comparison(tuple(rows), _advice(methods), tuple(notes))


def _counted(method: MethodInfo) -> bool:
    """Whether the method's worked solution counts its equations against its unknowns: a count with
    none of one or the other ("4 equations in 0 unknowns") would be false."""
    return method.equations > 0 and method.unknowns > 0


def _advice(methods: Sequence[MethodInfo]) -> str:
    """Which method suits this problem and why: the fewest equations for the motion, and who gives the
    constraint forces asked for."""
    motion = [m for m in methods if _counted(m)]
    if not motion:
        return ""
    quickest = min(motion, key=lambda m: (m.equations + m.unknowns, len(m.steps)))
    most = max(motion, key=lambda m: m.equations)
    said = [
        f"**{quickest.title}** {_verb([quickest], 'reach', 'reaches')} the answer with the least algebra here: {quickest.equations} "
        f"equation{'s' if quickest.equations != 1 else ''} in {quickest.unknowns} unknown"
        f"{'s' if quickest.unknowns != 1 else ''}"
        + (
            f", against {most.equations} for {most.title}, which must name every constraint force"
            if most is not quickest and most.equations > quickest.equations
            else ""
        )
        + "."
    ]
    free = [m for m in methods if not m.constraint_forces]
    if free:
        said.append(
            f"{_join([m.title for m in free])} never {_verb(free, 'name', 'names')} a constraint force: the constraints "
            "are built into the coordinates (or do no work), so the motion comes without them."
        )
    giving = [m for m in methods if m.constraint_forces]
    if giving and any(m.name in _VECTORIAL for m in giving):
        vectorial = next(m for m in giving if m.name in _VECTORIAL)
        said.append(
            f"A force the problem asks for ({_join([f'${f}$' for f in vectorial.constraint_forces])}) "
            f"comes directly from {vectorial.title}, which have it as an unknown; the scalar methods need "
            "one more equation of Newton's per force once they have the motion."
        )
    return " ".join(said)


def _verb(subject: Sequence[MethodInfo], plural: str, singular: str) -> str:
    """The verb agreeing with the methods' titles as its subject: laws reach, one principle reaches."""
    return singular if len(subject) == 1 and subject[0].name in _SINGULAR else plural


def _join(items: Sequence[str]) -> str:
    items = list(items)
    return items[0] if len(items) == 1 else ", ".join(items[:-1]) + " and " + items[-1]
