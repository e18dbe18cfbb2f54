"""CPU milliseconds per check of each answer kind the engine grades against a model (Lagrangian,
kinetic energy, potential energy, equation, free-body diagram, lab data), in process, on a prepared
question: medians of rounds.

    .venv/bin/python bench/kinds_cpu.py [--rounds 20]

The questions are POST /v1/check bodies (the wedge's T and V, the incline's Newton's law), prepared
once as a worker does (a block on a rough incline's forces; a lab's seven accelerations); each round
grades typical answers, right and wrong in several notations, each
with a constant added that differs from round to round (the same verdict, but no answer seen before:
no cache of sympy's or ours answers it). CPU time, not wall time. Target: at most 10 ms per check.
"""

from __future__ import annotations

import argparse
import re
import statistics
import time

from pydantic import TypeAdapter

from physics.mathinput import InputLimits
from problems.kinds import CheckIn

WEDGE = {
    "coordinates": ["X", "s"],
    "kinetic": "(M+m)/2*X'^2 + m*X'*s'*cos(theta) + m/2*s'^2",
    "potential": "-m*g*s*sin(theta)",
    "symbols": {
        "m": {"dimension": "kg"},
        "M": {"dimension": "kg"},
        "g": {"dimension": "m/s^2"},
        "theta": {"dimension": "1", "range": [0, "pi/2"]},
    },
}
INCLINE = {
    "expected": "m*a = m*g*sin(theta) - mu*N",
    "unknowns": {"a": "acceleration down the slope", "N": "normal force"},
    "symbols": {
        "m": {"dimension": "kg"},
        "g": {"dimension": "m/s^2"},
        "mu": {"dimension": "1"},
        "theta": {"dimension": "1", "range": [0, "pi/2"]},
    },
}
FORCES = {
    "body": "the block",
    "expected": [
        {"kind": "weight", "angle": 270},
        {"kind": "normal", "angle": 60},
        {"kind": "friction", "angle": 30},
    ],
}
LAB = {
    "quantity": "g*sin(theta)",
    "vary": "theta",
    "fit": "g",
    "settings": [0.0873, 0.1745, 0.2618, 0.3491, 0.4363, 0.5236, 0.6109],  # 5° to 35°, in radians
    "measured": [0.885, 1.73, 2.36, 3.39, 4.0, 4.91, 5.55],
    "units": "m/s^2",
}
CASES = {
    "lagrangian": (WEDGE, [
        "1/2 (M+m) X'^2 + m X' s' cos θ + 1/2 m s'^2 + m g s sin θ",
        r"\frac{1}{2}(M+m)\dot{X}^2 + m\dot{X}\dot{s}\cos\theta + \frac{1}{2}m\dot{s}^2 + mgs\sin\theta",
        "1/2 M Ẋ^2 + 1/2 m ((Ẋ + ṡ cos θ)^2 + (ṡ sin θ)^2) + m g s sin θ",
        "1/2 (M+m) X'^2 + m X' s' cos θ + 1/2 m s'^2 - m g s sin θ",
        "1/2 M X'^2 + 1/2 m s'^2 + m g s sin θ",
        "1/2 (M+m) X'^2 + m X' s' sin θ + 1/2 m s'^2 + m g s sin θ",
    ]),
    "kinetic_energy": ({k: v for k, v in WEDGE.items() if k != "potential"}, [
        "1/2 (M+m) X'^2 + m X' s' cos θ + 1/2 m s'^2",
        "1/2 M Ẋ^2 + 1/2 m ((Ẋ + ṡ cos θ)^2 + (ṡ sin θ)^2)",
        "1/2 (M+m) X'^2 + 1/2 m s'^2",
        "(M+m) X'^2 + 2 m X' s' cos θ + m s'^2",
    ]),
    "potential_energy": ({k: v for k, v in WEDGE.items() if k != "kinetic"}, [
        "-m g s sin θ", "m g (1 - s sin θ)", "m g s sin θ", "-m g s cos θ",
    ]),
    "equation": (INCLINE, [
        "m a = m g sin θ - μ N", "m g sin θ - μ N = m a", "m a = m g sin θ", "m a = m g cos θ - μ N",
        "N = m g cos θ",
    ]),
    "free_body": (FORCES, [
        "weight {270}; normal {60}; friction {30}", "normal@{60}, friction@{30}, weight@{270}",
        "weight {270}; normal {90}; friction {30}", "weight {270}; normal {60}",
        "weight {270}; normal {60}; friction {210}; motion {210}",
    ]),
    "data": (LAB, ["{9.79} m/s^2", "{9.6} m/s^2", "{979} cm/s^2", "{2.1} m/s^2", "{9.79}"]),
}  # fmt: skip
SHIFTED = ("free_body", "data")  # their numbers move a little each round (not a constant added)


def varied(kind: str, answer: str, n: int) -> str:
    """The answer with the constant n added (to both sides of an equation), or its numbers moved by a
    hair: never the same text twice."""
    if kind in SHIFTED:
        return re.sub(r"\{([0-9.]+)\}", lambda m: f"{float(m.group(1)) * (1 + n * 1e-6):.9g}", answer)
    if kind == "equation":
        left, right = answer.split("=")
        return f"{left} + {n} = {right} + {n}"
    return f"{answer} + {n}"


def main() -> None:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("--rounds", type=int, default=20)
    args = parser.parse_args()
    adapter = TypeAdapter(CheckIn)
    limits = InputLimits()
    for kind, (body, answers) in CASES.items():
        question = adapter.validate_python({"kind": kind, "answer": "0", **body}).job().question()
        for answer in answers:  # warm-up: the question's prepared values, the parser's tables
            question.grade(varied(kind, answer, 1), limits)
        rounds = []
        for n in range(args.rounds):
            texts = [varied(kind, answer, n + 2) for answer in answers]
            started = time.process_time()
            for text in texts:
                question.grade(text, limits)
            rounds.append((time.process_time() - started) / len(answers) * 1e3)
        print(f"{kind:17} {statistics.median(rounds):6.2f} ms CPU per check (median of {args.rounds} rounds)")


if __name__ == "__main__":
    main()
