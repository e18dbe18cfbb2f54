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


FRICTION_CHOICES = [
    {"text": "Up the slope", "correct": True},
    {"text": "Down the slope", "feedback": "Friction opposes the sliding, which is down the slope."},
    {"text": "Perpendicular to the slope"},
]


def choice(answer: str, choices: list[dict] | None = None) -> dict:
    return {"kind": "choice", "answer": answer, "choices": FRICTION_CHOICES if choices is None else choices}


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
        pytest.param(
            symbolic("The acceleration is -m g sin θ cos θ/(M + m sin^2 θ)"),
            "invalid",
            "parse_error",
            id="sentence-before-the-expression",
        ),
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
        pytest.param(numeric("4.58 smoots"), "invalid", "unknown_unit", id="unknown-unit"),
        pytest.param(numeric("4.58 m/s"), "incorrect", "wrong_dimension", id="wrong-dimension"),
        pytest.param(numeric("-4.58 m/s^2"), "incorrect", "sign_error", id="numeric-sign"),
        pytest.param(numeric("5.2 m/s^2"), "incorrect", "wrong_value", id="numeric-wrong"),
        pytest.param(numeric("4,580 m/s^2"), "invalid", "parse_error", id="thousands-or-decimal-comma"),
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
        pytest.param(numeric("4.58 Hz", units="rad/s"), "correct", "equivalent", id="hertz-for-omega"),
        pytest.param(
            numeric("4.58 Hz", units="rad/s", angular_units="strict"),
            "incorrect",
            "constant_factor",
            id="hertz-for-omega-strict",
        ),
        pytest.param(
            numeric("12.3*m/s", expected=12.3, units="m/s", tolerance={"sigfigs": 3}),
            "correct",
            "equivalent",
            id="joined-literal",
        ),
        pytest.param(
            numeric("50 lb", expected="222.41", units="N"), "correct", "equivalent", id="pound-force"
        ),
        pytest.param(numeric("50 lb", units="m/s"), "invalid", "ambiguous", id="pound-for-a-speed"),
        pytest.param(choice("A"), "correct", "equivalent", id="choice-letter"),
        pytest.param(choice("(a)"), "correct", "equivalent", id="choice-letter-in-brackets"),
        pytest.param(choice("  up the SLOPE "), "correct", "equivalent", id="choice-text"),
        pytest.param(choice("C"), "incorrect", "wrong_value", id="choice-wrong"),
        pytest.param(choice("b)"), "incorrect", "known_mistake", id="choice-wrong-with-feedback"),
        pytest.param(choice("D"), "invalid", "parse_error", id="choice-beyond-the-choices"),
        pytest.param(choice("sideways"), "invalid", "parse_error", id="choice-no-such-text"),
        pytest.param(choice(""), "invalid", "parse_error", id="choice-empty"),
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


def test_a_choice_check_reads_the_answer_as_the_letter_it_names(client, student_headers):
    result = client.post("/v1/check", json=choice("Down the slope"), headers=student_headers).json()
    assert result["read_as"]["text"] == "B"
    assert result["feedback"] == FRICTION_CHOICES[1]["feedback"]


def test_an_unreadable_choice_is_invalid_and_says_which_letters_there_are(client, student_headers):
    result = client.post("/v1/check", json=choice("E"), headers=student_headers).json()
    assert (result["verdict"], result["score"]) == ("invalid", 0.0)
    assert result["error"] == {"message": "Answer with the letter of one choice, A to C.", "position": 0}


@pytest.mark.parametrize(
    ("expected", "answer"),
    [(6.02214076e23, "6.022e23"), (1.602176634e-19, "1.6e-19"), ("6.674e-11", "6.67e-11"), (0, "0")],
    ids=["avogadro", "charge", "gravitation-text", "zero"],
)
def test_physical_constants_are_expected_values_the_check_takes(client, student_headers, expected, answer):
    result = client.post(
        "/v1/check", json=numeric(answer, expected=expected, units=None), headers=student_headers
    ).json()
    assert (result["verdict"], result["reason"]) == ("correct", "equivalent"), result


FORTY_DIGITS = "1.234567890123456789012345678901234567890"  # as many as `expected` may have
OFF_IN_THE_30TH = "1.234567890123456789012345678911234567890"  # one unit more in the 30th digit


@pytest.mark.parametrize(
    ("answer", "tolerance", "verdict"),
    [
        pytest.param(FORTY_DIGITS, {"abs": 0}, "correct", id="every-digit-exact"),
        pytest.param(OFF_IN_THE_30TH, {"abs": 0}, "incorrect", id="30th-digit-off-exact"),
        pytest.param(OFF_IN_THE_30TH, {"rel": "1e-28"}, "correct", id="30th-digit-off-within-rel"),
        pytest.param(OFF_IN_THE_30TH, {"rel": "1e-30"}, "incorrect", id="30th-digit-off-beyond-rel"),
        pytest.param("1.23456789012", {"rel": "1e-20"}, "incorrect", id="rounded-to-12-figures"),
        pytest.param("1.23456789012", {"rel": "1e-11"}, "correct", id="12-figures-within-rel"),
    ],
)
def test_an_expected_value_is_graded_with_all_its_digits(client, student_headers, answer, tolerance, verdict):
    body = numeric(f"{answer} m", expected=FORTY_DIGITS, units="m", tolerance=tolerance)
    result = client.post("/v1/check", json=body, headers=student_headers).json()
    assert result["verdict"] == verdict, result


