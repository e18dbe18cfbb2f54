"""Lagrangian, kinetic-energy and potential-energy parts, tried as students would: every equivalent form
people write is accepted (a multiple of L, L plus a total time derivative, V from another level, the
velocity written x', ẋ, \\dot{x}, dx/dt or xdot), every wrong one refused, with feedback that names the
physics. Hand-written tables over four systems, checked ad hoc (`POST /v1/check` bodies, no engine) and
on the bank's own yo-yo, whose model gives each body's kinetic energy."""

from __future__ import annotations

from functools import cache

import pytest
from pydantic import TypeAdapter

from physics.checking import preview, run_job
from physics.verdict import Outcome, Reason, Verdict
from problems.compiled import compile_problem
from problems.kinds import CheckIn
from tests.bank import bank_documents

_POSITIVE = {"dimension": "kg"}
SYSTEMS = {
    # block on a moving wedge (the seed's problem): X the wedge, s the block down the slope
    "wedge": {
        "coordinates": ["X", "s"],
        "kinetic": "(M+m)/2*X_dot^2 + m*X_dot*s_dot*cos(theta) + m/2*s_dot^2",
        "potential": "-m*g*s*sin(theta)",
        "symbols": {
            "m": _POSITIVE,
            "M": _POSITIVE,
            "g": {"dimension": "m/s^2"},
            "theta": {"range": ["0", "pi/2"]},
        },
    },
    # pendulum (length L) hanging from a cart on a frictionless track
    "cart": {
        "coordinates": ["X", "phi"],
        "kinetic": "(M+m)/2*X_dot^2 + m*L*X_dot*phi_dot*cos(phi) + m*L^2/2*phi_dot^2",
        "potential": "-m*g*L*cos(phi)",
        "symbols": {"m": _POSITIVE, "M": _POSITIVE, "g": {"dimension": "m/s^2"}, "L": {"dimension": "m"}},
    },
    # a mass on a vertical spring, x down from the spring's natural length
    "spring": {
        "coordinates": ["x"],
        "kinetic": "m/2*x_dot^2",
        "potential": "k/2*x^2 - m*g*x",
        "symbols": {"m": _POSITIVE, "k": {"dimension": "N/m"}, "g": {"dimension": "m/s^2"}},
    },
    # a yo-yo unwinding (d down), rolling on its string: I = m q^2 about its axis, axle radius r
    "yoyo": {
        "coordinates": ["d"],
        "kinetic": "m/2*d_dot^2 + m*q^2/(2*r^2)*d_dot^2",
        "potential": "-m*g*d",
        "symbols": {
            "m": _POSITIVE,
            "g": {"dimension": "m/s^2"},
            "q": {"dimension": "m"},
            "r": {"dimension": "m"},
        },
    },
}


def check(kind: str, system: str, answer: str) -> Verdict:
    body = {"kind": kind, "answer": answer, **SYSTEMS[system]}
    if kind == "kinetic_energy":
        body.pop("potential")
    if kind == "potential_energy":
        body.pop("kinetic")
    return run_job(TypeAdapter(CheckIn).validate_python(body).job())


