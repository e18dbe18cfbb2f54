"""Size and shape limits of an uploaded document, checked on its text before anything else reads it.

Reading a document into objects (json.loads, yaml's composer, pydantic) recurses once per level of
nesting, and vetting derives whatever the document declares: a document nested 500 levels deep ended
in a RecursionError, and a 20,000-key one held the vetting worker for its whole time limit. So the text
is first walked as a stream of tokens (JSON) or events (YAML), iteratively and in one pass that stops
at the first limit passed, and a document over a limit is refused with the path where it passed it.

The limits are far above any textbook problem (the bank's largest: 8 levels, 128 keys, 6 parts,
3 bodies) and documented in problems/FORMAT.md.
"""

from __future__ import annotations

import json
import re
from collections.abc import Iterator
from dataclasses import dataclass

import yaml

from problems.errors import ErrorItem, format_path
from problems.fields import MAX_ITEMS, MAX_TEXT
from problems.loader import MAX_DOCUMENT_BYTES

MAX_DEPTH = 32  # levels of mappings and lists, the document itself being the first
MAX_KEYS = 2_000  # mapping keys in the whole document
MAX_LIST_ITEMS = 2_000  # list entries in the whole document
MAX_PARTS = MAX_ITEMS
MAX_BODIES = 12  # as the engine's own limit (physics.engine.loading.LIMITS), checked before deriving


@dataclass
class _Frame:
    mapping: bool
    step: str | int | None = None  # the key or index of the node being read in it
    expect_key: bool = True  # mappings: the next node is a key
    items: int = 0


class _TooLarge(Exception):
    def __init__(self, path: str, message: str):
        super().__init__(message)
        self.item: ErrorItem = (path, message)


class _Walk:
    """Counts as the nodes arrive: a node starts (a scalar or a collection), a collection ends."""

    def __init__(self) -> None:
        self.frames: list[_Frame] = []
        self.keys = 0
        self.list_items = 0

    def _path(self) -> str:
        return format_path(tuple(f.step for f in self.frames if f.step is not None))

    def _refuse(self, message: str) -> None:
        raise _TooLarge(self._path(), message)

    def _node(self, key_text: str | None) -> bool:
        """Account for a node starting in the current collection; True when it is a mapping's key."""
        if not self.frames:
            return False
        frame = self.frames[-1]
        if frame.mapping and not frame.expect_key:
            frame.expect_key = True  # the value of the key just read
            return False
        if frame.mapping:
            frame.expect_key = False
            frame.step = key_text if key_text is not None else "?"
            self.keys += 1
            if self.keys > MAX_KEYS:
                self._refuse(f"the document has more than {MAX_KEYS} keys")
        else:
            frame.step = frame.items
            self.list_items += 1
            if self.list_items > MAX_LIST_ITEMS:
                self._refuse(f"the document has more than {MAX_LIST_ITEMS} list entries")
        frame.items += 1
        # Parts are a list; a model's bodies a mapping by name (or a list): entries either way.
        where = tuple(f.step for f in self.frames[:-1])
        if where == ("parts",) and frame.items > MAX_PARTS:
            self._refuse(f"the document has more than {MAX_PARTS} parts")
        if where == ("model", "bodies") and frame.items > MAX_BODIES:
            self._refuse(f"the model has more than {MAX_BODIES} bodies")
        return frame.mapping

    def scalar(self, text: str) -> None:
        is_key = self._node(text)
        if len(text) > MAX_TEXT:
            where = "key" if is_key else "value"
            self._refuse(f"a {where} is longer than {MAX_TEXT} characters")

    def start(self, mapping: bool) -> None:
        self._node(None)
        if len(self.frames) >= MAX_DEPTH:
            self._refuse(f"the document is nested more than {MAX_DEPTH} levels deep")
        self.frames.append(_Frame(mapping))

    def end(self) -> None:
        if self.frames:
            self.frames.pop()


def shape_errors(source: bytes, fmt: str) -> list[ErrorItem]:
    """The first size or shape limit the document passes, with its path; [] when within every limit
    (or when the text is malformed before any limit is reached: reading it reports that)."""
    if len(source) > MAX_DOCUMENT_BYTES:
        return [("", f"the document is larger than {MAX_DOCUMENT_BYTES // 1024} KiB ({len(source)} bytes)")]
    try:
        text = source.decode("utf-8")
    except UnicodeDecodeError:
        return []  # reading reports where
    walk = _Walk()
    try:
        for kind, value in _json_events(text) if fmt == "json" else _yaml_events(text):
            if kind == "scalar":
                walk.scalar(value)
            elif kind == "end":
                walk.end()
            else:
                walk.start(kind == "mapping")
    except _TooLarge as too_large:
        return [too_large.item]
    return []


_JSON_TOKEN = re.compile(r'\s*(?:("(?:[^"\\]|\\.)*")|([\[\]{}:,])|([^\s\[\]{}:,"]+))', re.DOTALL)


def _json_events(text: str) -> Iterator[tuple[str, str]]:
    """Nodes as they start and end; stops quietly at text that is not JSON (json.loads reports it)."""
    position = 0
    while True:
        match = _JSON_TOKEN.match(text, position)
        if match is None:
            return
        position = match.end()
        string, punctuation, bare = match.groups()
        if string is not None:
            try:
                yield "scalar", json.loads(string)
            except ValueError:
                return
        elif bare is not None:
            yield "scalar", bare
        elif punctuation in "[{":
            yield ("mapping" if punctuation == "{" else "sequence"), ""
        elif punctuation in "]}":
            yield "end", ""


def _yaml_events(text: str) -> Iterator[tuple[str, str]]:
    """The parser's events (a state machine, not recursive; the composer is what recurses)."""
    loader = yaml.CSafeLoader if yaml.__with_libyaml__ else yaml.SafeLoader
    try:
        for event in yaml.parse(text, Loader=loader):
            if isinstance(event, yaml.ScalarEvent | yaml.AliasEvent):
                yield "scalar", getattr(event, "value", "")
            elif isinstance(event, yaml.MappingStartEvent):
                yield "mapping", ""
            elif isinstance(event, yaml.SequenceStartEvent):
                yield "sequence", ""
            elif isinstance(event, yaml.MappingEndEvent | yaml.SequenceEndEvent):
                yield "end", ""
    except yaml.YAMLError:
        return
