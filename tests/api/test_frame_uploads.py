"""Uploads with a rotating frame (`POST /v1/problems`): the fictitious-forces method is one of the methods
that derive the answers, and a frame declared wrong is refused with what each method found."""

from __future__ import annotations

from typing import Any

from tests.api.test_engine_uploads import upload


def spinning_rod(frame: dict[str, Any] | None = None) -> dict[str, Any]:
    """A bead on a spring along a rod that turns about a vertical axis through the spring's anchor."""
    model: dict[str, Any] = {
        "coordinates": ["r"],
        "bodies": {"bead": {"mass": "m", "position": {"x": "r", "y": 0}}},
        "gravity": "g",
        "constraints": {"rod": {"kind": "surface", "gap": "y_bead"}},
        "potentials": [{"bodies": ["bead"], "anchor": {"x": 0}, "distance": "d", "energy": "k*(d - L0)^2/2"}],
        "state": {"r": "L0"},
        "domain": {"ranges": {"r": ["0", "oo"]}, "positive": ["k - m*omega^2"]},
        "quantities": {"rest_radius": {"equilibrium": "r"}, "start": {"acceleration": "r"}},
    }
    if frame is None:
        model["elements"] = {"spin": {"kind": "rotating", "rate": "omega", "bodies": ["bead"]}}
    else:
        model["potentials"].append(
            {"bodies": ["bead"], "anchor": {"x": 0}, "distance": "e", "energy": "-m*omega^2*e^2/2"}
        )
        model["frame"] = frame
    return {
        "id": "my-spinning-rod",
        "title": "Bead on a spring along a spinning rod",
        "topics": ["non-inertial frames"],
        "statement": "A bead $m$ on a spring $k$ (natural length $L_0$) slides on a rod spun at $\\omega$.",
        "symbols": {
            "m": {"meaning": "mass of the bead", "dimension": "kg"},
            "k": {"meaning": "spring constant", "dimension": "N/m"},
            "L0": {"meaning": "natural length", "dimension": "m"},
            "omega": {"meaning": "angular velocity of the rod", "dimension": "rad/s"},
            "g": {"meaning": "gravity", "dimension": "m/s^2"},
        },
        "constraints": ["m*omega^2 < k"],
        "given": {
            "m": {"min": 0.1, "max": 0.2, "unit": "kg"},
            "k": {"min": 50, "max": 100, "unit": "N/m"},
            "L0": {"min": 0.1, "max": 0.3, "unit": "m"},
            "omega": {"min": 5, "max": 10, "unit": "rad/s"},
            "g": {"min": 9.81, "max": 9.81, "unit": "m/s^2"},
        },
        "parts": [
            {"id": "rest_radius", "kind": "symbolic", "prompt": "Where does the bead rest on the rod?"},
            {"id": "start", "kind": "symbolic", "prompt": "Released at rest at r = L0, its acceleration?"},
        ],
        "model": model,
    }


def test_an_upload_with_a_rotating_frame_is_derived_by_the_fictitious_forces_too(client, instructor_headers):
    response = upload(client, instructor_headers, spinning_rod())
    assert response.status_code == 201, response.text
    solution = client.get("/v1/problems/my-spinning-rod/solution", headers=instructor_headers).json()
    assert "frames" in solution["agreement"]["rest_radius"]
    assert "dalembert" in solution["agreement"]["start"]
    frames = next(m for m in solution["methods"] if m["name"] == "frames")
    assert any("centrifugal" in step["title"] for step in frames["steps"])


def test_an_upload_whose_frame_turns_at_the_wrong_rate_is_refused(client, instructor_headers):
    response = upload(client, instructor_headers, spinning_rod({"rate": "2*omega", "bodies": ["bead"]}))
    assert response.status_code == 422, response.text
    details = {d["path"]: d["message"] for d in response.json()["error"]["details"]}
    message = details["model.quantities.start"]
    assert "frames gives 5*L0*omega^2" in message and "lagrange gives L0*omega^2" in message
