"""An angle coordinate on a curved surface: what the declared inequalities settle (|R − r| is R − r
where R > r is declared, atan(tan θ) is θ with θ inside (−π/2, π/2)) is settled in the consistency check
and in the answers, and nothing else is."""

from __future__ import annotations

import pytest
import sympy
import yaml

from physics.engine import Model, derivation, load_model
from physics.engine.settle import settle
from physics.errors import DerivationError

uncached = derivation._derive.__wrapped__
NAMES = ("m", "r", "R", "g")
SYMBOLS = {name: sympy.Symbol(name, positive=True) for name in NAMES}
m, r, R, g = (SYMBOLS[n] for n in NAMES)

BALL_IN_BOWL = """
coordinates: [theta]
bodies:
  ball:
    mass: m
    inertia: "2*m*r^2/5"
    position: {x: "(R - r)*sin(theta)", y: "-(R - r)*cos(theta)"}
    angle: "-(R - r)*theta/r"
gravity: g
constraints:
  bowl: {kind: surface, gap: "R - r - sqrt(x_ball^2 + y_ball^2)"}
  rolling: {kind: rolling, gap: "r*phi_ball + (R - r)*atan(x_ball/(-y_ball))"}
domain:
  ranges: {theta: ["-pi/2", "pi/2"]}
  positive: ["R - r"]
state: {theta: "pi/6"}
quantities:
  omega: {angular_frequency: theta, amplitude: small}
  normal: {force: bowl}
"""


def _model(text: str) -> Model:
    return load_model(yaml.safe_load(text), SYMBOLS)


def test_a_ball_rolling_in_a_bowl_with_an_angle_coordinate_is_derived_without_absolute_values() -> None:
    result = uncached(_model(BALL_IN_BOWL))
    assert sympy.simplify(result.quantities["omega"] ** 2 - 5 * g / (7 * (R - r))) == 0
    assert result.quantities["normal"] == sympy.sqrt(3) * m * g / 2
    assert len(result.agreement["normal"]) >= 2 and len(result.agreement["omega"]) >= 2
    assert {"omega", "normal"} <= set(result.simulation)


@pytest.mark.parametrize(
    ("declared", "written", "settled"),
    [
        ('positive: ["R - r"]', "abs(R - r)", "R - r"),
        ('positive: ["R - r"]', "abs(r - R)", "R - r"),
        ('positive: ["R - r"]', "atan(tan(theta))", "theta"),
        ('positive: ["R - r"]', "asin(sin(theta))", "theta"),
        ('positive: ["R - r"]', "acos(cos(theta))", "acos(cos(theta))"),  # θ < 0 is in the range
        ("positive: []", "abs(R - r)", "abs(R - r)"),  # either sign on the domain
        # a root of a quotient splits where the divisor keeps its sign: a conical pendulum's sqrt(1/cos)
        ('positive: ["R - r"]', "sqrt(1/(R - r))", "1/sqrt(R - r)"),
        ('positive: ["R - r"]', "sqrt(1/cos(theta))", "1/sqrt(cos(theta))"),  # cos > 0 on (-pi/2, pi/2)
        ('positive: ["R - r"]', "(m*g/cos(theta))^(-1/2)", "sqrt(cos(theta))/(sqrt(m)*sqrt(g))"),
        ("positive: []", "sqrt(1/(R - r))", "sqrt(1/(R - r))"),  # either sign: sqrt(1/-1) is not 1/sqrt(-1)
        ('positive: ["R - r"]', "sqrt(1/sin(theta))", "sqrt(1/sin(theta))"),  # sin < 0 for theta < 0
        ('positive: ["R - r"]', "sqrt(g/(R - r) - g/R)", "sqrt(g/(R - r) - g/R)"),  # a sum stays whole
    ],
)
def test_settle_removes_only_what_the_declared_domain_decides(
    declared: str, written: str, settled: str
) -> None:
    model = _model(BALL_IN_BOWL.replace('positive: ["R - r"]', declared))
    scope = {**SYMBOLS, "theta": model.coordinate("theta").symbol}
    expr = sympy.sympify(written, locals=scope)  # test-internal text, not user input
    assert settle(expr, model) == sympy.sympify(settled, locals=scope)


def test_an_undeclared_side_of_r_minus_big_r_is_refused_at_the_constraint_saying_what_is_left() -> None:
    with pytest.raises(DerivationError) as caught:
        uncached(_model(BALL_IN_BOWL.replace('positive: ["R - r"]', "positive: []")))
    assert "gap = R - r - abs(R - r) instead of 0" in str(caught.value)
    assert caught.value.path == ("constraints", "bowl")


def test_an_angle_whose_declared_range_reaches_past_the_principal_range_keeps_its_inverse() -> None:
    model = _model(BALL_IN_BOWL.replace('theta: ["-pi/2", "pi/2"]', 'theta: ["0", "3"]'))
    theta = model.coordinate("theta").symbol
    assert settle(sympy.atan(sympy.tan(theta)), model) == sympy.atan(sympy.tan(theta))
    assert settle(sympy.acos(sympy.cos(theta)), model) == theta  # (0, 3) lies inside acos's [0, pi]
