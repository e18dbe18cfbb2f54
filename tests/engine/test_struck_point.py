"""A projectile that sticks in a rigid body away from its centre of mass (a bullet in a hanging rod's
end): every method counts the embedded mass where it is, the simulation couples the bullet at that
point, and a point that is not fixed on the body, or is away from a particle, is refused, as is a target
that turns struck with no point written."""

from __future__ import annotations

import pytest
import sympy
import yaml

from physics.engine import derivation, load_model
from physics.errors import SpecErrors

uncached = derivation._derive.__wrapped__
m, M, L, g, theta = (sympy.Symbol(n, positive=True) for n in ("m", "M", "L", "g", "theta"))
TABLE = {str(s): s for s in (m, M, L, g, theta)}

ROD = """
elements:
  axle: {kind: pendulum, body: rod, mass: M, inertia: "M*L^2/12", distance: L/2, coordinate: phi}
gravity: g
collision:
  projectile: bullet
  mass: m
  direction: {x: 1}
  target: rod
  POINT
  at: {phi: 0}
  reaches: {phi: theta}
domain:
  ranges: {theta: ["0", "pi/2"]}
quantities:
  speed: {projectile_speed: bullet}
  lost: {energy_fraction_lost: bullet}
"""


def rod(point: str) -> dict[str, object]:
    data: dict[str, object] = yaml.safe_load(ROD.replace("POINT", point))
    return data


def struck_at(s: sympy.Expr) -> tuple[sympy.Expr, sympy.Expr]:
    """The textbook answer for a bullet sticking at distance s below the pivot: angular momentum about
    the pivot across the blow, then energy up to the turning point."""
    inertia = M * L**2 / 3 + m * s**2
    speed = sympy.sqrt(2 * inertia * g * (1 - sympy.cos(theta)) * (M * L / 2 + m * s)) / (m * s)
    return speed, 1 - m * s**2 / inertia


@pytest.mark.parametrize(
    ("s", "point"),
    [
        pytest.param(L, '{x: "L*sin(phi)", y: "-L*cos(phi)"}', id="lower-end"),
        pytest.param(2 * L / 3, '{x: "2*L*sin(phi)/3", y: "-2*L*cos(phi)/3"}', id="two-thirds-down"),
        pytest.param(L / 2, '{x: "L*sin(phi)/2", y: "-L*cos(phi)/2"}', id="centre"),
    ],
)
@pytest.mark.sample(2)
def test_a_bullet_in_a_rod_counts_its_moment_about_the_pivot_where_it_sticks(
    s: sympy.Expr, point: str
) -> None:
    result = uncached(load_model(rod(f"point: {point}"), TABLE))
    speed, lost = struck_at(s)
    assert sympy.simplify(result.quantities["speed"] - speed) == 0
    assert sympy.simplify(result.quantities["lost"] - lost) == 0
    assert set(result.agreement["speed"]) >= {"newton", "conservation"}
    assert result.simulation["speed"].max_relative_error < 1e-3
    assert result.simulation["lost"].max_relative_error < 1e-3


def test_without_a_point_a_turning_target_is_refused_saying_where_its_centre_is() -> None:
    # it had stuck at the centre of mass without a word: the lower end's speed is another
    with pytest.raises(SpecErrors, match="rod turns") as refused:
        load_model(rod(""), TABLE)
    [error] = refused.value.errors
    assert error.path == ("collision", "point")
    assert "at its centre: {x: L*sin(phi)/2, y: -L*cos(phi)/2}" in error.message


def test_newtons_method_balances_the_impulses_on_the_rod_and_on_the_bullet_in_it() -> None:
    result = uncached(load_model(rod('point: {x: "L*sin(phi)", y: "-L*cos(phi)"}'), TABLE))
    newton = next(report for report in result.methods if report.name == "newton")
    titles = [step.title for step in newton.steps]
    assert "Impulse balance on «rod», constraint impulses unknown" in titles
    assert "Impulse balance on the bullet, constraint impulses unknown" in titles
    assert "Velocities just after, as the constraints allow" in titles


@pytest.mark.parametrize(
    ("point", "message"),
    [
        pytest.param('{x: "L*sin(phi)", y: "-L"}', "the point moves on rod", id="in-the-rooms-axes"),
        pytest.param('{x: "L*sin(phi)"}', "give the point's x and y", id="one-axis"),
    ],
)
def test_a_point_not_fixed_on_the_rod_is_refused(point: str, message: str) -> None:
    with pytest.raises(SpecErrors, match=message) as refused:
        load_model(rod(f"point: {point}"), TABLE)
    assert [error.path for error in refused.value.errors] == [("collision", "point")]


BLOCK = """
elements:
  string: {kind: pendulum, body: block, mass: M, length: L, coordinate: phi}
gravity: g
collision:
  projectile: PROJECTILE
  mass: m
  direction: {x: 1}
  target: block
  point: POINT
  at: {phi: 0}
  reaches: {phi: theta}
quantities:
  speed: {projectile_speed: PROJECTILE}
"""