LAGRANGIAN_RIGHT = [
    ("wedge", "(M+m)/2*X'^2 + m X' s' cos(theta) + m/2*s'^2 + m g s sin(theta)"),
    ("wedge", "1/2 M X'^2 + 1/2 m (X'^2 + 2 X' s' cos θ + s'^2) + m g s sin θ"),
    ("wedge", "1/2 M Ẋ^2 + 1/2 m (Ẋ^2 + 2 Ẋ ṡ cos θ + ṡ^2) + m g s sin θ"),
    (
        "wedge",
        r"\frac{1}{2}(M+m)\dot{X}^2 + m\dot{X}\dot{s}\cos\theta + \frac{1}{2}m\dot{s}^2 + m g s\sin\theta",
    ),
    ("wedge", "1/2 (M+m) (dX/dt)^2 + m (dX/dt)(ds/dt) cos θ + 1/2 m (ds/dt)^2 + m g s sin θ"),
    ("wedge", "1/2 (M+m) Xdot^2 + m Xdot sdot cos θ + 1/2 m sdot^2 + m g s sin θ"),
    ("wedge", "(M+m) X'^2 + 2 m X' s' cos θ + m s'^2 + 2 m g s sin θ"),  # 2L
    ("wedge", "-(M+m)/2*X'^2 - m X' s' cos(theta) - m/2*s'^2 - m g s sin(theta)"),  # −L
    ("wedge", "((M+m)/2*X'^2 + m X' s' cos(theta) + m/2*s'^2 + m g s sin(theta))/m"),  # L/m
    ("wedge", "(M+m)/2*X'^2 + m X' s' cos(theta) + m/2*s'^2 + m g s sin(theta) + 7"),  # + constant
    ("wedge", "(M+m)/2*X'^2 + m X' s' cos(theta) + m/2*s'^2 + m g s sin(theta) + 3 m g X'"),  # + d(3mgX)/dt
    ("wedge", "(M+m)/2*X'^2 + m X' s' cos(theta) + m/2*s'^2 + m g s sin(theta) + 2 s s'"),  # + d(s²)/dt
    ("wedge", "1/2 M X'^2 + 1/2 m ((X' + s' cos θ)^2 + (s' sin θ)^2) + m g s sin θ"),  # by components
    ("wedge", "1/2 M X'^2 + 1/2 m ((X' + s' cos θ)^2 + (-s' sin θ)^2) - m g (-s sin θ)"),
    ("wedge", "m g s sin θ + m/2*s'^2 + m X' s' cos θ + (M+m)/2*X'^2"),
    ("cart", "(M+m)/2*X'^2 + m L X' phi' cos(phi) + m L^2/2*phi'^2 + m g L cos(phi)"),
    ("cart", "1/2 M X'^2 + 1/2 m ((X' + L φ' cos φ)^2 + (L φ' sin φ)^2) + m g L cos φ"),
    (
        "cart",
        r"\frac{1}{2}(M+m)\dot{X}^2 + m L\dot{X}\dot{\phi}\cos\phi + \frac{1}{2}mL^2\dot{\phi}^2 + mgL\cos\phi",
    ),
    ("cart", "(M+m) X'^2 + 2 m L X' φ' cos φ + m L^2 φ'^2 + 2 m g L cos φ"),
    (
        "cart",
        "(M+m)/2*X'^2 + m L X' phi' cos(phi) + m L^2/2*phi'^2 - m g L (1 - cos(phi))",
    ),  # V from the bottom
    ("cart", "((M+m)/2*X'^2 + m L X' phi' cos(phi) + m L^2/2*phi'^2 + m g L cos(phi))/(m L^2)"),
    ("spring", "1/2 m x'^2 - 1/2 k x^2 + m g x"),
    ("spring", "m/2*ẋ^2 - k/2*x^2 + m g x"),
    ("spring", "m x'^2 - k x^2 + 2 m g x"),
    ("spring", "1/2 m x'^2 - 1/2 k (x - m g/k)^2"),  # V about the equilibrium: a constant apart
    ("spring", "1/2 m (dx/dt)^2 - 1/2 k x^2 + m g x + 5 sqrt(k m) x x'"),  # d/dt of an energy times a time
    ("spring", "1/2 x'^2 - k/(2 m)*x^2 + g x"),  # L/m
    ("yoyo", "1/2 m d'^2 + 1/2 m q^2 (d'/r)^2 + m g d"),
    ("yoyo", "1/2 m (1 + q^2/r^2) d'^2 + m g d"),
    ("yoyo", "m (r^2 + q^2) d'^2/(2 r^2) + m g d"),
    ("yoyo", r"\frac{1}{2} m \dot{d}^2 + \frac{1}{2} m q^2 \frac{\dot{d}^2}{r^2} + m g d"),
    ("yoyo", "(r^2 + q^2) d'^2 + 2 g r^2 d"),  # times 2r²/m
]

