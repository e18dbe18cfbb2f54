"""Figures of problems drawn from their models, as SVG text (no web imports).

    svg = model_figure(model, {"theta": 0.52, "m1": 0.4}, title="Cart on an incline")

    svg = free_body_figure(model, "block", values, title="Block on a wedge")   # forces on one body

`model` is the engine's loaded `Model`; values are SI (angles in radians) by symbol name, and missing
ones take typical values. The SVG has role="img", a <title> and a <desc> saying what is drawn.

The scene (scene.py) is drawn from the elements the author wrote: `DRAWERS` maps each element kind to
its picture family's `from_elements` (incline.py: inclines, wedges, floors and rolling bodies with the
springs and pulleys on them; pulleys.py; pendulum.py; spring_block.py; turning.py), an impact section
to impact.py, and a hand-written low-level model to recognise.py. A new element kind is one drawer
there. Shared parts: figure.py (Figure, Values, labels), geometry.py (reading the model), shapes.py.
"""

from __future__ import annotations

from collections.abc import Mapping
from html import escape

from physics.engine.model import Model
from physics.figures.free_body import Force, body_forces, free_body_figure
from physics.figures.scene import compose
from physics.wording import symbol_label

__all__ = ["Force", "body_forces", "free_body_figure", "model_figure", "symbol_label"]


def model_figure(model: Model, values: Mapping[str, float], *, title: str) -> str:
    """The figure; where an angle could not be drawn at its value it says so, in the drawing, in its
    description and as `data-to-scale="no"` on the <svg> (the page's caption reads it)."""
    figure = compose(model, values)
    said = " ".join(figure.said)
    if figure.unscaled:
        note = "Not to scale: " + "; ".join(figure.unscaled) + "."
        svg = figure.canvas.svg(f"Figure: {title}", f"{said} {note}")
        return svg.replace("<svg ", '<svg data-to-scale="no" data-scale-note="' + escape(note) + '" ', 1)
    return figure.canvas.svg(f"Figure: {title}", said)
