"""Impacts between two moving bodies (coefficient of restitution, elastic, perfectly inelastic, glancing in
the plane) and explosions: final velocities and the kinetic energy lost, each by conservation laws and by
impulses, proved equal, and measured on an integrated spring-dashpot contact."""

from __future__ import annotations

from typing import Any

import pytest
import sympy

from physics.engine import derivation, load_model
from physics.errors import DerivationError, SpecErrors

uncached = derivation._derive.__wrapped__
NAMES = ("m1", "m2", "u1", "u2", "e", "u", "phi", "Q")
SYMBOLS = {name: sympy.Symbol(name, positive=True) for name in NAMES}
m1, m2, u1, u2, e, u, phi, Q = (SYMBOLS[n] for n in NAMES)


def carts(restitution: Any = "e", **impact: Any) -> dict[str, Any]:
    """Two carts on a track, both moving; cart1 catches up with cart2."""
    return {
        "coordinates": ["x1", "x2"],
        "bodies": {
            "cart1": {"mass": "m1", "position": {"x": "x1"}},
            "cart2": {"mass": "m2", "position": {"x": "x2"}},
        },
        "state": {"x1_dot": "u1", "x2_dot": "u2"},
        "impact": {"bodies": ["cart1", "cart2"], "restitution": restitution, **impact},
        "domain": {"ranges": {"e": ["0", "1"]}, "positive": ["u1 - u2"]},
        "quantities": {
            "v1": {"final_velocity": "cart1"},
            "v2": {"final_velocity": "cart2"},
            "lost": {"kinetic_energy_lost": "impact"},
        },
    }


def pucks() -> dict[str, Any]:
    """Puck 1 slides along x into puck 2 at rest, which moves off at phi below the x axis."""
    return {
        "coordinates": ["x1", "y1", "x2", "y2"],
        "bodies": {
            "puck1": {"mass": "m1", "position": {"x": "x1", "y": "y1"}},
            "puck2": {"mass": "m2", "position": {"x": "x2", "y": "y2"}},
        },
        "state": {"x1_dot": "u"},
        "impact": {
            "bodies": ["puck1", "puck2"],
            "restitution": 1,
            "normal": {"x": "cos(phi)", "y": "-sin(phi)"},
        },
        "domain": {"ranges": {"phi": ["0", "pi/2"]}},
        "quantities": {"v1": {"final_speed": "puck1"}, "v2": {"final_speed": "puck2"}},
    }


def shell() -> dict[str, Any]:
    """A shell moving at u1 splits into two fragments along its motion, releasing Q."""
    data = carts()
    data["state"] = {"x1_dot": "u1", "x2_dot": "u1"}
    data["impact"] = {"bodies": ["cart1", "cart2"], "release": "Q"}
    del data["domain"]
    return data


def _same(a: sympy.Expr, b: sympy.Expr) -> bool:
    return bool(sympy.simplify(a - b) == 0)


TOTAL = m1 * u1 + m2 * u2
M = m1 + m2


@pytest.mark.parametrize(
    ("restitution", "v1", "v2", "lost"),
    [
        ("e", (TOTAL - e * m2 * (u1 - u2)) / M, (TOTAL + e * m1 * (u1 - u2)) / M,
         m1 * m2 * (1 - e**2) * (u1 - u2) ** 2 / (2 * M)),
        (1, (TOTAL - m2 * (u1 - u2)) / M, (TOTAL + m1 * (u1 - u2)) / M, sympy.Integer(0)),
        (0, TOTAL / M, TOTAL / M, m1 * m2 * (u1 - u2) ** 2 / (2 * M)),
    ],
    ids=["restitution", "elastic", "perfectly-inelastic"],
)  # fmt: skip
def test_a_one_dimensional_impact_gives_each_final_velocity_by_two_methods_and_the_contact_model(
    restitution: Any, v1: sympy.Expr, v2: sympy.Expr, lost: sympy.Expr
) -> None:
    result = uncached(load_model(carts(restitution), SYMBOLS))
    for name, expected in {"v1": v1, "v2": v2, "lost": lost}.items():
        assert _same(result.quantities[name], expected), (name, result.quantities[name])
        assert set(result.agreement[name]) == {"conservation", "newton"}
        assert result.simulation[name].points == 3
        assert result.simulation[name].max_relative_error < 1e-3


def test_the_elastic_case_is_worked_by_energy_and_the_others_by_the_restitution_law() -> None:
    def conservation_steps(restitution: Any) -> list[str]:
        report = uncached(load_model(carts(restitution), SYMBOLS)).methods
        return [s.title for r in report if r.name == "conservation" for s in r.steps]

    assert any("Kinetic energy balance" in t for t in conservation_steps(1))
    assert any("restitution law" in t for t in conservation_steps("e"))


@pytest.mark.slow
def test_a_glancing_elastic_collision_of_pucks_gives_both_speeds() -> None:
    result = uncached(load_model(pucks(), SYMBOLS))
    assert _same(result.quantities["v2"], 2 * m1 * u * sympy.cos(phi) / M)
    speed1 = result.quantities["v1"]
    # kinetic energy is conserved, and for equal masses the two pucks leave at right angles
    assert _same(m1 * speed1**2 + m2 * result.quantities["v2"] ** 2 - m1 * u**2, 0)
    assert _same(speed1.subs(m2, m1) ** 2, (u * sympy.sin(phi)) ** 2)
    assert set(result.simulation) == {"v1", "v2"}