UNREADABLE_NUMBERS = [
    # (where, value, message): the one decimal reader's message, at the field's path
    ("expected", "1e101", "must be 0 or of size from 1e-100 to below 1e101"),
    ("expected", 1e300, "must be 0 or of size from 1e-100 to below 1e101"),
    ("expected", 10**200, "must be 0 or of size from 1e-100 to below 1e101"),
    ("expected", "1e999999999", "must be 0 or of size from 1e-100 to below 1e101"),
    ("expected", "1." + "1" * 40, "must have at most 40 significant digits"),
    ("expected", "NaN", "must be a decimal number such as 9.81 or 6.022e23"),
    ("expected", "4_58", "must be a decimal number such as 9.81 or 6.022e23"),
    ("expected", True, "must be a number, not true/false"),
    ("expected", None, "must be a number such as 9.81 or 6.022e23"),
    ("tolerance.rel", "1e-101", "must be 0 or of size from 1e-100 to below 1e101"),
    ("tolerance.abs", "Infinity", "must be a decimal number such as 9.81 or 6.022e23"),
]


@pytest.mark.parametrize(
    ("where", "value", "message"),
    UNREADABLE_NUMBERS,
    ids=[f"{c[0]}-{str(c[1])[:20]}" for c in UNREADABLE_NUMBERS],
)
def test_an_unreadable_number_is_422_with_its_path_and_the_readers_message(
    client, student_headers, where, value, message
):
    body = numeric("4.58 m/s^2")
    if where == "expected":
        body["expected"] = value
    else:
        body["tolerance"] = {where.split(".")[1]: value}
    response = client.post("/v1/check", json=body, headers=student_headers)
    assert response.status_code == 422, response.text
    error = response.json()["error"]
    assert error["code"] == "malformed_request"
    assert {"path": f"numeric.{where}", "message": message} in error["details"], error


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


def test_read_as_note_says_how_a_bare_function_argument_with_a_power_was_read(client, student_headers):
    result = client.post(
        "/v1/check", json=symbolic("-m g sin θ cos θ/(M + m sin θ^2)"), headers=student_headers
    ).json()
    assert (result["verdict"], result["reason"]) == ("incorrect", "wrong_value")
    assert result["read_as"]["text"] == "-m*g*sin(theta)*cos(theta)/(M + m*sin(theta**2))"
    assert result["read_as"]["note"] == "sin θ^2 is read as sin(θ²); for (sin θ)² write sin^2 θ or (sin θ)^2"
    assert result["feedback"].startswith("Read as sin(θ²); if you meant (sin θ)², write sin^2 θ. ")


def test_read_as_note_is_absent_where_the_power_is_written_unambiguously(client, student_headers):
    result = client.post(
        "/v1/check", json=symbolic("-m g sin θ cos θ/(M + m (sin θ)^2)"), headers=student_headers
    ).json()
    assert result["verdict"] == "correct"
    assert result["read_as"].get("note") is None


def test_numeric_units_in_square_brackets_are_read_as_the_units(client, student_headers):
    result = client.post("/v1/check", json=numeric("4.58 [m/s^2]"), headers=student_headers).json()
    assert result["verdict"] == "correct"
    assert result["read_as"]["text"] == "4.58 m/s^2"
    refused = client.post("/v1/check", json=numeric("4.58 [m/smoot]"), headers=student_headers).json()
    assert (refused["verdict"], refused["reason"]) == ("invalid", "unknown_unit")
    assert refused["error"]["position"] == 8


def test_angular_units_other_than_strict_is_422(client, student_headers):
    body = numeric("1 Hz", units="rad/s", angular_units="loose")
    response = client.post("/v1/check", json=body, headers=student_headers)
    assert response.status_code == 422


def test_units_system_other_than_si_is_422(client, student_headers):
    response = client.post("/v1/check", json=numeric("1 m", units_system="imperial"), headers=student_headers)
    assert response.status_code == 422


def test_invalid_verdict_points_at_the_problem(client, student_headers):
    result = client.post("/v1/check", json=symbolic("m g + * M"), headers=student_headers).json()
    assert result["verdict"] == "invalid"
    assert result["error"]["position"] == 6  # the "*" with nothing before it
    assert result["error"]["message"]


CONTRACT_NUMBERS = [
    # (body, position, message): API.md's "a comma inside a number (4,58) or two numbers side by side
    # (12 500) is invalid", in both kinds of answer
    (numeric("4,58 m/s^2"), 1, "4,58: a decimal comma is not read; write 4.58"),
    (numeric("12 500", expected=12500, units=None), 3, "12 500: two numbers side by side; for one number"),
    (symbolic("4,58 m g", "4.58*m*g"), 1, "4,58: a decimal comma is not read; write 4.58"),
    (symbolic("12 500 m g", "12500*m*g"), 3, "12 500: two numbers side by side; for one number"),
]


