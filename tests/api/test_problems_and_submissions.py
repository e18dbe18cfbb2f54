"""Problems, variants and submissions through the HTTP API, as students and instructors use them."""

from __future__ import annotations

import math

import pytest

CONTRACT_BANK = {
    "moving-wedge": {
        "wedge_acceleration",
        "block_relative_acceleration",
        "normal_force",
        "wedge_acceleration_numeric",
    },
    "yo-yo": {"acceleration", "tension", "acceleration_numeric"},
    "lennard-jones": {
        "equilibrium_separation",
        "force",
        "spring_constant",
        "oscillation_frequency",
        "oscillation_frequency_numeric",
    },
    "ballistic-pendulum": {"bullet_speed", "energy_fraction_lost", "bullet_speed_numeric"},
    "skier-friction": {
        "friction_coefficient",
        "acceleration",
        "friction_coefficient_numeric",
        "acceleration_numeric",
    },
}
WEDGE = "/v1/problems/moving-wedge"


def submit(client, headers, part, answer, problem="moving-wedge", **extra):
    return client.post(
        f"/v1/problems/{problem}/parts/{part}/submissions", json={"answer": answer, **extra}, headers=headers
    )


def test_listing_has_the_contract_bank(client, student_headers):
    listing = {p["id"]: p for p in client.get("/v1/problems", headers=student_headers).json()}
    for problem, parts in CONTRACT_BANK.items():
        assert problem in listing
        assert {part["id"] for part in listing[problem]["parts"]} >= parts
        assert all(set(part) >= {"id", "kind", "prompt"} for part in listing[problem]["parts"])


def test_student_view_has_given_values_and_no_reference(client, student_headers):
    view = client.get(WEDGE, headers=student_headers).json()
    assert set(view["given"]) >= {"m", "M", "theta", "g"}
    assert view["given"]["theta"]["unit"] in {"deg", "°"}
    text = str(view)
    for leak in ("sin(theta)*cos(theta)", "M + m*sin", "answer", "mistakes", "model"):
        assert leak not in text
    given = {k: v["value"] for k, v in view["given"].items()}
    theta = math.radians(given["theta"])
    reference = (
        -given["m"]
        * given["g"]
        * math.sin(theta)
        * math.cos(theta)
        / (given["M"] + given["m"] * math.sin(theta) ** 2)
    )
    assert f"{reference:.3f}" not in text


def test_each_student_keeps_one_variant_and_students_differ(client, instructor_headers):
    def given(student):
        return client.get(WEDGE, params={"student": student}, headers=instructor_headers).json()["given"]

    assert given("ada") == given("ada")
    assert len({str(given(f"student-{i}")) for i in range(6)}) > 1


def test_instructor_sees_the_variant_the_student_sees(client, settings, student_headers, instructor_headers):
    own = client.get(WEDGE, headers=student_headers).json()
    named = client.get(WEDGE, params={"student": own["student"]}, headers=instructor_headers).json()
    assert named["given"] == own["given"]


def test_student_key_cannot_name_another_student(client, student_headers):
    assert client.get(WEDGE, params={"student": "someone-else"}, headers=student_headers).status_code == 422
    response = submit(client, student_headers, "wedge_acceleration", "0", student="someone-else")
    assert response.status_code == 422


@pytest.mark.parametrize("field", ["score", "correct", "verdict", "attempts_used"])
def test_client_sent_grading_fields_are_rejected(client, student_headers, field):
    response = submit(client, student_headers, "wedge_acceleration", "0", **{field: 1})
    assert response.status_code == 422
    assert response.json()["error"]["code"] == "malformed_request"


def test_correct_symbolic_submission_is_stored_and_counts_an_attempt(client, student_headers):
    response = submit(client, student_headers, "wedge_acceleration", "-m g sin(θ)cos(θ)/(M + m sin^2 θ)")
    assert response.status_code == 201, response.text
    result = response.json()
    assert (result["verdict"], result["reason"], result["attempts_used"]) == ("correct", "equivalent", 1)
    listed = client.get("/v1/submissions", headers=student_headers).json()["items"]
    assert [item["submission_id"] for item in listed] == [result["submission_id"]]
    assert listed[0]["problem_version"] >= 1


def test_invalid_submission_is_stored_but_uses_no_attempt(client, student_headers):
    submit(client, student_headers, "wedge_acceleration", "0")
    result = submit(client, student_headers, "wedge_acceleration", "m g +").json()
    assert (result["verdict"], result["attempts_used"]) == ("invalid", 1)
    assert len(client.get("/v1/submissions", headers=student_headers).json()["items"]) == 2


