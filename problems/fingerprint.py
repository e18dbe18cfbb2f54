"""What a compiled problem depends on besides its document: the engine's code and the libraries it uses.

Two digests of the same files, every module under `physics/` and `problems/`:

- `source_digest`: their bytes. Milliseconds to compute; changes with any edit, even to a comment.
- `engine_digest`: their syntax trees with docstrings dropped. About half a CPU-second; changes only
  when what the code does can change.

Compiled problems are persisted under `engine_digest`, so a docstring, comment or layout edit keeps them
(the catalog remembers `engine_digest` by `source_digest` in the database: a restart parses the code
only after its files changed). Why a stale compilation is never used when behaviour changed:

- Comments and layout are not in a syntax tree; line numbers are left out of the dump. Everything
  else is in it: every statement, name, operator, annotation, default and constant, so any edit that
  can change what runs changes the digest (err on the side of deriving again: a renamed local or an
  edited error message counts as a change too).
- A statement that is only a string constant (a docstring, or a string left as a comment) does nothing
  when run; its one effect, `__doc__`, is read nowhere in the engine (a test pins that).
- Every module of both packages counts, whether or not compiling imports it, and so does its path.
- The interpreter's version and the versions of the libraries the engine computes with count too.
"""

from __future__ import annotations

import ast
import hashlib
import importlib.metadata
import platform
from functools import cache
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
ENGINE_PACKAGES = ("physics", "problems")
# Distributions the engine imports (sympy, mpmath: derivations and references; pint: units; numpy:
# simulations; pydantic and PyYAML: reading documents).
LIBRARIES = ("sympy", "mpmath", "pint", "numpy", "pydantic", "PyYAML")


def engine_files(root: Path = ROOT) -> list[Path]:
    return sorted(path for package in ENGINE_PACKAGES for path in (root / package).rglob("*.py"))


def _environment() -> bytes:
    versions = " ".join(f"{name} {importlib.metadata.version(name)}" for name in LIBRARIES)
    return f"{platform.python_implementation()} {platform.python_version()} {versions}".encode()


@cache
def source_digest(root: Path = ROOT) -> str:
    """A digest of the engine's files as bytes (and of the environment): cheap, changed by any edit."""
    digest = hashlib.sha256(_environment())
    for path in engine_files(root):
        digest.update(b"\0" + str(path.relative_to(root)).encode() + b"\0")
        digest.update(path.read_bytes())
    return digest.hexdigest()


@cache
def engine_digest(root: Path = ROOT) -> str:
    """A digest of what the engine's code does (and of the environment): unchanged by docstrings,
    comments and layout (module docstring)."""
    digest = hashlib.sha256(_environment())
    for path in engine_files(root):
        digest.update(b"\0" + str(path.relative_to(root)).encode() + b"\0")
        digest.update(code_meaning(path.read_bytes()).encode())
    return digest.hexdigest()


def code_meaning(source: bytes) -> str:
    """The module's syntax tree without its bare string statements, dumped without positions."""
    tree = _DropBareStrings().visit(ast.parse(source))
    return ast.dump(tree, include_attributes=False)


class _DropBareStrings(ast.NodeTransformer):
    def visit_Expr(self, node: ast.Expr) -> ast.AST | None:
        if isinstance(node.value, ast.Constant) and isinstance(node.value.value, str):
            return None
        return self.generic_visit(node)
