"""Several degrees of freedom oscillating: every normal-mode frequency, ordered, each askable."""

from __future__ import annotations

import time
from typing import Any

import pytest
import sympy
import yaml

from physics.engine import derivation, load_model
from physics.engine.results import Derivation
from physics.engine.simulation import Simulator
from physics.errors import DerivationError, SpecErrors

uncached = derivation._derive.__wrapped__
SYMBOLS = {name: sympy.Symbol(name, positive=True) for name in ("m", "k", "g", "L")}
m, k, g, L = SYMBOLS.values()


def three_springs() -> dict[str, Any]:
    """Two equal masses between two walls, joined by three equal springs; x1, x2 from rest."""
    return {
        "coordinates": ["x1", "x2"],
        "bodies": {"a": {"mass": "m", "position": {"x": "x1"}}, "b": {"mass": "m", "position": {"x": "x2"}}},
        "potentials": [
            {"bodies": ["a"], "anchor": {"x": 0}, "distance": "d", "energy": "k*d^2/2"},
            {"bodies": ["a", "b"], "distance": "d", "energy": "k*d^2/2"},
            {"bodies": ["b"], "anchor": {"x": 0}, "distance": "d", "energy": "k*d^2/2"},
        ],
        "quantities": {"slow": {"normal_frequency": 1}, "fast": {"normal_frequency": 2}},
    }


def double_pendulum() -> dict[str, Any]:
    return {
        "coordinates": ["p1", "p2"],
        "bodies": {
            "upper": {"mass": "m", "position": {"x": "L*sin(p1)", "y": "-L*cos(p1)"}},
            "lower": {"mass": "m", "position": {"x": "L*sin(p1) + L*sin(p2)", "y": "-L*cos(p1) - L*cos(p2)"}},
        },
        "gravity": "g",
        "constraints": {
            "rod1": {"kind": "string", "gap": "L - sqrt(x_upper^2 + y_upper^2)"},
            "rod2": {"kind": "string", "gap": "L - sqrt((x_lower - x_upper)^2 + (y_lower - y_upper)^2)"},
        },
        "domain": {"ranges": {"p1": ["-pi/2", "pi/2"], "p2": ["-pi/2", "pi/2"]}},
        "quantities": {"slow": {"normal_frequency": 1}, "fast": {"normal_frequency": 2}},
    }


def test_two_masses_and_three_springs_have_both_modes_in_order() -> None:
    result = uncached(load_model(three_springs(), SYMBOLS))
    assert sympy.simplify(result.quantities["slow"] - sympy.sqrt(k / m)) == 0
    assert sympy.simplify(result.quantities["fast"] - sympy.sqrt(3 * k / m)) == 0
    assert set(result.agreement["fast"]) == {"lagrange", "newton", "conservation"}
    assert result.simulation["fast"].max_relative_error < 1e-3


@pytest.mark.slow
def test_double_pendulum_small_oscillations() -> None:
    started = time.process_time()
    result = uncached(load_model(double_pendulum(), SYMBOLS))
    spent = time.process_time() - started
    for name, sign in (("slow", -1), ("fast", 1)):
        expected = sympy.sqrt((2 + sign * sympy.sqrt(2)) * g / L)
        assert abs(float((result.quantities[name] - expected).subs({g: 9.8, L: 1.3}))) < 1e-9
        assert len(result.agreement[name]) >= 2
        assert result.simulation[name].max_relative_error < 1e-3
    print(f"double pendulum derived in {spent:.1f} s CPU")


def test_a_mode_number_beyond_the_coordinates_is_a_spec_error() -> None:
    data = three_springs()
    data["quantities"]["third"] = {"normal_frequency": 3}
    with pytest.raises(SpecErrors) as caught:
        load_model(data, SYMBOLS)
    assert caught.value.errors[0].path == ("quantities", "third", "normal_frequency")


# bodies on a frictionless track in absolute coordinates: at rest wherever the springs have their natural
# lengths, the whole system anywhere on the track (a free translation, its zero-frequency mode)
CARTS = """
coordinates: [x1, x2]
bodies:
  a: {mass: m1, position: {x: X1}}
  b: {mass: m2, position: {x: x2}}
elements:
  spring: {kind: spring, between: [a, b], stiffness: k, length: L0}
domain:
  ranges: {x1: ["-oo", "0"], x2: ["0", "oo"]}
quantities:
  stretch: {normal_frequency: 1}
  shape: {mode_shape: {mode: 1, ratio: [x2, x1]}}
"""
CO2 = """
coordinates: [x1, x2, x3]
bodies:
  o1: {mass: m, position: {x: x1}}
  c: {mass: M, position: {x: x2}}
  o2: {mass: m, position: {x: x3}}
potentials:
  - {bodies: [o1, c], distance: d, energy: "k*(d - L0)^2/2"}
  - {bodies: [c, o2], distance: d, energy: "RIGHT*(d - L0)^2/2"}
domain:
  ranges: {x1: ["-oo", "0"], x2: ["0", "L0"], x3: ["L0", "oo"]}
quantities:
  symmetric: {normal_frequency: 1}
  asymmetric: {normal_frequency: 2}
"""
PUCK_ON_A_RING = """
coordinates: [x, y]
bodies:
  puck: {mass: m, position: {x: x, y: y}}
elements:
  spring: {kind: spring, between: [puck, {x: 0, y: 0}], stiffness: k, length: L0}
quantities:
  w: {normal_frequency: 1}
"""
_m1, _m2, _M, _k, _L0 = sympy.symbols("m1 m2 M k L0", positive=True)


def _translating(text: str, names: str) -> Derivation:
    symbols = {name: sympy.Symbol(name, positive=True) for name in names.split()}
    return uncached(load_model(yaml.safe_load(text), symbols))


