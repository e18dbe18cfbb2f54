"""Small problem documents for the bank's tests (fresh copies: tests mutate them)."""

from __future__ import annotations

import copy
from typing import Any

_SPRING: dict[str, Any] = {
    "id": "tiny-spring",
    "title": "Tiny spring",
    "topics": ["oscillations"],
    "statement": "A mass $m$ on a spring $k$. Here $m$ = {m} and $k$ = {k}; note $\\frac{m}{k}$ stays.",
    "symbols": {
        "m": {"meaning": "mass", "dimension": "kg"},
        "k": {"meaning": "spring constant", "dimension": "N/m"},
        "theta": {"meaning": "an angle", "dimension": "1", "range": [0, "pi/2"]},
    },
    "constraints": [],
    "given": {
        "m": {"min": 0.5, "max": 2.0, "unit": "kg", "sigfigs": 2},
        "k": {"min": 10, "max": 100, "unit": "N/m", "step": 5},
        "theta": {"min": 10, "max": 40, "unit": "deg", "step": 1},
    },
    "parts": [
        {
            "id": "angular_frequency",
            "kind": "symbolic",
            "prompt": "Find the angular frequency.",
            "answer": "sqrt(k/m)",
            "symbols": ["m", "k"],
            "mistakes": [{"answer": "sqrt(k/m)/(2*pi)", "feedback": "That is the frequency f, not omega."}],
            "limits": [{"where": {"m": "oo"}, "description": "a huge mass barely moves"}],
        },
        {
            "id": "angular_frequency_numeric",
            "kind": "numeric",
            "prompt": "Find it numerically.",
            "of": "angular_frequency",
            "units": "rad/s",
        },
    ],
}


def spring() -> dict[str, Any]:
    return copy.deepcopy(_SPRING)


FRICTION_CHOICE: dict[str, Any] = {
    "id": "friction_direction",
    "kind": "choice",
    "prompt": "The block slides down the slope. Which way does friction act on it?",
    "choices": [
        {"text": "Up the slope", "correct": True},
        {"text": "Down the slope", "feedback": "Friction opposes the sliding, which is down the slope."},
        {"text": "Perpendicular to the slope"},
    ],
    "max_attempts": 1,
}


def spring_with_choice() -> dict[str, Any]:
    """The spring problem with a third part, a multiple choice."""
    data = spring()
    data["parts"].append(copy.deepcopy(FRICTION_CHOICE))
    return data


def stated_value(value: str = "4.5807", units: str = "m/s^2", **part: Any) -> dict[str, Any]:
    """A problem of one numeric part that states its value (as a `POST /v1/check` body does)."""
    return {
        "id": "stated-value",
        "title": "Stated value",
        "statement": "The acceleration of the cart is measured.",
        "symbols": {"a": {"meaning": "acceleration", "dimension": "m/s^2"}},
        "parts": [
            {
                "id": "a_value",
                "kind": "numeric",
                "prompt": "What is a?",
                "value": value,
                "units": units,
                **part,
            }
        ],
    }
