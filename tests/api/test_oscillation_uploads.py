"""Damped oscillations, mode shapes and driving forces through `POST /v1/problems`: derived and graded,
and a wrong model (or a wrong typed answer) refused at its path."""

from __future__ import annotations

from typing import Any

from tests.api.test_engine_uploads import _details, three_springs, upload


def damped_block() -> dict[str, Any]:
    return {
        "id": "my-damped-block",
        "title": "Damped oscillator",
        "topics": ["oscillations", "damping"],
        "statement": "A block $m$ on a spring $k$ with a dashpot $b$ (light damping) is released.",
        "symbols": {
            "m": {"meaning": "mass", "dimension": "kg"},
            "k": {"meaning": "spring constant", "dimension": "N/m"},
            "b": {"meaning": "damping coefficient", "dimension": "kg/s"},
        },
        "constraints": ["b^2 < 4*k*m"],
        "given": {
            "m": {"min": 1, "max": 2, "unit": "kg"},
            "k": {"min": 20, "max": 40, "unit": "N/m"},
            "b": {"min": 0.5, "max": 1, "unit": "kg/s"},
        },
        "parts": [
            {"id": "omega_d", "kind": "symbolic", "prompt": "The damped angular frequency."},
            {"id": "tau", "kind": "symbolic", "prompt": "The amplitude's e-folding time."},
        ],
        "model": {
            "coordinates": ["x"],
            "bodies": {"block": {"mass": "m", "position": {"x": "x"}}},
            "elements": {"spring": {"kind": "spring", "between": [{"x": 0}, "block"], "stiffness": "k"}},
            "forces": [{"body": "block", "drag": "b"}],
            "domain": {"positive": ["4*k*m - b^2"]},
            "quantities": {"omega_d": {"damped_frequency": "x"}, "tau": {"decay_time": "x"}},
        },
    }


def test_a_damped_oscillator_is_derived_checked_and_graded(client, instructor_headers, student_headers):
    response = upload(client, instructor_headers, damped_block())
    assert response.status_code == 201, response.text
    solution = client.get("/v1/problems/my-damped-block/solution", headers=instructor_headers).json()
    assert {r["part"]: r["source"] for r in solution["references"]} == {
        "omega_d": "derived",
        "tau": "derived",
    }
    assert {"dimensions", "limit omega_d (no damping)"} <= set(solution["checks"])
    for part, answer, verdict in [
        ("omega_d", "sqrt(k/m - (b/(2*m))^2)", "correct"),
        ("omega_d", "sqrt(k/m)", "incorrect"),
        ("tau", "2*m/b", "correct"),
    ]:
        graded = client.post(
            f"/v1/problems/my-damped-block/parts/{part}/submissions",
            json={"answer": answer},
            headers=student_headers,
        ).json()
        assert graded["verdict"] == verdict, (part, answer, graded)


def test_a_damped_model_that_may_be_overdamped_is_refused_saying_what_to_declare(client, instructor_headers):
    doc = damped_block()
    doc["model"].pop("domain")
    details = _details(upload(client, instructor_headers, doc))
    assert "not underdamped" in details["model.quantities.omega_d"]
    assert "domain.positive" in details["model.quantities.omega_d"]


def test_a_mode_shape_is_derived_from_an_upload(client, instructor_headers, student_headers):
    doc = three_springs()
    doc["parts"].append(
        {"id": "fast_shape", "kind": "symbolic", "prompt": "x2's amplitude over x1's, fast mode."}
    )
    doc["model"]["quantities"]["fast_shape"] = {"mode_shape": {"mode": 2, "ratio": ["x2", "x1"]}}
    response = upload(client, instructor_headers, doc)
    assert response.status_code == 201, response.text
    graded = client.post(
        "/v1/problems/my-three-springs/parts/fast_shape/submissions",
        json={"answer": "-1"},
        headers=student_headers,
    ).json()
    assert graded["verdict"] == "correct"


def test_a_puck_on_a_ring_of_rests_is_refused_as_a_continuum_not_a_simulation_overflow(
    client, instructor_headers
):
    """A spring of natural length L0 to the origin, the puck free in x and y: sympy gives the ring's top as
    an isolated rest beside the ring, whose simulation overflowed."""
    doc = three_springs()
    doc["symbols"]["L0"] = {"meaning": "natural length", "dimension": "m"}
    doc["given"]["L0"] = {"min": 0.1, "max": 0.5, "unit": "m"}
    doc["parts"] = [{"id": "w", "kind": "symbolic", "prompt": "The angular frequency of small oscillations."}]
    doc["model"] = {
        "coordinates": ["x", "y"],
        "bodies": {"puck": {"mass": "m", "position": {"x": "x", "y": "y"}}},
        "elements": {
            "spring": {
                "kind": "spring",
                "between": ["puck", {"x": 0, "y": 0}],
                "stiffness": "k",
                "length": "L0",
            }
        },
        "quantities": {"w": {"normal_frequency": 1}},
    }
    said = _details(upload(client, instructor_headers, doc))["model.quantities.w"]
    assert "a continuum of equilibria" in said
    assert "a ring about the origin" in said
    assert "OverflowError" not in said


def driven_cart(state: dict[str, str]) -> dict[str, Any]:
    return {
        "id": "my-driven-cart",
        "title": "Driven cart",
        "topics": ["forces", "oscillations"],
        "statement": "A cart $m$ on a spring $k$ is driven by $F_0\\cos(\\omega t)$.",
        "symbols": {
            "m": {"meaning": "mass", "dimension": "kg"},
            "k": {"meaning": "spring constant", "dimension": "N/m"},
            "F0": {"meaning": "amplitude of the driving force", "dimension": "N"},
            "w": {"meaning": "driving angular frequency", "dimension": "1/s"},
            "A": {"meaning": "displacement at that moment", "dimension": "m"},
        },
        "given": {
            "m": {"min": 1, "max": 2, "unit": "kg"},
            "k": {"min": 20, "max": 40, "unit": "N/m"},
            "F0": {"min": 1, "max": 2, "unit": "N"},
            "w": {"min": 1, "max": 3, "unit": "1/s"},
            "A": {"min": 0.01, "max": 0.02, "unit": "m"},
        },
        "parts": [{"id": "a", "kind": "symbolic", "prompt": "The acceleration at $t = \\pi/(3\\omega)$."}],
        "model": {
            "coordinates": ["x"],
            "bodies": {"cart": {"mass": "m", "position": {"x": "x"}}},
            "elements": {"spring": {"kind": "spring", "between": [{"x": 0}, "cart"], "stiffness": "k"}},
            "forces": [{"body": "cart", "force": {"x": "F0*cos(w*t)"}}],
            "state": state,
            "quantities": {"a": {"acceleration": "x"}},
        },
    }


def test_a_driving_force_is_taken_at_the_states_time(client, instructor_headers, student_headers):
    response = upload(client, instructor_headers, driven_cart({"x": "A", "t": "pi/(3*w)"}))
    assert response.status_code == 201, response.text
    graded = client.post(
        "/v1/problems/my-driven-cart/parts/a/submissions",
        json={"answer": "(F0/2 - k*A)/m"},
        headers=student_headers,
    ).json()
    assert graded["verdict"] == "correct"


def test_a_driving_force_without_a_time_is_refused(client, instructor_headers):
    details = _details(upload(client, instructor_headers, driven_cart({"x": "A"})))
    assert "give their values in the model's state" in details["model.quantities.a"]
