"""`solve` (and a collision's projectile speed) keep the root the solved symbol's declared sign and
range allow, at every sampled point of the domain: a rate declared positive drops −√, an angle ranged in
[0, π/2] drops 2π − acos(2/3), a speed drops the root negative where cos θ > 0."""

from __future__ import annotations

import dataclasses

import pytest
import sympy
import yaml

from physics.engine import derivation, load_model
from physics.engine.roots import admissible
from physics.errors import DerivationError

uncached = derivation._derive.__wrapped__
NAMES = ("m", "M", "L", "g", "d", "alpha", "theta", "Omega")
SYMBOLS = {name: sympy.Symbol(name, positive=True) for name in NAMES}
m, M, L, g, d, alpha, theta, Omega = (SYMBOLS[n] for n in NAMES)

CONICAL_RATE = """
# a conical pendulum: the rate Omega at which the bob circles with its string at alpha to the vertical
coordinates: [phi]
bodies:
  bob: {mass: m, position: {x: "L*sin(phi)", y: "-L*cos(phi)"}}
gravity: g
constraints:
  string: {kind: string, gap: "L - sqrt(x_bob^2 + y_bob^2)"}
elements:
  frame: {kind: rotating, rate: Omega, bodies: [bob]}
state: {phi: alpha}
domain:
  ranges: {alpha: ["0", "pi/2"]}
quantities:
  rate: {solve: Omega, zero: {acceleration: phi}}
"""
BULLET_INTO_BLOCK_ON_INCLINE = """
# A block M rests at the foot of a fixed smooth incline; a bullet m flying horizontally embeds in it,
# and the block slides a distance d up the incline before it stops.
elements:
  ramp: {kind: incline, body: block, mass: M, angle: theta, coordinate: s, direction: up}
gravity: g
collision: {projectile: bullet, mass: m, direction: {x: 1}, target: block, at: {s: 0}, reaches: {s: d}}
domain:
  ranges: {theta: ["0", "pi/2"]}
quantities:
  bullet_speed: {projectile_speed: bullet}
  lost: {energy_fraction_lost: bullet}
"""


def _same(a: sympy.Expr, b: sympy.Expr) -> bool:
    return bool(sympy.simplify(a - b) == 0)


def test_a_rate_declared_positive_keeps_the_positive_root() -> None:
    result = uncached(load_model(yaml.safe_load(CONICAL_RATE), SYMBOLS))
    assert _same(result.quantities["rate"] ** 2, g / (L * sympy.cos(alpha)))
    assert float(result.quantities["rate"].subs({g: 9.8, L: 1, alpha: 0.5})) > 0
    assert "rate" in result.simulation


def test_the_right_bullet_into_a_block_on_an_incline_is_accepted() -> None:
    result = uncached(load_model(yaml.safe_load(BULLET_INTO_BLOCK_ON_INCLINE), SYMBOLS))
    # momentum along the incline (its impulse takes the rest): m v cos(theta) = (m + M) w; then
    # (m + M) w^2 / 2 = (m + M) g d sin(theta)
    expected = (m + M) * sympy.sqrt(2 * g * d * sympy.sin(theta)) / (m * sympy.cos(theta))
    assert _same(result.quantities["bullet_speed"], expected)
    assert _same(result.quantities["lost"], (M + m * sympy.sin(theta) ** 2) / (M + m))
    assert set(result.simulation) == {"bullet_speed", "lost"}  # the coupling respects the incline


def test_an_angle_keeps_the_root_inside_its_declared_range() -> None:
    theta_c = sympy.Symbol("theta_c", positive=True)
    model = load_model(yaml.safe_load(CONICAL_RATE), {**SYMBOLS, "theta_c": theta_c})
    roots = [sympy.acos(sympy.Rational(2, 3)), 2 * sympy.pi - sympy.acos(sympy.Rational(2, 3))]
    assert admissible(roots, theta_c, model) == roots  # no range declared: both are angles
    ranged = dataclasses.replace(model, symbol_ranges=((theta_c, sympy.Integer(0), sympy.pi / 2),))
    assert admissible(roots, theta_c, ranged) == roots[:1]