def test_sin_theta_squared_is_read_as_sin_of_theta_squared_and_the_student_is_told(client, student_headers):
    answer = "-m g sinθcosθ/(M + m sinθ^2)"  # meant (sin θ)², read as sin(θ²)
    shown = client.post(
        f"{WEDGE}/parts/wedge_acceleration/preview", json={"answer": answer}, headers=student_headers
    ).json()
    assert shown["read_as"]["note"] == "sinθ^2 is read as sin(θ²); for (sin θ)² write sin^2 θ or (sin θ)^2"
    result = submit(client, student_headers, "wedge_acceleration", answer).json()
    assert (result["verdict"], result["attempts_used"]) == ("incorrect", 1)
    assert result["feedback"].startswith("Read as sin(θ²); if you meant (sin θ)², write sin^2 θ. ")


def test_known_mistake_gets_its_targeted_feedback(client, student_headers):
    result = submit(client, student_headers, "wedge_acceleration", "-m g sin(θ) cos(θ)/M").json()
    assert (result["verdict"], result["reason"]) == ("incorrect", "known_mistake")
    assert "fixed" in result["feedback"].lower() or "recoil" in result["feedback"].lower()


def test_numeric_part_is_graded_with_the_students_own_values(client, student_headers):
    given = {k: v["value"] for k, v in client.get(WEDGE, headers=student_headers).json()["given"].items()}
    theta = math.radians(given["theta"])
    a = (
        -given["m"]
        * given["g"]
        * math.sin(theta)
        * math.cos(theta)
        / (given["M"] + given["m"] * math.sin(theta) ** 2)
    )
    right = submit(client, student_headers, "wedge_acceleration_numeric", f"{a:.4g} m/s^2").json()
    assert right["verdict"] == "correct", right
    in_cm = submit(client, student_headers, "wedge_acceleration_numeric", f"{a * 100:.4g} cm/s^2").json()
    assert in_cm["verdict"] == "correct", in_cm
    wrong = submit(client, student_headers, "wedge_acceleration_numeric", f"{a * 1.1:.4g} m/s^2").json()
    assert wrong["verdict"] == "incorrect"


@pytest.mark.parametrize(
    ("path", "status"),
    [
        pytest.param("/v1/problems/no-such-problem/parts/x/submissions", 404, id="unknown-problem"),
        pytest.param("/v1/problems/moving-wedge/parts/no_such_part/submissions", 404, id="unknown-part"),
    ],
)
def test_unknown_problem_or_part_is_404(client, student_headers, path, status):
    response = client.post(path, json={"answer": "1"}, headers=student_headers)
    assert response.status_code == status
    assert response.json()["error"]["code"] == "not_found"


def test_students_see_only_their_own_submissions(client, student_headers, instructor_headers):
    from tests.api.conftest import key_headers

    other = key_headers(client, "student", "bob")
    submit(client, student_headers, "wedge_acceleration", "0")
    submit(client, other, "wedge_acceleration", "0")
    mine = client.get("/v1/submissions", headers=student_headers).json()["items"]
    assert len(mine) == 1
    assert (
        client.get("/v1/submissions", params={"student": "bob"}, headers=student_headers).status_code == 403
    )
    everyone = client.get("/v1/submissions", headers=instructor_headers).json()["items"]
    assert len(everyone) == 2


def test_instructor_submits_for_a_named_student(client, instructor_headers):
    result = submit(client, instructor_headers, "wedge_acceleration", "0", student="carol")
    assert result.status_code == 201
    listed = client.get("/v1/submissions", params={"student": "carol"}, headers=instructor_headers).json()[
        "items"
    ]
    assert [item["student"] for item in listed] == ["carol"]


def test_submissions_page_through_with_a_cursor(client, student_headers):
    for answer in ("0", "1", "2"):
        submit(client, student_headers, "wedge_acceleration", answer)
    seen, cursor = [], None
    while True:
        params = {"limit": 2} | ({"cursor": cursor} if cursor else {})
        page = client.get("/v1/submissions", params=params, headers=student_headers).json()
        seen += [item["answer"] for item in page["items"]]
        cursor = page["next"]
        if cursor is None:
            break
    assert seen == ["0", "1", "2"]


@pytest.mark.parametrize(
    ("method", "path", "body"),
    [
        pytest.param(
            "post",
            "/v1/problems/atwood/parts/acceleration/submissions",
            b'{"answer": "m\\u0000"}',
            id="nul-answer",
        ),
        pytest.param(
            "post",
            "/v1/problems/atwood/parts/acceleration/submissions",
            b'{"answer": "\\ud800x"}',
            id="surrogate-answer",
        ),
        pytest.param(
            "post",
            "/v1/problems/atwood/parts/acceleration/preview",
            b'{"answer": "g\\u0000"}',
            id="nul-preview",
        ),
        pytest.param("get", "/v1/submissions?problem=%00", None, id="nul-query"),
        pytest.param("get", "/v1/problems/%00", None, id="nul-path"),
    ],
)
def test_text_no_database_can_store_is_refused_with_422(client, student_headers, method, path, body):
    headers = {**student_headers, "content-type": "application/json"}
    response = client.request(method, path, content=body, headers=headers)
    assert response.status_code == 422, response.text
    assert response.json()["error"]["code"] == "malformed_request"
