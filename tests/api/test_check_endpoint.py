"""`POST /v1/check` as the contract describes it: verdicts, reasons, read_as, and the error shape."""

from __future__ import annotations

import pytest

WEDGE_SYMBOLS = {
    "m": {"dimension": "kg"},
    "M": {"dimension": "kg"},
    "g": {"dimension": "m/s^2"},
    "theta": {"dimension": "1", "range": [0, "pi/2"]},
}
WEDGE_EXPECTED = "-m*g*sin(theta)*cos(theta)/(M + m*sin(theta)**2)"


def symbolic(answer: str, expected: str = WEDGE_EXPECTED, symbols: dict | None = None, **extra) -> dict:
    return {
        "kind": "symbolic",
        "answer": answer,
        "expected": expected,
        "symbols": symbols or WEDGE_SYMBOLS,
        **extra,
    }


def numeric(answer: str, expected: float | str = 4.5807, units: str | None = "m/s^2", **extra) -> dict:
    body = {"kind": "numeric", "answer": answer, "expected": expected, **extra}
    if units is not None:
        body["units"] = units
    return body


@pytest.mark.parametrize(
    ("body", "verdict", "reason"),
    [
        pytest.param(
            symbolic("-m g sin(θ)cos(θ)/(M + m sin^2 θ)"), "correct", "equivalent", id="contract-example"
        ),
        pytest.param(
            symbolic("-m g tan θ/(M(1+tan^2 θ) + m tan^2 θ)"), "correct", "equivalent", id="seed-tan-form"
        ),
        pytest.param(symbolic("m g sin(θ)cos(θ)/(M + m sin^2 θ)"), "incorrect", "sign_error", id="sign"),
        pytest.param(
            symbolic("-2 m g sin(θ)cos(θ)/(M + m sin^2 θ)"), "incorrect", "constant_factor", id="factor-2"
        ),
        pytest.param(
            symbolic("-m sin(θ)cos(θ)/(M + m sin^2 θ)"), "incorrect", "wrong_dimension", id="dropped-g"
        ),
        pytest.param(symbolic("-g sin(θ)cos(θ)"), "incorrect", "wrong_value", id="fixed-wedge-like"),
        pytest.param(symbolic("-m g sin(θ)cos(θ)/(M + m sin^2 θ"), "invalid", "parse_error", id="unbalanced"),
        pytest.param(symbolic("-m g sin(φ)"), "invalid", "unknown_symbol", id="unknown-symbol"),
        pytest.param(symbolic("foo(m)"), "invalid", "unknown_function", id="unknown-function"),
        pytest.param(symbolic("9^9^9"), "invalid", "too_large", id="tower"),
        pytest.param(numeric("4.58 m/s^2"), "correct", "equivalent", id="numeric-contract-example"),
        pytest.param(numeric("16.49 km/h/s"), "correct", "equivalent", id="numeric-converted"),
        pytest.param(numeric("4.58"), "invalid", "missing_units", id="missing-units"),
        pytest.param(
            numeric("4.58 m/s^2", units=None, expected=4.58),
            "invalid",
            "unexpected_units",
            id="unexpected-units",
        ),
        pytest.param(numeric("4.58 furlongs"), "invalid", "unknown_unit", id="unknown-unit"),
        pytest.param(numeric("4.58 m/s"), "incorrect", "wrong_dimension", id="wrong-dimension"),
        pytest.param(numeric("-4.58 m/s^2"), "incorrect", "sign_error", id="numeric-sign"),
        pytest.param(numeric("5.2 m/s^2"), "incorrect", "wrong_value", id="numeric-wrong"),
        pytest.param(numeric("4,58 m/s^2"), "invalid", "parse_error", id="comma"),
        pytest.param(
            numeric("4.6 m/s^2", tolerance={"sigfigs": 3}), "invalid", "sigfigs", id="sigfigs-shown"
        ),
        pytest.param(numeric("229/50 m/s^2"), "correct", "equivalent", id="numeric-arithmetic"),
        pytest.param(numeric("0.5 kg * 9.16 m/s^2", units="N"), "correct", "equivalent", id="quantities"),
        pytest.param(
            numeric("229/50 m/s^2", arithmetic=False), "invalid", "parse_error", id="plain-decimal-asked"
        ),
        pytest.param(numeric("2 ohms", expected=2, units="ohm"), "correct", "equivalent", id="ohms"),
        pytest.param(
            numeric("15.03 ft/s^2", units_system="SI"), "invalid", "unknown_unit", id="si-only-refuses-ft"
        ),
        pytest.param(numeric("15.03 ft/s^2"), "correct", "equivalent", id="ft-converted"),
    ],
)
def test_check_gives_contract_verdict_and_reason(client, student_headers, body, verdict, reason):
    response = client.post("/v1/check", json=body, headers=student_headers)
    assert response.status_code == 200, response.text
    result = response.json()
    assert (result["verdict"], result["reason"]) == (verdict, reason), result
    assert set(result) == {"verdict", "score", "reason", "feedback", "read_as", "error"}
    assert result["score"] == (1.0 if verdict == "correct" else 0.0)
    assert (result["error"] is not None) == (verdict == "invalid")
    assert result["feedback"]


def test_read_as_shows_how_the_answer_was_understood(client, student_headers):
    result = client.post(
        "/v1/check", json=symbolic("-mgsin(θ)cos(θ)/(M + m sin^2 θ)"), headers=student_headers
    ).json()
    assert result["verdict"] == "correct"
    assert "m*g*sin(theta)" in result["read_as"]["text"]
    assert "\\theta" in result["read_as"]["latex"]


