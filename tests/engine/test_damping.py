"""Damped oscillations: the damped angular frequency and the decay time about the stable equilibrium,
each derived by at least two methods, measured on the integrated motion, refused when not underdamped."""

from __future__ import annotations

import re
from typing import Any

import pytest
import sympy

from physics.engine import derivation, load_model
from physics.engine.results import StepKind
from physics.errors import DerivationError

uncached = derivation._derive.__wrapped__
SYMBOLS = {name: sympy.Symbol(name, positive=True) for name in ("m", "k", "b", "c", "g", "L")}
m, k, b, c, g, L = SYMBOLS.values()


def damped_spring(domain: dict[str, Any] | None = None) -> dict[str, Any]:
    """A block on a horizontal spring with a dashpot b."""
    return {
        "coordinates": ["x"],
        "bodies": {"block": {"mass": "m", "position": {"x": "x"}}},
        "elements": {"spring": {"kind": "spring", "between": [{"x": 0}, "block"], "stiffness": "k"}},
        "forces": [{"body": "block", "drag": "b"}],
        "domain": {"positive": ["4*k*m - b^2"]} if domain is None else domain,
        "quantities": {"omega_d": {"damped_frequency": "x"}, "tau": {"decay_time": "x"}},
    }


def damped_pendulum() -> dict[str, Any]:
    """A simple pendulum whose bob feels linear drag b: constrained, so Newton's Cartesian route stops."""
    return {
        "coordinates": ["theta"],
        "bodies": {"bob": {"mass": "m", "position": {"x": "L*sin(theta)", "y": "-L*cos(theta)"}}},
        "gravity": "g",
        "constraints": {"rod": {"kind": "string", "gap": "L - sqrt(x_bob^2 + y_bob^2)"}},
        "forces": [{"body": "bob", "drag": "b"}],
        "domain": {"ranges": {"theta": ["-pi/2", "pi/2"]}, "positive": ["4*g*m^2 - b^2*L"]},
        "quantities": {"omega_d": {"damped_frequency": "theta"}, "tau": {"decay_time": "theta"}},
    }


def test_a_damped_spring_is_derived_by_three_methods_and_measured_on_its_motion() -> None:
    result = uncached(load_model(damped_spring(), SYMBOLS))
    assert sympy.simplify(result.quantities["omega_d"] - sympy.sqrt(k / m - b**2 / (4 * m**2))) == 0
    assert sympy.simplify(result.quantities["tau"] - 2 * m / b) == 0
    for name in ("omega_d", "tau"):
        assert {"lagrange", "newton", "conservation"} <= set(result.agreement[name])
        assert result.simulation[name].max_relative_error < 1e-3
    assert "zero crossings" in result.simulation["omega_d"].compared
    assert "limit omega_d (no damping)" in result.checks
    slips = {sympy.simplify(mistake.expr) for mistake in result.mistakes["omega_d"]}
    assert sympy.sqrt(k) / sympy.sqrt(m) in slips  # the undamped frequency
    assert {sympy.simplify(mistake.expr) for mistake in result.mistakes["tau"]} == {m / b, b / (2 * m)}
    assert [dict(case.substitutions) for case in result.limits["omega_d"]] == [{b: 0}]


@pytest.mark.slow
def test_a_damped_pendulum_is_derived_by_lagrange_and_the_energy_balance() -> None:
    result = uncached(load_model(damped_pendulum(), SYMBOLS))
    expected = sympy.sqrt(g / L - b**2 / (4 * m**2))
    assert abs(float((result.quantities["omega_d"] - expected).subs({g: 9.8, L: 1.2, b: 0.3, m: 2}))) < 1e-12
    assert {"lagrange", "conservation"} <= set(result.agreement["tau"])
    assert result.simulation["tau"].max_relative_error < 1e-3


