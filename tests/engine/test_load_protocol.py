"""The methods consume loads through their protocol alone (physics/engine/loads/): load classes written
here, known to no module of the engine, are derived by every method that applies and simulated."""

from __future__ import annotations

import dataclasses
from collections.abc import Mapping
from typing import Any

import sympy

from physics.dimensions import Dimension
from physics.engine import derivation, load_model
from physics.engine.loads import Traits, View, nothing, on_body
from physics.engine.mechanics import Mechanics
from physics.engine.model import Model
from physics.engine.text import Path

uncached = derivation._derive.__wrapped__
NAMES = ("m", "k", "b", "E", "A")
SYMBOLS = {name: sympy.Symbol(name, positive=True) for name in NAMES}
m, k, b, E, A = (SYMBOLS[n] for n in NAMES)


@dataclasses.dataclass(frozen=True)
class Field:
    """A uniform force `strength` along x on one body (a charge in an electric field): potential -F x."""

    body: str
    strength: sympy.Expr

    def traits(self, model: Model) -> Traits:
        return Traits(conservative=True, bodies=(self.body,))

    def potential(self, mech: Mechanics, place: Mapping[str, sympy.Expr]) -> sympy.Expr:
        return -self.strength * place[f"x_{self.body}"]

    def force(self, mech: Mechanics, view: View) -> list[sympy.Expr]:
        return nothing(mech)

    def expressions(self) -> tuple[sympy.Expr, ...]:
        return (self.strength,)

    def dimensions(self, path: Path) -> list[tuple[Path, sympy.Expr, Dimension]]:
        return []


@dataclasses.dataclass(frozen=True)
class Dashpot:
    """-b x' on one body along x, from whichever velocity the method reads."""

    body: str
    coefficient: sympy.Expr

    def traits(self, model: Model) -> Traits:
        return Traits(conservative=False, bodies=(self.body,), dissipates=True, viscous=True)

    def potential(self, mech: Mechanics, place: Mapping[str, sympy.Expr]) -> sympy.Expr:
        return sympy.Integer(0)

    def force(self, mech: Mechanics, view: View) -> list[sympy.Expr]:
        (dof,) = (d for d in mech.dofs if d.name == f"x_{self.body}")
        velocity = dof.velocity if view.cartesian else mech.velocity_of(dof)
        return on_body(mech, self.body, {"x": -self.coefficient * velocity})

    def expressions(self) -> tuple[sympy.Expr, ...]:
        return (self.coefficient,)

    def dimensions(self, path: Path) -> list[tuple[Path, sympy.Expr, Dimension]]:
        return []


def spring(quantities: dict[str, Any], loads: tuple[Any, ...]) -> Model:
    data = {
        "coordinates": ["x"],
        "bodies": {"block": {"mass": "m", "position": {"x": "x"}}},
        "elements": {"spring": {"kind": "spring", "between": [{"x": 0}, "block"], "stiffness": "k"}},
        "state": {"x": "A"},
        "quantities": quantities,
    }
    return dataclasses.replace(load_model(data, SYMBOLS), force_entries=loads)


def test_a_conservative_load_of_its_own_kind_moves_the_equilibrium_by_every_method() -> None:
    model = spring({"x0": {"equilibrium": "x"}, "a": {"acceleration": "x"}}, (Field("block", E),))
    result = uncached(model)
    assert sympy.simplify(result.quantities["x0"] - E / k) == 0
    assert sympy.simplify(result.quantities["a"] - (E - k * A) / m) == 0
    assert {"lagrange", "newton", "conservation", "dalembert"} <= set(result.agreement["a"])
    assert result.simulation["a"].max_relative_error < 1e-3


def test_a_viscous_load_of_its_own_kind_damps_the_oscillation_by_every_method() -> None:
    model = spring(
        {"ringing": {"damped_frequency": "x"}, "fading": {"decay_time": "x"}}, (Dashpot("block", b),)
    )
    model = dataclasses.replace(model, positive=(4 * k * m - b**2,))
    result = uncached(model)
    assert sympy.simplify(result.quantities["ringing"] - sympy.sqrt(k / m - b**2 / (4 * m**2))) == 0
    assert sympy.simplify(result.quantities["fading"] - 2 * m / b) == 0
    assert {"lagrange", "newton", "conservation"} <= set(result.agreement["ringing"])
    assert result.simulation["ringing"].max_relative_error < 1e-3
