"""A model with a body on z (depth.py), drawn from the side: every picture here is of the x–y plane, z out
of the page, which shows such a model truly where its bodies are in the page (z = 0) as drawn. One shape
is drawn so, a bob on a string from a point going round a cone (a conical pendulum, in a lift or not);
any other model with z is drawn as its bodies side by side."""

from __future__ import annotations

import sympy

from physics.engine.depth import DEPTH
from physics.engine.model import ConstraintKind, Model
from physics.figures.figure import Figure, NotDrawable, Values, body_label
from physics.figures.geometry import is_linear
from physics.figures.pendulum import draw_pendulum

IN_THE_PAGE = 1e-9  # |z| below this, in the model's lengths, is in the page


def draw_side_view(figure: Figure, model: Model, values: Values) -> None:
    strings = [c for c in model.constraints if c.kind is ConstraintKind.STRING]
    if len(model.bodies) != 1 or len(strings) != 1 or is_linear(strings[0].gap, model):
        raise NotDrawable(
            "a body moves along z, across the page, and only a conical pendulum is drawn from the side: "
            "the bodies are drawn side by side"
        )
    body = model.bodies[0]
    place = values.at_state(model, {c.symbol: 0.0 for c in model.coordinates})
    if abs(values.number(dict(body.position).get(DEPTH, sympy.Integer(0)), place)) > IN_THE_PAGE:
        raise NotDrawable(
            f"{body_label(body, model)} is off the page (z ≠ 0) at the state, so a side view would draw it "
            "where it is not: the bodies are drawn side by side"
        )
    draw_pendulum(figure, model, body, strings[0], values)
