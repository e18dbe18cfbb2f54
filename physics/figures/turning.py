"""A rotating frame's element drawn with the body that turns in it: a bob on a string sweeping a cone
(a conical pendulum), or a body on a curve turning about the vertical axis (a bead on a spinning hoop)."""

from __future__ import annotations

from physics.engine.model import AuthoredElement, ConstraintKind, Model
from physics.figures.figure import Figure, Values
from physics.figures.geometry import bodies_in, is_linear, of_kind
from physics.figures.path import draw_path
from physics.figures.pendulum import draw_pendulum


def from_elements(
    figure: Figure, model: Model, values: Values, elements: tuple[AuthoredElement, ...]
) -> bool:
    """False unless one body turns with the frame, held by a string or moving on one coordinate."""
    frame = of_kind(elements, "rotating")[0]
    if len(frame.fields["bodies"]) != 1:
        return False
    body = model.body(str(frame.fields["bodies"][0]))
    strings = [
        c
        for c in model.constraints
        if c.kind is ConstraintKind.STRING and body in bodies_in(c.gap, model) and not is_linear(c.gap, model)
    ]
    if strings:
        draw_pendulum(figure, model, body, strings[0], values)
        return True
    if len(model.coordinates) != 1:
        return False
    spin = next(p for p in model.potentials if p.name == frame.potentials[0])
    draw_path(figure, model, body, values, spin=spin)
    return True
