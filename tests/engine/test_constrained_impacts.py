"""Impacts that respect the constraints of every body in them: a cart hitting a block that a surface
keeps on a fixed incline (the incline's impulsive push takes part of the blow), and bodies hitting a
fixed floor or wall. Both methods carry the constraints (Newton with each constraint's impulse as an
unknown, conservation in the coordinates), and the simulation integrates the contact in the
coordinates, so a derivation that ignores a constraint is caught."""

from __future__ import annotations

import pytest
import sympy
import yaml

from physics.engine import derivation, load_model
from physics.errors import DerivationError, SpecErrors

uncached = derivation._derive.__wrapped__
NAMES = ("m", "m1", "m2", "u", "v", "e", "g", "L", "theta", "alpha")
SYMBOLS = {name: sympy.Symbol(name, positive=True) for name in NAMES}
m, m1, m2, u, v, e, g, L, theta, alpha = (SYMBOLS[n] for n in NAMES)

CART_AND_BLOCK_ON_INCLINE = """
# A cart on a level track at x hits a block resting at the foot of a fixed incline; the block can
# only move up the incline (s along it), and the incline pushes it during the impact.
coordinates: [x]
bodies:
  cart: {mass: m1, position: {x: x}}
elements:
  ramp: {kind: incline, body: block, mass: m2, angle: theta, coordinate: s, direction: up}
gravity: g
state: {x: 0, s: 0, x_dot: u}
impact: {bodies: [cart, block], restitution: 1}
domain:
  ranges: {theta: ["0", "pi/2"]}
quantities:
  cart_velocity: {final_velocity: cart}
  block_speed: {final_speed: block}
"""
BALL_ON_FLOOR = """
coordinates: [y]
bodies:
  ball: {mass: m, position: {y: y}}
gravity: g
state: {y: 0, y_dot: -v}                 # falling at v onto the floor at y = 0
impact: {bodies: [ball, {fixed: floor}], normal: {y: -1}, restitution: e}
domain:
  ranges: {e: ["0", "1"]}
quantities:
  rebound: {final_velocity: ball}
  lost: {kinetic_energy_lost: impact}
"""
PUCK_ON_WALL = """
coordinates: [x, y]
bodies:
  puck: {mass: m, position: {x: x, y: y}}
state: {x_dot: "v*cos(alpha)", y_dot: "v*sin(alpha)"}
impact: {bodies: [{fixed: wall}, puck], normal: {x: -1}, restitution: e}   # the normal from the wall
domain:
  ranges: {e: ["0", "1"], alpha: ["0", "pi/2"]}
quantities:
  speed: {final_speed: puck}
"""


def _derive(text: str) -> derivation.Derivation:
    return uncached(load_model(yaml.safe_load(text), SYMBOLS))


def _same(a: sympy.Expr, b: sympy.Expr) -> bool:
    return bool(sympy.simplify(a - b) == 0)


def test_a_block_held_on_an_incline_takes_the_blow_with_the_inclines_impulse() -> None:
    result = _derive(CART_AND_BLOCK_ON_INCLINE)
    # by hand: the cart's impulse J along x moves the block only along the incline, m2 w = J cos(theta);
    # elastic: w cos(theta) - v = u with m1 (v - u) = -J
    c = sympy.cos(theta)
    assert _same(result.quantities["block_speed"], 2 * m1 * u * c / (m1 * c**2 + m2))
    assert _same(result.quantities["cart_velocity"], u * (m1 * c**2 - m2) / (m1 * c**2 + m2))
    at = {m1: 1, m2: sympy.Rational(3, 2), u: 2, theta: sympy.Rational(3, 5)}
    assert round(float(result.quantities["cart_velocity"].subs(at)), 3) == -0.751
    assert round(float(result.quantities["block_speed"].subs(at)), 3) == 1.514
    for name in ("cart_velocity", "block_speed"):
        assert set(result.agreement[name]) == {"newton", "conservation"}
        assert result.simulation[name].max_relative_error < 1e-3
        assert "constraints holding" in result.simulation[name].compared