LAGRANGIAN_WRONG = [
    (
        "wedge",
        "(M+m)/2*X'^2 + m X' s' cos(theta) + m/2*s'^2 - m g s sin(theta)",
        "added instead of subtracted",
    ),
    ("wedge", "(M+m)/2*X'^2 + m X' s' cos(theta) + m/2*s'^2", "potential energy is missing"),
    ("wedge", "m g s sin θ", "kinetic energy is missing"),
    ("wedge", "(M+m)/2*X'^2 + m/2*s'^2 + m g s sin θ", "cross term"),
    ("wedge", "M/2*X'^2 + m/2*s'^2 + m g s sin θ", None),
    ("wedge", "m/2*X'^2 + m X' s' cos(theta) + m/2*s'^2 + m g s sin(theta)", None),  # the wedge's own T
    ("wedge", "(M+m)/2*X'^2 + m X' s' sin(theta) + m/2*s'^2 + m g s sin(theta)", None),
    ("wedge", "(M+m)/2*X'^2 + m X' s' cos(theta) + m/2*s'^2 + m g s cos(theta)", None),
    ("wedge", "(M+m)/2*X'^2 - m X' s' cos(theta) + m/2*s'^2 + m g s sin(theta)", None),
    ("wedge", "(M+m)*X'^2 + m X' s' cos(theta) + m/2*s'^2 + m g s sin(theta)", None),
    ("wedge", "(M+m)/2*X'^2 + m X' s' cos(theta) + m s'^2 + m g s sin(theta)", None),
    ("wedge", "(M+m)/2*X'^2 + m X' s' cos(theta) + m/2*s'^2 + m g X sin(theta)", None),
    ("wedge", "(M+m)/2*X'^2 + m X' s' cos(theta) + m/2*s'^2 + m g s", None),
    ("wedge", "((M+m)/2*X'^2 + m X' s' cos(theta) + m/2*s'^2 + m g s sin(theta)) s", None),  # not a constant
    ("wedge", "((M+m)/2*X'^2 + m X' s' cos(theta) + m/2*s'^2 + m g s sin(theta)) X'", None),
    ("wedge", "0", "no equation of motion"),
    ("wedge", "5 X'", "no equation of motion"),
    ("wedge", "1/2 m s'^2 + m g s sin θ", None),
    ("cart", "(M+m)/2*X'^2 + m L X' phi' cos(phi) + m L^2/2*phi'^2 - m g L cos(phi)", "added instead"),
    ("cart", "(M+m)/2*X'^2 + m L^2/2*phi'^2 + m g L cos(phi)", "cross term"),
    ("cart", "(M+m)/2*X'^2 + m L X' phi' sin(phi) + m L^2/2*phi'^2 + m g L cos(phi)", None),
    ("cart", "M/2*X'^2 + m L^2/2*phi'^2 + m g L cos(phi)", None),
    ("cart", "(M+m)/2*X'^2 + m L X' phi' cos(phi) + m L/2*phi'^2 + m g L cos(phi)", None),
    ("cart", "(M+m)/2*X'^2 + m L X' phi' cos(phi) + m L^2/2*phi'^2 + m g L sin(phi)", None),
    ("spring", "1/2 m x'^2 + 1/2 k x^2 - m g x", "added instead"),
    ("spring", "1/2 m x'^2", "potential energy is missing"),
    ("spring", "1/2 m x'^2 - k x^2 + m g x", None),
    ("spring", "1/2 m x'^2 - 1/2 k x^2 - m g x", None),
    ("spring", "1/2 m x'^2 - 1/2 k x + m g x", None),
    ("spring", "1/2 m x'^2 - 1/2 k x^2", None),
    ("yoyo", "1/2 m d'^2 + m g d", None),  # the rotation left out
    ("yoyo", "1/2 m d'^2 + 1/2 m q^2 d'^2 + m g d", None),  # ω = d' (no 1/r)
    ("yoyo", "1/2 m d'^2 + 1/2 m q^2 (d'/r)^2 - m g d", "added instead"),
    ("yoyo", "1/2 m q^2 (d'/r)^2 + m g d", None),
]

