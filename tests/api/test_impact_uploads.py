"""An impact model uploaded through `POST /v1/problems`: both carts moving, a coefficient of restitution;
each final velocity and the energy lost derived, proved by two methods, simulated, and graded."""

from __future__ import annotations

from typing import Any

import pytest

from tests.api.test_engine_uploads import upload

pytestmark = pytest.mark.slow  # each upload derives and simulates the impact in the vetting worker


def carts() -> dict[str, Any]:
    return {
        "id": "my-cart-collision",
        "title": "Two carts collide",
        "topics": ["collisions", "momentum"],
        "statement": "Cart $m_1$ at $u_1$ catches up with cart $m_2$ at $u_2$; the coefficient of restitution is $e$.",
        "symbols": {
            "m1": {"meaning": "mass of the first cart", "dimension": "kg"},
            "m2": {"meaning": "mass of the second cart", "dimension": "kg"},
            "u1": {"meaning": "first cart's velocity before", "dimension": "m/s"},
            "u2": {"meaning": "second cart's velocity before", "dimension": "m/s"},
            "e": {"meaning": "coefficient of restitution", "dimension": "1", "range": [0, 1]},
        },
        "constraints": ["u2 < u1"],
        "given": {
            "m1": {"min": 1, "max": 2, "unit": "kg"},
            "m2": {"min": 1, "max": 3, "unit": "kg"},
            "u1": {"min": 3, "max": 5, "unit": "m/s"},
            "u2": {"min": 0.5, "max": 2, "unit": "m/s"},
            "e": {"min": 0.2, "max": 0.8, "unit": "1"},
        },
        "parts": [
            {"id": "v1", "kind": "symbolic", "prompt": "The first cart's velocity after."},
            {"id": "v2", "kind": "symbolic", "prompt": "The second cart's velocity after."},
            {"id": "lost", "kind": "symbolic", "prompt": "The kinetic energy lost."},
        ],
        "model": {
            "coordinates": ["x1", "x2"],
            "bodies": {
                "cart1": {"mass": "m1", "position": {"x": "x1"}},
                "cart2": {"mass": "m2", "position": {"x": "x2"}},
            },
            "state": {"x1_dot": "u1", "x2_dot": "u2"},
            "impact": {"bodies": ["cart1", "cart2"], "restitution": "e"},
            "domain": {"ranges": {"e": ["0", "1"]}, "positive": ["u1 - u2"]},
            "quantities": {
                "v1": {"final_velocity": "cart1"},
                "v2": {"final_velocity": "cart2"},
                "lost": {"kinetic_energy_lost": "impact"},
            },
        },
    }


def test_an_uploaded_collision_derives_both_final_velocities_and_grades_them(
    client, instructor_headers, student_headers
):
    response = upload(client, instructor_headers, carts())
    assert response.status_code == 201, response.text
    solution = client.get("/v1/problems/my-cart-collision/solution", headers=instructor_headers).json()
    assert {r["part"]: r["source"] for r in solution["references"]} == dict.fromkeys(
        ("v1", "v2", "lost"), "derived"
    )
    assert solution["methods_agree"] is True

    def grade(part: str, answer: str) -> str:
        verdict = client.post(
            f"/v1/problems/my-cart-collision/parts/{part}/submissions",
            json={"answer": answer},
            headers=student_headers,
        )
        assert verdict.status_code in (200, 201), verdict.text
        return str(verdict.json()["verdict"])

    assert grade("v2", "(m1*u1 + m2*u2 + e*m1*(u1 - u2))/(m1 + m2)") == "correct"
    assert grade("v1", "(m1*u1 + m2*u2)/(m1 + m2)") == "incorrect"  # the perfectly inelastic answer
    assert grade("lost", "m1*m2*(1 - e^2)*(u1 - u2)^2/(2*(m1 + m2))") == "correct"


def test_an_uploaded_collision_whose_bodies_separate_is_refused(client, instructor_headers):
    doc = carts()
    del doc["model"]["domain"]["positive"]
    response = upload(client, instructor_headers, doc)
    assert response.status_code == 422, response.text
    assert "do not approach" in response.text


def shell() -> dict[str, Any]:
    """A shell at rest bursts into two fragments, releasing Q as kinetic energy."""
    return {
        "id": "bursting-shell",
        "title": "A shell bursts",
        "topics": ["explosions", "momentum"],
        "statement": "A shell at rest bursts into fragments $m_1$ and $m_2$ that fly apart along a line; "
        "the burst gives them kinetic energy $Q$.",
        "symbols": {
            "m1": {"meaning": "mass of the first fragment", "dimension": "kg"},
            "m2": {"meaning": "mass of the second fragment", "dimension": "kg"},
            "Q": {"meaning": "energy released", "dimension": "J"},
        },
        "given": {
            "m1": {"min": 1, "max": 2, "unit": "kg"},
            "m2": {"min": 2, "max": 3, "unit": "kg"},
            "Q": {"min": 100, "max": 200, "unit": "J"},
        },
        "parts": [
            {
                "id": "v2",
                "kind": "symbolic",
                "prompt": "The second fragment's velocity (along the line, away from the first).",
            },
            {
                "id": "v2_numeric",
                "kind": "numeric",
                "prompt": "Its value in m/s.",
                "of": "v2",
                "units": "m/s",
            },
        ],
        "model": {
            "coordinates": ["x1", "x2"],
            "bodies": {
                "fragment1": {"mass": "m1", "position": {"x": "x1"}},
                "fragment2": {"mass": "m2", "position": {"x": "x2"}},
            },
            "impact": {"bodies": ["fragment1", "fragment2"], "release": "Q"},
            "quantities": {"v2": {"final_velocity": "fragment2"}},
        },
    }


def test_an_uploaded_explosion_derives_the_fragments_velocity_and_grades_it(
    client, instructor_headers, student_headers
):
    response = upload(client, instructor_headers, shell())
    assert response.status_code == 201, response.text
    solution = client.get("/v1/problems/bursting-shell/solution", headers=instructor_headers).json()
    assert solution["methods_agree"] is True
    right = client.post(
        "/v1/problems/bursting-shell/parts/v2/submissions",
        json={"answer": "sqrt(2*Q*m1/(m2*(m1 + m2)))"},
        headers=student_headers,
    ).json()
    assert right["verdict"] == "correct"
    all_energy = client.post(  # as if the second fragment took all of Q
        "/v1/problems/bursting-shell/parts/v2/submissions",
        json={"answer": "sqrt(2*Q/m2)"},
        headers=student_headers,
    ).json()
    assert all_energy["verdict"] == "incorrect"
