"""`maximize` / `minimize`: the value of a parameter at which a quantity is largest or smallest, kept by
the parameter's declared sign and range and by the second derivative's sign, derived by each method
from its own expression of the quantity and checked on simulated runs either side."""

from __future__ import annotations

import math
from typing import Any

import pytest
import sympy
import yaml

from physics.engine import derivation, extremum, load_model
from physics.errors import DerivationError, SpecErrors

uncached = derivation._derive.__wrapped__
SYMBOLS = {
    name: sympy.Symbol(name, positive=True)
    for name in ("m", "g", "v0", "alpha", "mu", "F", "v", "h", "r", "theta")
}
m, g, v0, alpha, mu, F, v, h, r, theta = SYMBOLS.values()

LAUNCH = """
coordinates: [x, y]
bodies:
  ball: {mass: m, position: {x: x, y: y}}
gravity: g
state: {x: 0, y: 0, x_dot: "v0*cos(alpha)", y_dot: "v0*sin(alpha)"}
domain:
  ranges: {alpha: ["0", "pi/2"]}
quantities:
  best: {maximize: alpha, of: {range: ball}}
"""
# thrown from the foot of an incline at theta, landing on it: the longest range along it at pi/4 + theta/2
UP_AN_INCLINE = """
coordinates: [x, y]
bodies:
  ball: {mass: m, position: {x: x, y: y}}
gravity: g
state: {x: 0, y: 0, x_dot: "v0*cos(alpha)", y_dot: "v0*sin(alpha)"}
domain:
  ranges: {alpha: ["0", "pi/2"], theta: ["0", "pi/2"]}
  positive: ["alpha - theta"]
quantities:
  best: {maximize: alpha, of: {range: ball, slope: theta}}
"""
ROPE = """
gravity: g
elements:
  floor: {kind: surface, body: block, mass: m, coordinate: x, friction: mu}
forces:
  - {body: block, force: {x: "F*cos(alpha)", y: "F*sin(alpha)"}}
state: {x_dot: v}
domain:
  ranges: {alpha: ["0", "pi/2"]}
  positive: ["m*g - F*sin(alpha)"]
quantities:
  best: {maximize: alpha, of: {acceleration: x}}
"""
PIVOT = """
elements:
  axle: {kind: pendulum, body: rod, mass: m, inertia: "m*r^2", distance: h, coordinate: phi}
gravity: g
quantities:
  best: {minimize: h, of: {period: phi}}
"""
# F (alpha^3 - 6 alpha^2 + 9 alpha): a local maximum at 1, a local minimum at 3, larger still at 5
CUBIC = """
coordinates: [x]
bodies:
  block: {mass: m, position: {x: x}}
forces:
  - {body: block, force: {x: "F*(alpha^3 - 6*alpha^2 + 9*alpha)"}}
domain:
  ranges: {alpha: ["0", "RANGE_END"]}
quantities:
  best: {KIND: alpha, of: {acceleration: x}}
"""


def cubic(kind: str, end: str) -> dict[str, Any]:
    data: dict[str, Any] = yaml.safe_load(CUBIC.replace("KIND", kind).replace("RANGE_END", end))
    return data


@pytest.mark.slow
@pytest.mark.parametrize(
    ("model", "expected", "measured"),
    [
        (LAUNCH, sympy.pi / 4, "integrated range"),
        (ROPE, sympy.atan(mu), "integrated acceleration"),
        (PIVOT, r, "integrated period"),
        (UP_AN_INCLINE, sympy.pi / 4 + theta / 2, "integrated range"),
    ],
    ids=[
        "launch-angle-for-range",
        "rope-angle-against-friction",
        "pivot-for-shortest-period",
        "launch-angle-up-an-incline",
    ],
)
@pytest.mark.sample(2)
def test_the_extremum_is_derived_by_two_methods_and_found_on_simulated_runs(
    model: str, expected: sympy.Expr, measured: str
) -> None:
    result = uncached(load_model(yaml.safe_load(model), SYMBOLS))
    assert result.quantities["best"] == expected  # in its simplest form: atan(mu), not a half-angle root
    assert len(result.agreement["best"]) >= 2
    assert measured in result.simulation["best"].compared
    assert result.simulation["best"].max_relative_error < 1e-3