def test_a_derivation_that_ignores_the_incline_is_caught_by_the_simulation(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    free = 2 * m1 * u / (m1 + m2)  # the one-dimensional answer, blind to the incline's impulse
    monkeypatch.setattr(derivation, "_simplest", lambda forms: free if forms[0].has(theta) else forms[0])
    model = load_model(
        yaml.safe_load(CART_AND_BLOCK_ON_INCLINE.replace("  cart_velocity: {final_velocity: cart}\n", "")),
        SYMBOLS,
    )
    with pytest.raises(derivation.DerivationError, match="simulation disagrees"):
        uncached(model)


def test_a_ball_bounces_off_a_fixed_floor_with_e_times_its_speed() -> None:
    result = _derive(BALL_ON_FLOOR)
    assert _same(result.quantities["rebound"], e * v)
    assert _same(result.quantities["lost"], m * v**2 * (1 - e**2) / 2)
    assert set(result.simulation) == {"rebound", "lost"}


def test_a_puck_glancing_off_a_wall_keeps_its_velocity_along_the_wall() -> None:
    result = _derive(PUCK_ON_WALL)
    expected = v * sympy.sqrt(e**2 * sympy.cos(alpha) ** 2 + sympy.sin(alpha) ** 2)
    assert _same(result.quantities["speed"] ** 2, expected**2)


def test_a_pendulum_bob_hitting_a_wall_at_the_bottom_rebounds_along_it() -> None:
    text = """
elements:
  string: {kind: pendulum, body: bob, mass: m, length: L, coordinate: phi}
gravity: g
state: {phi: 0, phi_dot: v/L}
impact: {bodies: [bob, {fixed: wall}], restitution: e}
domain:
  ranges: {e: ["0", "1"]}
quantities:
  rebound: {final_speed: bob}
"""
    assert _same(_derive(text).quantities["rebound"], e * v)


@pytest.mark.parametrize(
    ("bodies", "extra", "message"),
    [
        ("[{fixed: floor}, {fixed: wall}]", "", "not both"),
        ("[ball, {fixed: ball}]", "", "is a body of the model"),
        ("[ball, {fixed: floor, at: 0}]", "", "a fixed partner is {fixed: <its name>}"),
        ("[ball, {fixed: floor}]", ", release: Q", "a fixed partner cannot take a share"),
    ],
    ids=["both-fixed", "a-body", "extra-key", "explosion"],
)
def test_a_faulty_fixed_partner_is_refused_at_its_path(bodies: str, extra: str, message: str) -> None:
    text = BALL_ON_FLOOR.replace("[ball, {fixed: floor}]", bodies).replace(
        "restitution: e}", f"restitution: e{extra}}}"
    )
    symbols = {**SYMBOLS, "Q": sympy.Symbol("Q", positive=True)}
    with pytest.raises(SpecErrors) as caught:
        load_model(yaml.safe_load(text), symbols)
    assert any(message in error.message for error in caught.value.errors), caught.value.errors


def test_the_flight_after_a_bounce_starts_with_the_velocities_the_impact_leaves() -> None:
    text = BALL_ON_FLOOR.replace(
        "  lost: {kinetic_energy_lost: impact}\n",
        "  lost: {kinetic_energy_lost: impact}\n  rise: {max_height: ball, after: impact}\n"
        "  airborne: {time_of_flight: ball, after: impact}\n",
    )
    result = _derive(text)
    assert _same(result.quantities["rise"], e**2 * v**2 / (2 * g))
    assert _same(result.quantities["airborne"], 2 * e * v / g)
    for name in ("rise", "airborne"):
        assert set(result.agreement[name]) == {"newton", "conservation"}
        assert "after an integrated contact" in result.simulation[name].compared


def test_the_motion_after_an_impact_needs_one() -> None:
    text = BALL_ON_FLOOR.replace(
        "impact: {bodies: [ball, {fixed: floor}], normal: {y: -1}, restitution: e}\n", ""
    )
    text = text.replace(
        "  rebound: {final_velocity: ball}\n  lost: {kinetic_energy_lost: impact}\n",
        "  rise: {max_height: ball, after: impact}\n",
    )
    with pytest.raises(SpecErrors) as caught:
        load_model(yaml.safe_load(text), SYMBOLS)
    assert [e.path for e in caught.value.errors] == [("quantities", "rise", "after")]


# a ball flying straight up at u hits a body held still above it: the holding string or surface must
# take the blow with an impulse of its force's sign, else it lets go (the string slackens, the block lifts)
BOB_ON_A_STRING = """
coordinates: [s]
bodies:
  ball: {mass: m1, position: {y: s}}
elements:
  string: {kind: pendulum, body: target, mass: m2, length: L, coordinate: phi}
state: {s: "-L", phi: 0, s_dot: u}
impact: {bodies: [ball, target], normal: {y: 1}, restitution: e}
domain:
  ranges: {e: ["0", "1"]}
quantities:
  ball_after: {final_velocity: ball}
"""
BLOCK_ON_A_SURFACE = """
coordinates: [s, X]
bodies:
  ball: {mass: m1, position: {y: s}}
  target: {mass: m2, position: {x: X, y: 0}}
constraints:
  CONTACT: {kind: surface, gap: GAP}
state: {s: 0, X: 0, s_dot: u}
impact: {bodies: [ball, target], normal: {y: 1}, restitution: e}
domain:
  ranges: {e: ["0", "1"]}
quantities:
  ball_after: {final_velocity: ball}
"""
# (the model, the constraint that would act the wrong way, or None: it holds, and the ball rebounds)
STRUCK = [
    pytest.param(BOB_ON_A_STRING, "string", id="bob-on-a-string-struck-from-below"),
    pytest.param(
        BLOCK_ON_A_SURFACE.replace("CONTACT", "floor").replace("GAP", "y_target"),
        "floor",
        id="block-on-a-floor",
    ),
    pytest.param(
        BLOCK_ON_A_SURFACE.replace("CONTACT", "ceiling").replace("GAP", "-y_target"),
        None,
        id="block-under-a-ceiling",
    ),
]


@pytest.mark.parametrize(("text", "refused"), STRUCK)
def test_a_string_or_surface_whose_impulse_would_act_the_wrong_way_is_refused(
    text: str, refused: str | None
) -> None:
    model = load_model(yaml.safe_load(text), SYMBOLS)
    if refused is None:  # the ceiling takes the blow: the ball rebounds as off a wall
        assert sympy.simplify(uncached(model).quantities["ball_after"] + e * u) == 0
        return
    with pytest.raises(DerivationError, match=f"constraint '{refused}': the .* during the impact") as caught:
        uncached(model)
    assert caught.value.path == ("impact",)


# a bullet fired at alpha to the horizontal embeds itself in a bob hanging on a string
BULLET_AT_AN_ANGLE = """
elements:
  string: {kind: pendulum, body: bob, mass: m2, length: L, coordinate: phi}
collision: {projectile: bullet, mass: m1, direction: {x: "cos(alpha)", y: DY}, target: bob, at: {phi: 0}, speed: u}
domain:
  ranges: {alpha: ["0", "pi/2"]}
quantities:
  swing: {velocity_after: phi}
"""


@pytest.mark.parametrize(
    ("dy", "refused"), [("-sin(alpha)", False), ("sin(alpha)", True)], ids=["down", "up"]
)
def test_a_bullet_rising_into_a_hanging_bob_is_refused_at_its_direction(dy: str, refused: bool) -> None:
    """Fired from below, the string would have to push the bob down to hold it on its circle: it goes
    slack and the bob flies up. The collision had been worked with the string holding (m u cos(alpha)
    / ((m1 + m2) L), as from above)."""
    model = load_model(yaml.safe_load(BULLET_AT_AN_ANGLE.replace("DY", f'"{dy}"')), SYMBOLS)
    if not refused:
        swing = uncached(model).quantities["swing"]
        assert sympy.simplify(swing - m1 * u * sympy.cos(alpha) / ((m1 + m2) * L)) == 0
        return
    with pytest.raises(
        DerivationError, match="constraint 'string': the string would push as the projectile strikes"
    ):
        uncached(model)
