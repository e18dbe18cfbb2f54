"""Fictitious forces and d'Alembert's principle as methods of their own: where a frame is declared or
implied (a wedge, a rotating element, `frame:`), Newton's law in that frame agrees with the other
methods; d'Alembert's principle where the constraints do no work; a frame declared wrong is refused."""

from __future__ import annotations

from typing import Any

import pytest
import sympy

from physics.engine import derive, load_model
from physics.engine.dalembert import DAlembertMethod
from physics.engine.frames import FramesMethod
from physics.engine.mechanics import Mechanics
from physics.engine.method import NotApplicable
from physics.errors import DerivationError, SpecErrors

NAMES = ("m", "M", "k", "L0", "omega", "g", "m1", "m2", "mu")
SYMBOLS = {name: sympy.Symbol(name, positive=True) for name in NAMES}
m, M, k, L0, omega, g, m1, m2, mu = (SYMBOLS[n] for n in NAMES)


def bead_on_spinning_rod(frame: dict[str, Any] | None = None) -> dict[str, Any]:
    """A bead on a horizontal rod spun about a vertical axis through one end, held by a spring of
    natural length L0 from the axis: at rest in the rod's frame where k (r - L0) = m omega^2 r; released
    from rest at r = L0 it starts with omega^2 L0 outwards."""
    model: dict[str, Any] = {
        "coordinates": ["r"],
        "bodies": {"bead": {"mass": "m", "position": {"x": "r", "y": 0}}},
        "gravity": "g",
        "constraints": {"rod": {"kind": "surface", "gap": "y_bead"}},
        "potentials": [{"bodies": ["bead"], "anchor": {"x": 0}, "distance": "d", "energy": "k*(d - L0)^2/2"}],
        "domain": {"ranges": {"r": ["0", "oo"]}, "positive": ["k - m*omega^2"]},
        "quantities": {
            "rest_radius": {"equilibrium": "r"},
            "frequency": {"angular_frequency": "r"},
            "rod_push": {"force": "rod"},
            "start": {"acceleration": "r"},
        },
        "state": {"r": "L0"},
    }
    if frame is None:
        model["elements"] = {"spin": {"kind": "rotating", "rate": "omega", "bodies": ["bead"]}}
    else:  # the centrifugal potential written by hand, beside a hand-declared frame
        model["potentials"].append(
            {"bodies": ["bead"], "anchor": {"x": 0}, "distance": "e", "energy": "-m*omega^2*e^2/2"}
        )
        model["frame"] = frame
    return model


def wedge(angle: str = "pi/6") -> dict[str, Any]:
    """The seed document's moving wedge at a fixed angle (which keeps the test quick)."""
    return {
        "elements": {
            "ramp": {
                "kind": "incline",
                "body": "block",
                "mass": "m",
                "angle": angle,
                "coordinate": "s",
                "wedge": {"body": "wedge", "mass": "M", "coordinate": "X"},
            }
        },
        "gravity": "g",
        "quantities": {"wedge_acceleration": {"acceleration": "X"}, "normal_force": {"force": "ramp"}},
    }


def atwood(friction: bool = False) -> dict[str, Any]:
    """m1 pulled along a table by m2 hanging over a pulley; x: distance m2 has descended."""
    model: dict[str, Any] = {
        "coordinates": ["x"],
        "bodies": {
            "m1": {"mass": "m1", "position": {"x": "x", "y": 0}},
            "m2": {"mass": "m2", "position": {"y": "-x"}},
        },
        "gravity": "g",
        "constraints": {
            "table": {"kind": "surface", "gap": "y_m1"},
            "string": {"kind": "string", "gap": "y_m2 - x_m1"},
        },
        "quantities": {"a": {"acceleration": "x"}},
    }
    if friction:
        model["friction"] = [{"constraint": "table", "body": "m1", "coefficient": "mu", "sliding": "x"}]
        model["domain"] = {"positive": ["m2 - mu*m1"]}
    return model


def _method(cls: type, data: dict[str, Any]) -> Any:
    model = load_model(data, SYMBOLS)
    method = cls(model, Mechanics(model))
    method.derive()
    return model, method


def test_the_rotating_frame_gives_the_equilibrium_and_frequency_every_method_agrees_on() -> None:
    result = derive(load_model(bead_on_spinning_rod(), SYMBOLS))
    assert sympy.simplify(result.quantities["rest_radius"] - k * L0 / (k - m * omega**2)) == 0
    assert sympy.simplify(result.quantities["frequency"] ** 2 - (k / m - omega**2)) == 0
    assert {"frames", "dalembert", "lagrange"} <= set(result.agreement["rest_radius"])
    assert sympy.simplify(result.quantities["start"] - omega**2 * L0) == 0
    assert "frames" in result.agreement["frequency"] and "frames" in result.agreement["rod_push"]
    frames = next(r for r in result.methods if r.name == "frames")
    shown = " ".join(f"{s.title} {s.latex}" for s in frames.steps)
    assert "centrifugal" in shown.lower() and "Coriolis" in shown


def test_newton_in_the_ground_frame_writes_the_centripetal_acceleration() -> None:
    result = derive(load_model(bead_on_spinning_rod(), SYMBOLS))
    newton = next(r for r in result.methods if r.name == "newton")
    assert any("towards the axis" in s.title for s in newton.steps)


