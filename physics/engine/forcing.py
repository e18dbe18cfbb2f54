"""Forces that depend on the time `t`: `forces: [{body: cart, force: {x: "F0*cos(w*t)"}}]`.

The time is `t` in a given force's components (the problem's symbol `t` if its table has one, else the
engine's own); the model's `state` gives its value where answers are evaluated (`state: {t: "pi/w"}`),
or, when `t` is a symbol of the table, answers may be functions of it. Such a force has no potential:
Lagrange takes it as a generalized force and Newton on the Cartesian axes, at the state's time; the
simulation advances a clock with the motion, and the energy bookkeeping counts its work. What needs a
steady equilibrium (equilibria, frequencies, modes, terminal velocities) is refused with it.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Mapping

import sympy

from physics.engine.model import Model, QuantityKind
from physics.engine.supports import uses_time
from physics.errors import SpecError, SpecErrors

NAME = "t"
STEADY = frozenset(
    {
        QuantityKind.EQUILIBRIUM,
        QuantityKind.STIFFNESS,
        QuantityKind.ANGULAR_FREQUENCY,
        QuantityKind.PERIOD,
        QuantityKind.NORMAL_FREQUENCY,
        QuantityKind.MODE_SHAPE,
        QuantityKind.TERMINAL_VELOCITY,
        QuantityKind.DAMPED_FREQUENCY,
        QuantityKind.DECAY_TIME,
        QuantityKind.UNDAMPED_FREQUENCY,
    }
)


def time_symbol(symbols: Mapping[str, sympy.Symbol]) -> sympy.Symbol:
    return symbols.get(NAME) or sympy.Symbol(NAME, real=True)


def with_time(model: Model, time: sympy.Symbol) -> Model:
    """The model with its `time` set when a given force depends on it; SpecErrors for what it then
    cannot ask, and for a time in the state that no force uses."""
    used = any(time in e.free_symbols for f in model.force_entries for e in f.expressions())
    if not used:
        if uses_time(model, time):  # a support moving as prescribed: the methods decide what is steady
            return dataclasses.replace(model, time=time)
        if time in dict(model.state) and time not in model.parameters:
            raise SpecErrors([SpecError("no force or position depends on the time t", ("state", NAME))])
        return model
    faults = [
        SpecError(
            "a force depends on the time t, so the system has no steady equilibrium: ask for "
            "accelerations and forces at the state's time",
            ("quantities", q.name, q.kind.value),
        )
        for q in model.quantities
        if q.kind in STEADY or (q.inner is not None and q.inner.kind in STEADY)
    ]
    if faults:
        raise SpecErrors(faults)
    return dataclasses.replace(model, time=time)
