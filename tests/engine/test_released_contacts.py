"""A string gone slack or a surface left, declared `released:`: every method derives the motion without
it, and the declaration is refused where it is not the physics (held, the contact would still act; the
coordinates build it in; its gap would close)."""

from __future__ import annotations

import pytest
import sympy
import yaml

from physics.engine import derivation, derive, load_model
from physics.errors import DerivationError, SpecErrors

uncached = derivation._derive.__wrapped__

# each body its own height, measured from where it starts: the string's slack is y_m1 + y_m2
ATWOOD_SLACK = """
coordinates: [y1, y2]
bodies:
  m1: {mass: m1, position: {y: y1}}
  m2: {mass: m2, position: {y: y2}}
gravity: g
forces:
  - {body: m2, force: {y: F}}
constraints:
  string: {kind: string, gap: "y_m1 + y_m2"}
released: [string]
domain:
  positive: [DOMAIN]
quantities:
  a1: {acceleration: y1}
  a2: {acceleration: y2}
"""
LIFTED_CRATE = """
coordinates: [x, y]
bodies:
  crate: {mass: m, position: {x: x, y: y}}
gravity: g
constraints:
  floor: {kind: surface, gap: y_crate}
released: [floor]
forces:
  - {body: crate, force: {x: "F*cos(alpha)", y: "F*sin(alpha)"}}
domain:
  ranges: {alpha: ["0", "pi/2"]}
  positive: ["F*sin(alpha) - m*g"]
quantities:
  ax: {acceleration: x}
  ay: {acceleration: y}
"""
BALL_THROWN_UP = """
coordinates: [x, y]
bodies:
  ball: {mass: m, position: {x: x, y: y}}
gravity: g
constraints:
  floor: {kind: surface, gap: y_ball}
released: [floor]
state: {x: 0, y: 0, y_dot: v}
domain:
  positive: ["v^2 - 2*g*h"]
quantities:
  there: {velocity: y, at: {y: WHERE}}
"""
BALL_ON_FLOOR = """
coordinates: [x, y]
bodies:
  ball: {mass: m, position: {x: x, y: y}}
gravity: g
constraints:
  floor: {kind: surface, gap: y_ball}
released: [floor]
state: {y: HEIGHT, y_dot: RATE}
quantities:
  ay: {acceleration: y}
"""
ATWOOD_ONE_COORDINATE = """
coordinates: [s]
bodies:
  m1: {mass: m1, position: {y: s}}
  m2: {mass: m2, position: {y: "-s"}}
gravity: g
forces:
  - {body: m2, force: {y: F}}
STRING
released: [string]
domain:
  positive: ["F - 2*m2*g"]
quantities:
  acceleration: {acceleration: s}
"""
# the crate held on the floor; lifted off it in a scenario, its height a coordinate of its own there
CRATE_SCENARIOS = """
coordinates: [x]
bodies:
  crate: {mass: m, position: {x: x, y: 0}}
gravity: g
constraints:
  floor: {kind: surface, gap: y_crate}
forces:
  - {body: crate, force: {x: "F*cos(alpha)", y: "F*sin(alpha)"}}
domain:
  ranges: {alpha: ["0", "pi/2"]}
  positive: ["m*g - F*sin(alpha)"]
quantities:
  normal: {force: floor}
scenarios:
  lifted:
    coordinates: [x, y]
    bodies: {crate: {position: {y: y}}}
    released: [floor]
    domain: {positive: ["F*sin(alpha) - m*g"]}
    quantities:
      rise: {acceleration: y}
"""
# a particle on a dome of radius R, at the angle and speed where the dome's push has fallen to zero
DOME = """
coordinates: [x, y]
bodies:
  p: {mass: m, position: {x: x, y: y}}
gravity: g
constraints:
  dome: {kind: surface, gap: "sqrt(x_p^2 + y_p^2) - R"}
released: [dome]
state: {x: "sqrt(5)*R/3", y: "2*R/3", x_dot: "2*SPEED/3", y_dot: "-sqrt(5)*SPEED/3"}
quantities:
  ax: {acceleration: x}
  ay: {acceleration: y}
"""
BY_HAND = 'constraints:\n  string: {kind: string, gap: "y_m1 + y_m2"}'
PULLEY = "elements:\n  string: {kind: pulley, ends: [{body: m1, pulls: up}, {body: m2, pulls: up}]}"
ATWOOD = "m1 m2 g F"
CRATE = "m g F alpha"
BALL = "m g v h"