@pytest.mark.parametrize(
    ("body", "position", "message"), CONTRACT_NUMBERS, ids=[c[0]["answer"] for c in CONTRACT_NUMBERS]
)
def test_a_comma_in_a_number_or_two_numbers_side_by_side_are_invalid(
    client, student_headers, body, position, message
):
    result = client.post("/v1/check", json=body, headers=student_headers).json()
    assert (result["verdict"], result["reason"], result["read_as"]) == ("invalid", "parse_error", None)
    assert result["error"]["position"] == position
    assert result["error"]["message"].startswith(message)


MOMENTUM = {"p": {"dimension": "kg*m/s"}, "m": {"dimension": "kg"}}
CHARGE = {
    "m": {"dimension": "kg"},
    "v": {"dimension": "m/s"},
    "q": {"dimension": "C"},
    "B": {"dimension": "T"},
}
CONTRACT_DIVISIONS = [
    # API.md's own examples of a `/` followed by an unparenthesised juxtaposed product, with symbols
    # whose dimensions leave one reading: refused all the same (they were graded, read by dimension)
    (symbolic("p^2/2m", "p^2/(2*m)", MOMENTUM), "(p^2/2)·m", "p^2/(2·m)"),
    (
        symbolic("v^2/2g", "v^2/(2*g)", {"v": {"dimension": "m/s"}, "g": {"dimension": "m/s^2"}}),
        "(v^2/2)·g",
        "v^2/(2·g)",
    ),
    (symbolic("m v/q B", "m*v/(q*B)", CHARGE), "(m·v/q)·B", "m·v/(q·B)"),
    (symbolic("mv/qB", "m*v/(q*B)", CHARGE), "(m·v/q)·B", "m·v/(q·B)"),
    (symbolic("p^2/2m", "p^2/(2*m)", {"p": {}, "m": {"dimension": "kg"}}), "(p^2/2)·m", "p^2/(2·m)"),
]


@pytest.mark.parametrize(
    ("body", "one", "other"),
    CONTRACT_DIVISIONS,
    ids=[f"{c[0]['answer']} {c[0]['symbols']}" for c in CONTRACT_DIVISIONS],
)
def test_a_division_before_an_unbracketed_product_is_ambiguous_whatever_the_dimensions(
    client, student_headers, body, one, other
):
    result = client.post("/v1/check", json=body, headers=student_headers).json()
    assert (result["verdict"], result["reason"], result["read_as"]) == ("invalid", "ambiguous", None)
    assert result["error"]["position"] == body["answer"].index("/")
    assert result["error"]["message"] == f"Did you mean {one} or {other}? Add parentheses."


def test_an_integer_fraction_starting_a_term_is_a_coefficient(client, student_headers):
    body = symbolic("1/2 m v^2", "m*v^2/2", CHARGE)
    result = client.post("/v1/check", json=body, headers=student_headers).json()
    assert (result["verdict"], result["reason"]) == ("correct", "equivalent")
    assert result["read_as"]["text"] == "1/2*m*v**2"


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
        pytest.param(
            {"kind": "numeric", "answer": "1", "expected": 1, "tolerance": {}},
            "numeric.tolerance",
            id="empty-tolerance-would-pass-everything",
        ),
        pytest.param(choice("A", FRICTION_CHOICES[:1]), "choice.choices", id="one-choice"),
        pytest.param(choice("A", [{"text": f"{i}"} for i in range(27)]), "choice.choices", id="27-choices"),
        pytest.param(
            choice("A", [{"text": "Up", "correct": "yes"}, {"text": "Down"}]),
            "choice.choices.0.correct",
            id="correct-not-bool",
        ),
        pytest.param({"kind": "choice", "answer": "A"}, "choice.choices", id="no-choices"),
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
        pytest.param(
            choice("A", [{"text": "Up", "correct": True}, {"text": "Down", "correct": True}]),
            "choices",
            id="two-right-choices",
        ),
        pytest.param(choice("A", [{"text": "Up"}, {"text": "Down"}]), "choices", id="no-right-choice"),
        pytest.param(numeric("4.58 m/s^2", units="blorps"), "units", id="numeric-unknown-unit"),
        pytest.param(numeric("4.58 m/s^2", units="m/s^"), "units", id="numeric-unreadable-units"),
        pytest.param(numeric("4.58", units=""), "units", id="numeric-empty-units"),
        pytest.param(numeric("1 ft", units="ft", units_system="SI"), "units", id="numeric-units-not-si"),
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


@pytest.mark.parametrize("make", [symbolic, numeric, choice], ids=["symbolic", "numeric", "choice"])
def test_answer_longer_than_the_limit_is_invalid_not_an_error(client, student_headers, settings, make):
    result = client.post(
        "/v1/check", json=make("m" * (settings.max_answer_chars + 1)), headers=student_headers
    ).json()
    assert (result["verdict"], result["reason"]) == ("invalid", "too_large")


def test_health_answers_without_a_key(client):
    assert client.get("/health").json() == {"status": "ok"}
