"""Grading a free-body diagram: the forces a student drew on one body, each a kind from the palette and a
direction, against the loads the model puts on that body (physics.figures.free_body).

The answer is text, as the page's diagram writes it or a student types it: `weight 270; normal 110`,
each force's kind and its direction in degrees, anticlockwise from +x (`@` or a space between them,
`;`, `,` or a new line between forces). It is read by a small grammar of its own, never evaluated.
Each of the model's forces must be drawn once, of its kind, within TOLERANCE degrees; nothing else may
be drawn. Feedback is per force: missing, extra (the "force of motion" is no force), or pointing the
wrong way (a normal force is perpendicular to its surface; friction opposes the sliding).
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

from physics.errors import ParseError, TooLarge
from physics.mathinput import InputLimits
from physics.verdict import InputProblem, Judgement, Preview, ReadAs, Reason, Verdict

TOLERANCE = 10.0  # degrees
MAX_FORCES = 12
KINDS = {
    "weight": "the weight",
    "normal": "a normal force",
    "tension": "a tension",
    "friction": "a friction force",
    "spring": "a spring force",
    "applied": "an applied force",
    "motion": 'a "force of motion"',
}
_ALIASES = {
    "gravity": "weight",
    "mg": "weight",
    "w": "weight",
    "n": "normal",
    "t": "tension",
    "f": "friction",
}
_FORCE = re.compile(r"\s*([A-Za-z]+)\s*(?:@|\s)\s*(-?\d+(?:\.\d+)?)\s*(?:°|deg)?\s*")
_WHY = {
    "normal": "a normal force is perpendicular to the surface, pushing away from it",
    "friction": "friction acts along the surface, against the sliding (or the tendency to slide)",
    "weight": "the weight points straight down",
    "tension": "a string pulls along itself, away from the body",
}


@dataclass(frozen=True)
class DrawnForce:
    kind: str
    angle: float  # degrees, anticlockwise from +x


@dataclass(frozen=True)
class ExpectedForce:
    kind: str
    angle: float
    label: str  # as the worked solution's diagram names it (N₁, T, mg)


def read_forces(text: str, limits: InputLimits | None = None) -> list[DrawnForce]:
    """The forces in `text`; ParseError (with the position) on anything else."""
    limits = limits or InputLimits()
    if len(text) > limits.max_length:
        raise TooLarge(f"The answer is too long ({len(text)} characters).", limits.max_length)
    forces: list[DrawnForce] = []
    position = 0
    for piece in re.split(r"[;,\n]", text):
        if piece.strip():
            match = _FORCE.fullmatch(piece)
            if match is None:
                raise ParseError(
                    "Give each force as its kind and direction in degrees, as in: weight 270; normal 110.",
                    position + len(piece) - len(piece.lstrip()),
                )
            kind = _ALIASES.get(match.group(1).lower(), match.group(1).lower())
            if kind not in KINDS:
                raise ParseError(
                    f"Unknown force {match.group(1)!r}: use one of {', '.join(KINDS)}.",
                    position + match.start(1),
                )
            forces.append(DrawnForce(kind, float(match.group(2)) % 360.0))
        position += len(piece) + 1
    if not forces:
        raise ParseError("Draw at least one force.", 0)
    if len(forces) > MAX_FORCES:
        raise TooLarge(f"At most {MAX_FORCES} forces.", 0)
    return forces


def _named(force: ExpectedForce) -> str:
    return f" ({force.label})" if force.label else ""


def _gap(a: float, b: float) -> float:
    return abs((a - b + 180.0) % 360.0 - 180.0)


def _text(forces: list[DrawnForce]) -> ReadAs:
    said = "; ".join(f"{f.kind} {f.angle:g}°" for f in forces)
    # Each angle in math mode: a superscript inside \text{} is printed as the characters "^\circ".
    latex = r"\text{; }".join(rf"\text{{{f.kind} }}{f.angle:g}^\circ" for f in forces)
    return ReadAs(said, latex)


@dataclass(frozen=True)
class ForcesQuestion:
    body: str  # "the block"
    expected: tuple[ExpectedForce, ...]
    tolerance: float = TOLERANCE

    def judge(self, drawn: list[DrawnForce]) -> Judgement:
        left = list(drawn)
        said: list[str] = []
        for force in self.expected:
            same = [d for d in left if d.kind == force.kind]
            if not same:
                said.append(f"{KINDS[force.kind].capitalize()}{_named(force)} is missing.")
                continue
            nearest = min(same, key=lambda d: _gap(d.angle, force.angle))
            left.remove(nearest)
            if _gap(nearest.angle, force.angle) > self.tolerance:
                why = _WHY.get(force.kind)
                said.append(
                    f"{KINDS[force.kind].capitalize()}{_named(force)} points the wrong way"
                    + (f": {why}." if why else ".")
                )
        for extra in left:
            if extra.kind == "motion":
                said.append(
                    'There is no "force of motion": a moving body needs no force to keep moving; draw only '
                    "what pushes or pulls on it."
                )
            else:
                said.append(
                    f"There is no {KINDS[extra.kind].removeprefix('a ').removeprefix('an ')} on {self.body} here."
                )
        if not said:
            return Judgement(True, Reason.EQUIVALENT, "Correct.")
        return Judgement(False, Reason.WRONG_VALUE, " ".join(said))

    def grade(self, answer: str, limits: InputLimits | None = None) -> Verdict:
        try:
            drawn = read_forces(answer, limits)
        except (ParseError, TooLarge) as error:
            return Verdict.invalid(error)
        return Verdict.graded(self.judge(drawn), _text(drawn))

    def read(self, answer: str, limits: InputLimits | None = None) -> Preview:
        try:
            return Preview(_text(read_forces(answer, limits)), None)
        except (ParseError, TooLarge) as error:
            return Preview(None, InputProblem(error.message, error.position))


# Each finding of `ForcesQuestion.judge` is one sentence that starts with a capital and has no full stop
# before its end, so a stored feedback splits back into its findings (`findings_of`).
_SENTENCE_END = re.compile(r"(?<=\.)\s+(?=[A-Z])")


def findings_of(feedback: str) -> tuple[str, ...]:
    """The findings in the feedback of an incorrect free-body answer, one per force (missing, pointing
    the wrong way, extra), as the class results count them."""
    return tuple(piece for piece in _SENTENCE_END.split(feedback.strip()) if piece)


def kind_of_label(label: str, first: bool, gravity: bool) -> str:
    """The palette's kind of one of the model's drawn forces, from its label (mg, N₁, T, f, Fₖ, F)."""
    if first and gravity:
        return "weight"
    return {"N": "normal", "T": "tension", "f": "friction"}.get(
        label[:1], "spring" if label.startswith("Fₖ") else "applied"
    )


def direction_angle(direction: tuple[float, float]) -> float:
    return math.degrees(math.atan2(direction[1], direction[0])) % 360.0