KINETIC_RIGHT = [
    ("wedge", "(M+m)/2*X'^2 + m X' s' cos(theta) + m/2*s'^2"),
    ("wedge", "1/2 M X'^2 + 1/2 m ((X' + s' cos θ)^2 + (s' sin θ)^2)"),
    ("wedge", "1/2 M Ẋ^2 + 1/2 m (Ẋ^2 + 2 Ẋ ṡ cos θ + ṡ^2)"),
    ("wedge", r"\frac{M+m}{2}\dot{X}^2 + m\dot{X}\dot{s}\cos\theta + \frac{m}{2}\dot{s}^2"),
    ("wedge", "1/2 (M+m) (dX/dt)^2 + m (dX/dt)(ds/dt) cos θ + 1/2 m (ds/dt)^2"),
    ("wedge", "1/2 M Xdot^2 + 1/2 m (Xdot^2 + 2 Xdot sdot cos(theta) + sdot^2)"),
    ("wedge", "m/2*s'^2 + m X' s' cos θ + (M+m)/2*X'^2 + 10"),  # a constant apart
    ("wedge", "0.5 (M+m) X'^2 + m X' s' cos θ + 0.5 m s'^2"),
    ("wedge", "M X'^2/2 + m (X'^2 + 2 X' s' cos θ + s'^2)/2"),
    ("wedge", "1/2 M X'^2 + 1/2 m ((X' + s' cos θ)^2 + (-s' sin θ)^2)"),
    ("cart", "(M+m)/2*X'^2 + m L X' phi' cos(phi) + m L^2/2*phi'^2"),
    ("cart", "1/2 M X'^2 + 1/2 m ((X' + L φ' cos φ)^2 + (L φ' sin φ)^2)"),
    (
        "cart",
        r"\frac{1}{2}M\dot{X}^2 + \frac{1}{2}m(\dot{X}^2 + 2L\dot{X}\dot{\phi}\cos\phi + L^2\dot{\phi}^2)",
    ),
    ("cart", "1/2 M X'^2 + 1/2 m (X'^2 + 2 L X' φ' cos φ + L^2 φ'^2)"),
    ("cart", "1/2 (M+m) (dX/dt)^2 + m L (dX/dt) (dφ/dt) cos φ + 1/2 m L^2 (dφ/dt)^2"),
    ("cart", "1/2 M X'^2 + 1/2 m ((X' + L φ' cos φ)^2 + (L φ' sin(φ))^2) + m g L"),
    ("spring", "1/2 m x'^2"),
    ("spring", "m/2*ẋ^2"),
    ("spring", "m x'^2/2"),
    ("spring", r"\frac{1}{2} m \dot{x}^2"),
    ("spring", "1/2 m (dx/dt)^2"),
    ("spring", "1/2 m xdot^2"),
    ("spring", "0.5 m x_dot^2"),
    ("spring", "(1/2) m x' x'"),
    ("yoyo", "1/2 m d'^2 + 1/2 m q^2 (d'/r)^2"),
    ("yoyo", "1/2 m (1 + q^2/r^2) d'^2"),
    ("yoyo", "m (r^2 + q^2) d'^2/(2 r^2)"),
    ("yoyo", r"\frac{1}{2} m \dot{d}^2 + \frac{1}{2} (m q^2) \left(\frac{\dot{d}}{r}\right)^2"),
    ("yoyo", "1/2 m (dd/dt)^2 + 1/2 m q^2 ((dd/dt)/r)^2"),
    ("yoyo", "m d'^2 (1/2 + q^2/(2 r^2))"),
]

