"""Positions along z: a body on the second horizontal axis derives where the mechanics is generic, and
each part written for the x–y plane is refused where it is written, never silently left without z."""

from __future__ import annotations

import copy
from collections.abc import Callable
from typing import Any

import pytest
import sympy

from physics.answer_text import typed_text
from physics.engine import depth, derive, load_model
from physics.engine.model import QuantityKind
from physics.engine.notation import audit
from physics.engine.results import StepKind
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
        "write a spring as a potential of the distance (`potentials:`)",
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
        section: entry,
    }
    with pytest.raises(SpecErrors) as caught:
        load_model(data, SYMBOLS)
    found = {e.path: e.message for e in caught.value.errors}
    assert "z is for a body's position or a potential's anchor only" in found[(section, *path)]


def test_a_planar_model_keeps_every_section() -> None:
    planar = _puck(lambda d: d["bodies"]["puck"].update(position={"x": "r*cos(phi)", "y": "r*sin(phi)"}))
    planar["constraints"]["string"]["gap"] = "l - sqrt(x_puck^2 + y_puck^2) + y_weight"
    planar["quantities"]["flight"] = FLIGHT  # accepted by this check: refused for z alone
    try:
        load_model(planar, SYMBOLS)
    except SpecErrors as error:
        assert all(PLANE_ONLY not in e.message for e in error.errors)


L, ALPHA, A, L0 = (sympy.Symbol(n, positive=True) for n in ("L", "alpha", "A", "L0"))
K = SYMBOLS["k"]
CONE_SYMBOLS = {**SYMBOLS, "L": L, "alpha": ALPHA, "A": A, "L0": L0}
# a bob on a string of length L from a pivot at the origin, swinging round at the angle alpha
CONE: dict[str, Any] = {
    "coordinates": ["theta", "phi"],
    "bodies": {
        "bob": {
            "mass": "m1",
            "position": {"x": "L*sin(theta)*cos(phi)", "y": "-L*cos(theta)", "z": "L*sin(theta)*sin(phi)"},
        }
    },
    "gravity": "g",
    "constraints": {"string": {"kind": "string", "gap": "L - sqrt(x_bob^2 + y_bob^2 + z_bob^2)"}},
    "state": {"theta": "alpha"},
    "domain": {"ranges": {"alpha": ["0", "pi/2"], "theta": ["0", "pi/2"]}},
    "quantities": {"period": {"revolution_period": "phi"}},
}


def test_conical_pendulum_on_z_derives_the_positive_steady_rate() -> None:
    """sympy cannot sign ±sqrt(g/(L cos(alpha))) alone: the domain keeps the positive rate (orbits.py)."""
    derived = derive(load_model(CONE, CONE_SYMBOLS)).quantities
    expected = 2 * sympy.pi * sympy.sqrt(L * sympy.cos(ALPHA) / G)
    point = {L: 0.7, ALPHA: 0.6, G: 9.8}
    assert abs(float((derived["period"] - expected).subs(point))) < 1e-9


def test_conical_pendulum_period_and_speed_are_written_with_one_root() -> None:
    """As a teacher writes them: 2 pi sqrt(L cos(alpha)/g), sin(alpha) sqrt(g L/cos(alpha)); not
    2 pi sqrt(L)/(sqrt(g) sqrt(1/cos(alpha))) nor sqrt(L)*sqrt(g)*sin(alpha)/sqrt(cos(alpha))."""
    data = copy.deepcopy(CONE)
    data["quantities"]["speed"] = {"circular_speed": "phi"}
    derived = derive(load_model(data, CONE_SYMBOLS)).quantities
    assert typed_text(derived["period"]) == "2*pi*sqrt(L*cos(alpha)/g)"
    assert typed_text(derived["speed"]) == "sqrt(L*g/cos(alpha))*sin(alpha)"


@pytest.mark.parametrize(
    ("rate", "steady"),
    [
        pytest.param("sqrt(g/(L*cos(alpha)))", True, id="the-steady-rate"),
        pytest.param("sqrt(g/L/cos(alpha))", True, id="the-steady-rate-written-otherwise"),
        pytest.param("v/L", False, id="another-rate"),
    ],
)
def test_a_rate_in_the_state_beside_a_steady_period_must_be_the_steady_rate(rate: str, steady: bool) -> None:
    """Else the period would be of the steady motion and the tension of the state's, unsaid."""
    data = copy.deepcopy(CONE)
    data["state"]["phi_dot"] = rate
    data["quantities"]["tension"] = {"force": "string"}
    if steady:
        assert (
            sympy.simplify(
                derive(load_model(data, CONE_SYMBOLS)).quantities["tension"] - M1 * G / sympy.cos(ALPHA)
            )
            == 0
        )
        return
    with pytest.raises(
        DerivationError, match=r"For the steady motion give phi_dot: sqrt\(g/\(L\*cos\(alpha\)\)\)"
    ):
        derive(load_model(data, CONE_SYMBOLS))