def _symbols(names: str) -> dict[str, sympy.Symbol]:
    return {name: sympy.Symbol(name, positive=True) for name in names.split()}


def _derived(text: str, names: str) -> dict[str, sympy.Expr]:
    return dict(uncached(load_model(yaml.safe_load(text), _symbols(names))).quantities)


@pytest.mark.parametrize(
    ("text", "names", "expected"),
    [
        pytest.param(
            ATWOOD_SLACK.replace("DOMAIN", '"F - 2*m2*g"'),
            ATWOOD,
            {"a1": "-g", "a2": "(F - m2*g)/m2"},
            id="atwood-thrust-slack-m1-falls-freely",
        ),
        pytest.param(
            LIFTED_CRATE, CRATE, {"ax": "F*cos(alpha)/m", "ay": "F*sin(alpha)/m - g"}, id="crate-lifted-off"
        ),
        pytest.param(
            BALL_ON_FLOOR.replace("HEIGHT", "0").replace("RATE", "v"), BALL, {"ay": "-g"}, id="ball-thrown-up"
        ),
        pytest.param(
            BALL_ON_FLOOR.replace("HEIGHT", "h").replace("RATE", "-v"), BALL, {"ay": "-g"}, id="ball-above-it"
        ),
        pytest.param(
            BALL_THROWN_UP.replace("WHERE", "h"),
            BALL,
            {"there": "sqrt(v^2 - 2*g*h)"},
            id="ball-speed-above-it",
        ),
        pytest.param(
            DOME.replace("SPEED", "sqrt(2*g*R/3)"),
            "m g R",
            {"ax": "0", "ay": "-g"},
            id="dome-left-at-its-threshold",
        ),
    ],
)
def test_a_released_contact_acts_in_no_method(text: str, names: str, expected: dict[str, str]) -> None:
    found = _derived(text, names)
    symbols = _symbols(names)
    for name, value in expected.items():
        assert sympy.simplify(found[name] - sympy.sympify(value, locals=symbols)) == 0, name


def test_every_method_and_the_simulation_derive_the_slack_phase() -> None:
    model = load_model(yaml.safe_load(ATWOOD_SLACK.replace("DOMAIN", '"F - 2*m2*g"')), _symbols(ATWOOD))
    derived = uncached(model)
    assert {"lagrange", "newton", "conservation"} <= set(derived.agreement["a1"])
    assert set(derived.simulation) == {"a1", "a2"}
    shown = derived.checks["released contacts"]
    assert "held, its tension m1*(-F + 2*g*m2)/(m1 + m2) would be negative" in shown
    assert "its gap grows as F/m2 - 2*g > 0" in shown


def test_a_scenario_releases_the_contact_the_model_holds() -> None:
    found = derive(load_model(yaml.safe_load(CRATE_SCENARIOS), _symbols(CRATE))).quantities
    m, g, f, alpha = _symbols(CRATE).values()
    assert sympy.simplify(found["normal"] - (m * g - f * sympy.sin(alpha))) == 0
    assert sympy.simplify(found["lifted.rise"] - (f * sympy.sin(alpha) / m - g)) == 0


@pytest.mark.parametrize(
    ("text", "names", "says"),
    [
        pytest.param(
            ATWOOD_SLACK.replace("DOMAIN", '"2*m2*g - F"'),
            ATWOOD,
            "the string is taut wherever F < 2*g*m2, which is the whole domain: it pulls, it does not go "
            "slack (held, its tension m1*(-F + 2*g*m2)/(m1 + m2) is positive there)",
            id="taut-string-declared-slack",
        ),
        pytest.param(
            ATWOOD_SLACK.replace("DOMAIN", '"F"'),
            ATWOOD,
            "the string is taut where F < 2*g*m2: it pulls, it does not go slack",
            id="taut-on-part-of-the-domain",
        ),
        pytest.param(
            LIFTED_CRATE.replace('"F*sin(alpha) - m*g"', '"m*g - F*sin(alpha)"'),
            CRATE,
            "the surface pushes wherever",
            id="crate-too-heavy-to-lift",
        ),
        pytest.param(
            DOME.replace("SPEED", "sqrt(g*R/3)"),
            "m g R",
            "the surface pushes on the whole domain: the body stays on it, it does not leave it (held, its "
            "normal force g*m/3 is positive there)",
            id="dome-too-slow-to-leave",
        ),
        pytest.param(
            ATWOOD_ONE_COORDINATE.replace("STRING", BY_HAND),
            ATWOOD,
            "the coordinates build it in: its gap is 0 wherever they are, so its bodies cannot part. Give m1 "
            "and m2 coordinates of their own (in which the string can open) and state the string under "
            "`constraints:` by its gap",
            id="one-coordinate-for-both-masses",
        ),
        pytest.param(
            BALL_ON_FLOOR.replace("HEIGHT", "0").replace("RATE", "-v"),
            BALL,
            "its gap closes at the rate -v: the bodies move into the contact",
            id="ball-moving-into-the-floor",
        ),
        pytest.param(
            BALL_ON_FLOOR.replace("HEIGHT", "-h").replace("RATE", "0"),
            BALL,
            "its gap -h is negative at the state: the bodies would overlap",
            id="ball-below-the-floor",
        ),
    ],
)
def test_a_release_that_is_not_the_physics_is_refused(text: str, names: str, says: str) -> None:
    with pytest.raises(DerivationError) as caught:
        _derived(text, names)
    assert caught.value.path == ("released", 0)
    assert says in caught.value.message


