"""Composable elements: each expands to exactly the low-level model an author would write by hand, so
it derives the same answers; what it generates is physically right; its faults name the element."""

from __future__ import annotations

from dataclasses import replace
from typing import Any

import pytest
import sympy
import yaml
from sympy import sqrt

from physics.engine import derive, load_model
from physics.errors import SpecErrors
from tests.engine.conftest import BANK, LOWLEVEL

REWRITTEN = sorted(p.stem for p in LOWLEVEL.glob("*.yaml"))


def positive(*names: str) -> dict[str, sympy.Symbol]:
    return {n: sympy.Symbol(n, positive=True) for n in names}


@pytest.mark.parametrize("problem", REWRITTEN)
def test_bank_model_written_with_elements_is_the_hand_written_model(problem: str) -> None:
    data = yaml.safe_load((LOWLEVEL / f"{problem}.yaml").read_text())
    assert "elements" in yaml.safe_load(
        (LOWLEVEL.parents[2] / "problems" / "bank" / problem / "model.yaml").read_text()
    )
    names = yaml.safe_load((BANK / problem / "problem.yaml").read_text())["symbols"]
    table = {n: sympy.Symbol(n, positive=True) for n in names}
    written = load_model(yaml.safe_load((BANK / problem / "model.yaml").read_text()), table)
    # the notation names things for worked solutions, the element records draw figures: not physics
    assert replace(written, notation=(), elements=()) == replace(load_model(data, table), notation=())


def test_the_model_keeps_each_element_as_written_with_what_it_generated() -> None:
    model = {
        "bodies": {"m2": {"mass": "m2", "position": {"y": "s*cos(theta)"}}},
        "potentials": [{"bodies": ["m2"], "anchor": {"y": 0}, "distance": "d", "energy": "k*d^2/2"}],
        "gravity": "g",
        "quantities": {"acceleration": {"acceleration": "s"}},
        "elements": {
            "string": {
                "kind": "pulley",
                "ends": [{"body": "m1", "pulls": "left"}, {"body": "m2", "pulls": "up"}],
            },
            "ramp": {"kind": "incline", "body": "m1", "mass": "m1", "angle": "theta", "coordinate": "s"},
            "spring": {"kind": "spring", "between": ["m1", {"x": 0}], "stiffness": "k"},
        },
    }
    loaded = load_model(model, positive("m1", "m2", "theta", "g", "k"))
    ramp, string, spring = loaded.elements  # a pulley after the body it pulls on
    assert (ramp.kind, ramp.name, ramp.fields["angle"]) == ("incline", "ramp", "theta")
    assert (ramp.bodies, ramp.constraints, ramp.coordinates) == (("m1",), ("ramp",), ("s",))
    assert (string.kind, string.bodies, string.constraints) == ("pulley", (), ("string",))
    assert string.fields["ends"][0] == {"body": "m1", "pulls": "left"}
    assert spring.potentials == ("potential1",)  # after the hand-written one
    assert [p.name for p in loaded.potentials] == ["potential0", "potential1"]
    by_hand = {key: model[key] for key in ("bodies", "gravity", "quantities")} | {"coordinates": ["s"]}
    assert load_model(by_hand, positive("m2", "g", "theta")).elements == ()


def _derived(model: dict[str, Any], *names: str) -> dict[str, sympy.Expr]:
    return dict(derive(load_model(model, positive(*names))).quantities)


def _same(a: sympy.Expr, b: sympy.Expr) -> bool:
    return sympy.simplify(a - b) == 0


def test_pulley_with_inertia_slows_the_atwood_machine_and_splits_the_tension() -> None:
    model = {
        "coordinates": ["s"],
        "bodies": {
            "m1": {"mass": "m1", "position": {"y": "s"}},
            "m2": {"mass": "m2", "position": {"y": "-s"}},
        },
        "gravity": "g",
        "elements": {
            "string": {
                "kind": "pulley",
                "ends": [{"body": "m1", "pulls": "up"}, {"body": "m2", "pulls": "up"}],
                "inertia": "I",
                "radius": "R",
                "mass": "M",
            }
        },
        "quantities": {
            "a": {"acceleration": "s"},
            "T1": {"force": "string1"},
            "T2": {"force": "string2"},
            "axle": {"force": "stringAxleY"},
        },
    }
    m1, m2, g, i, r, big = positive("m1", "m2", "g", "I", "R", "M").values()
    q = _derived(model, "m1", "m2", "g", "I", "R", "M")
    a = (m2 - m1) * g / (m1 + m2 + i / r**2)
    assert _same(q["a"], a)
    assert _same(q["T1"], m1 * (g + a))
    assert _same(q["T2"], m2 * (g - a))
    assert _same(q["axle"], big * g + q["T1"] + q["T2"])


