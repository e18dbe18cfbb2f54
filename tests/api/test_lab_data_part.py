"""A lab's data over the API: a student's view carries their own measurements, the same on every
request and different for another student; a submission is graded against the fit of those data."""

from __future__ import annotations

import math

import numpy as np

from tests.api.conftest import key_headers

LAB = "/v1/problems/incline-lab"


def test_a_student_fits_their_own_data_and_is_graded_against_that_fit(client, student_headers) -> None:
    view = client.get(LAB, headers=student_headers).json()
    data = view["parts"][0]["data"]
    assert client.get(LAB, headers=student_headers).json()["parts"][0]["data"] == data
    other = client.get(LAB, headers=key_headers(client, "student", "other", "someone-else")).json()
    assert other["parts"][0]["data"]["measured"] != data["measured"]
    s = np.sin(np.radians(data["settings"]))
    a = np.array(data["measured"])
    slope = float(s @ a / (s @ s))  # the student's own least-squares fit of a against sin θ
    assert not math.isclose(slope, 9.81, rel_tol=1e-6)  # noisy data: not the true value
    url = f"{LAB}/parts/g_fit/submissions"
    right = client.post(url, json={"answer": f"{slope:.3f} m/s^2"}, headers=student_headers).json()
    assert right["verdict"] == "correct", right
    wrong = client.post(url, json={"answer": f"{slope * 1.2:.3f} m/s^2"}, headers=student_headers).json()
    assert wrong["verdict"] == "incorrect", wrong