def test_a_root_whose_sign_rests_on_the_domain_is_judged_there() -> None:
    model = load_model(yaml.safe_load(CONICAL_RATE), SYMBOLS)
    root = sympy.sqrt(g / L) / sympy.sqrt(sympy.cos(alpha))
    assert admissible([-root, root], Omega, model) == [root]


CIRCULAR_SPEED = """
# the speed v of a circular orbit of radius R: the one at which r stops accelerating
coordinates: [r, phi]
bodies:
  satellite: {mass: m, position: {x: "r*cos(phi)", y: "r*sin(phi)"}}
potentials:
  - {bodies: [satellite], anchor: {x: 0, y: 0}, distance: d, energy: ENERGY}
state: {r: R, phi: 0, phi_dot: v/R}
domain:
  ranges: {r: ["0", "oo"]}
quantities:
  orbit_speed: {solve: v, zero: {acceleration: r}}
"""


def _orbit(energy: str) -> object:
    names = {n: sympy.Symbol(n, positive=True) for n in ("G", "M", "m", "R", "v")}
    return load_model(yaml.safe_load(CIRCULAR_SPEED.replace("ENERGY", f'"{energy}"')), names)


def test_a_solve_with_no_admissible_root_says_plainly_why() -> None:
    """A repulsion pushes the satellite outward at every speed: the refusal says the acceleration keeps
    its sign whatever v is (it had said "found [] among the roots []")."""
    G, R = (sympy.Symbol(n, positive=True) for n in ("G", "R"))
    assert uncached(_orbit("-G*M*m/d")).quantities["orbit_speed"] == sympy.sqrt(G * M / R)
    with pytest.raises(DerivationError) as caught:
        uncached(_orbit("G*M*m/d"))
    assert "no value of v (positive) makes the acceleration of r vanish" in caught.value.message
    assert "(G*M + R*v^2)/R^2, positive on the whole domain, whatever v is" in caught.value.message
    assert "among the roots" not in caught.value.message


# A car held on a banked curve by static friction at its limit: slipping down below the least speed,
# up above the greatest; both roots are real and positive, and only an inequality separates them
BANKED = """
coordinates: []
bodies:
  car: {mass: m, position: {x: R, y: 0}}
gravity: g
constraints:
  bank: {kind: surface, gap: "-(x_car - R)*sin(theta) + y_car*cos(theta)"}
  grip: {kind: other, gap: "(x_car - R)*cos(theta) + y_car*sin(theta)"}
elements:
  frame: {kind: rotating, rate: v/R, bodies: [car]}
domain:
  ranges: {theta: ["0", "pi/2"]}
  positive: ["1 - mu_s*tan(theta)", "tan(theta) - mu_s", SIDE]
quantities:
  limit: {slipping: v, friction: grip, normal: bank, coefficient: mu_s}
"""
R, v, mu_s = (sympy.Symbol(n, positive=True) for n in ("R", "v", "mu_s"))
sin, cos = sympy.sin(theta), sympy.cos(theta)
SIDES = [
    pytest.param('"g*R*tan(theta) - v^2"', R * g * (sin - mu_s * cos) / (cos + mu_s * sin), id="least-speed"),
    pytest.param(
        '"v^2 - g*R*tan(theta)"', R * g * (sin + mu_s * cos) / (cos - mu_s * sin), id="greatest-speed"
    ),
]


@pytest.mark.parametrize(("side", "squared"), SIDES)
@pytest.mark.sample(1)
def test_an_inequality_under_domain_positive_chooses_between_roots(side: str, squared: sympy.Expr) -> None:
    table = {**SYMBOLS, "R": R, "v": v, "mu_s": mu_s}
    found = uncached(load_model(yaml.safe_load(BANKED.replace("SIDE", side)), table)).quantities["limit"]
    assert sympy.simplify(found**2 - squared) == 0


def test_roots_no_declaration_separates_are_refused_saying_how_to_choose() -> None:
    table = {**SYMBOLS, "R": R, "v": v, "mu_s": mu_s}
    with pytest.raises(DerivationError, match="say which one the problem means"):
        uncached(load_model(yaml.safe_load(BANKED.replace(", SIDE", "")), table))
