"""What a derivation hands back: reference answers, each method's worked steps, the checks made."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from enum import StrEnum

import sympy

from physics.engine.notation import Notation
from physics.symbolic.domain import KnownMistake, LimitCase

__all__ = [
    "Derivation",
    "KnownMistake",
    "LimitCase",
    "MethodReport",
    "SimulationCheck",
    "Step",
    "StepKind",
]


class StepKind(StrEnum):
    WORK = "work"  # a definition, an energy, a rewriting: read, not counted
    EQUATION = "equation"  # an equation the method then solves, numbered on the page
    SOLVE = "solve"  # the equations solved for the unknowns


@dataclass(frozen=True)
class Step:
    """One line of a worked solution: what is done (Markdown with TeX), and the equation(s) in TeX."""

    title: str
    latex: str
    kind: StepKind = StepKind.WORK
    unknowns: tuple[str, ...] = ()  # a SOLVE step's unknowns, as TeX
    symbols: tuple[str, ...] = ()  # the names of the sympy symbols its formula prints (the notation test)


@dataclass(frozen=True)
class MethodReport:
    name: str  # "lagrange", "newton", "conservation"
    title: str
    steps: tuple[Step, ...]
    results: Mapping[str, sympy.Expr]
    notes: tuple[str, ...] = ()  # e.g. why a quantity was out of this method's reach
    # the constraints whose forces the method had to name as unknowns (Newton's: all; Lagrange's: none
    # for the motion, each force asked for after it)
    forces: tuple[str, ...] = ()


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
    notation: Notation | None = None  # the names the worked solutions use, and what each means
