"""What a derivation hands back: reference answers, each method's worked steps, the checks made."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field

import sympy

from physics.symbolic.domain import KnownMistake, LimitCase

__all__ = ["Derivation", "KnownMistake", "LimitCase", "MethodReport", "SimulationCheck", "Step"]


@dataclass(frozen=True)
class Step:
    """One line of a worked solution: what is done, and the equation(s) in LaTeX."""

    title: str
    latex: str


@dataclass(frozen=True)
class MethodReport:
    name: str  # "lagrange", "newton", "conservation"
    title: str
    steps: tuple[Step, ...]
    results: Mapping[str, sympy.Expr]
    notes: tuple[str, ...] = ()  # e.g. why a quantity was out of this method's reach


@dataclass(frozen=True)
class SimulationCheck:
    """A numerical integration of the equations of motion compared with the closed form."""

    compared: str  # what was measured, e.g. "acceleration from finite differences of the trajectory"
    max_relative_error: float
    points: int  # parameter points tried


@dataclass(frozen=True)
class Derivation:
    quantities: Mapping[str, sympy.Expr]
    methods: tuple[MethodReport, ...]
    agreement: Mapping[str, tuple[str, ...]]
    simulation: Mapping[str, SimulationCheck]
    mistakes: Mapping[str, tuple[KnownMistake, ...]]
    limits: Mapping[str, tuple[LimitCase, ...]]
    proofs: Mapping[str, str] = field(default_factory=dict)  # quantity -> "symbolic" or "sampled (...)"
    # physical checks beside method agreement (energy bookkeeping, limiting cases): name -> what was shown
    checks: Mapping[str, str] = field(default_factory=dict)
