"""The physics engine: a mechanical model (data) in, reference answers out, each derived by at least two
independent methods, proved equal on the domain, and checked against a numerical simulation.

    load_model(data, symbols) -> Model       validate a model section (SpecErrors with paths, all at once)
    derive(model) -> Derivation              quantities, worked methods, agreement, simulation, mistakes, limits
"""

from physics.engine.derivation import derive
from physics.engine.loading import load_model
from physics.engine.model import Model
from physics.engine.results import (
    Derivation,
    KnownMistake,
    LimitCase,
    MethodReport,
    SimulationCheck,
    Step,
)

__all__ = [
    "Derivation",
    "KnownMistake",
    "LimitCase",
    "MethodReport",
    "Model",
    "SimulationCheck",
    "Step",
    "derive",
    "load_model",
]
