"""Where an error path (`parts[1].tolerance.rel`) is in the YAML or JSON text an author wrote.

The text is composed into YAML nodes (never constructed into objects) and only the path is followed,
so an alias cannot make the walk grow; text that does not compose locates nothing.
"""

from __future__ import annotations

import re
from collections.abc import Iterable
from typing import Any

import yaml

from problems.loader import MAX_DOCUMENT_BYTES

_SEGMENT = re.compile(r"([^.\[\]]+)|\[(\d+)\]")


def path_segments(path: str) -> list[str | int]:
    """ "parts[1].tolerance.rel" -> ["parts", 1, "tolerance", "rel"]."""
    return [int(index) if index else name for name, index in _SEGMENT.findall(path)]


def _step(node: Any, segment: str | int) -> tuple[Any, int] | None:
    """The child `segment` names, with the (0-based) line that names it."""
    if isinstance(node, yaml.MappingNode) and isinstance(segment, str):
        for key, value in node.value:
            if isinstance(key, yaml.ScalarNode) and key.value == segment:
                return value, key.start_mark.line
    if isinstance(node, yaml.SequenceNode) and isinstance(segment, int) and segment < len(node.value):
        child = node.value[segment]
        return child, child.start_mark.line
    return None


def locate(source: str, paths: Iterable[str]) -> dict[str, int]:
    """1-based line of each path found (the deepest part of it that exists); paths not found are left out."""
    if len(source.encode("utf-8")) > MAX_DOCUMENT_BYTES:
        return {}
    try:
        root = yaml.compose(source, Loader=yaml.SafeLoader)
    except yaml.YAMLError:
        return {}
    if root is None:
        return {}
    lines: dict[str, int] = {}
    for path in paths:
        node, line = root, None
        for segment in path_segments(path):
            found = _step(node, segment)
            if found is None:
                break
            node, line = found
        if line is not None:
            lines[path] = line + 1
    return lines