def test_rigid_pendulum_oscillates_with_the_physical_pendulum_frequency() -> None:
    model = {
        "elements": {
            "rod": {
                "kind": "pendulum",
                "mass": "m",
                "inertia": "m*L^2/12",
                "distance": "L/2",
                "coordinate": "phi",
            }
        },
        "gravity": "g",
        "quantities": {"omega": {"angular_frequency": "phi"}},
    }
    _, length, g = positive("m", "L", "g").values()
    assert _same(_derived(model, "m", "L", "g")["omega"], sqrt(3 * g / (2 * length)))


def test_surface_friction_decelerates_a_sliding_crate() -> None:
    model = {
        "elements": {
            "floor": {"kind": "surface", "body": "crate", "mass": "m", "coordinate": "x", "friction": "mu"}
        },
        "gravity": "g",
        "state": {"x_dot": "v"},
        "quantities": {"a": {"acceleration": "x"}, "N": {"force": "floor"}},
    }
    m, mu, g, _ = positive("m", "mu", "g", "v").values()
    q = _derived(model, "m", "mu", "g", "v")
    assert _same(q["a"], -mu * g)
    assert _same(q["N"], m * g)


def test_spring_between_two_bodies_oscillates_with_the_reduced_mass() -> None:
    model = {
        "coordinates": ["X", "r"],
        "bodies": {
            "a": {"mass": "m1", "position": {"x": "X - m2*r/(m1 + m2)"}},
            "b": {"mass": "m2", "position": {"x": "X + m1*r/(m1 + m2)"}},
        },
        "elements": {"spring": {"kind": "spring", "between": ["a", "b"], "stiffness": "k", "length": "L0"}},
        "domain": {"ranges": {"r": ["0", "oo"]}},  # b stays to the right of a: the spring's length is r
        "quantities": {"omega": {"angular_frequency": "r"}, "rest": {"equilibrium": "r"}},
    }
    m1, m2, k, l0 = positive("m1", "m2", "k", "L0").values()
    q = _derived(model, "m1", "m2", "k", "L0")
    assert _same(q["omega"], sqrt(k * (m1 + m2) / (m1 * m2)))
    assert _same(q["rest"], l0)


def test_rolling_up_a_slope_turns_the_body_clockwise_and_friction_points_back() -> None:
    model = {
        "elements": {
            "ball": {
                "kind": "rolling",
                "mass": "m",
                "radius": "R",
                "inertia": "2*m*R^2/5",
                "angle": "theta",
                "coordinate": "s",
                "direction": "up",
            }
        },
        "gravity": "g",
        "domain": {"ranges": {"theta": ["0", "pi/2"]}},
        "quantities": {"a": {"acceleration": "s"}, "f": {"force": "ballRolling"}},
    }
    m, _, th, g = positive("m", "R", "theta", "g").values()
    q = _derived(model, "m", "R", "theta", "g")
    assert _same(q["a"], -sympy.Rational(5, 7) * g * sympy.sin(th))
    # the friction opposes the coordinate's direction with a positive multiplier: it points up the slope
    assert _same(q["f"], -m * g * sympy.sin(th) * sympy.Rational(2, 7))


def _errors(model: dict[str, Any], *names: str) -> dict[str, str]:
    with pytest.raises(SpecErrors) as caught:
        load_model(model, positive(*names))
    found: dict[str, str] = {}
    for error in caught.value.errors:  # one fault may cause others at the same path: keep them all
        where = ".".join(map(str, error.path))
        found[where] = found.get(where, "") + error.message + "\n"
    return found


@pytest.mark.parametrize(
    ("element", "path", "says"),
    [
        ({"kind": "lever"}, "elements.ramp.kind", "unknown kind 'lever'"),
        ({"kind": "incline", "mass": "m", "angle": "theta"}, "elements.ramp.coordinate", "required"),
        (
            {"kind": "incline", "mass": "m", "angle": "theta", "coordinate": "s", "slope": 1},
            "elements.ramp.slope",
            "unknown field",
        ),
        (
            {"kind": "incline", "mass": "m +* 2", "angle": "theta", "coordinate": "s"},
            "elements.ramp",
            "bodies.ramp.mass",
        ),
        (
            {"kind": "incline", "mass": "m", "angle": "theta", "coordinate": "s", "direction": "sideways"},
            "elements.ramp.direction",
            "expected one of",
        ),
        (
            {"kind": "pulley", "ends": [{"body": "ghost", "pulls": "up"}, {"body": "ghost", "pulls": "up"}]},
            "elements.ramp.ends.0.body",
            "no body 'ghost'",
        ),
        ({"kind": "pendulum", "mass": "m", "coordinate": "phi"}, "elements.ramp.length", "required"),
        ({"kind": "spring", "between": ["a"], "stiffness": "k"}, "elements.ramp.between", "two ends"),
        ({"kind": "rotating", "rate": "k", "bodies": ["ghost"]}, "elements.ramp.bodies.0", "no body 'ghost'"),
    ],
)
def test_a_faulty_element_is_reported_at_its_own_path(element: dict[str, Any], path: str, says: str) -> None:
    errors = _errors({"elements": {"ramp": element}, "quantities": {}}, "m", "theta", "k")
    assert path in errors, errors
    assert says in errors[path]