STEADY_AND_STATE_AT_REST = [
    pytest.param(
        {"period": {"revolution_period": "phi"}, "tension": {"force": "string"}},
        None,
        id="period-and-tension",
    ),
    pytest.param(
        {"speed": {"circular_speed": "phi"}, "swing": {"acceleration": "theta"}},
        None,
        id="speed-and-acceleration",
    ),
    pytest.param(
        {"tension": {"force": "string"}}, M1 * G * sympy.cos(ALPHA), id="tension-of-a-bob-released-at-rest"
    ),
]


@pytest.mark.parametrize(("quantities", "tension"), STEADY_AND_STATE_AT_REST)
def test_a_steady_quantity_beside_a_force_needs_the_steady_rate_in_the_state(
    quantities: dict[str, Any], tension: sympy.Expr | None
) -> None:
    """phi_dot left out is 0: the tension would be m g cos(alpha), of a bob at rest at alpha, beside the
    period of the steady motion; asked alone, that tension is the released bob's, and right."""
    data = copy.deepcopy(CONE)
    data["quantities"] = quantities
    if tension is not None:
        assert sympy.simplify(derive(load_model(data, CONE_SYMBOLS)).quantities["tension"] - tension) == 0
        return
    with pytest.raises(
        DerivationError, match=r"For the steady motion give phi_dot: sqrt\(g/\(L\*cos\(alpha\)\)\)"
    ):
        derive(load_model(data, CONE_SYMBOLS))


def _moving_pivot(gap: str) -> dict[str, Any]:
    """The cone hung in a lift accelerating upwards at A: the pivot at A t^2/2."""
    data = copy.deepcopy(CONE)
    data["bodies"]["bob"]["position"]["y"] = "A*t^2/2 - L*cos(theta)"
    data["constraints"]["string"]["gap"] = gap
    data["quantities"]["tension"] = {"force": "string"}
    data["state"]["phi_dot"] = "sqrt((g + A)/(L*cos(alpha)))"
    return data


def test_conical_pendulum_in_an_accelerating_lift_feels_g_plus_a() -> None:
    derivation = derive(
        load_model(_moving_pivot("L - sqrt(x_bob^2 + (y_bob - A*t^2/2)^2 + z_bob^2)"), CONE_SYMBOLS)
    )
    derived = derivation.quantities
    assert sympy.simplify(derived["period"] - 2 * sympy.pi * sympy.sqrt(L * sympy.cos(ALPHA) / (G + A))) == 0
    assert sympy.simplify(derived["tension"] - M1 * (G + A) / sympy.cos(ALPHA)) == 0
    assert len(derivation.agreement["period"]) >= 2 and {"period", "tension"} <= set(derivation.simulation)


LIFT = _moving_pivot("L - sqrt(x_bob^2 + (y_bob - A*t^2/2)^2 + z_bob^2)")
# (numbered equations, unknowns) each method's worked solution counts: the page's comparison table
LIFT_COUNTS = {"newton": (4, 4), "frames": (4, 4), "dalembert": (2, 2), "lagrange": (3, 3)}


def test_the_lift_cones_worked_solutions_count_the_equations_and_unknowns_they_solve() -> None:
    """The steady rate is found by each method at another state: its equations stay numbered and its
    solve keeps its unknowns (T and the accelerations), read with the rate as phi', not an engine name."""
    derivation = derive(load_model(LIFT, CONE_SYMBOLS))
    counted = {}
    for report in derivation.methods:
        unknowns = {u for step in report.steps for u in step.unknowns}
        equations = sum(step.kind is StepKind.EQUATION for step in report.steps)
        counted[report.name] = (equations, len(unknowns))
        assert not any("steady" in step.latex for step in report.steps), report.name
    assert {name: counted[name] for name in LIFT_COUNTS} == LIFT_COUNTS
    assert audit(load_model(LIFT, CONE_SYMBOLS), derivation.notation, derivation.methods) == []
    newton = next(r for r in derivation.methods if r.name == "newton")
    solved = [step.latex for step in newton.steps if step.kind is StepKind.SOLVE]
    assert any(r"T = \frac{m_{1} \left(A + g\right)}{\cos{\left(\alpha \right)}}" in s for s in solved)


