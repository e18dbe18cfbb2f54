"""The n-th bounce off a fixed floor: each method works one cycle (the flight back, the impact) and raises
it to the n-th power; the simulation bounces the ball n times and disagrees with a wrong count; bounces
that cannot repeat are refused saying why."""

from __future__ import annotations

from typing import Any

import pytest
import sympy

from physics.engine import derivation, derive, load_model
from physics.engine.lagrange import LagrangeMethod
from physics.engine.mechanics import Mechanics
from physics.engine.simulation import Simulator
from physics.errors import DerivationError, SpecErrors

SYMBOLS = {n: sympy.Symbol(n, positive=True) for n in ("m", "g", "h", "e", "n", "u")}
m, g, h, e, n, u = SYMBOLS.values()


def ball(gravity: Any = "g", **quantities: Any) -> dict[str, Any]:
    """Dropped from h onto a fixed floor: it arrives at the speed of that fall."""
    return {
        "coordinates": ["y"],
        "bodies": {"ball": {"mass": "m", "position": {"y": "y"}}},
        **({"gravity": gravity} if gravity else {}),
        "state": {"y": 0, "y_dot": "-sqrt(2*g*h)"},
        "impact": {"bodies": ["ball", {"fixed": "floor"}], "normal": {"y": -1}, "restitution": "e"},
        "domain": {"ranges": {"e": ["0", "1"]}},
        "quantities": quantities,
    }


AFTER_N = {
    "height": {"max_height": "ball", "after": "impact", "bounces": "n"},
    "between": {"time_of_flight": "ball", "after": "impact", "bounces": "n"},
}


def test_the_height_after_the_nth_bounce_and_the_time_to_the_next() -> None:
    derived = derive(load_model(ball(**AFTER_N), SYMBOLS))
    assert sympy.simplify(derived.quantities["height"] - e ** (2 * n) * h) == 0
    assert sympy.simplify(derived.quantities["between"] - 2 * e**n * sympy.sqrt(2 * h / g)) == 0
    for name in AFTER_N:
        assert set(derived.agreement[name]) == {"newton", "conservation"}
        assert "integrated bounces" in derived.simulation[name].compared


def test_a_ball_bouncing_along_the_floor_keeps_its_horizontal_velocity_between_bounces() -> None:
    data = ball(hop={"range": "ball", "after": "impact", "bounces": "n"})
    data["coordinates"] = ["x", "y"]
    data["bodies"]["ball"]["position"] = {"x": "x", "y": "y"}
    data["state"] = {"x": 0, "y": 0, "x_dot": "u", "y_dot": "-sqrt(2*g*h)"}
    derived = derive(load_model(data, SYMBOLS))
    assert sympy.simplify(derived.quantities["hop"] - 2 * e**n * u * sympy.sqrt(2 * h / g)) == 0
    assert set(derived.agreement["hop"]) == {"newton", "conservation"}


def test_the_velocity_just_after_the_nth_bounce_is_derived_and_measured_after_n_bounces() -> None:
    derived = derive(load_model(ball(nth={"final_velocity": "ball", "bounces": "n"}), SYMBOLS))
    assert sympy.simplify(derived.quantities["nth"] - e**n * sympy.sqrt(2 * g * h)) == 0
    assert "integrated bounces" in derived.simulation["nth"].compared


# the kinetic energy the n-th bounce takes: the ball arrives with e^(2(n-1)) of the fall's m g h
ENERGY_LOST_IN_BOUNCE = [
    ("n", e ** (2 * n - 2) * m * g * h * (1 - e**2)),
    (1, m * g * h * (1 - e**2)),
    (3, e**4 * m * g * h * (1 - e**2)),
]


@pytest.mark.parametrize(("count", "expected"), ENERGY_LOST_IN_BOUNCE)
def test_the_energy_lost_in_the_nth_bounce_is_derived_and_measured_in_that_bounce(
    count: Any, expected: sympy.Expr
) -> None:
    derived = derive(load_model(ball(lost={"kinetic_energy_lost": "impact", "bounces": count}), SYMBOLS))
    assert sympy.simplify(derived.quantities["lost"] - expected) == 0
    assert "kinetic energy lost in bounce" in derived.simulation["lost"].compared


def test_the_simulation_disagrees_with_the_energy_lost_in_all_n_bounces() -> None:
    model = load_model(ball(lost={"kinetic_energy_lost": "impact", "bounces": "n"}), SYMBOLS)
    simulator = Simulator(model, LagrangeMethod(model, Mechanics(model)).equilibrium)
    with pytest.raises(DerivationError, match="lost: the simulation disagrees"):
        derivation._simulate(model, {"lost": m * g * h * (1 - e ** (2 * n))}, simulator)


# the kinetic energy the first n bounces take together: m g h arrives, e^(2n) of it leaves the n-th
ENERGY_LOST_IN_THE_FIRST_BOUNCES = [
    ("n", m * g * h * (1 - e ** (2 * n))),
    (3, m * g * h * (1 - e**6)),
]