KINETIC_WRONG = [
    ("wedge", "(M+m)/2*X'^2 + m/2*s'^2", "cross term"),
    ("wedge", "M/2*X'^2 + m/2*s'^2", None),
    ("wedge", "m/2*X'^2 + m X' s' cos(theta) + m/2*s'^2", None),
    ("wedge", "(M+m)*X'^2 + 2 m X' s' cos(theta) + m s'^2", "2 times"),
    ("wedge", "(M+m)/2*X'^2 + m X' s' sin(theta) + m/2*s'^2", None),
    ("wedge", "(M+m)/2*X'^2 - m X' s' cos(theta) + m/2*s'^2", None),
    ("wedge", "(M+m)/2*X'^2 + 2 m X' s' cos(theta) + m/2*s'^2", None),
    ("wedge", "(M+m)/2*X'^2 + m X' s' cos(theta) + m/2*s'^2 - m g s sin θ", None),  # V is not T
    ("wedge", "(M+m)/2*X'^2 + m X' s' cos(theta) + m/2*s'^2 + m g s sin θ", None),
    ("wedge", "1/2 M X'^2 + 1/2 m (X' + s')^2", None),
    ("cart", "(M+m)/2*X'^2 + m L^2/2*phi'^2", "cross term"),
    ("cart", "M/2*X'^2 + m L^2/2*phi'^2", None),
    ("cart", "(M+m)/2*X'^2 + m L X' phi' sin(phi) + m L^2/2*phi'^2", None),
    ("cart", "(M+m)/2*X'^2 + m L X' phi' cos(phi) + m L/2*phi'^2", None),
    ("cart", "(M+m)/2*X'^2 + m L X' phi' cos(phi) + m/2*phi'^2", None),
    ("cart", "(M+m) X'^2 + 2 m L X' phi' cos(phi) + m L^2 phi'^2", "2 times"),
    ("spring", "m x'^2", "2 times"),
    ("spring", "1/2 m x'", None),
    ("spring", "1/2 m x^2", None),
    ("spring", "1/2 k x'^2", None),
    ("spring", "1/2 m x'^2 + 1/2 k x^2", None),
    ("spring", "1/4 m x'^2", "1/2 times"),
    ("spring", "-1/2 m x'^2", None),
    ("yoyo", "1/2 m d'^2", None),
    ("yoyo", "1/2 m q^2 (d'/r)^2", None),
    ("yoyo", "1/2 m d'^2 + 1/2 m q^2 d'^2", None),
    ("yoyo", "1/2 m d'^2 + 1/2 m q^2 (d' r)^2", None),
    ("yoyo", "m d'^2 + m q^2 (d'/r)^2", "2 times"),
    ("yoyo", "1/2 m d'^2 + 1/2 m r^2 (d'/r)^2", None),
    ("yoyo", "1/2 m d'^2 + m q^2 (d'/r)^2", None),
]

POTENTIAL_RIGHT = [
    ("wedge", "-m g s sin(theta)"),
    ("wedge", "-m g s sin θ"),
    ("wedge", r"-m g s \sin\theta"),
    ("wedge", "m g (1 - s sin θ)"),  # from another level
    ("wedge", "-m*g*s*sin(theta) + M*g"),
    ("wedge", "m g (-s sin θ)"),
    ("wedge", "-(m g sin θ) s"),
    ("wedge", "-s m g sin(theta) + 3"),
    ("cart", "-m g L cos(phi)"),
    ("cart", "m g L (1 - cos φ)"),
    ("cart", "-m g L cos φ + M g L"),
    ("cart", r"mgL(1-\cos\phi)"),
    ("cart", "m g (L - L cos(phi))"),
    ("cart", "-L m g cos(φ)"),
    ("cart", "m g L - m g L cos φ"),
    ("spring", "k/2*x^2 - m g x"),
    ("spring", "1/2 k x^2 - m g x"),
    ("spring", "1/2 k (x - m g/k)^2"),  # from the equilibrium
    ("spring", r"\frac{1}{2} k x^2 - m g x"),
    ("spring", "k x^2/2 - m g x + 4 m^2 g^2/k"),
    ("spring", "1/2 k x x - m g x"),
    ("spring", "x (k x/2 - m g)"),
    ("spring", "0.5 k x^2 - m g x"),
    ("yoyo", "-m g d"),
    ("yoyo", "m g (10 r - d)"),
    ("yoyo", "-g m d"),
    ("yoyo", "-d m g + m g r"),
    ("yoyo", "m g (r - d)"),
    ("yoyo", r"-mgd"),
    ("yoyo", "-(m g) d + q m g"),
]

