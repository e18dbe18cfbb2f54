"""Reading problem documents: YAML (safe subset, no aliases) or JSON, then shape and meaning checks.

`parse_problem` is the one way in, for the built-in bank and for uploads alike: instructors upload
these files, so the text is read with the safe loader only, its size is bounded, anchors/aliases
(the "billion laughs" bomb) and non-standard tags are refused, and every expression goes through the
whitelist parser in `problems.semantics`.
"""

from __future__ import annotations

import hashlib
import json
from collections.abc import Mapping
from pathlib import Path
from typing import Any, Literal

import yaml
from pydantic import ValidationError

from problems.errors import ErrorItem, ProblemInvalid
from problems.schema import ProblemDocument, shape_errors

Format = Literal["yaml", "json"]

MAX_DOCUMENT_BYTES = 256 * 1024
BANK_DIR = Path(__file__).parent / "bank"
PROBLEM_FILES = ("problem.yaml", "problem.yml", "problem.json")
MODEL_FILES = ("model.yaml", "model.yml", "model.json")


class _NoDuplicateKeys:
    """Refuses a silently repeated key (mixed into a safe loader)."""

    def construct_mapping(self, node: Any, deep: bool = False) -> Any:
        if isinstance(node, yaml.MappingNode):
            seen: set[Any] = set()
            for key_node, _ in node.value:
                key = self.construct_object(key_node, deep=deep)  # type: ignore[attr-defined]
                if isinstance(key, list | dict):
                    raise yaml.constructor.ConstructorError(
                        None, None, "a mapping key must be a plain value", key_node.start_mark
                    )
                if key in seen:
                    raise yaml.constructor.ConstructorError(
                        None, None, f"duplicate key {key!r}", key_node.start_mark
                    )
                seen.add(key)
        return super().construct_mapping(node, deep=deep)  # type: ignore[misc]


_ALIASES_REFUSED = "anchors and aliases (*name) are not allowed"


class _SafeNoAliasLoader(_NoDuplicateKeys, yaml.SafeLoader):
    """The safe loader, minus aliases (exponential expansion) and silently repeated keys."""

    def compose_node(self, parent: Any, index: Any) -> Any:
        if self.check_event(yaml.AliasEvent):
            event = self.peek_event()  # type: ignore[no-untyped-call]
            raise yaml.composer.ComposerError(None, None, _ALIASES_REFUSED, event.start_mark)
        return super().compose_node(parent, index)


# libyaml's safe loader reads the bank ten times faster (a restart reads every bank file), but only
# files shipped with the service go through it: deep nesting takes it minutes where the Python loader
# stops at once. It composes in C, so aliases are refused by a look at its events first.
_FastLoader: type | None = (
    type("_FastLoader", (_NoDuplicateKeys, yaml.CSafeLoader), {}) if yaml.__with_libyaml__ else None
)


def _refuse_aliases(text: str) -> None:
    for event in yaml.parse(text, Loader=yaml.CSafeLoader):
        if isinstance(event, yaml.AliasEvent):
            mark: Any = event.start_mark  # libyaml's own Mark class, with the same fields
            raise yaml.composer.ComposerError(None, None, _ALIASES_REFUSED, mark)


def _load_yaml(text: str, trusted: bool) -> Any:
    if _FastLoader is None or not trusted:
        return yaml.load(text, Loader=_SafeNoAliasLoader)  # noqa: S506 -- a SafeLoader subclass
    _refuse_aliases(text)
    return yaml.load(text, Loader=_FastLoader)  # noqa: S506 -- a CSafeLoader subclass


def read_text(text: str | bytes, fmt: Format = "yaml", *, trusted: bool = False) -> Any:
    """Text -> plain data (dicts, lists, scalars); raises ProblemInvalid with a path-less error.

    `trusted`: a file of the service's own bank (read by the faster loader), never uploaded text.
    """
    if isinstance(text, bytes):
        if len(text) > MAX_DOCUMENT_BYTES:
            raise ProblemInvalid([("", f"document is larger than {MAX_DOCUMENT_BYTES} bytes")])
        try:
            text = text.decode("utf-8")
        except UnicodeDecodeError as error:
            raise ProblemInvalid([("", f"document is not UTF-8 (byte {error.start})")]) from None
    if len(text.encode("utf-8")) > MAX_DOCUMENT_BYTES:
        raise ProblemInvalid([("", f"document is larger than {MAX_DOCUMENT_BYTES} bytes")])
    try:
        if fmt == "json":
            return json.loads(text, object_pairs_hook=_no_duplicate_keys, parse_constant=_no_constants)
        return _load_yaml(text, trusted)
    except yaml.YAMLError as error:
        raise ProblemInvalid([("", f"YAML: {_yaml_message(error)}")]) from None
    except json.JSONDecodeError as error:
        raise ProblemInvalid(
            [("", f"JSON: {error.msg} at line {error.lineno} column {error.colno}")]
        ) from None
    except ValueError as error:
        raise ProblemInvalid([("", f"JSON: {error}")]) from None
    except RecursionError:
        raise ProblemInvalid([("", "document is nested too deeply")]) from None