def _lost_in_all(count: Any) -> dict[str, Any]:
    return ball(lost={"kinetic_energy_lost": "impact", "bounces": count, "total": True})


@pytest.mark.parametrize(("count", "expected"), ENERGY_LOST_IN_THE_FIRST_BOUNCES)
def test_the_energy_lost_in_the_first_n_bounces_together_is_derived_and_measured_over_them(
    count: Any, expected: sympy.Expr
) -> None:
    derived = derive(load_model(_lost_in_all(count), SYMBOLS))
    assert sympy.simplify(derived.quantities["lost"] - expected) == 0
    assert set(derived.agreement["lost"]) == {"newton", "conservation"}
    assert "kinetic energy lost in the first" in derived.simulation["lost"].compared


def test_the_simulation_disagrees_with_the_nth_bounce_alone_for_the_first_n_together() -> None:
    model = load_model(_lost_in_all("n"), SYMBOLS)
    simulator = Simulator(model, LagrangeMethod(model, Mechanics(model)).equilibrium)
    with pytest.raises(DerivationError, match="lost: the simulation disagrees"):
        derivation._simulate(model, {"lost": e ** (2 * n - 2) * m * g * h * (1 - e**2)}, simulator)


def test_the_nth_bounce_alone_is_a_known_mistake_for_the_first_n_together() -> None:
    mistakes = derive(load_model(_lost_in_all("n"), SYMBOLS)).mistakes["lost"]
    alone = e ** (2 * n - 2) * m * g * h * (1 - e**2)
    [feedback] = [k.feedback for k in mistakes if sympy.simplify(k.expr - alone) == 0]
    assert "the last of those bounces takes alone" in feedback


@pytest.mark.parametrize(
    "spec",
    [
        pytest.param({"kinetic_energy_lost": "impact", "total": True}, id="without-a-count"),
        pytest.param({"kinetic_energy_lost": "impact", "bounces": "n", "total": "all"}, id="not-true"),
    ],
)
def test_a_total_that_is_not_over_a_count_of_bounces_is_refused_at_its_path(spec: dict[str, Any]) -> None:
    with pytest.raises(SpecErrors) as caught:
        load_model(ball(lost=spec), SYMBOLS)
    found = {error.path: error.message for error in caught.value.errors}
    assert "`total: true` with `bounces: n`" in found[("quantities", "lost", "total")]


def test_a_number_of_bounces_may_be_a_number() -> None:
    derived = derive(load_model(ball(third={"max_height": "ball", "after": "impact", "bounces": 3}), SYMBOLS))
    assert sympy.simplify(derived.quantities["third"] - e**6 * h) == 0


@pytest.mark.parametrize("wrong", [e**n * h, e ** (2 * n - 2) * h])
def test_the_simulation_bounces_n_times_and_disagrees_with_a_wrong_height(wrong: sympy.Expr) -> None:
    model = load_model(ball(height=AFTER_N["height"]), SYMBOLS)
    simulator = Simulator(model, LagrangeMethod(model, Mechanics(model)).equilibrium)
    with pytest.raises(DerivationError, match="height: the simulation disagrees"):
        derivation._simulate(model, {"height": wrong}, simulator)


def test_bounces_off_a_body_that_moves_on_are_refused() -> None:
    data = {
        "coordinates": ["x1", "x2"],
        "bodies": {
            "cart1": {"mass": "m", "position": {"x": "x1"}},
            "cart2": {"mass": "m", "position": {"x": "x2"}},
        },
        "state": {"x1": 0, "x2": 0, "x1_dot": "u"},
        "impact": {"bodies": ["cart1", "cart2"], "restitution": "e"},
        "quantities": {"v": {"velocity": "x1", "at": {"x1": "-1"}, "after": "impact", "bounces": 2}},
    }
    with pytest.raises(SpecErrors, match="only off a fixed partner"):
        load_model(data, SYMBOLS)


def test_a_count_below_one_is_refused() -> None:
    with pytest.raises(SpecErrors, match="a whole number, 1 or more"):
        load_model(ball(height={"max_height": "ball", "after": "impact", "bounces": 0}), SYMBOLS)


def test_a_ball_gravity_carries_away_from_a_ceiling_is_refused_as_bouncing_once() -> None:
    data = ball(height=AFTER_N["height"])
    data["state"] = {"y": 0, "y_dot": "u"}  # thrown up against a ceiling: it falls away for good
    data["impact"]["normal"] = {"y": 1}
    with pytest.raises(DerivationError, match="nothing brings the body back to the contact"):
        derive(load_model(data, SYMBOLS))


def test_no_known_mistake_of_the_nth_bounce_raises_zero_to_a_symbolic_power() -> None:
    """e = 0 in e^(2n - 2) is no student's slip (there is no second bounce) and would show as 0**(2n - 2)."""
    mistakes = derive(load_model(ball(lost={"kinetic_energy_lost": "impact", "bounces": "n"}), SYMBOLS))
    for known in mistakes.mistakes["lost"]:
        assert not any(p.base == 0 for p in known.expr.atoms(sympy.Pow)), known.expr
