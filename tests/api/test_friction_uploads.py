"""Friction at a contact through upload: a rigid body's kinetic friction (a ball that skids, then rolls)
and static friction at its limit are derived by two methods, and graded."""

from __future__ import annotations

from typing import Any

import yaml

from tests.api.test_authoring import BANK, upload


def bowling_ball() -> dict[str, Any]:
    doc = yaml.safe_load((BANK / "bowling-ball-skid" / "problem.yaml").read_text())
    doc["model"] = yaml.safe_load((BANK / "bowling-ball-skid" / "model.yaml").read_text())
    doc["id"] = "my-bowling-ball"
    return doc


def steepest_ramp() -> dict[str, Any]:
    """A block at rest on a ramp: how steep may the ramp be before it slides?"""
    return {
        "id": "my-steepest-ramp",
        "title": "The steepest ramp a block stays on",
        "topics": ["static friction"],
        "statement": "A block $m$ rests on a ramp at $\\theta$; static friction $\\mu_s$.",
        "symbols": {
            "m": {"meaning": "mass", "dimension": "kg"},
            "theta": {"meaning": "angle of the ramp", "dimension": "1", "range": [0, "pi/2"]},
            "mu_s": {"meaning": "coefficient of static friction", "dimension": "1"},
            "g": {"meaning": "gravity", "dimension": "m/s^2"},
        },
        "given": {
            "m": {"min": 1, "max": 2, "unit": "kg"},
            "theta": {"min": 10, "max": 20, "unit": "deg"},
            "mu_s": {"min": 0.4, "max": 0.8, "unit": "1"},
            "g": {"min": 9.81, "max": 9.81, "unit": "m/s^2"},
        },
        "parts": [
            {"id": "grip", "kind": "symbolic", "prompt": "How large is the friction force holding it?"},
            {"id": "steepest", "kind": "symbolic", "prompt": "What is the steepest angle it stays at?"},
        ],
        "model": {
            "coordinates": [],
            "bodies": {"block": {"mass": "m", "position": {"x": 0, "y": 0}}},
            "gravity": "g",
            "constraints": {
                "slope": {"kind": "surface", "gap": "x_block*sin(theta) + y_block*cos(theta)"},
                "hold": {"kind": "other", "gap": "y_block*sin(theta) - x_block*cos(theta)"},
            },
            "domain": {"ranges": {"theta": ["0", "pi/2"]}},
            "quantities": {
                "grip": {"force": "hold"},
                "steepest": {
                    "slipping": "theta",
                    "friction": "hold",
                    "normal": "slope",
                    "coefficient": "mu_s",
                },
            },
        },
    }


def test_a_ball_that_skids_then_rolls_is_derived_and_graded(client, instructor_headers, student_headers):
    response = upload(client, instructor_headers, bowling_ball())
    assert response.status_code == 201, response.text
    solution = client.get("/v1/problems/my-bowling-ball/solution", headers=instructor_headers).json()
    assert solution["methods_agree"] is True
    assert "energy balance" in solution["checks"]
    answers = {"rolling_speed": "5 v0/7", "skid_time": "2 v0/(7 mu g)", "skid_distance": "12 v0^2/(49 mu g)"}
    for part, answer in answers.items():
        verdict = client.post(
            f"/v1/problems/my-bowling-ball/parts/{part}/submissions",
            json={"answer": answer},
            headers=student_headers,
        ).json()
        assert verdict["verdict"] == "correct", (part, verdict)
    forgot_torque = client.post(
        "/v1/problems/my-bowling-ball/parts/skid_time/submissions",
        json={"answer": "v0/(mu g)"},
        headers=student_headers,
    ).json()
    assert forgot_torque["verdict"] == "incorrect"
    assert "turns the body" in forgot_torque["feedback"]


def test_the_steepest_angle_at_the_limit_of_static_friction_is_derived(
    client, instructor_headers, student_headers
):
    response = upload(client, instructor_headers, steepest_ramp())
    assert response.status_code == 201, response.text
    verdict = client.post(
        "/v1/problems/my-steepest-ramp/parts/steepest/submissions",
        json={"answer": "atan(mu_s)"},
        headers=student_headers,
    ).json()
    assert verdict["verdict"] == "correct", verdict