def test_a_pulley_whose_ends_do_not_keep_the_string_length_is_refused() -> None:
    model = {
        "coordinates": ["s"],
        "bodies": {"m1": {"mass": "m", "position": {"y": "s"}}, "m2": {"mass": "m", "position": {"y": "s"}}},
        "elements": {
            "string": {
                "kind": "pulley",
                "ends": [{"body": "m1", "pulls": "up"}, {"body": "m2", "pulls": "up"}],
            }
        },
        "quantities": {},
    }
    assert "string's length" in _errors(model, "m")["elements.string.ends"]


def test_a_movable_pulley_halves_its_bodys_motion_and_doubles_the_pull_on_it() -> None:
    """A block on a table, its string over the edge and under a movable pulley carrying m2: the 2:1
    ratio of the accelerations, and twice the tension holding the pulley (m2 g - 2T = m2 a/2)."""
    model = {
        "coordinates": ["s"],
        "bodies": {
            "m1": {"mass": "m1", "position": {"x": "s"}},
            "m2": {"mass": "m2", "position": {"y": "-s/2"}},
        },
        "gravity": "g",
        "elements": {
            "string": {
                "kind": "pulley",
                "ends": [{"body": "m1", "pulls": "right"}, {"under": "m2", "pulls": "up"}],
            }
        },
        "quantities": {"a": {"acceleration": "s"}, "T": {"force": "string"}},
    }
    m1, m2, g = positive("m1", "m2", "g").values()
    found = _derived(model, "m1", "m2", "g")
    assert sympy.simplify(found["a"] - 2 * m2 * g / (4 * m1 + m2)) == 0
    assert sympy.simplify(m2 * g - 2 * found["T"] - m2 * found["a"] / 2) == 0


def test_the_movable_pulley_bank_model_is_the_string_whose_slack_counts_the_pulley_twice() -> None:
    by_hand = yaml.safe_load(
        """
        coordinates: [d]
        bodies:
          m1: {mass: m1, position: {y: "-2*d"}}
          m2: {mass: m2, position: {y: d}}
        gravity: g
        constraints:
          string: {kind: string, gap: "y_m1 + 2*y_m2"}
        quantities:
          acceleration: {acceleration: d}
          tension: {force: string}
        """
    )
    table = positive("m1", "m2", "g")
    written = load_model(yaml.safe_load((BANK / "movable-pulley" / "model.yaml").read_text()), table)
    assert replace(written, notation=(), elements=()) == replace(load_model(by_hand, table), notation=())


@pytest.mark.parametrize(
    ("end", "says"),
    [
        ({"under": "m2", "pulls": "up"}, "a movable pulley moves half as far"),  # m2 written as a free end
        ({"under": "m2", "body": "m2", "pulls": "up"}, "either the body at this end or"),
    ],
)
def test_a_movable_pulley_stated_wrongly_is_refused_saying_why(end: dict[str, str], says: str) -> None:
    model = {
        "coordinates": ["s"],
        "bodies": {"m1": {"mass": "m", "position": {"y": "-s"}}, "m2": {"mass": "m", "position": {"y": "s"}}},
        "elements": {"string": {"kind": "pulley", "ends": [{"body": "m1", "pulls": "up"}, end]}},
        "quantities": {},
    }
    errors = _errors(model, "m")
    assert any(says in message for message in errors.values()), errors


def test_a_pull_direction_that_is_not_a_unit_vector_is_refused() -> None:
    model = {
        "coordinates": ["s"],
        "bodies": {"m1": {"mass": "m", "position": {"y": "s"}}, "m2": {"mass": "m", "position": {"y": "-s"}}},
        "elements": {
            "string": {
                "kind": "pulley",
                "ends": [{"body": "m1", "pulls": {"y": 2}}, {"body": "m2", "pulls": "up"}],
            }
        },
        "quantities": {},
    }
    assert "unit vector" in _errors(model, "m")["elements.string.ends.0.pulls"]


def test_an_element_may_not_redefine_a_hand_written_body() -> None:
    model = {
        "coordinates": ["s"],
        "bodies": {"block": {"mass": "m", "position": {"x": "s"}}},
        "elements": {
            "ramp": {"kind": "incline", "body": "block", "mass": "m", "angle": "theta", "coordinate": "s"}
        },
        "quantities": {},
    }
    assert "already defined" in _errors(model, "m", "theta")["elements.ramp"]