def test_a_string_gap_left_at_the_fixed_pivot_under_a_moving_bob_is_refused_at_the_gap() -> None:
    with pytest.raises(DerivationError) as caught:
        derive(load_model(_moving_pivot("L - sqrt(x_bob^2 + y_bob^2 + z_bob^2)"), CONE_SYMBOLS))
    assert caught.value.path == ("constraints", "string"), caught.value


# two pucks on a frictionless table (x and z) joined by a spring of natural length L0, released with
# the second at (a, b) from the first: each is pulled along the line between them
PUCKS: dict[str, Any] = {
    "coordinates": ["x1", "z1", "x2", "z2"],
    "bodies": {
        "one": {"mass": "m1", "position": {"x": "x1", "z": "z1"}},
        "two": {"mass": "m2", "position": {"x": "x2", "z": "z2"}},
    },
    "potentials": [{"bodies": ["one", "two"], "distance": "d", "energy": "k*(d - L0)^2/2"}],
    "state": {"x1": 0, "z1": 0, "x2": "a", "z2": "b"},
    "quantities": {"ax1": {"acceleration": "x1"}, "az2": {"acceleration": "z2"}},
}
# a bob on a spring from the origin, free in x, y and z, released at (a, -h, b)
SPRUNG_BOB: dict[str, Any] = {
    "coordinates": ["X", "Y", "Z"],
    "bodies": {"bob": {"mass": "m1", "position": {"x": "X", "y": "Y", "z": "Z"}}},
    "gravity": "g",
    "potentials": [
        {"bodies": ["bob"], "anchor": {"x": 0, "y": 0, "z": 0}, "distance": "d", "energy": "k*(d - L0)^2/2"}
    ],
    "state": {"X": "a", "Y": "-h", "Z": "b"},
    "quantities": {"az": {"acceleration": "Z"}, "ay": {"acceleration": "Y"}},
}
SPRING_SYMBOLS = {**SYMBOLS, **{n: sympy.Symbol(n, positive=True) for n in ("L0", "a", "b", "h")}}
a, b, h = (SPRING_SYMBOLS[n] for n in ("a", "b", "h"))
SPRINGS_ON_Z = [
    pytest.param(
        PUCKS,
        {
            "ax1": K * (1 - L0 / sympy.sqrt(a**2 + b**2)) * a / M1,
            "az2": -K * (1 - L0 / sympy.sqrt(a**2 + b**2)) * b / M2,
        },
        id="two-pucks-on-a-table",
    ),
    pytest.param(
        SPRUNG_BOB,
        {
            "az": -K * (1 - L0 / sympy.sqrt(a**2 + b**2 + h**2)) * b / M1,
            "ay": K * (1 - L0 / sympy.sqrt(a**2 + b**2 + h**2)) * h / M1 - G,
        },
        id="bob-free-in-x-y-and-z",
    ),
]


@pytest.mark.parametrize(("data", "expected"), SPRINGS_ON_Z)
def test_a_spring_on_z_pulls_along_the_distance_in_three_dimensions(
    data: dict[str, Any], expected: dict[str, sympy.Expr]
) -> None:
    derivation = derive(load_model(data, SPRING_SYMBOLS))
    for name, value in expected.items():
        assert sympy.simplify(derivation.quantities[name] - value) == 0, name
        assert len(derivation.agreement[name]) >= 2 and name in derivation.simulation


SPRING_WITHOUT_Z = [
    pytest.param(
        lambda d: d["potentials"][0].update(anchor={"x": 0, "y": 0}),
        SPRUNG_BOB,
        ("potentials", 0, "anchor"),
        "bob is on z but the anchor gives no z",
        id="anchor-without-z",
    ),
    pytest.param(
        lambda d: d["bodies"]["two"].update(position={"x": "x2"}),
        PUCKS,
        ("potentials", 0, "bodies"),
        "one is on z but two gives no z",
        id="other-body-without-z",
    ),
]


