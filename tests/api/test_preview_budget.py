"""Live previews have their own budget: a student typing is never limited by the answers' budget, a
flood of previews is, with a 429 that says how long to wait and leaves the key working."""

from __future__ import annotations

from app.ratelimit import MemoryRateLimiter

PREVIEW = "/v1/problems/yo-yo/parts/acceleration/preview"
SUBMIT = "/v1/problems/yo-yo/parts/acceleration/submissions"


def test_previews_never_spend_the_students_request_budget(client, student_headers):
    services = client.app.state.services
    services.student_limiter = MemoryRateLimiter(3)
    for text in ["g", "g/", "g/2", "g/2 +", "g/(2)", "2g/3", "g r^2", "g r^2/(r^2", "g r^2/(r^2 + k^2)"]:
        assert client.post(PREVIEW, json={"answer": text}, headers=student_headers).status_code == 200
    assert client.post(SUBMIT, json={"answer": "g"}, headers=student_headers).status_code == 201


def test_a_flood_of_previews_is_limited_with_the_wait_and_the_key_still_works(client, student_headers):
    client.app.state.services.preview_limiter = MemoryRateLimiter(2)
    for _ in range(2):
        assert client.post(PREVIEW, json={"answer": "g"}, headers=student_headers).status_code == 200
    refused = client.post(PREVIEW, json={"answer": "g"}, headers=student_headers)
    assert refused.status_code == 429
    wait = int(refused.headers["Retry-After"])
    assert 1 <= wait <= 60 and f"{wait} s" in refused.json()["error"]["message"]
    assert client.post(SUBMIT, json={"answer": "g"}, headers=student_headers).status_code == 201
