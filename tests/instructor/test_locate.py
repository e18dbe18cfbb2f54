"""Error paths are found in the author's own text, to the line."""

from __future__ import annotations

import pytest

from problems.locate import locate, path_segments

SOURCE = """\
id: demo
title: Demo
parts:
  - id: a
    kind: symbolic
  - id: b
    kind: numeric
    tolerance:
      rel: -1
"""


@pytest.mark.parametrize(
    ("path", "line"),
    [
        ("title", 2),
        ("parts[1].tolerance.rel", 9),
        ("parts[1].kind", 7),
        ("parts[0]", 4),
        ("parts[1].units", 6),  # missing: the deepest part that exists
        ("parts[7].kind", 3),
    ],
)
def test_a_path_is_found_on_its_line(path: str, line: int):
    assert locate(SOURCE, [path]) == {path: line}


@pytest.mark.parametrize("source", ["", "{unclosed", "a: *alias\n", "[1, 2]"])
def test_text_that_does_not_compose_or_has_no_such_path_locates_nothing(source: str):
    assert locate(source, ["parts[0].kind", "title"]) == {}


def test_paths_are_split_into_keys_and_indices():
    assert path_segments("parts[12].mistakes[0].answer") == ["parts", 12, "mistakes", 0, "answer"]