@pytest.mark.parametrize(("change", "data", "path", "says"), SPRING_WITHOUT_Z)
def test_a_spring_whose_ends_do_not_both_give_z_is_refused_at_the_end_without_it(
    change: Callable[[dict[str, Any]], object], data: dict[str, Any], path: tuple[str | int, ...], says: str
) -> None:
    edited = copy.deepcopy(data)
    change(edited)
    with pytest.raises(SpecErrors) as caught:
        load_model(edited, SPRING_SYMBOLS)
    found = {e.path: e.message for e in caught.value.errors}
    assert path in found, found
    assert says in found[path]


@pytest.mark.parametrize("kind", sorted(set(QuantityKind) - depth.KINDS))
def test_no_quantity_kind_outside_the_generic_ones_loads_with_z(kind: QuantityKind) -> None:
    """Each is refused at the quantity: by depth.py, or already by its own reading (it needs a section
    a model with z cannot have)."""
    target = "r" if kind.value.endswith(("frequency", "time", "velocity", "distance")) else "puck"
    asked = _puck(lambda d: d["quantities"].update(asked={kind.value: target}))
    with pytest.raises(SpecErrors) as caught:
        load_model(asked, SYMBOLS)
    assert any(e.path[:2] == ("quantities", "asked") for e in caught.value.errors)


F = sympy.Symbol("F", positive=True)
W = sympy.Symbol("w", positive=True)
FORCE_SYMBOLS = {**{n: s for n, s in CONE_SYMBOLS.items() if n != "t"}, "F": F, "w": W}
# a puck on a frictionless table (x and z), pulled along z
PULLED_PUCK: dict[str, Any] = {
    "coordinates": ["X", "Z"],
    "bodies": {"puck": {"mass": "m1", "position": {"x": "X", "z": "Z"}}},
    "forces": [{"body": "puck", "force": {"z": "F"}}],
    "quantities": {"az": {"acceleration": "Z"}, "ax": {"acceleration": "X"}},
}
# the conical pendulum's bob held at rest at the angle alpha, a wind F blowing along x
WINDY_CONE = {
    **CONE,
    "forces": [{"body": "bob", "force": {"x": "F"}}],
    "state": {"theta": "alpha", "phi": 0},
    "quantities": {"tension": {"force": "string"}, "swing": {"acceleration": "theta"}},
}
FORCES_ON_Z = [
    pytest.param(PULLED_PUCK, {"az": F / M1, "ax": 0}, id="constant-pull-along-z"),
    pytest.param(
        {
            **PULLED_PUCK,
            "forces": [{"body": "puck", "force": {"z": "F*cos(w*t)"}}],
            "state": {"t": "pi/(3*w)"},
        },
        {"az": F / (2 * M1)},
        id="pull-along-z-in-the-time",
    ),
    pytest.param(
        WINDY_CONE,
        {
            "tension": M1 * G * sympy.cos(ALPHA) + F * sympy.sin(ALPHA),
            "swing": (F * sympy.cos(ALPHA) - M1 * G * sympy.sin(ALPHA)) / (M1 * L),
        },
        id="conical-pendulum-in-a-wind",
    ),
]


@pytest.mark.parametrize(("data", "expected"), FORCES_ON_Z)
def test_a_given_force_on_a_body_on_z_derives(data: dict[str, Any], expected: dict[str, sympy.Expr]) -> None:
    derivation = derive(load_model(data, FORCE_SYMBOLS))
    for name, value in expected.items():
        assert sympy.simplify(derivation.quantities[name] - value) == 0, name
        assert len(derivation.agreement[name]) >= 2 and name in derivation.simulation


@pytest.mark.parametrize(
    "table", [FORCE_SYMBOLS, {**FORCE_SYMBOLS, "t": SYMBOLS["t"]}], ids=["engine-t", "table-t"]
)
def test_a_pull_along_z_in_the_time_is_simulated_at_the_states_time(table: dict[str, sympy.Symbol]) -> None:
    """With t a symbol of the problem's table too, the state's time is where both the answer and the
    simulation are taken, not a sampled t."""
    data = {
        **PULLED_PUCK,
        "forces": [{"body": "puck", "force": {"z": "F*cos(w*t)"}}],
        "state": {"t": "pi/(3*w)"},
    }
    derivation = derive(load_model(data, table))
    assert sympy.simplify(derivation.quantities["az"] - F / (2 * M1)) == 0
    assert derivation.simulation["az"].max_relative_error < 1e-3