def _yaml_message(error: yaml.YAMLError) -> str:
    if isinstance(error, yaml.MarkedYAMLError):
        where = f" at line {error.problem_mark.line + 1}" if error.problem_mark is not None else ""
        return f"{error.problem or error.context}{where}"
    return str(error)


def _no_duplicate_keys(pairs: list[tuple[str, Any]]) -> dict[str, Any]:
    out: dict[str, Any] = {}
    for key, value in pairs:
        if key in out:
            raise ValueError(f"duplicate key {key!r}")
        out[key] = value
    return out


def _no_constants(name: str) -> Any:
    raise ValueError(f"{name} is not a number")


def parse_problem(
    source: str | bytes | Mapping[str, Any],
    fmt: Format = "yaml",
    *,
    model: Mapping[str, Any] | None = None,
    check_meaning: bool = True,
) -> ProblemDocument:
    """Read and validate one problem; raises ProblemInvalid listing every fault with its path.

    `model` (the contents of a `model.yaml` kept beside the problem) fills a missing `model` key.
    `check_meaning=False` checks the shape only (no expression is parsed).
    """
    data = source if isinstance(source, Mapping) else read_text(source, fmt)
    if not isinstance(data, Mapping):
        raise ProblemInvalid([("", "a problem document must be a mapping at the top level")])
    data = dict(data)
    if model is not None and data.get("model") is None:
        data["model"] = dict(model)
    problem_id = data.get("id") if isinstance(data.get("id"), str) else None
    try:
        document = ProblemDocument.model_validate(data)
    except ValidationError as error:
        raise ProblemInvalid(shape_errors(error), problem_id) from None
    if check_meaning:
        # Imported here: the meaning checks pull in sympy and the parser, the shape check does not.
        from problems.semantics import semantic_errors

        errors = semantic_errors(document)
        if errors:
            raise ProblemInvalid(errors, document.id)
    return document


def load_problem_dir(directory: Path, *, check_meaning: bool = True) -> ProblemDocument:
    """One bank directory: `problem.yaml` (or .json) with an optional `model.yaml` beside it."""
    problem_file = next((directory / name for name in PROBLEM_FILES if (directory / name).is_file()), None)
    if problem_file is None:
        raise ProblemInvalid([("", f"no {' or '.join(PROBLEM_FILES)} in {directory.name}")], directory.name)
    model_file = next((directory / name for name in MODEL_FILES if (directory / name).is_file()), None)
    model: Any = None
    if model_file is not None:
        model = read_text(model_file.read_bytes(), _format_of(model_file), trusted=True)
        if not isinstance(model, Mapping):
            raise ProblemInvalid([("model", f"{model_file.name} must be a mapping")], directory.name)
    data = read_text(problem_file.read_bytes(), _format_of(problem_file), trusted=True)
    if not isinstance(data, Mapping):
        raise ProblemInvalid([("", "a problem document must be a mapping at the top level")], directory.name)
    document = parse_problem(data, model=model, check_meaning=check_meaning)
    if document.id != directory.name:
        raise ProblemInvalid([("id", f"must match its directory name {directory.name!r}")], document.id)
    return document


def load_bank(dir: Path | str | None = None, *, check_meaning: bool = True) -> list[ProblemDocument]:
    """Every problem under `dir` (default: the built-in bank), sorted by id.

    Raises ProblemInvalid with the faults of every broken problem, each path prefixed by its id.
    """
    root = Path(dir) if dir is not None else BANK_DIR
    documents: list[ProblemDocument] = []
    errors: list[ErrorItem] = []
    for directory in sorted(p for p in root.iterdir() if p.is_dir() and not p.name.startswith((".", "_"))):
        try:
            documents.append(load_problem_dir(directory, check_meaning=check_meaning))
        except ProblemInvalid as error:
            errors.extend(
                (f"{directory.name}:{path}" if path else directory.name, msg) for path, msg in error.errors
            )
    if errors:
        raise ProblemInvalid(errors, f"bank {root}")
    return documents


def _format_of(path: Path) -> Format:
    return "json" if path.suffix == ".json" else "yaml"


def bank_digest(dir: Path | str | None = None) -> str:
    """SHA-256 over every file under the bank directory, names and bytes: the same digest, the same bank
    (milliseconds, where parsing it takes a fifth of a CPU-second)."""
    root = Path(dir) if dir is not None else BANK_DIR
    digest = hashlib.sha256()
    for path in sorted(root.rglob("*")):
        if path.is_file():
            digest.update(f"{path.relative_to(root)}\0".encode())
            digest.update(path.read_bytes())
    return digest.hexdigest()