def test_read_as_note_says_how_the_expected_dimension_chose_the_units(client, student_headers):
    result = client.post(
        "/v1/check", json=numeric("5 ms^-1", expected=5, units="m/s"), headers=student_headers
    ).json()
    assert result["verdict"] == "correct"
    assert result["read_as"]["text"] == "5 m/s"
    assert result["read_as"]["note"] == "Read ms^-1 as m/s: the only reading that is a speed"


def test_units_system_other_than_si_is_422(client, student_headers):
    response = client.post("/v1/check", json=numeric("1 m", units_system="imperial"), headers=student_headers)
    assert response.status_code == 422


def test_invalid_verdict_points_at_the_problem(client, student_headers):
    result = client.post("/v1/check", json=symbolic("m g + * M"), headers=student_headers).json()
    assert result["verdict"] == "invalid"
    assert result["error"]["position"] == 6  # the "*" with nothing before it
    assert result["error"]["message"]


def test_ambiguous_division_is_refused_with_both_readings(client, student_headers):
    symbols = {"p": {}, "m": {"dimension": "kg"}}  # p has no dimension: nothing can settle it
    result = client.post(
        "/v1/check", json=symbolic("p^2/2m", "p^2/(2*m)", symbols), headers=student_headers
    ).json()
    assert (result["verdict"], result["reason"]) == ("invalid", "ambiguous")
    assert "(" in result["error"]["message"]


def test_ambiguous_division_is_settled_where_one_reading_has_the_expected_dimension(client, student_headers):
    symbols = {"p": {"dimension": "kg*m/s"}, "m": {"dimension": "kg"}}
    result = client.post(
        "/v1/check", json=symbolic("p^2/2m", "p^2/(2*m)", symbols), headers=student_headers
    ).json()
    assert (result["verdict"], result["reason"]) == ("correct", "equivalent")
    assert result["read_as"]["text"] == "p**2/(2*m)"
    assert result["read_as"]["note"] == "Read as p**2/(2*m): the only reading that is an energy"


@pytest.mark.parametrize(
    ("body", "path"),
    [
        pytest.param(
            {"kind": "symbolic", "answer": 42, "expected": "m", "symbols": {"m": {}}},
            "symbolic.answer",
            id="answer-not-string",
        ),
        pytest.param(
            {"kind": "numeric", "answer": "1", "expected": 1, "surprise": True},
            "numeric.surprise",
            id="unknown-field",
        ),
        pytest.param({"kind": "vector", "answer": "1", "expected": 1}, "", id="unknown-kind"),
        pytest.param(
            {"kind": "symbolic", "answer": "m", "symbols": {"m": {}}},
            "symbolic.expected",
            id="missing-expected",
        ),
        pytest.param(
            {"kind": "numeric", "answer": "1", "expected": 1, "tolerance": {"rel": -1}},
            "numeric.tolerance.rel",
            id="negative-tolerance",
        ),
    ],
)
def test_malformed_request_is_422_in_the_error_shape(client, student_headers, body, path):
    response = client.post("/v1/check", json=body, headers=student_headers)
    assert response.status_code == 422
    error = response.json()["error"]
    assert error["code"] == "malformed_request"
    assert any(detail["path"].startswith(path) for detail in error["details"]), error


def test_malformed_json_is_422_in_the_error_shape(client, student_headers):
    response = client.post(
        "/v1/check",
        content=b'{"kind": "symbolic", "answer": ',
        headers={**student_headers, "content-type": "application/json"},
    )
    assert response.status_code == 422
    assert response.json()["error"]["code"] == "malformed_request"


@pytest.mark.parametrize(
    ("body", "path"),
    [
        pytest.param(symbolic("m", expected="m g +"), "expected", id="expected"),
        pytest.param(
            symbolic("m", symbols={**WEDGE_SYMBOLS, "m": {"dimension": "blorps"}}),
            "symbols.m.dimension",
            id="dimension",
        ),
        pytest.param(
            symbolic("m", symbols={**WEDGE_SYMBOLS, "theta": {"range": [0, "pi/"]}}),
            "symbols.theta.range.1",
            id="range",
        ),
        pytest.param(symbolic("m", constraints=["M <"]), "constraints.0", id="constraint"),
    ],
)
def test_unreadable_reference_is_422_naming_the_field(client, student_headers, body, path):
    response = client.post("/v1/check", json=body, headers=student_headers)
    assert response.status_code == 422
    error = response.json()["error"]
    assert error["code"] == "invalid_reference"
    assert error["details"][0]["path"] == path


@pytest.mark.parametrize(
    "headers",
    [
        pytest.param({}, id="no-key"),
        pytest.param({"Authorization": "Bearer pck_not-a-real-key"}, id="unknown-key"),
        pytest.param({"Authorization": "Basic dXNlcjpwYXNz"}, id="wrong-scheme"),
    ],
)
def test_check_without_a_valid_key_is_401(client, headers):
    response = client.post("/v1/check", json=numeric("4.58 m/s^2"), headers=headers)
    assert response.status_code == 401
    assert response.json()["error"]["code"] == "unauthenticated"


def test_body_over_the_cap_is_413(client, student_headers, settings):
    answer = "1" * (settings.max_body_bytes + 10)
    response = client.post("/v1/check", json=numeric(answer), headers=student_headers)
    assert response.status_code == 413
    assert response.json()["error"]["code"] == "payload_too_large"


def test_answer_longer_than_the_limit_is_invalid_not_an_error(client, student_headers, settings):
    result = client.post(
        "/v1/check", json=symbolic("m" * (settings.max_answer_chars + 1)), headers=student_headers
    ).json()
    assert (result["verdict"], result["reason"]) == ("invalid", "too_large")


def test_health_answers_without_a_key(client):
    assert client.get("/health").json() == {"status": "ok"}
