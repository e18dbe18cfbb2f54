"""A problem's figure, drawn from what the author wrote.

An impact section sets the picture whatever holds its bodies (impact.py). Otherwise a model written
with elements is drawn by the picture family of its leading element kind (DRAWERS: a pendulum hangs
from whatever else there is, an incline carries the springs and pulleys on it, ...), from the elements'
own fields. A hand-written low-level model, or elements in a combination no family draws, is recognised
from its sections (recognise.py); a model with a body on z is seen from the side (side_view.py). A
figure that cannot be drawn because a parameter has no number at the figure's values is drawn as its
bodies side by side, with the reason kept; any other failure is a bug, and is raised.

Angles are labelled with the problem's symbol that sets them, bodies with their mass symbols. Values
are the student's (angles set the drawing's slopes) or typical ones; sizes are the figure's own.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping

from physics.engine import depth
from physics.engine.model import AuthoredElement, Model
from physics.figures import incline, pendulum, pulleys, spring_block, turning
from physics.figures.figure import Figure, NotDrawable, Values
from physics.figures.impact import draw_impact
from physics.figures.path import draw_row
from physics.figures.recognise import draw_recognised
from physics.figures.side_view import draw_side_view

# Draws the picture of a model's elements, or returns False (before drawing) for a combination it
# does not know.
ElementDrawer = Callable[[Figure, Model, Values, tuple[AuthoredElement, ...]], bool]

# One drawer per element kind, in the order in which a kind leads the picture when several are written.
DRAWERS: dict[str, ElementDrawer] = {
    "pendulum": pendulum.from_elements,
    "incline": incline.from_elements,
    "surface": incline.from_elements,
    "rolling": incline.from_elements,
    "pulley": pulleys.from_elements,
    "spring": spring_block.from_elements,
    "rotating": turning.from_elements,
}


def compose(model: Model, given: Mapping[str, float]) -> Figure:
    """The figure for `model` with the parameters in `given` (SI, radians) or typical values."""
    values = Values(model, given)
    figure = Figure()
    try:
        _draw(figure, model, values)
    except NotDrawable as reason:
        figure = Figure(drawn_from=figure.drawn_from, fallback=str(reason))
        draw_row(figure, model)
    return figure


def _draw(figure: Figure, model: Model, values: Values) -> None:
    if depth.uses_depth(model.bodies):  # every picture here is of the x–y plane: seen from the side
        figure.drawn_from = "low-level model"
        draw_side_view(figure, model, values)
        return
    if model.impact is not None:
        figure.drawn_from = "impact"
        draw_impact(figure, model, values)
        return
    kinds = {element.kind for element in model.elements}
    leading = next((kind for kind in DRAWERS if kind in kinds), None)
    figure.drawn_from = "elements"
    if leading is not None and DRAWERS[leading](figure, model, values, model.elements):
        return
    figure.drawn_from = "low-level model"
    draw_recognised(figure, model, values)