def test_an_explosion_shares_the_energy_released_and_keeps_the_momentum() -> None:
    result = uncached(load_model(shell(), SYMBOLS))
    v1, v2 = result.quantities["v1"], result.quantities["v2"]
    assert _same(m1 * v1 + m2 * v2, M * u1)
    assert _same(m1 * (v1 - u1) ** 2 / 2 + m2 * (v2 - u1) ** 2 / 2, Q)
    assert _same(v2, u1 + sympy.sqrt(2 * Q * m1 / (m2 * M)))  # the second fragment goes forward
    assert _same(result.quantities["lost"], -Q)
    assert set(result.simulation) == {"v1", "v2", "lost"}


@pytest.mark.parametrize(
    ("state", "closing"),
    [
        ({"x1_dot": "u1"}, "u1"),  # a sticking collision's lost energy typed as released
        ({"x1_dot": "u1", "x2_dot": "u2"}, "u1 - u2"),
    ],
)
def test_an_explosion_between_bodies_that_meet_at_a_speed_is_refused_at_its_release(
    state: dict[str, str], closing: str
) -> None:
    data = shell()
    data["state"] = state
    with pytest.raises(DerivationError) as caught:
        uncached(load_model(data, SYMBOLS))
    assert caught.value.path == ("impact", "release")
    assert f"they close along the normal at {closing} at the state" in caught.value.message
    assert "write `restitution: 0`" in caught.value.message


def test_bodies_that_do_not_approach_are_refused_by_the_simulation() -> None:
    data = carts()
    data["domain"] = {"ranges": {"e": ["0", "1"]}}  # u1 - u2 not declared positive
    with pytest.raises(DerivationError, match="do not approach"):
        uncached(load_model(data, SYMBOLS))


def test_a_normal_pointing_the_wrong_way_is_named_as_the_likely_cause() -> None:
    """A ball falling onto the floor with the normal from the floor up to the ball (+y): the ball moves
    apart along it, so the refusal says which way the normal points, beside declaring the approach."""
    data = {
        "coordinates": ["y"],
        "bodies": {"ball": {"mass": "m1", "position": {"y": "y"}}},
        "state": {"y": 0, "y_dot": "-u"},
        "impact": {"bodies": ["ball", {"fixed": "floor"}], "normal": {"y": 1}, "restitution": "e"},
        "domain": {"ranges": {"e": ["0", "1"]}},
        "quantities": {"rebound": {"final_velocity": "ball"}},
    }
    with pytest.raises(
        DerivationError, match=r"the normal points from the first body \(ball\) to the second \(floor\)"
    ):
        uncached(load_model(data, SYMBOLS))


def test_a_restitution_above_one_is_refused() -> None:
    with pytest.raises(DerivationError, match=r"lies in \[0, 1\]"):
        uncached(load_model(carts("1 + e"), SYMBOLS))


@pytest.mark.parametrize(
    ("change", "path", "message"),
    [
        (lambda d: d.pop("impact"), ("quantities", "v1", "final_velocity"), "needs an impact section"),
        (lambda d: d["impact"].update(release="Q"), ("impact",), "exactly one of restitution"),
        (lambda d: d["impact"].update(bodies=["cart1", "cart3"]), ("impact", "bodies", 1), "unknown body"),
        (lambda d: d["impact"].update(bodies=["cart1"]), ("impact", "bodies"), "two different bodies"),
        (lambda d: d["quantities"].update(v3={"final_velocity": "wall"}), ("quantities", "v3", "final_velocity"),
         "not 'wall'"),
        (lambda d: d["quantities"].update(k={"kinetic_energy_lost": "cart1"}),
         ("quantities", "k", "kinetic_energy_lost"), "kinetic_energy_lost: impact"),
        (lambda d: d["impact"].update(spin=1), ("impact", "spin"), "unknown key"),
    ],
    ids=["no-impact", "both-kinds", "unknown-body", "one-body", "not-a-body", "energy-target", "unknown-key"],
)  # fmt: skip
def test_a_faulty_impact_is_refused_at_its_path(change: Any, path: tuple[Any, ...], message: str) -> None:
    data = carts()
    change(data)
    with pytest.raises(SpecErrors) as caught:
        load_model(data, SYMBOLS)
    assert any(err.path == path and message in err.message for err in caught.value.errors), (
        caught.value.errors
    )


def test_a_final_velocity_in_the_plane_asks_for_the_speed() -> None:
    data = pucks()
    data["quantities"]["v1"] = {"final_velocity": "puck1"}
    with pytest.raises(SpecErrors, match="final_speed"):
        load_model(data, SYMBOLS)


def test_a_release_that_is_not_an_energy_is_refused() -> None:
    from physics.dimensions import Dimension

    mass, length, time = Dimension({"mass": 1}), Dimension({"length": 1}), Dimension({"time": 1})
    speed = length / time
    dims = {"m1": mass, "m2": mass, "u1": speed, "u2": speed, "Q": mass * speed}  # a momentum
    with pytest.raises(SpecErrors) as caught:
        load_model(shell(), SYMBOLS, dims)
    assert [err.path for err in caught.value.errors] == [("impact", "release")]


def test_the_common_slips_are_known_mistakes_with_feedback_naming_them() -> None:
    result = uncached(load_model(carts(), SYMBOLS))
    mistakes = result.mistakes["v1"]
    # e taken as 0: the common velocity of a perfectly inelastic collision
    assert any(_same(m.expr, TOTAL / M) and "perfectly inelastic" in m.feedback for m in mistakes)
    elastic = (TOTAL - m2 * (u1 - u2)) / M
    assert any(_same(m.expr, elastic) and "elastic collision" in m.feedback for m in mistakes)
    sign = (TOTAL + e * m2 * (u1 - u2)) / M
    assert any(_same(m.expr, sign) and "reverses" in m.feedback for m in mistakes)
