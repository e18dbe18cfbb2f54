"""A model with a body on z is drawn plainly: every picture is of the x–y plane, and z would be dropped."""

from __future__ import annotations

from physics.engine import load_model
from physics.figures import free_body_figure
from physics.figures.scene import compose
from tests.engine.test_depth import PUCK, SYMBOLS


def test_a_model_with_z_is_drawn_as_its_bodies_side_by_side() -> None:
    figure = compose(load_model(PUCK, SYMBOLS), {})
    assert figure.fallback is not None and "along z" in figure.fallback
    assert "The bodies of the problem" in " ".join(figure.said)


def test_free_body_diagram_leaves_out_the_forces_on_a_body_on_z_only() -> None:
    model = load_model(PUCK, SYMBOLS)
    puck = free_body_figure(model, "puck", {}, title="Puck")
    weight = free_body_figure(model, "weight", {}, title="Puck")
    assert "not drawn, as m₁ moves along z" in puck
    assert "<line" not in puck and "from the +x axis" not in puck
    assert "m₂g at -90° from the +x axis" in weight and "T at 90° from the +x axis" in weight
