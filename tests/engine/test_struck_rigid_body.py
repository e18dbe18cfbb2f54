"""A body bouncing off a rigid body away from its centre (a ball off a hanging rod's end, a puck off a
free rod's end on ice): the contact's impulse turns the rigid body by its moment, in Newton's impulse
laws, in the conservation of generalized momentum and in the integrated contact; the velocities just
after are the textbook's."""

from __future__ import annotations

import pytest
import sympy
import yaml

from physics.engine import derivation, load_model
from physics.errors import SpecErrors

uncached = derivation._derive.__wrapped__
m, M, L, u, e = (sympy.Symbol(n, positive=True) for n in ("m", "M", "L", "u", "e"))
TABLE = {str(s): s for s in (m, M, L, u, e)}

HANGING = """
coordinates: [s]
bodies:
  ball: {mass: m, position: {x: s}}
elements:
  axle: {kind: pendulum, body: rod, mass: M, inertia: "M*L^2/12", distance: L/2, coordinate: phi}
state: {s: 0, phi: 0, s_dot: u}
impact: {bodies: [ball, rod], restitution: e, points: {rod: POINT}}
domain:
  ranges: {e: ["0", "1"]}
quantities:
  spin: {velocity_after: phi}
  ball: {final_velocity: ball}
"""
END = '{x: "L*sin(phi)", y: "-L*cos(phi)"}'
# lying along y, struck at its upper end by a puck sliding along x
FREE = """
coordinates: [s, X, Y, theta]
bodies:
  puck: {mass: m, position: {x: s}}
  rod: {mass: M, inertia: "M*L^2/12", position: {x: X, y: Y}, angle: theta}
state: {s: 0, X: 0, Y: 0, theta: 0, s_dot: u}
impact: {bodies: [puck, rod], restitution: e, points: {rod: {x: "X - L*sin(theta)/2", y: "Y + L*cos(theta)/2"}}}
domain:
  ranges: {e: ["0", "1"]}
quantities:
  spin: {velocity_after: theta}
  drift: {velocity_after: X}
"""
FREE_IMPULSE = (1 + e) * u * m * M / (4 * m + M)  # the end's effective mass is M/4
# seen from above: a turntable turning at u (rad/s here) picks up a blob at rest at its rim, radius L
TURNTABLE = """
coordinates: [s]
bodies:
  blob: {mass: m, position: {x: s}}
elements:
  axle: {kind: pendulum, body: table, mass: M, inertia: "M*L^2/2", distance: 0, coordinate: phi}
state: {s: 0, phi: 0, phi_dot: u, s_dot: 0}
impact: {bodies: [blob, table], restitution: 0, normal: {x: -1}, points: {table: {x: "L*sin(phi)", y: "-L*cos(phi)"}}}
quantities:
  spin: {velocity_after: phi}
"""

CASES = [
    pytest.param(
        HANGING.replace("POINT", END),
        {"spin": 3 * m * u * (1 + e) / (L * (M + 3 * m)), "ball": u * (3 * m - e * M) / (M + 3 * m)},
        id="ball-off-a-hanging-rods-end",
    ),
    pytest.param(
        FREE, {"spin": -6 * FREE_IMPULSE / (M * L), "drift": FREE_IMPULSE / M}, id="puck-off-a-free-rods-end"
    ),
    pytest.param(TURNTABLE, {"spin": M * u / (M + 2 * m)}, id="turntable-picks-up-a-blob-at-its-rim"),
]


@pytest.mark.parametrize(("text", "expected"), CASES)
def test_the_struck_point_turns_the_rigid_body_by_the_impulses_moment(
    text: str, expected: dict[str, sympy.Expr]
) -> None:
    result = uncached(load_model(yaml.safe_load(text), TABLE))
    for name, value in expected.items():
        assert sympy.simplify(result.quantities[name] - value) == 0, name
        assert set(result.agreement[name]) >= {"newton", "conservation"}
        assert result.simulation[name].max_relative_error < 1e-3


def test_a_turning_rigid_body_struck_without_its_point_is_refused_saying_its_centre() -> None:
    # it had been struck at its centre without a word: spin 6 m u (1 + e)/((4 M + 3 m) L), not the end's
    with pytest.raises(SpecErrors) as caught:
        load_model(yaml.safe_load(HANGING.replace(", points: {rod: POINT}", "")), TABLE)
    [fault] = caught.value.errors
    assert fault.path == ("impact", "points")
    assert "rod turns" in fault.message
    assert "at its centre: {x: L*sin(phi)/2, y: -L*cos(phi)/2}" in fault.message


@pytest.mark.parametrize(
    ("change", "message"),
    [
        pytest.param(("POINT", '{x: "L*sin(phi)", y: "-L"}'), "the point moves on rod", id="moving-point"),
        pytest.param(
            ("points: {rod: POINT}", "points: {ball: {x: s, y: 1}}"), "ball is a particle", id="particle"
        ),
        pytest.param(
            ("points: {rod: POINT}", "points: {wall: {x: 0}}"), "not 'wall'", id="not-in-the-impact"
        ),
        pytest.param(
            ("restitution: e, points: {rod: POINT}", "stick: true"),
            "sticking is modelled for particles",
            id="rigid-body-sticking",
        ),
    ],
)
def test_a_struck_point_that_cannot_be_is_refused(change: tuple[str, str], message: str) -> None:
    with pytest.raises(SpecErrors, match=message):
        load_model(yaml.safe_load(HANGING.replace(*change)), TABLE)


def test_a_normal_the_bodies_do_not_approach_along_is_refused_and_said_once() -> None:
    text = TURNTABLE.replace("normal: {x: -1}", "normal: {x: 1}").replace(
        "spin: {velocity_after: phi}", "spin: {velocity_after: phi}\n  lost: {kinetic_energy_lost: impact}"
    )
    with pytest.raises(derivation.DerivationError) as refused:
        uncached(load_model(yaml.safe_load(text), TABLE))
    assert str(refused.value).count("do not approach along the normal") == 1
