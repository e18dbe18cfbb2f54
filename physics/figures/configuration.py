"""The configuration a problem is drawn in, shared by its scene and its free-body diagrams so that every
force in a diagram points as it does in the scene: the model's state where it gives a coordinate, else
0, except where the scene places a body itself (a pendulum swung aside to show that it swings, in a
turning frame at an angle that does not give the cone's away; a bead partway along its hoop); a support
moving in the time t is drawn where it starts, at t = 0.
"""

from __future__ import annotations

from collections.abc import Mapping

import sympy

from physics.engine.model import Model
from physics.figures.figure import Values
from physics.figures.scene import compose


def drawn_configuration(model: Model, given: Mapping[str, float]) -> dict[sympy.Symbol, float]:
    """Every coordinate's value in the configuration the scene draws (and the time's, 0), with the
    parameters in `given` (SI, radians) or typical values."""
    place = Values(model, given).at_state(model, {c.symbol: 0.0 for c in model.coordinates})
    if model.time is not None:
        place[model.time] = 0.0
    return place | compose(model, given).placed
