"""`POST /v1/check` of a Lagrangian, an energy and an equation: each kind's body as README shows it,
graded in a worker like any check, its reference errors a 422 at their field."""

from __future__ import annotations

import pytest

WEDGE = {
    "coordinates": ["X", "s"],
    "kinetic": "(M+m)/2*X'^2 + m*X'*s'*cos(theta) + m/2*s'^2",
    "potential": "-m*g*s*sin(theta)",
    "symbols": {
        "m": {"dimension": "kg"},
        "M": {"dimension": "kg"},
        "g": {"dimension": "m/s^2"},
        "theta": {"dimension": "1", "range": [0, "pi/2"]},
    },
}
INCLINE = {
    "expected": "m*a = m*g*sin(theta) - mu*N",
    "unknowns": {"a": "the block's acceleration down the slope", "N": "the normal force on the block"},
    "symbols": {
        "m": {"dimension": "kg"},
        "g": {"dimension": "m/s^2"},
        "mu": {"dimension": "1"},
        "theta": {"dimension": "1", "range": [0, "pi/2"]},
    },
}


@pytest.mark.parametrize(
    ("body", "verdict", "reason", "said"),
    [
        pytest.param(
            {
                "kind": "lagrangian",
                "answer": "1/2 (M+m) Ẋ^2 + m Ẋ ṡ cos θ + 1/2 m ṡ^2 + m g s sin θ",
                **WEDGE,
            },
            "correct",
            "equivalent",
            "Correct",
            id="lagrangian",
        ),
        pytest.param(
            {
                "kind": "lagrangian",
                "answer": "M X'^2 + m (X'^2 + 2 X' s' cos θ + s'^2) + 2 m g s sin θ",
                **WEDGE,
            },
            "correct",
            "equivalent",
            "2 times",
            id="lagrangian-doubled",
        ),
        pytest.param(
            {
                "kind": "lagrangian",
                "answer": "1/2 (M+m) X'^2 + m X' s' cos θ + 1/2 m s'^2 - m g s sin θ",
                **WEDGE,
            },
            "incorrect",
            "known_mistake",
            "added instead of subtracted",
            id="lagrangian-plus-v",
        ),
        pytest.param(
            {
                "kind": "kinetic_energy",
                "answer": "1/2 (M+m) X'^2 + 1/2 m s'^2",
                **{k: v for k, v in WEDGE.items() if k != "potential"},
            },
            "incorrect",
            "known_mistake",
            "cross term",
            id="kinetic-no-cross-term",
        ),
        pytest.param(
            {
                "kind": "potential_energy",
                "answer": "m g s sin θ",
                **{k: v for k, v in WEDGE.items() if k != "kinetic"},
            },
            "incorrect",
            "sign_error",
            "opposite sign",
            id="potential-sign",
        ),
        pytest.param(
            {"kind": "lagrangian", "answer": "1/2 m y'^2", **WEDGE},
            "invalid",
            "unknown_symbol",
            "y",
            id="unknown",
        ),
        pytest.param(
            {"kind": "equation", "answer": "m g sin θ - μ N = m a", **INCLINE},
            "correct",
            "equivalent",
            "Correct",
            id="equation",
        ),
        pytest.param(
            {"kind": "equation", "answer": "m a = m g sin θ", **INCLINE},
            "incorrect",
            "known_mistake",
            "missing",
            id="equation-force-missing",
        ),
        pytest.param(
            {"kind": "equation", "answer": r"$m g \sin\theta - \mu N = m a$", **INCLINE},
            "correct",
            "equivalent",
            "Correct",
            id="equation-in-latex-math-delimiters",
        ),
        pytest.param(
            {"kind": "equation", "answer": "m a", **INCLINE},
            "invalid",
            "parse_error",
            "'='",
            id="not-an-equation",
        ),
    ],
)
def test_each_new_kind_is_checked_ad_hoc(client, student_headers, body, verdict, reason, said) -> None:
    response = client.post("/v1/check", json=body, headers=student_headers)
    assert response.status_code == 200, response.text
    result = response.json()
    assert (result["verdict"], result["reason"]) == (verdict, reason), result
    assert said in result["feedback"]


def test_a_lagrangian_body_without_its_potential_energy_is_refused(client, student_headers) -> None:
    body = {"kind": "lagrangian", "answer": "x'", **{k: v for k, v in WEDGE.items() if k != "potential"}}
    response = client.post("/v1/check", json=body, headers=student_headers)
    assert response.status_code == 422


def test_an_unreadable_reference_is_a_422_at_its_field(client, student_headers) -> None:
    body = {"kind": "equation", "answer": "m a = 0", **{**INCLINE, "expected": "m a = = 2"}}
    response = client.post("/v1/check", json=body, headers=student_headers)
    assert response.status_code == 422, response.text


def test_the_unreadable_expected_equation_is_named(client, student_headers) -> None:
    body = {"kind": "equation", "answer": "m a = 0", **{**INCLINE, "expected": "m a = = 2"}}
    details = client.post("/v1/check", json=body, headers=student_headers).json()["error"]["details"]
    assert any("expected" in str(item.get("path", "")) for item in details), details