def test_a_root_an_arctangents_branch_leaves_out_is_found_a_half_turn_on() -> None:
    """solve gives tan(2 alpha - theta) = -cot(theta) only theta/2 - pi/4, outside alpha's range."""
    model = load_model(yaml.safe_load(UP_AN_INCLINE), SYMBOLS)
    slope = sympy.sin(2 * alpha) * sympy.tan(theta) + sympy.cos(2 * alpha)  # d(range)/d(alpha), less a factor
    roots = extremum._other_turns(sympy.solve(slope, alpha), slope, alpha, model)
    values = {round(float(root.subs(theta, 0.3)), 9) for root in roots}
    assert round(math.pi / 4 + 0.15, 9) in values


def test_the_other_stationary_value_is_a_minimum_not_the_maximum() -> None:
    result = uncached(load_model(cubic("maximize", "2"), SYMBOLS))
    assert result.quantities["best"] == 1
    result = uncached(load_model(cubic("minimize", "4"), SYMBOLS))
    assert result.quantities["best"] == 3


def test_a_local_maximum_beaten_at_the_end_of_the_range_is_refused() -> None:
    with pytest.raises(
        DerivationError,
        match=r"alpha = 1 is a local maximum only: at alpha = 4\.\d+ the acceleration of x is larger",
    ):
        uncached(load_model(cubic("maximize", "5"), SYMBOLS))


def test_two_equal_maxima_in_the_range_are_refused() -> None:
    data = cubic("maximize", "4")
    data["forces"][0]["force"]["x"] = "-F*(alpha - 1)^2*(alpha - 3)^2"  # maxima at 1 and 3, a minimum at 2
    with pytest.raises(
        DerivationError,
        match=r"expected one maximum of the acceleration of x in alpha's declared sign and range, found \[1, 3\]",
    ):
        uncached(load_model(data, SYMBOLS))


def test_an_unknown_symbol_to_vary_is_a_spec_error() -> None:
    data = yaml.safe_load(LAUNCH)
    data["quantities"]["best"]["maximize"] = "beta"
    with pytest.raises(Exception, match="unknown symbol 'beta'"):
        load_model(data, SYMBOLS)


CARTS = """
coordinates: [x1, x2]
bodies:
  cart1: {mass: m1, position: {x: x1}}
  cart2: {mass: m2, position: {x: x2}}
state: {x1_dot: u}
impact: {bodies: [cart1, cart2], restitution: 1}
quantities:
  v2: {final_velocity: cart2}
  energy2: {expression: "m2*v2^2/2"}
  best: {maximize: m2, of: OF}
"""
CART_SYMBOLS = {n: sympy.Symbol(n, positive=True) for n in ("m1", "m2", "u")}


def test_an_extremum_of_another_quantity_named_is_derived_and_simulated() -> None:
    """`of: energy2`: the target mass that takes the most energy in an elastic collision is the moving one."""
    result = uncached(load_model(yaml.safe_load(CARTS.replace("OF", "energy2")), CART_SYMBOLS))
    assert result.quantities["best"] == CART_SYMBOLS["m1"]
    assert len(result.agreement["best"]) >= 2
    assert "vertex of the parabola" in result.simulation["best"].compared


@pytest.mark.parametrize(
    ("of", "refusal"),
    [
        pytest.param("energy3", "unknown quantity 'energy3'", id="unknown-name"),
        pytest.param(
            '{expression: "m2*v2^2/2"}', "write the expression as a quantity of its own", id="in-place"
        ),
    ],
)
def test_an_extremum_of_a_quantity_not_of_the_model_is_a_spec_error(of: str, refusal: str) -> None:
    with pytest.raises(SpecErrors, match=refusal):
        load_model(yaml.safe_load(CARTS.replace("OF", of)), CART_SYMBOLS)
