"""Uploads over a documented size or shape limit (problems/shape.py) are refused with 422 naming the
limit and where it was passed, before anything recursive reads them and without the vetting worker."""

from __future__ import annotations

import json

import pytest
import yaml

from app.authoring import AuthoringPool
from problems.shape import MAX_BODIES, MAX_DEPTH, MAX_KEYS, MAX_PARTS, shape_errors
from tests.api.test_authoring import atwood_upload

JSON = {"content-type": "application/json"}
YAML = {"content-type": "application/yaml"}


def _deep_json(levels: int) -> bytes:
    return ('{"id": "deep", "model": ' + '{"a": ' * levels + "1" + "}" * levels + "}").encode()


def _deep_yaml(levels: int) -> bytes:
    return ("id: deep\nmodel: " + "[" * levels + "1" + "]" * levels + "\n").encode()


def _junk_keys(count: int) -> bytes:
    return json.dumps({"id": "junk", **{str(i): 0 for i in range(count)}}, separators=(",", ":")).encode()


def _many(path: str, count: int) -> bytes:
    doc = atwood_upload()
    if path == "parts":
        doc["parts"] = [dict(doc["parts"][0], id=f"p{i}") for i in range(count)]
    else:
        doc["model"]["bodies"] = {f"b{i}": {"mass": "m1", "position": {"y": "s"}} for i in range(count)}
    return json.dumps(doc).encode()


CASES = [
    ("json-500-levels", _deep_json(500), JSON, "model.a.a", "nested more than"),
    ("yaml-500-levels", _deep_yaml(500), YAML, "model[0][0]", "nested more than"),
    ("json-100000-levels", b"[" * 100_000 + b"]" * 100_000, JSON, "", "nested more than"),
    ("yaml-20000-levels", b"a: " + b"{b: " * 20_000 + b"1" + b"}" * 20_000, YAML, "a.b.b", "nested more"),
    ("20000-keys", _junk_keys(20_000), JSON, "", f"more than {MAX_KEYS} keys"),
    ("too-many-parts", _many("parts", MAX_PARTS + 1), JSON, f"parts[{MAX_PARTS}]", "parts"),
    ("too-many-bodies", _many("bodies", MAX_BODIES + 1), JSON, f"model.bodies.b{MAX_BODIES}", "bodies"),
    ("long-text", json.dumps({"id": "x", "statement": "a" * 30_000}).encode(), JSON, "statement", "longer"),
    ("over-256-KiB", b" " * (300 * 1024) + b"{}", JSON, "", "larger than 256 KiB"),
]


@pytest.fixture
def no_vetting(monkeypatch):
    """The vetting worker must not be asked (it would derive the junk for up to its whole time limit)."""

    async def refuse(self, source, fmt):
        raise AssertionError("a document over a limit reached the vetting worker")

    monkeypatch.setattr(AuthoringPool, "_vet", refuse)


@pytest.mark.parametrize(
    ("body", "headers", "path", "words"), [c[1:] for c in CASES], ids=[c[0] for c in CASES]
)
def test_upload_over_a_limit_is_422_naming_it_without_vetting(
    client, instructor_headers, no_vetting, body, headers, path, words
):
    response = client.post("/v1/problems", content=body, headers={**instructor_headers, **headers})
    assert response.status_code == 422, response.text[:500]
    error = response.json()["error"]
    assert error["code"] == "invalid_problem"
    [detail] = error["details"]
    assert detail["path"].startswith(path), detail
    assert words in detail["message"], detail
    # The same client (connection) goes on: nothing broke.
    assert client.get("/v1/problems", headers=instructor_headers).status_code == 200


def test_the_whole_bank_is_within_the_limits():
    from problems.loader import BANK_DIR

    for problem in sorted(BANK_DIR.glob("*/problem.yaml")):
        assert shape_errors(problem.read_bytes(), "yaml") == [], problem
        data = yaml.safe_load(problem.read_text())
        assert shape_errors(json.dumps(data).encode(), "json") == [], problem


@pytest.mark.parametrize("fmt", ["json", "yaml"])
def test_a_document_at_the_depth_limit_is_read(fmt):
    deep = _deep_json if fmt == "json" else _deep_yaml
    assert shape_errors(deep(MAX_DEPTH - 1), fmt) == []  # the document itself is the first level
    assert shape_errors(deep(MAX_DEPTH), fmt) != []


@pytest.mark.parametrize(
    ("source", "fmt"),
    [
        (json.dumps({"id": "x", "statement": "[{" * 900 + ' \\" ' + "}]" * 900}).encode(), "json"),
        (b"id: x\nstatement: '" + b"[{" * 900 + b"'\n", "yaml"),
        (b"id: x\nstatement: |\n  " + b"- " * 900 + b"\n", "yaml"),
    ],
    ids=["json-brackets-in-a-string", "yaml-brackets-in-a-string", "yaml-dashes-in-a-block"],
)
def test_brackets_inside_text_are_not_nesting(source: bytes, fmt: str):
    assert shape_errors(source, fmt) == []


def test_block_style_yaml_nesting_is_counted_too():
    source = (
        "".join(f"{'  ' * level}k{level}:\n" for level in range(MAX_DEPTH + 5))
        + "  " * (MAX_DEPTH + 5)
        + "v\n"
    )
    [(path, message)] = shape_errors(source.encode(), "yaml")
    assert path.startswith("k0.k1.k2") and "nested more than" in message