def test_a_frame_declared_wrong_is_refused_saying_what_each_method_found() -> None:
    wrong = {"rate": "2*omega", "bodies": ["bead"]}  # the frame turns faster than the model's bead
    with pytest.raises(DerivationError) as caught:
        derive(load_model(bead_on_spinning_rod(wrong), SYMBOLS))
    found = dict((".".join(map(str, path)), message) for path, message in caught.value.items())
    assert "frames gives 5*L0*omega^2" in found["quantities.start"]
    assert "lagrange gives L0*omega^2" in found["quantities.start"]
    # where the frame finds no equilibrium at all, that is not passed over either
    assert "in the model's frame the fictitious forces stopped" in found["quantities.rest_radius"]


def test_a_frame_about_another_axis_is_not_the_model_s_centrifugal_potential() -> None:
    model, frames = _method(
        FramesMethod, bead_on_spinning_rod({"rate": "omega", "axis": "L0/2", "bodies": ["bead"]})
    )
    assert sympy.simplify(frames.answer(model.quantity("start")) - omega**2 * L0 * 3 / 2) == 0


def test_a_frame_declared_right_by_hand_agrees() -> None:
    model, frames = _method(FramesMethod, bead_on_spinning_rod({"rate": "omega", "bodies": ["bead"]}))
    assert sympy.simplify(frames.answer(model.quantity("rest_radius")) - k * L0 / (k - m * omega**2)) == 0


def test_the_wedge_is_solved_in_its_own_frame_with_the_translational_force() -> None:
    model, frames = _method(FramesMethod, wedge())
    s3 = sympy.sqrt(3)
    expected = -m * g * (s3 / 4) / (M + m / 4)  # -m g sin cos / (M + m sin^2) at 30 degrees
    assert sympy.simplify(frames.answer(model.quantity("wedge_acceleration")) - expected) == 0
    assert (
        sympy.simplify(frames.answer(model.quantity("normal_force")) - M * m * g * (s3 / 2) / (M + m / 4))
        == 0
    )
    shown = " ".join(s.latex for s in frames.steps)
    # -m A, and the block's motion relative to the wedge (primed)
    assert r"\mathrm{trans}" in shown and r"'_{\mathrm{block}}" in shown


def test_dalembert_gives_the_wedge_but_not_its_constraint_force() -> None:
    model, dalembert = _method(DAlembertMethod, wedge())
    expected = -m * g * (sympy.sqrt(3) / 4) / (M + m / 4)
    assert sympy.simplify(dalembert.answer(model.quantity("wedge_acceleration")) - expected) == 0
    with pytest.raises(NotApplicable):
        dalembert.answer(model.quantity("normal_force"))


@pytest.mark.parametrize(("friction", "applies"), [(False, True), (True, False)])
def test_dalembert_applies_only_where_the_constraints_do_no_work(friction: bool, applies: bool) -> None:
    model, dalembert = _method(DAlembertMethod, atwood(friction))
    if applies:
        assert sympy.simplify(dalembert.answer(model.quantity("a")) - m2 * g / (m1 + m2)) == 0
        assert any("Virtual work" in s.title for s in dalembert.steps)
    else:
        with pytest.raises(NotApplicable, match="friction"):
            dalembert.answer(model.quantity("a"))


def test_without_a_frame_the_fictitious_forces_do_not_apply() -> None:
    model, frames = _method(FramesMethod, atwood())
    with pytest.raises(NotApplicable, match="no accelerating or rotating frame"):
        frames.answer(model.quantity("a"))


@pytest.mark.parametrize(
    ("frame", "path", "says"),
    [
        ({"body": "bead", "rate": "omega"}, "frame", "exactly one of body"),
        ({"body": "nobody"}, "frame.body", "unknown body"),
        ({"rate": "omega", "bodies": ["ghost"]}, "frame.bodies.0", "unknown body"),
        ({"rate": "omega"}, "frame.bodies", "list of the bodies"),
        ({"body": "bead", "axis": 1}, "frame.axis", "only a turning frame"),
    ],
)
def test_a_malformed_frame_is_refused_at_its_path(frame: dict[str, Any], path: str, says: str) -> None:
    data = bead_on_spinning_rod(frame)
    with pytest.raises(SpecErrors) as caught:
        load_model(data, SYMBOLS)
    found = {".".join(map(str, e.path)): e.message for e in caught.value.errors}
    assert says in found[path]


def test_a_rotating_element_beside_a_declared_frame_is_refused() -> None:
    data = bead_on_spinning_rod()
    data["frame"] = {"body": "bead"}
    with pytest.raises(SpecErrors) as caught:
        load_model(data, SYMBOLS)
    found = {".".join(map(str, e.path)): e.message for e in caught.value.errors}
    assert "already has a frame" in found["elements.spin"]


def test_a_wedge_implies_its_frame_and_a_declared_frame_replaces_it() -> None:
    assert load_model(wedge(), SYMBOLS).frame.body == "wedge"  # type: ignore[union-attr]
    data = wedge()
    data["frame"] = {"body": "block"}
    assert load_model(data, SYMBOLS).frame.body == "block"  # type: ignore[union-attr]