def test_a_particle_is_struck_where_it_is() -> None:
    where = BLOCK.replace("PROJECTILE", "bullet")
    same = uncached(
        load_model(yaml.safe_load(where.replace("POINT", '{x: "L*sin(phi)", y: "-L*cos(phi)"}')), TABLE)
    )
    plain = uncached(load_model(yaml.safe_load(where.replace("  point: POINT\n", "")), TABLE))
    assert sympy.simplify(same.quantities["speed"] - plain.quantities["speed"]) == 0
    with pytest.raises(SpecErrors, match="block is a particle: a projectile sticks where it is"):
        load_model(yaml.safe_load(where.replace("POINT", '{x: "L*sin(phi)/2", y: "-L*cos(phi)/2"}')), TABLE)


def test_a_projectile_named_as_a_body_is_refused() -> None:
    text = BLOCK.replace("PROJECTILE", "block").replace("  point: POINT\n", "")
    with pytest.raises(SpecErrors, match="'block' names a body already"):
        load_model(yaml.safe_load(text), TABLE)


u, k, R, h = (sympy.Symbol(n, positive=True) for n in ("u", "k", "R", "h"))
GIVEN = {**TABLE, "u": u, "k": k, "R": R, "h": h}
# A cylinder rolling on a level floor (its angle -x/R), struck at height h above its centre.
CYLINDER = """
elements:
  cylinder: {kind: rolling, mass: M, radius: R, inertia: "M*R^2/2", coordinate: x}
collision:
  projectile: bullet
  mass: m
  direction: {x: 1}
  target: cylinder
  point: {x: "x + h*sin(x/R)", y: "h*cos(x/R)"}
  at: {x: 0}
  speed: u
domain:
  positive: [R - h]
quantities:
  after: {velocity_after: x}
"""
BLOCK_ON_SPRING = """
coordinates: [x]
bodies:
  block: {mass: M, position: {x: x}}
elements:
  spring: {kind: spring, between: [block, {x: 0}], stiffness: k}
collision: {projectile: bullet, mass: m, direction: {x: 1}, target: block, at: {x: 0}, speed: u}
quantities:
  after: {velocity_after: x}
"""
ROD_GIVEN = (
    ROD.replace("POINT", 'point: {x: "L*sin(phi)", y: "-L*cos(phi)"}')
    .replace("reaches: {phi: theta}", "speed: u")
    .replace("speed: {projectile_speed: bullet}", "after: {velocity_after: phi}")
)
BLOCK_GIVEN = (
    BLOCK.replace("PROJECTILE", "bullet")
    .replace("  point: POINT\n", "")
    .replace("reaches: {phi: theta}", "speed: u")
    .replace("speed: {projectile_speed: bullet}", "after: {velocity_after: phi}")
)


@pytest.mark.parametrize(
    ("text", "after"),
    [
        pytest.param(BLOCK_ON_SPRING, m * u / (M + m), id="block-on-a-spring"),
        pytest.param(BLOCK_GIVEN, m * u / ((M + m) * L), id="block-on-a-string"),
        pytest.param(ROD_GIVEN, 3 * m * u / ((M + 3 * m) * L), id="rod-struck-at-its-end"),
        pytest.param(  # angular momentum about the contact point, which the floor's impulses pass through
            CYLINDER,
            2 * R * m * u * (R + h) / (3 * M * R**2 + 2 * m * (R + h) ** 2),
            id="rolling-cylinder-struck-above-its-centre",
        ),
    ],
)
def test_with_the_speed_given_the_velocity_just_after_the_blow_is_derived(
    text: str, after: sympy.Expr
) -> None:
    result = uncached(load_model(yaml.safe_load(text), GIVEN))
    assert sympy.simplify(result.quantities["after"] - after) == 0
    assert set(result.agreement["after"]) >= {"newton", "conservation"}
    assert result.simulation["after"].max_relative_error < 1e-3


def test_a_rod_struck_at_its_end_has_the_centre_of_mass_slip_among_its_mistakes() -> None:
    result = uncached(load_model(yaml.safe_load(ROD_GIVEN), GIVEN))
    at_centre = 6 * m * u / ((4 * M + 3 * m) * L)  # the bullet's mass and moment taken at L/2
    slips = {
        str(sympy.simplify(mistake.expr - at_centre)): mistake.feedback
        for mistake in result.mistakes["after"]
    }
    assert "sticks where it strikes" in slips["0"]


@pytest.mark.parametrize(
    ("change", "message"),
    [
        pytest.param(("speed: u", "speed: u, reaches: {x: 1}"), "give exactly one of reaches", id="both"),
        pytest.param((", speed: u", ""), "give exactly one of reaches", id="neither"),
        pytest.param(
            ("after: {velocity_after: x}", "after: {projectile_speed: bullet}"),
            "the collision gives the projectile's speed",
            id="speed-asked-and-given",
        ),
    ],
)
def test_a_collision_gives_the_speed_or_asks_it_never_both(change: tuple[str, str], message: str) -> None:
    with pytest.raises(SpecErrors, match=message):
        load_model(yaml.safe_load(BLOCK_ON_SPRING.replace(*change)), GIVEN)


def test_the_velocity_after_needs_the_speed() -> None:
    text = ROD.replace("POINT", "").replace(
        "speed: {projectile_speed: bullet}", "after: {velocity_after: phi}"
    )
    with pytest.raises(SpecErrors, match=r"needs the collision's speed \(`speed:`\)"):
        load_model(yaml.safe_load(text), TABLE)
