"""Every request body in the OpenAPI document has an example that works: it validates against the
documented schema, and sending it (with the path's own examples, and an instructor key) is accepted,
never a 422, as /docs "Try it out" sends it."""

from __future__ import annotations

import json
from typing import Any

import jsonschema
import pytest
import yaml
from fastapi.testclient import TestClient

from app.main import create_app
from app.settings import Settings

pytestmark = pytest.mark.slow
# A new version needs the problem the upload example makes: uploads before their new versions.
METHOD_ORDER = {"post": 0, "put": 1, "patch": 2}


def _spec() -> dict[str, Any]:
    spec: dict[str, Any] = create_app(
        Settings(database_url="sqlite://", secret="s" * 20, warm_up=False)
    ).openapi()
    return spec


def _bodies(spec: dict[str, Any]) -> list[tuple[str, str, str, str, Any]]:
    """(method, path, media type, example name, value) of every request body's every example, in the
    order they can be sent; an operation whose body has no example is listed with name None."""
    found = []
    for path, item in spec["paths"].items():
        for method, operation in item.items():
            for media, content in operation.get("requestBody", {}).get("content", {}).items():
                named = content.get("examples") or {None: {"value": None}}
                found += [(method, path, media, name, example["value"]) for name, example in named.items()]
    return sorted(found, key=lambda body: (METHOD_ORDER.get(body[0], 9), body[1]))


SPEC = _spec()
BODIES = _bodies(SPEC)


def test_every_operation_with_a_body_has_examples_for_every_media_type():
    missing = [
        f"{method.upper()} {path} ({media})" for method, path, media, name, _ in BODIES if name is None
    ]
    assert not missing, f"no example for: {missing}"
    assert len({(method, path) for method, path, *_ in BODIES}) >= 5  # the walk found them


@pytest.mark.parametrize(
    ("method", "path", "media", "name", "value"), BODIES, ids=[f"{b[0]} {b[1]} {b[2]} {b[3]}" for b in BODIES]
)
def test_example_validates_against_its_schema(method, path, media, name, value):
    content = SPEC["paths"][path][method]["requestBody"]["content"][media]
    schema = {**content["schema"], "components": SPEC["components"]}
    jsonschema.Draft202012Validator(schema).validate(value)
    if media == "application/yaml":
        assert isinstance(yaml.safe_load(value), dict)


def _url(path: str, operation: dict[str, Any]) -> str:
    for parameter in operation.get("parameters", []):
        if parameter["in"] == "path":
            examples = parameter.get("examples")
            assert examples, f"path parameter {parameter['name']} of {path} has no example"
            path = path.replace("{" + parameter["name"] + "}", str(next(iter(examples.values()))["value"]))
    return path


def test_every_example_is_accepted_with_an_instructor_key(
    client: TestClient, instructor_headers: dict[str, str]
):
    refused = []
    for method, path, media, name, value in BODIES:
        operation = SPEC["paths"][path][method]
        body = value if isinstance(value, str) else json.dumps(value)
        response = client.request(
            method, _url(path, operation), content=body, headers={**instructor_headers, "content-type": media}
        )
        # 409: the upload example sent a second time (as YAML after JSON) names a problem that exists.
        if response.status_code == 422 or response.status_code >= 500 or response.status_code in (400, 404):
            refused.append(
                f"{method.upper()} {path} {media} {name}: {response.status_code} {response.text[:300]}"
            )
    assert not refused, "\n".join(refused)
