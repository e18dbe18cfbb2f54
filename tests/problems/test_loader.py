"""Reading documents safely (YAML safe subset, JSON) and loading the built-in bank."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
import yaml

from problems.errors import ProblemInvalid
from problems.loader import MAX_DOCUMENT_BYTES, load_bank, parse_problem, read_text
from tests.problems.documents import spring

BILLION_LAUGHS = """
a: &a ["lol", "lol", "lol", "lol", "lol", "lol", "lol", "lol", "lol"]
b: &b [*a, *a, *a, *a, *a, *a, *a, *a, *a]
c: &c [*b, *b, *b, *b, *b, *b, *b, *b, *b]
d: &d [*c, *c, *c, *c, *c, *c, *c, *c, *c]
e: &e [*d, *d, *d, *d, *d, *d, *d, *d, *d]
f: &f [*e, *e, *e, *e, *e, *e, *e, *e, *e]
g: &g [*f, *f, *f, *f, *f, *f, *f, *f, *f]
"""

UNSAFE_TEXTS = [
    pytest.param(BILLION_LAUGHS, "yaml", "aliases", id="yaml-billion-laughs"),
    pytest.param("id: !!python/object/apply:os.system ['true']", "yaml", "constructor", id="yaml-python-tag"),
    pytest.param("id: !!python/name:os.system", "yaml", "constructor", id="yaml-python-name"),
    pytest.param("id: a\nid: b\n", "yaml", "duplicate key", id="yaml-duplicate-key"),
    pytest.param("[" * 100_000, "yaml", "nested too deeply", id="yaml-deep-nesting"),
    pytest.param("id: [unclosed", "yaml", "YAML", id="yaml-syntax"),
    pytest.param('{"id": "a", "id": "b"}', "json", "duplicate key", id="json-duplicate-key"),
    pytest.param('{"x": NaN}', "json", "NaN", id="json-nan"),
    pytest.param("[" * 100_000, "json", "nested too deeply", id="json-deep-nesting"),
    pytest.param("x" * (MAX_DOCUMENT_BYTES + 1), "yaml", "larger than", id="oversized"),
]


# The bank's own files are read by libyaml's loader (faster at start-up): it refuses the same things.
BANK_FILE_REFUSALS = [
    pytest.param(BILLION_LAUGHS, "aliases", id="aliases"),
    pytest.param("a: &x 1\nb: *x\n", "aliases", id="one-alias"),
    pytest.param("id: !!python/object/apply:os.system ['true']", "constructor", id="python-tag"),
    pytest.param("id: a\nid: b\n", "duplicate key", id="duplicate-key"),
    pytest.param("? [a]\n: 1\n", "plain value", id="list-as-key"),
]


@pytest.mark.parametrize(("text", "message"), BANK_FILE_REFUSALS)
def test_a_bank_file_read_by_the_fast_loader_is_refused_like_any_other(text: str, message: str) -> None:
    for trusted in (False, True):
        with pytest.raises(ProblemInvalid) as caught:
            read_text(text, "yaml", trusted=trusted)
        assert message in caught.value.errors[0][1]


@pytest.mark.parametrize(("text", "fmt", "message"), UNSAFE_TEXTS)
def test_unsafe_or_malformed_text_is_refused_without_evaluating_it(text: str, fmt: str, message: str) -> None:
    with pytest.raises(ProblemInvalid) as caught:
        read_text(text, fmt)  # type: ignore[arg-type]
    assert message in caught.value.errors[0][1]


def test_yaml_and_json_of_the_same_document_give_the_same_problem() -> None:
    data = spring()
    from_yaml = parse_problem(yaml.safe_dump(data), "yaml", check_meaning=False)
    from_json = parse_problem(json.dumps(data), "json", check_meaning=False)
    assert from_yaml == from_json


def test_top_level_must_be_a_mapping() -> None:
    with pytest.raises(ProblemInvalid, match="mapping"):
        parse_problem("- a\n- b\n", check_meaning=False)


def test_model_file_beside_the_problem_fills_the_model(tmp_path: Path) -> None:
    folder = tmp_path / "tiny-spring"
    folder.mkdir()
    (folder / "problem.yaml").write_text(yaml.safe_dump(spring()))
    (folder / "model.yaml").write_text("bodies: {}\n")
    [doc] = load_bank(tmp_path, check_meaning=False)
    assert doc.model == {"bodies": {}}


def test_bank_directory_name_must_match_the_id(tmp_path: Path) -> None:
    folder = tmp_path / "other-name"
    folder.mkdir()
    (folder / "problem.yaml").write_text(yaml.safe_dump(spring()))
    with pytest.raises(ProblemInvalid) as caught:
        load_bank(tmp_path, check_meaning=False)
    assert ("other-name:id", "must match its directory name 'other-name'") in caught.value.errors


def test_bank_reports_the_faults_of_every_broken_problem(tmp_path: Path) -> None:
    for name in ("first", "second"):
        data = spring()
        data["id"] = name
        del data["title"]
        (tmp_path / name).mkdir()
        (tmp_path / name / "problem.yaml").write_text(yaml.safe_dump(data))
    with pytest.raises(ProblemInvalid) as caught:
        load_bank(tmp_path, check_meaning=False)
    assert [path for path, _ in caught.value.errors] == ["first:title", "second:title"]


def test_format_guide_example_is_a_valid_problem() -> None:
    from problems.loader import BANK_DIR

    guide = (BANK_DIR.parent / "FORMAT.md").read_text()
    example = guide.split("```yaml\n", 1)[1].split("```", 1)[0]
    doc = parse_problem(example)
    assert doc.id == "incline-pulley-demo" and doc.max_attempts == 5
