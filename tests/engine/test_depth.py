"""Positions along z: a body on the second horizontal axis derives where the mechanics is generic, and
each part written for the x–y plane is refused where it is written, never silently left without z."""

from __future__ import annotations

import copy
from collections.abc import Callable
from typing import Any

import pytest
import sympy

from physics.engine import depth, derive, load_model
from physics.engine.model import QuantityKind
from physics.errors import DerivationError, SpecErrors

SYMBOLS = {n: sympy.Symbol(n, positive=True) for n in ("m1", "m2", "g", "R", "l", "mu", "k", "v", "t")}
M1, M2, G, R = (SYMBOLS[n] for n in ("m1", "m2", "g", "R"))

# a puck on a frictionless table tied through a hole to a hanging weight (problems/GUIDE.md)
PUCK: dict[str, Any] = {
    "coordinates": ["r", "phi"],
    "bodies": {
        "puck": {"mass": "m1", "position": {"x": "r*cos(phi)", "z": "r*sin(phi)"}},
        "weight": {"mass": "m2", "position": {"y": "r - l"}},
    },
    "gravity": "g",
    "constraints": {"string": {"kind": "string", "gap": "l - sqrt(x_puck^2 + z_puck^2) + y_weight"}},
    "state": {"r": "R", "phi_dot": "sqrt(m2*g/(m1*R))"},
    "domain": {"ranges": {"r": ["0", "l"]}, "positive": ["l - R"]},
    "quantities": {"speed": {"circular_speed": "phi"}, "tension": {"force": "string"}},
}


def _puck(change: Callable[[dict[str, Any]], object]) -> dict[str, Any]:
    data = copy.deepcopy(PUCK)
    change(data)
    return data


def test_puck_through_a_hole_derives_speed_and_tension_with_z() -> None:
    derivation = derive(load_model(PUCK, SYMBOLS))
    derived = derivation.quantities
    assert sympy.simplify(derived["speed"] - sympy.sqrt(M2 * G * R / M1)) == 0
    assert sympy.simplify(derived["tension"] - M2 * G) == 0
    assert "horizontal position" in derivation.notation.cartesian["z_puck"].words
    assert "+z" in derivation.notation.cartesian["z_puck"].words
    # its figure draws the bodies side by side, not the angle
    assert "see the figure" not in derivation.notation.coordinates["phi"].words


def test_a_string_through_the_hole_that_would_push_is_refused() -> None:
    flipped = _puck(
        lambda d: d["constraints"]["string"].update(gap="sqrt(x_puck^2 + z_puck^2) - l - y_weight")
    )
    with pytest.raises(DerivationError, match="would push"):
        derive(load_model(flipped, SYMBOLS))


PLANE_ONLY = "written for the x–y plane"
FLIGHT = {"time_of_flight": "puck"}
REFUSED = [
    pytest.param(
        lambda d: d.update(
            friction=[{"constraint": "string", "body": "puck", "coefficient": "mu", "sliding": "r"}]
        ),
        ("friction",),
        PLANE_ONLY,
        id="friction",
    ),
    pytest.param(
        lambda d: d.update(
            potentials=[{"bodies": ["puck"], "anchor": {"x": 0}, "energy": "k*d^2/2", "distance": "d"}]
        ),
        ("potentials",),
        PLANE_ONLY,
        id="potentials",
    ),
    pytest.param(
        lambda d: d.update(forces=[{"body": "puck", "drag": "k"}]), ("forces",), PLANE_ONLY, id="forces"
    ),
    pytest.param(lambda d: d.update(frame={"body": "weight"}), ("frame",), PLANE_ONLY, id="frame"),
    pytest.param(
        lambda d: d.update(impact={"bodies": ["puck", "weight"]}), ("impact",), PLANE_ONLY, id="impact"
    ),
    pytest.param(
        lambda d: d.update(collision={"projectile": "bullet", "target": "puck"}),
        ("collision",),
        PLANE_ONLY,
        id="collision",
    ),
    pytest.param(lambda d: d.update(released=["string"]), ("released",), PLANE_ONLY, id="released"),
    pytest.param(
        lambda d: d.update(elements={"s": {"kind": "spring", "ends": ["puck", {"x": 0, "y": 0}], "k": "k"}}),
        ("elements",),
        PLANE_ONLY,
        id="elements",
    ),
    pytest.param(
        lambda d: d["bodies"]["puck"].update(inertia="m1*R^2/2", angle="phi"),
        ("bodies", "puck", "angle"),
        "a body on z is a particle",
        id="angle-of-a-body-on-z",
    ),
    pytest.param(
        lambda d: d["constraints"].update(grip={"kind": "rolling", "gap": "x_puck"}),
        ("constraints", "grip", "kind"),
        PLANE_ONLY,
        id="rolling-grip",
    ),
    pytest.param(
        lambda d: d["bodies"]["weight"]["position"].update(x="v*t"),
        ("bodies", "weight", "position"),
        "moving in the time",
        id="support-moving-in-time",
    ),
    pytest.param(
        lambda d: d["quantities"].update(flight=FLIGHT),
        ("quantities", "flight", "time_of_flight"),
        PLANE_ONLY,
        id="time-of-flight",
    ),
    pytest.param(
        lambda d: d["quantities"].update(far={"range": "puck"}),
        ("quantities", "far", "range"),
        PLANE_ONLY,
        id="range",
    ),
    pytest.param(
        lambda d: d["quantities"].update(high={"max_height": "puck"}),
        ("quantities", "high", "max_height"),
        PLANE_ONLY,
        id="max-height",
    ),
    pytest.param(
        lambda d: d["quantities"].update(best={"maximize": "R", "of": FLIGHT}),
        ("quantities", "best", "maximize"),
        "time_of_flight is " + PLANE_ONLY,
        id="extremum-of-a-flight",
    ),
    pytest.param(
        lambda d: d["quantities"].update(ring={"damped_frequency": "r"}),
        ("quantities", "ring", "damped_frequency"),
        PLANE_ONLY,
        id="damped-frequency",
    ),
    pytest.param(
        lambda d: d["quantities"].update(drift={"terminal_velocity": "r"}),
        ("quantities", "drift", "terminal_velocity"),
        PLANE_ONLY,
        id="terminal-velocity",
    ),
]


