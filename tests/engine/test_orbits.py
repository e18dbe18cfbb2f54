"""Central forces in polar coordinates: steady circular motion (speed, period, energy), the effective
potential's circular orbit and its epicyclic frequency, the energy of a state; each by every method,
simulated, and a wrong model refused with the reason."""

from __future__ import annotations

from typing import Any

import pytest
import sympy

from physics.engine import derivation, load_model
from physics.errors import DerivationError, SpecErrors

uncached = derivation._derive.__wrapped__
NAMES = ("G", "M", "m", "R", "h", "k", "l", "r")
SYMBOLS = {name: sympy.Symbol(name, positive=True) for name in NAMES}
G, M, m, R, h, k, ell, r = (SYMBOLS[n] for n in NAMES)


def polar(energy: str, state: dict[str, str], quantities: dict[str, Any]) -> dict[str, Any]:
    """A body at distance r and angle theta from a fixed centre, with the potential energy U(d)."""
    return {
        "coordinates": ["r", "theta"],
        "bodies": {"body": {"mass": "m", "position": {"x": "r*cos(theta)", "y": "r*sin(theta)"}}},
        "potentials": [{"bodies": ["body"], "anchor": {"x": 0, "y": 0}, "distance": "d", "energy": energy}],
        "state": state,
        "quantities": quantities,
    }


@pytest.mark.slow
def test_a_satellite_orbit_speed_period_and_energy_by_every_method_and_simulated() -> None:
    model = load_model(
        polar(
            "-G*M*m/d",
            {"r": "R + h"},
            {
                "v": {"circular_speed": "theta"},
                "T": {"revolution_period": "theta"},
                "E": {"circular_energy": "theta"},
            },
        ),
        SYMBOLS,
    )
    result = uncached(model)
    expected = {
        "v": sympy.sqrt(G * M / (R + h)),
        "T": 2 * sympy.pi * sympy.sqrt((R + h) ** 3 / (G * M)),
        "E": -G * M * m / (2 * (R + h)),
    }
    for name, value in expected.items():
        assert sympy.simplify(result.quantities[name] - value) == 0, name
        assert set(result.agreement[name]) >= {"lagrange", "newton", "conservation"}, name
        assert result.simulation[name].max_relative_error < 1e-3, name
    assert "time of one revolution" in result.simulation["T"].compared
    slips = {m.feedback: m.expr for m in result.mistakes["T"] + result.mistakes["E"]}
    assert any("2π" in feedback for feedback in slips)
    assert any("kinetic energy only" in feedback for feedback in slips)


def test_a_harmonic_centre_has_its_epicyclic_frequency_twice_the_orbital_one() -> None:
    """U = k r^2 / 2 with angular momentum l: r0^4 = l^2/(m k), and radial oscillations at 2 sqrt(k/m)."""
    model = load_model(
        polar(
            "k*d^2/2",
            {"theta_dot": "l/(m*r^2)"},
            {
                "radius": {"circular_radius": "r"},
                "epicyclic": {"epicyclic_frequency": "r"},
                "energy": {"mechanical_energy": "state"},
            },
        ),
        SYMBOLS,
    )
    result = uncached(model)
    assert sympy.simplify(result.quantities["radius"] - (ell**2 / (m * k)) ** sympy.Rational(1, 4)) == 0
    assert sympy.simplify(result.quantities["epicyclic"] - 2 * sympy.sqrt(k / m)) == 0
    assert sympy.simplify(result.quantities["energy"] - (k * r**2 / 2 + ell**2 / (2 * m * r**2))) == 0
    for name in ("radius", "epicyclic", "energy"):
        assert set(result.agreement[name]) >= {"lagrange", "newton", "conservation"}, name
        assert result.simulation[name].max_relative_error < 1e-3, name


def test_a_repulsive_centre_has_no_circular_orbit_and_says_why() -> None:
    model = load_model(polar("G*M*m/d", {"r": "R"}, {"v": {"circular_speed": "theta"}}), SYMBOLS)
    with pytest.raises(DerivationError, match="pull towards the centre"):
        uncached(model)


def test_a_coordinate_that_does_not_turn_uniformly_is_refused() -> None:
    pendulum = {
        "coordinates": ["r", "phi"],
        "bodies": {"bob": {"mass": "m", "position": {"x": "r*sin(phi)", "y": "-r*cos(phi)"}}},
        "gravity": "G",
        "potentials": [{"bodies": ["bob"], "anchor": {"x": 0, "y": 0}, "distance": "d", "energy": "k*d^2/2"}],
        "state": {"r": "R", "phi": "1"},
        "quantities": {"T": {"revolution_period": "phi"}},
    }
    with pytest.raises(DerivationError, match="does not turn uniformly"):
        uncached(load_model(pendulum, SYMBOLS))


@pytest.mark.parametrize(
    ("quantity", "message"),
    [
        ({"mechanical_energy": "body"}, "mechanical_energy: state"),
        ({"circular_speed": "phi"}, "unknown coordinate 'phi'"),
        ({"circular_radius": "R"}, "unknown coordinate 'R'"),
    ],
)
def test_an_orbit_quantity_with_a_wrong_target_is_refused_at_its_path(quantity: Any, message: str) -> None:
    with pytest.raises(SpecErrors) as caught:
        load_model(polar("-G*M*m/d", {"r": "R"}, {"q": quantity}), SYMBOLS)
    (error,) = caught.value.errors
    assert error.path[:2] == ("quantities", "q")
    assert message in error.message


def test_one_turn_of_a_frame_needs_a_rotating_frame() -> None:
    spring = {
        "coordinates": ["x"],
        "bodies": {"block": {"mass": "m", "position": {"x": "x"}}},
        "potentials": [{"bodies": ["block"], "anchor": {"x": 0}, "distance": "d", "energy": "k*d^2/2"}],
        "quantities": {"T": {"revolution_period": "frame"}},
    }
    with pytest.raises(DerivationError, match="needs a rotating frame"):
        uncached(load_model(spring, SYMBOLS))