@pytest.mark.parametrize(
    ("change", "message"),
    [
        pytest.param(
            {"domain": {}},
            "the motion is not underdamped on the whole domain",
            id="underdamping-not-declared",
        ),
        pytest.param(
            {"forces": [{"body": "block", "quadratic_drag": "c"}]},
            "not linear in the velocity",
            id="quadratic",
        ),
        pytest.param({"forces": []}, "no viscous damping", id="no-drag"),
    ],
)
def test_a_damped_frequency_the_model_cannot_have_is_refused_with_the_reason(
    change: dict[str, Any], message: str
) -> None:
    data = {**damped_spring(), **change}
    with pytest.raises(DerivationError) as caught:
        uncached(load_model(data, SYMBOLS))
    assert message in str(caught.value)


@pytest.mark.parametrize(
    ("change", "reason"),
    [
        pytest.param(
            {"domain": {}}, "the motion is not underdamped on the whole domain", id="maybe-overdamped"
        ),
        pytest.param(
            {"forces": [{"body": "block", "quadratic_drag": "c"}]},
            "quadratic drag is not linear",
            id="quadratic",
        ),
    ],
)
def test_a_refusal_says_each_reason_once_naming_the_methods_that_gave_it(
    change: dict[str, Any], reason: str
) -> None:
    data = {**damped_spring(), **change, "quantities": {"omega_d": {"damped_frequency": "x"}}}
    with pytest.raises(DerivationError) as caught:
        uncached(load_model(data, SYMBOLS))
    ((path, message),) = caught.value.findings
    assert path == ("quantities", "omega_d")
    assert message.count(reason) == 1
    said = re.search(r"(\w+(?:, \w+)*(?: and \w+)?) stopped: " + re.escape(reason), message)
    assert said is not None, message
    assert {"lagrange", "newton", "conservation"} <= set(re.split(r", | and ", said.group(1)))
    assert "omega_d: omega_d" not in message and "stopped: omega_d:" not in message


@pytest.mark.slow
@pytest.mark.parametrize(
    ("model", "coordinate", "undamped"),
    [(damped_spring(), "x", sympy.sqrt(k / m)), (damped_pendulum(), "theta", sympy.sqrt(g / L))],
    ids=["spring", "pendulum"],
)
def test_the_undamped_frequency_of_a_damped_model_leaves_the_drag_out(
    model: dict[str, Any], coordinate: str, undamped: sympy.Expr
) -> None:
    model["quantities"] = {
        "omega_0": {"undamped_frequency": coordinate},
        "omega_d": {"damped_frequency": coordinate},
    }
    result = uncached(load_model(model, SYMBOLS))
    assert sympy.simplify(result.quantities["omega_0"] - undamped) == 0
    assert len(result.agreement["omega_0"]) >= 2
    # measured on the damped motion itself: omega_0^2 = omega_d^2 + 1/tau^2
    assert "decay time" in result.simulation["omega_0"].compared
    assert result.simulation["omega_0"].max_relative_error < 1e-3
    assert sympy.simplify(result.quantities["omega_0"] - result.quantities["omega_d"]) != 0


def test_the_undamped_frequencys_steps_keep_the_drag_free_solves_kinds_and_symbols() -> None:
    """Copied whole, not title and formula alone: its solves keep their kind (and unknowns), and the notation
    check sees its symbols."""
    model = damped_spring()
    model["quantities"] = {"omega_0": {"undamped_frequency": "x"}}
    result = uncached(load_model(model, SYMBOLS))
    for report in result.methods:
        copied = [step for step in report.steps if step.title.endswith("(the damping left out)")]
        assert any(step.kind is StepKind.SOLVE and step.unknowns for step in copied), report.name
        assert all(step.symbols for step in copied), report.name


def test_the_undamped_frequency_of_a_model_without_drag_is_refused_naming_angular_frequency() -> None:
    model = damped_spring()
    model["forces"] = []
    model["quantities"] = {"omega_0": {"undamped_frequency": "x"}}
    with pytest.raises(DerivationError, match="no drag to leave out: ask for its angular_frequency"):
        uncached(load_model(model, SYMBOLS))