POTENTIAL_WRONG = [
    ("wedge", "m g s sin θ", "opposite sign"),
    ("wedge", "-m g s cos θ", None),
    ("wedge", "-m g s", None),
    ("wedge", "-M g s sin θ", None),
    ("wedge", "-m g X sin θ", None),
    ("wedge", "-(M+m) g s sin θ", None),
    ("wedge", "-2 m g s sin θ", "2 times"),
    ("wedge", "-m g s sin θ + 1/2 m s'^2", None),
    ("cart", "m g L cos φ", "opposite sign"),
    ("cart", "-m g L sin φ", None),
    ("cart", "-m g cos φ", None),
    ("cart", "m g L (1 + cos φ)", None),
    ("cart", "-m g L cos φ - M g X", None),
    ("cart", "-(M+m) g L cos φ", None),
    ("cart", "m g L φ^2/2", None),  # small-angle: not the model's V
    ("spring", "-k/2*x^2 + m g x", "opposite sign"),
    ("spring", "k/2*x^2", None),
    ("spring", "k/2*x^2 + m g x", None),
    ("spring", "k x^2 - m g x", None),
    ("spring", "k/2*x - m g x", None),
    ("spring", "-m g x", None),
    ("spring", "k x^2 - 2 m g x", "2 times"),
    ("spring", "1/2 k x^2 - m g x + 1/2 m x'^2", None),
    ("yoyo", "m g d", "opposite sign"),
    ("yoyo", "-m g r", None),
    ("yoyo", "-m g d/r", None),
    ("yoyo", "-m g d^2", None),
    ("yoyo", "-g d", None),
    ("yoyo", "-m g d sin(d)", None),
    ("yoyo", "m g (d - 10)", "opposite sign"),
]

TABLES = {
    "lagrangian": (LAGRANGIAN_RIGHT, LAGRANGIAN_WRONG),
    "kinetic_energy": (KINETIC_RIGHT, KINETIC_WRONG),
    "potential_energy": (POTENTIAL_RIGHT, POTENTIAL_WRONG),
}


def test_each_table_has_thirty_right_and_thirty_wrong_answers_per_kind() -> None:
    for right, wrong in TABLES.values():
        assert len(right) >= 30 and len(wrong) >= 30


@pytest.mark.parametrize(
    ("kind", "system", "answer"),
    [(kind, system, answer) for kind, (right, _) in TABLES.items() for system, answer in right],
)
def test_an_equivalent_form_is_accepted(kind: str, system: str, answer: str) -> None:
    verdict = check(kind, system, answer)
    assert verdict.outcome is Outcome.CORRECT, verdict


@pytest.mark.parametrize(
    ("kind", "system", "answer", "said"),
    [(kind, system, answer, said) for kind, (_, wrong) in TABLES.items() for system, answer, said in wrong],
)
def test_a_wrong_answer_is_refused_with_what_differs(
    kind: str, system: str, answer: str, said: str | None
) -> None:
    verdict = check(kind, system, answer)
    assert verdict.outcome is Outcome.INCORRECT, verdict
    assert verdict.feedback
    if said is not None:
        assert said in verdict.feedback, verdict.feedback


