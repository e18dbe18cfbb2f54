"""A coordinate's velocity, written the ways students write it, reads as its declared name `x_dot`
where a part asks for velocities, and is refused as before everywhere else."""

from __future__ import annotations

import pytest
import sympy

from physics.errors import AnswerError
from physics.mathinput import parse_math

x, x_dot, theta, theta_dot, m = sympy.symbols("x x_dot theta theta_dot m", real=True)
NAMES = {"x": x, "x_dot": x_dot, "theta": theta, "theta_dot": theta_dot, "m": m}

READ = [
    ("x'", x_dot),
    ("x′", x_dot),
    ("xdot", x_dot),
    ("x_dot", x_dot),
    ("ẋ", x_dot),
    ("x\u0307", x_dot),
    ("\\dot{x}", x_dot),
    ("\\dot x", x_dot),
    ("dx/dt", x_dot),
    ("\\frac{dx}{dt}", x_dot),
    ("(dx/dt)^2", x_dot**2),
    ("m x'^2/2", m * x_dot**2 / 2),
    ("1/2 m ẋ^2", m * x_dot**2 / 2),
    ("mẋ^2", m * x_dot**2),
    ("mx'", m * x_dot),
    ("θ'", theta_dot),
    ("theta'", theta_dot),
    ("θ̇", theta_dot),
    ("\\dot{\\theta}", theta_dot),
    ("\\dot\\theta", theta_dot),
    ("dθ/dt", theta_dot),
    ("\\frac{1}{2} m \\dot{x}^2 - m x", m * x_dot**2 / 2 - m * x),
    ("x' theta' cos(theta)", x_dot * theta_dot * sympy.cos(theta)),
]


@pytest.mark.parametrize(("text", "expected"), READ, ids=[t for t, _ in READ])
def test_a_velocity_reads_as_the_coordinates_dot_name(text: str, expected: sympy.Expr) -> None:
    assert parse_math(text, NAMES, velocities=True).expr == expected


def test_a_velocity_is_shown_with_a_dot() -> None:
    assert parse_math("x'^2", NAMES, velocities=True).read_as.latex == r"\dot{x}^{2}"


@pytest.mark.parametrize("text", ["x'", "\\dot{x}", "dx/dt", "ẋ"])
def test_without_velocities_the_notations_are_refused_as_before(text: str) -> None:
    with pytest.raises(AnswerError):
        parse_math(text, NAMES)


@pytest.mark.parametrize("text", ["y'", "\\dot{}", "\\dot{x+1}", "dy/dt", "dx/dt^2"])
def test_a_velocity_of_no_coordinate_is_refused(text: str) -> None:
    with pytest.raises(AnswerError):
        parse_math(text, NAMES, velocities=True)
