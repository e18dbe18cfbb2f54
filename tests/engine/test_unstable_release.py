"""A body released at rest on an unstable equilibrium "with a negligible push": the methods take the
motion from zero speed, the simulation starts it with a vanishing push towards where the quantity is
taken, even where the equilibrium's float value leaves rounding in the forces (sin(pi) = 1.2e-16)."""

from __future__ import annotations

import pytest
import sympy
import yaml

from physics.engine import derivation, load_model

uncached = derivation._derive.__wrapped__
SYMBOLS = {name: sympy.Symbol(name, positive=True) for name in ("m", "g", "L", "R")}
m, g, L, R = SYMBOLS.values()

ROD_UPRIGHT = """
elements:
  hinge: {kind: pendulum, body: rod, mass: m, inertia: "m*L^2/12", distance: L/2, coordinate: phi}
gravity: g
state: {phi: pi}                     # balanced upright over its hinged foot
domain:
  ranges: {phi: ["pi", "3*pi/2"]}
quantities:
  released: {velocity: phi, at: {phi: "3*pi/2"}}
"""
TOP_OF_SPHERE = """
coordinates: [theta]
bodies:
  block: {mass: m, position: {x: "R*sin(theta)", y: "R*cos(theta)"}}
gravity: g
constraints:
  dome: {kind: surface, gap: "sqrt(x_block^2 + y_block^2) - R"}
state: {theta: 0}                    # at rest on the top
quantities:
  released: {speed: block, at: {theta: "acos(2/3)"}}
"""


@pytest.mark.slow
@pytest.mark.parametrize(
    ("model", "expected"),
    [(ROD_UPRIGHT, sympy.sqrt(3 * g / L)), (TOP_OF_SPHERE, sympy.sqrt(2 * g * R / 3))],
    ids=["rod-balanced-upright", "block-on-top-of-a-sphere"],
)
@pytest.mark.sample(1)
def test_a_release_from_an_unstable_top_is_derived_and_simulated_with_a_vanishing_push(
    model: str, expected: sympy.Expr
) -> None:
    result = uncached(load_model(yaml.safe_load(model), SYMBOLS))
    assert sympy.simplify(result.quantities["released"] - expected) == 0
    assert len(result.agreement["released"]) >= 2
    assert "integrated motion reaches" in result.simulation["released"].compared
    assert result.simulation["released"].max_relative_error < 1e-3