@pytest.mark.parametrize(
    ("text", "names", "expected"),
    [
        pytest.param(
            CARTS.replace("X1", "x1"),
            "m1 m2 k L0",
            {"stretch": sympy.sqrt(_k * (_m1 + _m2) / (_m1 * _m2)), "shape": -_m1 / _m2},
            id="carts",
        ),
        pytest.param(  # the reduction to the separation d: x1 is cyclic, d has one rest
            CARTS.replace("X1", "x1")
            .replace("[x1, x2]", "[x1, d]")
            .replace("{x: x2}", '{x: "x1 + d"}')
            .replace('x1: ["-oo", "0"], x2', "d")
            .replace("[x2, x1]", "[d, x1]"),
            "m1 m2 k L0",
            {"stretch": sympy.sqrt(_k * (_m1 + _m2) / (_m1 * _m2)), "shape": -(_m1 + _m2) / _m2},
            id="carts-by-their-separation",
        ),
        pytest.param(
            CO2.replace("RIGHT", "k"),
            "m M k L0",
            {"symmetric": sympy.sqrt(_k / m), "asymmetric": sympy.sqrt(_k / m * (1 + 2 * m / _M))},
            id="co2",
        ),
    ],
)
def test_a_free_translation_leaves_the_oscillating_modes_about_any_of_its_rests(
    text: str, names: str, expected: dict[str, sympy.Expr]
) -> None:
    """The rests form a continuum, but the modes are the same about each: its zero frequency is the drift
    along the track, left out, so mode 1 is the lowest oscillation (CO2's symmetric stretch)."""
    result = _translating(text, names)
    for name, value in expected.items():
        assert sympy.simplify(result.quantities[name] - value) == 0, name
        assert len(result.agreement[name]) >= 2
        assert result.simulation[name].max_relative_error < 1e-6
    worked = [
        step.title for report in result.methods for step in report.steps if "Normal modes" in step.title
    ]
    assert worked and all("the root $\\omega = 0$, a free drift" in title for title in worked)


@pytest.mark.parametrize(
    ("text", "names", "said"),
    [
        pytest.param(
            CO2.replace("RIGHT", "-k"),
            "m M k L0",
            "x3 taking any value, but unstably: the potential's Hessian has a negative eigenvalue",
            id="co2-spring-typed-negative",
        ),
        pytest.param(
            CARTS.replace("X1", '"x1^3"'),
            "m1 m2 k L0",
            "a continuum of equilibria, with no one point to oscillate about: the mass or stiffness matrix "
            "changes with x2 along it",
            id="continuum-that-is-no-translation",
        ),
        pytest.param(
            "coordinates: [x]\nbodies:\n  bead: {mass: m, position: {x: x}}\ngravity: g\n"
            "quantities:\n  w: {normal_frequency: 1}\n",
            "m g",
            "mode 1 asked for, but the system has no oscillating mode",
            id="bead-alone-on-a-rod",
        ),
        pytest.param(  # sympy's isolated root {x: 0, y: L0} lies on the ring: no rest of its own
            PUCK_ON_A_RING,
            "m k L0",
            "a continuum of equilibria, with no one point to oscillate about: the mass or stiffness matrix "
            "changes with y along it, so it is no free translation whose small oscillations are the same "
            "everywhere; the potential depends on x and y only through sqrt(x^2 + y^2), so the rests are a ring",
            id="puck-on-a-spring-free-in-x-and-y",
        ),
    ],
)
def test_a_continuum_of_rests_with_no_stable_translation_is_refused(text: str, names: str, said: str) -> None:
    with pytest.raises(DerivationError) as caught:
        _translating(text, names)
    assert said in caught.value.message


@pytest.mark.parametrize(
    ("text", "names", "path", "said"),
    [
        pytest.param(
            CO2.replace("RIGHT", "k").replace(
                "asymmetric: {normal_frequency: 2}", "third: {normal_frequency: 3}"
            ),
            "m M k L0",
            ("quantities", "third", "normal_frequency"),
            "mode 3 asked for, but the system has 2 oscillating modes: ask for 1 (the lowest) to 2",
            id="co2-third-mode",
        ),
        pytest.param(
            CARTS.replace("X1", "x1").replace("{mode: 1,", "{mode: 2,"),
            "m1 m2 k L0",
            ("quantities", "shape", "mode_shape", "mode"),
            "mode 2 asked for, but the system has 1 oscillating mode: ask for 1 (the lowest)",
            id="carts-second-shape",
        ),
    ],
)
def test_a_mode_number_beyond_the_oscillating_modes_is_refused_at_its_path_with_their_count(
    text: str, names: str, path: tuple[str, ...], said: str
) -> None:
    """The loader allows a number up to the coordinates' count; a free drift's zero frequency is no
    oscillating mode, known only once derived."""
    with pytest.raises(DerivationError) as caught:
        _translating(text, names)
    assert caught.value.path == path
    assert said in caught.value.message


@pytest.mark.parametrize("error", [OverflowError, ZeroDivisionError, FloatingPointError])
@pytest.mark.parametrize(
    ("step", "said"),
    [("check", "slow: the simulation failed"), ("energy_balance", "energy balance: the simulation failed")],
)
def test_a_numeric_error_in_the_simulation_is_a_refusal_that_names_what_was_simulated(
    monkeypatch: pytest.MonkeyPatch, error: type[ArithmeticError], step: str, said: str
) -> None:
    def failing(*args: object) -> None:
        raise error("out of range")

    monkeypatch.setattr(Simulator, step, failing)
    with pytest.raises(DerivationError) as caught:
        uncached(load_model(three_springs(), SYMBOLS))
    assert f"{said}: {error.__name__}: out of range" in caught.value.message
