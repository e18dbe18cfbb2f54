"""Bank models as fixtures: each problem's model.yaml loaded with its symbol table (positive symbols)."""

from __future__ import annotations

from functools import cache
from pathlib import Path
from typing import Any

import sympy
import yaml

from physics.engine import Derivation, Model, derive, load_model

BANK = Path(__file__).resolve().parents[2] / "problems" / "bank"
LOWLEVEL = Path(__file__).resolve().parent / "lowlevel"

SYMBOLS: dict[str, tuple[str, ...]] = {
    "moving-wedge": ("m", "M", "theta", "g"),
    "yo-yo": ("m", "r", "k", "g"),
    "lennard-jones": ("U0", "r0", "r", "m"),
    "ballistic-pendulum": ("m", "M", "L", "theta", "g"),
    "skier-friction": ("alpha", "mu", "g", "m"),
    "incline-pulley": ("m1", "m2", "theta", "g"),
    "rolling-incline": ("m", "R", "theta", "g"),
    "mass-spring": ("m", "k"),
    "atwood": ("m1", "m2", "g"),
    "bowling-ball-skid": ("m", "R", "v0", "mu", "g"),
    "quarter-circle-slide": ("m", "R", "g"),
}
SLOW_PROBLEMS = frozenset(
    {"moving-wedge", "lennard-jones", "ballistic-pendulum", "skier-friction", "rolling-incline"}
)


@cache
def symbols(problem: str) -> dict[str, sympy.Symbol]:
    return {name: sympy.Symbol(name, positive=True) for name in SYMBOLS[problem]}


def model_data(problem: str) -> dict[str, Any]:
    """The problem's model in the low-level form, for tests that edit its sections: the bank's own file,
    or, where the bank writes it with elements, the hand-written equivalent in tests/engine/lowlevel."""
    hand_written = LOWLEVEL / f"{problem}.yaml"
    data = yaml.safe_load(
        (hand_written if hand_written.exists() else BANK / problem / "model.yaml").read_text()
    )
    assert isinstance(data, dict)
    return data


@cache
def bank_model(problem: str) -> Model:
    """The model exactly as the bank writes it."""
    return load_model(yaml.safe_load((BANK / problem / "model.yaml").read_text()), symbols(problem))


def bank_derivation(problem: str) -> Derivation:
    return derive(bank_model(problem))  # derive caches per model


def s(problem: str, name: str) -> sympy.Symbol:
    return symbols(problem)[name]
