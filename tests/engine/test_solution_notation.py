"""Worked solutions name what they use as a textbook does: every constraint force by its physical name,
no two things written alike, nothing written as the d of d/dt, every printed symbol defined.

The names are checked for every bank problem (cheap: no derivation); the derived solutions for a few
always and a daily sample of the rest (`physcheck bank verify`, in `make test`, audits every one)."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import pytest
import sympy

from physics.engine import derive, load_model
from physics.engine.notation import RESERVED, Source, audit, notation_of
from problems.modelinfo import load_doc_model
from problems.symbols import symbol_table
from tests.bank import bank_documents
from tests.sampling import sampled

MODELLED = sorted(doc_id for doc_id, doc in bank_documents().items() if doc.model is not None)
ALWAYS = ["moving-wedge", "yo-yo", "lennard-jones", "ladder-slipping", "flywheel", "incline-pulley-friction"]


def _model(problem: str) -> Any:
    doc = bank_documents()[problem]
    return load_doc_model(doc, symbol_table(doc))


@pytest.mark.parametrize("problem", MODELLED)
def test_every_constraint_force_and_coordinate_has_a_name_that_clashes_with_nothing(problem: str) -> None:
    model = _model(problem)
    notation = notation_of(model)
    for key, force in notation.forces.items():
        assert force.source in (Source.AUTHOR, Source.PHYSICS), (key, force)
        assert force.words.strip(), key
    problem_tex = {sympy.latex(p) for p in model.parameters}
    names = [
        n.tex
        for n in (*notation.coordinates.values(), *notation.forces.values(), *notation.cartesian.values())
    ]
    assert len(names) == len(set(names)), names
    for key, name in notation.coordinates.items():
        assert name.words.strip(), key
        if name.source is not Source.PROBLEM:
            assert name.tex not in RESERVED | problem_tex, (key, name.tex)


@pytest.mark.slow
@pytest.mark.parametrize("problem", ALWAYS + sampled([p for p in MODELLED if p not in ALWAYS], 4, "notation"))
def test_no_step_of_any_method_uses_an_undefined_or_clashing_symbol(problem: str) -> None:
    model = _model(problem)
    derivation = derive(model)
    assert derivation.notation is not None
    assert audit(model, derivation.notation, derivation.methods) == []


CASES: list[tuple[str, Mapping[str, Any], Mapping[str, str]]] = [
    # (what, model, expected TeX by coordinate or constraint name)
    (
        "a coordinate named d is renamed: it would read as the d of d/dt",
        {
            "coordinates": ["d"],
            "bodies": {"b": {"mass": "m", "position": {"y": "-d"}}},
            "gravity": "g",
            "quantities": {"a": {"acceleration": "d"}},
        },
        {"d": "q"},
    ),
    (
        "a problem symbol T (a period) keeps the tension off T, and the kinetic energy too",
        {
            "coordinates": ["s"],
            "bodies": {
                "b": {"mass": "m", "position": {"y": "-1"}},
                "c": {"mass": "m", "position": {"y": "-s"}},
            },
            "gravity": "g",
            "constraints": {"rope": {"kind": "string", "gap": "y_b + 1"}},
            "quantities": {"a": {"acceleration": "s"}},
        },
        {"rope": r"\mathcal{T}"},
    ),
    (
        "the author's notation names the force and the coordinate",
        {
            "coordinates": ["d"],
            "bodies": {"b": {"mass": "m", "position": {"y": "-d"}}},
            "gravity": "g",
            "notation": {"d": {"symbol": "h", "says": "the drop"}, "b": {"says": "the bob"}},
            "quantities": {"a": {"acceleration": "d"}},
        },
        {"d": "h"},
    ),
    (
        "a support's letter R is shared by its own components only: the string beside it keeps a tension's",
        {
            "coordinates": ["s"],
            "bodies": {
                "block": {"mass": "m", "position": {"x": "s", "y": "0"}},
                "weight": {"mass": "m", "position": {"x": "0", "y": "-s"}},
            },
            "gravity": "g",
            "constraints": {
                "table": {"kind": "surface", "gap": "y_block"},
                "wall": {"kind": "other", "gap": "x_weight"},
            },
            "elements": {
                "string": {
                    "kind": "pulley",
                    "ends": [{"body": "block", "pulls": "right"}, {"body": "weight", "pulls": "up"}],
                }
            },
            "quantities": {"a": {"acceleration": "s"}},
        },
        {"wall": "R_{x}", "string": r"\mathcal{T}"},
    ),
]


@pytest.mark.parametrize(("what", "data", "expected"), CASES, ids=[c[0] for c in CASES])
def test_names_avoid_clashes(what: str, data: Mapping[str, Any], expected: Mapping[str, str]) -> None:
    symbols = {n: sympy.Symbol(n, positive=True) for n in ("m", "g", "T")}
    notation = notation_of(load_model(data, symbols))
    found = {
        **{k: v.tex for k, v in notation.coordinates.items()},
        **{k: v.tex for k, v in notation.forces.items()},
    }
    for key, tex in expected.items():
        assert found[key] == tex, (what, found)
    if "rope" in expected:
        assert notation.letters.kinetic not in ("T", expected["rope"])


def test_the_wedge_names_its_normal_forces_as_the_seed_does() -> None:
    notation = notation_of(_model("moving-wedge"))
    assert notation.forces["incline"].tex == "N_{1}"  # between the block and the wedge
    assert notation.forces["inclineFloor"].tex == "N_{2}"  # from the floor on the wedge
    assert "floor" in notation.forces["inclineFloor"].words


def test_a_yoyo_derivation_writes_the_tension_and_no_internal_name() -> None:
    derivation = derive(_model("yo-yo"))
    newton = next(m for m in derivation.methods if m.name == "newton")
    written = " ".join(s.latex for s in newton.steps)
    assert r"\lambda" not in written and "T r" in written  # the string's torque, T times r
    assert newton.forces == ("string",)
    dalembert = next(m for m in derivation.methods if m.name == "dalembert")
    assert dalembert.forces == ()  # constraint forces do no virtual work


def test_a_speed_where_the_motion_gets_to_names_the_body_in_the_problems_words() -> None:
    # two carts pushed apart by a spring: cart2's speed once they part, titled without the name cart2
    data = {
        "coordinates": ["x1", "d"],
        "bodies": {
            "cart1": {"mass": "m1", "position": {"x": "x1"}},
            "cart2": {"mass": "m2", "position": {"x": "x1 + d"}},
        },
        "elements": {
            "spring": {"kind": "spring", "between": ["cart1", "cart2"], "stiffness": "k", "length": "L0"}
        },
        "domain": {"ranges": {"d": ["0", "oo"]}, "positive": ["L0 - c"]},
        "state": {"x1": 0, "d": "L0 - c"},
        "notation": {"cart1": {"says": "the first cart"}, "cart2": {"says": "the second cart"}},
        "quantities": {"parting": {"speed": "cart2", "at": {"d": "L0"}}},
    }
    model = load_model(data, {n: sympy.Symbol(n, positive=True) for n in ["m1", "m2", "k", "L0", "c"]})
    derivation = derive(model)
    assert derivation.notation is not None
    assert audit(model, derivation.notation, derivation.methods) == []
    titles = [s.title for m in derivation.methods for s in m.steps]
    assert "Speed of «cart2» there" in titles


SLIPPING: list[tuple[str, Mapping[str, Any]]] = [
    (
        "a rolling element's grip, named by the element (hoopRolling)",
        {
            "elements": {
                "hoop": {
                    "kind": "rolling",
                    "mass": "m",
                    "radius": "R",
                    "inertia": "m*R^2",
                    "angle": "theta",
                    "coordinate": "s",
                }
            },
            "gravity": "g",
            "domain": {"ranges": {"theta": ["0", "pi/2"]}},
            "quantities": {
                "least": {
                    "slipping": "mu_s",
                    "friction": "hoopRolling",
                    "normal": "hoop",
                    "coefficient": "mu_s",
                }
            },
        },
    ),
    (
        "a grip written by hand",
        {
            "coordinates": [],
            "bodies": {"block": {"mass": "m", "position": {"x": 0, "y": 0}}},
            "gravity": "g",
            "constraints": {
                "slope": {"kind": "surface", "gap": "x_block*sin(theta) + y_block*cos(theta)"},
                "hold": {"kind": "other", "gap": "y_block*sin(theta) - x_block*cos(theta)"},
            },
            "domain": {"ranges": {"theta": ["0", "pi/2"]}},
            "quantities": {
                "steepest": {
                    "slipping": "theta",
                    "friction": "hold",
                    "normal": "slope",
                    "coefficient": "mu_s",
                }
            },
        },
    ),
]


@pytest.mark.parametrize(("what", "data"), SLIPPING, ids=[c[0] for c in SLIPPING])
def test_a_limit_of_static_friction_names_the_friction_force_as_the_solution_writes_it(
    what: str, data: Mapping[str, Any]
) -> None:
    symbols = {n: sympy.Symbol(n, positive=True) for n in ["m", "R", "theta", "g", "mu_s"]}
    model = load_model(data, symbols)
    derivation = derive(model)
    assert derivation.notation is not None
    assert audit(model, derivation.notation, derivation.methods) == []
    titles = [s.title for m in derivation.methods for s in m.steps if s.title.startswith("Limit of static")]
    assert titles and all("$" in t for t in titles), titles


def _hung_beside(notation: Mapping[str, Any] | None) -> Any:
    """A block hung under a pulley's rim at x = R, which a constraint `side` holds there beside the axle's."""
    data: dict[str, Any] = {
        "coordinates": ["s"],
        "bodies": {
            "wheel": {"mass": "M", "inertia": "M*R^2/2", "position": {"x": 0, "y": 0}, "angle": "-s/R"},
            "block": {"mass": "m", "position": {"x": "R", "y": "-s"}},
        },
        "gravity": "g",
        "constraints": {
            "string": {"kind": "string", "gap": "y_block - y_wheel - R*phi_wheel"},
            "axleX": {"kind": "other", "gap": "x_wheel"},
            "axleY": {"kind": "other", "gap": "y_wheel"},
            "side": {"kind": "other", "gap": "x_block - R"},
        },
        "quantities": {"a": {"acceleration": "s"}},
        **({"notation": notation} if notation else {}),
    }
    return load_model(data, {n: sympy.Symbol(n, positive=True) for n in ("m", "M", "R", "g")})


def test_each_support_of_several_has_its_own_number_shared_by_its_two_components() -> None:
    """The block held beside the axle: its support's force was written P_{x} like the axle's."""
    model = _hung_beside(None)
    forces = {key: name.tex for key, name in notation_of(model).forces.items()}
    assert forces == {"string": "T", "axleX": "P_{x,1}", "axleY": "P_{y,1}", "side": "P_{x,2}"}
    assert not audit(model, notation_of(model), [])


def test_two_forces_written_alike_are_refused_saying_how_to_name_one_apart() -> None:
    model = _hung_beside({"side": {"symbol": "Q"}, "axleX": {"symbol": "Q"}})
    (fault,) = [f for f in audit(model, notation_of(model), []) if "both written" in f]
    assert "force side and force axleX are both written 'Q'" in fault
    assert "give side a symbol of its own under the model's `notation:`" in fault
    named = _hung_beside({"side": {"symbol": "Q", "says": "the sideways force on the block"}})
    assert not [f for f in audit(named, notation_of(named), []) if "both written" in f]


def test_newtons_constraints_for_the_accelerations_say_which_constraint_is_differentiated() -> None:
    # "The same constraint for the accelerations (the wedge stays on the floor), differentiated twice
    # in time" split the constraint from what was done to it
    newton = next(m for m in derive(_model("moving-wedge")).methods if m.name == "newton")
    titles = [s.title for s in newton.steps if "differentiated" in s.title]
    assert titles == [  # «wedge»: the body, in the problem's words on the page
        "Constraint («wedge» stays on the floor) differentiated twice in time, for the accelerations",
        "Constraint («wedge» stays in contact with «block») differentiated twice in time, for the accelerations",
    ]


@pytest.mark.parametrize(
    ("problem", "said"),
    [
        ("moving-wedge", {"wedge": "the wedge", "block": "the block"}),
        ("yo-yo", {"yoyo": "the yo-yo"}),  # the author's words
        ("cart-collision", {"cart1": "the cart $m_{1}$", "cart2": "the cart $m_{2}$"}),  # by their masses
        ("double-pendulum", {"bob1": "the upper bob", "bob2": "the lower bob"}),  # the author's words
    ],
)
def test_bodies_whose_names_say_alike_are_told_apart(problem: str, said: Mapping[str, str]) -> None:
    # two carts were each "the cart": "Newton's second law for the cart, along x", twice, for two bodies
    assert dict(notation_of(_model(problem)).bodies) == said


def test_bodies_of_one_mass_whose_names_say_alike_are_told_apart_by_their_numbers() -> None:
    # the double pendulum without the words its notation gives: one mass m, so bob 1 and bob 2
    doc = bank_documents()["double-pendulum"]
    assert doc.model is not None
    unsaid = doc.model_copy(update={"model": {k: v for k, v in doc.model.items() if k != "notation"}})
    model = load_doc_model(unsaid, symbol_table(unsaid))
    assert dict(notation_of(model).bodies) == {"bob1": "bob 1", "bob2": "bob 2"}


def test_a_forces_words_under_the_notation_are_said_with_the_letter_physics_gives_it() -> None:
    # `upper: {says: …}` without a symbol was dropped: "the tension in the upper string", of a rod
    forces = notation_of(_model("double-pendulum")).forces
    assert (forces["upper"].tex, forces["upper"].words) == (
        "T_{1}",
        "the tension in the upper rod, which pulls the upper bob towards the fixed point",
    )