@pytest.mark.parametrize(("change", "path", "says"), REFUSED)
def test_a_model_with_z_refuses_what_is_written_for_the_plane(
    change: Callable[[dict[str, Any]], object], path: tuple[str, ...], says: str
) -> None:
    with pytest.raises(SpecErrors) as caught:
        load_model(_puck(change), SYMBOLS)
    found = {e.path: e.message for e in caught.value.errors}
    assert path in found, found
    assert says in found[path]


@pytest.mark.parametrize(
    ("section", "entry", "path"),
    [
        (
            "potentials",
            {"bodies": ["weight"], "anchor": {"z": 0}, "energy": "k*d^2/2", "distance": "d"},
            (0, "anchor", "z"),
        ),
        (
            "collision",
            {"projectile": "bullet", "target": "weight", "direction": {"z": 1}},
            ("direction", "z"),
        ),
    ],
)
def test_z_in_a_point_or_direction_other_than_a_position_is_refused(
    section: str, entry: dict[str, Any], path: tuple[str | int, ...]
) -> None:
    data = {
        "coordinates": ["s"],
        "bodies": {"weight": {"mass": "m2", "position": {"y": "s"}}},
        "quantities": {"a": {"acceleration": "s"}},
        section: [entry] if section == "potentials" else entry,
    }
    with pytest.raises(SpecErrors) as caught:
        load_model(data, SYMBOLS)
    found = {e.path: e.message for e in caught.value.errors}
    assert "z is for a body's position only" in found[(section, *path)]


def test_a_planar_model_keeps_every_section() -> None:
    planar = _puck(lambda d: d["bodies"]["puck"].update(position={"x": "r*cos(phi)", "y": "r*sin(phi)"}))
    planar["constraints"]["string"]["gap"] = "l - sqrt(x_puck^2 + y_puck^2) + y_weight"
    planar["quantities"]["flight"] = FLIGHT  # accepted by this check: refused for z alone
    try:
        load_model(planar, SYMBOLS)
    except SpecErrors as error:
        assert all(PLANE_ONLY not in e.message for e in error.errors)


def test_conical_pendulum_on_z_derives_the_positive_steady_rate() -> None:
    """sympy cannot sign ±sqrt(g/(L cos(alpha))) alone: the domain keeps the positive rate (orbits.py)."""
    L, alpha = sympy.Symbol("L", positive=True), sympy.Symbol("alpha", positive=True)
    data = {
        "coordinates": ["theta", "phi"],
        "bodies": {
            "bob": {
                "mass": "m1",
                "position": {
                    "x": "L*sin(theta)*cos(phi)",
                    "y": "-L*cos(theta)",
                    "z": "L*sin(theta)*sin(phi)",
                },
            }
        },
        "gravity": "g",
        "constraints": {"string": {"kind": "string", "gap": "L - sqrt(x_bob^2 + y_bob^2 + z_bob^2)"}},
        "state": {"theta": "alpha"},
        "domain": {"ranges": {"alpha": ["0", "pi/2"], "theta": ["0", "pi/2"]}},
        "quantities": {"period": {"revolution_period": "phi"}},
    }
    derived = derive(load_model(data, {**SYMBOLS, "L": L, "alpha": alpha})).quantities
    expected = 2 * sympy.pi * sympy.sqrt(L * sympy.cos(alpha) / G)
    point = {L: 0.7, alpha: 0.6, G: 9.8}
    assert abs(float((derived["period"] - expected).subs(point))) < 1e-9


@pytest.mark.parametrize("kind", sorted(set(QuantityKind) - depth.KINDS))
def test_no_quantity_kind_outside_the_generic_ones_loads_with_z(kind: QuantityKind) -> None:
    """Each is refused at the quantity: by depth.py, or already by its own reading (it needs a section
    a model with z cannot have)."""
    target = "r" if kind.value.endswith(("frequency", "time", "velocity", "distance")) else "puck"
    asked = _puck(lambda d: d["quantities"].update(asked={kind.value: target}))
    with pytest.raises(SpecErrors) as caught:
        load_model(asked, SYMBOLS)
    assert any(e.path[:2] == ("quantities", "asked") for e in caught.value.errors)