@pytest.mark.parametrize("answer", ["1/2 m x'^2 - 1/2 k x^2 + m g", "m x'' ", "1/2 m y'^2", "1/2 m x'^2 - "])
def test_an_answer_that_does_not_read_is_invalid_not_wrong(answer: str) -> None:
    verdict = check("lagrangian", "spring", answer)
    if answer == "1/2 m x'^2 - 1/2 k x^2 + m g":  # reads (a constant m g is fine): the Lagrangian is wrong
        assert verdict.outcome is Outcome.INCORRECT
    else:
        assert verdict.outcome is Outcome.INVALID and verdict.error is not None


def test_the_preview_shows_a_velocity_with_its_dot() -> None:
    body = TypeAdapter(CheckIn).validate_python(
        {"kind": "lagrangian", "answer": "m x'^2/2", **SYSTEMS["spring"]}
    )
    read = preview(body.job())
    assert read.error is None and read.read_as is not None and r"\dot{x}" in read.read_as.latex


@cache
def _yoyo():  # the bank's yo-yo: its model splits T into the yo-yo's motion and its rotation
    return compile_problem(bank_documents()["yo-yo-lagrangian"])


@pytest.mark.parametrize(
    ("part", "answer", "said", "reason"),
    [
        ("lagrangian", "1/2 m d'^2 + m g d", "rotation is missing", Reason.KNOWN_MISTAKE),
        ("lagrangian", "1/2 m k^2 (d'/r)^2 + m g d", "motion is missing", Reason.KNOWN_MISTAKE),
        (
            "lagrangian",
            "1/2 m d'^2 + 1/2 m k^2 (d'/r)^2 - m g d",
            "added instead of subtracted",
            Reason.KNOWN_MISTAKE,
        ),
        ("kinetic_energy", "1/2 m d'^2", "rotation is missing", Reason.KNOWN_MISTAKE),
        ("potential_energy", "m g d", "opposite sign", Reason.SIGN_ERROR),
        ("lagrangian", "1/2 m d'^2 + 1/2 m k^2 (d'/r)^2 + m g d", "Correct", Reason.EQUIVALENT),
        ("kinetic_energy", "m (r^2 + k^2) \\dot{d}^2/(2 r^2)", "Correct", Reason.EQUIVALENT),
    ],
)
def test_a_bank_part_names_the_kinetic_term_left_out(
    part: str, answer: str, said: str, reason: Reason
) -> None:
    compiled = _yoyo()
    verdict = run_job(compiled.part(part).job(answer))
    assert verdict.reason is reason and said in verdict.feedback, verdict


MIXED_DIMENSIONS = [
    # (kind, system, a wrong answer whose terms differ in dimension, what the feedback says)
    ("lagrangian", "spring", "1/2 m x'^2 - 1/2 k x^2 + m g", "adds an energy to a force"),  # x left out
    ("lagrangian", "cart", "(M+m)/2*X'^2 + m L X' φ' cos φ + m L^2/2*φ'^2 + g L cos φ", "an energy"),
    ("lagrangian", "yoyo", "1/2 m d' + m q^2/(2 r^2)*d'^2 + m g d", "a momentum"),  # a square left out
    ("kinetic_energy", "cart", "(M+m)/2*X'^2 + m L X' φ' cos φ + m/2*φ'^2", "a spring constant to an energy"),
    ("potential_energy", "spring", "k/2*x^2 - g x", "a quantity in m²/s² to an energy"),  # m left out
]


@pytest.mark.parametrize(
    ("kind", "system", "answer", "said"), MIXED_DIMENSIONS, ids=[f"{c[0]}-{c[2]}" for c in MIXED_DIMENSIONS]
)
def test_a_wrong_answer_whose_terms_differ_in_dimension_is_told_so(
    kind: str, system: str, answer: str, said: str
) -> None:
    verdict = check(kind, system, answer)
    assert verdict.outcome is Outcome.INCORRECT
    assert verdict.reason is Reason.WRONG_DIMENSION
    assert said in verdict.feedback and "each of its terms must be an energy" in verdict.feedback


