"""A quantity evaluated at another quantity's solved value (`with: {Omega: rate}`): each method puts in
its own value, the simulation measures at the derived value and disagrees with a wrong one, and a
`with` that cannot mean anything is refused saying why."""

from __future__ import annotations

from typing import Any

import pytest
import sympy

from physics.engine import derivation, derive, load_model
from physics.engine.lagrange import LagrangeMethod
from physics.engine.mechanics import Mechanics
from physics.engine.proof import domain_points
from physics.engine.scenarios import quantity_names
from physics.engine.simulation import Simulator
from physics.errors import DerivationError, SpecErrors

SYMBOLS = {n: sympy.Symbol(n, positive=True) for n in ("m", "L", "g", "alpha", "Omega")}
m, L, g, alpha, Omega = SYMBOLS.values()


def cone(**quantities: Any) -> dict[str, Any]:
    """A bob circling on a string at alpha from the vertical, at rest in the frame turning at Omega."""
    return {
        "coordinates": ["phi"],
        "bodies": {"bob": {"mass": "m", "position": {"x": "L*sin(phi)", "y": "-L*cos(phi)"}}},
        "gravity": "g",
        "constraints": {"string": {"kind": "string", "gap": "L - sqrt(x_bob^2 + y_bob^2)"}},
        "elements": {"frame": {"kind": "rotating", "rate": "Omega", "bodies": ["bob"]}},
        "state": {"phi": "alpha"},
        "domain": {"ranges": {"alpha": ["0", "pi/2"]}},
        "quantities": {"rate": {"solve": "Omega", "zero": {"acceleration": "phi"}}, **quantities},
    }


AT_RATE = {"tension": {"force": "string", "with": {"Omega": "rate"}}}


def test_the_tension_at_the_solved_rate_is_derived_by_several_methods_and_simulated() -> None:
    derived = derive(load_model(cone(**AT_RATE), SYMBOLS))
    assert sympy.simplify(derived.quantities["tension"] - m * g / sympy.cos(alpha)) == 0
    assert len(derived.agreement["tension"]) >= 2
    assert derived.simulation["tension"].points > 0


def test_the_simulation_disagrees_when_the_rate_it_is_taken_at_is_wrong() -> None:
    model = load_model(cone(**AT_RATE), SYMBOLS)
    simulator = Simulator(model, LagrangeMethod(model, Mechanics(model)).equilibrium)
    wrong_rate = sympy.sqrt(g * sympy.tan(alpha) / L)  # the radius taken as L
    with pytest.raises(DerivationError, match="tension: the simulation disagrees"):
        derivation._simulate(model, {"rate": wrong_rate, "tension": m * g / sympy.cos(alpha)}, simulator)
    assert domain_points(model, 1)  # the points the simulation used are the model's


def test_asking_for_the_tension_asks_for_the_rate_it_is_taken_at() -> None:
    assert quantity_names(load_model(cone(**AT_RATE), SYMBOLS))["tension"] == ("rate",)


@pytest.mark.parametrize(
    ("given", "said"),
    [
        ({"tension": {"force": "string", "with": {"Theta": "rate"}}}, "unknown symbol 'Theta'"),
        ({"tension": {"force": "string", "with": {"Omega": "tension"}}}, "expected another quantity"),
        ({"tension": {"force": "string", "with": {"Omega": "rte"}}}, "not 'rte'"),
        (
            {"t2": {"expression": "2*rate", "with": {"Omega": "rate"}}},
            "unknown key 'with'",
        ),  # it names them in its formula
        (
            {
                "a": {"force": "string", "with": {"Omega": "b"}},
                "b": {"force": "string", "with": {"Omega": "a"}},
            },
            "in a circle",
        ),
    ],
)
def test_a_with_that_names_nothing_it_can_use_is_refused(given: dict[str, Any], said: str) -> None:
    with pytest.raises(SpecErrors) as caught:
        load_model(cone(**given), SYMBOLS)
    assert said in str(caught.value)


def test_a_with_on_a_symbol_the_other_quantity_does_not_solve_for_is_refused() -> None:
    model = load_model(cone(tension={"force": "string", "with": {"m": "rate"}}), SYMBOLS)
    with pytest.raises(DerivationError, match="rate is the value of Omega, not of m"):
        derive(model)