def test_a_force_along_z_on_a_body_without_z_is_refused_at_its_component() -> None:
    data = copy.deepcopy(PULLED_PUCK)
    data["coordinates"].append("s")
    data["bodies"]["cart"] = {"mass": "m2", "position": {"x": "s"}}
    data["forces"] = [{"body": "cart", "force": {"z": "F"}}]
    with pytest.raises(SpecErrors) as caught:
        load_model(data, FORCE_SYMBOLS)
    found = {e.path: e.message for e in caught.value.errors}
    assert "cart has no z in its position" in found[("forces", 0, "force", "z")], found


def test_a_wind_on_a_steadily_circling_bob_is_refused_as_no_steady_rotation() -> None:
    data = _puck(lambda d: d.update(forces=[{"body": "puck", "force": {"z": "F"}}]))
    with pytest.raises(DerivationError, match="does not turn uniformly"):
        derive(load_model(data, {**SYMBOLS, "F": F}))


# the bob on a spring free in x, y and z, now at rest below the anchor
RESTING_BOB = {
    **SPRUNG_BOB,
    "state": {"X": 0, "Y": "-L0 - m1*g/k", "Z": 0},
    "domain": {"ranges": {"Y": ["-oo", "0"]}},
    "quantities": {
        "rest": {"equilibrium": "Y"},
        "bounce": {"angular_frequency": "Y"},
        "sway": {"angular_frequency": "X"},
        "stiff": {"stiffness": "Y"},
    },
}


def test_a_bob_on_a_spring_free_in_three_dimensions_has_each_coordinates_equilibrium_and_frequency() -> None:
    """Y's force depends on X and Z, but the coordinates rest together below the anchor and separate
    there: it bounces at sqrt(k/m) and sways as a pendulum of the stretched spring's length."""
    derivation = derive(load_model(RESTING_BOB, SPRING_SYMBOLS))
    stretched = L0 + M1 * G / K
    expected = {
        "rest": -stretched,
        "bounce": sympy.sqrt(K / M1),
        "sway": sympy.sqrt(G / stretched),
        "stiff": K,
    }
    for name, value in expected.items():
        assert sympy.simplify(derivation.quantities[name] - value) == 0, name
        assert len(derivation.agreement[name]) >= 2 and name in derivation.simulation


def test_an_equilibrium_whose_first_root_is_in_a_later_coordinate_is_found() -> None:
    """The bob hung at x = X - Y: X's equation gives X = Y, a root in Y still to solve, which is followed
    (not dropped) to the one rest point X = Y = -(L0 + m g/k)."""
    sheared = copy.deepcopy(RESTING_BOB)
    sheared["bodies"]["bob"]["position"]["x"] = "X - Y"
    sheared["state"] = {"X": "-L0 - m1*g/k", "Y": "-L0 - m1*g/k", "Z": 0}
    sheared["domain"] = {"ranges": {"X": ["-oo", "0"], "Y": ["-oo", "0"]}}
    sheared["quantities"] = {"rest": {"equilibrium": "Y"}, "across": {"equilibrium": "X"}}
    derived = derive(load_model(sheared, SPRING_SYMBOLS)).quantities
    for name in ("rest", "across"):
        assert sympy.simplify(derived[name] + L0 + M1 * G / K) == 0, name


def test_a_coordinate_oscillating_with_another_is_refused_naming_normal_frequency() -> None:
    """Two carts in a chain of springs from a wall, the second s beyond the first: x1 has no frequency of
    its own (moving it moves the second cart too), though s has its equilibrium."""
    chain = {
        "coordinates": ["x1", "s"],
        "bodies": {
            "one": {"mass": "m1", "position": {"x": "x1"}},
            "two": {"mass": "m1", "position": {"x": "x1 + s"}},
        },
        "potentials": [
            {"bodies": ["one"], "anchor": {"x": 0}, "distance": "d", "energy": "k*(d - L0)^2/2"},
            {"bodies": ["one", "two"], "distance": "e", "energy": "k*(e - L0)^2/2"},
        ],
        "state": {"x1": "L0", "s": "L0"},
        "domain": {"ranges": {"x1": ["0", "oo"], "s": ["0", "oo"]}},
        "quantities": {"rest": {"equilibrium": "s"}, "w1": {"angular_frequency": "x1"}},
    }
    with pytest.raises(DerivationError) as caught:
        derive(load_model(chain, SPRING_SYMBOLS))
    assert {path[1] for path, _ in caught.value.findings} == {"w1"}
    assert "x1 oscillates together with s" in str(caught.value)
    assert "ask for normal_frequency" in str(caught.value)