@pytest.mark.parametrize(
    ("system", "answer"),
    [
        ("spring", "1/2 x'^2 - k/(2 m)*x^2 + g x"),  # L/m: the same equations of motion
        ("spring", "1/2 m x'^2 - 1/2 k x^2 + m g x + m^2 g^2/k"),  # a constant energy, as a level of V
    ],
)
def test_a_right_lagrangian_scaled_or_with_a_constant_energy_is_correct(system: str, answer: str) -> None:
    assert check("lagrangian", system, answer).outcome is Outcome.CORRECT


CONSTANTS_NOT_ENERGIES = [
    # (kind, system, the model's answer plus a constant that is no energy, what the feedback says)
    ("lagrangian", "spring", "1/2 m x'^2 - 1/2 k x^2 + m g x + m g", "adds an energy to a force"),
    ("lagrangian", "cart", "(M+m)/2*X'^2 + m L X' φ' cos φ + m L^2/2*φ'^2 + m g L cos φ + g L", "an energy"),
    ("lagrangian", "spring", "1/2 m x'^2 - 1/2 k x^2 + m g x + 4", "a pure number"),
    ("potential_energy", "spring", "k/2*x^2 - m g x + k", "a spring constant"),
    ("potential_energy", "spring", "k x^2/2 - m g x + 4", "a pure number"),
    ("potential_energy", "yoyo", "m g (10 - d)", "a pure number to a length"),  # a level 10, no unit
    ("kinetic_energy", "cart", "1/2 M X'^2 + 1/2 m ((X' + L φ' cos φ)^2 + (L φ' sin(φ))^2) + m", "a mass"),
]


@pytest.mark.parametrize(
    ("kind", "system", "answer", "said"),
    CONSTANTS_NOT_ENERGIES,
    ids=[f"{c[0]}-{c[2]}" for c in CONSTANTS_NOT_ENERGIES],
)
def test_a_right_answer_plus_a_constant_that_is_no_energy_is_incorrect(
    kind: str, system: str, answer: str, said: str
) -> None:
    verdict = check(kind, system, answer)
    assert verdict.outcome is Outcome.INCORRECT
    assert verdict.reason is Reason.WRONG_DIMENSION
    assert said in verdict.feedback and "the model's derivatives" in verdict.feedback, verdict.feedback


def test_the_coordinates_dimensions_follow_from_the_models_energy() -> None:
    import sympy

    from physics.dimensions import DIMENSIONLESS, Dimension
    from physics.lagrangian import Coordinate, state_dimensions

    def coordinate(name: str) -> Coordinate:
        return Coordinate(name, *(sympy.Symbol(name + end, real=True) for end in ("", "_dot", "_ddot")))

    x, phi = coordinate("x"), coordinate("phi")
    m, k, length, g = sympy.symbols("m k L g", positive=True)
    known = {
        m: Dimension({"mass": 1}),
        k: Dimension({"mass": 1, "time": -2}),
        length: Dimension({"length": 1}),
        g: Dimension({"length": 1, "time": -2}),
    }
    pendulum = m * length**2 * phi.velocity**2 / 2 + m * g * length * sympy.cos(phi.symbol)
    found = state_dimensions(pendulum, [phi], known)
    assert found is not None and found[phi.symbol] == DIMENSIONLESS
    assert found[phi.velocity] == Dimension({"time": -1})
    spring = m * x.velocity**2 / 2 - k * (sympy.sqrt(x.symbol**2 + length**2) - length) ** 2 / 2
    found = state_dimensions(spring, [x], known)
    assert found is not None and found[x.symbol] == Dimension({"length": 1})
    # a coordinate seen only under a root tells nothing: no dimension, and no answer held to one
    assert state_dimensions(-k * length * sympy.sqrt(x.symbol**2 + length**2), [x], known) is None