@pytest.mark.parametrize(
    ("edit", "path", "says"),
    [
        pytest.param(
            {"friction": [{"constraint": "floor", "body": "crate", "coefficient": "mu", "sliding": "x"}]},
            ("friction", 0, "constraint"),
            "with no normal force there is no friction",
            id="friction-at-a-released-surface",
        ),
        pytest.param(
            {"quantities": {"normal": {"force": "floor"}}},
            ("quantities", "normal"),
            "constraint 'floor' is released: it exerts no force",
            id="force-of-a-released-surface",
        ),
        pytest.param(
            {"released": ["ground"]}, ("released", 0), "unknown constraint 'ground'", id="unknown-constraint"
        ),
        pytest.param(
            {"constraints": {"floor": {"kind": "other", "gap": "y_crate"}}},
            ("released", 0),
            "it holds both ways and cannot be released",
            id="a-bilateral-constraint",
        ),
    ],
)
def test_a_release_that_does_not_read_is_refused_when_loaded(
    edit: dict[str, object], path: tuple[str | int, ...], says: str
) -> None:
    data = {**yaml.safe_load(LIFTED_CRATE), **edit}
    with pytest.raises(SpecErrors) as caught:
        load_model(data, _symbols(f"{CRATE} mu"))
    assert [e.path for e in caught.value.errors if says in e.message] == [path]


@pytest.mark.parametrize(
    ("text", "names", "element"),
    [
        pytest.param(ATWOOD_ONE_COORDINATE.replace("STRING", PULLEY), ATWOOD, "pulley", id="a-pulley"),
        pytest.param(
            "gravity: g\nelements:\n  floor: {kind: surface, body: block, mass: m, coordinate: x, friction: 0}\n"
            "released: [floor]\nquantities:\n  a: {acceleration: x}\n",
            "m g",
            "surface",
            id="a-block-on-a-surface",
        ),
    ],
)
def test_an_elements_constraint_released_is_asked_for_by_hand(text: str, names: str, element: str) -> None:
    with pytest.raises(SpecErrors) as caught:
        load_model(yaml.safe_load(text), _symbols(names))
    [error] = caught.value.errors
    assert error.path == ("released", 0)
    assert f"comes from the {element} element" in error.message
    assert "state it under `constraints:` by its gap, its bodies on coordinates of their own" in error.message


def test_a_pulley_element_released_with_its_ends_apart_asks_for_the_string_as_a_constraint() -> None:
    data = yaml.safe_load(ATWOOD_ONE_COORDINATE.replace("STRING", PULLEY))
    data["coordinates"] = ["y1", "y2"]
    data["bodies"] = {
        "m1": {"mass": "m1", "position": {"y": "y1"}},
        "m2": {"mass": "m2", "position": {"y": "y2"}},
    }
    with pytest.raises(SpecErrors) as caught:
        load_model(data, _symbols(ATWOOD))
    [error] = caught.value.errors
    assert error.path == ("elements", "string", "ends")
    assert "a string released to go slack is stated under `constraints:` by its gap" in error.message


def test_a_quantity_taken_beyond_a_released_contact_is_refused_there() -> None:
    with pytest.raises(DerivationError) as caught:
        _derived(BALL_THROWN_UP.replace("WHERE", '"-h"'), BALL)
    assert caught.value.path == ("quantities", "there", "at")
    assert "the released constraint 'floor' has the gap -h there, negative" in caught.value.message
